// Soft shadows of vtkSoftShadowPass against the ray tracer's many-sample truth: averaged hard
// shadows, penumbra wedges (hard cases, shapes, corners, temporal stability), plateaus and
// Automatic's choice on layered outlines. Tolerances are stated at each check.
#include "penumbraTestHarness.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkContourFilter.h"
#include "vtkCylinderSource.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRTAnalyticSource.h"
#include "vtkTrivialProducer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace penumbra_test;

namespace
{

using Scene = PassScene;

/// Light `lightIndex`'s soft visibility after a fresh frame against `truth`, by the benchmark's
/// measure (VisibilityError); Finite: every value of the pass's image is within [0, 1].
struct SoftComparison
{
  penumbra::metrics::ErrorStats Error;
  bool Finite = true;
};

SoftComparison CompareSoft(Scene& scene, vtkRayTracedVisibility* truth, int lightIndex = 0)
{
  scene.Window->Render();
  SoftComparison result;
  const std::vector<float> ours = ImageValues(scene.Pass->GetVisibilityImage(lightIndex));
  result.Finite = std::all_of(
    ours.begin(), ours.end(), [](float v) { return std::isfinite(v) && v >= 0.0f && v <= 1.0f; });
  result.Error =
    VisibilityError(ours, truth, lightIndex, WindowDepth(scene.Window, scene.Renderer));
  return result;
}

/// The same against a fresh 256-sample truth of the scene as it stands.
SoftComparison CompareSoft(Scene& scene, int lightIndex = 0)
{
  scene.Window->Render();
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(scene.Renderer);
  truth->SetSamplesPerLight(256);
  truth->Update();
  return CompareSoft(scene, truth, lightIndex);
}

void TestAveragedHardShadows()
{
  // Heckbert-Herf averaging converges to the ray-traced soft shadow of a spherical light.
  Scene scene;
  scene.Window->SetMultiSamples(0);
  scene.Ground();
  scene.Sphere(-0.8, 0.9, 0, 0.7);
  scene.Box(1.0, 0.6, 0.3, 0.8, 1.2, 0.8);
  scene.Camera(3, 4, 7, 0, 0.5, 0);
  scene.Light->SetPosition(-2, 5, 2);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 0.5);
  scene.Window->Render();
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(scene.Renderer);
  truth->SetSamplesPerLight(256);
  truth->Update();
  scene.Pass->SetMethodToAveragedHardShadows();
  double errors[3];
  const int samples[3] = { 4, 16, 64 };
  for (int i = 0; i < 3; ++i)
  {
    scene.Pass->SetLightSamples(samples[i]);
    errors[i] = CompareSoft(scene, truth).Error.MAE;
    std::printf("     averaged %d samples: MAE %.4f\n", samples[i], errors[i]);
  }
  Check(errors[1] < errors[0] && errors[2] < errors[1], "averaged error shrinks with samples");
  Check(errors[2] < 0.012, "averaged 64 samples within 0.012 MAE of the truth");
  scene.Pass->SetMethodToHardVolumes();
  const double hard = CompareSoft(scene, truth).Error.MAE;
  std::printf("     hard volumes on the same light: MAE %.4f\n", hard);
  Check(hard > 2 * errors[1], "hard shadows ignore the radius (larger error)");
  // Automatic counts or averages the same 64 samples: the error of averaging 64.
  scene.Pass->SetMethodToAutomatic();
  const double automatic = CompareSoft(scene, truth).Error.MAE;
  std::printf("     automatic: MAE %.4f\n", automatic);
  Check(std::abs(automatic - errors[2]) < 0.003, "automatic is as accurate as averaging 64");
}

