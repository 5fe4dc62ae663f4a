// MinimalShadows: the least an application needs for soft shadows. A sphere over a plane, one
// scene light of radius 0.3, and vtkSoftShadowPass set on the renderer. It links
// Penumbra::Rendering only: no ray tracer, no Embree.
//
//   MinimalShadows [FILE.png]    render one frame and write it (default minimal_shadows.png)
//   MinimalShadows --no-render   build the scene and the pass, draw nothing (no display needed)

#include "vtkSoftShadowPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <string>

namespace
{
vtkSmartPointer<vtkActor> ActorOf(vtkPolyDataAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string argument = argc > 1 ? argv[1] : "minimal_shadows.png";

  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-3, 0, -3);
  ground->SetPoint1(3, 0, -3);
  ground->SetPoint2(-3, 0, 3);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 1, 0);
  sphere->SetRadius(0.6);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(ActorOf(ground));
  renderer->AddActor(ActorOf(sphere));
  // Shadows come from scene and camera lights (headlights cast none).
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetConeAngle(180);
  light->SetPosition(1.5, 5, 1);
  vtkSoftShadowPass::SetLightRadius(light, 0.3); // an area light: soft shadows
  renderer->AddLight(light);

  vtkNew<vtkSoftShadowPass> shadows;
  renderer->SetPass(shadows);
  if (argument == "--no-render")
  {
    return shadows->GetLightSamples() > 0 ? 0 : 1;
  }

  vtkNew<vtkRenderWindow> window;
  window->SetSize(640, 480);
  window->AddRenderer(renderer);
  renderer->GetActiveCamera()->SetPosition(3, 4, 6);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0.5, 0);
  renderer->ResetCameraClippingRange();
  window->Render();
  vtkNew<vtkWindowToImageFilter> image;
  image->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(image->GetOutputPort());
  writer->SetFileName(argument.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0 ? 0 : 1;
}
