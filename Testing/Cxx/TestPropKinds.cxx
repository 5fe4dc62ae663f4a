// Every kind of prop VTK draws casts and receives as VTK draws it: glyph mappers (direction and
// rotation orientation, source indexing, masking), composite data (block visibility and opacity,
// nested and empty blocks), assemblies (composed matrices, parts that receive), props that draw
// through actors of their own (vtkAxesActor, vtkAnnotatedCubeActor) and imposter spheres and
// sticks.
//
// Each scene is rendered twice with hard shadows at a non-square 400 x 250: once with the prop
// kind and once built from plain actors the way VTK's own filters build it (vtkGlyph3D, one
// actor per block, the assembly's matrices as user matrices). Tolerances: at most 0.2% of the
// pixels differ in visibility by more than 0.5 and at most 0.5% in colour by more than 8 of 255
// (rasterization of the same triangles drawn by different mappers); against the ray-traced truth,
// CheckAgainstTruth's 0.2%. Then what cannot cast: one warning per prop and reason, and the rest of
// the scene still shadows.
#include "penumbraTestHarness.h"

#include "vtkAnnotatedCubeActor.h"
#include "vtkAssembly.h"
#include "vtkAxesActor.h"
#include "vtkBitArray.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkClipPolyData.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkConeSource.h"
#include "vtkCubeAxesActor.h"
#include "vtkCylinderSource.h"
#include "vtkDataSetMapper.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkDelaunay3D.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkFollower.h"
#include "vtkGlyph3D.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkLODActor.h"
#include "vtkLODProp3D.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMolecule.h"
#include "vtkMoleculeMapper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkOpenGLStickMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProp3DCollection.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkQuadricClustering.h"
#include "vtkQuadricLODActor.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkShaderProperty.h"
#include "vtkSkybox.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

using namespace penumbra_test;

namespace
{
constexpr int Width = 400, Height = 250;

/// The tests' pass scene (its light at (-2, 6, 3)) with hard shadows and a fixed camera.
struct View : PassScene
{
  View()
    : PassScene(Width, Height)
  {
    this->Renderer->SetBackground(0.2, 0.2, 0.25);
    this->Window->SetMultiSamples(0);
    this->Pass->SetMethodToHardVolumes();
  }

  void Render()
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(3.0, 5.0, 8.0);
    camera->SetFocalPoint(0.0, 0.5, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    this->Renderer->ResetCameraClippingRange(-4, 4, -1, 4, -4, 4);
    this->Window->Render();
  }

  std::vector<float> Visibility() { return ImageValues(this->Pass->GetVisibilityImage(0)); }

  std::vector<unsigned char> Colours() { return WindowColours(this->Window, this->Renderer); }
};

vtkSmartPointer<vtkActor> Ground(vtkRenderer* renderer)
{
  auto ground = MakeActor(GroundSource(4.0), 0.85, 0.85, 0.8);
  renderer->AddActor(ground);
  return ground;
}

/// Light 0's hard visibility (one ray a pixel) as the ray tracer sees the view's scene; empty
/// when it could not trace.
std::vector<float> TruthOf(View& view)
{
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(view.Renderer);
  truth->SetSamplesPerLight(1);
  return truth->Update() ? ImageValues(truth->GetVisibilityImage(0)) : std::vector<float>();
}

/// Renders `kind` and `plain` alike and checks that they agree, and `kind` with the truth.
void CompareScenes(const std::string& name, const std::function<void(vtkRenderer*)>& kind,
  const std::function<void(vtkRenderer*)>& plain, double visibilityTolerance = 0.002,
  double colourTolerance = 0.005)
{
  View a, b;
  const WarningLog warnings(a.Pass);
  kind(a.Renderer);
  plain(b.Renderer);
  a.Render();
  b.Render();
  const std::vector<float> va = a.Visibility(), vb = b.Visibility();
  const std::vector<unsigned char> ca = a.Colours(), cb = b.Colours();
  int visibilityOff = 0, colourOff = 0, shadowed = 0;
  for (std::size_t i = 0; i < va.size(); ++i)
  {
    visibilityOff += std::abs(va[i] - vb[i]) > 0.5f;
    shadowed += vb[i] < 0.5f;
  }
  for (std::size_t i = 0; i < ca.size(); i += 3)
  {
    int worst = 0;
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(int(ca[i + c]) - int(cb[i + c])));
    }
    colourOff += worst > 8;
  }
  const double pixels = double(Width) * Height;
  std::printf("%-40s shadowed %6d px; visibility differs on %.3f%%, colour on %.3f%%\n",
    name.c_str(), shadowed, 100.0 * visibilityOff / pixels, 100.0 * colourOff / pixels);
  Check(shadowed > pixels / 50, name + ": the plain scene has shadow in view");
  Check(
    visibilityOff <= visibilityTolerance * pixels, name + ": shadows as its plain-actor scene's");
  Check(colourOff <= colourTolerance * pixels, name + ": colours as its plain-actor scene's");
  CheckAgainstTruth(name, CompareWithTruth(a.Window, a.Renderer, a.Pass, 0));
  for (const std::string& w : warnings.Messages)
  {
    std::printf("     warning: %s", w.c_str());
  }
  Check(warnings.Messages.empty(), name + ": no warning");

  // The truth walks each kind of prop its own way (vtkGlyph3D, the leaves, the path's matrix):
  // it must see the kind's scene as it sees the plain one.
  const std::vector<float> ta = TruthOf(a), tb = TruthOf(b);
  const int truthOff = PixelsApart(ta, tb);
  Check(!ta.empty() && ta.size() == tb.size() && truthOff <= visibilityTolerance * pixels,
    name + ": the truth sees it as the plain-actor scene (" + std::to_string(truthOff) +
      " px differ)");

  // It receives: where its shadows are, the image is darker than with shadows off.
  a.Pass->ShadowsEnabledOff();
  a.Render();
  const std::vector<unsigned char> unshadowed = a.Colours();
  a.Pass->ShadowsEnabledOn();
  a.Render();
  const std::vector<unsigned char> shadowedColours = a.Colours();
  int inShadow = 0, darker = 0;
  for (std::size_t i = 0; i < va.size() && 3 * va.size() == unshadowed.size(); ++i)
  {
    if (va[i] < 0.5f)
    {
      ++inShadow;
      const std::size_t c = 3 * i;
      darker += shadowedColours[c] + shadowedColours[c + 1] + shadowedColours[c + 2] + 15 <
        unshadowed[c] + unshadowed[c + 1] + unshadowed[c + 2];
    }
  }
  Check(darker >= inShadow / 2,
    name + ": its shadows are in the image (" + std::to_string(darker) + " of " +
      std::to_string(inShadow) + " shadowed px darker than unshadowed)");
}

//------------------------------------------------------------------------------
/// Twelve points above the ground, with a size and a direction each.
vtkSmartPointer<vtkPolyData> GlyphPoints()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> size, direction, angles, index, stretch;
  size->SetName("size");
  stretch->SetName("stretch");
  stretch->SetNumberOfComponents(3);
  direction->SetName("direction");
  direction->SetNumberOfComponents(3);
  angles->SetName("angles");
  angles->SetNumberOfComponents(3);
  index->SetName("index");
  vtkNew<vtkBitArray> mask;
  mask->SetName("mask");
  for (int i = 0; i < 12; ++i)
  {
    const double x = -1.5 + (i % 4), z = -1.0 + (i / 4);
    points->InsertNextPoint(x, 1.0 + 0.1 * (i % 3), z);
    size->InsertNextValue(0.5 + 0.08 * i);
    direction->InsertNextTuple3(1.0, 0.3 * (i % 5) - 0.6, 0.2 * (i % 3));
    angles->InsertNextTuple3(15.0 * i, 40.0 - 7.0 * i, 25.0 * (i % 4));
    index->InsertNextValue(i % 2);
    stretch->InsertNextTuple3(0.4 + 0.05 * i, 1.2 - 0.06 * i, 0.5 + 0.1 * (i % 3));
    mask->InsertNextValue(i % 5 != 3);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->GetPointData()->AddArray(size);
  poly->GetPointData()->AddArray(direction);
  poly->GetPointData()->AddArray(angles);
  poly->GetPointData()->AddArray(index);
  poly->GetPointData()->AddArray(mask);
  poly->GetPointData()->AddArray(stretch);
  return poly;
}

/// An actor (of type A) drawing `mapper`, lit as MakeActor's, for mappers MakeActor does not make.
template <typename A = vtkActor>
vtkSmartPointer<A> LitActor(vtkMapper* mapper)
{
  auto actor = vtkSmartPointer<A>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.2);
  actor->GetProperty()->SetDiffuse(0.8);
  return actor;
}

vtkSmartPointer<vtkConeSource> Cone()
{
  auto cone = vtkSmartPointer<vtkConeSource>::New();
  cone->SetResolution(12);
  cone->SetHeight(1.0);
  cone->SetRadius(0.3);
  return cone;
}

/// The second glyph source of the glyph scenes: a flat box.
vtkSmartPointer<vtkCubeSource> GlyphBox()
{
  return BoxSource(0.0, 0.0, 0.0, 0.6, 0.25, 0.4);
}

/// Adds a vtkGlyph3D's output as a plain actor, uncoloured (vtkGlyph3D colours by scale; the
/// glyph mapper does not).
void AddGlyphFilter(vtkRenderer* renderer, vtkGlyph3D* glyphs)
{
  auto actor = MakeActor(glyphs, 1, 1, 1);
  actor->GetMapper()->ScalarVisibilityOff();
  renderer->AddActor(actor);
}

/// A glyph mapper over `points` with two sources (index 0 and 1).
vtkSmartPointer<vtkGlyph3DMapper> TwoSourceGlyphs(
  vtkPolyData* points, vtkAlgorithm* first, vtkAlgorithm* second)
{
  auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
  mapper->SetInputData(points);
  mapper->SetSourceConnection(0, first->GetOutputPort());
  mapper->SetSourceConnection(1, second->GetOutputPort());
  return mapper;
}

