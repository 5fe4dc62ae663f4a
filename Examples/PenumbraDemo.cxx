// PenumbraDemo: a small scientific scene (an isosurface of vtkRTAnalyticSource floating over a
// ground plane, with a field of glyphs standing on it) lit by one key light, a spot light of
// radius 0.4 (an area light: soft shadows), rendered with and without vtkSoftShadowPass.
//
//   PenumbraDemo --output DIR [--width W] [--height H] [--frames N] [--truth-samples N]
//
// It writes DIR/demo_no_shadows.png and DIR/demo_shadows.png, times N orbiting frames with and
// without shadows (median and min of renderWindow->Render()), and compares the pass's light
// visibility at the final camera of the orbit with the ray-traced ground truth of
// vtkRayTracedVisibility, writing both as grey images (DIR/visibility_pass.png,
// DIR/visibility_truth.png) next to the shadowed view they belong to
// (DIR/demo_shadows_final_view.png). It ends with a short version of PenumbraBench's table
// (Benchmarks/): none, hard_volumes, averaged_16, soft_volumes_64_half (the default's 64 samples
// counted with HalfResolutionCounting) and shadowmap_1024, each timed over the same orbit (fewer
// frames once 5 s have passed) and scored at the final camera against the same truth.
// Exits 0 on success, 1 when something failed to render or to be written, 2 on a usage error.

#include "vtkRayTracedVisibility.h"
#include "vtkSoftShadowPass.h"

// Shared with PenumbraBench (header-only): error metrics and VTK's shadow maps.
#include "penumbraBenchSupport.h"
#include "penumbraMetrics.h"
#include "penumbraOptions.h"
#include "penumbraSceneDescription.h"
#include "penumbraShadowMap.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkConeSource.h"
#include "vtkContourFilter.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3D.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

using penumbra::bench::Frame;
using penumbra::bench::GrabFrame;
using penumbra::bench::Summarize;
using penumbra::bench::Timing;
using penumbra::bench::WriteGrey;
using penumbra::bench::WritePNG;
using penumbra::scene::CountTriangles;

namespace
{

struct Options
{
  std::string Output = ".";
  int Width = 1024;
  int Height = 768;
  int Frames = 30;
  int TruthSamples = 256;
};

void Usage(const char* program)
{
  std::fprintf(stderr,
    "usage: %s [--output DIR] [--width W] [--height H] [--frames N] [--truth-samples N]\n"
    "  renders the Penumbra demo scene with and without shadows into DIR (default .),\n"
    "  times N orbiting frames of each (default 1024x768, 30 frames) and compares the\n"
    "  shadow pass with ray-traced ground truth (default 256 shadow rays per pixel).\n",
    program);
}

bool ParseArguments(int argc, char* argv[], Options& options)
{
  using namespace penumbra::bench;
  return ParseOptions(argc, argv,
    { TextOption("--output", options.Output, "-o"), IntOption("--width", 16, 16384, options.Width),
      IntOption("--height", 16, 16384, options.Height),
      IntOption("--frames", 1, 16384, options.Frames),
      IntOption("--truth-samples", 1, 16384, options.TruthSamples) },
    Usage);
}

/// Renders `warmUp` frames, then `frames` timed ones, the camera orbiting one degree before each
/// so that no frame is a repeat. Each sample is Render() plus glFinish (WaitForCompletion), so
/// that work the driver queued is charged to its frame. Stops early once 3 frames are timed and
/// they took more than maxSeconds.
/// One more frame with the pass's stage times on: "depth 1.2 ms, casters ..." (wall-clock to the
/// end of each stage's GL work).
std::string StageSplit(vtkSoftShadowPass* pass, vtkRenderWindow* window)
{
  const std::vector<double> ms = penumbra::bench::TimedStages(pass, window);
  std::string split;
  for (int stage = 0; stage < vtkSoftShadowPass::NUMBER_OF_STAGES; ++stage)
  {
    char item[64];
    std::snprintf(item, sizeof(item), "%s%s %.1f ms", stage ? ", " : "",
      vtkSoftShadowPass::GetStageName(stage), ms[stage]);
    split += item;
  }
  return split;
}

Timing TimeFrames(
  vtkRenderWindow* window, vtkCamera* camera, int warmUp, int frames, double maxSeconds = 1e30)
{
  for (int i = 0; i < warmUp; ++i)
  {
    camera->Azimuth(1.0);
    window->Render();
  }
  window->WaitForCompletion();
  std::vector<double> ms;
  ms.reserve(frames);
  double total = 0.0;
  for (int i = 0; i < frames; ++i)
  {
    if (i >= 3 && total > 1000.0 * maxSeconds)
    {
      break;
    }
    camera->Azimuth(1.0);
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    const auto stop = std::chrono::steady_clock::now();
    ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    total += ms.back();
  }
  return Summarize(ms);
}

bool WriteScreenshot(vtkRenderWindow* window, const std::string& path)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  return WritePNG(grab->GetOutput(), path);
}

} // namespace