void CheckSoft(
  const std::string& name, const SoftComparison& c, double meanTolerance, double fractionTolerance)
{
  std::printf("     %s: %zu px in shadow or penumbra, MAE %.4f, >0.1: %.2f%%\n", name.c_str(),
    c.Error.Pixels, c.Error.MAE, 100.0 * c.Error.FracGt01);
  Check(c.Error.Pixels > 500, name + ": penumbra in view");
  Check(c.Finite, name + ": visibility finite and within [0, 1]");
  Check(c.Error.MAE <= meanTolerance && c.Error.FracGt01 <= fractionTolerance,
    name + ": agrees with the ray-traced soft shadow");
}

void TestPenumbraWedges()
{
  Scene scene;
  scene.Window->SetMultiSamples(0);
  scene.Ground();
  scene.Sphere(-0.8, 0.9, 0, 0.7);
  scene.Box(1.0, 0.6, 0.3, 0.8, 1.2, 0.8); // resting on the ground: contact shadow
  scene.Camera(3, 4, 7, 0, 0.5, 0);
  scene.Light->SetPosition(-2, 5, 2);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 0.5);
  scene.Pass->SetMethodToPenumbraWedges();
  // Tolerances: the method's single silhouette (from the light's centre) errs most on the
  // casters' own terminators; the ground penumbrae are within a few thousandths.
  CheckSoft("wedges, sphere light", CompareSoft(scene), 0.012, 0.03);
  Check(scene.Pass->GetNumberOfPenumbraWedges() > 50, "one wedge per silhouette edge");

  scene.Light->SetPositional(false);
  scene.Light->SetPosition(-1, 3, 1.5);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 4.0); // degrees
  CheckSoft("wedges, directional light of 4 degrees", CompareSoft(scene), 0.012, 0.03);

  // Radius towards 0: the hard shadow.
  scene.Light->SetPositional(true);
  scene.Light->SetPosition(-2, 5, 2);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 1e-4);
  CheckAgainstTruth("wedges, radius 1e-4 (hard limit)", scene.Render());
}

