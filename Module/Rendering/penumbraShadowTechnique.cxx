#include "penumbraShadowTechnique.h"

#include "penumbraCulling.h"
#include "penumbraLightIntensityBuffer.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

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

bool ShadowLight::CountsVolumesInColour() const
{
  return this->Technique && this->Technique->CountsInColour(*this);
}

std::pair<vtkLight*, int> ShadowLight::VolumeKey(std::size_t k) const
{
  return { this->Light, this->CountsCentreInColour() ? CentreVolume : static_cast<int>(k) };
}

const std::vector<glm::dvec4>& ShadowLight::TranslucentSamples() const
{
  return this->CountsCentreInColour() ? this->CountingSamples : this->Samples;
}

PixelRect ShadowFrame::DrawTranslucentVolumes(const ShadowLight& light, std::size_t first,
  std::size_t count, vtkTextureObject* target, int components) const
{
  return this->Volumes->DrawTranslucent(*this, light, first, count, target, components);
}

vtkTextureObject* ShadowFrame::DepthCopy() const
{
  return this->Buffer->GetDepthCopy();
}

vtkTextureObject* ShadowFrame::Layers() const
{
  return this->Buffer->GetLayers();
}

void ShadowFrame::AttachColour(vtkTextureObject* texture, int layer) const
{
  this->Buffer->AttachColour(texture, layer);
}

void ShadowFrame::AttachDepth(vtkTextureObject* depth) const
{
  this->Buffer->AttachDepth(depth);
}

void ShadowFrame::AttachClearedFloatTarget(vtkTextureObject* texture, int components) const
{
  if (TextureNeedsAllocation(texture, this->Window, this->Size[0], this->Size[1], 1, components,
        vtkTextureObject::Nearest))
  {
    texture->Allocate2D(this->Size[0], this->Size[1], components, VTK_FLOAT);
  }
  vtkOpenGLState* ostate = this->Window->GetState();
  this->AttachColour(texture, 0);
  vtkOpenGLState::ScopedglColorMask colorMask(ostate);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  vtkOpenGLState::ScopedglClearColor clearColor(ostate);
  ostate->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
}

void ShadowFrame::SetDepthUniforms(vtkShaderProgram* program, vtkTextureObject* depth) const
{
  const float viewport[2] = { static_cast<float>(this->Size[0]),
    static_cast<float>(this->Size[1]) };
  program->SetUniformi("depthTexture", (depth ? depth : this->DepthCopy())->GetTextureUnit());
  program->SetUniform2f("viewportSize", viewport);
}

void ShadowFrame::SetClipToLocal(vtkShaderProgram* program, const glm::dvec3& origin) const
{
  glm::dmat4 clipToLocal = glm::translate(glm::dmat4(1.0), -origin) * this->ClipToWorld;
  clipToLocal[3] += clipToLocal[2];
  const glm::mat4 uniform(clipToLocal);
  program->SetUniformMatrix4x4("clipToLocal", const_cast<float*>(glm::value_ptr(uniform)));
}

void ShadowFrame::SetClipToLight(vtkShaderProgram* program, const glm::dvec4& light) const
{
  const bool positional = light.w != 0.0;
  this->SetClipToLocal(program, positional ? glm::dvec3(light) : glm::dvec3(0.0));
  const glm::vec4 lightWedge(positional ? glm::dvec4(0.0, 0.0, 0.0, 1.0) : light);
  program->SetUniform4f("lightWedge", glm::value_ptr(lightWedge));
}

void ShadowFrame::SetSurfaceSideUniforms(vtkShaderProgram* program) const
{
  program->SetUniformi("surfacePlanesDrawn", this->SurfacePlanes ? 1 : 0);
  // Without planes the sampler, unread, still needs a unit of its own type: the depth copy's.
  program->SetUniformi("surfacePlanes",
    (this->SurfacePlanes ? this->SurfacePlanes : this->DepthCopy())->GetTextureUnit());
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

void ShadowFrame::LightBackground()
{
  vtkOpenGLState* ostate = this->Window->GetState();
  ScopedDrawState saved(ostate);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDepthFunc(GL_LEQUAL);
  this->DrawResolve(1.0f);
}

void ShadowFrame::DrawWedgeBuffer(vtkShaderProgram* program, const CasterCache& caster,
  WedgeBuffer& buffer, const std::vector<VertexAttribute>& attributes, const ShadowLight& light)
{
  if (buffer.IndexCount() == 0)
  {
    return;
  }
  vtkOpenGLState* ostate = this->Window->GetState();
  // The light the wedges were built around: its own, or counting's about CountingReference.
  const glm::dvec4& wedgeLight = light.Samples.front();
  const bool frontFaces = WedgesDrawnByFrontFaces(caster.WorldMin, caster.WorldMax, wedgeLight,
    light.SoftRadius, this->NearCorners, buffer.Fallbacks != 0);
  ostate->vtkglCullFace(frontFaces ? GL_BACK : GL_FRONT);
  ostate->vtkglDepthFunc(frontFaces ? GL_LEQUAL : GL_GEQUAL);
  const glm::mat4 toClip(this->WorldToClip * glm::translate(glm::dmat4(1.0), buffer.Origin));
  const glm::vec4 lightWedge(buffer.LightInWedgeSpace());
  program->SetUniformMatrix4x4("MCDCMatrix", const_cast<float*>(glm::value_ptr(toClip)));
  this->SetClipToLocal(program, buffer.Origin);
  program->SetUniform4f("lightWedge", glm::value_ptr(lightWedge));
  buffer.Bind(program, attributes);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(buffer.IndexCount()), GL_UNSIGNED_INT, nullptr);
  buffer.IndexBuffer->Release();
  buffer.VAO->Release();
  this->Counts.Wedges += static_cast<vtkIdType>(buffer.Wedges + buffer.Fallbacks);
  this->Counts.FullViewportWedges += static_cast<vtkIdType>(buffer.FullViewport);
}

} // namespace penumbra
