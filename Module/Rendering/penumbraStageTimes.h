/**
 * @file   penumbraStageTimes.h
 * @brief  CPU and GPU time of each stage of vtkSoftShadowPass's frame.
 *
 * GPU times come from GL timestamp queries (glQueryCounter) at each stage's ends, so stages that
 * recur within a frame (one volume pass per light) add up. CPU times are the wall-clock time
 * from a stage's start to the end of its GL work. Both need the pipeline drained at every stage
 * boundary (glFinish), or a driver that defers work to its next flush bills it to the wrong
 * stage: a timed frame is slower than an untimed one, and collection is off unless asked for
 * (vtkSoftShadowPass::CollectStageTimes).
 */
#ifndef penumbraStageTimes_h
#define penumbraStageTimes_h

#include "vtk_glew.h"

#include <array>
#include <chrono>
#include <vector>

namespace penumbra
{

class StageTimes
{
public:
  StageTimes()
  {
    this->Cpu.fill(-1.0);
    this->Gpu.fill(-1.0);
  }
  /// The stages, in frame order; the same numbers as vtkSoftShadowPass::STAGE_*.
  enum Stage
  {
    Depth,   ///< the depth pass and its copy for the wedge shaders
    Casters, ///< the scene walk, topology, silhouettes and wedge buffers (CPU)
    Volumes, ///< shadow volumes and their resolves into the LI buffer
    Wedges,  ///< wedges, per-sample counting (a counted light's translucent casters too), plateaus
    Compositing, ///< the delegate: the scene drawn with the LI buffer applied
    Count
  };

  /// Starts a frame; with `enabled` false every call until EndFrame does nothing.
  void BeginFrame(bool enabled);
  void Begin(Stage stage);
  void End(Stage stage);
  /// Reads the frame's queries back (waiting for the GPU) and sums each stage.
  void EndFrame();
  /// Negative when the frame was not timed.
  double CpuMilliseconds(Stage stage) const { return this->Cpu[stage]; }
  /// Negative when the frame was not timed or timestamps are not supported.
  double GpuMilliseconds(Stage stage) const { return this->Gpu[stage]; }
  void ReleaseGraphicsResources();

  /// Times a scope as one stage.
  class Scope
  {
  public:
    Scope(StageTimes& times, Stage stage)
      : Times(times)
      , Which(stage)
    {
      this->Times.Begin(stage);
    }
    ~Scope() { this->Times.End(this->Which); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

  private:
    StageTimes& Times;
    Stage Which;
  };

private:
  struct Interval
  {
    Stage Which;
    GLuint Queries[2];
  };
  using Clock = std::chrono::steady_clock;
  GLuint NextQuery();

  bool Enabled = false;
  std::vector<GLuint> Pool; ///< query objects, reused frame after frame
  std::size_t Used = 0;
  std::vector<Interval> Intervals;
  std::array<Clock::time_point, Count> CpuStart{};
  std::array<GLuint, Count> OpenQuery{};
  std::array<double, Count> Cpu{};
  std::array<double, Count> Gpu{};
};

} // namespace penumbra

#endif
