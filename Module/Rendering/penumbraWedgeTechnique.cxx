#include "penumbraWedgeTechnique.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "penumbraHorizonFS.h"
#include "penumbraResolveVS.h"
#include "penumbraWedgeFS.h"
#include "penumbraWedgeVS.h"

namespace penumbra
{

vtkIdType WedgeTechnique::UpdateCaster(
  const ShadowLight& light, CasterCache& caster, const ReceiverBounds& receivers)
{
  caster.Wedges[light.Light].Update(*caster.Mesh, caster.Volumes[light.VolumeKey(0)],
    caster.ObjectToWorld, light.World, light.SoftRadius, receivers.Whole);
  return 0; // the centre volume's update is the silhouette update
}

void WedgeTechnique::ResolveSample(ShadowFrame& frame, const ShadowLight&, std::size_t)
{
  frame.LightBackground();
}

void WedgeTechnique::Finish(ShadowFrame& frame, const ShadowLight& light)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkShaderProgram* program = frame.Programs->Ready(
    window, penumbraWedgeVS, penumbraWedgeFS, "penumbra wedge", "penumbra wedges are left out");
  if (!program)
  {
    return;
  }
  vtkOpenGLState* ostate = window->GetState();
  ScopedDrawState saved(ostate);
  frame.DepthCopy()->Activate();
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_CULL_FACE);
  ostate->vtkglEnable(GL_DEPTH_CLAMP);

  frame.SetDepthUniforms(program);
  program->SetUniformf("lightRadius", static_cast<float>(light.SoftRadius));
  for (CasterCache* caster : *frame.Casters)
  {
    if (caster->Culled.count(light.Light))
    {
      continue;
    }
    frame.DrawWedgeBuffer(
      program, *caster, caster->Wedges[light.Light], WedgeCache::Attributes(), light);
  }
  ostate->vtkglDisable(GL_CULL_FACE);

  // Cap by the part of the light above each visible point's own plane (GL_MIN).
  vtkShaderProgram* horizon = frame.Programs->Ready(window, penumbraResolveVS, penumbraHorizonFS,
    "horizon cap", "the wedges' horizon cap is left out");
  if (horizon)
  {
    frame.SetDepthUniforms(horizon);
    horizon->SetUniformf("lightRadius", static_cast<float>(light.SoftRadius));
    frame.SetClipToLight(horizon, light.World);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglBlendEquation(GL_MIN);
    frame.FullScreen->Draw(horizon, this->HorizonVAO);
  }
  frame.DepthCopy()->Deactivate();
}

void WedgeTechnique::ReleaseGraphicsResources(vtkWindow*)
{
  this->HorizonVAO.ReleaseGraphicsResources();
}

} // namespace penumbra
