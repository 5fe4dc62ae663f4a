#include "penumbraShadowVolumeRenderer.h"

#include "penumbraCasterDepth.h"
#include "penumbraShadowTechnique.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include "penumbraShadowVolumeFS.h"
#include "penumbraShadowVolumeVS.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace penumbra
{
namespace
{

/// NDC depth by which light caps are pushed back: well above float rounding of the two
/// vertex transforms (VTK's mapper and ours), which differ by about 1e-6 relative.
constexpr float CapDepthBias = 5e-5f;
/// The same for a caster seen through (not in the depth pass), whose cap may lie on an opaque
/// surface (a translucent label's boundary on an opaque one's): pushed back by a few times the
/// rounding, a visible point on the cap's plane is not behind it, as the ray-traced truth
/// starts its rays off the surface; a generous push would also hide a cap just in front.
constexpr float SeenThroughCapDepthBias = 1e-5f;

/// The pixels where the caster's volume from `sample` can count (penumbra::ShadowScissor).
PixelRect VolumeScissor(
  const ShadowFrame& frame, const CasterCache& caster, const glm::dvec4& sample)
{
  return ShadowScissor(caster.WorldMin, caster.WorldMax, sample, frame.SceneBox, frame.WorldToClip,
    frame.Size[0], frame.Size[1]);
}

/**
 * Draws a volume's sides or dark cap, which start at index `offset` of the bound index buffer
 * and hold `count` indices. The stencil adds 1 a crossing, so it draws every copy; counting in
 * colour draws each run of first copies once, its crossings weighted by their multiplicity.
 * Returns the triangles drawn.
 */
std::size_t DrawCounted(vtkShaderProgram* program, float frontFaceValue, bool countInColour,
  const std::vector<TriangleRun>& runs, std::size_t offset, std::size_t count)
{
  if (!countInColour)
  {
    program->SetUniformf("frontFaceValue", frontFaceValue);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
      reinterpret_cast<const void*>(offset * sizeof(std::uint32_t)));
    return count / 3;
  }
  std::size_t drawn = 0;
  for (const TriangleRun& run : runs)
  {
    program->SetUniformf("frontFaceValue", frontFaceValue * static_cast<float>(run.Multiplicity));
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(run.Count), GL_UNSIGNED_INT,
      reinterpret_cast<const void*>((offset + run.First) * sizeof(std::uint32_t)));
    drawn += run.Count;
  }
  return drawn / 3;
}

} // namespace

vtkIdType ShadowVolumeRenderer::UpdateOpaque(const ShadowLight& light, CasterCache& caster)
{
  const glm::dmat4 worldToObject = glm::inverse(caster.ObjectToWorld);
  const bool mirrored = glm::determinant(caster.ObjectToWorld) < 0.0;
  vtkIdType updates = 0;
  for (std::size_t k = 0; k < light.Samples.size(); ++k)
  {
    VolumeCache& volume = caster.Volumes[light.VolumeKey(k)];
    updates += volume.Update(*caster.Mesh, worldToObject * light.Samples[k], mirrored,
                 CountingRule::FrontFacesWhereTheySuffice)
      ? 1
      : 0;
  }
  return updates;
}

vtkIdType ShadowVolumeRenderer::UpdateTranslucent(const ShadowLight& light, CasterCache& caster)
{
  const glm::dmat4 worldToObject = glm::inverse(caster.ObjectToWorld);
  const bool mirrored = glm::determinant(caster.ObjectToWorld) < 0.0;
  const std::vector<glm::dvec4>& samples = light.TranslucentSamples();
  vtkIdType updates = 0;
  for (std::size_t k = 0; k < samples.size(); ++k)
  {
    VolumeCache& volume = caster.Volumes[light.TranslucentVolumeKey(k)];
    updates +=
      volume.Update(*caster.Mesh, worldToObject * samples[k], mirrored, CountingRule::EveryTriangle)
      ? 1
      : 0;
  }
  return updates;
}

bool ShadowVolumeRenderer::Begin(const ShadowFrame& frame)
{
  this->Triangles = 0;
  this->ZFailVolumes = 0;
  this->Program = frame.Programs->Ready(frame.Window, penumbraShadowVolumeVS,
    penumbraShadowVolumeFS, "shadow-volume", "no shadow is drawn");
  return this->Program != nullptr;
}

