#include "vtkRendererSettingsPass.h"

#include "penumbraWindowReleaseCallback.h"

#include "vtkCameraPass.h"
#include "vtkHardwareSelector.h"
#include "vtkLightsPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOverlayPass.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkVolumetricPass.h"

#include <memory>
#include <vector>

namespace
{
/// vtkViewport::PickFromProps, which VTK 9.1 keeps protected: the props a vtkRenderer::PickProp
/// call restricts its selection to (nullptr: every prop).
struct PickFromPropsOf : vtkViewport
{
  static vtkPropCollection* Get(vtkViewport* viewport)
  {
    return viewport->*(&PickFromPropsOf::PickFromProps);
  }
};

/// A selection render (vtkHardwareSelector, vtkPropPicker, vtkRenderer::PickProp) as
/// vtkRenderer::UpdateGeometry sends it when the renderer has no pass: every prop, or those it
/// picks from, drawn by the selector with their ids. Returns the props drawn.
int RenderForSelection(
  vtkRenderer* renderer, vtkHardwareSelector* selector, const vtkRenderState* s)
{
  vtkPropCollection* pickFrom = PickFromPropsOf::Get(renderer);
  if (!pickFrom)
  {
    return selector->Render(renderer, s->GetPropArray(), s->GetPropArrayCount());
  }
  std::vector<vtkProp*> props;
  vtkCollectionSimpleIterator it;
  vtkProp* prop;
  for (pickFrom->InitTraversal(it); (prop = pickFrom->GetNextProp(it));)
  {
    if (prop->GetVisibility())
    {
      props.push_back(prop);
    }
  }
  return props.empty() ? 0
                       : selector->Render(renderer, props.data(), static_cast<int>(props.size()));
}

/// What runs inside the camera pass: VTK's steps after the camera, as DeviceRender orders them.
class vtkRendererSettingsSteps : public vtkRenderPass
{
public:
  static vtkRendererSettingsSteps* New();
  vtkTypeMacro(vtkRendererSettingsSteps, vtkRenderPass);

  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    auto renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
    if (!renderer)
    {
      return;
    }
    if (vtkHardwareSelector* selector = renderer->GetSelector())
    {
      this->NumberOfRenderedProps = RenderForSelection(renderer, selector, s);
      return;
    }
    const int before = renderer->GetNumberOfPropsRendered();
    this->Lights->Render(s);
    renderer->DeviceRenderOpaqueGeometry(s->GetFrameBuffer());

    bool translucent = false;
    for (int i = 0; i < s->GetPropArrayCount() && !translucent; ++i)
    {
      translucent = s->GetPropArray()[i]->HasTranslucentPolygonalGeometry() != 0;
    }
    if (translucent)
    {
      renderer->DeviceRenderTranslucentPolygonalGeometry(s->GetFrameBuffer());
    }
    if (renderer->GetUseFXAA())
    {
      if (renderer->GetFXAAOptions())
      {
        this->FXAA->UpdateConfiguration(renderer->GetFXAAOptions());
      }
      this->FXAA->Execute(renderer);
    }
    // Dual depth peeling draws volumes with the translucent props when asked to.
    if (!translucent || !renderer->GetUseDepthPeeling() ||
      !renderer->GetUseDepthPeelingForVolumes())
    {
      this->Volumes->Render(s);
      this->NumberOfRenderedProps += this->Volumes->GetNumberOfRenderedProps();
    }
    this->Overlays->Render(s);
    this->NumberOfRenderedProps += this->Overlays->GetNumberOfRenderedProps();
    // The renderer counts what its own Device* calls drew.
    this->NumberOfRenderedProps += renderer->GetNumberOfPropsRendered() - before;
  }

  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    this->FXAA->ReleaseGraphicsResources();
    this->Volumes->ReleaseGraphicsResources(w);
    this->Overlays->ReleaseGraphicsResources(w);
    this->Superclass::ReleaseGraphicsResources(w);
  }

private:
  vtkNew<vtkLightsPass> Lights;
  vtkNew<vtkOpenGLFXAAFilter> FXAA;
  vtkNew<vtkVolumetricPass> Volumes;
  vtkNew<vtkOverlayPass> Overlays;
};
vtkStandardNewMacro(vtkRendererSettingsSteps);
} // namespace

class vtkRendererSettingsPass::vtkInternals
{
public:
  vtkNew<vtkCameraPass> Camera;
  vtkNew<vtkRendererSettingsSteps> Steps;
  /// Releases FXAA's and the steps' GPU resources when the window goes, even while the pass is
  /// off its renderer (which then does not release it).
  std::unique_ptr<penumbra::WindowReleaseCallback> WindowRelease;
};

vtkStandardNewMacro(vtkRendererSettingsPass);

vtkRendererSettingsPass::vtkRendererSettingsPass()
  : Internals(new vtkInternals)
{
  this->Internals->Camera->SetDelegatePass(this->Internals->Steps);
  this->Internals->WindowRelease.reset(new penumbra::WindowReleaseCallback(
    [this](vtkWindow* w) { this->ReleaseGraphicsResources(w); }));
}

vtkRendererSettingsPass::~vtkRendererSettingsPass()
{
  this->Internals->WindowRelease->Release();
}

void vtkRendererSettingsPass::Render(const vtkRenderState* s)
{
  this->Internals->WindowRelease->RegisterGraphicsResources(
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow()));
  this->Internals->Camera->Render(s);
  this->NumberOfRenderedProps = this->Internals->Camera->GetNumberOfRenderedProps();
}

void vtkRendererSettingsPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Internals->Camera->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}

void vtkRendererSettingsPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent
     << "Steps: camera, lights, opaque (hidden-line removal, SSAO), translucent (depth "
        "peeling, OIT), FXAA, volumes, overlays, as the renderer's settings ask\n";
}
