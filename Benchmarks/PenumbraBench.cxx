// PenumbraBench: speed versus error of every shadowing method on a fixed set of scenes.
//
//   PenumbraBench [--output DIR] [--width W --height H] [--frames N] [--scenes a,b,...]
//                 [--methods a,b,...] [--radii r1,r2,...] [--truth-samples N]
//                 [--max-seconds S] [--azimuth-step DEG] [--images classic|all|none]
//                 [--no-noise-check] [--no-plot] [--quick]
//
// For every scene and light radius it ray-traces the true light visibility (vtkRayTracedVisibility)
// once, then renders the scene with each method: the error at the starting camera (against the
// truth's visibility, or for methods without a visibility image against a reference image shaded
// with it), then the frame time over an orbit. All methods are timed in this one run, in one
// window, one after the other. It writes
//   DIR/results.csv            the table (columns below), one row per scene and method
//   DIR/results_luminance.csv  the same with every method's error measured on luminance
//   DIR/results_ground.csv     the visibility methods' error on the ground plane's pixels only
//                              (where the planar methods, plateaus, shadow)
//   DIR/truth.csv              per scene: truth samples, trace time and the truth's own noise
//   DIR/stages.csv             per scene and pass method: one frame's time in each stage of the
//                              pass (CollectStageTimes: the pipeline drained at each stage's end)
//   DIR/README.md              what the columns mean, which rows use which error
//   DIR/<scene>_<method>.png   still images (for the scenes --images selects)
//   DIR/speed_vs_error.png     the plot (plot_results.py), when /usr/bin/python3 has matplotlib
// and prints a table with the frame times' ratios to `none`.
//
// Exits 0 on success, 1 when a render, the truth or a file failed, 2 on a usage error.

#include "penumbraBenchSupport.h"
#include "penumbraMetrics.h"
#include "penumbraOptions.h"
#include "penumbraSceneDescription.h"
#include "penumbraShadowMap.h"

#include "vtkPlanarSoftShadowFilter.h"
#include "vtkRayTracedVisibility.h"
#include "vtkSoftShadowPass.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkAppendPolyData.h"
#include "vtkArrowSource.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellLocator.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkGenericCell.h"
#include "vtkGlyph3D.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
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
#include "vtkSphereSource.h"
#include "vtkStreamTracer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTubeFilter.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#ifndef PENUMBRA_BENCH_DEFAULT_OUTPUT
#define PENUMBRA_BENCH_DEFAULT_OUTPUT "bench"
#endif
#ifndef PENUMBRA_BENCH_PLOT_SCRIPT
#define PENUMBRA_BENCH_PLOT_SCRIPT "plot_results.py"
#endif

namespace
{
using penumbra::bench::Clock;
using penumbra::bench::Frame;
using penumbra::bench::GrabFrame;
using penumbra::bench::ParseDouble;
using penumbra::bench::ParseInt;
using penumbra::bench::SecondsSince;
using penumbra::bench::SplitList;
using penumbra::bench::Summarize;
using penumbra::bench::Timing;
using penumbra::bench::WriteGrey;
using penumbra::bench::WritePNG;
using penumbra::bench::WriteRGB;
using penumbra::metrics::ErrorStats;

//--------------------------------------------------------------------------------------------------
// Options
//--------------------------------------------------------------------------------------------------
struct Options
{
  std::string Output = PENUMBRA_BENCH_DEFAULT_OUTPUT;
  int Width = 1024;
  int Height = 768;
  int Frames = 20;
  int WarmUp = 3;
  double WarmUpSeconds = 3.0; // warm-up stops early past this (at least 1 warm-up frame)
  double AzimuthStep = 0.5;   // degrees per frame
  double MaxSeconds = 10.0;   // per method's timed frames; at least 3 frames are always timed
  int TruthSamples = 256;
  bool NoiseCheck = true; // a second truth with another seed: the truth's own noise
  bool Plot = true;
  std::string Images = "classic"; // scenes whose still images are written: classic, all, none
  std::vector<std::string> Scenes = { "classic", "isosurface", "glyphs", "large" };
  std::vector<std::string> Methods; // empty: all
  std::vector<double> Radii = { 0.2, 1.0 };
  bool Quick = false;
  bool SizeGiven = false, FramesGiven = false, TruthGiven = false, MaxGiven = false;
};

void Usage(const char* program)
{
  std::fprintf(stderr,
    "usage: %s [options]\n"
    "  --output DIR          results directory (default %s)\n"
    "  --width W --height H  window size (default 1024x768)\n"
    "  --frames N            timed frames per method (default 20), after up to 3 warm-up\n"
    "                        frames (none once 3 s have been spent warming up, the renders\n"
    "                        the error is measured on included)\n"
    "  --max-seconds S       stop a method's timing once its timed frames pass S seconds\n"
    "                        (default 10; at least 1 frame; the frames column says how many)\n"
    "  --azimuth-step DEG    degrees the camera orbits before each warm-up and timed frame\n"
    "                        (default 0.5); 0 keeps it still, so that the pass composites\n"
    "                        the shadows it drew last (ReuseUnchangedShadows) wherever\n"
    "                        nothing else changes\n"
    "  --scenes a,b,...      among classic,isosurface,glyphs,large (default all of these)\n"
    "                        and streamtubes (open stream tubes), timevarying (a 241k-\n"
    "                        triangle isosurface whose data changes every frame); not in\n"
    "                        the default\n"
    "  --methods a,b,...     among none,shadowmap_1024,shadowmap_4096,hard_volumes,\n"
    "                        averaged_4,averaged_16,averaged_64,averaged_256,wedges,\n"
    "                        plateaus, planar_filter_16, planar_filter_64,\n"
    "                        soft_volumes_16, soft_volumes_64 (counting), automatic_64\n"
    "                        (default all of these);\n"
    "                        also soft_volumes_16_half, soft_volumes_64_half: counted at\n"
    "                        half resolution (HalfResolutionCounting); automatic_16;\n"
    "                        also shadowmap_1024_vtkaspect, shadowmap_4096_vtkaspect: VTK's\n"
    "                        shadow maps without the benchmark's square-bake fix;\n"
    "                        hard_volumes_vtkdepth, averaged_16_vtkdepth: with VTK drawing\n"
    "                        every prop's depth (DepthFromCasterMeshes off)\n"
    "  --radii r1,r2,...     light radii in world units (default 0.2,1); the scenes are ~10\n"
    "                        units across, the light ~12 units from their centre\n"
    "  --truth-samples N     shadow rays per pixel of the ray-traced truth (default 256)\n"
    "  --images WHICH        still images of: classic (default), all or none of the scenes\n"
    "  --no-noise-check      skip the second truth (other seed) that measures the truth's noise\n"
    "  --no-plot             do not run plot_results.py at the end\n"
    "  --quick               smoke test: 320x240, 3 frames, 1 warm-up, 64 truth samples,\n"
    "                        5 s timing cap, no averaged_256 unless --methods names it\n",
    program, PENUMBRA_BENCH_DEFAULT_OUTPUT);
}

bool ParseArguments(int argc, char* argv[], Options& options)
{
  using namespace penumbra::bench;
  const std::vector<Option> table = { FlagOption("--quick", [&] { options.Quick = true; }),
    FlagOption("--no-plot", [&] { options.Plot = false; }),
    FlagOption("--no-noise-check", [&] { options.NoiseCheck = false; }),
    TextOption("--output", options.Output, "-o"),
    IntOption("--width", 16, 8192, options.Width, &options.SizeGiven),
    IntOption("--height", 16, 8192, options.Height, &options.SizeGiven),
    IntOption("--frames", 1, 100000, options.Frames, &options.FramesGiven),
    DoubleOption("--max-seconds", 0.0, options.MaxSeconds, &options.MaxGiven),
    DoubleOption("--azimuth-step", 0.0, options.AzimuthStep),
    IntOption("--truth-samples", 1, 65536, options.TruthSamples, &options.TruthGiven),
    ListOption("--scenes", options.Scenes), ListOption("--methods", options.Methods),
    ValueOption("--radii",
      [&](const char* value)
      {
        options.Radii.clear();
        bool ok = true;
        for (const std::string& item : SplitList(value))
        {
          double r = 0.0;
          ok = ok && ParseDouble(item.c_str(), 0.0, r);
          options.Radii.push_back(r);
        }
        return ok && !options.Radii.empty();
      }),
    ValueOption("--images",
      [&](const char* value)
      {
        options.Images = value;
        return options.Images == "classic" || options.Images == "all" || options.Images == "none";
      }) };
  if (!ParseOptions(argc, argv, table, Usage))
  {
    return false;
  }
  if (options.Quick)
  {
    if (!options.SizeGiven)
    {
      options.Width = 320;
      options.Height = 240;
    }
    if (!options.FramesGiven)
    {
      options.Frames = 3;
    }
    if (!options.TruthGiven)
    {
      options.TruthSamples = 64;
    }
    if (!options.MaxGiven)
    {
      options.MaxSeconds = 5.0;
    }
    options.WarmUp = 1;
  }
  return true;
}

//--------------------------------------------------------------------------------------------------
// Scenes. All share one frame (z up): a 14 x 14 ground plane at z = 0 centred on the origin, the
// casters within ~8 units of it and up to ~4 units high, one spot light ~12.5 units from the
// centre (cone 55 degrees, covering the whole ground), one camera orbiting around (0, 0, 1).
//--------------------------------------------------------------------------------------------------

using Scene = penumbra::scene::Description;

vtkSmartPointer<vtkActor> MakeActor(vtkAlgorithm* source, double r, double g, double b)
{
  return penumbra::bench::MakeShadedActor(penumbra::bench::DetachedOutput(source), r, g, b);
}

void AddGround(Scene& scene)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-7.0, -7.0, 0.0);
  plane->SetPoint1(7.0, -7.0, 0.0);
  plane->SetPoint2(-7.0, 7.0, 0.0);
  plane->SetResolution(1, 1);
  auto ground = MakeActor(plane, 0.85, 0.85, 0.82);
  ground->GetProperty()->SetSpecular(0.0);
  // The receiver plane of the planar methods (plateaus); other methods ignore the mark.
  vtkSoftShadowPass::SetShadowPlane(ground, true);
  scene.Add(ground);
}

