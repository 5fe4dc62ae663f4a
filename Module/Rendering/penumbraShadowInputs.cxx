#include "penumbraShadowInputs.h"

#include "penumbraSceneWalk.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkAlgorithmOutput.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCommand.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataObject.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkImageProperty.h"
#include "vtkImageSlice.h"
#include "vtkInformation.h"
#include "vtkLODActor.h"
#include "vtkLODProp3D.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp3D.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkShaderProperty.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowPass.h"
#include "vtkTexture.h"
#include "vtkUniforms.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace penumbra
{

namespace
{
vtkAbstractMapper* MapperOf(vtkProp* leaf)
{
  if (auto actor = vtkActor::SafeDownCast(leaf))
  {
    return MapperDrawn(actor);
  }
  if (auto slice = vtkImageSlice::SafeDownCast(leaf))
  {
    return slice->GetMapper();
  }
  return nullptr;
}

/// vtkOpenGLPolyDataMapper's shader code and replacements set through its deprecated API, which
/// its time records and no getter shows (the member is protected; reached through a derived
/// class's pointer to it).
struct LegacyShaders : vtkOpenGLPolyDataMapper
{
  static bool Of(vtkOpenGLPolyDataMapper* mapper)
  {
    return mapper->*(&LegacyShaders::LegacyShaderProperty) != nullptr;
  }
};

/// Whether `actor`'s colours can change what VTK draws of it, not only how it looks: custom
/// shader code may read them; VTK drops fragments of alpha 0 even from an actor forced opaque,
/// or through a texture with alpha (which VTK may not count as translucency, and whose name,
/// coordinates and interpolation decide where it applies). Otherwise colours with alpha make
/// the actor translucent, or a composite mapper's block (AddBlockShapes), which is recorded.
bool ColoursShapeIt(vtkActor* actor)
{
  auto mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper());
  return actor->GetForceOpaque() || HasCustomShaders(actor) ||
    (mapper && LegacyShaders::Of(mapper)) || TexturesMayOpenHoles(actor);
}

/// What of an actor's look can change its shadows or the depth they are drawn against: whether
/// VTK draws it opaque or seen through and by what opacity, what of it VTK draws and how wide
/// (representation, culling, edges, line widths and point sizes) and its lighting (its textures
/// are recorded with every actor). Colours, lighting coefficients and PBR terms change neither, so
/// changing only them reuses the shadows; the receivers' shading is VTK's own draw, done every
/// frame.
void AddDrawnLook(ShadowInputs& inputs, vtkActor* actor)
{
  // Colours with alpha (scalars, a lookup table, a texture) make an actor translucent.
  inputs.Add(
    static_cast<double>(actor->HasOpaqueGeometry() + 2 * actor->HasTranslucentPolygonalGeometry()));
  inputs.Add(static_cast<double>(actor->GetForceOpaque() + 2 * actor->GetForceTranslucent()));
  for (vtkProperty* property : { actor->GetProperty(), actor->GetBackfaceProperty() })
  {
    inputs.Add(property);
    if (!property)
    {
      continue;
    }
    inputs.Add(glm::dvec4(property->GetOpacity(), property->GetRepresentation(),
      property->GetBackfaceCulling() + 2 * property->GetFrontfaceCulling(),
      property->GetLighting()));
    inputs.Add(glm::dvec4(property->GetLineWidth(), property->GetPointSize(),
      property->GetEdgeVisibility() + 2 * property->GetVertexVisibility(),
      property->GetRenderLinesAsTubes() + 2 * property->GetRenderPointsAsSpheres()));
    // A mapper's selection is drawn with the surface, into the depth; its alpha 0 is dropped.
    inputs.Add(glm::dvec4(property->GetSelectionPointSize(), property->GetSelectionLineWidth(),
      property->GetSelectionColor()[3], 0.0));
  }
}

/// What places and picks a glyph mapper's glyphs (penumbra::SceneWalk::Glyphs reads the same):
/// scaling, orientation, source indexing, masking, the arrays chosen for them, the source table.
void AddGlyphPlacement(ShadowInputs& inputs, vtkGlyph3DMapper* glyphs)
{
  const double* range = glyphs->GetRange();
  inputs.Add(glm::dvec4(
    glyphs->GetScaling(), glyphs->GetScaleMode(), glyphs->GetScaleFactor(), glyphs->GetClamping()));
  inputs.Add(glm::dvec4(range[0], range[1], glyphs->GetOrient(), glyphs->GetOrientationMode()));
  inputs.Add(glm::dvec4(glyphs->GetSourceIndexing(), glyphs->GetMasking(),
    glyphs->GetUseSourceTableTree(), glyphs->GetUseSelectionIds()));
  vtkDataObjectTree* table = glyphs->GetSourceTableTree();
  inputs.Add(table);
  inputs.AddTime(table ? table->GetMTime() : 0);
  for (int array : { vtkGlyph3DMapper::SCALE, vtkGlyph3DMapper::SOURCE_INDEX,
         vtkGlyph3DMapper::MASK, vtkGlyph3DMapper::ORIENTATION })
  {
    // SetScaleArray and its kin set these (SetInputArrayToProcess), which the times record.
    vtkInformation* chosen = glyphs->GetInputArrayInformation(array);
    inputs.Add(chosen);
    inputs.AddTime(chosen ? chosen->GetMTime() : 0);
  }
}

/// What of `mapper` can change the shape or depth VTK draws, for the mappers whose settings are
/// known (VTK 9.1's polydata, composite polydata, dataset and glyph mappers) of an actor whose
/// colours shape nothing (not ColoursShapeIt): their time moves with colour settings too
/// (scalar range, lookup table, colour array), which change nothing of the shadows but
/// translucency, recorded with the actor (AddDrawnLook). Returns false for any other mapper: its
/// time is recorded instead.
bool AddDrawnShape(ShadowInputs& inputs, vtkMapper* mapper)
{
  auto polyMapper = vtkOpenGLPolyDataMapper::SafeDownCast(mapper);
  auto glyphs = vtkGlyph3DMapper::SafeDownCast(mapper);
  const bool known = IsExactly(mapper, "vtkOpenGLPolyDataMapper") ||
    IsExactly(mapper, "vtkCompositePolyDataMapper2") || IsExactly(mapper, "vtkDataSetMapper") ||
    IsExactly(mapper, "vtkOpenGLGlyph3DMapper");
  if (!known)
  {
    return false;
  }
  if (glyphs)
  {
    AddGlyphPlacement(inputs, glyphs);
  }
  double polygon[2], line[2], point;
  mapper->GetRelativeCoincidentTopologyPolygonOffsetParameters(polygon[0], polygon[1]);
  mapper->GetRelativeCoincidentTopologyLineOffsetParameters(line[0], line[1]);
  mapper->GetRelativeCoincidentTopologyPointOffsetParameter(point);
  inputs.Add(glm::dvec4(polygon[0], polygon[1], line[0], line[1]));
  inputs.Add(glm::dvec4(
    point, mapper->GetStatic(), polyMapper ? polyMapper->GetVBOShiftScaleMethod() : -1, 0.0));
  if (auto pieces = vtkPolyDataMapper::SafeDownCast(mapper))
  {
    inputs.Add(glm::dvec4(pieces->GetPiece(), pieces->GetNumberOfPieces(),
      pieces->GetNumberOfSubPieces(), pieces->GetGhostLevel()));
    inputs.Add(static_cast<double>(pieces->GetSeamlessU() + 2 * pieces->GetSeamlessV()));
  }
  vtkSelection* selection = mapper->GetSelection();
  inputs.Add(selection);
  inputs.AddTime(selection ? selection->GetMTime() : 0);
  vtkPlaneCollection* planes = mapper->GetClippingPlanes();
  inputs.Add(planes);
  inputs.AddTime(planes ? planes->GetMTime() : 0); // planes added or removed
  return true;
}

/// Every node's visibility and opacity where `blocks` sets one, as the composite mappers read
/// them (the nearest node that sets one decides), and for a `composite` mapper whether each
/// block's colours are opaque, by which it sorts blocks into VTK's opaque and translucent passes;
/// block colours change no shadow.
void AddBlockShapes(ShadowInputs& inputs, vtkCompositeDataDisplayAttributes* blocks,
  vtkDataObject* data, vtkCompositePolyDataMapper2* composite = nullptr)
{
  inputs.Add(blocks);
  if (!data || (!blocks && !composite))
  {
    return;
  }
  const auto addNode = [&](vtkDataObject* node)
  {
    inputs.Add(node);
    if (blocks)
    {
      inputs.Add(blocks->HasBlockVisibility(node) ? blocks->GetBlockVisibility(node) : -1.0);
      inputs.Add(blocks->HasBlockOpacity(node) ? blocks->GetBlockOpacity(node) : -1.0);
    }
    auto block = vtkPolyData::SafeDownCast(node);
    if (composite && block)
    {
      inputs.Add(static_cast<double>(BlockColoursOpaque(composite, block)));
    }
  };
  addNode(data); // keyed by the input itself too, tree or not
  if (auto tree = vtkDataObjectTree::SafeDownCast(data))
  {
    for (vtkDataObject* node : vtk::Range(tree, vtk::DataObjectTreeOptions::TraverseSubTree))
    {
      addNode(node);
    }
  }
}

void AddShadowKeys(ShadowInputs& inputs, vtkProp* prop)
{
  inputs.Add(static_cast<double>(vtkSoftShadowPass::GetCastsShadows(prop)));
  inputs.Add(static_cast<double>(vtkSoftShadowPass::GetReceivesShadows(prop)));
  inputs.Add(static_cast<double>(vtkSoftShadowPass::GetShadowPlane(prop)));
}

/// The times of `leaf` that AddLeaf records. A prop of its own: its time (an actor whose look is
/// recorded by value: its vtkProp3D time, without its properties'). An assembly's part, whose
/// own time moves every frame: its properties' times, unless its look is recorded by value.
void AddLeafTimes(ShadowInputs& inputs, vtkProp* leaf, vtkActor* actor, bool part, bool lookByValue)
{
  if (!part)
  {
    inputs.AddTime(lookByValue ? actor->vtkProp3D::GetMTime() : leaf->GetMTime());
  }
  else if (actor && !lookByValue)
  {
    inputs.AddTime(actor->GetProperty()->GetMTime());
    inputs.AddTime(actor->GetBackfaceProperty() ? actor->GetBackfaceProperty()->GetMTime() : 0);
  }
}

/// Each of `actor`'s textures with the times of it and its image.
void AddTextures(ShadowInputs& inputs, vtkActor* actor)
{
  // A texture's alpha makes the actor translucent or opens holes in it (VTK drops fragments
  // of alpha 0), and its image can change (edited in place) without the texture's time or
  // the actor's moving.
  for (vtkTexture* texture : TexturesOf(actor))
  {
    vtkImageData* image = texture->GetInput();
    inputs.Add(texture);
    inputs.AddTime(texture->GetMTime());
    inputs.AddTime(image ? image->GetMTime() : 0);
  }
}

/// The times of `actor`'s shader property and of its custom uniforms, which the property's
/// does not follow.
void AddShaderTimes(ShadowInputs& inputs, vtkActor* actor)
{
  vtkShaderProperty* shaders = actor->GetShaderProperty();
  inputs.AddTime(shaders->GetMTime());
  inputs.AddTime(shaders->GetVertexCustomUniforms()->GetMTime());
  inputs.AddTime(shaders->GetGeometryCustomUniforms()->GetMTime());
  inputs.AddTime(shaders->GetFragmentCustomUniforms()->GetMTime());
}

/// What of `actor` itself changes what VTK draws: its look by value where `withLook`
/// (AddDrawnLook), its textures and its shaders.
void AddActorDrawing(ShadowInputs& inputs, vtkActor* actor, bool withLook)
{
  if (withLook)
  {
    AddDrawnLook(inputs, actor);
  }
  AddTextures(inputs, actor);
  AddShaderTimes(inputs, actor);
}

/// The time of each of `mapper`'s clipping planes: the collection's time does not follow its
/// planes'.
void AddClippingPlaneTimes(ShadowInputs& inputs, vtkAbstractMapper* mapper)
{
  if (vtkPlaneCollection* planes = mapper->GetClippingPlanes())
  {
    vtkCollectionSimpleIterator planeIt;
    planes->InitTraversal(planeIt);
    while (vtkPlane* plane = planes->GetNextPlane(planeIt))
    {
      inputs.AddTime(plane->GetMTime());
    }
  }
}

/// The block attributes of the mappers that read them (AddBlockShapes).
void AddMapperBlocks(ShadowInputs& inputs, vtkAbstractMapper* mapper)
{
  if (auto composite = vtkCompositePolyDataMapper2::SafeDownCast(mapper))
  {
    AddBlockShapes(inputs, composite->GetCompositeDataDisplayAttributes(),
      composite->GetInputDataObject(0, 0), composite);
  }
  if (auto glyphs = vtkGlyph3DMapper::SafeDownCast(mapper))
  {
    AddBlockShapes(inputs, glyphs->GetBlockAttributes(), glyphs->GetInputDataObject(0, 0));
  }
}

/// `data` (null too) with its time, and each leaf of composite data with its own.
void AddInputData(ShadowInputs& inputs, vtkDataObject* data)
{
  inputs.Add(data);
  if (!data)
  {
    return;
  }
  inputs.AddTime(data->GetMTime());
  if (auto composite = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> block;
    block.TakeReference(composite->NewIterator());
    for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
    {
      vtkDataObject* leafData = block->GetCurrentDataObject();
      inputs.Add(leafData);
      inputs.AddTime(leafData ? leafData->GetMTime() : 0);
    }
  }
}

/// `mapper` with its settings (by value where `lookByValue` and AddDrawnShape knows them, else
/// its time), clipping planes, block attributes and input data. False where an UpdateShaderEvent
/// observer may change what it draws without any of that changing.
bool AddMapper(ShadowInputs& inputs, vtkAbstractMapper* mapper, bool lookByValue)
{
  if (mapper->HasObserver(vtkCommand::UpdateShaderEvent))
  {
    return false; // its observer may move vertices through uniforms, frame by frame
  }
  inputs.Add(mapper);
  if (!lookByValue || !AddDrawnShape(inputs, vtkMapper::SafeDownCast(mapper)))
  {
    inputs.AddTime(mapper->GetMTime());
  }
  AddClippingPlaneTimes(inputs, mapper);
  AddMapperBlocks(inputs, mapper);
  // The inputs are up to date (UpdateMapperInputs).
  for (int port = 0; port < mapper->GetNumberOfInputPorts(); ++port)
  {
    for (int connection = 0; connection < mapper->GetNumberOfInputConnections(port); ++connection)
    {
      AddInputData(inputs, mapper->GetInputDataObject(port, connection));
    }
  }
  return true;
}

/// Whether every entry of `a` and `b` differs by at most 1e-7 of the largest magnitude in its
/// row of either (false for NaN): a clip-space row scaled by that much moves a point in view by
/// about 1e-7 of the viewport, and a depth by about one 24-bit step.
bool NearlyEqualRows(const glm::dmat4& a, const glm::dmat4& b)
{
  for (int row = 0; row < 4; ++row)
  {
    double scale = 0.0;
    for (int column = 0; column < 4; ++column)
    {
      scale = std::max({ scale, std::abs(a[column][row]), std::abs(b[column][row]) });
    }
    for (int column = 0; column < 4; ++column)
    {
      if (!(std::abs(a[column][row] - b[column][row]) <= 1e-7 * scale))
      {
        return false;
      }
    }
  }
  return true;
}

/// Runs the producer of each input connection of `algorithm`.
void UpdateInputs(vtkAlgorithm* algorithm)
{
  for (int port = 0; port < algorithm->GetNumberOfInputPorts(); ++port)
  {
    for (int connection = 0; connection < algorithm->GetNumberOfInputConnections(port);
         ++connection)
    {
      vtkAlgorithmOutput* output = algorithm->GetInputConnection(port, connection);
      if (output && output->GetProducer())
      {
        output->GetProducer()->Update(output->GetIndex());
      }
    }
  }
}

} // namespace

