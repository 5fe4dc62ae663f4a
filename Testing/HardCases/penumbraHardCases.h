// The hard-case suite of vtkSoftShadowPass (issue 5): scenes that break shadow algorithms, each
// rendered with every method of the pass and compared with the ray-traced truth by
// PenumbraHardCases. Documentation/robustness.md lists the cases, the metrics and the figures.
#ifndef penumbraHardCases_h
#define penumbraHardCases_h

#include "penumbraTestHarness.h"

#include <functional>
#include <string>
#include <vector>

namespace penumbra_hard
{

/// The pass's methods, as the suite runs them (Automatic is one of these per light).
enum MethodId
{
  HARD = 0,      ///< METHOD_HARD_VOLUMES, compared with the truth of the lights' centres
  AVERAGED = 1,  ///< METHOD_AVERAGED_HARD_SHADOWS with 16 samples
  WEDGES = 2,    ///< METHOD_PENUMBRA_WEDGES
  AUTOMATIC = 3, ///< METHOD_AUTOMATIC, what a user gets by default
  COUNTED = 4,   ///< METHOD_SOFT_SHADOW_VOLUMES with 16 samples, whatever Automatic would pick
  HALF_RESOLUTION = 5, ///< the same with HalfResolutionCounting on
  METHOD_COUNT = 6
};
const char* MethodName(int method);

/// A known limitation: the case/method may exceed the default limits up to these, for a reason
/// the report prints next to the figures.
struct Allowance
{
  int Method;
  int Leaks;      ///< leaks accepted
  double MAE;     ///< mean absolute error accepted
  double Popping; ///< share of popping pixels accepted in the worst step (temporal cases)
  std::string Why;
};

/// A scene under test: one window, one or more renderers, each with its own shadow pass; it
/// starts without a light (the case adds its own).
using CaseScene = penumbra_test::PassScene;

struct HardCase
{
  std::string Name;
  int Group;            ///< the issue's case number (1..14)
  std::string Expected; ///< the behaviour the case must show, in one sentence
  int Width = 200, Height = 150;
  /// Frames rendered; Frame(scene, i) runs before each (a moving light, a resize).
  int Frames = 1;
  std::function<void(CaseScene&)> Build;
  std::function<void(CaseScene&, int)> Frame;
  /// Frame-to-frame change of visibility is compared with the truth's (temporal stability).
  bool Temporal = false;
  /// Compare the visibility with this (earlier) case's, pixel for pixel, and use its truth.
  std::string Reference;
  /// Also render through vtkRenderLargeImage tiles and compare with the direct frame.
  bool LargeImageTiles = false;
  /// Bad input: the pass must say so with at least one warning.
  bool ExpectWarnings = false;
  std::vector<Allowance> Known;
};

/// Every case, in the order.
const std::vector<HardCase>& AllCases();

} // namespace penumbra_hard

#endif
