/**
 * @class   vtkRendererSettingsPass
 * @brief   Renders a renderer's props as vtkOpenGLRenderer does without a pass, honouring its
 *          settings.
 *
 * Setting a pass on a renderer replaces vtkOpenGLRenderer::DeviceRender, and with it everything
 * the renderer's own settings asked for: vtkRenderStepsPass draws translucent props with plain
 * alpha blending and knows nothing of FXAA or SSAO. This pass runs VTK's own steps in VTK's
 * order instead, reading the renderer's settings every frame:
 * - the camera and lights (vtkCameraPass, vtkLightsPass);
 * - opaque geometry through vtkRenderer::DeviceRenderOpaqueGeometry: hidden-line removal and
 *   SSAO (UseHiddenLineRemoval, UseSSAO and its radius, bias, kernel and blur);
 * - translucent geometry through vtkRenderer::DeviceRenderTranslucentPolygonalGeometry: depth
 *   peeling (dual where supported, MaximumNumberOfPeels, OcclusionRatio) or VTK's
 *   order-independent translucency;
 * - FXAA (UseFXAA, FXAAOptions), before volumes and overlays as in VTK;
 * - volumes (unless depth peeling already drew them, UseDepthPeelingForVolumes) and overlays.
 * A selection render (vtkHardwareSelector, vtkPropPicker, vtkRenderer::PickProp) draws the props
 * through the renderer's selector instead, as vtkRenderer does without a pass.
 *
 * It is vtkSoftShadowPass's default delegate, so that a renderer looks the same with and
 * without shadows wherever the shadows are not.
 */
#ifndef vtkRendererSettingsPass_h
#define vtkRendererSettingsPass_h

#include "vtkPenumbraRenderingModule.h" // for export macro
#include "vtkRenderPass.h"

#include <memory>

class VTKPENUMBRARENDERING_EXPORT vtkRendererSettingsPass : public vtkRenderPass
{
public:
  static vtkRendererSettingsPass* New();
  vtkTypeMacro(vtkRendererSettingsPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkRendererSettingsPass();
  ~vtkRendererSettingsPass() override;

private:
  vtkRendererSettingsPass(const vtkRendererSettingsPass&) = delete;
  void operator=(const vtkRendererSettingsPass&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
