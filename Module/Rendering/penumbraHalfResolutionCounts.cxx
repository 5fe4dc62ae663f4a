#include "penumbraHalfResolutionCounts.h"

#include "penumbraLightIntensityBuffer.h"
#include "penumbraShadowTechnique.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <string>

#include "penumbraHalfDepthFS.h"
#include "penumbraHalfUpsampleFS.h"
#include "penumbraResolveVS.h"

namespace penumbra
{

namespace
{
constexpr const char* FullResolutionInstead = "soft shadows are counted at full resolution";
}

glm::ivec2 HalfResolutionCounts::CounterSize(const int size[2])
{
  return { (size[0] + 1) / 2, (size[1] + 1) / 2 };
}

glm::vec4 HalfResolutionCounts::ClipToCounters(const int size[2])
{
  // Window x of the counters is (X + 0.5) / 2 for the viewport's window X = (ndc + 1) W / 2, so
  // that texel t's centre, t + 0.5, is pixel 2t's centre, 2t + 0.5.
  const glm::vec2 pixels(size[0], size[1]);
  const glm::vec2 texels(CounterSize(size));
  return { pixels / (2.0f * texels), (0.5f * pixels + 0.5f) / texels - 1.0f };
}

bool HalfResolutionCounts::ReadyPrograms(ShadowFrame& frame)
{
  if (this->ProgramsFailed)
  {
    return false;
  }
  vtkOpenGLRenderWindow* window = frame.Window;
  std::string markFS = penumbraHalfUpsampleFS;
  vtkShaderProgram::Substitute(
    markFS, "//PENUMBRA::Defines", "#define PENUMBRA_MARK_UNCERTAIN", false);
  this->DepthProgram = frame.Programs->Ready(
    window, penumbraResolveVS, penumbraHalfDepthFS, "half-resolution depth", FullResolutionInstead);
  this->UpsampleProgram = frame.Programs->Ready(window, penumbraResolveVS, penumbraHalfUpsampleFS,
    "half-resolution upsample", FullResolutionInstead);
  this->MarkProgram = frame.Programs->Ready(window, penumbraResolveVS, markFS.c_str(),
    "half-resolution uncertain pixels", FullResolutionInstead);
  this->ProgramsFailed = !this->DepthProgram || !this->UpsampleProgram || !this->MarkProgram;
  return !this->ProgramsFailed;
}

bool HalfResolutionCounts::Begin(ShadowFrame& frame)
{
  if (!this->ReadyPrograms(frame) ||
    !frame.Programs->Bind(frame.Window, this->DepthProgram, "half-resolution depth"))
  {
    return false;
  }
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkShaderProgram* program = this->DepthProgram;
  const glm::ivec2 size = CounterSize(frame.Size);
  // A new window releases the textures (SetContext), so both are allocated again.
  if (this->Framebuffer->GetContext() != window)
  {
    this->Framebuffer->SetContext(window);
    this->DepthStencil->SetContext(window);
    this->Size = glm::ivec2(0);
  }
  if (size != this->Size)
  {
    this->DepthStencil->AllocateDepthStencil(size.x, size.y);
    this->Size = size;
  }
  if (TextureNeedsAllocation(
        this->Visibility, window, size.x, size.y, 1, 1, vtkTextureObject::Nearest))
  {
    this->Visibility->Allocate2D(size.x, size.y, 1, VTK_FLOAT);
  }
  this->Framebuffer->Bind();
  glFramebufferTexture2D(
    GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, this->DepthStencil->GetHandle(), 0);
  this->AttachVisibility();

  // The viewport stays for the wedges; the stencil is cleared by their pass.
  vtkOpenGLState* ostate = window->GetState();
  ostate->vtkglViewport(0, 0, size.x, size.y);
  {
    ScopedDrawState saved(ostate);
    ostate->vtkglDisable(GL_SCISSOR_TEST);
    ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_STENCIL_TEST);
    ostate->vtkglDisable(GL_CULL_FACE);
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
    frame.DepthCopy()->Activate();
    program->SetUniformi("depthTexture", frame.DepthCopy()->GetTextureUnit());
    frame.FullScreen->Draw(program, this->DepthVAO);
    frame.DepthCopy()->Deactivate();
  }
  return true;
}