void ShadowInputs::Begin()
{
  this->Current.clear();
  this->WorldToClip = glm::dmat4(0.0);
}

void ShadowInputs::Add(const void* object)
{
  this->Current.push_back(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(object)));
}

void ShadowInputs::Add(double value)
{
  // The bits, not the value: -0 and NaN compare as themselves.
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  this->Current.push_back(bits);
}

void ShadowInputs::Add(const glm::dmat4& matrix)
{
  for (int column = 0; column < 4; ++column)
  {
    this->Add(matrix[column]);
  }
}

void ShadowInputs::Add(const glm::dvec4& vector)
{
  for (int i = 0; i < 4; ++i)
  {
    this->Add(vector[i]);
  }
}

void ShadowInputs::AddTime(vtkMTimeType time)
{
  this->Current.push_back(static_cast<std::uint64_t>(time));
}

void ShadowInputs::AddCoincidentTopologySettings()
{
  // Static, so in no object's time; they offset the depth of every mapper's polygons and lines.
  double polygonFactor, polygonUnits, lineFactor, lineUnits, pointUnits;
  vtkMapper::GetResolveCoincidentTopologyPolygonOffsetParameters(polygonFactor, polygonUnits);
  vtkMapper::GetResolveCoincidentTopologyLineOffsetParameters(lineFactor, lineUnits);
  vtkMapper::GetResolveCoincidentTopologyPointOffsetParameter(pointUnits);
  this->Add(glm::dvec4(vtkMapper::GetResolveCoincidentTopology(),
    vtkMapper::GetResolveCoincidentTopologyPolygonOffsetFaces(),
    vtkMapper::GetResolveCoincidentTopologyZShift(), pointUnits));
  this->Add(glm::dvec4(polygonFactor, polygonUnits, lineFactor, lineUnits));
}

