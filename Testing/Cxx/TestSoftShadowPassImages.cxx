// Regression images of vtkSoftShadowPass (baselines in Testing/Data/Baseline), compared with
// vtkTesting's image difference at VTK's usual threshold, and each shadowing light's
// visibility with the ray-traced truth. Usage: TestSoftShadowPassImages <scene>
// <baseline.png> <output directory>.
#include "penumbraTestHarness.h"

#include "vtkCamera.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkGlyph3D.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkParametricBoy.h"
#include "vtkParametricFunctionSource.h"
#include "vtkPlaneSource.h"
#include "vtkPointSource.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"

#include <set>
#include <string>
#include <vector>

namespace
{
using penumbra::scene::Description;

/// Largest MAE against the truth of a light with a radius, over the pixels either shadows (the
/// soft scene measured 0.0077 on 2026-12-07).
constexpr double SoftMAE = 0.015;
/// Plateaus cannot beat the hard shadow on mean error (Documentation/plateaus.md): the soft
/// scene measured 0.178 against the same light's hard shadow's 0.135 (1.32 times) on
/// 2026-12-07. They may exceed the hard shadow's by this share.
constexpr double PlateauExcess = 0.5;

/// An isosurface of vtkRTAnalyticSource (open where the extent clips it) and sphere glyphs
/// over a ground plane, under a positional key light and a second, coloured directional light.
Description ScientificScene()
{
  Description scene;
  scene.Name = "scientific";
  vtkNew<vtkRTAnalyticSource> field;
  field->SetWholeExtent(-10, 10, -10, 10, -10, 10);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(field->GetOutputPort());
  contour->SetValue(0, 200);
  auto surface = penumbra_test::MakeActor(contour, 0.8, 0.55, 0.3);
  surface->GetMapper()->ScalarVisibilityOff();
  surface->SetScale(0.1);
  surface->SetPosition(0, 1.3, 0);
  surface->GetProperty()->SetSpecular(0.4);
  surface->GetProperty()->SetSpecularPower(40);
  scene.Add(surface);

  vtkNew<vtkPointSource> seeds;
  seeds->SetNumberOfPoints(40);
  seeds->SetRadius(2.5);
  seeds->SetCenter(0, 0.6, 0);
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(0.12);
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputConnection(seeds->GetOutputPort());
  glyphs->SetSourceConnection(ball->GetOutputPort());
  scene.Add(penumbra_test::MakeActor(glyphs, 0.3, 0.5, 0.9));

  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-4, -0.2, -4);
  ground->SetPoint1(4, -0.2, -4);
  ground->SetPoint2(-4, -0.2, 4);
  scene.Add(penumbra_test::MakeActor(ground, 0.85, 0.85, 0.8));

  scene.AddLight(true, { -2, 6, 2 }, 0.0);
  vtkLight* fill = scene.AddLight(false, { 3, 4, 1 }, 0.0);
  fill->SetDiffuseColor(0.4, 0.5, 0.9);
  fill->SetIntensity(0.5);
  scene.SetCamera({ 3.5, 5, 7 }, { 0, 0.8, 0 }, { 0, 1, 0 }, 30);
  return scene;
}

/// Boy's surface (non-orientable, self-intersecting) over a PBR ground, seen from inside the
/// shadow of a roof.
Description AwkwardScene()
{
  Description scene;
  scene.Name = "awkward";
  vtkNew<vtkParametricBoy> boy;
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(boy);
  source->SetUResolution(60);
  source->SetVResolution(60);
  auto surface = penumbra_test::MakeActor(source, 0.3, 0.8, 0.5);
  surface->SetPosition(0, 1.2, 0);
  scene.Add(surface);

  vtkNew<vtkPlaneSource> roof;
  roof->SetOrigin(-1, 3.5, 1.5);
  roof->SetPoint1(3, 3.5, 1.5);
  roof->SetPoint2(-1, 3.5, 6);
  scene.Add(penumbra_test::MakeActor(roof, 0.7, 0.7, 0.75));

  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-5, 0, -5);
  ground->SetPoint1(5, 0, -5);
  ground->SetPoint2(-5, 0, 5);
  auto floor = penumbra_test::MakeActor(ground, 0.9, 0.9, 0.9);
  floor->GetProperty()->SetInterpolationToPBR();
  floor->GetProperty()->SetRoughness(0.5);
  scene.Add(floor);

  scene.AddLight(true, { 0.5, 8, 2.5 }, 0.0);
  scene.SetCamera({ 0.8, 1.0, 3.5 }, { 0, 0.8, 0 }, { 0, 1, 0 }, 30);
  return scene;
}

