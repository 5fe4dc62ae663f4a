#include "penumbraCountingTechnique.h"

#include "penumbraLightSamples.h"
#include "penumbraSampleCounting.h"
#include "penumbraShadowVolume.h"

#include "vtkObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <glm/gtc/type_ptr.hpp>

#include "penumbraCountingDepthFS.h"
#include "penumbraCountingResolveFS.h"
#include "penumbraCountingTransmissionFS.h"
#include "penumbraCountingWedgeFS.h"
#include "penumbraCountingWedgeVS.h"
#include "penumbraResolveVS.h"

#include <algorithm>

namespace penumbra
{

namespace
{
/// Window depth by which counting takes a pixel's point in front of its surface, so that the
/// sides of the surface's own volume start behind it: four steps of a 24-bit depth buffer.
/// Much more moves it measurably off the surface where the depth range is wide (a near plane at
/// 1/1000 of the far one makes 5e-5 a tenth of the scene's unit).
constexpr float CountingDepthBias = 4.0f / 16777216.0f;
/// Where the surface's plane is known, the point lies off the plane along its normal by at least
/// this share of its view ray's ends' distances from the planes' origin: the float rounding of
/// the ray, the plane and the wedges' point. (1, 16 or 64 steps instead of 4 left more of a
/// sweep of random scenes off averaging, Documentation/wedges.md.)
constexpr float CountingPlaneBias = 4.0f / 16777216.0f;
/// The share of the point's and the eye's distances from the caster's origin by which the wedges
/// move the point further towards the eye: where the tight depth range makes depth steps finer than
/// the float rounding of the coordinates the depth was drawn from, the depth is off by that
/// rounding (a cylinder's cap drawn 2e-7 off its plane in a user trial, half a depth step then).
/// Two float steps: four moved grazing terminators of the benchmark's large torus a sample
/// brighter, one left edges seen at grazing angles off in a sweep of scenes (wedges.md).
constexpr float CountingEyeFloatBias = 2.0f / 16777216.0f;

/// The largest difference of counted neighbours' visibilities that half-resolution counting
/// takes as smooth (penumbraHalfUpsampleFS.glsl's `uncertain`): two samples' shares, or fewer
/// where two would be more than a quarter (with few samples, a hard shadow's whole step), and
/// half a share more so that float rounding cannot move a step across it.
float SmoothLimit(std::size_t samples)
{
  const std::size_t steps = std::min<std::size_t>(2, samples / 4);
  return (static_cast<float>(steps) + 0.5f) / static_cast<float>(samples);
}

/// A shader source with its sample count compiled in (the loops' bounds and the samples' array)
/// and `define` defined when given.
std::string CountingShader(const char* source, std::size_t samples, const char* define = nullptr)
{
  // Compiled for a power-of-two capacity, the sample count a constant where it fills it and a
  // uniform otherwise: every program stays in the window's shader cache until the window goes,
  // so one program per distinct LightSamples would keep megabytes of compiled code each (0.8 GB
  // for 1 to 256 on llvmpipe). The constant keeps the loops unrolled (the wedges took 6% longer
  // with a uniform count of 16).
  std::size_t capacity = 4;
  while (capacity < samples)
  {
    capacity *= 2;
  }
  std::string text = source;
  std::string defines = "#define PENUMBRA_SAMPLE_CAPACITY " + std::to_string(capacity) + "\n";
  if (samples == capacity)
  {
    defines += "#define PENUMBRA_SAMPLES_FILL_CAPACITY\n";
  }
  if (define)
  {
    defines += std::string("#define ") + define + "\n";
  }
  vtkShaderProgram::Substitute(text, "//PENUMBRA::SampleCount", defines, false);
  return text;
}

/// Sets the sample count of a CountingShader program that does not hold it as a constant.
void SetSampleCount(vtkShaderProgram* program, std::size_t samples)
{
  if (program->IsUniformUsed("sampleCount"))
  {
    program->SetUniformi("sampleCount", static_cast<int>(samples));
  }
}

/// The image unit of the resolve's deepest-count report (the wedges bind the counters to 0).
constexpr int DeepCountsImageUnit = 1;

/// The counters' 32-bit words for each pixel: four 8-bit counts to a word.
std::size_t CounterWords(std::size_t samples)
{
  return (samples + 3) / 4;
}

/// Whether the caster's shadow is counted for the light: translucent casters are drawn one
/// sample at a time instead.
bool Counted(const CasterCache& caster, const ShadowLight& light)
{
  return !caster.Translucent() && !caster.Culled.count(light.Light);
}

/// Sets the counting wedges' light samples: offsets from the light's centre, which each
/// caster's wedge coordinates place (lightWedge), or directions, which no origin moves. Their
/// spread about the centre lets a fragment skip an edge whose plane through it misses them all
/// (penumbra::EdgePlaneMissesSamples).
void SetLightSamples(vtkShaderProgram* program, const ShadowLight& light)
{
  const glm::dvec4& reference = light.Samples.front(); // CountingReference
  const glm::dvec3 centre = reference.w != 0.0 ? glm::dvec3(0.0) : glm::dvec3(reference);
  std::vector<float> samples;
  samples.reserve(4 * light.CountingSamples.size());
  double spread = 0.0;
  for (const glm::dvec4& sample : light.CountingSamples)
  {
    const glm::dvec3 position = glm::dvec3(sample) - sample.w * glm::dvec3(reference);
    samples.insert(samples.end(),
      { static_cast<float>(position.x), static_cast<float>(position.y),
        static_cast<float>(position.z), static_cast<float>(sample.w) });
    spread = std::max(spread, glm::length(position - centre));
  }
  program->SetUniform4fv(
    "lightSamples", static_cast<int>(light.CountingSamples.size()), samples.data());
  program->SetUniformf("sampleSpread", static_cast<float>(spread));
}

/// The depth copy and surface planes, active for the full-screen passes while it lives.
class ActiveTextures
{
public:
  explicit ActiveTextures(const ShadowFrame& frame)
    : Depth(frame.DepthCopy())
    , Planes(frame.SurfacePlanes)
  {
    this->Depth->Activate();
    if (this->Planes)
    {
      this->Planes->Activate();
    }
  }
  ~ActiveTextures()
  {
    if (this->Planes)
    {
      this->Planes->Deactivate();
    }
    this->Depth->Deactivate();
  }
  ActiveTextures(const ActiveTextures&) = delete;
  ActiveTextures& operator=(const ActiveTextures&) = delete;

private:
  vtkTextureObject* Depth;
  vtkTextureObject* Planes;
};

/// Sets what a full-screen pass reads of the scene depth and surface planes while ActiveTextures
/// lives: the textures' units (ShadowFrame::SetSurfaceSideUniforms) and, with `light`, what
/// //PENUMBRA::SurfaceSide::Dec reads besides: the depth point about counting's reference and the
/// light's samples, which a program keeps.
void SetSurfaceSide(
  const ShadowFrame& frame, vtkShaderProgram* program, const ShadowLight* light = nullptr)
{
  frame.SetDepthUniforms(program);
  frame.SetSurfaceSideUniforms(program);
  if (light)
  {
    // About counting's reference: the frame in which SetLightSamples gives the samples.
    frame.SetClipToLight(program, light->Samples.front());
    SetLightSamples(program, *light);
  }
}

/// Draws the wedges of every caster counted for the light, with the wedge program bound.
void DrawCountedWedges(ShadowFrame& frame, vtkShaderProgram* program, const ShadowLight& light)
{
  for (CasterCache* caster : *frame.Casters)
  {
    if (!Counted(*caster, light))
    {
      continue;
    }
    CountingWedgeCache& cache = caster->CountingWedges[light.Light];
    program->SetUniformi("frontFacesOnly", cache.FrontFacesOnly ? 1 : 0);
    frame.DrawWedgeBuffer(program, *caster, cache, CountingWedgeCache::Attributes(), light);
  }
}
} // namespace

float CountingTechnique::VolumeDepthBias() const
{
  // A side that starts on the surface near the point (a silhouette of the centre through the
  // point's neighbourhood) is rasterized from vertices snapped to the pixel grid, and its depth
  // there can be off by more than the point's four steps: it counted at random (whole pixels
  // dark on terminators). Pushed back by as much again at the caster, where it starts; far
  // from it the push fades, and the counting depth's own margin is what separates them.
  return 2.0f * CountingDepthBias; // NDC: twice the window depth
}

bool CountingTechnique::Supported(vtkObject* owner)
{
  if (this->Support < 0)
  {
    this->Support =
      GLEW_VERSION_4_4 || (GLEW_ARB_shader_image_load_store && GLEW_ARB_clear_texture);
    if (!this->Support)
    {
      vtkWarningWithObjectMacro(owner,
        "This OpenGL context has no image atomics or texture "
        "clears (OpenGL 4.4): soft shadows average "
        "LightSamples hard shadows instead of counting them.");
    }
  }
  return this->Support != 0;
}

std::vector<glm::dvec4> CountingTechnique::ChooseSamples(
  vtkObject* owner, const glm::dvec4& light, double radius, int requested, const glm::dvec3& target)
{
  if (requested > MaximumSamples && !this->WarnedSamples)
  {
    vtkWarningWithObjectMacro(owner,
      "Soft shadow volumes count at most " << MaximumSamples << " light samples; LightSamples "
                                           << requested << " is clamped for them.");
    this->WarnedSamples = true;
  }
  return SpreadLightSamples(light, radius, std::min(requested, MaximumSamples), target);
}

bool CountingTechnique::IsCheaper(
  const ShadowLight& light, const std::vector<CasterCache*>& casters, LastChoice last) const
{
  std::vector<CountingCost> costs;
  for (CasterCache* caster : casters)
  {
    if (!Counted(*caster, light))
    {
      continue;
    }
    CountingCost cost;
    cost.PotentialEdges = caster->CountingWedges[light.Light].Potential.size();
    const std::vector<SilhouetteEdge>& silhouette =
      caster->Volumes[light.VolumeKey(0)].Volume.Silhouette;
    cost.SilhouetteEdges = silhouette.size();
    cost.AngularRadius = light.World.w != 0.0
      ? CasterAngularRadius(glm::dvec3(light.World), light.SoftRadius, caster->WorldMin,
          caster->WorldMax, caster->Mesh->Topology.Points, silhouette, caster->ObjectToWorld)
      : light.SoftRadius;
    costs.push_back(cost);
  }
  return CountingIsCheaper(costs, static_cast<int>(light.CountingSamples.size()), last);
}

void CountingTechnique::PrepareLight(
  const ShadowLight& light, const std::vector<CasterCache*>& casters)
{
  for (CasterCache* caster : casters)
  {
    if (Counted(*caster, light))
    {
      caster->CountingWedges[light.Light].BuildVertices(*caster->Mesh);
    }
  }
}

vtkIdType CountingTechnique::UpdateCaster(
  const ShadowLight& light, CasterCache& caster, const ReceiverBounds& receivers)
{
  const glm::dvec4& reference = light.Samples.front(); // CountingReference
  const bool frontFacesOnly = ShadowVolume::FrontFacesSuffice(
    caster.Mesh->Topology, glm::inverse(caster.ObjectToWorld) * reference);
  return caster.CountingWedges[light.Light].Update(*caster.Mesh, caster.ObjectToWorld, reference,
           light.SoftRadius, frontFacesOnly, receivers)
    ? 1
    : 0;
}

void CountingTechnique::BeginVolumes(ShadowFrame& frame, const ShadowLight&)
{
  this->CountingDepthDrawn = this->DrawCountingDepth(frame);
  frame.AttachClearedFloatTarget(this->CentreCount);
}

bool CountingTechnique::DrawCountingDepth(ShadowFrame& frame)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkShaderProgram* program =
    frame.Programs->Ready(window, penumbraResolveVS, penumbraCountingDepthFS,
      "soft shadow volume point", "soft shadows average hard shadows instead");
  if (!program)
  {
    return false;
  }
  if (TextureNeedsAllocation(this->CountingDepth, window, frame.Size[0], frame.Size[1], 1, 1,
        vtkTextureObject::Nearest) &&
    !this->CountingDepth->AllocateDepth(frame.Size[0], frame.Size[1], vtkTextureObject::Float32))
  {
    this->CountingDepth->ReleaseGraphicsResources(window);
    vtkWarningWithObjectMacro(frame.Programs->Owner,
      "OpenGL refused a " << frame.Size[0] << "x" << frame.Size[1]
                          << " float depth texture for soft shadow volumes' points: lights average "
                             "their samples' hard shadows instead (the same image, more slowly).");
    return false;
  }
  // The centre's volumes are counted against it: it stays attached until Finish.
  frame.AttachDepth(this->CountingDepth);
  vtkOpenGLState* ostate = window->GetState();
  ScopedDrawState saved(ostate);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglEnable(GL_DEPTH_CLAMP); // the full-screen triangle lies on the far plane
  ActiveTextures surface(frame);
  SetSurfaceSide(frame, program);
  frame.SetClipToLocal(program, frame.SurfacePlanesOrigin);
  program->SetUniformf("depthBias", CountingDepthBias);
  program->SetUniformf("planeBias", CountingPlaneBias);
  frame.FullScreen->Draw(program, this->DepthVAO);
  return true;
}

