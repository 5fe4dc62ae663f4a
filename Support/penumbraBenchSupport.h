// Header-only helpers shared by PenumbraBench, PenumbraLoad, the demo (Examples/PenumbraDemo.cxx)
// and the hard-case suite: frame-time summaries, frame grabs and PNG output.
#ifndef penumbraBenchSupport_h
#define penumbraBenchSupport_h

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowPass.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace penumbra
{
namespace bench
{

using Clock = std::chrono::steady_clock;

/// Seconds elapsed since `start`.
inline double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/**
 * An output window that counts the errors and warnings VTK logs, and still prints them, so that a
 * run can report them and fail on them. Install it with vtkOutputWindow::SetInstance.
 */
class vtkCountingOutputWindow : public vtkOutputWindow
{
public:
  static vtkCountingOutputWindow* New() { VTK_STANDARD_NEW_BODY(vtkCountingOutputWindow); }
  vtkTypeMacro(vtkCountingOutputWindow, vtkOutputWindow);

  void DisplayErrorText(const char* text) override
  {
    ++this->Errors;
    this->Keep(text, true);
    this->Superclass::DisplayErrorText(text);
  }
  void DisplayWarningText(const char* text) override
  {
    ++this->Warnings;
    this->Keep(text, false);
    this->Superclass::DisplayWarningText(text);
  }
  void DisplayGenericWarningText(const char* text) override
  {
    ++this->Warnings;
    this->Keep(text, false);
    this->Superclass::DisplayGenericWarningText(text);
  }

  int Errors = 0;
  int Warnings = 0;
  std::string First;      ///< the first message (error or warning) since the last Reset
  std::string FirstError; ///< the first error since the last Reset
  void Reset()
  {
    this->Errors = this->Warnings = 0;
    this->First.clear();
    this->FirstError.clear();
  }

private:
  void Keep(const char* text, bool error)
  {
    if (!text)
    {
      return;
    }
    if (this->First.empty())
    {
      this->First = text;
    }
    if (error && this->FirstError.empty())
    {
      this->FirstError = text;
    }
  }
};

/// One more frame with `pass`'s stage times on (the pipeline drained at each stage's end): the
/// wall-clock milliseconds of each stage, in vtkSoftShadowPass's stage order.
inline std::vector<double> TimedStages(vtkSoftShadowPass* pass, vtkRenderWindow* window)
{
  pass->CollectStageTimesOn();
  window->Render();
  pass->CollectStageTimesOff();
  std::vector<double> ms;
  for (int stage = 0; stage < vtkSoftShadowPass::NUMBER_OF_STAGES; ++stage)
  {
    ms.push_back(pass->GetStageCPUMilliseconds(stage));
  }
  return ms;
}

/// The algorithm's polydata output, detached from the pipeline (a mapper holding it keeps it
/// alive, and later pipeline updates do not change it).
inline vtkSmartPointer<vtkPolyData> DetachedOutput(vtkAlgorithm* source)
{
  source->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->ShallowCopy(vtkPolyData::SafeDownCast(source->GetOutputDataObject(0)));
  return data;
}

/// An actor drawing `data` in one colour with the benchmarks' material (ambient 0.15, diffuse
/// 0.85, a little specular), ignoring its scalars.
inline vtkSmartPointer<vtkActor> MakeShadedActor(vtkPolyData* data, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  property->SetColor(r, g, b);
  property->SetAmbient(0.15);
  property->SetDiffuse(0.85);
  property->SetSpecular(0.2);
  property->SetSpecularPower(30.0);
  return actor;
}

struct Timing
{
  int Frames = 0;
  double Median = 0.0;
  double Min = 0.0;
};

/// Median and minimum of per-frame times in ms (at least one).
inline Timing Summarize(std::vector<double> ms)
{
  std::sort(ms.begin(), ms.end());
  Timing t;
  const std::size_t n = ms.size();
  t.Frames = static_cast<int>(n);
  t.Median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  t.Min = ms.front();
  return t;
}

struct Frame
{
  std::vector<unsigned char> RGB; ///< 3 bytes a pixel, row 0 at the bottom
  std::vector<float> Z;           ///< window depth
};

/// Reads the colour and depth of the frame just rendered (no re-render).
inline Frame GrabFrame(vtkRenderWindow* window, int width, int height)
{
  Frame frame;
  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(0, 0, width - 1, height - 1, /*front*/ 0, rgb, /*right*/ 0);
  frame.RGB.assign(rgb->GetPointer(0), rgb->GetPointer(0) + rgb->GetNumberOfValues());
  frame.Z.resize(static_cast<std::size_t>(width) * height);
  window->GetZbufferData(0, 0, width - 1, height - 1, frame.Z.data());
  return frame;
}

inline bool WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::fprintf(stderr, "error: could not write %s\n", path.c_str());
    return false;
  }
  return true;
}

inline bool WriteRGB(
  const std::vector<unsigned char>& rgb, int width, int height, const std::string& path)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(rgb.begin(), rgb.end(), static_cast<unsigned char*>(image->GetScalarPointer()));
  return WritePNG(image, path);
}

/// Writes values in [0, 1] (a visibility image) as an 8-bit grey PNG; NaN as black.
inline bool WriteGrey(const float* values, int width, int height, const std::string& path)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  unsigned char* bytes = static_cast<unsigned char*>(image->GetScalarPointer());
  const std::size_t n = static_cast<std::size_t>(width) * height;
  for (std::size_t p = 0; p < n; ++p)
  {
    const float v = std::isfinite(values[p]) ? std::min(1.0f, std::max(0.0f, values[p])) : 0.0f;
    bytes[p] = static_cast<unsigned char>(std::lround(255.0f * v));
  }
  return WritePNG(image, path);
}

} // namespace bench
} // namespace penumbra

#endif
