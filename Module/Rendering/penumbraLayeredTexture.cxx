#include "penumbraLayeredTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkPenumbraLayeredTexture);

void vtkPenumbraLayeredTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Layers: " << this->Depth << " of " << this->Width << " x " << this->Height
     << (this->Target == GL_TEXTURE_2D_ARRAY ? " (2D array)" : " (not allocated as layers)")
     << "\n";
}

bool vtkPenumbraLayeredTexture::AllocateLayers(
  unsigned int width, unsigned int height, unsigned int layers, int components, int vtkType)
{
  if (!this->Context)
  {
    vtkErrorMacro("No context specified. Cannot create texture.");
    return false;
  }
  this->Target = GL_TEXTURE_2D_ARRAY;
  this->GetInternalFormat(vtkType, components, false);
  this->GetFormat(vtkType, components, false);
  this->GetDataType(vtkType);
  this->Components = components;
  this->Width = width;
  this->Height = height;
  this->Depth = layers;
  this->NumberOfDimensions = 3;

  this->Context->ActivateTexture(this);
  this->CreateTexture();
  this->Bind();
  // Errors left by others are drained first, so that a refusal is this call's.
  while (glGetError() != GL_NO_ERROR)
  {
  }
  glTexImage3D(this->Target, 0, static_cast<GLint>(this->InternalFormat),
    static_cast<GLsizei>(width), static_cast<GLsizei>(height), static_cast<GLsizei>(layers), 0,
    this->Format, this->Type, nullptr);
  const bool allocated = glGetError() == GL_NO_ERROR;
  this->Deactivate();
  if (!allocated)
  {
    this->ReleaseGraphicsResources(this->Context);
  }
  return allocated;
}

void vtkPenumbraLayeredTexture::AttachLayer(unsigned int index, int layer)
{
  glFramebufferTextureLayer(
    GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + index, this->GetHandle(), 0, layer);
}