bool CountingTechnique::AllocateCounters(
  vtkOpenGLRenderWindow* window, const glm::ivec2& texels, std::size_t samples)
{
  // Allocated for these texels and samples only when a light is counted, so averaging lights
  // hold none.
  const int words = static_cast<int>(CounterWords(samples));
  if (!TextureNeedsAllocation(
        this->SampleCounters, window, texels.x, texels.y, words, 1, vtkTextureObject::Nearest))
  {
    return true;
  }
  this->SampleCounters->SetInternalFormat(GL_R32UI);
  this->SampleCounters->SetFormat(GL_RED_INTEGER);
  this->SampleCounters->SetDataType(GL_UNSIGNED_INT);
  return this->SampleCounters->AllocateLayers(texels.x, texels.y, words, 1, VTK_UNSIGNED_INT);
}

bool CountingTechnique::ReadyCounters(
  vtkOpenGLRenderWindow* window, const int size[2], std::size_t samples, vtkObject* owner)
{
  const std::size_t bytes = static_cast<std::size_t>(size[0]) * size[1] * CounterWords(samples) * 4;
  if (this->RefusedCounterBytes && bytes >= this->RefusedCounterBytes)
  {
    return false;
  }
  if (this->AllocateCounters(window, glm::ivec2(size[0], size[1]), samples))
  {
    return true;
  }
  this->RefusedCounterBytes = bytes;
  vtkWarningWithObjectMacro(owner,
    "The sample counters for " << samples << " light samples at " << size[0] << "x" << size[1]
                               << " pixels need " << bytes / (1 << 20)
                               << " MiB of GPU memory in one texture, which this OpenGL "
                                  "refused: such lights average their samples' hard shadows "
                                  "instead (the same image, more slowly). Fewer LightSamples or "
                                  "a smaller frame count them.");
  return false;
}

