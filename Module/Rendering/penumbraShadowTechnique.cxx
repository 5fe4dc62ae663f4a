#include "penumbraShadowTechnique.h"

#include "penumbraCulling.h"
#include "penumbraLightIntensityBuffer.h"

#include "vtkObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "penumbraDepthPointDec.h"
#include "penumbraResolveFS.h"
#include "penumbraResolveVS.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace penumbra
{

bool ShadowLight::CountsCentreInColour() const
{
  return this->Technique && this->Technique->CountsCentreInColour();
}

std::pair<vtkLight*, int> ShadowLight::VolumeKey(std::size_t k) const
{
  return { this->Light, this->CountsCentreInColour() ? CentreVolume : static_cast<int>(k) };
}

const std::vector<glm::dvec4>& ShadowLight::TranslucentSamples() const
{
  return this->CountsCentreInColour() ? this->CountingSamples : this->Samples;
}

std::size_t TextureBytes(vtkTextureObject* texture)
{
  if (!texture->GetHandle())
  {
    return 0;
  }
  return static_cast<std::size_t>(texture->GetWidth()) * texture->GetHeight() *
    std::max(1u, texture->GetDepth()) * static_cast<std::size_t>(texture->GetComponents()) * 4;
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
  // The pass's fragment shaders share one reconstruction of a pixel's point from depth.
  std::string fragment = fragmentShader;
  vtkShaderProgram::Substitute(fragment, "//PENUMBRA::DepthPoint::Dec", penumbraDepthPointDec);
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vertexShader, fragment.c_str(), "");
  if (!program && this->Failed.insert(name).second)
  {
    vtkErrorWithObjectMacro(
      this->Owner, "Could not compile the " << name << " shader: " << instead << ".");
  }
  return program;
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

void ShadowFrame::AttachColour(vtkTextureObject* texture, int layer) const
{
  this->Buffer->AttachColour(texture, layer);
}

void ShadowFrame::AttachClearedFloatTarget(vtkTextureObject* texture, int components) const
{
  if (texture->GetContext() != this->Window)
  {
    texture->SetContext(this->Window);
  }
  if (static_cast<int>(texture->GetWidth()) != this->Size[0] ||
    static_cast<int>(texture->GetHeight()) != this->Size[1] ||
    texture->GetComponents() != components)
  {
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->Allocate2D(this->Size[0], this->Size[1], components, VTK_FLOAT);
  }
  vtkOpenGLState* ostate = this->Window->GetState();
  this->AttachColour(texture, 0);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkOpenGLState::ScopedglClearColor clearColor(ostate);
  ostate->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
}

void ShadowFrame::SetDepthUniforms(vtkShaderProgram* program) const
{
  const float viewport[2] = { static_cast<float>(this->Size[0]),
    static_cast<float>(this->Size[1]) };
  program->SetUniformi("depthTexture", this->DepthCopy->GetTextureUnit());
  program->SetUniform2f("viewportSize", viewport);
}

void ShadowFrame::DrawResolve(float lightIntensity)
{
  vtkShaderProgram* program = this->Programs->Ready(this->Window, penumbraResolveVS,
    penumbraResolveFS, "LI resolve", "shadows are not written into the LI buffer");
  if (!program)
  {
    return;
  }
  program->SetUniformf("lightIntensity", lightIntensity);
  this->FullScreen->Draw(program, *this->ResolveVAO);
}

void ShadowFrame::DrawWedgeBuffer(vtkShaderProgram* program, const CasterCache& caster,
  WedgeBuffer& buffer, const std::vector<VertexAttribute>& attributes, const ShadowLight& light)
{
  if (buffer.IndexCount() == 0)
  {
    return;
  }
  vtkOpenGLState* ostate = this->Window->GetState();
  // A point inside a wedge lies behind its front faces and in front of its back faces. When
  // neither the eye nor the near plane can be inside this caster's wedges (its bounds grown by
  // the light's radius miss the near plane's hull with the light, as for z-pass), front faces
  // tested against the scene depth skip every point in front of the wedge. Otherwise back
  // faces, which every ray meeting the wedge crosses once, skip points behind it.
  const glm::dvec3 grow(light.World.w != 0.0 ? light.SoftRadius : 0.0);
  const bool frontFaces = light.World.w != 0.0 && buffer.Fallbacks == 0 &&
    !VolumeMayReachNearPlane(
      caster.WorldMin - grow, caster.WorldMax + grow, light.World, this->NearCorners);
  ostate->vtkglCullFace(frontFaces ? GL_BACK : GL_FRONT);
  ostate->vtkglDepthFunc(frontFaces ? GL_LEQUAL : GL_GEQUAL);
  const glm::mat4 toClip(this->WorldToClip * glm::translate(glm::dmat4(1.0), buffer.Origin));
  const glm::mat4 fromClip(glm::translate(glm::dmat4(1.0), -buffer.Origin) * this->ClipToWorld);
  const glm::vec4 lightWedge(buffer.LightInWedgeSpace());
  program->SetUniformMatrix4x4("MCDCMatrix", const_cast<float*>(glm::value_ptr(toClip)));
  program->SetUniformMatrix4x4("clipToLocal", const_cast<float*>(glm::value_ptr(fromClip)));
  program->SetUniform4f("lightWedge", glm::value_ptr(lightWedge));
  buffer.Bind(program, attributes);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(buffer.IndexCount()), GL_UNSIGNED_INT, nullptr);
  buffer.IndexBuffer->Release();
  buffer.VAO->Release();
  this->Counts.Wedges += static_cast<vtkIdType>(buffer.Wedges + buffer.Fallbacks);
  this->Counts.FullViewportWedges += static_cast<vtkIdType>(buffer.FullViewport);
}

} // namespace penumbra