/// Spheres and boxes on the ground plane, one of the spheres floating.
Scene MakeClassic()
{
  Scene scene;
  scene.Name = "classic";
  AddGround(scene);
  struct Ball
  {
    double X, Y, Z, R;
    double Colour[3];
  };
  for (const Ball& b : { Ball{ -2.2, 1.2, 1.1, 1.1, { 0.85, 0.30, 0.25 } },
         Ball{ 1.6, 2.2, 2.6, 0.7, { 0.30, 0.55, 0.85 } },
         Ball{ 2.8, -1.8, 0.55, 0.55, { 0.35, 0.75, 0.40 } } })
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(b.X, b.Y, b.Z);
    sphere->SetRadius(b.R);
    sphere->SetThetaResolution(64);
    sphere->SetPhiResolution(32);
    scene.Add(MakeActor(sphere, b.Colour[0], b.Colour[1], b.Colour[2]));
  }
  struct Box
  {
    double X, Y, Sx, Sy, Sz, Angle;
    double Colour[3];
  };
  for (const Box& b : { Box{ 0.2, -0.8, 1.5, 1.5, 1.5, 30.0, { 0.90, 0.75, 0.30 } },
         Box{ -3.4, -2.2, 0.6, 0.6, 3.2, 10.0, { 0.70, 0.45, 0.80 } },
         Box{ 3.0, 1.6, 2.0, 0.8, 0.9, -20.0, { 0.45, 0.75, 0.75 } } })
  {
    vtkNew<vtkCubeSource> cube;
    cube->SetXLength(b.Sx);
    cube->SetYLength(b.Sy);
    cube->SetZLength(b.Sz);
    auto actor = MakeActor(cube, b.Colour[0], b.Colour[1], b.Colour[2]);
    actor->SetPosition(b.X, b.Y, 0.5 * b.Sz);
    actor->RotateZ(b.Angle);
    scene.Add(actor);
  }
  return scene;
}

/// A `Contour` filter (vtkContourFilter, vtkFlyingEdges3D) of the value 160 over a
/// vtkRTAnalyticSource of half extent `half`, with normals and no scalars.
template <typename Contour>
vtkSmartPointer<Contour> WaveletIsosurface(int half)
{
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-half, half, -half, half, -half, half);
  auto contour = vtkSmartPointer<Contour>::New();
  contour->SetInputConnection(wavelet->GetOutputPort());
  contour->SetValue(0, 160.0); // open where the extent clips it: ~600 boundary edges at 20
  contour->ComputeNormalsOn();
  contour->ComputeScalarsOff();
  return contour;
}

/// An isosurface of vtkRTAnalyticSource, open where the extent clips it, floating over the plane.
Scene MakeIsosurface()
{
  Scene scene;
  scene.Name = "isosurface";
  AddGround(scene);
  auto actor = MakeActor(WaveletIsosurface<vtkContourFilter>(20), 0.90, 0.55, 0.25);
  actor->SetScale(0.1);
  actor->SetPosition(0.0, 0.0, 2.4);
  actor->RotateZ(20.0);
  scene.Add(actor);
  return scene;
}

/// 400 arrows (one vtkGlyph3D actor) following a swirling field over the plane.
Scene MakeGlyphs()
{
  Scene scene;
  scene.Name = "glyphs";
  AddGround(scene);
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> vectors;
  vectors->SetNumberOfComponents(3);
  vectors->SetName("field");
  const int n = 20;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const double x = -5.0 + 10.0 * i / (n - 1), y = -5.0 + 10.0 * j / (n - 1);
      const double z = 0.8 + 0.5 * std::sin(0.7 * x) * std::cos(0.6 * y);
      points->InsertNextPoint(x, y, z);
      const double v[3] = { -y + 0.3 * x, x + 0.3 * y, 2.0 + 0.5 * std::sin(x + y) };
      vectors->InsertNextTuple(v);
    }
  }
  vtkNew<vtkPolyData> sites;
  sites->SetPoints(points);
  sites->GetPointData()->SetVectors(vectors);
  vtkNew<vtkArrowSource> arrow;
  arrow->SetTipResolution(12);
  arrow->SetShaftResolution(12);
  arrow->SetShaftRadius(0.06);
  arrow->SetTipRadius(0.15);
  vtkNew<vtkGlyph3D> glyph;
  glyph->SetInputData(sites);
  glyph->SetSourceConnection(arrow->GetOutputPort());
  glyph->SetVectorModeToUseVector();
  glyph->SetScaleModeToDataScalingOff();
  glyph->SetScaleFactor(0.9);
  glyph->OrientOn();
  scene.Add(MakeActor(glyph, 0.30, 0.50, 0.85));
  return scene;
}

