#include "penumbraOpenGLHelpers.h"

#include "vtkObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "penumbraDepthPointDec.h"
#include "penumbraSurfacePlaneDec.h"
#include "penumbraSurfaceSideDec.h"

#include <algorithm>

namespace penumbra
{

std::size_t TextureBytes(vtkTextureObject* texture)
{
  if (!texture->GetHandle())
  {
    return 0;
  }
  return static_cast<std::size_t>(texture->GetWidth()) * texture->GetHeight() *
    std::max(1u, texture->GetDepth()) * static_cast<std::size_t>(texture->GetComponents()) * 4;
}

void ReleaseFramebuffer(vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, vtkWindow* window)
{
  framebuffer->ReleaseGraphicsResources(window);
  framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
}

bool TextureNeedsAllocation(vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width,
  int height, int depth, int components, int filter)
{
  if (texture->GetContext() != window)
  {
    texture->SetContext(window);
  }
  if (texture->GetHandle() && static_cast<int>(texture->GetWidth()) == width &&
    static_cast<int>(texture->GetHeight()) == height &&
    static_cast<int>(std::max(1u, texture->GetDepth())) == depth &&
    texture->GetComponents() == components)
  {
    return false;
  }
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(filter);
  return true;
}

void SetScissor(vtkOpenGLState* state, const PixelRect& rect)
{
  state->vtkglScissor(rect.X0, rect.Y0, rect.X1 - rect.X0, rect.Y1 - rect.Y0);
}

ScopedDrawState::ScopedDrawState(vtkOpenGLState* state)
  : State(state)
  , Blend(state, GL_BLEND)
  , StencilTest(state, GL_STENCIL_TEST)
  , DepthTest(state, GL_DEPTH_TEST)
  , CullFace(state, GL_CULL_FACE)
  , DepthClamp(state, GL_DEPTH_CLAMP)
  , ScissorTest(state, GL_SCISSOR_TEST)
  , ScissorBox(state)
  , BlendFunc(state)
  , ColorMask(state)
  , DepthMask(state)
  , DepthFunc(state)
  , ClearColor(state)
  , Viewport(state)
{
  static const GLenum names[2][7] = {
    { GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL,
      GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK },
    { GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF, GL_STENCIL_BACK_VALUE_MASK, GL_STENCIL_BACK_FAIL,
      GL_STENCIL_BACK_PASS_DEPTH_FAIL, GL_STENCIL_BACK_PASS_DEPTH_PASS, GL_STENCIL_BACK_WRITEMASK }
  };
  for (int face = 0; face < 2; ++face)
  {
    for (int k = 0; k < 7; ++k)
    {
      glGetIntegerv(names[face][k], &this->Stencil[face][k]);
    }
  }
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &this->CullFaceMode);
  glGetIntegerv(GL_BLEND_EQUATION_RGB, &this->BlendEquationRGB);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &this->BlendEquationAlpha);
  glGetDoublev(GL_DEPTH_CLEAR_VALUE, &this->ClearDepth);
}

ScopedDrawState::~ScopedDrawState()
{
  vtkOpenGLState* state = this->State;
  const GLenum faces[2] = { GL_FRONT, GL_BACK };
  for (int face = 0; face < 2; ++face)
  {
    const int* s = this->Stencil[face];
    state->vtkglStencilFuncSeparate(faces[face], s[0], s[1], static_cast<unsigned int>(s[2]));
    state->vtkglStencilOpSeparate(faces[face], s[3], s[4], s[5]);
    state->vtkglStencilMaskSeparate(faces[face], static_cast<unsigned int>(s[6]));
  }
  state->vtkglCullFace(this->CullFaceMode);
  state->vtkglBlendEquationSeparate(this->BlendEquationRGB, this->BlendEquationAlpha);
  state->vtkglClearDepth(this->ClearDepth);
}