/// Cones at `points`, along their "direction", scaled by their "size" times 0.8, as a glyph
/// mapper draws them: the mapper, for an actor at (0.2, 0.1, -0.1).
vtkSmartPointer<vtkGlyph3DMapper> DirectedCones(vtkPolyData* points, vtkAlgorithm* cone)
{
  auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
  mapper->SetInputData(points);
  mapper->SetSourceConnection(cone->GetOutputPort());
  mapper->SetOrientationArray("direction");
  mapper->SetScaleArray("size");
  mapper->SetScaleModeToScaleByMagnitude();
  mapper->SetScaleFactor(0.8);
  return mapper;
}

/// The same cones as vtkGlyph3D builds them (to be drawn at the same actor position).
vtkSmartPointer<vtkGlyph3D> DirectedConesByFilter(vtkPolyData* points, vtkAlgorithm* cone)
{
  auto glyphs = vtkSmartPointer<vtkGlyph3D>::New();
  glyphs->SetInputData(points);
  glyphs->SetSourceConnection(cone->GetOutputPort());
  glyphs->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "size");
  glyphs->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "direction");
  glyphs->SetScaleModeToScaleByScalar();
  glyphs->SetVectorModeToUseVector();
  glyphs->SetScaleFactor(0.8);
  return glyphs;
}

void TestGlyphsByDirection()
{
  vtkSmartPointer<vtkPolyData> points = GlyphPoints();
  auto cone = Cone();
  CompareScenes(
    "glyph mapper, direction and size",
    [&](vtkRenderer* r)
    {
      Ground(r);
      auto actor = LitActor(DirectedCones(points, cone));
      actor->SetPosition(0.2, 0.1, -0.1); // the actor's matrix applies to every glyph
      r->AddActor(actor);
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      auto actor = MakeActor(DirectedConesByFilter(points, cone), 1, 1, 1);
      actor->GetMapper()->ScalarVisibilityOff(); // vtkGlyph3D colours by scale; the mapper does not
      actor->SetPosition(0.2, 0.1, -0.1);
      r->AddActor(actor);
    });
}

void TestGlyphsOfCompositeInput()
{
  // Composite input: a glyph mapper draws each leaf's points, except a leaf whose block
  // visibility is off. The hidden block, in view, must cast nothing.
  vtkSmartPointer<vtkPolyData> shown = GlyphPoints();
  vtkSmartPointer<vtkPolyData> hidden = GlyphPoints();
  vtkNew<vtkTransform> shift;
  shift->Translate(0.3, 0.0, 2.2);
  vtkNew<vtkPoints> moved;
  shift->TransformPoints(hidden->GetPoints(), moved);
  hidden->SetPoints(moved);
  auto cone = Cone();
  CompareScenes(
    "glyph mapper, composite input, a hidden block",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkMultiBlockDataSet> blocks;
      blocks->SetBlock(0, shown);
      blocks->SetBlock(1, hidden);
      vtkNew<vtkCompositeDataDisplayAttributes> attributes;
      attributes->SetBlockVisibility(hidden, false);
      vtkNew<vtkGlyph3DMapper> mapper;
      mapper->SetInputDataObject(blocks);
      mapper->SetBlockAttributes(attributes);
      mapper->SetSourceConnection(cone->GetOutputPort());
      mapper->SetOrientationArray("direction");
      r->AddActor(LitActor(mapper));
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkGlyph3D> glyphs;
      glyphs->SetInputData(shown);
      glyphs->SetSourceConnection(cone->GetOutputPort());
      glyphs->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "direction");
      glyphs->SetScaleModeToDataScalingOff();
      glyphs->SetVectorModeToUseVector();
      AddGlyphFilter(r, glyphs);
    });
}

void TestGlyphsByDirectionAndIndex(bool clamping)
{
  // Direction, sizes (clamped to a range, or not), two sources picked by an index: the mapper
  // clamps with Range and picks by the index value, so the plain scene is one vtkGlyph3D per
  // source, each over the points that pick it. (vtkGlyph3D reads sizes and indices from one
  // array: the truth must not build these with one.)
  vtkSmartPointer<vtkPolyData> points = GlyphPoints();
  auto cone = Cone();
  auto box = GlyphBox();
  const double range[2] = { 0.4, 1.1 }, factor = 0.9;
  CompareScenes(
    clamping ? "glyph mapper, direction, clamping, index" : "glyph mapper, direction, index",
    [&](vtkRenderer* r)
    {
      Ground(r);
      auto mapper = TwoSourceGlyphs(points, cone, box);
      mapper->SetOrientationArray("direction");
      mapper->SetScaleArray("size");
      mapper->SetScaleModeToScaleByMagnitude();
      mapper->SetClamping(clamping);
      mapper->SetRange(range[0], range[1]);
      mapper->SetScaleFactor(factor);
      mapper->SourceIndexingOn();
      mapper->SetSourceIndexArray("index");
      r->AddActor(LitActor(mapper));
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      for (const int picked : { 0, 1 })
      {
        auto subset = vtkSmartPointer<vtkPolyData>::New();
        vtkNew<vtkPoints> kept;
        subset->GetPointData()->CopyAllocate(points->GetPointData());
        for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
        {
          if (points->GetPointData()->GetArray("index")->GetTuple1(i) == picked)
          {
            subset->GetPointData()->CopyData(
              points->GetPointData(), i, kept->InsertNextPoint(points->GetPoint(i)));
          }
        }
        subset->SetPoints(kept);
        vtkNew<vtkGlyph3D> glyphs;
        glyphs->SetInputData(subset);
        glyphs->SetSourceConnection(picked ? box->GetOutputPort() : cone->GetOutputPort());
        glyphs->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "size");
        glyphs->SetInputArrayToProcess(
          1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "direction");
        glyphs->SetScaleModeToScaleByScalar();
        glyphs->SetVectorModeToUseVector();
        glyphs->SetClamping(clamping);
        glyphs->SetRange(range[0], range[1]);
        glyphs->SetScaleFactor(factor);
        AddGlyphFilter(r, glyphs);
      }
    });
}

void TestGlyphsByRotation()
{
  // Rotation angles, two sources picked by an index array, masked points: one plain actor per
  // glyph with the rotation VTK documents (z, then x, then y).
  vtkSmartPointer<vtkPolyData> points = GlyphPoints();
  auto cone = Cone();
  auto box = GlyphBox();
  CompareScenes(
    "glyph mapper, rotation, index, mask",
    [&](vtkRenderer* r)
    {
      Ground(r);
      auto mapper = TwoSourceGlyphs(points, cone, box);
      mapper->SetOrientationModeToRotation();
      mapper->SetOrientationArray("angles");
      mapper->SetScaling(false);
      mapper->SourceIndexingOn();
      mapper->SetSourceIndexArray("index");
      mapper->MaskingOn();
      mapper->SetMaskArray("mask");
      auto actor = LitActor(mapper);
      r->AddActor(actor);
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        if (i % 5 == 3)
        {
          continue; // masked
        }
        double angles[3];
        points->GetPointData()->GetArray("angles")->GetTuple(i, angles);
        vtkNew<vtkTransform> transform;
        transform->Translate(points->GetPoint(i));
        transform->RotateZ(angles[2]);
        transform->RotateX(angles[0]);
        transform->RotateY(angles[1]);
        auto actor = MakeActor(i % 2 ? static_cast<vtkAlgorithm*>(box) : cone, 1, 1, 1);
        actor->SetUserTransform(transform);
        r->AddActor(actor);
      }
    });
}

void TestGlyphsByQuaternionTableAndClamping()
{
  // Unit quaternions (w, x, y, z), sources from a source table tree picked by an index array,
  // sizes clamped to a range and mapped onto [0, 1] before the scale factor, as VTK 9.1's
  // vtkOpenGLGlyph3DMapper does: one plain actor per glyph, built with vtkTransform.
  vtkSmartPointer<vtkPolyData> points = GlyphPoints();
  vtkNew<vtkDoubleArray> quaternions;
  quaternions->SetName("quaternion");
  quaternions->SetNumberOfComponents(4);
  std::vector<std::pair<double, glm::dvec3>> rotations;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    const double degrees = 25.0 * static_cast<double>(i);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1.0, 0.5 * (i % 3), 0.4 * (i % 2) - 0.2));
    const double half = vtkMath::RadiansFromDegrees(degrees) / 2.0;
    quaternions->InsertNextTuple4(
      std::cos(half), std::sin(half) * axis.x, std::sin(half) * axis.y, std::sin(half) * axis.z);
    rotations.emplace_back(degrees, axis);
  }
  points->GetPointData()->AddArray(quaternions);
  auto cone = Cone();
  auto box = GlyphBox();
  cone->Update();
  box->Update();
  vtkNew<vtkMultiBlockDataSet> table;
  table->SetBlock(0, cone->GetOutput());
  table->SetBlock(1, box->GetOutput());
  const double range[2] = { 0.4, 1.2 }, factor = 0.9;
  CompareScenes(
    "glyph mapper, quaternions, source table, clamping",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkGlyph3DMapper> mapper;
      mapper->SetInputData(points);
      mapper->SetUseSourceTableTree(true);
      mapper->SetSourceTableTree(table);
      mapper->SourceIndexingOn();
      mapper->SetSourceIndexArray("index");
      mapper->SetOrientationModeToQuaternion();
      mapper->SetOrientationArray("quaternion");
      mapper->SetScaleArray("size");
      mapper->SetScaleModeToScaleByMagnitude();
      mapper->ClampingOn();
      mapper->SetRange(range[0], range[1]);
      mapper->SetScaleFactor(factor);
      r->AddActor(LitActor(mapper));
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkDataArray* sizes = points->GetPointData()->GetArray("size");
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        const double size = std::min(std::max(sizes->GetTuple1(i), range[0]), range[1]);
        const double scale = factor * (size - range[0]) / (range[1] - range[0]);
        const auto& rotation = rotations[static_cast<std::size_t>(i)];
        vtkNew<vtkTransform> transform;
        transform->Translate(points->GetPoint(i));
        transform->RotateWXYZ(
          rotation.first, rotation.second.x, rotation.second.y, rotation.second.z);
        transform->Scale(scale, scale, scale);
        auto actor = MakeActor(i % 2 ? static_cast<vtkAlgorithm*>(box) : cone, 1, 1, 1);
        actor->SetUserTransform(transform);
        r->AddActor(actor);
      }
    });
}