/// A tilted torus of 1,000,000 triangles over the plane: triangle throughput and self-shadowing.
Scene MakeLarge()
{
  Scene scene;
  scene.Name = "large";
  AddGround(scene);
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(2.4);
  torus->SetCrossSectionRadius(0.8);
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(torus);
  source->SetUResolution(1000);
  source->SetVResolution(500);
  source->GenerateTextureCoordinatesOff();
  source->SetScalarModeToNone();
  auto actor = MakeActor(source, 0.75, 0.75, 0.80);
  actor->RotateX(35.0);
  actor->SetPosition(0.0, 0.0, 2.6);
  scene.Add(actor);
  return scene;
}

/// Stream tubes through a swirling field over the plane: long, thin, open (uncapped) tubes, the
/// everyday flow-visualization caster; every triangle of an open mesh casts.
Scene MakeStreamTubes()
{
  Scene scene;
  scene.Name = "streamtubes";
  AddGround(scene);
  vtkNew<vtkImageData> field;
  field->SetDimensions(33, 33, 13);
  field->SetOrigin(-4.0, -4.0, 0.4);
  field->SetSpacing(0.25, 0.25, 0.25);
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < field->GetNumberOfPoints(); ++i)
  {
    double p[3];
    field->GetPoint(i, p);
    velocity->InsertNextTuple3(-p[1] + 0.2 * p[0], p[0] + 0.2 * p[1], 0.4 * std::sin(p[0] + p[1]));
  }
  field->GetPointData()->SetVectors(velocity);
  vtkNew<vtkPoints> seedPoints;
  for (int i = 0; i < 24; ++i)
  {
    seedPoints->InsertNextPoint(0.4 + 3.2 * i / 23.0, 0.0, 1.0 + 1.6 * (i % 6) / 5.0);
  }
  vtkNew<vtkPolyData> seeds;
  seeds->SetPoints(seedPoints);
  vtkNew<vtkStreamTracer> tracer;
  tracer->SetInputData(field);
  tracer->SetSourceData(seeds);
  tracer->SetIntegrationDirectionToBoth();
  tracer->SetMaximumPropagation(30.0);
  tracer->SetInitialIntegrationStep(0.2);
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputConnection(tracer->GetOutputPort());
  tubes->SetRadius(0.06);
  tubes->SetNumberOfSides(10);
  tubes->CappingOff();
  scene.Add(MakeActor(tubes, 0.35, 0.70, 0.55));
  return scene;
}

/// A simulation played back (as Benchmarks/time_varying.py): a vtkFlyingEdges3D isosurface of
/// a fine vtkRTAnalyticSource, about 241,000 triangles, open where the extent clips it, whose
/// value changes every frame, so that every frame brings new data; frame 0 is the data as built,
/// at which the truth and the errors are taken.
Scene MakeTimeVarying()
{
  Scene scene;
  scene.Name = "timevarying";
  AddGround(scene);
  auto contour = WaveletIsosurface<vtkFlyingEdges3D>(60);
  contour->Update();
  // The mapper draws the filter's own output, which each update rewrites in place.
  auto actor = penumbra::bench::MakeShadedActor(contour->GetOutput(), 0.90, 0.55, 0.25);
  actor->SetScale(0.1 / 3.0);
  actor->SetPosition(0.0, 0.0, 2.4);
  actor->RotateZ(20.0);
  scene.Add(actor);
  scene.Advance = [contour](int frame)
  {
    contour->SetValue(0, 160.0 + 6.0 * std::sin(0.9 * frame));
    contour->Update();
  };
  return scene;
}

/// The frame every scene shares: the key light, a spot (cone < 90 degrees, so that
/// vtkShadowMapBakerPass accepts it) aimed at the scene, light index 0, its radius set per row;
/// and the camera's start.
void AddKeyLightAndCamera(Scene& scene)
{
  vtkLight* key = scene.AddLight(true, { 4.0, -6.0, 10.0 }, 0.0);
  key->SetConeAngle(55.0);
  key->SetExponent(1.0);
  key->SetIntensity(1.0);
  scene.SetCamera({ -6.5, -13.0, 7.5 }, { 0.0, 0.0, 1.0 }, { 0.0, 0.0, 1.0 }, 35.0);
}

bool MakeScene(const std::string& name, Scene& scene)
{
  if (name == "classic")
    scene = MakeClassic();
  else if (name == "isosurface")
    scene = MakeIsosurface();
  else if (name == "glyphs")
    scene = MakeGlyphs();
  else if (name == "large")
    scene = MakeLarge();
  else if (name == "streamtubes")
    scene = MakeStreamTubes();
  else if (name == "timevarying")
    scene = MakeTimeVarying();
  else
    return false;
  AddKeyLightAndCamera(scene);
  return true;
}

//--------------------------------------------------------------------------------------------------
// Methods. Each entry makes a fresh render pass (nullptr: VTK's own rendering) and, for methods
// that expose it, a way to read light 0's visibility back; rows of methods without it are scored
// on luminance against the reference image. New methods (penumbra wedges, ...) are one more entry.
//--------------------------------------------------------------------------------------------------
struct MethodInstance
{
  vtkSmartPointer<vtkRenderPass> Pass;        ///< installed with renderer->SetPass
  std::function<vtkImageData*()> Visibility;  ///< empty: scored on luminance
  std::function<long long()> ShadowTriangles; ///< empty: not applicable
  std::function<long long()> Wedges;          ///< empty: not applicable
  /// Scene changes the method makes (a decal actor) and takes back; empty: none.
  std::function<void(vtkRenderer*)> Attach, Detach;
};

/// What the planar filter's visibility needs from the loop: the ground's pixels, and where they
/// are on the ground, found where the truth was traced (later renders may move the clipping
/// planes, and with them what a window depth means).
struct GroundView
{
  std::vector<std::size_t> Pixels;
  std::vector<std::array<double, 2>> Points; ///< world (x, y) of each, z = 0
};
GroundView CurrentGround;

struct MethodSpec
{
  std::string Name;
  std::function<MethodInstance()> Make;
  bool Default = true; ///< run unless --methods names others
};

MethodInstance MakeShadowMap(int resolution, bool squareBake)
{
  // penumbraShadowMap.h: as VTK's TestShadowMapPass, baked at aspect 1 unless squareBake is
  // false (the `_vtkaspect` methods: VTK 9.1 as it is, shadows misplaced in non-square windows).
  MethodInstance instance;
  instance.Pass = penumbra::bench::MakeShadowMapPass(resolution, squareBake);
  return instance;
}

