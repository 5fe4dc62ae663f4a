#include "penumbraHardShadowTechnique.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "penumbraResolveVS.h"
#include "penumbraTransmissionResolveFS.h"

namespace penumbra
{

bool HardShadowTechnique::CountsInColour(const ShadowLight& light) const
{
  // Averaged samples each need their own count before the share is taken (a count of 2 must
  // not take two shares), and translucent casters multiply where the count is 0: both keep the
  // stencil.
  return light.Samples.size() == 1 && !light.ShadowedByTranslucentCasters;
}

void HardShadowTechnique::ResolveSample(ShadowFrame& frame, const ShadowLight& light, std::size_t k)
{
  if (this->CountsInColour(light))
  {
    return;
  }
  vtkOpenGLState* ostate = frame.Window->GetState();
  ScopedDrawState saved(ostate);
  const float share = 1.0f / static_cast<float>(light.Samples.size());
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglEnable(GL_STENCIL_TEST);
  ostate->vtkglStencilFunc(GL_NOTEQUAL, 0, 0xFF);
  ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  ostate->vtkglDepthFunc(GL_GREATER);
  frame.DrawResolve(-share);
  if (!light.ShadowedByTranslucentCasters)
  {
    return;
  }
  const PixelRect covered = frame.DrawTranslucentVolumes(light, k, 1, this->LogTransmission, 1);
  if (covered.Empty())
  {
    return;
  }
  vtkShaderProgram* program = frame.Programs->Ready(frame.Window, penumbraResolveVS,
    penumbraTransmissionResolveFS, "transmission resolve", "translucent casters cast no shadow");
  if (!program)
  {
    return;
  }
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  SetScissor(ostate, covered);
  ostate->vtkglEnable(GL_STENCIL_TEST);
  ostate->vtkglStencilFunc(GL_EQUAL, 0, 0xFF);
  ostate->vtkglEnable(GL_BLEND);
  this->LogTransmission->Activate();
  program->SetUniformi("logTransmission", this->LogTransmission->GetTextureUnit());
  program->SetUniformf("sampleShare", share);
  frame.FullScreen->Draw(program, this->TransmissionVAO);
  this->LogTransmission->Deactivate();
}

std::size_t HardShadowTechnique::GraphicsMemoryBytes() const
{
  return TextureBytes(this->LogTransmission);
}

void HardShadowTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->LogTransmission->ReleaseGraphicsResources(window);
  this->TransmissionVAO.ReleaseGraphicsResources();
}

} // namespace penumbra