void TestGlyphsStretchedAndDirected()
{
  // Scaled by the components of one array and turned along another: vtkGlyph3D has one vector
  // array for both, so the truth must not build these with it.
  vtkSmartPointer<vtkPolyData> points = GlyphPoints();
  auto cone = Cone();
  cone->Update();
  const double factor = 1.3;
  CompareScenes(
    "glyph mapper, component scales, directions",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkGlyph3DMapper> mapper;
      mapper->SetInputData(points);
      mapper->SetSourceConnection(cone->GetOutputPort());
      mapper->SetOrientationArray("direction");
      mapper->SetScaleArray("stretch");
      mapper->SetScaleModeToScaleByVectorComponents();
      mapper->SetScaleFactor(factor);
      r->AddActor(LitActor(mapper));
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkDataArray* directions = points->GetPointData()->GetArray("direction");
      vtkDataArray* stretches = points->GetPointData()->GetArray("stretch");
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        // The mapper turns x onto the direction by a half turn about their bisector.
        double d[3], s[3];
        directions->GetTuple(i, d);
        stretches->GetTuple(i, s);
        vtkNew<vtkTransform> transform;
        transform->Translate(points->GetPoint(i));
        transform->RotateWXYZ(180.0, d[0] + vtkMath::Norm(d), d[1], d[2]);
        transform->Scale(factor * s[0], factor * s[1], factor * s[2]);
        auto actor = MakeActor(cone, 1, 1, 1);
        actor->SetUserTransform(transform);
        r->AddActor(actor);
      }
    });
}

//------------------------------------------------------------------------------
void TestMultiBlock()
{
  // Blocks: a sphere, a nested multiblock (a box, an empty block, a hidden sphere), a
  // translucent box. Hidden blocks cast nothing, the translucent one casts by its block opacity
  // (its shadow lets 0.36 through, far enough from the lit 1 for the comparison's 0.5); the
  // rest cast and receive.
  auto sphere = SphereSource(-0.9, 1.0, 0.0, 0.6, 32, 16);
  auto box = BoxSource(1.0, 0.7, 0.3, 0.7, 1.0, 0.7);
  auto hidden = SphereSource(0.0, 1.5, -1.0, 0.5, 24, 12);
  auto glass = BoxSource(0.2, 1.6, 1.2, 0.5, 0.2, 0.5);
  for (vtkAlgorithm* source : std::vector<vtkAlgorithm*>{ sphere, box, hidden, glass })
  {
    source->Update();
  }
  auto data = [](vtkAlgorithm* a) { return vtkPolyData::SafeDownCast(a->GetOutputDataObject(0)); };
  vtkNew<vtkMultiBlockDataSet> nested;
  nested->SetBlock(0, data(box));
  nested->SetBlock(1, nullptr);
  nested->SetBlock(2, data(hidden));
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, data(sphere));
  blocks->SetBlock(1, nested);
  blocks->SetBlock(2, data(glass));

  CompareScenes(
    "multiblock with hidden, empty, translucent blocks",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkCompositePolyDataMapper2> mapper;
      mapper->SetInputDataObject(blocks);
      vtkNew<vtkCompositeDataDisplayAttributes> attributes;
      attributes->SetBlockVisibility(data(hidden), false);
      attributes->SetBlockOpacity(data(glass), 0.4);
      mapper->SetCompositeDataDisplayAttributes(attributes);
      mapper->ScalarVisibilityOff();
      r->AddActor(LitActor(mapper));
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      r->AddActor(MakeActor(sphere, 1, 1, 1));
      r->AddActor(MakeActor(box, 1, 1, 1));
      auto translucent = MakeActor(glass, 1, 1, 1);
      translucent->GetProperty()->SetOpacity(0.4);
      r->AddActor(translucent);
    });
}

//------------------------------------------------------------------------------
/// A plane through `origin` keeping the side `normal` points to.
vtkSmartPointer<vtkPlane> KeepPlane(
  double ox, double oy, double oz, double nx, double ny, double nz)
{
  auto plane = vtkSmartPointer<vtkPlane>::New();
  plane->SetOrigin(ox, oy, oz);
  plane->SetNormal(nx, ny, nz);
  return plane;
}

/// The surface `placed` draws when its mapper clips by `planes`, built the long way: `source`
/// moved to world coordinates by the actor's matrix (vtkTransformPolyDataFilter), then cut by
/// each world plane (vtkClipPolyData), drawn by an actor at the identity. vtkClipPolyData
/// merges coincident points, so a box's corners keep one face's normal: `faceted` puts each
/// face's normal back (vtkPolyDataNormals, split at the box's edges).
vtkSmartPointer<vtkActor> ClippedByFilters(vtkAlgorithm* source, vtkActor* placed,
  const std::vector<vtkPlane*>& planes, bool faceted = false)
{
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(placed->GetMatrix());
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetTransform(transform);
  moved->SetInputConnection(source->GetOutputPort());
  vtkSmartPointer<vtkAlgorithm> last = moved.Get();
  for (vtkPlane* plane : planes)
  {
    vtkNew<vtkClipPolyData> clip;
    clip->SetClipFunction(plane);
    clip->SetInputConnection(last->GetOutputPort());
    last = clip.Get();
  }
  if (faceted)
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(last->GetOutputPort());
    normals->SplittingOn();
    normals->ConsistencyOff();
    normals->AutoOrientNormalsOff();
    last = normals.Get();
  }
  return MakeActor(last, 1, 1, 1);
}

void TestClippingPlanes()
{
  // A sphere cut open at the top and a box cut open at one side, each moved and turned by its
  // actor (so that the data's coordinates are not the world's): VTK draws only the kept parts,
  // whose shadows fall through the openings onto the insides. The planes miss every vertex, so
  // the cut leaves no zero-area triangle to warn about.
  auto sphere = SphereSource(0.0, 1.1, 0.0, 0.8, 32, 16);
  auto box = BoxSource(0.0, 0.8, 0.0, 0.9, 1.2, 0.9);
  auto top = KeepPlane(0.0, 1.37, 0.0, 0.2, -1.0, 0.15);
  auto side = KeepPlane(1.23, 0.0, 0.27, 0.3, 0.1, -1.0);
  auto lid = KeepPlane(0.0, 1.13, 0.0, 0.1, -1.0, -0.2);
  auto place = [](vtkActor* actor, double x, double angle)
  {
    actor->SetPosition(x, 0.1, 0.2);
    actor->RotateY(angle);
  };
  CompareScenes(
    "clipping planes (a cut sphere, a cut box)",
    [&](vtkRenderer* r)
    {
      Ground(r);
      auto bowl = MakeActor(sphere, 1, 1, 1);
      place(bowl, -0.9, 25.0);
      bowl->GetMapper()->AddClippingPlane(top);
      r->AddActor(bowl);
      auto open = MakeActor(box, 1, 1, 1);
      place(open, 1.2, -20.0);
      open->GetMapper()->AddClippingPlane(side);
      open->GetMapper()->AddClippingPlane(lid);
      r->AddActor(open);
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      auto bowl = MakeActor(sphere, 1, 1, 1);
      place(bowl, -0.9, 25.0);
      r->AddActor(ClippedByFilters(sphere, bowl, { top }));
      auto open = MakeActor(box, 1, 1, 1);
      place(open, 1.2, -20.0);
      r->AddActor(ClippedByFilters(box, open, { side, lid }, true));
    });

  // The same through vtkCompositePolyDataMapper2, which hands its planes to each block.
  sphere->Update();
  box->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, sphere->GetOutput());
  blocks->SetBlock(1, box->GetOutput());
  auto split = KeepPlane(0.0, 0.0, 0.31, 0.15, 0.05, -1.0);
  CompareScenes(
    "clipping planes of a composite mapper",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkCompositePolyDataMapper2> mapper;
      mapper->SetInputDataObject(blocks);
      mapper->ScalarVisibilityOff();
      mapper->AddClippingPlane(split);
      auto actor = LitActor(mapper);
      place(actor, 0.3, 15.0);
      r->AddActor(actor);
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkActor> placed;
      place(placed, 0.3, 15.0);
      r->AddActor(ClippedByFilters(sphere, placed, { split }));
      r->AddActor(ClippedByFilters(box, placed, { split }, true));
    });

  // Glyphs: VTK clips each where it is placed. The plane runs through some cones, above some
  // and below others.
  vtkSmartPointer<vtkPolyData> points = GlyphPoints();
  auto cone = Cone();
  auto slant = KeepPlane(0.0, 1.05, 0.0, 0.25, -1.0, 0.1);
  CompareScenes(
    "clipping planes of a glyph mapper",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkSmartPointer<vtkGlyph3DMapper> mapper = DirectedCones(points, cone);
      mapper->AddClippingPlane(slant);
      auto actor = LitActor(mapper);
      actor->SetPosition(0.2, 0.1, -0.1);
      r->AddActor(actor);
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkActor> placed;
      placed->SetPosition(0.2, 0.1, -0.1);
      auto actor = ClippedByFilters(DirectedConesByFilter(points, cone), placed, { slant });
      actor->GetMapper()->ScalarVisibilityOff();
      r->AddActor(actor);
    });

  // Soft shadows: averaged and counted hard shadows drew dark "ghosts" of the clipped-away
  // parts (volumes open where VTK draws no depth); with the cut casters each equals the plain
  // scene's.
  for (const int method : { vtkSoftShadowPass::METHOD_AVERAGED_HARD_SHADOWS,
         vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES })
  {
    View clipped, plain;
    for (View* view : { &clipped, &plain })
    {
      view->Pass->SetMethod(method);
      view->Pass->SetLightSamples(16);
      vtkSoftShadowPass::SetLightRadius(view->Light, 0.3);
      Ground(view->Renderer);
    }
    auto bowl = MakeActor(sphere, 1, 1, 1);
    place(bowl, -0.9, 25.0);
    bowl->GetMapper()->AddClippingPlane(top);
    clipped.Renderer->AddActor(bowl);
    plain.Renderer->AddActor(ClippedByFilters(sphere, bowl, { top }));
    clipped.Render();
    plain.Render();
    const int apart = PixelsApart(clipped.Visibility(), plain.Visibility());
    std::printf("clipping planes, %s: %d px differ by more than 0.5 from the cut scene\n",
      clipped.Pass->GetMethodAsString(), apart);
    Check(apart <= 0.002 * Width * Height,
      std::string("clipping planes, ") + clipped.Pass->GetMethodAsString() +
        ": shadows as the cut scene's");
  }

  // Moving a plane between frames moves the shadow: the cut is redone, not kept.
  View moving, fresh;
  Ground(moving.Renderer);
  Ground(fresh.Renderer);
  auto cut = KeepPlane(0.0, 1.37, 0.0, 0.2, -1.0, 0.15);
  auto lowered = KeepPlane(0.0, 0.93, 0.0, 0.2, -1.0, 0.15);
  auto bowl = MakeActor(sphere, 1, 1, 1);
  bowl->GetMapper()->AddClippingPlane(cut);
  moving.Renderer->AddActor(bowl);
  auto lowBowl = MakeActor(sphere, 1, 1, 1);
  lowBowl->GetMapper()->AddClippingPlane(lowered);
  fresh.Renderer->AddActor(lowBowl);
  moving.Render();
  const std::vector<float> before = moving.Visibility();
  cut->SetOrigin(lowered->GetOrigin());
  moving.Render();
  fresh.Render();
  const int moved = PixelsApart(before, moving.Visibility());
  const int apart = PixelsApart(moving.Visibility(), fresh.Visibility());
  std::printf(
    "moving a clipping plane: %d px change; %d px differ from a fresh render\n", moved, apart);
  Check(moved > Width * Height / 200, "moving a clipping plane changes the shadow");
  Check(apart <= 0.002 * Width * Height, "the moved plane shadows as a fresh render of it");
}