bool ShadowInputs::AddProps(vtkRenderer* renderer)
{
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (OutsideTheShadows(prop))
    {
      continue;
    }
    this->Add(prop);
    this->Add(static_cast<double>(prop->GetVisibility()));
    if (!prop->GetVisibility())
    {
      continue;
    }
    // The scene walk reads an assembly's keys on the assembly, not on its parts.
    AddShadowKeys(*this, prop);
    // What VTK draws for it, as the scene walk takes it: a vtkAxesActor's shafts, whose
    // properties the axes' time does not follow. Such a prop places its parts only as VTK
    // draws them, after this record: it goes in as a leaf of its own too (time and matrix).
    const std::vector<vtkProp*> drawn = PropsDrawnFor(prop);
    if ((drawn.size() != 1 || drawn.front() != prop) && !this->AddLeaf(prop, nullptr, false))
    {
      return false;
    }
    for (vtkProp* part : drawn)
    {
      if (!this->AddPaths(part))
      {
        return false;
      }
    }
  }
  return true;
}

bool ShadowInputs::AddPaths(vtkProp* prop)
{
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkAssemblyNode* node = path->GetLastNode();
    vtkMatrix4x4* matrix = node->GetMatrix();
    if (!this->AddLeaf(
          node->GetViewProp(), matrix ? matrix->GetData() : nullptr, path->GetNumberOfItems() > 1))
    {
      return false;
    }
  }
  return true;
}