MethodInstance MakeSoftShadow(int method, int samples)
{
  auto pass = vtkSmartPointer<vtkSoftShadowPass>::New();
  pass->SetMethod(method);
  pass->SetLightSamples(samples);
  MethodInstance instance;
  instance.Pass = pass;
  vtkSoftShadowPass* raw = pass;
  instance.Visibility = [raw]() { return raw->GetVisibilityImage(0); };
  instance.ShadowTriangles = [raw]()
  { return static_cast<long long>(raw->GetNumberOfShadowVolumeTriangles()); };
  instance.Wedges = [raw]() { return static_cast<long long>(raw->GetNumberOfPenumbraWedges()); };
  return instance;
}

/**
 * vtkPlanarSoftShadowFilter with `samples` light samples: the casters' soft shadow on the ground
 * (z = 0) as triangles, drawn as a translucent black decal over the ground, which then takes no
 * shadow from the pass; every other surface gets the pass's hard shadows. Its visibility is the
 * filter's LightIntensity at the ground's pixels and the hard shadow elsewhere. The filter runs
 * when the method is attached (light and casters stand still while the camera orbits); its time
 * is printed.
 */
MethodInstance MakePlanarFilter(int samples)
{
  MethodInstance instance = MakeSoftShadow(vtkSoftShadowPass::METHOD_HARD_VOLUMES, 1);
  auto pass = vtkSoftShadowPass::SafeDownCast(instance.Pass);
  auto filter = vtkSmartPointer<vtkPlanarSoftShadowFilter>::New();
  auto decal = vtkSmartPointer<vtkActor>::New();
  auto ground = std::make_shared<vtkSmartPointer<vtkActor>>();
  auto image = vtkSmartPointer<vtkImageData>::New();
  instance.Attach = [=](vtkRenderer* renderer)
  {
    vtkNew<vtkAppendPolyData> casters;
    vtkActorCollection* actors = renderer->GetActors();
    vtkCollectionSimpleIterator it;
    vtkActor* actor;
    for (actors->InitTraversal(it); (actor = actors->GetNextActor(it));)
    {
      if (vtkSoftShadowPass::GetShadowPlane(actor))
      {
        *ground = actor;
        continue;
      }
      vtkNew<vtkTransform> toWorld;
      toWorld->SetMatrix(actor->GetMatrix());
      vtkNew<vtkTransformPolyDataFilter> place;
      place->SetTransform(toWorld);
      place->SetInputData(vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0)));
      place->Update();
      casters->AddInputData(place->GetOutput());
    }
    vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
    filter->SetInputConnection(casters->GetOutputPort());
    filter->SetLightPosition(light->GetPosition());
    filter->SetPositional(light->GetPositional());
    filter->SetLightRadius(vtkSoftShadowPass::GetLightRadius(light));
    filter->SetLightSamples(samples);
    filter->SetPlaneOrigin(0, 0, 0);
    filter->SetPlaneNormal(0, 0, 1);
    filter->SetOffset(1e-3);
    const auto start = Clock::now();
    filter->Update();
    std::printf("  (planar_filter_%d: filter update %.1f ms, %lld triangles)\n", samples,
      1000.0 * SecondsSince(start),
      static_cast<long long>(filter->GetOutput()->GetNumberOfCells()));
    // Black with alpha (1 - intensity): the ground darkened as far as the light is hidden.
    vtkNew<vtkLookupTable> shade;
    shade->SetTableRange(0.0, 1.0);
    shade->SetHueRange(0.0, 0.0);
    shade->SetSaturationRange(0.0, 0.0);
    shade->SetValueRange(0.0, 0.0);
    shade->SetAlphaRange(0.8, 0.0);
    shade->Build();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(filter->GetOutputPort());
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray("LightIntensity");
    mapper->SetLookupTable(shade);
    mapper->SetScalarRange(0.0, 1.0);
    mapper->SetColorModeToMapScalars();
    decal->SetMapper(mapper);
    decal->GetProperty()->SetLighting(false);
    decal->ForceTranslucentOn();
    vtkSoftShadowPass::SetCastsShadows(decal, false);
    renderer->AddActor(decal);
    if (*ground)
    {
      vtkSoftShadowPass::SetReceivesShadows(*ground, false);
    }
  };
  instance.Detach = [=](vtkRenderer* renderer)
  {
    renderer->RemoveActor(decal);
    if (*ground)
    {
      vtkSoftShadowPass::SetReceivesShadows(*ground, true);
    }
  };
  vtkSoftShadowPass* raw = pass;
  instance.Visibility = [=]() -> vtkImageData*
  {
    vtkImageData* hard = raw->GetVisibilityImage(0);
    const GroundView& view = CurrentGround;
    if (!hard)
    {
      return hard;
    }
    image->DeepCopy(hard);
    auto values = static_cast<float*>(image->GetScalarPointer());
    // The ground's pixels as points on the decal's plane, located in the filter's triangles.
    vtkPolyData* shadow = filter->GetOutput();
    vtkDataArray* intensity = shadow->GetPointData()->GetArray("LightIntensity");
    vtkNew<vtkCellLocator> locator;
    locator->SetDataSet(shadow);
    locator->BuildLocator();
    vtkNew<vtkGenericCell> cell;
    for (std::size_t i = 0; i < view.Pixels.size(); ++i)
    {
      double point[3] = { view.Points[i][0], view.Points[i][1], filter->GetOffset() };
      double pcoords[3], weights[3];
      const vtkIdType id = intensity ? locator->FindCell(point, 1e-12, cell, pcoords, weights) : -1;
      double v = 1.0; // outside the filter's triangles the ground is lit
      if (id >= 0)
      {
        v = 0.0;
        for (vtkIdType k = 0; k < cell->GetNumberOfPoints() && k < 3; ++k)
        {
          v += weights[k] * intensity->GetTuple1(cell->GetPointId(k));
        }
      }
      values[view.Pixels[i]] = static_cast<float>(v);
    }
    return image;
  };
  return instance;
}