void TestWedgesHardCases()
{
  // The eye low in the sphere's penumbra, the near plane through the wedges and the umbra.
  Scene scene;
  scene.Window->SetMultiSamples(0);
  scene.Ground(6);
  scene.Sphere(0, 1.0, 0, 0.6);
  scene.Light->SetPosition(0.3, 4, 0.2);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 0.8);
  scene.Pass->SetMethodToPenumbraWedges();
  scene.Camera(0.9, 0.3, 0.6, -0.5, 0.0, -0.3);
  scene.Renderer->GetActiveCamera()->SetClippingRange(0.05, 30);
  CheckSoft("wedges, eye and near plane inside the penumbra", CompareSoft(scene), 0.012, 0.03);

  // A light larger than its caster: the umbra vanishes, nothing is fully dark.
  Scene large;
  large.Window->SetMultiSamples(0);
  large.Ground(6);
  vtkActor* small = large.Sphere(0, 1.2, 0, 0.15);
  large.Light->SetPosition(0, 3, 0);
  vtkSoftShadowPass::SetLightRadius(large.Light, 0.6);
  large.Pass->SetMethodToPenumbraWedges();
  large.Camera(0.5, 4, 3, 0, 0, 0);
  vtkSoftShadowPass::SetReceivesShadows(small, false);
  CheckSoft("wedges, light larger than the caster", CompareSoft(large), 0.01, 0.02);
  // The ground right under the sphere still sees most of the light.
  double below[4];
  large.Renderer->SetWorldPoint(0, 0, 0, 1);
  large.Renderer->WorldToDisplay();
  large.Renderer->GetDisplayPoint(below);
  auto visibility =
    vtkFloatArray::SafeDownCast(large.Pass->GetVisibilityImage(0)->GetPointData()->GetScalars());
  const float centre =
    visibility->GetValue(static_cast<vtkIdType>(below[1]) * large.Window->GetSize()[0] +
      static_cast<vtkIdType>(below[0]));
  std::printf("     visibility under the small sphere: %.3f\n", centre);
  Check(centre > 0.5 && centre < 0.99, "no umbra under a light larger than the caster");

  // Two soft lights, each in its own layer.
  Scene two;
  two.Window->SetMultiSamples(0);
  two.Ground();
  two.Sphere(0, 1, 0, 0.6);
  vtkSoftShadowPass::SetLightRadius(two.Light, 0.4);
  auto second = penumbra::scene::MakeLight(true, { 2.5, 5, -1 }, 0.7);
  second->SetDiffuseColor(0.4, 0.6, 1.0);
  two.Renderer->AddLight(second);
  two.Pass->SetMethodToPenumbraWedges();
  two.Camera(3, 5, 6, 0, 0.5, 0);
  CheckSoft("wedges, first of two lights", CompareSoft(two, 0), 0.012, 0.035);
  CheckSoft("wedges, second of two lights", CompareSoft(two, 1), 0.012, 0.035);

  // A ribbon thinner than a pixel, in full light: across it, both neighbours of its pixels are
  // the ground behind, which gives the horizon cap no plane; a plane joining the ribbon to the
  // ground faces away from the light and capped its pixels dark.
  Scene thin;
  thin.Window->SetMultiSamples(0);
  thin.Ground(6);
  vtkNew<vtkPlaneSource> ribbonShape;
  ribbonShape->SetOrigin(-2, 0.3, 0);
  ribbonShape->SetPoint1(2, 0.3, 0);
  ribbonShape->SetPoint2(-2, 0.3, 0.008);
  vtkActor* ribbon = thin.Add(ribbonShape, 0.9, 0.9, 0.9);
  thin.Light->SetPosition(0.5, 5, 2);
  vtkSoftShadowPass::SetLightRadius(thin.Light, 0.5);
  thin.Pass->SetMethodToPenumbraWedges();
  thin.Camera(0.3, 2, 3.5, 0, 0.2, 0);
  ribbon->VisibilityOff();
  thin.Window->Render();
  const std::vector<float> groundDepth = WindowDepth(thin.Window, thin.Renderer);
  ribbon->VisibilityOn();
  thin.Window->Render();
  const std::vector<float> depth = WindowDepth(thin.Window, thin.Renderer);
  const std::vector<float> lit = ImageValues(thin.Pass->GetVisibilityImage(0));
  int ribbonPixels = 0, dark = 0;
  for (std::size_t i = 0; i < depth.size(); ++i)
  {
    if (depth[i] < groundDepth[i] - 1e-4f)
    {
      ++ribbonPixels;
      dark += lit[i] < 0.9f;
    }
  }
  std::printf(
    "     a sub-pixel ribbon in full light: %d of its %d px below 0.9\n", dark, ribbonPixels);
  Check(ribbonPixels >= 40 && dark * 100 <= ribbonPixels,
    "wedges: a ribbon thinner than a pixel in full light reads lit (at most 1% below 0.9)");
}