//------------------------------------------------------------------------------
void TestAssembly()
{
  // A moved, turned and scaled assembly of a ground, a sphere and a box: its parts cast onto
  // and receive from each other at the composed matrices.
  auto groundSource = GroundSource(3.0);
  auto sphereSource = SphereSource(0.0, 0.0, 0.0, 0.6, 32, 16);
  auto boxSource = BoxSource(0.0, 0.0, 0.0, 0.7, 1.0, 0.7);
  auto build = [&](vtkRenderer* r, bool flatten)
  {
    auto ground = MakeActor(groundSource, 0.85, 0.85, 0.8);
    auto sphere = MakeActor(sphereSource, 0.9, 0.3, 0.3);
    sphere->SetPosition(-0.9, 1.0, 0.0);
    auto box = MakeActor(boxSource, 0.3, 0.6, 0.9);
    box->SetPosition(1.0, 0.6, 0.3);
    box->RotateY(30.0);
    vtkNew<vtkAssembly> assembly;
    assembly->AddPart(ground);
    assembly->AddPart(sphere);
    assembly->AddPart(box);
    assembly->SetPosition(0.3, -0.2, 0.1);
    assembly->RotateY(-20.0);
    assembly->SetScale(1.1);
    // A vtkPropAssembly around the assembly and one more actor, at its own matrix.
    auto extra = MakeActor(SphereSource(0.0, 0.0, 0.0, 0.35, 24, 12), 0.4, 0.8, 0.4);
    extra->SetPosition(0.2, 1.7, -0.8);
    if (!flatten)
    {
      // Bad input: a part without a mapper draws nothing in VTK, so it casts nothing and the
      // rest of the assembly is as without it. (A null part crashes VTK 9.1 itself, with or
      // without the pass: vtkAssembly::AddPart(nullptr) is not checked.)
      vtkNew<vtkActor> unmapped;
      assembly->AddPart(unmapped);
      vtkNew<vtkPropAssembly> props;
      props->AddPart(assembly);
      props->AddPart(extra);
      r->AddViewProp(props);
      return;
    }
    r->AddActor(extra);
    for (vtkActor* part : { ground.Get(), sphere.Get(), box.Get() })
    {
      vtkNew<vtkMatrix4x4> composed;
      vtkMatrix4x4::Multiply4x4(assembly->GetMatrix(), part->GetMatrix(), composed);
      vtkNew<vtkActor> flat;
      flat->SetMapper(part->GetMapper());
      flat->SetProperty(part->GetProperty());
      flat->SetUserMatrix(composed);
      r->AddActor(flat);
    }
  };
  CompareScenes(
    "prop assembly: an assembly and an actor", [&](vtkRenderer* r) { build(r, false); },
    [&](vtkRenderer* r) { build(r, true); });
}

//------------------------------------------------------------------------------
/// Colour tolerance where both scenes draw with the same mappers: only a part that does not
/// receive (or casts elsewhere) can change a colour.
constexpr double SameMappers = 0.0005;

/// A plain actor drawing `part`'s mapper and property at `matrix`: VTK's own drawing of the part,
/// without the prop that places it.
void AddPlainCopy(vtkRenderer* renderer, vtkActor* part, vtkMatrix4x4* matrix)
{
  vtkNew<vtkMatrix4x4> placed;
  placed->DeepCopy(matrix);
  vtkNew<vtkActor> copy;
  copy->SetMapper(part->GetMapper());
  copy->SetProperty(part->GetProperty());
  copy->SetVisibility(part->GetVisibility());
  copy->SetUserMatrix(placed);
  renderer->AddActor(copy);
}

/// Draws `prop` once in `renderer`'s window, so that VTK places its parts, and takes it out.
void LetVTKPlace(vtkRenderer* renderer, vtkProp* prop)
{
  renderer->AddViewProp(prop);
  renderer->GetRenderWindow()->Render();
  renderer->RemoveViewProp(prop);
}

/// Compares the prop `makeProp` makes, on the ground under a ball that shadows it, with the same
/// scene built from its parts: `copyParts(renderer, prop)` adds them as plain actors once VTK
/// has drawn the prop and so placed them.
template <typename MakeProp, typename CopyParts>
void CompareWithPlacedParts(
  const std::string& name, vtkAlgorithm* ball, const MakeProp& makeProp, const CopyParts& copyParts)
{
  auto groundAndBall = [&](vtkRenderer* r)
  {
    Ground(r);
    r->AddActor(MakeActor(ball, 0.9, 0.3, 0.3));
  };
  CompareScenes(
    name,
    [&](vtkRenderer* r)
    {
      groundAndBall(r);
      r->AddViewProp(makeProp());
    },
    [&](vtkRenderer* r)
    {
      groundAndBall(r);
      auto prop = makeProp();
      LetVTKPlace(r, prop);
      copyParts(r, prop.Get());
    },
    0.002, SameMappers);
}

void TestAxesActor()
{
  // A vtkAxesActor with cylinder shafts, moved by a user transform: VTK draws its shafts and tips
  // as actors of its own, placed only when it draws them. They cast from the first frame, where
  // VTK draws them (the plain scene: each part's mapper at the matrix VTK drew it with), and
  // receive the shadow of a ball above them.
  auto ball = SphereSource(-1.5, 1.9, 0.5, 0.3, 24, 12);
  auto makeAxes = []
  {
    auto axes = vtkSmartPointer<vtkAxesActor>::New();
    axes->SetShaftTypeToCylinder();
    axes->SetCylinderRadius(0.2);
    axes->SetConeRadius(0.5);
    axes->SetTotalLength(2.2, 1.8, 2.2);
    vtkNew<vtkTransform> place;
    place->Translate(-0.8, 0.4, -0.2);
    place->RotateY(25.0);
    axes->SetUserTransform(place);
    axes->AxisLabelsOff(); // 2D captions: they neither cast nor receive, and would only differ
    return axes;
  };
  CompareWithPlacedParts("vtkAxesActor (cylinder shafts, user transform)", ball, makeAxes,
    [](vtkRenderer* r, vtkAxesActor* axes)
    {
      vtkNew<vtkPropCollection> parts;
      axes->GetActors(parts);
      for (int i = 0; i < parts->GetNumberOfItems(); ++i)
      {
        auto part = vtkActor::SafeDownCast(parts->GetItemAsObject(i));
        AddPlainCopy(r, part, part->GetMatrix());
      }
    });
}

void TestAnnotatedCube()
{
  // A vtkAnnotatedCubeActor, placed through its assembly (VTK ignores the cube actor's own
  // matrix): its cube and face letters cast at the assembly's composed matrices, and its faces
  // receive the shadow of a ball above it.
  auto ball = SphereSource(0.0, 2.2, 0.9, 0.35, 24, 12);
  auto makeCube = []
  {
    auto cube = vtkSmartPointer<vtkAnnotatedCubeActor>::New();
    cube->SetTextEdgesVisibility(false); // lines: they cast nothing, with a warning
    cube->SetFaceTextScale(0.4);
    cube->GetAssembly()->SetPosition(0.6, 1.0, 0.2);
    cube->GetAssembly()->RotateY(30.0);
    cube->GetAssembly()->SetScale(1.1);
    return cube;
  };
  CompareWithPlacedParts("vtkAnnotatedCubeActor", ball, makeCube,
    [](vtkRenderer* r, vtkAnnotatedCubeActor* cube)
    {
      vtkAssembly* assembly = cube->GetAssembly();
      vtkProp3DCollection* parts = assembly->GetParts();
      for (int i = 0; i < parts->GetNumberOfItems(); ++i)
      {
        auto part = vtkActor::SafeDownCast(parts->GetItemAsObject(i));
        vtkNew<vtkMatrix4x4> composed;
        vtkMatrix4x4::Multiply4x4(assembly->GetMatrix(), part->GetMatrix(), composed);
        AddPlainCopy(r, part, composed);
      }
    });
}

void TestCubeAxes()
{
  // A vtkCubeAxesActor draws its axes, ticks and grid lines through actors of its own, which
  // take the pass's keys from it: VTK draws those lines unlit by design, so nothing is said
  // (eleven warnings before, one for each of them).
  View view;
  Ground(view.Renderer);
  view.Renderer->AddActor(MakeActor(SphereSource(-0.9, 1.0, 0.0, 0.6, 32, 16), 0.9, 0.3, 0.3));
  vtkNew<vtkCubeAxesActor> cubeAxes;
  cubeAxes->SetBounds(-1.5, -0.3, 0.4, 1.6, -0.6, 0.6);
  cubeAxes->SetCamera(view.Renderer->GetActiveCamera());
  cubeAxes->DrawXGridlinesOn();
  cubeAxes->DrawYGridlinesOn();
  view.Renderer->AddActor(cubeAxes);
  const WarningLog log(view.Pass);
  view.Render();
  view.Render();
  for (const std::string& w : log.Messages)
  {
    std::printf("     warning: %s", w.c_str());
  }
  Check(log.Count("without lighting") == 0, "vtkCubeAxesActor's lines: no warning");
}