std::vector<MethodSpec> AllMethods()
{
  std::vector<MethodSpec> methods;
  methods.push_back({ "none", []() { return MethodInstance{}; } });
  for (int resolution : { 1024, 4096 })
  {
    methods.push_back({ "shadowmap_" + std::to_string(resolution),
      [resolution]() { return MakeShadowMap(resolution, true); } });
  }
  methods.push_back(
    { "hard_volumes", []() { return MakeSoftShadow(vtkSoftShadowPass::METHOD_HARD_VOLUMES, 1); } });
  for (int samples : { 4, 16, 64, 256 })
  {
    methods.push_back({ "averaged_" + std::to_string(samples),
      [samples]()
      { return MakeSoftShadow(vtkSoftShadowPass::METHOD_AVERAGED_HARD_SHADOWS, samples); } });
  }
  // VTK 9.1's shadow maps exactly as they come, aspect bug included (only with --methods).
  for (int resolution : { 1024, 4096 })
  {
    methods.push_back({ "shadowmap_" + std::to_string(resolution) + "_vtkaspect",
      [resolution]() { return MakeShadowMap(resolution, false); }, false });
  }
  // Hard and averaged shadows with VTK drawing every prop's depth (DepthFromCasterMeshes off),
  // the pass's depth before 2026-12-04 (only with --methods).
  for (int samples : { 1, 16 })
  {
    methods.push_back({ samples == 1 ? "hard_volumes_vtkdepth" : "averaged_16_vtkdepth",
      [samples]()
      {
        MethodInstance instance =
          MakeSoftShadow(samples == 1 ? vtkSoftShadowPass::METHOD_HARD_VOLUMES
                                      : vtkSoftShadowPass::METHOD_AVERAGED_HARD_SHADOWS,
            samples);
        vtkSoftShadowPass::SafeDownCast(instance.Pass)->DepthFromCasterMeshesOff();
        return instance;
      },
      false });
  }
  // Penumbra wedges: the hard shadow of the light's centre plus one wedge per silhouette edge.
  methods.push_back(
    { "wedges", []() { return MakeSoftShadow(vtkSoftShadowPass::METHOD_PENUMBRA_WEDGES, 1); } });
  // Soft shadow volumes: per-sample counting, the averaged method's answer for the same samples.
  for (int samples : { 16, 64 })
  {
    methods.push_back({ "soft_volumes_" + std::to_string(samples),
      [samples]()
      { return MakeSoftShadow(vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES, samples); } });
  }
  // The same, counted at half resolution (HalfResolutionCounting).
  for (int samples : { 16, 64 })
  {
    methods.push_back({ "soft_volumes_" + std::to_string(samples) + "_half",
      [samples]()
      {
        MethodInstance instance =
          MakeSoftShadow(vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES, samples);
        vtkSoftShadowPass::SafeDownCast(instance.Pass)->HalfResolutionCountingOn();
        return instance;
      } });
  }
  // The default: counting or averaging 64 samples, whichever the cost model expects faster.
  methods.push_back(
    { "automatic_64", []() { return MakeSoftShadow(vtkSoftShadowPass::METHOD_AUTOMATIC, 64); } });
  // The same choice for 16 samples (only with --methods).
  methods.push_back({ "automatic_16",
    []() { return MakeSoftShadow(vtkSoftShadowPass::METHOD_AUTOMATIC, 16); }, false });
  // Haines' plateaus on the ground plane; hard shadows of the light's centre elsewhere.
  methods.push_back(
    { "plateaus", []() { return MakeSoftShadow(vtkSoftShadowPass::METHOD_PLATEAUS, 1); } });
  // The triangulated geometric soft shadow on the ground (vtkPlanarSoftShadowFilter).
  for (int samples : { 16, 64 })
  {
    methods.push_back({ "planar_filter_" + std::to_string(samples),
      [samples]() { return MakePlanarFilter(samples); } });
  }
  return methods;
}

//--------------------------------------------------------------------------------------------------
// Frame grabs and images.
//--------------------------------------------------------------------------------------------------
//--------------------------------------------------------------------------------------------------
// Timing.
//--------------------------------------------------------------------------------------------------
/// Up to WarmUp orbiting warm-up frames, none once WarmUpSeconds of warming up (counting the
/// `warmSeconds` already spent rendering at the starting camera) have passed; then up to Frames
/// timed ones, fewer once MaxSeconds have passed (at least 1), the camera orbiting `step` degrees
/// before each so that no frame repeats the previous one. Each sample is Render() plus glFinish
/// (WaitForCompletion). With `advance` (a scene whose data changes), warm-up frame i shows data
/// frame i + 1 and timed frame i data frame WarmUp + 1 + i, its update inside the frame's time,
/// so that every method is timed on the same data however many warm-up frames it skipped.
Timing TimeFrames(vtkRenderWindow* window, vtkRenderer* renderer, const Options& options,
  double warmSeconds, const std::function<void(int)>& advance)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  auto showData = [&](int frame)
  {
    if (advance)
    {
      advance(frame);
    }
  };
  const auto warmUpStart = Clock::now();
  for (int i = 0; i < options.WarmUp; ++i)
  {
    if (warmSeconds + SecondsSince(warmUpStart) > options.WarmUpSeconds)
    {
      break;
    }
    camera->Azimuth(options.AzimuthStep);
    renderer->ResetCameraClippingRange();
    showData(i + 1);
    window->Render();
  }
  window->WaitForCompletion();
  std::vector<double> ms;
  const auto begin = Clock::now();
  for (int i = 0; i < options.Frames; ++i)
  {
    if (i >= 1 && SecondsSince(begin) > options.MaxSeconds)
    {
      break;
    }
    camera->Azimuth(options.AzimuthStep);
    renderer->ResetCameraClippingRange();
    const auto start = Clock::now();
    showData(options.WarmUp + 1 + i); // an application updates its data before rendering
    window->Render();
    window->WaitForCompletion();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  return Summarize(ms);
}

//--------------------------------------------------------------------------------------------------
// Results.
//--------------------------------------------------------------------------------------------------
struct Row
{
  std::string Scene, Method;
  int Width = 0, Height = 0;
  long long Triangles = 0;
  Timing Time;
  ErrorStats Error;     ///< the error results.csv reports
  ErrorStats Luminance; ///< every method on luminance (results_luminance.csv)
  ErrorStats Ground;    ///< visibility on the ground's pixels only (results_ground.csv)
  bool VisibilityMetric = false;
  long long ShadowTriangles = -1;
  long long Wedges = -1;
};

const char* CsvHeader =
  "scene,method,width,height,triangles,frames,ms_median,ms_min,mae,rmse,p99,max,"
  "frac_gt_0.1,frac_gt_0.5";

void WriteCsvRow(std::FILE* file, const Row& row, const ErrorStats& e)
{
  std::fprintf(file, "%s,%s,%d,%d,%lld,%d,%.3f,%.3f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n",
    row.Scene.c_str(), row.Method.c_str(), row.Width, row.Height, row.Triangles, row.Time.Frames,
    row.Time.Median, row.Time.Min, e.MAE, e.RMSE, e.P99, e.Max, e.FracGt01, e.FracGt05);
  std::fflush(file);
}

/// One more frame with the pass's stage times on (the pipeline drained at each stage's end):
/// printed under the row and written to stages.csv.
void WriteStageSplit(
  std::FILE* file, const Row& row, vtkSoftShadowPass* pass, vtkRenderWindow* window)
{
  const std::vector<double> ms = penumbra::bench::TimedStages(pass, window);
  std::fprintf(file, "%s,%s", row.Scene.c_str(), row.Method.c_str());
  std::printf("  %-15s stages:", "");
  for (int stage = 0; stage < vtkSoftShadowPass::NUMBER_OF_STAGES; ++stage)
  {
    std::fprintf(file, ",%.3f", ms[stage]);
    std::printf(" %s %.1f ms", vtkSoftShadowPass::GetStageName(stage), ms[stage]);
  }
  std::fprintf(file, "\n");
  std::fflush(file);
  std::printf("\n");
}

void PrintTableHeader()
{
  std::printf("  %-15s %6s %10s %10s %8s %8s %8s %7s %7s %7s %7s  %-4s %8s %10s %8s %8s\n",
    "method", "frames", "median ms", "min ms", "x none", "MAE", "RMSE", "p99", "max", ">0.1",
    ">0.5", "err", "pixels", "sv tris", "gnd MAE", "wedges");
}