void TestWedgeShapes()
{
  // A torus (saddle-shaped silhouette), an open sheet, and two overlapping casters over a
  // non-planar receiver (a lying cylinder).
  auto wedgeScene = [](Scene& scene)
  {
    scene.Window->SetMultiSamples(0);
    scene.Light->SetPosition(-1, 5, 1.5);
    vtkSoftShadowPass::SetLightRadius(scene.Light, 0.5);
    scene.Pass->SetMethodToPenumbraWedges();
    scene.Camera(2.5, 5, 6, 0, 0.3, 0);
  };
  {
    Scene scene;
    wedgeScene(scene);
    scene.Ground();
    vtkNew<vtkParametricTorus> torus;
    torus->SetRingRadius(0.7);
    torus->SetCrossSectionRadius(0.2);
    vtkNew<vtkParametricFunctionSource> source;
    source->SetParametricFunction(torus);
    source->SetUResolution(48);
    source->SetVResolution(16);
    vtkActor* ring = scene.Add(source, 0.9, 0.6, 0.2);
    ring->SetPosition(0, 1.2, 0);
    ring->RotateX(70);
    CheckSoft("wedges, torus", CompareSoft(scene), 0.015, 0.04);
  }
  {
    Scene scene;
    wedgeScene(scene);
    scene.Ground();
    vtkNew<vtkPlaneSource> sheet;
    sheet->SetResolution(4, 4);
    vtkActor* open = scene.Add(sheet, 0.6, 0.6, 0.9);
    open->SetPosition(0, 1.2, 0);
    open->SetScale(1.5);
    open->RotateX(70);
    open->RotateY(20);
    CheckSoft("wedges, open sheet", CompareSoft(scene), 0.012, 0.03);
  }
  {
    Scene scene;
    wedgeScene(scene);
    scene.Ground();
    scene.Sphere(-0.3, 1.3, 0, 0.45);
    scene.Sphere(0.3, 1.6, 0.2, 0.4);
    // Overlapping penumbrae add (conservatively dark, never a hole): measured MAE 0.0135 and
    // 3.6% of pixels off by more than 0.1 (Documentation/wedges.md).
    CheckSoft("wedges, overlapping casters", CompareSoft(scene), 0.02, 0.05);
  }
  {
    Scene scene;
    wedgeScene(scene);
    vtkNew<vtkCylinderSource> cylinder;
    cylinder->SetRadius(1.5);
    cylinder->SetHeight(8);
    cylinder->SetResolution(64);
    vtkActor* receiver = scene.Add(cylinder, 0.85, 0.85, 0.8);
    receiver->RotateZ(90);
    receiver->SetPosition(0, -1.5, 0);
    scene.Sphere(0.0, 1.3, 0, 0.45);
    // The cylinder's own terminator is seen from the single centre silhouette: measured MAE
    // 0.025 and 8.4% off by more than 0.1 (Documentation/wedges.md).
    CheckSoft("wedges, curved receiver", CompareSoft(scene), 0.03, 0.1);
  }
}

void TestWedgeCorners()
{
  // Two boxes touching at one corner: a silhouette vertex shared by four silhouette edges.
  {
    Scene scene;
    scene.Window->SetMultiSamples(0);
    scene.Ground();
    scene.Box(-0.35, 1.35, -0.35, 0.7, 0.7, 0.7);
    scene.Box(0.35, 1.35 + 0.7, 0.35, 0.7, 0.7, 0.7)->SetPosition(0, -0.7, 0);
    scene.Light->SetPosition(0.3, 5, 0.4);
    vtkSoftShadowPass::SetLightRadius(scene.Light, 0.4);
    scene.Pass->SetMethodToPenumbraWedges();
    scene.Camera(2, 5, 5, 0, 0.3, 0);
    CheckSoft("wedges, boxes touching at a corner", CompareSoft(scene), 0.012, 0.03);
  }
  // An acute silhouette corner: a thin triangular prism.
  {
    Scene scene;
    scene.Window->SetMultiSamples(0);
    scene.Ground();
    vtkNew<vtkPoints> points;
    const double corners[6][3] = { { -1.0, 1.2, -0.1 }, { 1.0, 1.2, 0.0 }, { -1.0, 1.2, 0.1 },
      { -1.0, 1.3, -0.1 }, { 1.0, 1.3, 0.0 }, { -1.0, 1.3, 0.1 } };
    for (const auto& corner : corners)
    {
      points->InsertNextPoint(corner);
    }
    vtkNew<vtkCellArray> faces;
    const vtkIdType bottom[3] = { 0, 2, 1 }, top[3] = { 3, 4, 5 }, sideA[4] = { 0, 1, 4, 3 },
                    sideB[4] = { 1, 2, 5, 4 }, sideC[4] = { 2, 0, 3, 5 };
    faces->InsertNextCell(3, bottom);
    faces->InsertNextCell(3, top);
    faces->InsertNextCell(4, sideA);
    faces->InsertNextCell(4, sideB);
    faces->InsertNextCell(4, sideC);
    vtkNew<vtkPolyData> prism;
    prism->SetPoints(points);
    prism->SetPolys(faces);
    vtkNew<vtkTrivialProducer> producer;
    producer->SetOutput(prism);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(producer->GetOutputPort());
    vtkNew<vtkActor> spike;
    spike->SetMapper(mapper);
    scene.Renderer->AddActor(spike);
    scene.Light->SetPosition(-0.5, 4, 0.5);
    vtkSoftShadowPass::SetLightRadius(scene.Light, 0.4);
    scene.Pass->SetMethodToPenumbraWedges();
    scene.Camera(1, 5, 4, 0.3, 0, 0);
    CheckSoft("wedges, acute silhouette corner", CompareSoft(scene), 0.012, 0.03);
  }
}

