// penumbraShadowMap.h: VTK 9.1's shadow maps (vtkShadowMapBakerPass + vtkShadowMapPass) set up
// as in VTK's TestShadowMapPass, for PenumbraBench and PenumbraDemo to compare against.
// Header-only; needs VTK::RenderingOpenGL2.
//
// VTK 9.1 bakes a spot light's map with the light camera's projection at the renderer's aspect
// ratio (vtkOpenGLCamera::GetKeyMatrices uses GetTiledAspectRatio) but vtkShadowMapPass looks it
// up at aspect 1, so in any non-square window every shadow is stretched and misplaced (VTK's own
// test renders a square window). MakeShadowMapPass(resolution, true) wraps the baker in
// SquareAspectPass, which bakes with the renderer's viewport shrunk to a square; the map has its
// own framebuffer, so nothing else changes. Pass false for VTK's behaviour as it is.
#ifndef penumbraShadowMap_h
#define penumbraShadowMap_h

#include "vtkCameraPass.h"
#include "vtkNew.h"
#include "vtkRenderPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkSmartPointer.h"

namespace penumbra
{
namespace bench
{

/// Renders its delegate with the renderer's viewport shrunk to a square (see the file comment).
class SquareAspectPass : public vtkRenderPass
{
public:
  static SquareAspectPass* New()
  {
    SquareAspectPass* pass = new SquareAspectPass;
    pass->InitializeObjectBase();
    return pass;
  }
  vtkTypeMacro(SquareAspectPass, vtkRenderPass);

  vtkSmartPointer<vtkRenderPass> Delegate;

  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (!this->Delegate)
    {
      return;
    }
    vtkRenderer* renderer = s->GetRenderer();
    double viewport[4];
    renderer->GetViewport(viewport);
    int width = 0, height = 0, x = 0, y = 0;
    renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
    const bool shrink = width > 0 && height > 0 && width != height;
    if (shrink)
    {
      double square[4] = { viewport[0], viewport[1], viewport[2], viewport[3] };
      if (width > height)
      {
        square[2] = viewport[0] + (viewport[2] - viewport[0]) * height / width;
      }
      else
      {
        square[3] = viewport[1] + (viewport[3] - viewport[1]) * width / height;
      }
      renderer->SetViewport(square);
    }
    this->Delegate->Render(s);
    this->NumberOfRenderedProps = this->Delegate->GetNumberOfRenderedProps();
    if (shrink)
    {
      renderer->SetViewport(viewport);
    }
  }

  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    if (this->Delegate)
    {
      this->Delegate->ReleaseGraphicsResources(window);
    }
    this->Superclass::ReleaseGraphicsResources(window);
  }

protected:
  SquareAspectPass() = default;
  ~SquareAspectPass() override = default;

private:
  SquareAspectPass(const SquareAspectPass&) = delete;
  void operator=(const SquareAspectPass&) = delete;
};

/**
 * The pass to install with renderer->SetPass for shadow maps of `resolution` texels a side:
 * camera pass -> sequence [baker, shadow map pass], the latter drawing the opaque geometry
 * through its default [lights, opaque] sequence. Only spot lights (cone angle < 90) and
 * directional lights cast shadows. VTK re-bakes the maps only when a light or a prop changes.
 */
inline vtkSmartPointer<vtkRenderPass> MakeShadowMapPass(int resolution, bool squareBake = true)
{
  vtkNew<vtkShadowMapPass> shadows;
  shadows->GetShadowMapBakerPass()->SetResolution(resolution);
  vtkNew<vtkRenderPassCollection> passes;
  if (squareBake)
  {
    vtkNew<SquareAspectPass> bake;
    bake->Delegate = shadows->GetShadowMapBakerPass();
    passes->AddItem(bake);
  }
  else
  {
    passes->AddItem(shadows->GetShadowMapBakerPass());
  }
  passes->AddItem(shadows);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  auto camera = vtkSmartPointer<vtkCameraPass>::New();
  camera->SetDelegatePass(sequence);
  return camera;
}

} // namespace bench
} // namespace penumbra

#endif