void TestUnlitPartsWarn()
{
  // Unlit actors drawn for the renderer's props warn once each: assembly parts, and a
  // vtkLODActor's and a vtkFollower's device actors, which draw with their property. Finding
  // the parts walked the assembly's paths while VTK drew them, which rebuilt them under VTK's
  // loop (freed memory read; ctest runs this with MALLOC_PERTURB_ set).
  View view;
  Ground(view.Renderer);
  vtkNew<vtkAssembly> assembly;
  for (int i = 0; i < 6; ++i)
  {
    auto part = MakeActor(SphereSource(-1.5 + 0.6 * i, 1.0, 0.0, 0.25, 16, 8), 0.9, 0.3, 0.3);
    part->GetProperty()->SetLighting(i % 2 == 0);
    assembly->AddPart(part);
  }
  view.Renderer->AddActor(assembly);
  vtkNew<vtkLODActor> levels;
  levels->SetMapper(MakeActor(SphereSource(-1.0, 0.5, 1.5, 0.3, 16, 8), 1, 1, 1)->GetMapper());
  levels->GetProperty()->LightingOff();
  view.Renderer->AddActor(levels);
  vtkNew<vtkFollower> follower;
  follower->SetMapper(MakeActor(SphereSource(1.0, 0.5, 1.5, 0.3, 16, 8), 1, 1, 1)->GetMapper());
  follower->SetCamera(view.Renderer->GetActiveCamera());
  follower->GetProperty()->LightingOff();
  view.Renderer->AddActor(follower);
  const WarningLog log(view.Pass);
  view.Render();
  view.Render();
  Check(log.Count("Lighting off") == 5,
    "three unlit assembly parts, a vtkLODActor and a vtkFollower: one warning each");
}

//------------------------------------------------------------------------------
void TestLODActor()
{
  // A vtkLODActor (VTK may draw a coarser level while interacting): it casts from its full
  // mapper's data, as the same data in a plain actor does.
  auto sphere = SphereSource(-0.9, 1.0, 0.0, 0.6, 32, 16);
  auto box = BoxSource(1.0, 0.6, 0.3, 0.7, 1.2, 0.7);
  CompareScenes(
    "vtkLODActor",
    [&](vtkRenderer* r)
    {
      Ground(r);
      for (vtkAlgorithm* source : std::vector<vtkAlgorithm*>{ sphere, box })
      {
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(source->GetOutputPort());
        r->AddActor(LitActor<vtkLODActor>(mapper));
      }
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      r->AddActor(MakeActor(sphere, 1, 1, 1));
      r->AddActor(MakeActor(box, 1, 1, 1));
    });
}

/// A polydata mapper whose draws take the time it is told: VTK times them with timer queries,
/// which would make the level a vtkLODActor draws depend on this machine.
class FixedTimeMapper : public vtkOpenGLPolyDataMapper
{
public:
  static FixedTimeMapper* New();
  vtkTypeMacro(FixedTimeMapper, vtkOpenGLPolyDataMapper);
  void SetSeconds(double seconds) { this->TimeToDraw = this->Seconds = seconds; }
  void RenderPiece(vtkRenderer* renderer, vtkActor* actor) override
  {
    this->Superclass::RenderPiece(renderer, actor);
    this->TimeToDraw = this->Seconds;
  }

private:
  double Seconds = 0.0001;
};
vtkStandardNewMacro(FixedTimeMapper);

/// A vtkLODActor whose full mapper (`full`) takes a second to draw and whose one added level
/// (`coarse`) takes 10 microseconds.
vtkSmartPointer<vtkLODActor> SlowLODActor(vtkAlgorithm* full, vtkAlgorithm* coarse)
{
  vtkNew<FixedTimeMapper> fullMapper;
  fullMapper->SetInputConnection(full->GetOutputPort());
  fullMapper->SetSeconds(1.0);
  auto levels = LitActor<vtkLODActor>(fullMapper);
  if (coarse)
  {
    vtkNew<FixedTimeMapper> coarseMapper;
    coarseMapper->SetInputConnection(coarse->GetOutputPort());
    coarseMapper->SetSeconds(1e-5);
    levels->AddLODMapper(coarseMapper);
  }
  return levels;
}

void TestLODActorLevels()
{
  // A vtkLODActor whose full mapper is slower than the time allotted to it draws a level added
  // with AddLODMapper (here a slab in place of a sphere): it casts the level VTK draws.
  auto sphere = SphereSource(-0.9, 1.0, 0.0, 0.6, 32, 16);
  auto slab = BoxSource(-0.9, 1.0, 0.0, 1.4, 0.3, 1.4);
  auto box = BoxSource(1.0, 0.6, 0.3, 0.7, 1.2, 0.7);
  for (bool hurried : { false, true })
  {
    // The renderer allots each prop 1/(rate * props) seconds.
    const double rate = hurried ? 1000.0 : 0.0001;
    CompareScenes(
      std::string("vtkLODActor drawing its ") + (hurried ? "added level" : "mapper"),
      [&](vtkRenderer* r)
      {
        r->GetRenderWindow()->SetDesiredUpdateRate(rate);
        Ground(r);
        r->AddActor(SlowLODActor(sphere, slab));
        r->AddActor(MakeActor(box, 1, 1, 1));
      },
      [&](vtkRenderer* r)
      {
        Ground(r);
        r->AddActor(MakeActor(hurried ? static_cast<vtkAlgorithm*>(slab) : sphere, 1, 1, 1));
        r->AddActor(MakeActor(box, 1, 1, 1));
      });
  }

  // Without added levels it draws a cloud of points of its own, made on its first draw: no
  // shadow then, and one warning.
  View hurried, plain;
  const WarningLog warnings(hurried.Pass);
  Ground(hurried.Renderer);
  hurried.Renderer->AddActor(SlowLODActor(sphere, nullptr));
  hurried.Renderer->AddActor(MakeActor(box, 1, 1, 1));
  hurried.Render(); // at VTK's default rate: the full mapper, timed
  const std::vector<float> full = hurried.Visibility();
  hurried.Window->SetDesiredUpdateRate(1000.0);
  hurried.Render();
  hurried.Render();
  Ground(plain.Renderer);
  plain.Renderer->AddActor(MakeActor(box, 1, 1, 1));
  plain.Render();
  const int apart = PixelsApart(hurried.Visibility(), plain.Visibility());
  const int sphereShadow = PixelsApart(full, plain.Visibility());
  std::printf("vtkLODActor drawing its points: %d px off the scene without it (its full "
              "shadow: %d px)\n",
    apart, sphereShadow);
  Check(sphereShadow > 500 && apart <= 0.002 * Width * Height,
    "vtkLODActor drawing its points: no shadow, as the scene without it");
  Check(PixelsApart(TruthOf(hurried), TruthOf(plain)) <= 0.002 * Width * Height,
    "vtkLODActor drawing its points: the truth sees no shadow either");
  Check(warnings.Count("point cloud or outline") == 1,
    "vtkLODActor drawing its points: one warning (" + std::to_string(warnings.Messages.size()) +
      " in all)");
}

/// A sphere of radius 0.6 at (0, 0.9, 0) with bumps whose self-shadows a decimated level
/// does not have; no normals, so that both levels are shaded by their facets.
vtkSmartPointer<vtkPolyData> BumpySphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.6);
  sphere->SetThetaResolution(120);
  sphere->SetPhiResolution(80);
  sphere->Update();
  auto bumpy = vtkSmartPointer<vtkPolyData>::New();
  bumpy->DeepCopy(sphere->GetOutput());
  bumpy->GetPointData()->SetNormals(nullptr);
  vtkPoints* points = bumpy->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const glm::dvec3 n = glm::normalize(glm::dvec3(p[0], p[1], p[2]));
    const double wave = std::sin(9.0 * std::atan2(n.z, n.x)) * std::sin(7.0 * std::acos(n.y));
    const glm::dvec3 moved = glm::dvec3(0.0, 0.9, 0.0) + n * (0.6 + 0.08 * wave * wave);
    points->SetPoint(i, moved.x, moved.y, moved.z);
  }
  return bumpy;
}

/// Light 0's visibility and the truth's, hard, of a ground, a box and `data` in a plain actor.
std::pair<std::vector<float>, std::vector<float>> PlainShadows(vtkPolyData* data, vtkAlgorithm* box)
{
  View view;
  Ground(view.Renderer);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  view.Renderer->AddActor(actor);
  view.Renderer->AddActor(MakeActor(box, 1, 1, 1));
  view.Render();
  return { view.Visibility(), TruthOf(view) };
}