/// The world point at pixel `p` (row-major, `width` wide) of the renderer's viewport and window
/// depth `depth`, at the pixel's centre, where the truth traced its ray.
std::array<double, 3> WorldAtPixel(vtkRenderer* renderer, std::size_t p, int width, double depth)
{
  renderer->SetDisplayPoint(
    static_cast<double>(p % width) + 0.5, static_cast<double>(p / width) + 0.5, depth);
  renderer->DisplayToWorld();
  const double* w = renderer->GetWorldPoint();
  return { w[0] / w[3], w[1] / w[3], w[2] / w[3] };
}

void TestWedgesTemporalStability()
{
  // The light passes through the planes of two faces of a box (faces flipping between lit and
  // unlit). Frame-to-frame change of the visibility must follow the truth's change: no popping
  // on the receiving ground. Points on the flipping faces themselves (where shading is ~0 anyway)
  // and on their contact line with the ground are degenerate for the wedge function while the
  // light lies in the faces' plane: reported, not asserted (Documentation/wedges.md).
  Scene scene;
  scene.Window->SetMultiSamples(0);
  scene.Ground();
  scene.Box(0, 0.6, 0, 0.6, 1.2, 0.6);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 0.3);
  scene.Pass->SetMethodToPenumbraWedges();
  scene.Camera(2, 4, 4, 0, 0.3, 0);
  const int* size = scene.Window->GetSize();
  std::vector<float> previousOurs, previousTruth;
  double worstGround = 0.0, worstAll = 0.0;
  int groundSamples = 0;
  for (int step = 0; step <= 8; ++step)
  {
    scene.Light->SetPosition(0.3 - 0.0125 * step, 4, 0.3 - 0.0125 * step); // through x, z = 0.3
    scene.Window->Render();
    vtkNew<vtkRayTracedVisibility> truth;
    truth->SetRenderer(scene.Renderer);
    truth->SetSamplesPerLight(256);
    truth->Update();
    auto depth = vtkFloatArray::SafeDownCast(truth->GetDepthImage()->GetPointData()->GetScalars());
    std::vector<float> o = ImageValues(scene.Pass->GetVisibilityImage(0));
    std::vector<float> t = ImageValues(truth->GetVisibilityImage(0));
    if (!previousOurs.empty())
    {
      for (std::size_t i = 0; i < o.size(); ++i)
      {
        if (depth->GetValue(i) >= 1.0f)
        {
          continue;
        }
        // Change beyond the truth's own change (and its sampling noise) over one step.
        const double excess =
          std::abs(o[i] - previousOurs[i]) - std::abs(t[i] - previousTruth[i]) - 0.05;
        worstAll = penumbra_test::Worse(worstAll, excess);
        const auto world = WorldAtPixel(scene.Renderer, i, size[0], depth->GetValue(i));
        const double x = world[0], y = world[1], z = world[2];
        // On the ground, off the box, and more than 0.05 from the lines where the planes of
        // the flipping faces (x = 0.3, z = 0.3) meet it: there the receiver lies in the plane
        // of a silhouette edge's wedge and single pixels drop out for a frame (measured up to
        // 0.45 within 0.045 of the line; Documentation/wedges.md, robustness.md).
        const bool offBox = std::abs(x) > 0.3 || std::abs(z) > 0.3;
        const bool clearOfFacePlanes = std::abs(x - 0.3) > 0.05 && std::abs(z - 0.3) > 0.05;
        if (std::abs(y) < 1e-3 && offBox && clearOfFacePlanes)
        {
          worstGround = penumbra_test::Worse(worstGround, excess);
          ++groundSamples;
        }
      }
    }
    previousOurs = o;
    previousTruth = t;
  }
  std::printf("     worst step beyond the truth's: ground %.3f (%d pixel steps), anywhere %.3f\n",
    worstGround, groundSamples, worstAll);
  Check(groundSamples > 10000, "the ground is in view (pixel-centre unprojection)");
  Check(worstAll <= 1.0, "steps anywhere are finite (not limited: Documentation/wedges.md)");
  Check(worstGround < 0.1,
    "no popping on the ground (clear of the contact) as the light crosses the planes of faces");
}

