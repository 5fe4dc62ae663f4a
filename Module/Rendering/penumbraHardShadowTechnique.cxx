#include "penumbraHardShadowTechnique.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "penumbraResolveVS.h"
#include "penumbraSampleCountResolveFS.h"
#include "penumbraTransmissionResolveFS.h"

namespace penumbra
{
namespace
{
/// Draws a resolve over the viewport that reads `texture` through `sampler` and takes one
/// sample's `share` of the light.
void DrawSampleResolve(ShadowFrame& frame, vtkShaderProgram* program, vtkTextureObject* texture,
  const char* sampler, float share, FullScreenTriangle::VAO& vao)
{
  texture->Activate();
  program->SetUniformi(sampler, texture->GetTextureUnit());
  program->SetUniformf("sampleShare", share);
  frame.FullScreen->Draw(program, vao);
  texture->Deactivate();
}
} // namespace

bool HardShadowTechnique::CountsInColour(const ShadowLight& light) const
{
  // Translucent casters multiply where the opaque count is 0: that test keeps the stencil.
  return !light.ShadowedByTranslucentCasters &&
    (light.Samples.size() == 1 || this->AveragedInColour.count(light.Light));
}

void HardShadowTechnique::PrepareLight(
  const ShadowLight& light, const std::vector<CasterCache*>& casters)
{
  std::size_t sides = 0, repeated = 0;
  for (CasterCache* caster : casters)
  {
    if (caster->Translucent() || caster->Culled.count(light.Light))
    {
      continue;
    }
    const auto cached = caster->Volumes.find(light.VolumeKey(0));
    if (cached != caster->Volumes.end())
    {
      sides += cached->second.Volume.Sides.size();
      repeated += cached->second.Volume.RepeatedSideIndices();
    }
  }
  if (sides > 0 &&
    static_cast<double>(repeated) >= AveragedColourShare * static_cast<double>(sides))
  {
    this->AveragedInColour.insert(light.Light);
  }
  else
  {
    this->AveragedInColour.erase(light.Light);
  }
}

void HardShadowTechnique::AttachSampleCount(ShadowFrame& frame)
{
  frame.AttachClearedFloatTarget(this->SampleCount);
}

void HardShadowTechnique::BeginVolumes(ShadowFrame& frame, const ShadowLight& light)
{
  if (this->CountsInColour(light) && light.Samples.size() > 1)
  {
    this->AttachSampleCount(frame);
  }
}

void HardShadowTechnique::ResolveSample(ShadowFrame& frame, const ShadowLight& light, std::size_t k)
{
  const float share = 1.0f / static_cast<float>(light.Samples.size());
  if (this->CountsInColour(light))
  {
    if (light.Samples.size() == 1)
    {
      frame.LightBackground(); // the count went straight into the layer
      return;
    }
    this->ResolveSampleCount(frame, light, share);
    if (k + 1 < light.Samples.size())
    {
      this->AttachSampleCount(frame);
    }
    return;
  }
  vtkOpenGLState* ostate = frame.Window->GetState();
  ScopedDrawState saved(ostate);
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
  DrawSampleResolve(
    frame, program, this->LogTransmission, "logTransmission", share, this->TransmissionVAO);
}

void HardShadowTechnique::ResolveSampleCount(
  ShadowFrame& frame, const ShadowLight& light, float share)
{
  frame.AttachColour(frame.Layers(), light.Layer);
  vtkShaderProgram* program = frame.Programs->Ready(frame.Window, penumbraResolveVS,
    penumbraSampleCountResolveFS, "sample count resolve", "averaged shadows are not written");
  if (!program)
  {
    return;
  }
  // At every geometry pixel (the far-plane triangle passes GL_GREATER exactly there).
  vtkOpenGLState* ostate = frame.Window->GetState();
  ScopedDrawState saved(ostate);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglDepthFunc(GL_GREATER);
  DrawSampleResolve(frame, program, this->SampleCount, "sampleCount", share, this->SampleCountVAO);
}

std::size_t HardShadowTechnique::GraphicsMemoryBytes() const
{
  return TextureBytes(this->SampleCount) + TextureBytes(this->LogTransmission);
}

void HardShadowTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->SampleCount->ReleaseGraphicsResources(window);
  this->SampleCountVAO.ReleaseGraphicsResources();
  this->LogTransmission->ReleaseGraphicsResources(window);
  this->TransmissionVAO.ReleaseGraphicsResources();
}

} // namespace penumbra
