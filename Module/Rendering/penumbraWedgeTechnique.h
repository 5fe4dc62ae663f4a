/**
 * @file    penumbraWedgeTechnique.h
 * @brief   Penumbra wedges of the centre silhouette (METHOD_PENUMBRA_WEDGES): the centre's
 *          volumes counted into the layer, each silhouette edge's exact occlusion term added
 *          over its wedge, then the horizon cap (Documentation/wedges.md).
 */
#ifndef penumbraWedgeTechnique_h
#define penumbraWedgeTechnique_h

#include "penumbraShadowTechnique.h"

namespace penumbra
{

class WedgeTechnique : public ShadowTechnique
{
public:
  bool CountsCentreInColour() const override { return true; }
  /// Rebuilds the caster's wedges when its centre silhouette, matrix, the light or the
  /// receivers' box changed.
  vtkIdType UpdateCaster(
    const ShadowLight& light, CasterCache& caster, const ReceiverBounds& receivers) override;
  /// The centre's volume was also counted over the background: put it back to fully lit.
  void ResolveSample(ShadowFrame& frame, const ShadowLight& light, std::size_t k) override;
  /// Adds every caster's wedges into the layer, then caps it by the horizon.
  void Finish(ShadowFrame& frame, const ShadowLight& light) override;
  void ReleaseGraphicsResources(vtkWindow*) override;

private:
  FullScreenTriangle::VAO HorizonVAO;
};

} // namespace penumbra

#endif