/// Soft shadows from penumbra wedges: a box resting on the ground (the penumbra shrinks to zero
/// at the contact), overlapping casters and a curved receiver under a large spherical light.
Description SoftScene()
{
  Description scene;
  scene.Name = "soft";
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-4, 0, -4);
  ground->SetPoint1(4, 0, -4);
  ground->SetPoint2(-4, 0, 4);
  auto groundActor = penumbra_test::MakeActor(ground, 0.85, 0.85, 0.8);
  vtkSoftShadowPass::SetShadowPlane(groundActor, true); // for the plateaus variant
  scene.Add(groundActor);
  vtkNew<vtkCubeSource> box;
  box->SetCenter(1.2, 0.5, -0.5);
  box->SetXLength(0.8);
  box->SetYLength(1.0);
  box->SetZLength(0.8);
  scene.Add(penumbra_test::MakeActor(box, 0.3, 0.5, 0.9));
  vtkNew<vtkSphereSource> first, second;
  first->SetCenter(-0.9, 1.1, 0.2);
  first->SetRadius(0.5);
  second->SetCenter(-0.4, 1.5, 0.5);
  second->SetRadius(0.35);
  for (vtkSphereSource* sphere : { first.GetPointer(), second.GetPointer() })
  {
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
    scene.Add(penumbra_test::MakeActor(sphere, 0.9, 0.3, 0.3));
  }
  vtkNew<vtkCylinderSource> hump;
  hump->SetCenter(0, 0, 0);
  hump->SetRadius(0.6);
  hump->SetHeight(3);
  hump->SetResolution(48);
  auto curved = penumbra_test::MakeActor(hump, 0.8, 0.8, 0.6);
  curved->RotateZ(90);
  curved->SetPosition(0.2, -0.25, 1.6);
  scene.Add(curved);
  scene.AddLight(true, { -1.5, 5, 2 }, 0.7);
  scene.SetCamera({ 3, 4.5, 6.5 }, { 0, 0.4, 0.3 }, { 0, 1, 0 }, 30);
  return scene;
}

/// The MAE of light `index`'s visibility against `truth`, over the pixels either shadows.
double SoftError(penumbra_test::PassScene& view, vtkRayTracedVisibility* truth, int index)
{
  vtkImageData* image = view.Pass->GetVisibilityImage(index);
  return penumbra_test::VisibilityError(penumbra_test::ImageValues(image), truth, index,
    penumbra_test::WindowDepth(view.Window, view.Renderer))
    .MAE;
}

/// Each shadowing light's visibility against the ray-traced truth: hard lights as the other
/// hard-shadow tests judge them (CheckAgainstTruth), lights with a radius by their MAE (SoftMAE;
/// plateaus against the hard shadow's, PlateauExcess).
void CheckLightsAgainstTruth(penumbra_test::PassScene& view, const std::string& name)
{
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(view.Renderer);
  truth->SetSamplesPerLight(256);
  penumbra_test::Check(truth->Update(), name + ": ray tracer ran");
  vtkLightCollection* lights = view.Renderer->GetLights();
  std::vector<int> soft;
  int compared = 0;
  for (int i = 0; i < lights->GetNumberOfItems(); ++i)
  {
    if (!view.Pass->GetVisibilityImage(i))
    {
      continue;
    }
    ++compared;
    const std::string light = name + " light " + std::to_string(i);
    if (vtkSoftShadowPass::GetLightRadius(vtkLight::SafeDownCast(lights->GetItemAsObject(i))) > 0)
    {
      soft.push_back(i);
      continue;
    }
    penumbra_test::CheckAgainstTruth(
      light, penumbra_test::CompareWithTruth(view.Window, view.Renderer, view.Pass, i));
  }
  penumbra_test::Check(compared == view.Pass->GetNumberOfShadowingLights(),
    name + ": every shadowing light compared with the truth");
  std::vector<double> errors;
  for (int i : soft)
  {
    errors.push_back(SoftError(view, truth, i));
  }
  if (name == "plateaus")
  {
    view.Pass->SetMethodToHardVolumes();
    view.Window->Render();
  }
  for (std::size_t k = 0; k < soft.size(); ++k)
  {
    const std::string light = name + " light " + std::to_string(soft[k]);
    if (name == "plateaus")
    {
      const double hard = SoftError(view, truth, soft[k]);
      std::printf("     %s: MAE %.4f against the truth, the hard shadow's %.4f\n", light.c_str(),
        errors[k], hard);
      penumbra_test::Check(errors[k] <= (1.0 + PlateauExcess) * hard,
        light + ": plateaus' MAE near the hard shadow's");
      continue;
    }
    std::printf("     %s: MAE %.4f against the truth\n", light.c_str(), errors[k]);
    penumbra_test::Check(
      errors[k] <= SoftMAE, light + ": MAE within " + std::to_string(SoftMAE) + " of the truth");
  }
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 4)
  {
    std::fprintf(
      stderr, "usage: %s scientific|awkward|soft|plateaus baseline.png output-dir\n", argv[0]);
    return 2;
  }
  const std::string name = argv[1];
  if (!std::set<std::string>{ "scientific", "awkward", "soft", "plateaus" }.count(name))
  {
    std::fprintf(stderr, "unknown scene %s\n", name.c_str());
    return 2;
  }
  penumbra_test::PassScene view(400, 300);
  view.Renderer->SetBackground(0.15, 0.17, 0.25);
  // The plateaus variant is the soft scene with Haines' plateaus on the ground plane.
  const Description scene = name == "scientific" ? ScientificScene()
    : name == "awkward"                          ? AwkwardScene()
                                                 : SoftScene();
  view.AddDescription(scene);
  if (name == "awkward")
  {
    // The eye is inside the roof's shadow, close to Boy's surface: a near plane of 0.1.
    view.Renderer->GetActiveCamera()->SetClippingRange(0.1, 30);
  }
  if (name == "plateaus")
  {
    view.Pass->SetMethodToPlateaus();
  }
  view.Window->Render();

  vtkNew<vtkTesting> testing;
  testing->AddArgument("-V");
  testing->AddArgument(argv[2]);
  testing->AddArgument("-T");
  testing->AddArgument(argv[3]);
  testing->SetRenderWindow(view.Window);
  const int result = testing->RegressionTest(10);
  penumbra_test::Check(result == vtkTesting::PASSED, name + " matches its baseline image");
  penumbra_test::Check(
    view.Pass->GetNumberOfShadowingLights() >= 1, name + " has shadowing lights");
  CheckLightsAgainstTruth(view, name);
  return penumbra_test::Failures() ? 1 : 0;
}
