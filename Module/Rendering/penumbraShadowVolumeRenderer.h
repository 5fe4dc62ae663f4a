/**
 * @file    penumbraShadowVolumeRenderer.h
 * @brief   The casters' shadow volumes, one per light sample: kept up to date from the cached
 *          silhouettes and counted into the LI buffer, z-pass where the volume cannot reach the
 *          near plane, z-fail with caps elsewhere, the far end at infinity.
 *
 * Opaque casters' volumes are counted one sample at a time, for the light's technique to
 * resolve: in the stencil, or, where the technique counts in colour
 * (ShadowTechnique::CountsInColour), additively into the float target it bound. Translucent
 * casters' volumes add log(1 - opacity) per crossing into a float target, one sample per channel
 * (ShadowFrame::DrawTranslucentVolumes). Each volume is drawn only inside its scissor
 * (penumbra::ShadowScissor): elsewhere it counts 0.
 */
#ifndef penumbraShadowVolumeRenderer_h
#define penumbraShadowVolumeRenderer_h

#include "penumbraCulling.h" // for PixelRect
#include "penumbraShadowCaches.h"

#include "vtkType.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <utility>

class vtkLight;
class vtkShaderProgram;
class vtkTextureObject;

namespace penumbra
{

struct ShadowFrame;
struct ShadowLight;

class ShadowVolumeRenderer
{
public:
  /// Brings the opaque caster's volume of each of the light's samples up to date; returns the
  /// silhouette updates it made.
  static vtkIdType UpdateOpaque(const ShadowLight& light, CasterCache& caster);
  /// The same for a translucent caster, one volume per TranslucentSamples entry, every triangle
  /// counted (its count is the number of its surfaces in the way).
  static vtkIdType UpdateTranslucent(const ShadowLight& light, CasterCache& caster);

  /// Readies the volume program for this frame and zeroes the counts; false (reported once) when
  /// it does not build: then no shadow is drawn.
  bool Begin(const ShadowFrame& frame);
  /// Counts the opaque casters' volumes from light.Samples[k] into the stencil (cleared first),
  /// or, where the light's technique counts in colour (ShadowTechnique::CountsInColour),
  /// additively into the float target bound. The GL state is restored on return; the counts
  /// stay.
  void DrawOpaqueSample(const ShadowFrame& frame, const ShadowLight& light, std::size_t k);
  /// What ShadowFrame::DrawTranslucentVolumes does.
  PixelRect DrawTranslucent(const ShadowFrame& frame, const ShadowLight& light, std::size_t first,
    std::size_t count, vtkTextureObject* target, int components);

  vtkIdType GetTriangles() const { return this->Triangles; }
  vtkIdType GetZFailVolumes() const { return this->ZFailVolumes; }

private:
  /// Draws one caster's volume from `sample` into the stencil or, with `countInColour`, as
  /// -weight per crossing in front of the point (z-pass) or the same total from those behind it
  /// (z-fail) into colour, its sides' ends at the caster pushed away from the eye by
  /// `sideDepthBias` (ShadowTechnique::VolumeDepthBias). It sets the stencil operations and depth
  /// function of its draws: its callers hold the ScopedDrawState, not it, as it runs per caster
  /// and sample.
  void DrawVolume(const ShadowFrame& frame, CasterCache& caster,
    const std::pair<vtkLight*, int>& key, const glm::dvec4& sample, bool countInColour,
    float weight, float sideDepthBias = 0.0f);

  vtkShaderProgram* Program = nullptr;
  vtkIdType Triangles = 0;
  vtkIdType ZFailVolumes = 0;
};

} // namespace penumbra

#endif
