#include "penumbraSceneWalk.h"

#include "penumbraCulling.h"
#include "penumbraGlyphs.h"
#include "penumbraMatrices.h"
#include "vtkSoftShadowPass.h"

#include "vtkAbstractMapper3D.h"
#include "vtkActor.h"
#include "vtkAnnotatedCubeActor.h"
#include "vtkAssembly.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkAxesActor.h"
#include "vtkBitArray.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkDataSet.h"
#include "vtkDataSetMapper.h"
#include "vtkExecutive.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkImageSlice.h"
#include "vtkInformation.h"
#include "vtkInformationExecutivePortVectorKey.h"
#include "vtkLODActor.h"
#include "vtkLODProp3D.h"
#include "vtkLightActor.h"
#include "vtkMapperCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLMoleculeMapper.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkOpenGLStickMapper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp3D.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkQuadricClustering.h"
#include "vtkQuadricLODActor.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProperty.h"
#include "vtkSkybox.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <utility>

namespace penumbra
{
namespace
{
/// Reads the arrays vtkGlyph3DMapper itself reads (its protected Get*Array), through pointers
/// to its members, so that array selection, Orient, SourceIndexing and Masking act as in VTK.
struct GlyphArrays : vtkGlyph3DMapper
{
  using Getter = vtkDataArray* (vtkGlyph3DMapper::*)(vtkDataSet*);
  static constexpr Getter Scale = &GlyphArrays::GetScaleArray;
  static constexpr Getter Orientation = &GlyphArrays::GetOrientationArray;
  static constexpr Getter SourceIndex = &GlyphArrays::GetSourceIndexArray;
  static constexpr Getter Mask = &GlyphArrays::GetMaskArray;
};

/// Reads the name of the array of radii a vtkOpenGLSphereMapper reads (it has no getter).
struct SphereArrays : vtkOpenGLSphereMapper
{
  static constexpr const char* vtkOpenGLSphereMapper::*Scale = &SphereArrays::ScaleArray;
};

/// The same for a vtkOpenGLStickMapper's arrays of sizes and orientations.
struct StickArrays : vtkOpenGLStickMapper
{
  static constexpr const char* vtkOpenGLStickMapper::*Scale = &StickArrays::ScaleArray;
  static constexpr const char* vtkOpenGLStickMapper::*Orientation = &StickArrays::OrientationArray;
};

/// A vtkOpenGLMoleculeMapper's bond mapper, which it does not give out.
struct MoleculeParts : vtkOpenGLMoleculeMapper
{
  static constexpr vtkNew<vtkOpenGLStickMapper> vtkOpenGLMoleculeMapper::*Bonds =
    &MoleculeParts::FastBondMapper;
};

/// Whether `points` has a coordinate whose range is infinite.
bool InfiniteRange(vtkPoints* points)
{
  for (int component = 0; points && component < 3; ++component)
  {
    double range[2];
    points->GetData()->GetRange(range, component);
    if (!std::isfinite(range[0]) || !std::isfinite(range[1]))
    {
      return true;
    }
  }
  return false;
}

/// Whether VTK 9.1 draws nothing of `data`: its polydata mapper's automatic shift methods (the
/// default) move the vertex buffer by the middle of the points' range, which a point at an
/// infinite coordinate, used by a cell or not, makes infinite (vtkOpenGLVertexBufferObject).
/// vtkDataSetMapper draws a polydata input through a polydata mapper of its own (made at its
/// first frame, with the default method), all its points kept; a composite mapper shifts one
/// buffer by all its polydata blocks' points.
bool ShiftedToInfinity(vtkMapper* mapper, vtkDataObject* data)
{
  if (!vtkOpenGLVertexBufferObject::GetGlobalCoordShiftAndScaleEnabled())
  {
    return false;
  }
  vtkMapper* drawing = mapper;
  if (auto datasets = vtkDataSetMapper::SafeDownCast(mapper))
  {
    if (!vtkPolyData::SafeDownCast(data))
    {
      return false; // drawn from its surface's points
    }
    drawing = datasets->GetPolyDataMapper();
  }
  auto polyMapper = vtkOpenGLPolyDataMapper::SafeDownCast(drawing);
  if (drawing && !polyMapper)
  {
    return false;
  }
  const int method = polyMapper ? polyMapper->GetVBOShiftScaleMethod()
                                : vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE;
  if (method != vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE &&
    method != vtkOpenGLVertexBufferObject::ALWAYS_AUTO_SHIFT_SCALE &&
    method != vtkOpenGLVertexBufferObject::AUTO_SHIFT)
  {
    return false;
  }
  if (auto tree = vtkDataObjectTree::SafeDownCast(data))
  {
    for (vtkDataObject* leaf : vtk::Range(tree))
    {
      auto block = vtkPolyData::SafeDownCast(leaf);
      if (block && InfiniteRange(block->GetPoints()))
      {
        return true;
      }
    }
    return false;
  }
  auto polyData = vtkPolyData::SafeDownCast(data);
  return polyData && InfiniteRange(polyData->GetPoints());
}

/// Mappers that draw spheres or sticks as imposters, for which the walk casts tessellated
/// stand-ins (SceneWalk::Spheres, Sticks, Molecule); VTK draws them whatever the representation.
bool DrawsImposterInstances(vtkMapper* mapper)
{
  return vtkOpenGLSphereMapper::SafeDownCast(mapper) ||
    vtkOpenGLStickMapper::SafeDownCast(mapper) || vtkOpenGLMoleculeMapper::SafeDownCast(mapper);
}

/// Whether VTK's imposter mappers read `array` as it is: they take it as floats, `components`
/// to a point, for every point (GetVoidPointer). Another type or layout they draw from garbage
/// or from past the array's end.
bool LaidOutAsVTKReadsIt(vtkDataArray* array, int components, vtkIdType points)
{
  return array->GetDataType() == VTK_FLOAT && array->GetNumberOfComponents() == components &&
    array->GetNumberOfTuples() >= points;
}

/// A polydata of `mesh`, the caster of every imposter of one kind.
vtkSmartPointer<vtkPolyData> NewPolyData(const TriangleMesh& mesh)
{
  vtkNew<vtkPoints> points;
  for (const glm::dvec3& p : mesh.Points)
  {
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> triangles;
  for (const glm::uvec3& t : mesh.Triangles)
  {
    const vtkIdType ids[3] = { static_cast<vtkIdType>(t.x), static_cast<vtkIdType>(t.y),
      static_cast<vtkIdType>(t.z) };
    triangles->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  return poly;
}
/// What an actor's own surfaces let through, as VTK draws them: in the opaque pass (ForceOpaque
/// included) they cast fully; in the translucent pass (opacity below 1, colours with alpha, a
/// texture, ForceTranslucent) they are seen through and cast by the property's opacity.
struct DrawnOpacity
{
  double Opacity;
  bool SeenThrough;
};

DrawnOpacity ActorOpacity(vtkActor* actor)
{
  const bool seenThrough = !actor->HasOpaqueGeometry();
  return { seenThrough ? std::min(actor->GetProperty()->GetOpacity(), 1.0) : 1.0, seenThrough };
}

/// The same for a block of a composite mapper, as vtkCompositePolyDataMapper2 sorts its blocks
/// into VTK's passes (BuildRenderValues): opaque where its opacity (the nearest block's that sets
/// one, else the property's) is 1, the actor's texture is opaque and, with scalars shown, the
/// lookup table draws the block's scalars opaque. ForceOpaque draws every block opaque, and
/// ForceTranslucent every block seen through. An opaque block is drawn in the opaque pass only,
/// which VTK skips for an actor it takes for translucent (a property opacity below 1 under a
/// block's 1): drawn nowhere, opacity 0.
DrawnOpacity BlockOpacity(
  vtkActor* actor, vtkCompositePolyDataMapper2* mapper, vtkPolyData* block, double opacity)
{
  if (actor->GetForceOpaque())
  {
    return { 1.0, false };
  }
  const bool opaque = opacity >= 1.0 &&
    !(actor->GetTexture() && actor->GetTexture()->IsTranslucent()) &&
    BlockColoursOpaque(mapper, block);
  if (actor->GetForceTranslucent() || !opaque)
  {
    return { std::min(opacity, 1.0), true };
  }
  return { actor->HasOpaqueGeometry() ? 1.0 : 0.0, false };
}

/// The points an imposter mapper draws its shapes at, or null where VTK draws none: no points,
/// an actor of opacity 0, or points without cells (no bounds in VTK 9.1, so that its culler
/// drops the actor).
vtkPolyData* DrawnCentres(vtkActor* actor, vtkPolyDataMapper* mapper, const DrawnOpacity& drawn)
{
  vtkPolyData* centres = mapper->GetInput();
  const bool drawnAtAll = drawn.Opacity > 0.0 && centres && centres->GetPoints() &&
    vtkMath::AreBoundsInitialized(actor->GetBounds());
  return drawnAtAll ? centres : nullptr;
}

/// One surface per point of `centres`, each an instance of `shape` at the matrix `place` gives
/// it (place(id, centre, matrix) returns false to leave the point out). Returns whether every
/// point was placed.
template <typename Place>
bool AddInstances(vtkActor* actor, const DrawnOpacity& drawn, vtkPolyData* shape,
  vtkPolyData* centres, const Place& place, std::vector<DrawnSurface>& surfaces)
{
  bool placedAll = true;
  for (vtkIdType id = 0; id < centres->GetNumberOfPoints(); ++id)
  {
    double centre[3];
    centres->GetPoint(id, centre);
    glm::dmat4 matrix;
    if (!place(id, glm::make_vec3(centre), matrix))
    {
      placedAll = false;
      continue;
    }
    surfaces.push_back(
      { actor, shape, matrix, static_cast<std::size_t>(id), drawn.Opacity, drawn.SeenThrough });
  }
  return placedAll;
}

/// The glyph sources of a vtkGlyph3DMapper, in the order its source indices pick them: its
/// source table's blocks, or the sources on its input port 1.
std::vector<vtkDataObject*> GlyphSources(vtkGlyph3DMapper* mapper)
{
  std::vector<vtkDataObject*> sources;
  if (mapper->GetUseSourceTableTree())
  {
    if (vtkDataObjectTree* table = mapper->GetSourceTableTree())
    {
      for (vtkDataObject* source : vtk::Range(table, vtk::DataObjectTreeOptions::None))
      {
        sources.push_back(vtkPolyData::SafeDownCast(source));
      }
    }
  }
  else
  {
    for (int i = 0; i < mapper->GetNumberOfInputConnections(1); ++i)
    {
      sources.push_back(mapper->GetSource(i));
    }
  }
  // Without a source VTK draws its default glyph, a line: like any glyph without surface
  // cells it casts nothing, and says so once here rather than once per glyph.
  if (sources.empty())
  {
    sources.push_back(nullptr);
  }
  return sources;
}

/// How a vtkGlyph3DMapper scales and orients its glyphs.
GlyphSettings GlyphSettingsOf(vtkGlyph3DMapper* mapper)
{
  GlyphSettings settings;
  settings.Scaling = mapper->GetScaling();
  settings.ScaleMode = mapper->GetScaleMode();
  settings.ScaleFactor = mapper->GetScaleFactor();
  settings.Clamping = mapper->GetClamping();
  mapper->GetRange(settings.Range);
  settings.OrientationMode = mapper->GetOrientationMode();
  return settings;
}

/// The datasets whose points a vtkGlyph3DMapper places glyphs at (null for a leaf that is no
/// dataset).
std::vector<vtkDataSet*> GlyphInputs(vtkGlyph3DMapper* mapper)
{
  std::vector<vtkDataSet*> inputs;
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  if (auto composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    // As vtkOpenGLGlyph3DMapper draws composite input: each leaf unless its own block
    // visibility hides it (VTK 9.1's glyph mapper reads no inherited visibility, no opacity).
    vtkCompositeDataDisplayAttributes* blocks = mapper->GetBlockAttributes();
    auto it = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      vtkDataObject* leaf = it->GetCurrentDataObject();
      if (!blocks || !blocks->HasBlockVisibility(leaf) || blocks->GetBlockVisibility(leaf))
      {
        inputs.push_back(vtkDataSet::SafeDownCast(leaf));
      }
    }
  }
  else
  {
    inputs.push_back(vtkDataSet::SafeDownCast(input));
  }
  return inputs;
}

/// What every glyph of one vtkGlyph3DMapper shares: the actor and matrix it is drawn with, its
/// opacity, how it is placed and the sources it is picked from (null: casts nothing).
struct GlyphSet
{
  vtkActor* Actor;
  glm::dmat4 Matrix;
  DrawnOpacity Drawn;
  GlyphSettings Settings;
  std::vector<vtkDataObject*> Sources;
};

/// The arrays a vtkGlyph3DMapper reads at one input's points (GlyphArrays), each null where
/// it reads none.
struct GlyphPointArrays
{
  vtkDataArray* Scale;
  vtkDataArray* Orientation;
  vtkDataArray* SourceIndex;
  vtkBitArray* Mask;
};

/// The arrays of `points` that `mapper` reads its glyphs' scales, orientations, sources and
/// mask from (none that it does not use).
GlyphPointArrays GlyphPointArraysOf(vtkGlyph3DMapper* mapper, vtkDataSet* points)
{
  return { (mapper->*GlyphArrays::Scale)(points), (mapper->*GlyphArrays::Orientation)(points),
    (mapper->*GlyphArrays::SourceIndex)(points),
    vtkBitArray::SafeDownCast((mapper->*GlyphArrays::Mask)(points)) };
}

/// Which of `count` sources glyph `id` is drawn from: as VTK, the norm of its index tuple,
/// clamped to the table; the first without an index array.
std::size_t SourceEntry(vtkDataArray* sourceIndex, vtkIdType id, std::size_t count)
{
  if (!sourceIndex)
  {
    return 0;
  }
  const double value =
    vtkMath::Norm(sourceIndex->GetTuple(id), sourceIndex->GetNumberOfComponents());
  return static_cast<std::size_t>(
    std::min(std::max(static_cast<int>(value), 0), static_cast<int>(count) - 1));
}

/// The glyphs of one input's points, numbered on from `part` (masked and unplaced points keep
/// their numbers); `nonFinite` is set where one has no finite matrix. False for an orientation
/// array of the wrong size, which VTK reports: the caller then takes none of the mapper's glyphs,
/// although VTK 9.1 (vtkOpenGLGlyph3DMapper::RebuildStructures) skips that input only and draws
/// the other inputs' (composite input: a known difference, not fixed).
bool AddGlyphsAt(const GlyphSet& glyphs, vtkGlyph3DMapper* mapper, vtkDataSet* points,
  std::size_t& part, bool& nonFinite, std::vector<DrawnSurface>& surfaces)
{
  const GlyphPointArrays arrays = GlyphPointArraysOf(mapper, points);
  const int orientationComponents =
    glyphs.Settings.OrientationMode == GlyphSettings::Quaternion ? 4 : 3;
  if (arrays.Orientation && arrays.Orientation->GetNumberOfComponents() != orientationComponents)
  {
    return false;
  }
  for (vtkIdType id = 0; id < points->GetNumberOfPoints(); ++id, ++part)
  {
    if (arrays.Mask && arrays.Mask->GetValue(id) == 0)
    {
      continue;
    }
    vtkDataObject* source =
      glyphs.Sources[SourceEntry(arrays.SourceIndex, id, glyphs.Sources.size())];
    if (!source)
    {
      continue;
    }
    double position[3];
    points->GetPoint(id, position);
    const glm::dvec3 size =
      GlyphScale(glyphs.Settings, arrays.Scale ? arrays.Scale->GetTuple(id) : nullptr,
        arrays.Scale ? arrays.Scale->GetNumberOfComponents() : 0);
    glm::dmat4 glyph;
    if (!GlyphMatrix(glyphs.Settings, glm::dvec3(position[0], position[1], position[2]),
          arrays.Orientation ? arrays.Orientation->GetTuple(id) : nullptr, size, glyph))
    {
      nonFinite = true;
      continue;
    }
    surfaces.push_back({ glyphs.Actor, source, glyphs.Matrix * glyph, part, glyphs.Drawn.Opacity,
      glyphs.Drawn.SeenThrough });
  }
  return true;
}
} // namespace

std::vector<vtkProp*> PropsDrawnFor(vtkProp* prop)
{
  if (auto axes = vtkAxesActor::SafeDownCast(prop))
  {
    vtkNew<vtkPropCollection> parts;
    axes->GetActors(parts);
    std::vector<vtkProp*> drawn;
    for (int i = 0; i < parts->GetNumberOfItems(); ++i)
    {
      drawn.push_back(static_cast<vtkProp*>(parts->GetItemAsObject(i)));
    }
    return drawn; // its labels are 2D captions: nothing to cast or receive
  }
  if (auto cube = vtkAnnotatedCubeActor::SafeDownCast(prop))
  {
    return { cube->GetAssembly() }; // VTK draws the assembly at its own matrix, not the cube's
  }
  return { prop };
}

bool IsExactly(vtkObject* object, const char* className)
{
  return object && std::strcmp(object->GetClassName(), className) == 0;
}

bool BlockColoursOpaque(vtkCompositePolyDataMapper2* mapper, vtkPolyData* block)
{
  if (!mapper->GetScalarVisibility())
  {
    return true;
  }
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(block, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  // Without scalars VTK still asks the lookup table, which answers for its whole table. Built
  // first, as VTK builds it: asked before, it would keep its old answer for VTK too.
  vtkScalarsToColors* table = mapper->GetLookupTable();
  table->Build();
  return table->IsOpaque(scalars, mapper->GetColorMode(), mapper->GetArrayComponent()) != 0;
}

std::vector<vtkTexture*> TexturesOf(vtkActor* actor, bool colourOnly)
{
  // The PBR maps other than the albedo (normals, material, emission...) carry no opacity.
  static const std::array<const char*, 7> noOpacity = { "normalTex", "materialTex", "brdfTex",
    "emissiveTex", "anisotropyTex", "coatNormalTex", "colortexture" };
  std::vector<vtkTexture*> textures;
  if (actor->GetTexture())
  {
    textures.push_back(actor->GetTexture());
  }
  for (const auto& named : actor->GetProperty()->GetAllTextures())
  {
    if (!colourOnly ||
      std::none_of(noOpacity.begin(), noOpacity.end(),
        [&named](const char* name) { return named.first == name; }))
    {
      textures.push_back(named.second);
    }
  }
  return textures;
}

namespace
{
/// A texture's texels where VTK takes them as colours as they are: unsigned chars, not mapped
/// through a lookup table (whose alpha is not looked into). Null otherwise, or where none are
/// known yet.
vtkDataArray* DirectColours(vtkTexture* texture)
{
  vtkImageData* image = texture->GetInput();
  vtkDataArray* texels = image ? image->GetPointData()->GetScalars() : nullptr;
  const bool direct = texels && texels->GetDataType() == VTK_UNSIGNED_CHAR &&
    texture->GetColorMode() != VTK_COLOR_MODE_MAP_SCALARS;
  return direct ? texels : nullptr;
}

/// Whether colours of `components` to a texel carry alpha: luminance-alpha or RGBA.
bool HasAlpha(int components)
{
  return components == 2 || components == 4;
}
} // namespace

bool TexturesMayOpenHoles(vtkActor* actor)
{
  const auto mayHaveAlpha = [](vtkTexture* texture)
  {
    vtkDataArray* colours = DirectColours(texture);
    return !colours || HasAlpha(colours->GetNumberOfComponents());
  };
  const std::vector<vtkTexture*> textures = TexturesOf(actor);
  return std::any_of(textures.begin(), textures.end(), mayHaveAlpha);
}

bool TexturesCutHoles(vtkActor* actor)
{
  const auto cutsHoles = [](vtkTexture* texture)
  {
    // VTK 9.1 discards a fragment whose alpha is 0.
    vtkDataArray* colours = DirectColours(texture);
    const int components = colours ? colours->GetNumberOfComponents() : 0;
    return HasAlpha(components) && colours->GetRange(components - 1)[0] <= 0.0;
  };
  const std::vector<vtkTexture*> textures = TexturesOf(actor, true);
  return std::any_of(textures.begin(), textures.end(), cutsHoles);
}

bool HasCustomShaders(vtkActor* actor)
{
  vtkShaderProperty* shaders = actor->GetShaderProperty();
  return shaders &&
    (shaders->HasVertexShaderCode() || shaders->HasFragmentShaderCode() ||
      shaders->HasGeometryShaderCode() || shaders->GetNumberOfShaderReplacements() > 0);
}

bool OutsideTheShadows(vtkProp* prop)
{
  return (!vtkProp3D::SafeDownCast(prop) && !vtkPropAssembly::SafeDownCast(prop)) ||
    vtkLightActor::SafeDownCast(prop);
}

std::vector<vtkProp*> VisiblePropsInTheShadows(vtkRenderer* renderer)
{
  std::vector<vtkProp*> props;
  vtkPropCollection* all = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  for (all->InitTraversal(it); vtkProp* prop = all->GetNextProp(it);)
  {
    if (prop->GetVisibility() && !OutsideTheShadows(prop))
    {
      props.push_back(prop);
    }
  }
  return props;
}

namespace
{
/// The largest magnitude of component `component` of `array`, or `fallback` without an array.
double LargestComponent(vtkDataArray* array, int component, double fallback)
{
  if (!array || component >= array->GetNumberOfComponents() || array->GetNumberOfTuples() == 0)
  {
    return fallback;
  }
  double range[2];
  array->GetRange(range, component);
  return std::max(std::abs(range[0]), std::abs(range[1]));
}

/// ImposterReach of one actor's mapper, in the mapper's (object) units.
double MapperImposterReach(vtkMapper* mapper)
{
  auto input = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  if (!input)
  {
    return 0.0;
  }
  vtkPointData* points = input->GetPointData();
  auto named = [&](const char* name) { return name ? points->GetArray(name) : nullptr; };
  if (auto spheres = vtkOpenGLSphereMapper::SafeDownCast(mapper))
  {
    return LargestComponent(named(spheres->*SphereArrays::Scale), 0, spheres->GetRadius());
  }
  if (auto sticks = vtkOpenGLStickMapper::SafeDownCast(mapper))
  {
    // Half the length (first size component times the orientation's norm) and the radius.
    vtkDataArray* sizes = named(sticks->*StickArrays::Scale);
    vtkDataArray* axes = named(sticks->*StickArrays::Orientation);
    const double axis = axes ? axes->GetMaxNorm() : 1.0;
    return 0.5 * LargestComponent(sizes, 0, 0.0) * axis + LargestComponent(sizes, 1, 0.0);
  }
  return 0.0;
}
} // namespace

double ImposterReach(vtkProp* prop)
{
  double reach = 0.0;
  vtkAssemblyPath* path;
  for (prop->InitPathTraversal(); (path = prop->GetNextPath());)
  {
    auto actor = vtkActor::SafeDownCast(path->GetLastNode()->GetViewProp());
    const double local = actor ? MapperImposterReach(MapperDrawn(actor)) : 0.0;
    if (local == 0.0)
    {
      continue;
    }
    // How far the path's matrix (a lone actor's own) stretches a length: the largest singular
    // value of its linear part, shear included.
    vtkMatrix4x4* matrix = path->GetLastNode()->GetMatrix();
    matrix = matrix ? matrix : actor->GetMatrix();
    double linear[3][3], u[3][3], singular[3], vt[3][3];
    for (int row = 0; row < 3; ++row)
    {
      for (int column = 0; column < 3; ++column)
      {
        linear[row][column] = matrix->GetElement(row, column);
      }
    }
    vtkMath::SingularValueDecomposition3x3(linear, u, singular, vt);
    const double stretch =
      std::max({ std::abs(singular[0]), std::abs(singular[1]), std::abs(singular[2]) });
    reach = std::max(reach, std::isfinite(local) ? local * stretch : HUGE_VAL);
  }
  return reach;
}

namespace
{
/// Whether `mapper` is one of the levels a vtkLODActor makes of its own: a cloud of points and
/// the outline of its bounds.
bool DrawsPointsOrOutline(vtkLODActor* levels, vtkMapper* mapper)
{
  vtkAlgorithm* input =
    mapper->GetNumberOfInputConnections(0) ? mapper->GetInputAlgorithm() : nullptr;
  return levels && input &&
    (input == levels->GetLowResFilter() || input == levels->GetMediumResFilter());
}

/// The interactor of the window `prop` is drawn in: through the renderers it was added to, or
/// the assemblies it is a part of (`depth` guards against a cycle). Null when none has one.
vtkRenderWindowInteractor* InteractorOf(vtkProp* prop, int depth = 0)
{
  for (int i = 0; depth < 16 && i < prop->GetNumberOfConsumers(); ++i)
  {
    vtkObject* consumer = prop->GetConsumer(i);
    auto* renderer = vtkRenderer::SafeDownCast(consumer);
    vtkRenderWindow* window = renderer ? renderer->GetRenderWindow() : nullptr;
    auto* assembly = vtkProp::SafeDownCast(consumer);
    vtkRenderWindowInteractor* interactor = window ? window->GetInteractor()
      : assembly                                   ? InteractorOf(assembly, depth + 1)
                                                   : nullptr;
    if (interactor)
    {
      return interactor;
    }
  }
  return nullptr;
}

/// The mapper a vtkQuadricLODActor draws its decimated level with where its Render counts the
/// frame as interactive (the time the renderer allotted it at most 1.1 over its window's
/// interactor's desired update rate, clamped to 1 to 75), found as the mapper its LOD filter
/// feeds. Null otherwise, and before the actor has built that level.
vtkMapper* QuadricLevelDrawn(vtkQuadricLODActor* actor)
{
  vtkRenderWindowInteractor* interactor = InteractorOf(actor);
  if (!interactor || !actor->GetLODFilter())
  {
    return nullptr;
  }
  // As VTK compares them: the allotted time as a float.
  const double rate = std::min(std::max(interactor->GetDesiredUpdateRate(), 1.0), 75.0);
  const float allotted = static_cast<float>(actor->GetAllocatedRenderTime());
  if (allotted > 1.1 / rate)
  {
    return nullptr;
  }
  vtkInformation* output = actor->GetLODFilter()->GetOutputInformation(0);
  vtkInformationExecutivePortVectorKey* consumers = vtkExecutive::CONSUMERS();
  vtkExecutive** executives = consumers->GetExecutives(output);
  for (int i = 0; i < consumers->Length(output); ++i)
  {
    if (auto* level = vtkMapper::SafeDownCast(executives[i]->GetAlgorithm()))
    {
      return level;
    }
  }
  return nullptr;
}
} // namespace

vtkMapper* MapperDrawn(vtkActor* actor)
{
  vtkMapper* drawn = actor->GetMapper();
  if (auto* quadric = vtkQuadricLODActor::SafeDownCast(actor))
  {
    vtkMapper* level = drawn ? QuadricLevelDrawn(quadric) : nullptr;
    return level ? level : drawn;
  }
  auto levels = vtkLODActor::SafeDownCast(actor);
  if (!levels || !drawn)
  {
    return drawn;
  }
  // vtkLODActor::Render's choice, step for step (it depends on the levels' order as VTK's
  // does): the full mapper while it fits the time, else faster levels until one fits and then
  // slower ones that still fit.
  const double allotted = levels->GetAllocatedRenderTime();
  double drawnTime = drawn->GetTimeToDraw();
  if (drawnTime <= allotted)
  {
    return drawn;
  }
  vtkCollectionSimpleIterator it;
  vtkMapperCollection* mappers = levels->GetLODMappers();
  mappers->InitTraversal(it);
  for (vtkMapper* level; drawnTime != 0.0 && (level = mappers->GetNextMapper(it));)
  {
    const double time = level->GetTimeToDraw();
    if (time == 0.0 || (drawnTime > allotted && time < drawnTime) ||
      (time > drawnTime && time < allotted))
    {
      drawn = level;
      drawnTime = time;
    }
  }
  return drawn;
}

std::vector<vtkProp*> PropsCulledInView(const vtkRenderState* s)
{
  std::vector<vtkProp*> culled;
  vtkRenderer* renderer = s->GetRenderer();
  vtkPropCollection* props = renderer->GetViewProps();
  const int drawnCount = s->GetPropArrayCount();
  if (drawnCount >= props->GetNumberOfItems())
  {
    return culled;
  }
  std::vector<vtkProp*> drawn(s->GetPropArray(), s->GetPropArray() + drawnCount);
  std::sort(drawn.begin(), drawn.end());
  double planes[24];
  renderer->GetActiveCamera()->GetFrustumPlanes(renderer->GetTiledAspectRatio(), planes);
  vtkCollectionSimpleIterator it;
  for (props->InitTraversal(it); vtkProp* prop = props->GetNextProp(it);)
  {
    const double* bounds = prop->GetVisibility() ? prop->GetBounds() : nullptr;
    if (!bounds || !vtkMath::AreBoundsInitialized(bounds) ||
      std::binary_search(drawn.begin(), drawn.end(), prop))
    {
      continue;
    }
    const glm::dvec3 lo(bounds[0], bounds[2], bounds[4]), hi(bounds[1], bounds[3], bounds[5]);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = 0.5 * glm::length(hi - lo);
    bool outside = false;
    for (int plane = 0; plane < 6 && !outside; ++plane)
    {
      outside =
        glm::dot(glm::make_vec3(planes + 4 * plane), centre) + planes[4 * plane + 3] < -radius;
    }
    if (!outside)
    {
      culled.push_back(prop);
    }
  }
  std::sort(culled.begin(), culled.end());
  return culled;
}

std::vector<DrawnSurface> SceneWalk::Casters(
  vtkRenderer* renderer, const std::vector<vtkProp*>& culledInView, vtkObject* owner)
{
  std::vector<DrawnSurface> surfaces;
  for (vtkProp* prop : VisiblePropsInTheShadows(renderer))
  {
    if (!vtkSoftShadowPass::GetCastsShadows(prop) ||
      std::binary_search(culledInView.begin(), culledInView.end(), prop))
    {
      continue;
    }
    const std::size_t first = surfaces.size();
    for (vtkProp* drawn : PropsDrawnFor(prop))
    {
      drawn->InitPathTraversal();
      while (vtkAssemblyPath* path = drawn->GetNextPath())
      {
        vtkAssemblyNode* node = path->GetLastNode();
        if (node && node->GetViewProp())
        {
          this->Leaf(node->GetViewProp(), node->GetMatrix(), owner, surfaces);
        }
      }
    }
    for (std::size_t i = first; i < surfaces.size(); ++i)
    {
      surfaces[i].ViewProp = prop;
    }
  }
  // A matrix that flattens the surface (a zero scale) has no inverse to put the light into the
  // mesh's coordinates: such a surface is left out, said once, rather than cast wrongly.
  const auto singular = std::remove_if(surfaces.begin(), surfaces.end(),
    [this, owner](const DrawnSurface& surface)
    {
      const double determinant = glm::determinant(glm::dmat3(surface.ObjectToWorld));
      if (std::abs(determinant) > 0.0 && std::isfinite(determinant))
      {
        return false;
      }
      this->Warn(owner, surface.Actor,
        "is drawn through a singular matrix (a zero scale), which flattens it: it casts no "
        "shadow");
      return true;
    });
  surfaces.erase(singular, surfaces.end());
  this->Clipped.PurgeUnused();
  return surfaces;
}

void SceneWalk::LODLevel(
  vtkLODProp3D* levels, vtkObject* owner, std::vector<DrawnSurface>& surfaces)
{
  // VTK draws one level, a vtkActor of the prop's own at its matrix. Its pick level is that one
  // once VTK has drawn the prop (before, the most detailed): the shadow is that of what is drawn.
  vtkAbstractMapper3D* mapper = levels->GetLODMapper(levels->GetPickLODID());
  vtkNew<vtkPropCollection> actors;
  levels->GetActors(actors);
  for (int i = 0; i < actors->GetNumberOfItems(); ++i)
  {
    auto level = vtkActor::SafeDownCast(actors->GetItemAsObject(i));
    if (level && level->GetMapper() == mapper)
    {
      this->Leaf(level, levels->GetMatrix(), owner, surfaces);
      return;
    }
  }
  this->Warn(owner, levels,
    "is a vtkLODProp3D whose pick level is not a surface actor (a volume or an image): it "
    "casts no shadow");
}

void SceneWalk::Leaf(vtkProp* leaf, const vtkMatrix4x4* pathMatrix, vtkObject* owner,
  std::vector<DrawnSurface>& surfaces)
{
  if (!leaf->GetVisibility())
  {
    return;
  }
  if (auto levels = vtkLODProp3D::SafeDownCast(leaf))
  {
    this->LODLevel(levels, owner, surfaces);
    return;
  }
  auto actor = vtkActor::SafeDownCast(leaf);
  if (vtkSkybox::SafeDownCast(leaf))
  {
    return; // drawn at infinity, behind everything: nothing lies beyond it to shadow
  }
  if (!actor)
  {
    this->WarnVolumeOrSlice(leaf, owner);
    return; // 2D props and the like: overlays, nothing to cast
  }
  vtkMapper* mapper = MapperDrawn(actor);
  if (!mapper || !(actor->HasOpaqueGeometry() || actor->HasTranslucentPolygonalGeometry()))
  {
    return;
  }
  if (DrawsPointsOrOutline(vtkLODActor::SafeDownCast(actor), mapper))
  {
    this->Warn(owner, leaf,
      "is a vtkLODActor drawing its point cloud or outline, as its mapper takes longer to draw "
      "than the time the renderer allots it: it casts no shadow while it does");
    return;
  }
  this->WarnShadowUnlikeDrawing(actor, mapper, owner);
  // A path's last matrix is the composed one; a plain actor's path carries none.
  const glm::dmat4 matrix = ToGlm(pathMatrix ? pathMatrix : actor->GetMatrix());
  if (!this->DrawsTriangles(actor, mapper, owner))
  {
    return;
  }
  if (!this->Instances(actor, mapper, matrix, owner, surfaces))
  {
    this->InputSurfaces(actor, mapper, matrix, owner, surfaces);
  }
}

void SceneWalk::WarnVolumeOrSlice(vtkProp* leaf, vtkObject* owner)
{
  auto volume = vtkVolume::SafeDownCast(leaf);
  auto slice = vtkImageSlice::SafeDownCast(leaf);
  if (volume && volume->GetMapper())
  {
    this->Warn(owner, leaf,
      "is drawn but neither casts nor receives shadows: the pass does not edit volume "
      "rendering");
  }
  else if (slice && slice->GetMapper())
  {
    // Drawn by the slice mapper's own internal actor, which the pass never sees, and unlit
    // by default; a shadow on it would be the visibility image's only.
    this->Warn(owner, leaf,
      "is drawn but neither casts nor receives shadows: the pass does not edit image slices");
  }
}

void SceneWalk::WarnShadowUnlikeDrawing(vtkActor* actor, vtkMapper* mapper, vtkObject* owner)
{
  if (!actor->HasOpaqueGeometry() && actor->GetProperty()->GetOpacity() >= 1.0 &&
    !vtkCompositePolyDataMapper2::SafeDownCast(mapper))
  {
    this->Warn(owner, actor,
      "is drawn translucent with an opacity of 1 (colours with alpha, a texture or "
      "ForceTranslucent): its shadow takes the opacity, 1, and is opaque");
  }
  if (actor->HasOpaqueGeometry() && TexturesCutHoles(actor))
  {
    // VTK 9.1 draws a texture whose alpha is only 0 or 1 (cut-outs: leaves, holes) in the
    // opaque pass (ForceOpaque any texture) and discards its texels of alpha 0; the casters are
    // meshes.
    this->Warn(owner, actor,
      "has a texture with transparent texels, which VTK leaves out of the surface it draws: "
      "its shadow is that of the whole surface (cut the holes into the mesh to cast them)");
  }
}

bool SceneWalk::DrawsTriangles(vtkActor* actor, vtkMapper* mapper, vtkObject* owner)
{
  if (auto splats = vtkPointGaussianMapper::SafeDownCast(mapper))
  {
    // Splats are sprites shaded in the fragment shader, with no triangles to cast from. Lit
    // ones are drawn in VTK's opaque pass, their squares' depth written corners and all; the
    // light-intensity buffer holds one surface a pixel, theirs.
    const bool lit = !splats->GetEmissive() && actor->HasOpaqueGeometry();
    this->Warn(owner, actor,
      std::string("is drawn by ") + mapper->GetClassName() +
        ", whose imposters have no triangles: it casts no shadow" +
        (lit ? "; its splats are lit (EmissiveOff) and write their squares' depth, so the "
               "surfaces seen through their squares' corners take the splats' shadows, not "
               "their own"
             : ""));
    return false;
  }
  if (actor->GetProperty()->GetRepresentation() != VTK_SURFACE && !DrawsImposterInstances(mapper))
  {
    this->Warn(owner, actor,
      "is drawn as a wireframe or as points (vtkProperty::SetRepresentation): lines and points "
      "cast no shadow");
    return false;
  }
  if (mapper->GetNumberOfClippingPlanes() > 0 && DrawsImposterInstances(mapper))
  {
    this->Warn(owner, actor,
      std::string("has clipping planes, which shadows do not follow for the imposters of its ") +
        mapper->GetClassName() + ": it casts no shadow");
    return false;
  }
  return true;
}

void SceneWalk::InputSurfaces(vtkActor* actor, vtkMapper* mapper, const glm::dmat4& matrix,
  vtkObject* owner, std::vector<DrawnSurface>& surfaces)
{
  vtkDataObject* data = mapper->GetInputDataObject(0, 0);
  if (!data)
  {
    return;
  }
  if (ShiftedToInfinity(mapper, data))
  {
    this->Warn(owner, actor,
      "has points at infinite coordinates: VTK 9.1 shifts its vertex buffer by the points' "
      "range, which they make infinite, and draws none of it; it casts nothing");
    return;
  }
  auto composite = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
  std::size_t part = 0;
  bool opaqueAtFull = false;
  this->Blocks(actor, composite,
    composite ? composite->GetCompositeDataDisplayAttributes() : nullptr, data, matrix, true,
    actor->GetProperty()->GetOpacity(), part, opaqueAtFull, surfaces);
  if (opaqueAtFull)
  {
    this->Warn(owner, actor,
      "has blocks drawn translucent with an opacity of 1 (colours with alpha, a texture or "
      "ForceTranslucent): their shadows take the opacity, 1, and are opaque");
  }
}

void SceneWalk::Blocks(vtkActor* actor, vtkCompositePolyDataMapper2* composite,
  vtkCompositeDataDisplayAttributes* attributes, vtkDataObject* node, const glm::dmat4& matrix,
  bool visible, double opacity, std::size_t& part, bool& opaqueAtFull,
  std::vector<DrawnSurface>& surfaces)
{
  // Block attributes apply to a node and everything under it unless a child sets its own,
  // as vtkCompositePolyDataMapper2 applies them.
  if (attributes && attributes->HasBlockVisibility(node))
  {
    visible = attributes->GetBlockVisibility(node);
  }
  if (attributes && attributes->HasBlockOpacity(node))
  {
    opacity = attributes->GetBlockOpacity(node);
  }
  if (auto tree = vtkDataObjectTree::SafeDownCast(node))
  {
    for (vtkDataObject* child : vtk::Range(tree, vtk::DataObjectTreeOptions::None))
    {
      if (child)
      {
        this->Blocks(actor, composite, attributes, child, matrix, visible, opacity, part,
          opaqueAtFull, surfaces);
      }
      else
      {
        ++part; // an empty block keeps the numbering of the others
      }
    }
    return;
  }
  const std::size_t index = part++;
  // vtkCompositePolyDataMapper2 draws its polydata blocks only: other datasets show nothing.
  auto block = vtkPolyData::SafeDownCast(node);
  if (!visible || !(opacity > 0.0) || (composite && !block))
  {
    return;
  }
  // A composite mapper draws each block by its opacity and colours; otherwise the actor decides.
  const DrawnOpacity drawn =
    composite ? BlockOpacity(actor, composite, block, opacity) : ActorOpacity(actor);
  if (!(drawn.Opacity > 0.0))
  {
    return;
  }
  opaqueAtFull = opaqueAtFull || (composite && drawn.SeenThrough && drawn.Opacity >= 1.0);
  if (vtkDataObject* clipped =
        this->Clipped.Apply(actor, index, node, matrix, DrawnClippingPlanes(MapperDrawn(actor))))
  {
    surfaces.push_back({ actor, clipped, matrix, index, drawn.Opacity, drawn.SeenThrough });
  }
}

void SceneWalk::Glyphs(vtkActor* actor, vtkGlyph3DMapper* mapper, const glm::dmat4& matrix,
  vtkObject* owner, std::vector<DrawnSurface>& surfaces)
{
  const DrawnOpacity drawn = ActorOpacity(actor);
  if (!(drawn.Opacity > 0.0))
  {
    return;
  }
  std::vector<vtkDataObject*> sources = this->CastingGlyphSources(actor, mapper, owner);
  if (std::none_of(sources.begin(), sources.end(), [](vtkDataObject* s) { return s; }))
  {
    return;
  }
  const GlyphSet glyphs{ actor, matrix, drawn, GlyphSettingsOf(mapper), std::move(sources) };
  std::size_t part = 0;
  bool nonFinite = false;
  const std::size_t firstGlyph = surfaces.size();
  for (vtkDataSet* points : GlyphInputs(mapper))
  {
    if (points && !AddGlyphsAt(glyphs, mapper, points, part, nonFinite, surfaces))
    {
      return; // VTK reports it and draws nothing
    }
  }
  if (nonFinite)
  {
    this->Warn(
      owner, actor, "has glyphs whose orientation is not finite: those glyphs cast no shadow");
  }
  this->ClipGlyphs(actor, firstGlyph, surfaces);
}

std::vector<vtkDataObject*> SceneWalk::CastingGlyphSources(
  vtkActor* actor, vtkGlyph3DMapper* mapper, vtkObject* owner)
{
  std::vector<vtkDataObject*> sources = GlyphSources(mapper);
  for (vtkDataObject*& source : sources)
  {
    auto poly = vtkPolyData::SafeDownCast(source);
    if (!poly || poly->GetNumberOfPolys() + poly->GetNumberOfStrips() == 0)
    {
      this->Warn(owner, actor,
        "has a vtkGlyph3DMapper glyph source that is missing or has no surface cells (VTK's "
        "default glyph is a line): those glyphs cast no shadow");
      source = nullptr;
    }
  }
  return sources;
}

void SceneWalk::ClipGlyphs(
  vtkActor* actor, std::size_t firstGlyph, std::vector<DrawnSurface>& surfaces)
{
  const std::vector<glm::dvec4> planes = DrawnClippingPlanes(MapperDrawn(actor));
  if (planes.empty())
  {
    return;
  }
  // VTK clips each glyph where it is placed. Most glyphs lie wholly on one side of the planes:
  // they keep the shared source, or go; only those the planes run through are cut, each on its
  // own.
  std::size_t kept = firstGlyph;
  for (std::size_t i = firstGlyph; i < surfaces.size(); ++i)
  {
    DrawnSurface glyph = surfaces[i];
    auto source = vtkDataSet::SafeDownCast(glyph.Data);
    const double* bounds = source ? source->GetBounds() : nullptr;
    const ClipSide side = bounds
      ? ClipBoxByPlanes(glm::dvec3(bounds[0], bounds[2], bounds[4]),
          glm::dvec3(bounds[1], bounds[3], bounds[5]), glyph.ObjectToWorld, planes)
      : ClipSide::Cut;
    if (side == ClipSide::Removed)
    {
      continue;
    }
    if (side == ClipSide::Cut)
    {
      glyph.Data = this->Clipped.Apply(actor, glyph.Part, glyph.Data, glyph.ObjectToWorld, planes);
      if (!glyph.Data)
      {
        continue;
      }
    }
    surfaces[kept++] = glyph;
  }
  surfaces.resize(kept);
}

bool SceneWalk::Instances(vtkActor* actor, vtkMapper* mapper, const glm::dmat4& matrix,
  vtkObject* owner, std::vector<DrawnSurface>& surfaces)
{
  if (auto glyphs = vtkGlyph3DMapper::SafeDownCast(mapper))
  {
    this->Glyphs(actor, glyphs, matrix, owner, surfaces);
  }
  else if (auto spheres = vtkOpenGLSphereMapper::SafeDownCast(mapper))
  {
    this->Spheres(actor, spheres, matrix, owner, surfaces);
  }
  else if (auto sticks = vtkOpenGLStickMapper::SafeDownCast(mapper))
  {
    this->Sticks(actor, sticks, matrix, owner, surfaces);
  }
  else if (auto molecule = vtkOpenGLMoleculeMapper::SafeDownCast(mapper))
  {
    this->Molecule(actor, molecule, matrix, owner, surfaces);
  }
  else
  {
    return false;
  }
  return true;
}

void SceneWalk::Spheres(vtkActor* actor, vtkOpenGLSphereMapper* mapper, const glm::dmat4& matrix,
  vtkObject* owner, std::vector<DrawnSurface>& surfaces)
{
  const DrawnOpacity drawn = ActorOpacity(actor);
  vtkPolyData* centres = DrawnCentres(actor, mapper, drawn);
  if (!centres)
  {
    return;
  }
  if (!this->UnitSphere)
  {
    this->UnitSphere = NewPolyData(ImposterSphereMesh(32));
  }
  // As the mapper: every point is a sphere, of the named array's radius where the input has
  // it, else of the mapper's Radius.
  const char* scaleName = mapper->*SphereArrays::Scale;
  vtkDataArray* radii = scaleName ? centres->GetPointData()->GetArray(scaleName) : nullptr;
  if (radii && !LaidOutAsVTKReadsIt(radii, 1, centres->GetNumberOfPoints()))
  {
    this->Warn(owner, actor,
      "has a radius array that is not one float per point (VTK misreads it): its imposter "
      "spheres cast no shadow");
    return;
  }
  const bool placedAll = AddInstances(
    actor, drawn, this->UnitSphere, centres,
    [&](vtkIdType id, const glm::dvec3& centre, glm::dmat4& sphere)
    {
      const double radius = radii ? radii->GetComponent(id, 0) : mapper->GetRadius();
      return ImposterSphereMatrix(matrix, centre, radius, sphere);
    },
    surfaces);
  if (!placedAll)
  {
    this->Warn(owner, actor,
      "has imposter spheres whose centre is not finite or whose radius is not positive and "
      "finite: those spheres cast no shadow");
  }
}

void SceneWalk::Sticks(vtkActor* actor, vtkOpenGLStickMapper* mapper, const glm::dmat4& matrix,
  vtkObject* owner, std::vector<DrawnSurface>& surfaces)
{
  const DrawnOpacity drawn = ActorOpacity(actor);
  vtkPolyData* centres = DrawnCentres(actor, mapper, drawn);
  if (!centres)
  {
    return;
  }
  // As the mapper: every point is a stick, its length (VTK's length(orientMC): the first
  // component's magnitude times the orientation's norm) and radius the first two components of
  // the scale array, its axis the orientation array (VTK needs both, and fails without).
  const char* scaleName = mapper->*StickArrays::Scale;
  const char* orientationName = mapper->*StickArrays::Orientation;
  vtkDataArray* sizes = scaleName ? centres->GetPointData()->GetArray(scaleName) : nullptr;
  vtkDataArray* axes =
    orientationName ? centres->GetPointData()->GetArray(orientationName) : nullptr;
  const vtkIdType count = centres->GetNumberOfPoints();
  if (!sizes || !axes || !LaidOutAsVTKReadsIt(sizes, 3, count) ||
    !LaidOutAsVTKReadsIt(axes, 3, count))
  {
    this->Warn(owner, actor,
      "is drawn by vtkOpenGLStickMapper without a scale array (length, radius, unused) and an "
      "orientation array of three floats per point: its sticks cast no shadow");
    return;
  }
  if (!this->UnitStick)
  {
    this->UnitStick = NewPolyData(ImposterStickMesh(24));
  }
  const bool placedAll = AddInstances(
    actor, drawn, this->UnitStick, centres,
    [&](vtkIdType id, const glm::dvec3& centre, glm::dmat4& stick)
    {
      double axis[3];
      axes->GetTuple(id, axis);
      const glm::dvec3 orientation = glm::make_vec3(axis);
      return ImposterStickMatrix(matrix, centre, orientation,
        std::abs(sizes->GetComponent(id, 0)) * glm::length(orientation), sizes->GetComponent(id, 1),
        stick);
    },
    surfaces);
  if (!placedAll)
  {
    this->Warn(owner, actor,
      "has imposter sticks whose centre or axis is not finite, or whose length or radius is not "
      "positive and finite: those sticks cast no shadow");
  }
}

void SceneWalk::Molecule(vtkActor* actor, vtkOpenGLMoleculeMapper* mapper, const glm::dmat4& matrix,
  vtkObject* owner, std::vector<DrawnSurface>& surfaces)
{
  // The molecule mapper draws with these two (its glyph data made while VTK drew the frame's
  // depth, before the casters are walked).
  vtkOpenGLSphereMapper* atoms = mapper->GetFastAtomMapper();
  if (mapper->GetRenderAtoms())
  {
    this->Spheres(actor, atoms, matrix, owner, surfaces);
  }
  const std::size_t firstBond = surfaces.size();
  if (mapper->GetRenderBonds())
  {
    this->Sticks(actor, &*(mapper->*MoleculeParts::Bonds), matrix, owner, surfaces);
  }
  // Atoms and bonds are parts of one actor: the bonds number theirs after every atom's.
  const std::size_t atomCount =
    atoms->GetInput() ? static_cast<std::size_t>(atoms->GetInput()->GetNumberOfPoints()) : 0;
  for (std::size_t i = firstBond; i < surfaces.size(); ++i)
  {
    surfaces[i].Part += atomCount;
  }
}

void SceneWalk::Warn(vtkObject* owner, vtkProp* prop, const std::string& reason)
{
  if (this->Warned.First(prop, reason))
  {
    vtkWarningWithObjectMacro(
      owner, << prop->GetClassName() << " (" << prop << ") " << reason << ".");
  }
}

} // namespace penumbra