bool ShadowInputs::AddLeaf(vtkProp* leaf, const double* pathMatrix, bool part)
{
  if (vtkLODActor::SafeDownCast(leaf) || vtkLODProp3D::SafeDownCast(leaf))
  {
    // They pick their level by render time, which modifies nothing.
    return false;
  }
  this->Add(leaf);
  this->Add(static_cast<double>(leaf->GetVisibility()));
  AddShadowKeys(*this, leaf);
  // An assembly modifies its parts as it draws them (vtkProp3D::PokeMatrix): a part's time moves
  // every frame, so its parts are recorded by what they are made of instead. A plain actor's
  // time moves with its property's colours too: its look is recorded by value where colours
  // cannot change what VTK draws.
  auto actor = vtkActor::SafeDownCast(leaf);
  const bool lookByValue =
    actor && (part || IsExactly(actor, "vtkOpenGLActor")) && !ColoursShapeIt(actor);
  AddLeafTimes(*this, leaf, actor, part, lookByValue);
  if (auto prop3D = vtkProp3D::SafeDownCast(leaf))
  {
    // Values: a user transform or matrix may change without the prop's time moving.
    this->Add(glm::make_mat4(pathMatrix ? pathMatrix : prop3D->GetMatrix()->GetData()));
  }
  if (actor)
  {
    AddActorDrawing(*this, actor, lookByValue || part);
  }
  auto slice = vtkImageSlice::SafeDownCast(leaf);
  if (part && slice)
  {
    this->AddTime(slice->GetProperty()->GetMTime());
  }
  vtkAbstractMapper* mapper = MapperOf(leaf);
  return !mapper || AddMapper(*this, mapper, lookByValue);
}

