/**
 * @file    penumbraDeepCounts.h
 * @brief   The deepest depth complexity that each counted light's resolve met, read back so
 *          that soft shadow volumes' 8-bit counters do not overflow silently.
 *
 * A sample behind more surfaces than the counters hold (penumbraCountingResolveFS.glsl) reads
 * as any count. The resolve reports, per light, the deepest count it decoded or the centre's
 * where either reaches ReportedCount: such a light's counts are near the limit, and a point a
 * little deeper overflows. The report is one texel per light, read at the next frame's choice,
 * when the GPU has long finished the frame that wrote it, so that no draw is waited for; only
 * Automatic's first count of a light is read back in its own frame, once in the light's life
 * (TechniqueChooser::AverageIfFirstCountWentDeep).
 */
#ifndef penumbraDeepCounts_h
#define penumbraDeepCounts_h

#include "vtkNew.h"
#include "vtkTextureObject.h" // for vtkNew<vtkTextureObject>

#include <cstddef>
#include <map>
#include <vector>

class vtkLight;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

namespace penumbra
{

class DeepCounts
{
public:
  /// Counts from here on are reported: 8-bit counters read up to 251.
  static constexpr int ReportedCount = 200;

  /// Binds the report as image unit `unit` of `program` (uniforms deepCounts, deepCountSlot and
  /// reportedCount) for a resolve of `light`'s counts.
  void Bind(vtkOpenGLRenderWindow* window, vtkShaderProgram* program, int unit, vtkLight* light);
  /// Unbinds image unit `unit` after the resolve.
  static void Unbind(int unit);
  /// The deepest count reported for `light` by the frames since the last read, 0 when none
  /// reached ReportedCount. The first call after a frame reads every light's report back.
  int Take(vtkOpenGLRenderWindow* window, vtkLight* light);
  std::size_t GraphicsMemoryBytes() const;
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  static constexpr int Slots = 64; ///< lights reported per frame; more go unreported
  void ReadBack(vtkOpenGLRenderWindow* window);

  vtkNew<vtkTextureObject> Report; ///< R32UI, Slots x 1: per slot the deepest count reported
  std::vector<vtkLight*> Pending;  ///< the light of each slot written since the last read
  std::map<vtkLight*, int> Deepest;
};

} // namespace penumbra

#endif