void CountingTechnique::ClearCounters()
{
  const GLuint zero = 0;
  glClearTexImage(this->SampleCounters->GetHandle(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void CountingTechnique::Finish(ShadowFrame& frame, const ShadowLight& light)
{
  frame.AttachDepth(nullptr);
  // A shader that does not build turns counting off: from the next frame on such lights
  // average the same samples.
  const bool drawn = this->CountingDepthDrawn && this->Draw(frame, light) &&
    (!light.ShadowedByTranslucentCasters || this->DrawTransmission(frame, light));
  if (!drawn)
  {
    this->Support = 0;
  }
  ++frame.Counts.CountedLights;
}

bool CountingTechnique::Draw(ShadowFrame& frame, const ShadowLight& light)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkOpenGLState* ostate = window->GetState();
  ScopedDrawState saved(ostate);
  if (!this->HalfResolution && this->HalfResolutionTargets.GraphicsMemoryBytes() > 0)
  {
    this->HalfResolutionTargets.ReleaseGraphicsResources(window); // the option was turned off
  }
  ScopedFramebufferBindings bindings(ostate);
  // Translucent casters' transmission reads every pixel's counters: such lights count at full
  // resolution.
  const bool half = this->HalfResolution && !light.ShadowedByTranslucentCasters &&
    this->HalfResolutionTargets.Begin(frame);
  // Full size either way: at half resolution the counters' corner holds the counted pixels,
  // then the whole every pixel that the counted ones leave uncertain. Allocated already
  // (ReadyCounters), unless OpenGL lost them since.
  if (!this->AllocateCounters(
        window, glm::ivec2(frame.Size[0], frame.Size[1]), light.CountingSamples.size()))
  {
    return false;
  }
  this->ClearCounters();
  bool drawn;
  if (half)
  {
    // Uncertain: counted neighbours more than two samples apart, or a surface between them that
    // neither sees (penumbraHalfUpsampleFS.glsl). One sample apart would leave the mean within
    // half a sample of the full count, at up to a fifth more time (Documentation/wedges.md).
    const float uncertain = SmoothLimit(light.CountingSamples.size());
    drawn = this->CountWedges(frame, light, WedgePixels::Counted) &&
      this->Resolve(frame, light, ResolveInto::HalfResolution) &&
      this->HalfResolutionTargets.Upsample(frame, light.Layer, uncertain, this->CentreCount);
    if (drawn)
    {
      this->ClearCounters();
      drawn = this->CountWedges(frame, light, WedgePixels::Uncertain) &&
        this->Resolve(frame, light, ResolveInto::UncertainPixels);
    }
  }
  else
  {
    drawn = this->CountWedges(frame, light, WedgePixels::All) &&
      this->Resolve(frame, light, ResolveInto::Layer);
  }
  return drawn;
}

bool CountingTechnique::CountWedges(
  ShadowFrame& frame, const ShadowLight& light, WedgePixels pixels)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  const std::string wedgeFS = CountingShader(penumbraCountingWedgeFS, light.CountingSamples.size());
  vtkShaderProgram* program = frame.Programs->Ready(window, penumbraCountingWedgeVS,
    wedgeFS.c_str(), "soft shadow volume wedge", "soft shadows average hard shadows instead");
  if (!program)
  {
    return false;
  }
  vtkOpenGLState* ostate = window->GetState();
  ScopedDrawState saved(ostate);
  SetWedgeState(ostate, pixels);
  glBindImageTexture(0, this->SampleCounters->GetHandle(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  this->CountingDepth->Activate();
  SetWedgeUniforms(frame, program, light, pixels);
  const TechniqueCounts before = frame.Counts;
  DrawCountedWedges(frame, program, light);
  if (pixels == WedgePixels::Uncertain)
  {
    frame.Counts = before; // the wedges the counted pixels' pass drew, in the statistics once
  }
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  // For the resolve's reads and for the clear of a second count (glClearTexImage).
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  this->CountingDepth->Deactivate();
  return true;
}

void CountingTechnique::SetWedgeState(vtkOpenGLState* ostate, WedgePixels pixels)
{
  ostate->vtkglEnable(GL_STENCIL_TEST);
  ostate->vtkglStencilMask(0xFF);
  if (pixels == WedgePixels::Uncertain)
  {
    // Only where the half-resolution count left the pixel uncertain; fragments that pass the
    // depth test mark it reached there, as below.
    ostate->vtkglStencilFunc(GL_EQUAL,
      HalfResolutionCounts::UncertainStencil | HalfResolutionCounts::ReachedStencil,
      HalfResolutionCounts::ClassStencilBits);
    ostate->vtkglStencilMask(HalfResolutionCounts::ReachedStencil);
    ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  }
  else
  {
    // Wedge fragments that pass the depth test mark their pixel in the stencil, so that the
    // resolve reads counters only there.
    ostate->vtkglClear(GL_STENCIL_BUFFER_BIT);
    ostate->vtkglStencilFunc(GL_ALWAYS, 1, 0xFF);
    ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  }
  // Counts go to the image, not to colour.
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_CULL_FACE);
  ostate->vtkglEnable(GL_DEPTH_CLAMP);
}

void CountingTechnique::SetWedgeUniforms(const ShadowFrame& frame, vtkShaderProgram* program,
  const ShadowLight& light, WedgePixels pixels) const
{
  const bool counted = pixels == WedgePixels::Counted;
  frame.SetDepthUniforms(program, this->CountingDepth);
  const glm::vec4 clipToCounters =
    counted ? HalfResolutionCounts::ClipToCounters(frame.Size) : glm::vec4(1.0f, 1.0f, 0.0f, 0.0f);
  program->SetUniform4f("clipToCounters", glm::value_ptr(clipToCounters));
  program->SetUniformi("counterStride", counted ? 2 : 1);
  SetSampleCount(program, light.CountingSamples.size());
  program->SetUniformi("counters", 0);
  program->SetUniformf("eyeFloatBias", CountingEyeFloatBias);
  SetLightSamples(program, light);
}

bool CountingTechnique::Resolve(ShadowFrame& frame, const ShadowLight& light, ResolveInto target)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  const bool countOffset = target == ResolveInto::CountOffset;
  const std::string resolveFS = CountingShader(penumbraCountingResolveFS,
    light.CountingSamples.size(), countOffset ? "PENUMBRA_COUNT_OFFSET" : nullptr);
  vtkShaderProgram* resolve = frame.Programs->Ready(window, penumbraResolveVS, resolveFS.c_str(),
    countOffset ? "soft shadow volume count offset" : "soft shadow volume resolve",
    "soft shadows average hard shadows instead");
  if (!resolve)
  {
    return false;
  }
  vtkOpenGLState* ostate = window->GetState();
  ScopedDrawState saved(ostate);
  ostate->vtkglDisable(GL_SCISSOR_TEST); // every geometry pixel
  switch (target)
  {
    case ResolveInto::Layer:
    case ResolveInto::UncertainPixels:
      frame.AttachColour(frame.Layers(), light.Layer);
      break;
    case ResolveInto::CountOffset:
      frame.AttachClearedFloatTarget(this->CountOffset);
      break;
    case ResolveInto::HalfResolution:
      this->HalfResolutionTargets.AttachVisibility();
      break;
  }
  // At every geometry pixel (the far-plane triangle passes GL_GREATER exactly there): counters
  // where a wedge reached (the stencil's mark), the centre's count elsewhere.
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_DEPTH_CLAMP);
  ostate->vtkglDepthFunc(GL_GREATER);
  ostate->vtkglEnable(GL_STENCIL_TEST);
  ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  this->CentreCount->Activate();
  this->SampleCounters->Activate();
  resolve->SetUniformi("centreCount", this->CentreCount->GetTextureUnit());
  resolve->SetUniformi("counters", this->SampleCounters->GetTextureUnit());
  resolve->SetUniformi("counterStride", target == ResolveInto::HalfResolution ? 2 : 1);
  SetSampleCount(resolve, light.CountingSamples.size());
  this->Deep.Bind(window, resolve, DeepCountsImageUnit, light.Light);
  ActiveTextures surface(frame);
  if (!countOffset)
  {
    SetSurfaceSide(frame, resolve, &light);
  }
  // Counted again only at the uncertain pixels (CountWedges); every other pixel is written.
  const int counted =
    target == ResolveInto::UncertainPixels ? HalfResolutionCounts::UncertainStencil : 0;
  const int reachedMark =
    target == ResolveInto::UncertainPixels ? HalfResolutionCounts::ReachedStencil : 1;
  for (const bool reached : { true, false })
  {
    ostate->vtkglStencilFunc(GL_EQUAL, counted | (reached ? reachedMark : 0), 0xFF);
    resolve->SetUniformi("useCounters", reached ? 1 : 0);
    frame.FullScreen->Draw(resolve, countOffset ? this->OffsetVAO : this->ResolveVAO);
  }
  DeepCounts::Unbind(DeepCountsImageUnit);
  this->SampleCounters->Deactivate();
  this->CentreCount->Deactivate();
  if (countOffset)
  {
    frame.AttachColour(frame.Layers(), light.Layer);
  }
  return true;
}