void PrintTableRow(const Row& row, double noneMedian)
{
  const ErrorStats& e = row.Error;
  char ratio[32] = "-";
  if (noneMedian > 0.0)
  {
    std::snprintf(ratio, sizeof(ratio), "%.2f", row.Time.Median / noneMedian);
  }
  char shadowTriangles[32] = "-";
  if (row.ShadowTriangles >= 0)
  {
    std::snprintf(shadowTriangles, sizeof(shadowTriangles), "%lld", row.ShadowTriangles);
  }
  char wedges[32] = "-";
  if (row.Wedges >= 0)
  {
    std::snprintf(wedges, sizeof(wedges), "%lld", row.Wedges);
  }
  char ground[32] = "-";
  if (row.VisibilityMetric)
  {
    std::snprintf(ground, sizeof(ground), "%.4f", row.Ground.MAE);
  }
  std::printf("  %-15s %6d %10.2f %10.2f %8s %8.4f %8.4f %7.3f %7.3f %6.2f%% %6.2f%%  %-4s %8zu "
              "%10s %8s %8s\n",
    row.Method.c_str(), row.Time.Frames, row.Time.Median, row.Time.Min, ratio, e.MAE, e.RMSE, e.P99,
    e.Max, 100.0 * e.FracGt01, 100.0 * e.FracGt05, row.VisibilityMetric ? "vis" : "lum", e.Pixels,
    shadowTriangles, ground, wedges);
  std::fflush(stdout);
}

bool WriteReadme(const std::string& path, const Options& options)
{
  std::ofstream out(path);
  out
    << "# PenumbraBench results\n\n"
       "Written by PenumbraBench (Benchmarks/PenumbraBench.cxx); see Benchmarks/README.md.\n\n"
       "Run: "
    << options.Width << "x" << options.Height
    << ". Per method: two renders at the starting camera (the error is measured on the\n"
       "second; only one when the first takes over 2 s), then up to "
    << options.WarmUp << " orbiting warm-up frames (none once\n"
    << options.WarmUpSeconds
    << " s have been spent warming up, those renders included), then up to " << options.Frames
    << " timed\nframes, fewer once they pass " << options.MaxSeconds
    << " s (at least 1; `frames` says how many). The camera orbits " << options.AzimuthStep
    << " degrees before each\nwarm-up and timed frame. Truth: " << options.TruthSamples
    << " shadow rays per pixel.\n\n"
       "## results.csv\n\n"
       "- `scene`: scene name and light radius, `<scene>_r<radius>` (world units; the scenes\n"
       "  are ~10 units across and the light, a spot of cone 55 degrees, ~12.5 units away).\n"
       "- `method`: `none` (VTK without shadows), `shadowmap_1024|4096` (vtkShadowMapPass),\n"
       "  `hard_volumes`, `averaged_N` (N light samples), `wedges` (vtkSoftShadowPass).\n"
       "- `triangles`: triangles of the scene. `frames`: timed frames.\n"
       "- `ms_median`, `ms_min`: Render() + glFinish per frame, in ms.\n"
       "- `mae, rmse, p99, max`: mean, root mean square, 99th percentile and largest absolute\n"
       "  error; `frac_gt_0.1`, `frac_gt_0.5`: fraction of the compared pixels whose error\n"
       "  exceeds 0.1 and 0.5. All at the orbit's starting camera.\n\n"
       "Which error each row reports:\n\n"
       "- **visibility** (`hard_volumes`, `averaged_*`, `wedges`): |pass visibility - ray-traced\n"
       "  visibility| of the light, over pixels where either is below 1 - 1e-3.\n"
       "- **luminance** (`none`, `shadowmap_*`: no visibility image): |lum(image) -\n"
       "  lum(reference)|, reference = A + v (D - A) per pixel (A: the scene with the light's\n"
       "  intensity 0, D: lit without shadows, v: the ray-traced visibility), Rec. 709\n"
       "  luminance of RGB in [0, 1], over pixels where v < 1 - 1e-3 or the image is darker\n"
       "  than D by more than 1/255. `none`'s image is D.\n\n"
       "Both kinds only count pixels where the rasterized and the ray-traced surface agree\n"
       "(|truth depth - z-buffer| < 1e-3, not background). Luminance errors are scaled by the\n"
       "light's contribution (D - A) and are therefore smaller than the visibility errors of the\n"
       "same shadow: compare luminance rows with luminance rows, or use\n"
       "results_luminance.csv, where every method (also the pass's) is scored on luminance.\n\n"
       "Shadow maps: VTK 9.1's vtkShadowMapBakerPass + vtkShadowMapPass (exponential shadow\n"
       "maps) set up as in VTK's TestShadowMapPass, with one fix: the map is baked with the\n"
       "renderer's viewport shrunk to a square, because VTK 9.1 bakes a spot light's map at the\n"
       "window's aspect ratio but looks it up at aspect 1, which misplaces every shadow in a\n"
       "non-square window (`--methods shadowmap_1024_vtkaspect` shows it unfixed). VTK re-bakes\n"
       "the maps only when a light or a prop changes, so under the orbiting camera of a static\n"
       "scene the shadowmap rows time the lookup only; the pass, too, reuses its silhouettes\n"
       "but draws its volumes every frame.\n\n"
       "## truth.csv\n\n"
       "Per scene: shadow rays per pixel, trace time, and the difference between two truths\n"
       "traced with different seeds over their shadowed pixels (MAE, p99, max). The truth's own\n"
       "error is about that MAE / sqrt(2).\n";
  return static_cast<bool>(out);
}

std::string RadiusLabel(double radius)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", radius);
  return text;
}

std::string BenchDirectory(const char* argv0)
{
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::canonical(argv0, error);
  return error ? std::string(".") : exe.parent_path().string();
}