void UpdateMapperInputs(vtkRenderer* renderer)
{
  for (vtkProp* prop : VisiblePropsInTheShadows(renderer))
  {
    for (vtkProp* part : PropsDrawnFor(prop))
    {
      part->InitPathTraversal();
      while (vtkAssemblyPath* path = part->GetNextPath())
      {
        vtkAbstractMapper* mapper = MapperOf(path->GetLastNode()->GetViewProp());
        auto staticMapper = vtkMapper::SafeDownCast(mapper);
        if (mapper && !(staticMapper && staticMapper->GetStatic()))
        {
          UpdateInputs(mapper);
        }
        // A texture's source runs only as VTK loads it, after the record reads its image.
        if (auto actor = vtkActor::SafeDownCast(path->GetLastNode()->GetViewProp()))
        {
          for (vtkTexture* texture : TexturesOf(actor))
          {
            UpdateInputs(texture);
          }
        }
      }
    }
  }
}

bool ShadowInputs::MatchKept() const
{
  return this->HaveKept && this->Current == this->Kept &&
    NearlyEqualRows(this->WorldToClip, this->KeptWorldToClip);
}

void ShadowInputs::Keep()
{
  this->Kept = this->Current;
  this->KeptWorldToClip = this->WorldToClip;
  this->HaveKept = true;
}

void ShadowInputs::Forget()
{
  this->HaveKept = false;
  this->Kept.clear();
}

} // namespace penumbra
