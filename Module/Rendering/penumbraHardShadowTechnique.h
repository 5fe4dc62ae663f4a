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

namespace penumbra
{

/// Hard shadows of each of the light's samples, averaged (one sample: hard shadow volumes).
///
/// Opaque casters count in the stencil: a sample whose count is not 0 takes its 1/N of the light
/// away. Hard shadows (one sample) with no translucent caster in view count in colour instead,
/// straight into the light's layer: it holds 1 - count, which every reader clamps to [0, 1]
/// (a count cannot be negative), so no resolve is drawn and each side is filled once. Translucent
/// casters (opacity a < 1) count in colour instead, log(1 - a) for each of their surfaces between
/// the point and the sample (every triangle counts, CountingRule::EveryTriangle), so that where the
/// stencil is 0 the sample's light is multiplied by the transmission exp(sum), as a ray tracer's
/// shadow ray through those surfaces.
class HardShadowTechnique : public ShadowTechnique
{
public:
  /// The stencil and the volumes' own depth test are all it needs.
  bool ReadsDepthCopy() const override { return false; }
  bool ShadowsTranslucentCasters() const override { return true; }
  bool CountsInColour(const ShadowLight& light) const override;
  /// Counted in colour, the layer is already written. Otherwise every geometry pixel with a
  /// non-zero stencil count is in sample k's shadow: 1/N of the light goes. Where the count is 0,
  /// 1/N of the light times one minus the transmission of the translucent casters' volumes of
  /// sample k, drawn then, goes.
  void ResolveSample(ShadowFrame& frame, const ShadowLight& light, std::size_t k) override;
  /// The log-transmission target, once a translucent caster was drawn: 4 bytes per pixel.
  std::size_t GraphicsMemoryBytes() const override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

private:
  /// log(1 - opacity) summed over one sample's translucent surfaces (R32F).
  vtkNew<vtkTextureObject> LogTransmission;
  FullScreenTriangle::VAO TransmissionVAO;
};

} // namespace penumbra

#endif
