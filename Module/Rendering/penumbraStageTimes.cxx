#include "penumbraStageTimes.h"

namespace penumbra
{

void StageTimes::BeginFrame(bool enabled)
{
  this->Enabled = enabled;
  this->Used = 0;
  this->Intervals.clear();
  this->Cpu.fill(enabled ? 0.0 : -1.0);
  this->Gpu.fill(-1.0);
}

GLuint StageTimes::NextQuery()
{
  if (this->Used == this->Pool.size())
  {
    GLuint query = 0;
    glGenQueries(1, &query);
    this->Pool.push_back(query);
  }
  return this->Pool[this->Used++];
}

void StageTimes::Begin(Stage stage)
{
  if (!this->Enabled)
  {
    return;
  }
  // Finishing what was queued before keeps it out of this stage: drivers that defer work to
  // the next flush (llvmpipe rasterizes at flush time) would otherwise bill it to whichever
  // stage flushes.
  glFinish();
  this->CpuStart[stage] = Clock::now();
  this->OpenQuery[stage] = this->NextQuery();
  glQueryCounter(this->OpenQuery[stage], GL_TIMESTAMP);
}

void StageTimes::End(Stage stage)
{
  if (!this->Enabled)
  {
    return;
  }
  const GLuint end = this->NextQuery();
  glQueryCounter(end, GL_TIMESTAMP);
  glFinish();
  this->Intervals.push_back({ stage, { this->OpenQuery[stage], end } });
  this->Cpu[stage] +=
    std::chrono::duration<double, std::milli>(Clock::now() - this->CpuStart[stage]).count();
}

void StageTimes::EndFrame()
{
  if (!this->Enabled)
  {
    return;
  }
  for (double& gpu : this->Gpu)
  {
    gpu = 0.0;
  }
  for (const Interval& interval : this->Intervals)
  {
    GLuint64 start = 0, end = 0;
    glGetQueryObjectui64v(interval.Queries[0], GL_QUERY_RESULT, &start); // waits for the GPU
    glGetQueryObjectui64v(interval.Queries[1], GL_QUERY_RESULT, &end);
    this->Gpu[interval.Which] += static_cast<double>(end - start) * 1e-6;
  }
}

void StageTimes::ReleaseGraphicsResources()
{
  if (!this->Pool.empty())
  {
    glDeleteQueries(static_cast<GLsizei>(this->Pool.size()), this->Pool.data());
  }
  this->Pool.clear();
  this->Used = 0;
  this->Intervals.clear();
}

} // namespace penumbra