void TestQuadricLODActorLevel(bool inAssembly)
{
  // A vtkQuadricLODActor draws a decimated level, built in its Render, in frames its
  // interactor's desired update rate makes interactive: it casts that level then, and its full
  // mesh in still frames; as an assembly's part too (VTK allots the part the assembly's time).
  const std::string name =
    std::string("vtkQuadricLODActor") + (inAssembly ? " in an assembly" : "");
  vtkSmartPointer<vtkPolyData> bumpy = BumpySphere();
  auto box = BoxSource(1.2, 0.6, 0.3, 0.7, 1.2, 0.7);
  View levels;
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(levels.Window);
  interactor->SetDesiredUpdateRate(100.0);
  const WarningLog warnings(levels.Pass);
  Ground(levels.Renderer);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(bumpy);
  vtkNew<vtkQuadricLODActor> quadric;
  quadric->SetMapper(mapper);
  quadric->GetProperty()->SetColor(1, 1, 1);
  vtkNew<vtkAssembly> assembly;
  assembly->AddPart(quadric);
  levels.Renderer->AddActor(inAssembly ? static_cast<vtkProp3D*>(assembly) : quadric);
  levels.Renderer->AddActor(MakeActor(box, 1, 1, 1));
  levels.Window->SetDesiredUpdateRate(0.0001);
  levels.Render();
  const std::vector<float> still = levels.Visibility(), stillTruth = TruthOf(levels);
  levels.Window->SetDesiredUpdateRate(100.0);
  levels.Render();
  const std::vector<float> interactive = levels.Visibility(), interactiveTruth = TruthOf(levels);

  auto coarse = vtkSmartPointer<vtkPolyData>::New();
  coarse->DeepCopy(quadric->GetLODFilter()->GetOutput());
  const auto full = PlainShadows(bumpy, box), level = PlainShadows(coarse, box);
  const int levelsApart = PixelsApart(full.first, level.first);
  const int stillOff = PixelsApart(still, full.first);
  const int interactiveOff = PixelsApart(interactive, level.first);
  std::printf("%s (%lld of %lld cells): the levels' shadows %d px apart; still frame %d px off "
              "the full mesh's, interactive %d off the level's\n",
    name.c_str(), static_cast<long long>(coarse->GetNumberOfCells()),
    static_cast<long long>(bumpy->GetNumberOfCells()), levelsApart, stillOff, interactiveOff);
  const double pixels = double(Width) * Height;
  Check(coarse->GetNumberOfCells() > 0 && levelsApart > 0.002 * pixels,
    name + ": its level shadows otherwise than its full mesh");
  Check(stillOff <= 0.0005 * pixels, name + ": a still frame casts the full mesh");
  Check(interactiveOff <= 0.0005 * pixels,
    name + ": an interactive frame casts the decimated level VTK draws");
  Check(!stillTruth.empty() && PixelsApart(stillTruth, full.second) <= 0.0005 * pixels &&
      !interactiveTruth.empty() && PixelsApart(interactiveTruth, level.second) <= 0.0005 * pixels,
    name + ": the truth traces the mesh VTK draws in either frame");
  Check(warnings.Messages.empty(), name + ": no warning");
}

void TestLODProp3D()
{
  // A vtkLODProp3D with a fine and a coarse level, moved by its own matrix: it casts from the
  // level VTK draws (here the one it is told to select, each in turn), as that level's data in
  // a plain actor does.
  auto fine = SphereSource(0.0, 0.0, 0.0, 0.6, 32, 16);
  auto coarse = SphereSource(0.0, 0.0, 0.0, 0.6, 6, 4);
  auto box = BoxSource(1.0, 0.6, 0.3, 0.7, 1.2, 0.7);
  for (vtkAlgorithm* drawn : std::vector<vtkAlgorithm*>{ fine, coarse })
  {
    CompareScenes(
      std::string("vtkLODProp3D drawing its ") + (drawn == fine ? "fine" : "coarse") + " level",
      [&](vtkRenderer* r)
      {
        Ground(r);
        vtkNew<vtkLODProp3D> levels;
        for (vtkAlgorithm* source : std::vector<vtkAlgorithm*>{ fine, coarse })
        {
          vtkNew<vtkPolyDataMapper> mapper;
          mapper->SetInputConnection(source->GetOutputPort());
          vtkNew<vtkProperty> property;
          property->SetAmbient(0.2);
          property->SetDiffuse(0.8);
          const int id = levels->AddLOD(mapper, property, 0.0);
          if (source == drawn)
          {
            levels->AutomaticLODSelectionOff();
            levels->SetSelectedLODID(id);
          }
        }
        levels->SetPosition(-0.9, 1.0, 0.0);
        r->AddViewProp(levels);
        r->AddActor(MakeActor(box, 1, 1, 1));
      },
      [&](vtkRenderer* r)
      {
        Ground(r);
        auto sphere = MakeActor(drawn, 1, 1, 1);
        sphere->SetPosition(-0.9, 1.0, 0.0);
        r->AddActor(sphere);
        r->AddActor(MakeActor(box, 1, 1, 1));
      });
  }
}

void TestSkybox()
{
  // A vtkSkybox is an actor VTK draws at infinity: it must cast nothing (its mapper's input, a
  // cube round the origin, once cast a phantom shadow) in the pass and in the truth.
  View withSky, without;
  for (View* view : { &withSky, &without })
  {
    Ground(view->Renderer);
    view->Renderer->AddActor(MakeActor(SphereSource(-0.9, 1.0, 0.0, 0.6, 32, 16), 0.9, 0.3, 0.3));
  }
  vtkNew<vtkImageData> sky;
  sky->SetDimensions(4, 4, 1);
  sky->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::fill_n(static_cast<unsigned char*>(sky->GetScalarPointer()), 48, 160);
  vtkNew<vtkTexture> texture;
  texture->SetInputData(sky);
  vtkNew<vtkSkybox> skybox;
  skybox->SetTexture(texture);
  withSky.Renderer->AddActor(skybox);
  const WarningLog warnings(withSky.Pass);
  withSky.Render();
  without.Render();
  const std::vector<float> a = withSky.Visibility(), b = without.Visibility();
  int differ = 0, shadowed = 0;
  for (std::size_t i = 0; i < a.size() && a.size() == b.size(); ++i)
  {
    const float va = std::isnan(a[i]) ? 1.0f : a[i], vb = std::isnan(b[i]) ? 1.0f : b[i];
    differ += std::abs(va - vb) > 0.5f;
    shadowed += vb < 0.5f;
  }
  const std::vector<float> ta = TruthOf(withSky), tb = TruthOf(without);
  const bool traced = !ta.empty() && ta.size() == tb.size();
  const int truthDiffer = PixelsApart(ta, tb);
  std::printf("skybox: %d of %d shadowed px differ, truth %d\n", differ, shadowed, truthDiffer);
  Check(shadowed > Width * Height / 100 && differ == 0 && a.size() == b.size(),
    "skybox: the shadows are those of the scene without it");
  Check(traced && truthDiffer == 0, "skybox: the truth ignores it too");
  Check(warnings.Messages.empty(), "skybox: no warning");
}

void TestCutOutTextures()
{
  // A quad with an RGBA texture whose alpha is 0 or 255: VTK draws it opaque and leaves out the
  // transparent texels, the pass casts the whole quad. One warning; none for the same quad
  // whose alpha is all 255, nor for one without an alpha channel.
  int cutWarnings[3] = { 0, 0, 0 };
  for (int alpha = 0; alpha < 3; ++alpha)
  {
    View view;
    Ground(view.Renderer);
    const int components = alpha == 2 ? 3 : 4;
    vtkNew<vtkImageData> texels;
    texels->SetDimensions(8, 8, 1);
    texels->AllocateScalars(VTK_UNSIGNED_CHAR, components);
    auto* values = static_cast<unsigned char*>(texels->GetScalarPointer());
    for (int i = 0; i < 64; ++i)
    {
      std::fill_n(values + components * i, components, 200);
      if (components == 4)
      {
        values[4 * i + 3] = alpha == 0 && (i / 8 + i % 8) % 2 ? 0 : 255; // a checker of holes
      }
    }
    vtkNew<vtkTexture> texture;
    texture->SetInputData(texels);
    auto leaf = MakeActor(GroundSource(0.8, 1.2), 0.9, 0.9, 0.9);
    leaf->SetTexture(texture);
    view.Renderer->AddActor(leaf);
    const WarningLog warnings(view.Pass);
    view.Render();
    cutWarnings[alpha] = warnings.Count("transparent texels");
  }
  std::printf("cut-out textures: %d, %d, %d warnings (holes, alpha all 1, RGB)\n", cutWarnings[0],
    cutWarnings[1], cutWarnings[2]);
  Check(cutWarnings[0] == 1, "a cut-out texture on a caster: one warning");
  Check(cutWarnings[1] == 0 && cutWarnings[2] == 0, "opaque textures: no warning");
}

void TestDataSetInput()
{
  // Not polydata: an unstructured grid of tetrahedra through vtkDataSetMapper, which VTK draws
  // as its outer surface. It casts as that surface in a plain actor does.
  auto ball = SphereSource(-0.6, 1.0, 0.2, 0.7, 16, 12);
  vtkNew<vtkDelaunay3D> tetrahedra;
  tetrahedra->SetInputConnection(ball->GetOutputPort());
  CompareScenes(
    "unstructured grid through vtkDataSetMapper",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkDataSetMapper> mapper;
      mapper->SetInputConnection(tetrahedra->GetOutputPort());
      r->AddActor(LitActor(mapper));
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkDataSetSurfaceFilter> surface;
      surface->SetInputConnection(tetrahedra->GetOutputPort());
      r->AddActor(MakeActor(surface, 1, 1, 1));
    });
}

//------------------------------------------------------------------------------
/// What cannot cast warns once per prop and reason, over two frames, and the rest still shadows.
/// Imposter spheres (a vtkOpenGLSphereMapper, radii from an array, one point overlapping
/// another sphere) against the same spheres as a vtkGlyph3D of a fine vtkSphereSource. The pass
/// casts them as inscribed 32-segment spheres; the truth traces them as analytic spheres.
void TestImposterSpheres()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> radius;
  radius->SetName("radius");
  vtkNew<vtkCellArray> verts; // VTK 9.1 bounds polydata by its cells: no verts, nothing drawn
  for (int i = 0; i < 9; ++i)
  {
    points->InsertNextPoint(-1.6 + 0.4 * i, 0.7 + 0.25 * (i % 3), 0.9 * std::sin(1.3 * i));
    radius->InsertNextValue(static_cast<float>(0.18 + 0.04 * i));
    verts->InsertNextCell(1);
    verts->InsertCellPoint(i);
  }
  vtkNew<vtkPolyData> atoms;
  atoms->SetPoints(points);
  atoms->SetVerts(verts);
  atoms->GetPointData()->AddArray(radius);
  CompareScenes(
    "imposter spheres, radii from an array",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkOpenGLSphereMapper> mapper;
      mapper->SetInputData(atoms);
      mapper->SetScaleArray("radius");
      r->AddActor(LitActor(mapper));
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkSphereSource> unit;
      unit->SetRadius(1.0);
      unit->SetThetaResolution(96);
      unit->SetPhiResolution(48);
      vtkNew<vtkPolyData> scaled;
      scaled->ShallowCopy(atoms);
      scaled->GetPointData()->SetScalars(radius);
      vtkNew<vtkGlyph3D> glyphs;
      glyphs->SetInputData(scaled);
      glyphs->SetSourceConnection(unit->GetOutputPort());
      glyphs->SetScaleModeToScaleByScalar();
      glyphs->SetScaleFactor(1.0);
      glyphs->OrientOff();
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(glyphs->GetOutputPort());
      mapper->ScalarVisibilityOff();
      r->AddActor(LitActor(mapper));
    },
    // The stand-in is inscribed, so points just past a sphere's terminator (facing away from
    // the light) see the light past it where the finer mesh shadows itself: 0.34% of the
    // pixels. Their colour does not change (VTK's diffuse and specular vanish there), as the
    // colour check and the truth confirm.
    0.005);
}