vtkShaderProgram* ShaderPrograms::Ready(vtkOpenGLRenderWindow* window, const char* vertexShader,
  const char* fragmentShader, const char* name, const char* instead)
{
  // The pass's fragment shaders share one reconstruction of a pixel's point and plane from depth.
  std::string fragment = fragmentShader;
  vtkShaderProgram::Substitute(fragment, "//PENUMBRA::DepthPoint::Dec", penumbraDepthPointDec);
  vtkShaderProgram::Substitute(fragment, "//PENUMBRA::SurfaceSide::Dec", penumbraSurfaceSideDec);
  // (After SurfaceSide, which holds it.)
  vtkShaderProgram::Substitute(fragment, "//PENUMBRA::SurfacePlane::Dec", penumbraSurfacePlaneDec);
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vertexShader, fragment.c_str(), "");
  if (!program && this->Failed.insert(name).second)
  {
    vtkErrorWithObjectMacro(
      this->Owner, "Could not compile the " << name << " shader: " << instead << ".");
  }
  return program;
}

bool ShaderPrograms::Bind(
  vtkOpenGLRenderWindow* window, vtkShaderProgram* program, const char* name)
{
  if (window->GetShaderCache()->ReadyShaderProgram(program))
  {
    return true;
  }
  if (this->Failed.insert(name).second)
  {
    vtkErrorWithObjectMacro(this->Owner, "Could not bind the " << name << " shader again.");
  }
  return false;
}

void FullScreenTriangle::VAO::ReleaseGraphicsResources()
{
  this->Array->ReleaseGraphicsResources();
  this->Program = nullptr;
}

void FullScreenTriangle::Draw(vtkShaderProgram* program, VAO& vao)
{
  if (this->Buffer->GetHandle() == 0)
  {
    const std::vector<float> triangle = { -1.f, -1.f, 3.f, -1.f, -1.f, 3.f };
    this->Buffer->Upload(triangle, vtkOpenGLBufferObject::ArrayBuffer);
    ++this->Generation;
  }
  if (vao.Generation != this->Generation)
  {
    vao.Program = nullptr; // bound to the buffer before this one
    vao.Generation = this->Generation;
  }
  BindVertexArray(vao.Array, program, vao.Program, this->Buffer, { { "ndCoordIn", 0, 2 } });
  glDrawArrays(GL_TRIANGLES, 0, 3);
  vao.Array->Release();
}

void FullScreenTriangle::ReleaseGraphicsResources()
{
  this->Buffer->ReleaseGraphicsResources();
}

void BindVertexArray(vtkOpenGLVertexArrayObject* vao, vtkShaderProgram* program,
  vtkShaderProgram*& boundProgram, vtkOpenGLBufferObject* buffer,
  const std::vector<VertexAttribute>& attributes)
{
  if (boundProgram != program)
  {
    // Releases the old VAO: must come before Bind.
    vao->ShaderProgramChanged();
    vao->Bind();
    const VertexAttribute& last = attributes.back();
    const std::size_t stride = (last.Offset + last.Components) * sizeof(float);
    for (const VertexAttribute& attribute : attributes)
    {
      vao->AddAttributeArray(program, buffer, attribute.Name, attribute.Offset * sizeof(float),
        stride, VTK_FLOAT, attribute.Components, false);
    }
    boundProgram = program;
  }
  vao->Bind();
}

bool WriteBuffer(vtkOpenGLBufferObject* buffer, vtkOpenGLBufferObject::ObjectType type,
  std::size_t bytes, const std::function<void(void*)>& write)
{
  const GLenum target = type == vtkOpenGLBufferObject::ArrayBuffer ? GL_ARRAY_BUFFER
    : type == vtkOpenGLBufferObject::ElementArrayBuffer            ? GL_ELEMENT_ARRAY_BUFFER
                                                                   : GL_TEXTURE_BUFFER;
  // VTK's Upload refuses to allocate without data: the same calls, with none.
  if (!buffer->GenerateBuffer(type) || !buffer->Bind())
  {
    return false;
  }
  glBufferData(target, static_cast<GLsizeiptr>(bytes), nullptr, GL_STATIC_DRAW);
  if (bytes == 0)
  {
    return true;
  }
  if (void* destination = glMapBufferRange(
        target, 0, static_cast<GLsizeiptr>(bytes), GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT))
  {
    write(destination);
    if (glUnmapBuffer(target) == GL_TRUE)
    {
      return true;
    }
  }
  std::vector<unsigned char> copy(bytes);
  write(copy.data());
  return buffer->Upload(copy, type);
}

} // namespace penumbra