void ShadowVolumeRenderer::DrawOpaqueSample(
  const ShadowFrame& frame, const ShadowLight& light, std::size_t k)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  ScopedDrawState saved(ostate);
  const bool countInColour = light.CountsVolumesInColour();
  ostate->vtkglStencilMask(0xFF);
  ostate->vtkglClear(GL_STENCIL_BUFFER_BIT);
  ostate->vtkglDisable(GL_DEPTH_CLAMP); // z-fail turns it on for itself
  if (countInColour)
  {
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglDisable(GL_STENCIL_TEST);
  }
  else
  {
    ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglEnable(GL_STENCIL_TEST);
    ostate->vtkglStencilFunc(GL_ALWAYS, 0, 0xFF);
  }
  if (!frame.Programs->Bind(frame.Window, this->Program, "shadow-volume"))
  {
    return;
  }
  // Translucent casters' volumes are drawn when the technique asks for them.
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  for (CasterCache* caster : *frame.Casters)
  {
    if (caster->Culled.count(light.Light) || caster->Translucent())
    {
      continue;
    }
    const PixelRect rect = VolumeScissor(frame, *caster, light.Samples[k]);
    if (!rect.Empty())
    {
      SetScissor(ostate, rect);
      this->DrawVolume(frame, *caster, light.VolumeKey(k), light.Samples[k], countInColour, 1.0f,
        light.Technique ? light.Technique->VolumeDepthBias() : 0.0f);
    }
  }
}

PixelRect ShadowVolumeRenderer::DrawTranslucent(const ShadowFrame& frame, const ShadowLight& light,
  std::size_t first, std::size_t count, vtkTextureObject* target, int components)
{
  struct Volume
  {
    CasterCache* Caster;
    std::size_t Sample;
    PixelRect Rect;
  };
  std::vector<Volume> volumes;
  PixelRect covered;
  for (std::size_t k = first; k < first + count; ++k)
  {
    for (CasterCache* caster : *frame.Casters)
    {
      if (caster->Translucent() && !caster->Culled.count(light.Light))
      {
        const PixelRect rect = VolumeScissor(frame, *caster, light.TranslucentSamples()[k]);
        if (!rect.Empty())
        {
          volumes.push_back({ caster, k, rect });
          covered = covered.United(rect);
        }
      }
    }
  }
  if (volumes.empty())
  {
    return covered;
  }
  vtkOpenGLState* ostate = frame.Window->GetState();
  ScopedDrawState saved(ostate);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  SetScissor(ostate, covered);
  frame.AttachClearedFloatTarget(target, components);
  ostate->vtkglDisable(GL_DEPTH_CLAMP); // as for the opaque volumes: z-fail turns it on itself
  // Each crossing adds log(1 - opacity) to its sample's channel; the stencil keeps what the
  // opaque casters' volumes or the counting made of it.
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFunc(GL_ONE, GL_ONE);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDisable(GL_CULL_FACE);
  if (frame.Programs->Bind(frame.Window, this->Program, "shadow-volume"))
  {
    for (const Volume& volume : volumes)
    {
      const int channel = static_cast<int>(volume.Sample - first);
      ostate->vtkglColorMask(channel == 0, channel == 1, channel == 2, channel == 3);
      SetScissor(ostate, volume.Rect);
      this->DrawVolume(frame, *volume.Caster, light.TranslucentVolumeKey(volume.Sample),
        light.TranslucentSamples()[volume.Sample], true,
        static_cast<float>(-std::log1p(-volume.Caster->Opacity)));
    }
  }
  frame.AttachColour(frame.Layers(), light.Layer);
  return covered;
}