/// Visibility of light 0 in the last frame, as a vector.
std::vector<float> Visibility(Scene& scene)
{
  return ImageValues(scene.Pass->GetVisibilityImage(0));
}

void TestPlateaus()
{
  // Haines' plateaus on a ground plane marked as the shadow plane. On the ground they must be
  // close to the truth (their umbra is too large by design: bounded error, not exact); off the
  // ground the pass keeps the hard shadow of the light's centre.
  Scene scene;
  scene.Window->SetMultiSamples(0);
  vtkActor* ground = scene.Ground();
  scene.Sphere(-0.8, 0.9, 0, 0.7);
  scene.Box(1.0, 0.6, 0.3, 0.8, 1.2, 0.8);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 0.4);
  scene.Camera(3, 4, 7, 0, 0.5, 0);

  int warnings = 0;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetClientData(&warnings);
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  scene.Pass->AddObserver(vtkCommand::WarningEvent, counter);

  scene.Pass->SetMethodToHardVolumes();
  scene.Window->Render();
  const std::vector<float> hard = Visibility(scene);

  // Without a plane: one warning, and hard shadows.
  scene.Pass->SetMethodToPlateaus();
  scene.Window->Render();
  Check(warnings == 1 && Visibility(scene) == hard,
    "plateaus without a plane: a warning, hard shadows");
  Check(scene.Pass->GetNumberOfPlateauTriangles() == 0, "no plane, no plateau triangles");

  vtkSoftShadowPass::SetShadowPlane(ground, true);
  const SoftComparison plateaus = CompareSoft(scene);
  const std::vector<float> ours = Visibility(scene);
  Check(scene.Pass->GetNumberOfPlateauTriangles() > 100, "plateau triangles drawn");
  CheckSoft("plateaus on the ground plane", plateaus, 0.09, 0.25);
  // Off the plane (the casters' own surfaces): exactly the hard shadow. On it: never darker
  // than the hard shadow, and a penumbra where the hard shadow is lit.
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(scene.Renderer);
  truth->SetSamplesPerLight(1);
  truth->Update();
  auto depth = vtkFloatArray::SafeDownCast(truth->GetDepthImage()->GetPointData()->GetScalars());
  const int* size = scene.Window->GetSize();
  int offPlaneDifferent = 0, lighter = 0, penumbra = 0;
  for (std::size_t i = 0; i < ours.size(); ++i)
  {
    if (depth->GetValue(static_cast<vtkIdType>(i)) >= 1.0f)
    {
      continue;
    }
    const bool onGround =
      std::abs(WorldAtPixel(scene.Renderer, i, size[0], depth->GetValue(i))[1]) < 1e-3;
    offPlaneDifferent += !onGround && std::abs(ours[i] - hard[i]) > 1e-6f;
    lighter += onGround && hard[i] < 0.5f && ours[i] > 0.01f;
    penumbra += onGround && hard[i] > 0.5f && ours[i] < 0.99f;
  }
  std::printf(
    "     off-plane pixels differing from hard: %d, on-plane lit inside the hard shadow: %d, "
    "penumbra pixels outside the hard shadow: %d\n",
    offPlaneDifferent, lighter, penumbra);
  Check(offPlaneDifferent == 0, "plateaus: pixels off the plane keep the hard shadow");
  Check(lighter < 20, "plateaus: the umbra is the hard shadow (outer penumbra only)");
  Check(penumbra > 200, "plateaus: a penumbra outside the hard shadow");

  // The same plane given to the pass, and the linear falloff.
  vtkSoftShadowPass::SetShadowPlane(ground, false);
  scene.Pass->SetReceiverPlaneOrigin(0, 0, 0);
  scene.Pass->SetReceiverPlaneNormal(0, 1, 0);
  scene.Pass->UseReceiverPlaneOn();
  scene.Window->Render();
  const std::vector<float> given = Visibility(scene);
  int different = 0;
  for (std::size_t i = 0; i < given.size(); ++i)
  {
    different += std::abs(given[i] - ours[i]) > 0.05f;
  }
  Check(different < 50,
    "plateaus: a plane set on the pass equals the marked actor (" + std::to_string(different) +
      " px differ)");
  scene.Pass->SetPlateauFalloffToLinear();
  CheckSoft("plateaus, linear falloff", CompareSoft(scene), 0.09, 0.25);
  Check(warnings == 1, "plateaus: no further warning");
}