/// Imposter sticks (a vtkOpenGLStickMapper: lengths and radii in a scale array, axes in an
/// orientation array) against the same sticks as fine capped vtkCylinderSource actors, each
/// placed by a vtkTransform; the truth traces its own cylinders.
void TestImposterSticks()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> sizes, axes;
  sizes->SetName("sizes");
  sizes->SetNumberOfComponents(3);
  axes->SetName("axes");
  axes->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> verts;
  for (int i = 0; i < 6; ++i)
  {
    points->InsertNextPoint(-1.5 + 0.6 * i, 0.8 + 0.15 * (i % 2), 0.4 * std::cos(1.7 * i));
    axes->InsertNextTuple3(std::cos(0.9 * i), 0.4 * std::sin(1.3 * i), std::sin(0.9 * i));
    sizes->InsertNextTuple3(0.7 + 0.1 * i, 0.06 + 0.015 * i, 0.0);
    verts->InsertNextCell(1);
    verts->InsertCellPoint(i);
  }
  // VTK's stick mapper reads colours for every stick (it crashes without): white, as the
  // plain actors' property.
  vtkNew<vtkUnsignedCharArray> white;
  white->SetNumberOfComponents(3);
  for (int i = 0; i < 6; ++i)
  {
    white->InsertNextTuple3(255, 255, 255);
  }
  vtkNew<vtkPolyData> bonds;
  bonds->SetPoints(points);
  bonds->SetVerts(verts);
  bonds->GetPointData()->SetScalars(white);
  bonds->GetPointData()->AddArray(sizes);
  bonds->GetPointData()->AddArray(axes);
  CompareScenes(
    "imposter sticks, lengths, radii, axes",
    [&](vtkRenderer* r)
    {
      Ground(r);
      vtkNew<vtkOpenGLStickMapper> mapper;
      mapper->SetInputData(bonds);
      mapper->SetScaleArray("sizes");
      mapper->SetOrientationArray("axes");
      mapper->SetColorModeToDirectScalars();
      r->AddActor(LitActor(mapper));
    },
    [&](vtkRenderer* r)
    {
      Ground(r);
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3], a[3];
        points->GetPoint(i, p);
        axes->GetTuple(i, a);
        const double length = sizes->GetComponent(i, 0) * vtkMath::Norm(a);
        vtkMath::Normalize(a);
        const double y[3] = { 0.0, 1.0, 0.0 };
        double turn[3];
        vtkMath::Cross(y, a, turn);
        vtkNew<vtkTransform> place;
        place->PostMultiply();
        place->Scale(sizes->GetComponent(i, 1), length, sizes->GetComponent(i, 1));
        place->RotateWXYZ(
          vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(turn), vtkMath::Dot(y, a))), turn);
        place->Translate(p);
        vtkNew<vtkCylinderSource> cylinder;
        cylinder->SetResolution(96);
        cylinder->SetRadius(1.0);
        cylinder->SetHeight(1.0);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputConnection(cylinder->GetOutputPort());
        auto actor = LitActor(mapper);
        actor->SetUserTransform(place);
        r->AddActor(actor);
      }
    });
}

/// A molecule (vtkMoleculeMapper, ball and stick): its atoms and bonds cast, no warning, and
/// the truth, which reads the same sphere and stick mappers its own way, agrees.
void TestMolecule()
{
  View view;
  Ground(view.Renderer);
  vtkNew<vtkMolecule> molecule;
  const vtkIdType carbon = molecule->AppendAtom(6, -0.6, 1.0, 0.0).GetId();
  const vtkIdType oxygen = molecule->AppendAtom(8, 0.6, 1.1, 0.2).GetId();
  const vtkIdType nitrogen = molecule->AppendAtom(7, -1.2, 1.3, -0.9).GetId();
  const vtkIdType hydrogen = molecule->AppendAtom(1, -1.4, 0.9, 0.7).GetId();
  molecule->AppendBond(carbon, oxygen, 2);
  molecule->AppendBond(carbon, nitrogen, 1);
  molecule->AppendBond(carbon, hydrogen, 1);
  vtkNew<vtkMoleculeMapper> mapper;
  mapper->SetInputData(molecule);
  mapper->UseBallAndStickSettings();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  view.Renderer->AddActor(actor);
  const WarningLog log(view.Pass);
  view.Render();
  view.Render();
  const std::vector<float> visibility = view.Visibility();
  const auto shadowed =
    std::count_if(visibility.begin(), visibility.end(), [](float v) { return v < 0.5f; });
  std::printf("molecule: %ld shadowed pixels, %zu warnings\n", static_cast<long>(shadowed),
    log.Messages.size());
  Check(shadowed > Width * Height / 100, "molecule: its atoms and bonds cast");
  Check(log.Messages.empty(), "molecule: no warning");
  CheckAgainstTruth("molecule", CompareWithTruth(view.Window, view.Renderer, view.Pass, 0));
}

void TestUserLightStatements()
{
  // A vtkShaderProperty that replaces VTK's own diffuse statement once VTK has written it (a
  // toon shading): where lit, drawn as VTK draws it; in the shadow, as VTK draws it with the
  // light off; without a warning.
  View view;
  auto ground = Ground(view.Renderer);
  ground->GetShaderProperty()->AddFragmentShaderReplacement("diffuse += (df * lightColor0);", false,
    "diffuse += (step(0.5, df) * 0.5 * lightColor0);", false);
  view.Renderer->AddActor(MakeActor(SphereSource(-0.9, 1.0, 0.0, 0.6, 32, 16), 0.9, 0.3, 0.3));
  const WarningLog log(view.Pass);
  view.Render();
  const std::vector<float> visibility = view.Visibility();
  const std::vector<unsigned char> withShadows = view.Colours();
  view.Renderer->SetPass(nullptr);
  view.Render();
  const std::vector<unsigned char> lightOn = view.Colours();
  const double intensity = view.Light->GetIntensity();
  view.Light->SetIntensity(0.0);
  view.Render();
  const std::vector<unsigned char> lightOff = view.Colours();
  view.Light->SetIntensity(intensity);
  view.Renderer->SetPass(view.Pass);
  auto apart = [&withShadows](const std::vector<unsigned char>& other, std::size_t pixel)
  {
    int worst = 0;
    for (std::size_t c = 3 * pixel; c < 3 * pixel + 3; ++c)
    {
      worst = std::max(worst, std::abs(int(withShadows[c]) - int(other[c])));
    }
    return worst > 8;
  };
  int lit = 0, litOff = 0, shadowed = 0, shadowedOff = 0;
  for (std::size_t i = 0; i < visibility.size(); ++i)
  {
    if (visibility[i] == 1.0f)
    {
      ++lit;
      litOff += apart(lightOn, i);
    }
    else if (visibility[i] == 0.0f)
    {
      ++shadowed;
      shadowedOff += apart(lightOff, i);
    }
  }
  std::printf("toon diffuse: %d of %d lit px off VTK's frame, %d of %d shadowed px off VTK's "
              "frame with the light off\n",
    litOff, lit, shadowedOff, shadowed);
  Check(lit > Width * Height / 4 && litOff <= lit / 1000,
    "a user's replacement of VTK's light statement: lit as VTK draws it");
  Check(shadowed > Width * Height / 100 && shadowedOff <= shadowed / 100,
    "a user's replacement of VTK's light statement: shadowed");
  Check(log.Messages.empty(), "a user's replacement of VTK's light statement: no warning");
}

