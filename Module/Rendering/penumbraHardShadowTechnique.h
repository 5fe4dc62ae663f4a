/**
 * @file    penumbraHardShadowTechnique.h
 * @brief   Hard shadow volumes (one light sample) and averaged hard shadows (LightSamples of
 *          them), translucent casters included: each sample's light is multiplied by what they
 *          let through.
 */
#ifndef penumbraHardShadowTechnique_h
#define penumbraHardShadowTechnique_h

#include "penumbraShadowTechnique.h"

#include "vtkNew.h"
#include "vtkTextureObject.h" // for vtkNew<vtkTextureObject>

#include <set>

namespace penumbra
{

/// Hard shadows of each of the light's samples, averaged (one sample: hard shadow volumes).
///
/// Opaque casters count in colour, with additive blending, so that each side of a volume is
/// filled once, weighted by its multiplicity (penumbra::ShadowVolume). One sample counts
/// straight into the light's layer, which then holds 1 - count and is clamped to [0, 1] wherever
/// it is read (a count cannot be negative); its resolve only puts the background back to 1, where
/// volumes crossed it (ShadowFrame::LightBackground). Averaged samples count in
/// colour where repeated sides make up at least AveragedColourShare of the light's sides (open
/// meshes), each into a count target cleared for it, from which a resolve takes the sample's
/// 1/N of the light where the count is not 0; elsewhere the clears and texture reads would cost
/// more than the fill they spare, and they count in the stencil. Translucent casters (opacity a <
/// 1) need the opaque count where they are drawn: with one in view the opaque casters count in the
/// stencil instead, and the translucent ones in colour, log(1 - a) for each of their surfaces
/// between the point and the sample (every triangle counts, CountingRule::EveryTriangle), so that
/// where the stencil is 0 the sample's light is multiplied by the transmission exp(sum), as a ray
/// tracer's shadow ray through those surfaces.
class HardShadowTechnique : public ShadowTechnique
{
public:
  /// The stencil and the volumes' own depth test are all it needs.
  bool ReadsDepthCopy() const override { return false; }
  bool ShadowsTranslucentCasters() const override { return true; }
  bool CountsInColour(const ShadowLight& light) const override;
  /// Decides CountsInColour for the light from its opaque casters' volumes.
  void PrepareLight(const ShadowLight& light, const std::vector<CasterCache*>& casters) override;
  /// Averaged samples count in colour from this share of repeated side indices on: with none
  /// (closed casters) the stencil was 1.6 times faster on the benchmark's classic scene, with 45%
  /// (an open isosurface) colour was 1.35 times faster (results.md, "Sides filled once").
  static constexpr double AveragedColourShare = 0.25;
  /// Attaches a cleared count target when several samples count in colour.
  void BeginVolumes(ShadowFrame& frame, const ShadowLight& light) override;
  /// Every geometry pixel with a non-zero count is in sample k's shadow: 1/N of the light goes
  /// (one sample counted in colour has written its layer already, but for the background). Where
  /// the stencil count is 0, 1/N of the light times one minus the transmission of the translucent
  /// casters' volumes of sample k, drawn then, goes.
  void ResolveSample(ShadowFrame& frame, const ShadowLight& light, std::size_t k) override;
  /// The count target, once several samples counted in colour, and the log-transmission target,
  /// once a translucent caster was drawn: 4 bytes per pixel each.
  std::size_t GraphicsMemoryBytes() const override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

private:
  /// The lights whose averaged samples count in colour this frame.
  std::set<const vtkLight*> AveragedInColour;
  /// Attaches the count target, cleared, for the next sample's volumes.
  void AttachSampleCount(ShadowFrame& frame);
  /// Attaches the light's layer and takes `share` away where the count target is not 0.
  void ResolveSampleCount(ShadowFrame& frame, const ShadowLight& light, float share);

  /// Minus one averaged sample's opaque count (R32F).
  vtkNew<vtkTextureObject> SampleCount;
  FullScreenTriangle::VAO SampleCountVAO;
  /// log(1 - opacity) summed over one sample's translucent surfaces (R32F).
  vtkNew<vtkTextureObject> LogTransmission;
  FullScreenTriangle::VAO TransmissionVAO;
};

} // namespace penumbra

#endif