void ShadowVolumeRenderer::DrawVolume(const ShadowFrame& frame, CasterCache& caster,
  const std::pair<vtkLight*, int>& key, const glm::dvec4& sample, bool countInColour, float weight,
  float sideDepthBias)
{
  VolumeCache& volume = caster.Volumes[key];
  if (volume.Volume.CastingTriangles == 0)
  {
    return;
  }
  vtkOpenGLState* ostate = frame.Window->GetState();
  vtkShaderProgram* program = this->Program;
  // Culling only the faces hidden behind the caster's own (back faces of a closed mesh seen from
  // outside) shows nothing through them.
  const bool seenThroughCulledFaces =
    caster.CulledFaces != 0 && caster.CulledFaces != HiddenFace(frame, caster);
  const VolumeDrawPlan plan = PlanVolumeDraw(caster.WorldMin, caster.WorldMax, sample,
    frame.NearCorners, caster.SeenThrough, seenThroughCulledFaces);
  if (plan.LightCap) // z-fail draws it too, beside the cap at infinity
  {
    volume.EnsureCaps(*caster.Mesh);
  }
  const std::size_t sides = volume.SideCount(), darkCap = volume.DarkCapCount(),
                    lightCap = volume.CapCount();
  const auto* lightCapStart =
    reinterpret_cast<const void*>((sides + darkCap) * sizeof(std::uint32_t));
  const glm::mat4 objectToClip(frame.WorldToClip * caster.ObjectToWorld);
  const glm::vec4 lightObject(volume.Light);
  program->SetUniformMatrix4x4("MCDCMatrix", const_cast<float*>(glm::value_ptr(objectToClip)));
  program->SetUniform4f("lightMC", glm::value_ptr(lightObject));
  caster.Mesh->Bind(program);
  volume.Upload();
  volume.Indices->Bind();

  if (!plan.ZFail)
  {
    // z-pass: count volume faces in front of the visible surface; caps are not needed but for
    // a translucent caster's light cap, and the volume may stop beyond the scene.
    const glm::vec4 endPlane(glm::transpose(caster.ObjectToWorld) *
      VolumeEndPlane(caster.WorldMin, caster.WorldMax, sample, frame.SceneBox, frame.NearCorners));
    program->SetUniform4f("endPlaneMC", glm::value_ptr(endPlane));
    program->SetUniformf("sweepLength", 0.0f);
    ostate->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    ostate->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    ostate->vtkglDepthFunc(GL_LESS);
    // Entering a volume takes the light away.
    program->SetUniformf("depthBias", sideDepthBias);
    this->Triangles += static_cast<vtkIdType>(
      DrawCounted(program, -weight, countInColour, volume.Volume.SideRuns, 0, sides));
    program->SetUniformf("depthBias", 0.0f);
    if (plan.LightCap)
    {
      program->SetUniformf("frontFaceValue", -weight);
      program->SetUniformf("depthBias", SeenThroughCapDepthBias);
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(lightCap), GL_UNSIGNED_INT, lightCapStart);
      program->SetUniformf("depthBias", 0.0f);
      this->Triangles += static_cast<vtkIdType>(lightCap / 3);
    }
  }
  else
  {
    // z-fail: count faces behind it, caps included; depth clamping keeps the far end at
    // infinity from being clipped. Counting in colour, "behind" is a depth test that passes.
    ostate->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    ostate->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    ostate->vtkglDepthFunc(countInColour ? GL_GEQUAL : GL_LESS);
    const glm::vec4 toInfinity(0.0f);
    program->SetUniform4f("endPlaneMC", glm::value_ptr(toInfinity));
    // A parallel projection draws the far end at infinity nowhere (w = 0 at every swept point),
    // though it lies behind every pixel or none: the volume then ends far beyond the scene.
    const double sweep = ProjectsInfinityToInfinity(frame.WorldToClip)
      ? ParallelSweepLength(caster.ObjectToWorld, caster.WorldMin, caster.WorldMax, sample,
          frame.SceneBox, frame.NearCorners)
      : 0.0;
    program->SetUniformf("sweepLength", static_cast<float>(sweep));
    vtkOpenGLState::ScopedglEnableDisable depthClamp(ostate, GL_DEPTH_CLAMP);
    ostate->vtkglEnable(GL_DEPTH_CLAMP);
    // Leaving a volume behind the point takes the light away.
    program->SetUniformf("depthBias", sideDepthBias);
    this->Triangles += static_cast<vtkIdType>(
      DrawCounted(program, weight, countInColour, volume.Volume.SideRuns, 0, sides) +
      DrawCounted(program, weight, countInColour, volume.Volume.DarkCapRuns, sides, darkCap));
    program->SetUniformf("frontFaceValue", weight);
    // The light cap lies on the caster's own surface: pushed away from the eye, a visible point
    // on it counts as outside its own triangle's volume, i.e. lit from the side it is seen from.
    // The cap only covers pixels where its opaque caster is the nearest surface, so a generous
    // push cannot move it behind any other visible point.
    // A caster seen through is not in the depth pass: a generous push could move its cap behind
    // an opaque point just behind it, so it is pushed by SeenThroughCapDepthBias only.
    program->SetUniformf("depthBias", caster.SeenThrough ? SeenThroughCapDepthBias : CapDepthBias);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(lightCap), GL_UNSIGNED_INT, lightCapStart);
    program->SetUniformf("depthBias", 0.0f);
    this->Triangles += static_cast<vtkIdType>(lightCap / 3);
    ++this->ZFailVolumes;
  }
  volume.Indices->Release();
  caster.Mesh->VAO->Release();
}

} // namespace penumbra