bool CountingTechnique::DrawTransmission(ShadowFrame& frame, const ShadowLight& light)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  const std::string transmissionFS =
    CountingShader(penumbraCountingTransmissionFS, light.CountingSamples.size());
  vtkShaderProgram* program =
    frame.Programs->Ready(window, penumbraResolveVS, transmissionFS.c_str(),
      "soft shadow volume transmission", "soft shadows average hard shadows instead");
  if (!program)
  {
    return false;
  }
  // Additive, at every geometry pixel of each group's rectangle. DrawTranslucentVolumes and
  // Resolve leave this state as they find it.
  vtkOpenGLState* ostate = window->GetState();
  ScopedDrawState saved(ostate);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_DEPTH_CLAMP);
  ostate->vtkglDepthFunc(GL_GREATER);
  ostate->vtkglEnable(GL_SCISSOR_TEST);
  const std::size_t samples = light.CountingSamples.size();
  const float share = 1.0f / static_cast<float>(samples);
  bool offsetResolved = false;
  bool lightSet = false;
  for (std::size_t first = 0; first < samples; first += 4)
  {
    const std::size_t group = std::min<std::size_t>(4, samples - first);
    const PixelRect covered =
      frame.DrawTranslucentVolumes(light, first, group, this->LogTransmission, 4);
    if (covered.Empty())
    {
      continue;
    }
    // Once a translucent volume reaches the view; it leaves the transmission target alone.
    if (!offsetResolved &&
      !(offsetResolved = this->Resolve(frame, light, ResolveInto::CountOffset)))
    {
      return false;
    }
    SetScissor(ostate, covered);
    if (!frame.Programs->Bind(window, program, "soft shadow volume transmission"))
    {
      return false;
    }
    ActiveTextures surface(frame);
    SetSurfaceSide(frame, program, lightSet ? nullptr : &light);
    lightSet = true;
    this->CountOffset->Activate();
    this->SampleCounters->Activate();
    this->LogTransmission->Activate();
    program->SetUniformi("countOffset", this->CountOffset->GetTextureUnit());
    program->SetUniformi("counters", this->SampleCounters->GetTextureUnit());
    program->SetUniformi("logTransmission", this->LogTransmission->GetTextureUnit());
    program->SetUniformi("word", static_cast<int>(first / 4));
    program->SetUniformi("groupSize", static_cast<int>(group));
    program->SetUniformf("sampleShare", share);
    frame.FullScreen->Draw(program, this->TransmissionVAO);
    this->LogTransmission->Deactivate();
    this->SampleCounters->Deactivate();
    this->CountOffset->Deactivate();
  }
  return true;
}

std::size_t CountingTechnique::GraphicsMemoryBytes() const
{
  return TextureBytes(this->CentreCount) + TextureBytes(this->CountingDepth) +
    TextureBytes(this->SampleCounters) + TextureBytes(this->CountOffset) +
    TextureBytes(this->LogTransmission) + this->HalfResolutionTargets.GraphicsMemoryBytes() +
    this->Deep.GraphicsMemoryBytes();
}

void CountingTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->CentreCount->ReleaseGraphicsResources(window);
  this->CountingDepth->ReleaseGraphicsResources(window);
  this->SampleCounters->ReleaseGraphicsResources(window);
  this->CountOffset->ReleaseGraphicsResources(window);
  this->LogTransmission->ReleaseGraphicsResources(window);
  this->HalfResolutionTargets.ReleaseGraphicsResources(window);
  this->Deep.ReleaseGraphicsResources(window);
  this->DepthVAO.ReleaseGraphicsResources();
  this->ResolveVAO.ReleaseGraphicsResources();
  this->OffsetVAO.ReleaseGraphicsResources();
  this->TransmissionVAO.ReleaseGraphicsResources();
  this->Support = -1;
  this->RefusedCounterBytes = 0;
}

} // namespace penumbra