void TestWarnings()
{
  View view;
  Ground(view.Renderer);
  view.Renderer->AddActor(MakeActor(SphereSource(-0.9, 1.0, 0.0, 0.6, 32, 16), 0.9, 0.3, 0.3));
  // Its own light code in place of VTK's: it still casts, but cannot be shadowed.
  auto selfLit = MakeActor(BoxSource(1.6, 0.3, -1.2, 0.5, 0.6, 0.5), 0.3, 0.6, 0.9);
  selfLit->GetShaderProperty()->AddFragmentShaderReplacement(
    "//VTK::Light::Impl", true, "  gl_FragData[0] = vec4(0.3, 0.6, 0.9, 1.0);\n", false);
  view.Renderer->AddActor(selfLit);
  // Lighting off: VTK draws it without light terms, so its shadow cannot show (one warning).
  auto unlit = MakeActor(BoxSource(-1.8, 0.2, 1.6, 0.4, 0.4, 0.4), 0.8, 0.8, 0.3);
  unlit->GetProperty()->LightingOff();
  view.Renderer->AddActor(unlit);
  // Lines without active normals (a vtkStreamTracer's): VTK draws them unlit (one warning);
  // with the same normals made active it lights them (none).
  std::string linesNamed[2]; // how a warning names each: without, then with active normals
  for (const bool activeNormals : { false, true })
  {
    vtkNew<vtkPolyData> streamline;
    vtkNew<vtkPoints> linePoints;
    vtkNew<vtkFloatArray> lineNormals;
    lineNormals->SetName("Normals");
    lineNormals->SetNumberOfComponents(3);
    vtkNew<vtkCellArray> lineCells;
    lineCells->InsertNextCell(8);
    for (int i = 0; i < 8; ++i)
    {
      lineCells->InsertCellPoint(
        linePoints->InsertNextPoint(-2.0 + 0.5 * i, 0.3, activeNormals ? -2.0 : 2.2));
      lineNormals->InsertNextTuple3(0.0, 1.0, 0.0);
    }
    streamline->SetPoints(linePoints);
    streamline->SetLines(lineCells);
    streamline->GetPointData()->AddArray(lineNormals);
    if (activeNormals)
    {
      streamline->GetPointData()->SetActiveNormals("Normals");
    }
    vtkNew<vtkPolyDataMapper> lineMapper;
    lineMapper->SetInputData(streamline);
    vtkNew<vtkActor> lines;
    lines->SetMapper(lineMapper);
    view.Renderer->AddActor(lines);
    std::ostringstream named;
    named << "(" << lines.GetPointer() << ", drawn by";
    linesNamed[activeNormals] = named.str();
  }

  // Imposter spheres cast, but not one whose radius is NaN (VTK draws nothing for it).
  vtkNew<vtkPolyData> centres;
  vtkNew<vtkPoints> centrePoints;
  vtkNew<vtkFloatArray> radius;
  radius->SetName("radius");
  vtkNew<vtkCellArray> verts;
  for (const double x : { 1.0, 1.5, 0.5 })
  {
    verts->InsertNextCell(1);
    verts->InsertCellPoint(centrePoints->InsertNextPoint(x, 1.0 + 0.2 * x, x - 1.0));
    radius->InsertNextValue(x == 0.5 ? std::numeric_limits<float>::quiet_NaN() : 0.3f);
  }
  centres->SetPoints(centrePoints);
  centres->SetVerts(verts);
  centres->GetPointData()->AddArray(radius);
  vtkNew<vtkOpenGLSphereMapper> imposters;
  imposters->SetInputData(centres);
  imposters->SetScaleArray("radius");
  vtkNew<vtkActor> atoms;
  atoms->SetMapper(imposters);
  view.Renderer->AddActor(atoms);

  vtkNew<vtkPointGaussianMapper> splats;
  splats->SetInputData(centres);
  splats->SetScaleFactor(0.2);
  vtkNew<vtkActor> particles;
  particles->SetMapper(splats);
  particles->SetPosition(-2.5, 0.0, 0.0);
  view.Renderer->AddActor(particles);

  vtkSmartPointer<vtkPolyData> points = GlyphPoints();
  vtkNew<vtkGlyph3DMapper> noSource;
  noSource->SetInputData(points);
  vtkNew<vtkActor> lines;
  lines->SetMapper(noSource);
  // Out of view: the truth has no lines to see, so their pixels would not compare.
  lines->SetPosition(50.0, 0.0, 0.0);
  view.Renderer->AddActor(lines);

  vtkNew<vtkPolyData> broken;
  broken->DeepCopy(points);
  vtkDataArray* direction = broken->GetPointData()->GetArray("direction");
  direction->SetTuple3(0, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  direction->SetTuple3(5, 0.0, std::numeric_limits<double>::infinity(), 0.0);
  auto cone = Cone();
  vtkNew<vtkGlyph3DMapper> nanGlyphs;
  nanGlyphs->SetInputData(broken);
  nanGlyphs->SetSourceConnection(cone->GetOutputPort());
  nanGlyphs->SetOrientationArray("direction");
  nanGlyphs->SetScaling(false);
  vtkNew<vtkActor> nanActor;
  nanActor->SetMapper(nanGlyphs);
  nanActor->SetPosition(0.0, 1.0, 0.0);
  view.Renderer->AddActor(nanActor);

  vtkNew<vtkImageData> picture;
  picture->SetDimensions(16, 16, 1);
  picture->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  std::fill_n(static_cast<unsigned char*>(picture->GetScalarPointer()), 256, 200);
  vtkNew<vtkImageActor> slice;
  slice->GetMapper()->SetInputData(picture);
  slice->SetPosition(-3.5, 0.01, -3.5);
  slice->SetScale(0.05);
  slice->RotateX(90.0);
  view.Renderer->AddViewProp(slice);

  // A volume: one warning that it casts nothing, and its shaders are left as VTK wrote them
  // (no warning about their light code).
  vtkNew<vtkImageData> density;
  density->SetDimensions(8, 8, 8);
  density->SetOrigin(-3.0, 0.1, 1.0);
  density->SetSpacing(0.1, 0.1, 0.1);
  density->AllocateScalars(VTK_FLOAT, 1);
  std::fill_n(static_cast<float*>(density->GetScalarPointer()), 512, 1.0f);
  vtkNew<vtkSmartVolumeMapper> volumeMapper;
  volumeMapper->SetInputData(density);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.3);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(volumeMapper);
  volume->GetProperty()->SetScalarOpacity(opacity);
  view.Renderer->AddVolume(volume);

  // vtkAxesActor's default shafts are lines: one warning for their shared data (out of view).
  vtkNew<vtkAxesActor> lineAxes;
  lineAxes->AxisLabelsOff();
  vtkNew<vtkTransform> away;
  away->Translate(50.0, 0.0, 0.0);
  lineAxes->SetUserTransform(away);
  view.Renderer->AddViewProp(lineAxes);

  // A sphere drawn as its wireframe, in view over lit ground: VTK draws lines, which cast
  // nothing (one warning). The truth traces no lines, so a shadow of the sphere would show as
  // wrong pixels against it; the lines themselves, over lit ground, compare lit either way.
  auto wires = MakeActor(SphereSource(2.2, 1.0, 2.6, 0.35, 16, 8), 0.9, 0.9, 0.9);
  wires->GetProperty()->SetRepresentationToWireframe();
  view.Renderer->AddActor(wires);
  // Imposter spheres with a clipping plane (out of view): the shadows do not follow the planes
  // of imposters, so they cast nothing, with one warning.
  vtkNew<vtkOpenGLSphereMapper> clippedImposters;
  clippedImposters->SetInputData(centres);
  clippedImposters->SetRadius(0.3);
  clippedImposters->AddClippingPlane(KeepPlane(0.0, 1.2, 0.0, 0.0, -1.0, 0.0));
  vtkNew<vtkActor> clippedImposterActor;
  clippedImposterActor->SetMapper(clippedImposters);
  clippedImposterActor->SetPosition(-50.0, 0.0, 0.0);
  view.Renderer->AddActor(clippedImposterActor);

  const WarningLog log(view.Pass);
  const std::vector<std::string>& warnings = log.Messages;
  view.Render();
  view.Render();
  auto count = [&](const std::string& needle) { return log.Count(needle); };
  for (const std::string& w : warnings)
  {
    std::printf("     warning: %s", w.c_str());
  }
  Check(count("PointGaussianMapper") == 1 && count("squares' corners") == 0,
    "point gaussian splats: one warning naming the mapper");
  Check(count("radius is not positive") == 1, "an imposter sphere of NaN radius: one warning");
  Check(count("default glyph is a line") == 1, "a glyph mapper without a source: one warning");
  Check(count("orientation is not finite") == 1,
    "glyphs with a NaN or infinite orientation: one warning");
  Check(count("does not use the colour of light 0") == 1, "custom light code: one warning");
  Check(count("neither casts nor receives shadows: the pass does not edit image slices") == 1,
    "an image slice: one warning, that it is not shadowed either");
  Check(count("neither casts nor receives shadows: the pass does not edit volume") == 1,
    "a volume: one warning, that it is not shadowed either");
  Check(count("Lighting off") == 1, "an actor with Lighting off: one warning");
  const auto unlitWarnings = [&](const std::string& named)
  {
    return std::count_if(warnings.begin(), warnings.end(),
      [&](const std::string& w)
      { return w.find(named) != std::string::npos && w.find("active point normals") != w.npos; });
  };
  Check(unlitWarnings(linesNamed[0]) == 1 && unlitWarnings(linesNamed[1]) == 0,
    "lines without active normals, drawn unlit: one warning (none with them)");
  Check(count("part of vtkAxesActor") == 1 && count("no surface triangles") == 3,
    "vtkAxesActor's line shafts and the lines: one warning each, naming the axes");
  Check(count("drawn as a wireframe") == 1, "a wireframe sphere: one warning");
  Check(count("has clipping planes") == 1 && count("imposters of its vtkOpenGLSphereMapper") == 1,
    "imposter spheres with a clipping plane: one warning naming the mapper");
  // The line shafts of vtkAxesActor have no normals either: one more such warning.
  Check(count("active point normals") == 2 && warnings.size() == 15, "no other warning");

  // Lit splats write their squares' depth: what is seen through their corners is shaded as
  // they are. Said in their warning.
  View litView;
  Ground(litView.Renderer);
  vtkNew<vtkPointGaussianMapper> litSplats;
  litSplats->SetInputData(centres);
  litSplats->SetScaleFactor(0.2);
  litSplats->EmissiveOff();
  vtkNew<vtkActor> litParticles;
  litParticles->SetMapper(litSplats);
  litView.Renderer->AddActor(litParticles);
  const WarningLog litLog(litView.Pass);
  litView.Render();
  Check(litLog.Count("PointGaussianMapper") == 1 && litLog.Count("squares' corners") == 1,
    "lit point gaussian splats: one warning, naming what is seen through their corners");
  const std::vector<float> visibility = view.Visibility();
  const auto shadowed =
    std::count_if(visibility.begin(), visibility.end(), [](float v) { return v < 0.5f; });
  Check(shadowed > Width * Height / 50, "the rest of the scene still casts");
  CheckAgainstTruth("scene with props that cannot cast",
    CompareWithTruth(view.Window, view.Renderer, view.Pass, 0));
}
} // namespace

int main()
{
  TestGlyphsByDirection();
  TestGlyphsByRotation();
  TestGlyphsOfCompositeInput();
  TestGlyphsByDirectionAndIndex(true);
  TestGlyphsByDirectionAndIndex(false);
  TestGlyphsByQuaternionTableAndClamping();
  TestGlyphsStretchedAndDirected();
  TestMultiBlock();
  TestClippingPlanes();
  TestAssembly();
  TestAxesActor();
  TestAnnotatedCube();
  TestCubeAxes();
  TestUnlitPartsWarn();
  TestLODActor();
  TestLODActorLevels();
  TestQuadricLODActorLevel(false);
  TestQuadricLODActorLevel(true);
  TestDataSetInput();
  TestLODProp3D();
  TestSkybox();
  TestCutOutTextures();
  TestImposterSpheres();
  TestImposterSticks();
  TestMolecule();
  TestUserLightStatements();
  TestWarnings();
  return penumbra_test::Finish();
}
