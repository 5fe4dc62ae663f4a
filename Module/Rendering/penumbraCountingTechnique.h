/**
 * @file    penumbraCountingTechnique.h
 * @brief   Soft shadow volumes (METHOD_SOFT_SHADOW_VOLUMES, and Automatic's choice where it is
 *          cheaper): the centre's count plus each light sample's changes over the potential
 *          silhouette's wedges, in 8-bit counters (Documentation/wedges.md).
 *
 * Only opaque casters are counted. Translucent ones are drawn after, four light samples at a
 * time, one a channel (ShadowFrame::DrawTranslucentVolumes), and where the counters say that opaque
 * casters leave the sample visible its share of the light is multiplied by their transmission: the
 * averaged method's image for the same samples, at the cost of averaging the translucent casters
 * only.
 */
#ifndef penumbraCountingTechnique_h
#define penumbraCountingTechnique_h

#include "penumbraDeepCounts.h"
#include "penumbraHalfResolutionCounts.h"
#include "penumbraLayeredTexture.h" // for vtkNew<vtkPenumbraLayeredTexture>
#include "penumbraSampleCounting.h" // for LastChoice
#include "penumbraShadowTechnique.h"

#include "vtkNew.h"
#include "vtkTextureObject.h" // for vtkNew<vtkTextureObject>

namespace penumbra
{

class CountingTechnique : public ShadowTechnique
{
public:
  /// The most samples the shaders count (their uniform array).
  static constexpr int MaximumSamples = 256;