void TestAutomaticOnLayeredOutlines()
{
  // An isosurface clipped open by its extent: its walls share outlines (silhouette edges of
  // multiplicity 2), which centre-silhouette wedges count twice. Automatic's soft shadow volumes
  // count every light sample exactly, layers and all.
  Scene scene;
  scene.Window->SetMultiSamples(0);
  scene.Ground(6);
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-10, 10, -10, 10, -10, 10);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, 160.0);
  vtkActor* surface = scene.Add(contour, 0.9, 0.55, 0.25);
  surface->GetMapper()->ScalarVisibilityOff();
  surface->SetScale(0.1);
  surface->SetPosition(0, 1.6, 0);
  scene.Light->SetPosition(-1, 5, 1.5);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 0.5);
  scene.Camera(2.5, 5, 6, 0, 0.6, 0);
  scene.Pass->SetMethodToAutomatic();
  const SoftComparison automatic = CompareSoft(scene);
  Check(scene.Pass->GetLightSamples() == 64, "the default is 64 light samples");
  CheckSoft("automatic on a clipped isosurface", automatic, 0.02, 0.03);
  const vtkIdType updates = scene.Pass->GetNumberOfSilhouetteUpdates();
  scene.Renderer->GetActiveCamera()->Azimuth(5);
  scene.Window->Render();
  scene.Renderer->GetActiveCamera()->Azimuth(5);
  scene.Window->Render();
  Check(scene.Pass->GetNumberOfSilhouetteUpdates() == updates,
    "camera orbit does no silhouette work with Automatic's soft shadow volumes");
  scene.Pass->SetMethodToPenumbraWedges();
  const SoftComparison wedges = CompareSoft(scene);
  std::printf("     forced wedges on it: MAE %.4f, >0.1: %.2f%%\n", wedges.Error.MAE,
    100.0 * wedges.Error.FracGt01);
  Check(wedges.Error.MAE > automatic.Error.MAE, "counting is the better choice there");
}

} // namespace

int main(int argc, char* argv[])
{
  static const Features features = {
    { "AveragedHardShadows", TestAveragedHardShadows },
    { "PenumbraWedges", TestPenumbraWedges },
    { "WedgesHardCases", TestWedgesHardCases },
    { "WedgeShapes", TestWedgeShapes },
    { "WedgeCorners", TestWedgeCorners },
    { "WedgesTemporalStability", TestWedgesTemporalStability },
    { "Plateaus", TestPlateaus },
    { "AutomaticOnLayeredOutlines", TestAutomaticOnLayeredOutlines },
  };
  return RunFeatures(argc, argv, features);
}