void HalfResolutionCounts::AttachVisibility()
{
  this->Framebuffer->RemoveColorAttachment(0);
  this->Framebuffer->AddColorAttachment(0, this->Visibility);
  this->Framebuffer->ActivateDrawBuffer(0);
}

bool HalfResolutionCounts::Upsample(
  ShadowFrame& frame, int layer, float uncertain, vtkTextureObject* centreCount)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkShaderProgram* mark = this->MarkProgram;
  vtkShaderProgram* upsample = this->UpsampleProgram;
  vtkOpenGLState* ostate = window->GetState();
  frame.Buffer->BindLayer(layer);
  ostate->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
  // At every geometry pixel: the far-plane triangle passes GL_GREATER exactly there.
  ScopedDrawState saved(ostate);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_DEPTH_CLAMP);
  ostate->vtkglDepthFunc(GL_GREATER);
  ostate->vtkglDepthMask(GL_FALSE);
  frame.DepthCopy()->Activate();
  this->Visibility->Activate();
  centreCount->Activate();
  // The mean at every geometry pixel, marked certain in the stencil; then uncertain where the
  // mark shader keeps the pixel. The background keeps 0.
  ostate->vtkglStencilMask(0xFF);
  ostate->vtkglClear(GL_STENCIL_BUFFER_BIT);
  ostate->vtkglEnable(GL_STENCIL_TEST);
  ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  ostate->vtkglStencilFunc(GL_ALWAYS, CertainStencil, 0xFF);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const bool averaged = frame.Programs->Bind(window, upsample, "half-resolution upsample");
  if (averaged)
  {
    this->SetUniforms(frame, upsample, uncertain, centreCount);
    frame.FullScreen->Draw(upsample, this->UpsampleVAO);
  }
  ostate->vtkglStencilFunc(GL_ALWAYS, UncertainStencil, 0xFF);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  const bool marked =
    averaged && frame.Programs->Bind(window, mark, "half-resolution uncertain pixels");
  if (marked)
  {
    this->SetUniforms(frame, mark, uncertain, centreCount);
    frame.FullScreen->Draw(mark, this->MarkVAO);
  }
  centreCount->Deactivate();
  this->Visibility->Deactivate();
  frame.DepthCopy()->Deactivate();
  return marked;
}

void HalfResolutionCounts::SetUniforms(
  ShadowFrame& frame, vtkShaderProgram* program, float uncertain, vtkTextureObject* centreCount)
{
  program->SetUniformi("centreCount", centreCount->GetTextureUnit());
  program->SetUniformi("depthTexture", frame.DepthCopy()->GetTextureUnit());
  program->SetUniformi("countedVisibility", this->Visibility->GetTextureUnit());
  program->SetUniformf("uncertain", uncertain);
}

std::size_t HalfResolutionCounts::GraphicsMemoryBytes() const
{
  return static_cast<std::size_t>(this->Size.x) * this->Size.y * 4 + TextureBytes(this->Visibility);
}

void HalfResolutionCounts::ReleaseGraphicsResources(vtkWindow* window)
{
  ReleaseFramebuffer(this->Framebuffer, window);
  this->DepthStencil->ReleaseGraphicsResources(window);
  this->Visibility->ReleaseGraphicsResources(window);
  this->DepthVAO.ReleaseGraphicsResources();
  this->UpsampleVAO.ReleaseGraphicsResources();
  this->MarkVAO.ReleaseGraphicsResources();
  this->Size = glm::ivec2(0);
  this->DepthProgram = this->UpsampleProgram = this->MarkProgram = nullptr;
  this->ProgramsFailed = false;
}

} // namespace penumbra
