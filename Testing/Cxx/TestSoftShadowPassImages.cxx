// Regression images of vtkSoftShadowPass (baselines in Testing/Data/Baseline), compared with
// vtkTesting's image difference at VTK's usual threshold. Usage: TestSoftShadowPassImages
// <scene> <baseline.png> <output directory>.
#include "penumbraTestHarness.h"

#include "vtkCamera.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkGlyph3D.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkParametricBoy.h"
#include "vtkParametricFunctionSource.h"
#include "vtkPlaneSource.h"
#include "vtkPointSource.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"

#include <string>

namespace
{
using penumbra::scene::Description;

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
  return penumbra_test::Failures() ? 1 : 0;
}