bool HasPlotPython()
{
  return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

std::string Quote(const std::string& text)
{
  std::string quoted = "'";
  for (char c : text)
  {
    quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  }
  return quoted + "'";
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
  const auto programStart = Clock::now();

  std::vector<MethodSpec> methods;
  {
    const std::vector<MethodSpec> all = AllMethods();
    if (options.Methods.empty())
    {
      for (const MethodSpec& m : all)
      {
        // --quick leaves out averaged_256: at 320x240 its 256 passes a frame cost as much as
        // the whole rest of the smoke test.
        if (m.Default && !(options.Quick && m.Name == "averaged_256"))
        {
          methods.push_back(m);
        }
      }
    }
    for (const std::string& name : options.Methods)
    {
      auto it =
        std::find_if(all.begin(), all.end(), [&](const MethodSpec& m) { return m.Name == name; });
      if (it == all.end())
      {
        std::fprintf(stderr, "%s: unknown method %s\n", argv[0], name.c_str());
        return 2;
      }
      methods.push_back(*it);
    }
  }
  for (const std::string& name : options.Scenes)
  {
    if (name != "classic" && name != "isosurface" && name != "glyphs" && name != "large" &&
      name != "streamtubes" && name != "timevarying")
    {
      std::fprintf(stderr, "%s: unknown scene %s\n", argv[0], name.c_str());
      return 2;
    }
  }

  const std::string out = options.Output;
  {
    std::error_code error;
    std::filesystem::create_directories(out, error);
    if (error)
    {
      std::fprintf(stderr, "error: cannot create %s: %s\n", out.c_str(), error.message().c_str());
      return EXIT_FAILURE;
    }
  }
  std::FILE* csv = std::fopen((out + "/results.csv").c_str(), "w");
  std::FILE* lumCsv = std::fopen((out + "/results_luminance.csv").c_str(), "w");
  std::FILE* groundCsv = std::fopen((out + "/results_ground.csv").c_str(), "w");
  std::FILE* truthCsv = std::fopen((out + "/truth.csv").c_str(), "w");
  std::FILE* stagesCsv = std::fopen((out + "/stages.csv").c_str(), "w");
  if (!csv || !lumCsv || !groundCsv || !truthCsv || !stagesCsv)
  {
    std::fprintf(stderr, "error: cannot write the CSV files in %s\n", out.c_str());
    return EXIT_FAILURE;
  }
  std::fprintf(csv, "%s\n", CsvHeader);
  std::fprintf(stagesCsv, "scene,method");
  for (int stage = 0; stage < vtkSoftShadowPass::NUMBER_OF_STAGES; ++stage)
  {
    std::fprintf(stagesCsv, ",%s_ms", vtkSoftShadowPass::GetStageName(stage));
  }
  std::fprintf(stagesCsv, "\n");
  std::fprintf(lumCsv, "%s\n", CsvHeader);
  std::fprintf(groundCsv, "%s\n", CsvHeader);
  std::fprintf(
    truthCsv, "scene,width,height,samples,trace_ms,noise_pixels,noise_mae,noise_p99,noise_max\n");
  if (!WriteReadme(out + "/README.md", options))
  {
    std::fprintf(stderr, "error: cannot write %s/README.md\n", out.c_str());
    return EXIT_FAILURE;
  }

  std::printf("PenumbraBench: %dx%d, up to %d frames (+%d warm-up, %.0f s cap) per method, "
              "truth %d spp, %zu methods, %zu scenes x %zu radii -> %s\n",
    options.Width, options.Height, options.Frames, options.WarmUp, options.MaxSeconds,
    options.TruthSamples, methods.size(), options.Scenes.size(), options.Radii.size(), out.c_str());

  bool ok = true;
  std::vector<std::string> oddities;
  const int width = options.Width, height = options.Height;
  const std::size_t pixels = static_cast<std::size_t>(width) * height;

  vtkNew<vtkRenderer> renderer;
  renderer->AutomaticLightCreationOff();
  renderer->SetBackground(0.12, 0.14, 0.18);
  renderer->SetBackground2(0.35, 0.40, 0.48);
  renderer->GradientBackgroundOn();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  window->AddRenderer(renderer);

  for (const std::string& sceneName : options.Scenes)
  {
    Scene scene;
    const auto buildStart = Clock::now();
    MakeScene(sceneName, scene);
    std::printf("\nscene %s: %lld triangles (built in %.1f s)\n", sceneName.c_str(),
      static_cast<long long>(scene.Triangles), SecondsSince(buildStart));

    for (double radius : options.Radii)
    {
      const std::string label = sceneName + "_r" + RadiusLabel(radius);
      const bool images =
        options.Images == "all" || (options.Images == "classic" && sceneName == "classic");

      // One window and renderer for the whole run (one X connection); the scene at its start,
      // its key light at this row's radius.
      vtkLight* key = scene.Lights[0];
      vtkSoftShadowPass::SetLightRadius(key, radius);
      scene.AddTo(renderer);
      auto resetCamera = [&]()
      {
        scene.ResetCamera(renderer);
        if (scene.Advance)
        {
          scene.Advance(0); // the data the truth was traced on
        }
      };

      // D (lit, no shadows) and A (the light at intensity 0: ambient only), on data frame 0 as
      // every method's error (resetCamera) whatever the last radius's methods left.
      if (scene.Advance)
      {
        scene.Advance(0);
      }
      window->Render();
      window->Render();
      const Frame lit = GrabFrame(window, width, height);
      key->SetIntensity(0.0);
      window->Render();
      const Frame ambient = GrabFrame(window, width, height);
      key->SetIntensity(1.0);
      window->Render();

      // Ground truth at the starting camera.
      vtkNew<vtkRayTracedVisibility> tracer;
      tracer->SetRenderer(renderer);
      tracer->SetSamplesPerLight(options.TruthSamples);
      tracer->SetSeed(1);
      const auto traceStart = Clock::now();
      if (!tracer->Update() || !tracer->GetVisibilityImage(0) || !tracer->GetDepthImage())
      {
        std::fprintf(stderr, "error: %s: the ray tracer gave no visibility\n", label.c_str());
        ok = false;
        continue;
      }
      const double traceMs = 1000.0 * SecondsSince(traceStart);
      const float* truthPointer =
        static_cast<const float*>(tracer->GetVisibilityImage(0)->GetScalarPointer());
      const std::vector<float> truth(truthPointer, truthPointer + pixels);
      const float* depthPointer =
        static_cast<const float*>(tracer->GetDepthImage()->GetScalarPointer());
      const std::vector<float> truthDepth(depthPointer, depthPointer + pixels);
      // The same depth with everything but the ground (z = 0) as background: comparisons on
      // the ground's pixels only.
      std::vector<float> groundDepth(truthDepth);
      CurrentGround = GroundView();
      for (std::size_t p = 0; p < pixels; ++p)
      {
        if (truthDepth[p] < 1.0f)
        {
          renderer->SetDisplayPoint(static_cast<double>(p % width) + 0.5,
            static_cast<double>(p / width) + 0.5, truthDepth[p]);
          renderer->DisplayToWorld();
          const double* world = renderer->GetWorldPoint();
          const bool onGround = std::abs(world[2] / world[3]) < 1e-3;
          groundDepth[p] = onGround ? truthDepth[p] : 1.0f;
          if (onGround)
          {
            CurrentGround.Pixels.push_back(p);
            CurrentGround.Points.push_back({ world[0] / world[3], world[1] / world[3] });
          }
        }
      }
      ErrorStats noise;
      if (options.NoiseCheck && radius > 0.0)
      {
        tracer->SetSeed(2);
        tracer->Update();
        const float* second =
          static_cast<const float*>(tracer->GetVisibilityImage(0)->GetScalarPointer());
        noise = penumbra::metrics::CompareTruths(truth.data(), second, truthDepth.data(), pixels);
      }
      std::fprintf(truthCsv, "%s,%d,%d,%d,%.1f,%zu,%.6f,%.6f,%.6f\n", label.c_str(), width, height,
        options.TruthSamples, traceMs, noise.Pixels, noise.MAE, noise.P99, noise.Max);
      std::fflush(truthCsv);

      std::printf("\n%s  (%dx%d, %lld triangles, light radius %g; truth %d spp in %.1f s",
        label.c_str(), width, height, static_cast<long long>(scene.Triangles), radius,
        options.TruthSamples, traceMs / 1000.0);
      if (noise.Pixels > 0)
      {
        std::printf(", truth seed-to-seed MAE %.4f p99 %.3f", noise.MAE, noise.P99);
      }
      std::printf(")\n");
      PrintTableHeader();

      if (images)
      {
        WriteGrey(truth.data(), width, height, out + "/" + label + "_truth_visibility.png");
        std::vector<unsigned char> reference(lit.RGB.size());
        for (std::size_t p = 0; p < pixels; ++p)
        {
          for (int k = 0; k < 3; ++k)
          {
            const double a = ambient.RGB[3 * p + k], d = lit.RGB[3 * p + k];
            const double v = truthDepth[p] < 1.0f ? truth[p] : 1.0;
            reference[3 * p + k] = static_cast<unsigned char>(std::lround(a + v * (d - a)));
          }
        }
        WriteRGB(reference, width, height, out + "/" + label + "_reference.png");
      }

      double noneMedian = 0.0;
      std::vector<float> hardVisibility;
      std::map<std::string, std::vector<float>> averagedVisibility;
      for (const MethodSpec& spec : methods)
      {
        MethodInstance method = spec.Make();
        renderer->SetPass(method.Pass);
        if (method.Attach)
        {
          method.Attach(renderer);
        }
        resetCamera();
        // The error is measured on the second frame at the starting camera (the first builds
        // shaders, silhouettes, shadow maps), or on the first where that took more than 2 s.
        const auto firstStart = Clock::now();
        window->Render();
        window->WaitForCompletion();
        if (SecondsSince(firstStart) < 2.0)
        {
          window->Render();
          window->WaitForCompletion();
        }
        const double startRenderSeconds = SecondsSince(firstStart);

        Row row;
        row.Scene = label;
        row.Method = spec.Name;
        row.Width = width;
        row.Height = height;
        row.Triangles = scene.Triangles;
        const Frame frame = GrabFrame(window, width, height);
        row.Luminance = penumbra::metrics::CompareLuminance(frame.RGB.data(), lit.RGB.data(),
          ambient.RGB.data(), 3, truth.data(), truthDepth.data(), frame.Z.data(), pixels);
        row.Error = row.Luminance;
        if (method.Visibility)
        {
          vtkImageData* image = method.Visibility();
          int dims[3] = { 0, 0, 0 };
          if (image)
          {
            image->GetDimensions(dims);
          }
          if (!image || dims[0] != width || dims[1] != height)
          {
            std::fprintf(stderr, "error: %s %s: no visibility image of the window's size\n",
              label.c_str(), spec.Name.c_str());
            ok = false;
          }
          else
          {
            const float* v = static_cast<const float*>(image->GetScalarPointer());
            std::size_t bad = 0;
            for (std::size_t p = 0; p < pixels; ++p)
            {
              bad += !(v[p] >= 0.0f && v[p] <= 1.0f); // NaN too
            }
            if (bad)
            {
              oddities.push_back(label + " " + spec.Name + ": " + std::to_string(bad) +
                " visibility pixels not finite or outside [0, 1]");
            }
            row.Error = penumbra::metrics::CompareVisibility(
              v, truth.data(), truthDepth.data(), frame.Z.data(), pixels);
            row.Ground = penumbra::metrics::CompareVisibility(
              v, truth.data(), groundDepth.data(), frame.Z.data(), pixels);
            row.VisibilityMetric = true;
            if (spec.Name == "hard_volumes")
            {
              hardVisibility.assign(v, v + pixels);
            }
            else if (spec.Name.rfind("averaged_", 0) == 0)
            {
              averagedVisibility[spec.Name].assign(v, v + pixels);
            }
            if (images)
            {
              WriteGrey(v, width, height, out + "/" + label + "_" + spec.Name + "_visibility.png");
            }
          }
        }
        if (method.ShadowTriangles)
        {
          row.ShadowTriangles = method.ShadowTriangles();
        }
        if (method.Wedges)
        {
          row.Wedges = method.Wedges();
        }
        if (images)
        {
          ok =
            WriteRGB(frame.RGB, width, height, out + "/" + label + "_" + spec.Name + ".png") && ok;
        }

        row.Time = TimeFrames(window, renderer, options, startRenderSeconds, scene.Advance);
        if (spec.Name == "none")
        {
          noneMedian = row.Time.Median;
        }
        PrintTableRow(row, noneMedian);
        if (auto soft = vtkSoftShadowPass::SafeDownCast(method.Pass))
        {
          if (scene.Advance)
          {
            scene.Advance(-1); // the split of a frame with new data, as the timed ones had
          }
          WriteStageSplit(stagesCsv, row, soft, window);
        }
        WriteCsvRow(csv, row, row.Error);
        WriteCsvRow(lumCsv, row, row.Luminance);
        if (row.VisibilityMetric)
        {
          WriteCsvRow(groundCsv, row, row.Ground);
        }

        renderer->SetPass(nullptr);
        if (method.Detach)
        {
          method.Detach(renderer);
        }
        if (method.Pass)
        {
          method.Pass->ReleaseGraphicsResources(window);
        }
      }

      // Is the averaged method live? At a light of radius > 0 it must differ from hard volumes.
      if (radius > 0.0 && !hardVisibility.empty())
      {
        for (const auto& [name, v] : averagedVisibility)
        {
          double maxDiff = 0.0;
          for (std::size_t p = 0; p < pixels; ++p)
          {
            maxDiff = std::max(maxDiff, static_cast<double>(std::abs(v[p] - hardVisibility[p])));
          }
          if (maxDiff < 1e-6)
          {
            oddities.push_back(label + " " + name +
              ": visibility identical to hard_volumes although the light has a radius");
          }
        }
      }
      renderer->RemoveAllViewProps();
      renderer->RemoveAllLights();
    }
    for (const auto& actor : scene.Actors)
    {
      actor->ReleaseGraphicsResources(window);
    }
  }
  std::fclose(csv);
  std::fclose(stagesCsv);
  std::fclose(lumCsv);
  std::fclose(groundCsv);
  std::fclose(truthCsv);

  if (!oddities.empty())
  {
    std::printf("\nnoticed:\n");
    for (const std::string& line : oddities)
    {
      std::printf("  %s\n", line.c_str());
    }
  }
  std::printf("\nwrote %s/results.csv, results_luminance.csv, results_ground.csv, truth.csv, "
              "README.md\n",
    out.c_str());

  std::fflush(stdout);
  if (options.Plot)
  {
    std::string script = PENUMBRA_BENCH_PLOT_SCRIPT;
    if (!std::filesystem::exists(script))
    {
      script = BenchDirectory(argv[0]) + "/plot_results.py";
    }
    if (!HasPlotPython())
    {
      std::printf("no matplotlib for /usr/bin/python3: apt-get install python3-matplotlib, then\n"
                  "  /usr/bin/python3 %s %s\n",
        script.c_str(), out.c_str());
    }
    else
    {
      const std::string command = "/usr/bin/python3 " + Quote(script) + " " + Quote(out);
      if (std::system(command.c_str()) != 0)
      {
        std::fprintf(stderr, "error: %s failed\n", command.c_str());
        ok = false;
      }
    }
  }
  std::printf("total %.1f s\n", SecondsSince(programStart));
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
