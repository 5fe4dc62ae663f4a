#include "penumbraHardShadowTechnique.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include "penumbraResolveVS.h"
#include "penumbraTransmissionResolveFS.h"

namespace penumbra
{

void HardShadowTechnique::BeginTransmission(ShadowFrame& frame)
{
  frame.AttachClearedFloatTarget(this->LogTransmission);
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->vtkglDisable(GL_STENCIL_TEST); // the stencil keeps the opaque casters' count
  ostate->vtkglEnable(GL_BLEND);
  this->TransmissionDrawn = true;
}

void HardShadowTechnique::EndTransmission(ShadowFrame& frame, const ShadowLight& light)
{
  frame.AttachColour(frame.LightIntensity, light.Layer);
}

void HardShadowTechnique::ResolveSample(ShadowFrame& frame, const ShadowLight& light)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  ScopedDrawState saved(ostate);
  const float share = 1.0f / static_cast<float>(light.Samples.size());
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglEnable(GL_STENCIL_TEST);
  ostate->vtkglStencilFunc(GL_NOTEQUAL, 0, 0xFF);
  ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  ostate->vtkglDepthFunc(GL_GREATER);
  frame.DrawResolve(-share);
  if (!this->TransmissionDrawn)
  {
    return;
  }
  this->TransmissionDrawn = false;
  vtkShaderProgram* program = frame.Programs->Ready(frame.Window, penumbraResolveVS,
    penumbraTransmissionResolveFS, "transmission resolve", "translucent casters cast no shadow");
  if (!program)
  {
    return;
  }
  ostate->vtkglStencilFunc(GL_EQUAL, 0, 0xFF);
  this->LogTransmission->Activate();
  program->SetUniformi("logTransmission", this->LogTransmission->GetTextureUnit());
  program->SetUniformf("sampleShare", share);
  frame.FullScreen->Draw(program, this->TransmissionVAO);
  this->LogTransmission->Deactivate();
}

std::size_t HardShadowTechnique::GraphicsMemoryBytes() const
{
  return this->LogTransmission->GetHandle()
    ? static_cast<std::size_t>(this->LogTransmission->GetWidth()) *
      this->LogTransmission->GetHeight() * 4
    : 0;
}

void HardShadowTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->LogTransmission->ReleaseGraphicsResources(window);
  this->TransmissionVAO.ReleaseGraphicsResources();
  this->TransmissionDrawn = false;
}

} // namespace penumbra
