/**
 * @file    penumbraTechniqueChooser.h
 * @brief   The pass's shadow methods, one object each, and the one place that picks which of
 *          them draws each light's LI layer this frame.
 */
#ifndef penumbraTechniqueChooser_h
#define penumbraTechniqueChooser_h

#include "penumbraCountingTechnique.h"
#include "penumbraHardShadowTechnique.h"
#include "penumbraPlateauTechnique.h"
#include "penumbraWedgeTechnique.h"

#include "vtkLight.h"
#include "vtkWeakPointer.h"

#include <glm/glm.hpp>

#include <array>
#include <map>
#include <vector>

class vtkObject;
class vtkRenderer;
class vtkSoftShadowPass;

namespace penumbra
{

/**
 * Holds the methods and chooses between them in two steps, and a third once in a light's life.
 * Choose, when the frame's lights are collected: from the pass's Method and the light's radius
 * (hard shadows without a radius; Automatic and soft shadow volumes count where the context allows,
 * and average the same samples where it does not; Automatic also averages more samples than
 * counting holds, and a light whose counts came near what the counters hold, penumbra::DeepCounts,
 * where the forced method warns instead). FindPlateauPlane, before the casters are updated:
 * plateaus without a receiver plane draw hard shadows. Reconsider, once the light's casters are
 * up to date: Automatic averages the counted samples where its cost model
 * (penumbra::CountingIsCheaper) expects averaging to be cheaper. And
 * AverageIfFirstCountWentDeep, after Automatic's first count of a light is drawn: a light whose
 * counts already came near the limit is averaged in that same frame.
 */
class TechniqueChooser
{
public:
  HardShadowTechnique Hard;
  WedgeTechnique Wedges;
  PlateauTechnique Plateaus;
  CountingTechnique Counting;

  std::array<ShadowTechnique*, 4> All()
  {
    return { &this->Hard, &this->Wedges, &this->Plateaus, &this->Counting };
  }

  /// Sets the light's technique, samples and radii from `pass`'s Method and LightSamples and
  /// the light's radius (vtkSoftShadowPass::GetLightRadius); the samples face `target`. A
  /// directional light's radius of 90 degrees or more is clamped to 89, with one warning.
  /// Reads back, from `window`, how deep the last frames' counts went (penumbra::DeepCounts).
  void Choose(vtkSoftShadowPass* pass, ShadowLight& light, const glm::dvec3& target,
    vtkOpenGLRenderWindow* window);

  /// Plateaus need a receiver plane: finds this frame's, and without one makes every light
  /// draw hard shadows (warned once). Call after Choose, before the casters are updated.
  void FindPlateauPlane(vtkRenderer* renderer, vtkObject* owner, std::vector<ShadowLight>& lights);

  /// Once the light's casters are up to date: Automatic averages the counted samples instead
  /// where that is expected to be cheaper (the same samples, the same image), with hysteresis
  /// on the light's last choice (penumbra::CountingIsCheaper), and any counted light averages
  /// where OpenGL refuses the counters for a frame of `size` (warned through `owner`). Returns
  /// true when it changed the light's samples, whose casters then need updating again.
  bool Reconsider(ShadowLight& light, const std::vector<CasterCache*>& casters, int lightSamples,
    vtkOpenGLRenderWindow* window, const int size[2], vtkObject* owner);

  /// After a light's layer is drawn: the first time Automatic counted the light, whether its
  /// counts came near what the counters hold in this very frame, read back at once from
  /// `window` (a wait for the GPU, once in the light's life). If so the light is recorded as
  /// deep and set to average its samples, and the caller updates its casters and draws its
  /// layer again: a single frame, as a regression test renders, is averaged, not overflowed.
  /// Later frames see deep counts a frame late (Choose).
  bool AverageIfFirstCountWentDeep(
    ShadowLight& light, int lightSamples, vtkOpenGLRenderWindow* window);

private:
  /// What the chooser remembers of a light. Held weakly: once the light is deleted, a new light
  /// that VTK allocates at its address starts afresh, warned again and without hysteresis.
  struct LightRecord
  {
    vtkWeakPointer<vtkLight> Light;
    bool WarnedRadius = false;
    LastChoice Last = LastChoice::None; ///< Automatic's last choice
    /// Its counts came near what counting's counters hold (penumbra::DeepCounts): warned for
    /// the forced method, averaged by Automatic from then on.
    bool DeepCounts = false;
    /// Automatic's first count of it was read back in its own frame.
    bool FirstCountChecked = false;
  };
  /// Makes the light average its samples (lightSamples of them) instead of counting them.
  void AverageSamples(ShadowLight& light, int lightSamples);
  /// The record of `light`, new if the light is; records of deleted lights are dropped then.
  LightRecord& Record(vtkLight* light);
  /// Whether the light's counts came near what the counters hold, in the frames read back so
  /// far (for as long as the light lives); the first time, the forced method warns.
  bool CountsCameNearLimit(
    vtkSoftShadowPass* pass, const ShadowLight& light, vtkOpenGLRenderWindow* window);

  std::map<vtkLight*, LightRecord> Records;
};

} // namespace penumbra

#endif
