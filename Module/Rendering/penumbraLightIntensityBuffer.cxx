#include "penumbraLightIntensityBuffer.h"

#include "penumbraOpenGLHelpers.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtk_glew.h"

namespace penumbra
{

std::size_t LightIntensityBuffer::LayerBytes(int width, int height, int layers)
{
  return static_cast<std::size_t>(width) * height * layers * 4;
}

bool LightIntensityBuffer::Prepare(vtkOpenGLRenderWindow* window, int width, int height, int layers)
{
  const std::size_t bytes = LayerBytes(width, height, layers);
  if (this->RefusedBytes && bytes >= this->RefusedBytes)
  {
    return false;
  }
  // A new window releases every texture (SetContext), so all are allocated again.
  const bool newWindow = this->Framebuffer->GetContext() != window;
  if (newWindow)
  {
    this->Framebuffer->SetContext(window);
    this->DepthCopyFramebuffer->SetContext(window);
    this->DepthStencil->SetContext(window);
    this->DepthCopy->SetContext(window);
  }
  if (newWindow || width != this->Width || height != this->Height)
  {
    this->DepthStencil->AllocateDepthStencil(width, height);
    this->DepthCopy->AllocateDepthStencil(width, height);
  }
  if (TextureNeedsAllocation(
        this->Layers, window, width, height, layers, 1, vtkTextureObject::Nearest) &&
    !this->Layers->AllocateLayers(width, height, layers, 1, VTK_FLOAT))
  {
    this->ReleaseGraphicsResources(window);
    this->RefusedBytes = bytes;
    return false;
  }
  this->Width = width;
  this->Height = height;
  this->LayerCount = layers;
  return true;
}

void LightIntensityBuffer::BindLayer(int layer)
{
  this->Framebuffer->Bind();
  this->AttachDepth(nullptr);
  this->AttachColour(this->Layers, layer);
}

void LightIntensityBuffer::AttachColour(vtkTextureObject* texture, int layer)
{
  // VTK 9.1 ignores a new slice of the attached texture, and attaches a layer of a 2D array as
  // a 3D slice: remove, then add, a layer through the layered texture itself.
  this->Framebuffer->RemoveColorAttachment(0);
  if (auto* layered = vtkPenumbraLayeredTexture::SafeDownCast(texture))
  {
    layered->AttachLayer(0, layer);
  }
  else
  {
    this->Framebuffer->AddColorAttachment(0, texture, static_cast<unsigned int>(layer));
  }
  this->Framebuffer->ActivateDrawBuffer(0);
}

void LightIntensityBuffer::CopyDepth(vtkOpenGLState* ostate)
{
  // A blit obeys the scissor test: the whole buffer, whatever box the caller left.
  vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ScopedFramebufferBindings bindings(ostate);
  this->Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  this->DepthCopyFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
    this->DepthCopy->GetHandle(), 0);
  ostate->vtkglBlitFramebuffer(0, 0, this->Width, this->Height, 0, 0, this->Width, this->Height,
    GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

void LightIntensityBuffer::AttachDepth(vtkTextureObject* depth)
{
  if (depth)
  {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    glFramebufferTexture2D(
      GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth->GetHandle(), 0);
  }
  else
  {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
      this->DepthStencil->GetHandle(), 0);
  }
}

bool LightIntensityBuffer::AttachClearedSurfacePlanes(vtkOpenGLRenderWindow* window)
{
  if (TextureNeedsAllocation(
        this->SurfacePlanes, window, this->Width, this->Height, 1, 4, vtkTextureObject::Nearest) &&
    !this->SurfacePlanes->Allocate2D(this->Width, this->Height, 4, VTK_FLOAT))
  {
    this->SurfacePlanes->ReleaseGraphicsResources(window);
    return false;
  }
  vtkOpenGLState* ostate = window->GetState();
  this->AttachColour(this->SurfacePlanes, 0);
  vtkOpenGLState::ScopedglColorMask colorMask(ostate);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkOpenGLState::ScopedglClearColor clearColor(ostate);
  ostate->vtkglClearColor(NoSurfacePlane, 0.0f, 0.0f, 0.0f);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  return true;
}

void LightIntensityBuffer::ReleaseSurfacePlanes(vtkWindow* window)
{
  if (this->SurfacePlanes->GetHandle())
  {
    this->SurfacePlanes->ReleaseGraphicsResources(window);
  }
}

vtkTextureObject* LightIntensityBuffer::GetSurfacePlanes()
{
  return this->SurfacePlanes->GetHandle() ? this->SurfacePlanes.GetPointer() : nullptr;
}

std::size_t LightIntensityBuffer::GraphicsMemoryBytes() const
{
  if (!this->DepthStencil->GetHandle())
  {
    return 0;
  }
  const std::size_t pixels = static_cast<std::size_t>(this->Width) * this->Height;
  return pixels * (2 + this->LayerCount) * 4 + TextureBytes(this->SurfacePlanes);
}

void LightIntensityBuffer::ReleaseGraphicsResources(vtkWindow* window)
{
  ReleaseFramebuffer(this->Framebuffer, window);
  this->DepthStencil->ReleaseGraphicsResources(window);
  this->DepthCopy->ReleaseGraphicsResources(window);
  ReleaseFramebuffer(this->DepthCopyFramebuffer, window);
  this->Layers->ReleaseGraphicsResources(window);
  this->SurfacePlanes->ReleaseGraphicsResources(window);
  this->Width = this->Height = this->LayerCount = 0;
  this->RefusedBytes = 0;
}

} // namespace penumbra