int main(int argc, char* argv[])
{
  Options options;
  if (!ParseArguments(argc, argv, options))
  {
    Usage(argv[0]);
    return 2;
  }
  const auto programStart = std::chrono::steady_clock::now();
  const std::string out = options.Output.empty() ? std::string(".") : options.Output;
  {
    std::error_code error;
    std::filesystem::create_directories(out, error);
    if (error)
    {
      std::fprintf(stderr, "error: cannot create %s: %s\n", out.c_str(), error.message().c_str());
      return EXIT_FAILURE;
    }
  }

  // --- The scene (z up). ------------------------------------------------------------------------
  // Isosurface of the analytic "wavelet" field: a blobby, closed-ish surface, open where the
  // extent clips it. Its data spans [-20, 20]^3; the actor scales it to ~3.6 units and lifts it.
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-20, 20, -20, 20, -20, 20);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, 172.0);
  contour->ComputeNormalsOn();
  contour->ComputeScalarsOff();
  contour->Update();
  vtkNew<vtkPolyDataMapper> isoMapper;
  isoMapper->SetInputConnection(contour->GetOutputPort());
  isoMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> isosurface;
  isosurface->SetMapper(isoMapper);
  isosurface->SetScale(0.09);
  isosurface->SetPosition(0.0, 0.0, 2.6);
  isosurface->RotateZ(20.0);
  isosurface->GetProperty()->SetColor(0.90, 0.55, 0.25);
  isosurface->GetProperty()->SetSpecular(0.3);
  isosurface->GetProperty()->SetSpecularPower(30.0);

  // Ground plane.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-8.0, -8.0, 0.0);
  plane->SetPoint1(8.0, -8.0, 0.0);
  plane->SetPoint2(-8.0, 8.0, 0.0);
  plane->SetResolution(1, 1);
  plane->Update();
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> ground;
  ground->SetMapper(planeMapper);
  ground->GetProperty()->SetColor(0.85, 0.85, 0.82);

  // A 7x7 grid of cones standing on the plane, one polydata.
  vtkNew<vtkPoints> sites;
  for (int i = 0; i < 7; ++i)
  {
    for (int j = 0; j < 7; ++j)
    {
      sites->InsertNextPoint(-5.4 + 1.8 * i, -5.4 + 1.8 * j, 0.35);
    }
  }
  vtkNew<vtkPolyData> siteData;
  siteData->SetPoints(sites);
  vtkNew<vtkConeSource> cone;
  cone->SetHeight(0.7);
  cone->SetRadius(0.22);
  cone->SetResolution(24);
  cone->SetDirection(0.0, 0.0, 1.0);
  cone->CappingOn();
  vtkNew<vtkGlyph3D> glyph;
  glyph->SetInputData(siteData);
  glyph->SetSourceConnection(cone->GetOutputPort());
  glyph->SetScaleModeToDataScalingOff();
  glyph->OrientOff();
  glyph->Update();
  vtkNew<vtkPolyDataMapper> glyphMapper;
  glyphMapper->SetInputConnection(glyph->GetOutputPort());
  glyphMapper->ScalarVisibilityOff();
  vtkNew<vtkActor> glyphs;
  glyphs->SetMapper(glyphMapper);
  glyphs->GetProperty()->SetColor(0.30, 0.50, 0.85);
  glyphs->GetProperty()->SetSpecular(0.2);

  for (vtkActor* actor : { isosurface.Get(), ground.Get(), glyphs.Get() })
  {
    actor->GetProperty()->SetAmbient(0.15);
    actor->GetProperty()->SetDiffuse(0.85);
  }
  const vtkIdType triangles = CountTriangles(contour->GetOutput()) +
    CountTriangles(plane->GetOutput()) + CountTriangles(glyph->GetOutput());

  // One key light from above, to the side: shadows fall across the plane. A spot light (cone
  // angle below 90 degrees, so that VTK's shadow maps can compare; 60 covers the whole ground)
  // with a radius of 0.4: an area light, soft shadows, a penumbra in the ray-traced truth.
  vtkNew<vtkLight> key;
  key->SetLightTypeToSceneLight();
  key->SetPositional(true);
  key->SetConeAngle(60.0);
  key->SetPosition(5.0, -8.7, 8.5);
  key->SetFocalPoint(0.0, 0.0, 0.0);
  key->SetIntensity(1.0);
  vtkSoftShadowPass::SetLightRadius(key, 0.4);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(ground);
  renderer->AddActor(isosurface);
  renderer->AddActor(glyphs);
  renderer->AddLight(key);
  renderer->AutomaticLightCreationOff(); // the key light alone, even at intensity 0
  renderer->SetAmbient(1.0, 1.0, 1.0);
  renderer->SetBackground(0.12, 0.14, 0.18);
  renderer->SetBackground2(0.35, 0.40, 0.48);
  renderer->GradientBackgroundOn();

  vtkCamera* camera = renderer->GetActiveCamera();
  // The timed orbit turns the camera towards the light's side; it starts where the shadows fall
  // across the view and ends (after 3 + frames degrees) still well away from the light.
  camera->SetFocalPoint(-1.2, 0.5, 1.2);
  camera->SetPosition(-6.0, -12.7, 7.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(35.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(options.Width, options.Height);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->SetWindowName("Penumbra demo");

  vtkNew<vtkSoftShadowPass> shadows; // METHOD_AUTOMATIC: the pass picks the soft method

  // --- a. Still images. ------------------------------------------------------------------------
  std::vector<std::string> written;
  bool ok = true;
  window->Render();
  if (!WriteScreenshot(window, out + "/demo_no_shadows.png"))
  {
    return EXIT_FAILURE;
  }
  written.push_back(out + "/demo_no_shadows.png");

  renderer->SetPass(shadows);
  window->Render();
  const int shadowingLights = shadows->GetNumberOfShadowingLights();
  if (shadowingLights < 1)
  {
    std::fprintf(stderr, "error: the shadow pass shadowed no light\n");
    ok = false;
  }
  if (!WriteScreenshot(window, out + "/demo_shadows.png"))
  {
    return EXIT_FAILURE;
  }
  written.push_back(out + "/demo_shadows.png");

  // --- b. Frame times, both in this run. -------------------------------------------------------
  // Both runs orbit through the same views from the same start, so their times compare. A run
  // stops early once its timed frames pass 10 s (soft shadows on a software rasterizer), and
  // then also ends at an earlier view: section c uses the shadowed run's last one.
  vtkNew<vtkCamera> start;
  start->DeepCopy(camera);
  renderer->SetPass(nullptr);
  const Timing plain = TimeFrames(window, camera, 3, options.Frames, 10.0);
  camera->DeepCopy(start);
  camera->Modified(); // DeepCopy does not (VTK 9.1): the mappers would keep stale lighting
  renderer->SetPass(shadows);
  const vtkIdType updatesBefore = shadows->GetNumberOfSilhouetteUpdates();
  const Timing shadowed = TimeFrames(window, camera, 3, options.Frames, 10.0);
  // Only the camera moves: the pass should reuse every caster's silhouette.
  const vtkIdType orbitUpdates = shadows->GetNumberOfSilhouetteUpdates() - updatesBefore;
  const vtkIdType volumeTriangles = shadows->GetNumberOfShadowVolumeTriangles();

  // --- c. Visibility against ray-traced truth at the final camera. -----------------------------
  // The last timed frame was shadowed; render once more without moving so that the z-buffer and
  // the pass's light-intensity buffer are this exact frame.
  window->Render();
  // The visibility images below are of this view, not of demo_shadows.png's: save it too.
  if (WriteScreenshot(window, out + "/demo_shadows_final_view.png"))
  {
    written.push_back(out + "/demo_shadows_final_view.png");
  }
  else
  {
    ok = false;
  }
  int lightIndex = -1;
  {
    vtkCollectionSimpleIterator it;
    renderer->GetLights()->InitTraversal(it);
    int index = 0;
    for (vtkLight* light; (light = renderer->GetLights()->GetNextLight(it)); ++index)
    {
      if (light == key.Get())
      {
        lightIndex = index;
      }
    }
  }
  vtkImageData* passVisibility = shadows->GetVisibilityImage(lightIndex);
  const int width = options.Width, height = options.Height;
  vtkNew<vtkFloatArray> zbuffer;
  window->GetZbufferData(0, 0, width - 1, height - 1, zbuffer);

  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(renderer);
  truth->SetSamplesPerLight(options.TruthSamples);
  const auto traceStart = std::chrono::steady_clock::now();
  const bool traced = truth->Update();
  const double traceMs =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - traceStart)
      .count();
  vtkImageData* truthVisibility = traced ? truth->GetVisibilityImage(lightIndex) : nullptr;
  vtkImageData* truthDepth = traced ? truth->GetDepthImage() : nullptr;

  auto sizeMatches = [&](vtkImageData* image)
  {
    int dims[3];
    image->GetDimensions(dims);
    return dims[0] == width && dims[1] == height;
  };
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  bool compared = false;
  penumbra::metrics::ErrorStats passError;
  if (!passVisibility || !truthVisibility || !truthDepth ||
    zbuffer->GetNumberOfValues() != static_cast<vtkIdType>(pixels))
  {
    std::fprintf(stderr, "error: no visibility to compare (pass %s, truth %s, z-buffer %s)\n",
      passVisibility ? "ok" : "missing", truthVisibility ? "ok" : "missing",
      zbuffer->GetNumberOfValues() ? "ok" : "missing");
    ok = false;
  }
  else if (!sizeMatches(passVisibility) || !sizeMatches(truthVisibility) ||
    !sizeMatches(truthDepth))
  {
    std::fprintf(stderr, "error: visibility images do not have the window's size\n");
    ok = false;
  }
  else
  {
    compared = true;
    // Pixels in shadow in either image, where raster and ray tracer saw the same surface.
    passError =
      penumbra::metrics::CompareVisibility(static_cast<float*>(passVisibility->GetScalarPointer()),
        static_cast<float*>(truthVisibility->GetScalarPointer()),
        static_cast<float*>(truthDepth->GetScalarPointer()), zbuffer->GetPointer(0), pixels);
    if (!WriteGrey(static_cast<float*>(passVisibility->GetScalarPointer()), width, height,
          out + "/visibility_pass.png") ||
      !WriteGrey(static_cast<float*>(truthVisibility->GetScalarPointer()), width, height,
        out + "/visibility_truth.png"))
    {
      ok = false;
    }
    else
    {
      written.push_back(out + "/visibility_pass.png");
      written.push_back(out + "/visibility_truth.png");
    }
  }

  // --- c2. Where a frame's time goes: per-stage split, soft (as above) and hard. --------------
  // The rows below are compared with the truth traced at this camera: put it back afterwards.
  vtkNew<vtkCamera> tracedView;
  tracedView->DeepCopy(camera);
  const std::string softSplit = StageSplit(shadows, window);
  const int countedLights = shadows->GetNumberOfCountedLights();
  const int averagedLights = shadows->GetNumberOfAveragedLights();
  camera->DeepCopy(start);
  camera->Modified();
  const int softMethod = shadows->GetMethod();
  shadows->SetMethodToHardVolumes();
  const Timing hard = TimeFrames(window, camera, 3, options.Frames, 10.0);
  const std::string hardSplit = StageSplit(shadows, window);
  shadows->SetMethod(softMethod);
  camera->DeepCopy(tracedView);
  camera->Modified();

  // --- d. Report. ------------------------------------------------------------------------------
  std::printf("Penumbra demo: %dx%d, %lld triangles, %d shadowing light%s (radius %.2f)\n", width,
    height, static_cast<long long>(triangles), shadowingLights, shadowingLights == 1 ? "" : "s",
    vtkSoftShadowPass::GetLightRadius(key));
  std::printf("  no shadows      median %6.1f ms  min %6.1f ms\n", plain.Median, plain.Min);
  std::printf("  shadows         median %6.1f ms  min %6.1f ms  (x%.2f; method %s: %d light%s "
              "counted, %d averaged, %d samples)\n",
    shadowed.Median, shadowed.Min, plain.Median > 0.0 ? shadowed.Median / plain.Median : 0.0,
    shadows->GetMethodAsString(), countedLights, countedLights == 1 ? "" : "s", averagedLights,
    shadows->GetLightSamples());
  std::printf("    (%d and %d orbiting frames, Render() + glFinish; %lld shadow-volume triangles "
              "per frame, %lld silhouette updates while orbiting)\n",
    plain.Frames, shadowed.Frames, static_cast<long long>(volumeTriangles),
    static_cast<long long>(orbitUpdates));
  std::printf("    stages: %s\n", softSplit.c_str());
  std::printf("  hard shadows    median %6.1f ms  min %6.1f ms  (x%.2f)\n", hard.Median, hard.Min,
    plain.Median > 0.0 ? hard.Median / plain.Median : 0.0);
  std::printf("    stages: %s\n", hardSplit.c_str());
  std::printf("    (stage times of one more frame, the pipeline drained at each stage's end: "
              "CollectStageTimes)\n");
  if (compared)
  {
    std::printf("  visibility vs ray-traced truth (%zu px in shadow): MAE %.4f  >0.1: %.2f%%  "
                ">0.5: %.2f%%\n",
      passError.Pixels, passError.MAE, 100.0 * passError.FracGt01, 100.0 * passError.FracGt05);
    std::printf("    (final camera; %zu shadow px skipped where raster and ray-traced surfaces "
                "differ; %d rays per pixel traced in %.0f ms)\n",
      passError.Skipped, options.TruthSamples, traceMs);
  }
  std::fflush(stdout);

  // --- e. A short speed-versus-error table (the full one: ./build.sh bench). -------------------
  // Each method: the error at the final camera (the view the truth above was traced for), then
  // the frame time over the same orbit as above (fewer frames once 5 s have passed). Methods with
  // a visibility image are scored on it; the others (no shadows, shadow maps) on luminance
  // against the reference A + v (D - A): A the scene with the key light at intensity 0, D lit
  // without shadows, v the ray-traced visibility.
  if (compared)
  {
    vtkNew<vtkCamera> finalView;
    finalView->DeepCopy(camera);
    const float* truthValues = static_cast<float*>(truthVisibility->GetScalarPointer());
    const float* truthZ = static_cast<float*>(truthDepth->GetScalarPointer());

    renderer->SetPass(nullptr);
    window->Render();
    const Frame lit = GrabFrame(window, width, height);
    key->SetIntensity(0.0);
    window->Render();
    const Frame ambient = GrabFrame(window, width, height);
    key->SetIntensity(1.0);

    struct ShortRow
    {
      const char* Name;
      std::function<vtkSmartPointer<vtkRenderPass>()> Make;
    };
    const ShortRow rows[] = {
      { "none", []() { return vtkSmartPointer<vtkRenderPass>(); } },
      { "hard_volumes",
        []()
        {
          auto pass = vtkSmartPointer<vtkSoftShadowPass>::New();
          pass->SetMethodToHardVolumes();
          return vtkSmartPointer<vtkRenderPass>(pass);
        } },
      { "averaged_16",
        []()
        {
          auto pass = vtkSmartPointer<vtkSoftShadowPass>::New();
          pass->SetMethodToAveragedHardShadows();
          pass->SetLightSamples(16);
          return vtkSmartPointer<vtkRenderPass>(pass);
        } },
      { "soft_volumes_64_half",
        []()
        {
          auto pass = vtkSmartPointer<vtkSoftShadowPass>::New();
          pass->SetMethodToSoftShadowVolumes();
          pass->SetLightSamples(64);
          pass->HalfResolutionCountingOn();
          return vtkSmartPointer<vtkRenderPass>(pass);
        } },
      { "shadowmap_1024", []() { return penumbra::bench::MakeShadowMapPass(1024); } },
    };
    std::printf("  speed vs error (the full benchmark: ./build.sh bench):\n");
    std::printf("    %-21s %10s %7s %8s %7s  %s\n", "method", "median ms", "x none", "MAE", ">0.1",
      "error on");
    for (const ShortRow& row : rows)
    {
      vtkSmartPointer<vtkRenderPass> pass = row.Make();
      renderer->SetPass(pass);
      camera->DeepCopy(finalView);
      camera->Modified();
      window->Render();
      window->Render();
      const Frame image = GrabFrame(window, width, height);
      penumbra::metrics::ErrorStats error;
      bool onVisibility = false;
      if (auto* soft = vtkSoftShadowPass::SafeDownCast(pass))
      {
        vtkImageData* visibility = soft->GetVisibilityImage(lightIndex);
        if (visibility && sizeMatches(visibility))
        {
          error = penumbra::metrics::CompareVisibility(
            static_cast<float*>(visibility->GetScalarPointer()), truthValues, truthZ,
            image.Z.data(), pixels);
          onVisibility = true;
        }
        else
        {
          std::fprintf(stderr, "error: %s gave no visibility image\n", row.Name);
          ok = false;
        }
      }
      else
      {
        error = penumbra::metrics::CompareLuminance(image.RGB.data(), lit.RGB.data(),
          ambient.RGB.data(), 3, truthValues, truthZ, image.Z.data(), pixels);
      }
      Timing timing = plain; // `none` was timed above, over the same orbit
      if (pass)
      {
        camera->DeepCopy(start);
        camera->Modified();
        timing = TimeFrames(window, camera, 1, options.Frames, 5.0);
      }
      std::printf("    %-21s %10.1f %7.2f %8.4f %6.2f%%  %s\n", row.Name, timing.Median,
        plain.Median > 0.0 ? timing.Median / plain.Median : 0.0, error.MAE, 100.0 * error.FracGt01,
        onVisibility ? "visibility" : "luminance");
      std::fflush(stdout);
      renderer->SetPass(nullptr);
      if (pass)
      {
        pass->ReleaseGraphicsResources(window);
      }
    }
    std::printf(
      "    (luminance errors are scaled by the light's share of each pixel and read lower "
      "than visibility errors of the same shadow)\n");
  }

  std::printf("wrote:\n");
  for (const std::string& path : written)
  {
    std::printf("  %s\n", path.c_str());
  }
  std::printf("total %.1f s\n",
    std::chrono::duration<double>(std::chrono::steady_clock::now() - programStart).count());

  renderer->SetPass(nullptr);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