  /// Whether the context has image atomics and texture clears (checked once per window; warns
  /// once through `owner` when not).
  bool Supported(vtkObject* owner);
  /// `requested` samples spread over the light as the averaged method spreads them, clamped to
  /// MaximumSamples with one warning.
  std::vector<glm::dvec4> ChooseSamples(vtkObject* owner, const glm::dvec4& light, double radius,
    int requested, const glm::dvec3& target);
  /// Whether counting the light's samples should be cheaper than averaging them
  /// (penumbra::CountingIsCheaper, with the light's `last` choice), from its casters' potential
  /// silhouettes.
  bool IsCheaper(
    const ShadowLight& light, const std::vector<CasterCache*>& casters, LastChoice last) const;
  /// Allocates the per-sample counters for a frame of `size` pixels and `samples` samples, or
  /// says, once per size refused, that OpenGL refused them (GL_OUT_OF_MEMORY: on llvmpipe a 4K
  /// frame's for more than about 200 samples, an 8K frame's for 64): the light must then average
  /// its samples. A size refused is not tried again until the counters are released.
  bool ReadyCounters(
    vtkOpenGLRenderWindow* window, const int size[2], std::size_t samples, vtkObject* owner);
  /// The deepest count that `light`'s resolves met in the frames drawn since the last call, 0
  /// unless it reached DeepCounts::ReportedCount (near what the 8-bit counters hold).
  int TakeDeepestCount(vtkOpenGLRenderWindow* window, vtkLight* light)
  {
    return this->Deep.Take(window, light);
  }
  /// Whether lights without translucent casters are counted at half the viewport's resolution
  /// in each direction (vtkSoftShadowPass::HalfResolutionCounting).
  void SetHalfResolution(bool half) { this->HalfResolution = half; }
  bool CountsCentreInColour() const override { return true; }
  bool ReadsSurfacePlanes() const override { return true; }
  float VolumeDepthBias() const override;
  bool ShadowsTranslucentCasters() const override { return true; }
  /// Builds the wedges of the opaque casters that are not culled (after the chooser kept
  /// counting).
  void PrepareLight(const ShadowLight& light, const std::vector<CasterCache*>& casters) override;
  /// Finds the caster's potential silhouette again when its mesh, matrix, the light or the
  /// counting rule changed.
  vtkIdType UpdateCaster(
    const ShadowLight& light, CasterCache& caster, const ReceiverBounds& receivers) override;
  /// Writes each pixel's counting depth (DrawCountingDepth), which the centre's volumes are then
  /// counted against, into a texture of their own for the resolve to read.
  void BeginVolumes(ShadowFrame& frame, const ShadowLight& light) override;
  void ResolveSample(ShadowFrame&, const ShadowLight&, std::size_t) override {}
  /// Counts the samples over the wedges and writes the share of visible ones into the layer,
  /// then multiplies each visible sample's share by its translucent casters' transmission.
  void Finish(ShadowFrame& frame, const ShadowLight& light) override;
  /// The counting depth, centre count and counters: 8 + N bytes per pixel, and 20 more for the
  /// count offset and the transmission of four samples once a light with translucent casters was
  /// counted; at half resolution the counted pixels' depth-stencil and visibility, 2 more.
  std::size_t GraphicsMemoryBytes() const override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

private:
  /// Where Resolve writes: the visibility into the light's layer, into the pixels that the
  /// half-resolution count left uncertain (HalfResolutionCounts::UncertainStencil), or into the
  /// counted pixels' visibility at half resolution; or the counts' per-pixel offset
  /// (PENUMBRA_COUNT_OFFSET).
  enum class ResolveInto
  {
    Layer,
    UncertainPixels,
    CountOffset,
    HalfResolution
  };
  /// Which pixels CountWedges counts: all, the half-resolution ones, or those the stencil marks
  /// uncertain after them.
  enum class WedgePixels
  {
    All,
    Counted,
    Uncertain
  };
  /// Writes into CountingDepth, and leaves attached as the LI framebuffer's depth, the depth of
  /// each pixel's point that the centre's volumes and the wedges count at
  /// (penumbra::CountingPointDepth). False where its shader does not build or OpenGL refuses the
  /// texture.
  bool DrawCountingDepth(ShadowFrame& frame);
  bool Draw(ShadowFrame& frame, const ShadowLight& light);
  /// Adds every opaque caster's wedges' changes into the counters at `pixels`.
  bool CountWedges(ShadowFrame& frame, const ShadowLight& light, WedgePixels pixels);
  /// The draw state of CountWedges: no colour, and the stencil marking the pixels that wedges
  /// reach (among the uncertain ones only, for WedgePixels::Uncertain).
  static void SetWedgeState(vtkOpenGLState* ostate, WedgePixels pixels);
  /// The wedge program's uniforms for counting the light's samples at `pixels`; CountingDepth,
  /// which the wedges read as their depth, must be active.
  void SetWedgeUniforms(const ShadowFrame& frame, vtkShaderProgram* program,
    const ShadowLight& light, WedgePixels pixels) const;
  /// Sizes the counters for `texels` and `samples`; false when OpenGL refuses them.
  bool AllocateCounters(
    vtkOpenGLRenderWindow* window, const glm::ivec2& texels, std::size_t samples);
  void ClearCounters();
  /// Into `target`, at every geometry pixel (or counted pixel at half resolution).
  bool Resolve(ShadowFrame& frame, const ShadowLight& light, ResolveInto target);
  /// Takes from each counted sample's visible share what translucent casters keep from it, four
  /// samples (one counters' word) at a time.
  bool DrawTransmission(ShadowFrame& frame, const ShadowLight& light);

  /// The centre's count (R32F) and the per-sample counters (R32UI, four 8-bit counts per texel,
  /// one slice per four samples), allocated once a light is counted and kept until the pass's
  /// ReleaseGraphicsResources (GetGraphicsMemoryBytes counts them while they are held).
  vtkNew<vtkTextureObject> CentreCount;
  vtkNew<vtkPenumbraLayeredTexture> SampleCounters;
  /// The depth of each pixel's counting point (DEPTH_COMPONENT32F).
  vtkNew<vtkTextureObject> CountingDepth;
  bool CountingDepthDrawn = false;
  /// The smallest counters' size OpenGL refused (0: none).
  std::size_t RefusedCounterBytes = 0;
  /// Per pixel, what makes a visible sample's counter field 0 (R32F), for the translucent
  /// casters' resolve.
  vtkNew<vtkTextureObject> CountOffset;
  /// log(1 - opacity) summed over the translucent surfaces in the way of four samples (RGBA32F).
  vtkNew<vtkTextureObject> LogTransmission;
  HalfResolutionCounts HalfResolutionTargets;
  DeepCounts Deep;
  FullScreenTriangle::VAO DepthVAO, ResolveVAO, OffsetVAO, TransmissionVAO;
  int Support = -1;
  bool WarnedSamples = false;
  bool HalfResolution = false;
};

} // namespace penumbra

#endif
