// PenumbraLoad: load test of vtkSoftShadowPass on large scenes (issue 5). Documentation/load.md
// has the figures and how they are measured.
//
//   PenumbraLoad [--scenes a,b] [--methods a,b] [--frames N] [--size WxH] [--max-seconds S]
//                [--jobs N] [--smoke] [--no-reuse] [--output DIR]
//
// Three scenes on a ground plane:
//   actors1000  1000 small actors (spheres, cubes, cones; some share one source's output, some
//               have their own data) spread wider than the view, one area light;
//   lights8     a few casters under 8 shadowing lights (point, spot, directional; hard and soft;
//               all coloured differently);
//   mesh4m      one torus of 4,000,000 triangles (1,000,000 with --smoke), one area light.
// Each scene and method (none = the pass with shadows disabled, hard_volumes, averaged_16,
// wedges, automatic) runs in a child process of its own, so that its memory figures are its own.
// There VTK draws the scene once without the pass (the memory baseline), then the pass renders a
// first frame (shader rebuilds, topology, silhouettes, uploads), N frames with the camera orbiting
// (silhouettes cached) and N frames with the lights moving (silhouettes recomputed every frame).
// It reports times, CPU memory (VmRSS, VmHWM), the pass's GPU memory, an estimate of VTK's own
// mapper buffers, the pass's counters, and every VTK error or warning and GL error logged.
//
// Exits 1 when a scene logged a VTK or GL error, a light that should shadow did not (or left no
// shadowed pixel in view), a visibility image holds NaN, a method left no shadowed pixel at all,
// or a child process failed; 2 on a usage error.

#include "penumbraBenchSupport.h"
#include "penumbraOptions.h"
#include "penumbraProcessMemory.h"
#include "penumbraSceneDescription.h"

#include "vtkSoftShadowPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkConeSource.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtk_glew.h"

#include <X11/Xlib.h> // the display, opened here so that a refused connection is retried

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
using penumbra::bench::Clock;
using penumbra::bench::DetachedOutput;
using penumbra::bench::GrabFrame;
using penumbra::bench::MakeShadedActor;
using penumbra::bench::SecondsSince;
using penumbra::bench::SplitList;
using penumbra::bench::Summarize;
using penumbra::bench::Timing;
using penumbra::bench::vtkCountingOutputWindow;
using penumbra::bench::WriteRGB;
using penumbra::scene::CountTriangles;

double MillisecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

constexpr double MiB = 1024.0 * 1024.0;

/// GL errors pending in the current context (VTK 9.1 from Debian does not check them itself).
int DrainGLErrors(vtkRenderWindow* window)
{
  window->MakeCurrent();
  int count = 0;
  while (glGetError() != GL_NO_ERROR && count < 1000)
  {
    ++count;
  }
  return count;
}

//--------------------------------------------------------------------------------------------------
// CPU memory from /proc/self/status.
//--------------------------------------------------------------------------------------------------
using penumbra::ProcessMemory;
using penumbra::ReadProcessMemory;

//--------------------------------------------------------------------------------------------------
// Options
//--------------------------------------------------------------------------------------------------
const std::vector<std::string> AllScenes = { "actors1000", "lights8", "mesh4m" };
const std::vector<std::string> AllMethods = { "none", "hard_volumes", "averaged_16", "wedges",
  "automatic" };

struct Options
{
  std::vector<std::string> Scenes = AllScenes;
  std::vector<std::string> Methods = AllMethods;
  int Frames = 0; ///< 0: each scene's default
  int Width = 1024, Height = 768;
  double MaxSeconds = 45.0; ///< per timed phase; at least one frame is always timed
  bool Smoke = false;
  bool Reuse = true;  ///< vtkSoftShadowPass::ReuseUnchangedShadows
  int Jobs = 1;       ///< child processes at once (more than 1 distorts the timings)
  std::string Output; ///< empty: no files
};

void Usage(const char* program)
{
  std::fprintf(stderr,
    "usage: %s [options]\n"
    "  --scenes a,b     among actors1000,lights8,mesh4m (default all)\n"
    "  --methods a,b    among none,hard_volumes,averaged_16,wedges,automatic (default all)\n"
    "  --frames N       timed frames per phase (orbit, moving light); default 5, 3 for mesh4m\n"
    "  --size WxH       window size (default 1024x768)\n"
    "  --max-seconds S  stop a timed phase once it passes S seconds (default 45; >= 1 frame)\n"
    "  --jobs N         run N scene/method processes at once (default 1; 2 with --smoke):\n"
    "                   faster, but the timings are then not worth reporting\n"
    "  --smoke          reduced scale: mesh4m at 1M triangles, 2 frames, 320x240, 2 jobs\n"
    "  --no-reuse       draw every frame's shadows (ReuseUnchangedShadows off): in the moving-\n"
    "                   light phase the scene is still, so the pass otherwise keeps its depth\n"
    "  --output DIR     write DIR/load.csv and DIR/<scene>.png (automatic's first frame)\n",
    program);
}

bool ParseArguments(int argc, char* argv[], Options& options)
{
  using namespace penumbra::bench;
  bool sizeGiven = false, framesGiven = false, jobsGiven = false;
  const std::vector<Option> table = { FlagOption("--smoke", [&] { options.Smoke = true; }),
    FlagOption("--no-reuse", [&] { options.Reuse = false; }),
    ListOption("--scenes", options.Scenes, &AllScenes),
    ListOption("--methods", options.Methods, &AllMethods),
    IntOption("--frames", 1, 1000000, options.Frames, &framesGiven),
    IntOption("--jobs", 1, 64, options.Jobs, &jobsGiven),
    ValueOption("--size",
      [&](const char* value)
      {
        sizeGiven = true;
        return std::sscanf(value, "%dx%d", &options.Width, &options.Height) == 2 &&
          options.Width >= 16 && options.Height >= 16 && options.Width <= 8192 &&
          options.Height <= 8192;
      }),
    ValueOption("--max-seconds",
      [&](const char* value)
      { return ParseDouble(value, 0.0, options.MaxSeconds) && options.MaxSeconds > 0.0; }),
    TextOption("--output", options.Output, "-o") };
  if (!ParseOptions(argc, argv, table, Usage))
  {
    return false;
  }
  if (options.Smoke)
  {
    if (!sizeGiven)
    {
      options.Width = 320;
      options.Height = 240;
    }
    if (!framesGiven)
    {
      options.Frames = 2;
    }
    if (!jobsGiven)
    {
      options.Jobs = 2; // a smoke test checks; its timings are not reported
    }
  }
  return true;
}

//--------------------------------------------------------------------------------------------------
// Scenes (z up, ground plane at z = 0).
//--------------------------------------------------------------------------------------------------
/// A load-test scene: the shared description (its Lights are the shadowing ones, light index
/// 0..n-1) and the frames a phase renders unless the command line says otherwise.
struct Scene : penumbra::scene::Description
{
  int DefaultFrames = 5;
};

void AddGround(Scene& scene, double halfX, double halfY)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-halfX, -halfY, 0.0);
  plane->SetPoint1(halfX, -halfY, 0.0);
  plane->SetPoint2(-halfX, halfY, 0.0);
  auto ground = MakeShadedActor(DetachedOutput(plane), 0.85, 0.85, 0.82);
  ground->GetProperty()->SetSpecular(0.0);
  scene.Add(ground);
}

/// A scene light: positional (point if cone >= 180, else spot) or directional (from `position`
/// towards the origin); `radius` in world units, or degrees for a directional light.
void AddLight(Scene& scene, bool positional, const penumbra::scene::Point& position,
  double coneAngle, double radius, double r, double g, double b, double intensity)
{
  vtkLight* light = scene.AddLight(positional, position, radius);
  light->SetConeAngle(coneAngle);
  light->SetExponent(1.0);
  light->SetColor(r, g, b);
  light->SetIntensity(intensity);
}

/// The camera the scene starts from, z up.
void SetCamera(Scene& scene, const penumbra::scene::Point& position,
  const penumbra::scene::Point& focal, double angle)
{
  scene.SetCamera(position, focal, { 0.0, 0.0, 1.0 }, angle);
}

/// 1000 small actors on a 40 x 25 jittered grid wider than the view (those out of view cast
/// shadows the pass should cull), under one area light.
Scene MakeActors1000()
{
  Scene scene;
  scene.Name = "actors1000";
  AddGround(scene, 21.0, 14.0);

  // Shared outputs: many actors draw the same polydata (one topology, one upload for the pass).
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  sphere->SetRadius(0.5);
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(16);
  cone->SetDirection(0.0, 0.0, 1.0);
  const vtkSmartPointer<vtkPolyData> shared[3] = { DetachedOutput(sphere), DetachedOutput(cube),
    DetachedOutput(cone) };

  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int columns = 40, rows = 25;
  for (int i = 0; i < columns * rows; ++i)
  {
    const int column = i % columns, row = i / columns;
    const double x = -19.5 + 39.0 * column / (columns - 1) + 0.3 * (unit(random) - 0.5);
    const double y = -12.0 + 24.0 * row / (rows - 1) + 0.3 * (unit(random) - 0.5);
    const int kind = i % 3;
    const double size = 0.35 + 0.3 * unit(random);
    // Every fourth actor has data of its own (another resolution), the rest share.
    vtkSmartPointer<vtkPolyData> data = shared[kind];
    if (i % 4 == 0)
    {
      if (kind == 0)
      {
        vtkNew<vtkSphereSource> own;
        own->SetThetaResolution(10 + i % 9);
        own->SetPhiResolution(8 + i % 7);
        own->SetRadius(0.5);
        data = DetachedOutput(own);
      }
      else if (kind == 1)
      {
        vtkNew<vtkCubeSource> own;
        own->SetXLength(0.6 + 0.4 * unit(random));
        own->SetYLength(0.6 + 0.4 * unit(random));
        data = DetachedOutput(own);
      }
      else
      {
        vtkNew<vtkConeSource> own;
        own->SetResolution(6 + i % 13);
        own->SetDirection(0.0, 0.0, 1.0);
        data = DetachedOutput(own);
      }
    }
    const double hue = unit(random);
    auto actor =
      MakeShadedActor(data, 0.45 + 0.5 * hue, 0.35 + 0.4 * (1.0 - hue), 0.3 + 0.5 * unit(random));
    actor->SetScale(size);
    // Spheres float (their shadows fall away from them), cubes and cones stand on the ground.
    const double z = kind == 0 ? 0.3 + 1.2 * unit(random) : 0.5 * size;
    actor->SetPosition(x, y, z);
    actor->RotateZ(360.0 * unit(random));
    scene.Add(actor);
  }
  AddLight(scene, true, { 6.0, -5.0, 16.0 }, 180.0, 0.8, 1.0, 0.97, 0.9, 1.0);
  SetCamera(scene, { -2.0, -17.0, 10.0 }, { 0.0, -2.0, 0.0 }, 32.0);
  return scene;
}

/**
 * A closed torus of 2 * u * v triangles around the z axis, with exact normals. Written out here
 * because vtkParametricFunctionSource duplicates its seam and leaves near-zero-area triangles
 * there, which the pass rightly reports (a warning per caster) and which would hide real ones.
 */
vtkSmartPointer<vtkPolyData> MakeTorus(double ring, double cross, int u, int v)
{
  const vtkIdType n = static_cast<vtkIdType>(u) * v;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  for (int i = 0; i < u; ++i)
  {
    const double a = 2.0 * vtkMath::Pi() * i / u;
    for (int j = 0; j < v; ++j)
    {
      const double b = 2.0 * vtkMath::Pi() * j / v;
      const double normal[3] = { std::cos(b) * std::cos(a), std::cos(b) * std::sin(a),
        std::sin(b) };
      const vtkIdType id = static_cast<vtkIdType>(i) * v + j;
      points->SetPoint(id, ring * std::cos(a) + cross * normal[0],
        ring * std::sin(a) + cross * normal[1], cross * normal[2]);
      normals->SetTuple(id, normal);
    }
  }
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(2 * n + 1);
  connectivity->SetNumberOfValues(6 * n);
  vtkIdType* c = connectivity->GetPointer(0);
  for (int i = 0; i < u; ++i)
  {
    for (int j = 0; j < v; ++j)
    {
      const vtkIdType p00 = static_cast<vtkIdType>(i) * v + j;
      const vtkIdType p10 = static_cast<vtkIdType>((i + 1) % u) * v + j;
      const vtkIdType p01 = static_cast<vtkIdType>(i) * v + (j + 1) % v;
      const vtkIdType p11 = static_cast<vtkIdType>((i + 1) % u) * v + (j + 1) % v;
      // Counter-clockwise seen from outside: d/du x d/dv points away from the ring.
      const vtkIdType corners[6] = { p00, p10, p11, p00, p11, p01 };
      c = std::copy(corners, corners + 6, c);
    }
  }
  for (vtkIdType k = 0; k <= 2 * n; ++k)
  {
    offsets->SetValue(k, 3 * k);
  }
  vtkNew<vtkCellArray> triangles;
  triangles->SetData(offsets, connectivity);
  auto torus = vtkSmartPointer<vtkPolyData>::New();
  torus->SetPoints(points);
  torus->GetPointData()->SetNormals(normals);
  torus->SetPolys(triangles);
  return torus;
}

/// A few casters under 8 lights of all kinds, each placed so that its shadow is in view.
Scene MakeLights8()
{
  Scene scene;
  scene.Name = "lights8";
  AddGround(scene, 10.0, 10.0);
  auto ring = MakeShadedActor(MakeTorus(1.2, 0.4, 96, 48), 0.85, 0.85, 0.85);
  ring->RotateX(60.0);
  ring->SetPosition(0.0, 0.0, 2.0);
  scene.Add(ring);
  struct Ball
  {
    double X, Y, Z, R;
  };
  for (const Ball& b : { Ball{ -2.5, 1.5, 1.0, 0.8 }, Ball{ 2.4, 1.8, 1.6, 0.6 } })
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(b.X, b.Y, b.Z);
    sphere->SetRadius(b.R);
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
    scene.Add(MakeShadedActor(DetachedOutput(sphere), 0.9, 0.9, 0.9));
  }
  vtkNew<vtkCubeSource> box;
  box->SetXLength(1.0);
  box->SetYLength(1.0);
  box->SetZLength(2.4);
  auto boxActor = MakeShadedActor(DetachedOutput(box), 0.9, 0.9, 0.9);
  boxActor->SetPosition(1.5, -2.0, 1.2);
  boxActor->RotateZ(25.0);
  scene.Add(boxActor);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(32);
  cone->SetHeight(1.8);
  cone->SetRadius(0.7);
  cone->SetDirection(0.0, 0.0, 1.0);
  auto coneActor = MakeShadedActor(DetachedOutput(cone), 0.9, 0.9, 0.9);
  coneActor->SetPosition(-2.0, -2.2, 0.9);
  scene.Add(coneActor);

  // 8 lights around the scene, 45 degrees apart, each its own colour; the camera looks from
  // azimuth ~ -100 degrees, so every light's shadows fall somewhere on the visible ground.
  struct Spec
  {
    bool Positional;
    double Cone, Radius, Elevation, Distance;
    double Colour[3];
  };
  const Spec specs[8] = {
    { true, 180.0, 0.0, 50.0, 10.0, { 1.0, 0.35, 0.3 } },  // point, hard
    { true, 180.0, 0.4, 45.0, 10.0, { 0.35, 1.0, 0.35 } }, // point, soft
    { true, 180.0, 0.8, 55.0, 11.0, { 0.35, 0.45, 1.0 } }, // point, softer
    { true, 45.0, 0.3, 50.0, 12.0, { 1.0, 0.9, 0.3 } },    // spot, soft
    { true, 35.0, 0.0, 60.0, 12.0, { 0.3, 0.95, 0.95 } },  // spot, hard
    { true, 50.0, 0.6, 45.0, 11.0, { 0.95, 0.35, 0.95 } }, // spot, soft
    { false, 180.0, 0.0, 50.0, 10.0, { 1.0, 0.6, 0.25 } }, // directional, hard
    { false, 180.0, 3.0, 40.0, 10.0, { 0.9, 0.9, 0.9 } },  // directional, 3 degrees
  };
  for (int i = 0; i < 8; ++i)
  {
    const Spec& s = specs[i];
    const double azimuth = vtkMath::RadiansFromDegrees(20.0 + 45.0 * i);
    const double elevation = vtkMath::RadiansFromDegrees(s.Elevation);
    const penumbra::scene::Point p{ s.Distance * std::cos(elevation) * std::cos(azimuth),
      s.Distance * std::cos(elevation) * std::sin(azimuth), s.Distance * std::sin(elevation) };
    AddLight(scene, s.Positional, p, s.Cone, s.Radius, s.Colour[0], s.Colour[1], s.Colour[2], 0.2);
  }
  SetCamera(scene, { -3.0, -15.0, 10.0 }, { 0.0, 0.0, 0.5 }, 40.0);
  return scene;
}

/// One tilted torus of 2 * u * v triangles over the plane, under one area spot light.
Scene MakeMesh(bool smoke)
{
  Scene scene;
  scene.Name = "mesh4m";
  scene.DefaultFrames = 3;
  AddGround(scene, 8.0, 8.0);
  auto actor = MakeShadedActor(
    smoke ? MakeTorus(2.4, 0.8, 1000, 500) : MakeTorus(2.4, 0.8, 2000, 1000), 0.75, 0.75, 0.80);
  actor->RotateX(35.0);
  actor->SetPosition(0.0, 0.0, 2.6);
  scene.Add(actor);
  AddLight(scene, true, { 4.0, -6.0, 10.0 }, 55.0, 0.5, 1.0, 1.0, 1.0, 1.0);
  SetCamera(scene, { -6.5, -13.0, 7.5 }, { 0.0, 0.0, 1.0 }, 35.0);
  return scene;
}

Scene MakeScene(const std::string& name, bool smoke)
{
  if (name == "actors1000")
  {
    return MakeActors1000();
  }
  if (name == "lights8")
  {
    return MakeLights8();
  }
  return MakeMesh(smoke);
}

/**
 * Estimate of the GPU memory VTK's own mappers hold for the scene: vtkOpenGLPolyDataMapper
 * uploads points and point normals as float3 (12 bytes per point each), shared between mappers
 * that draw the same arrays (VTK's VBO cache is keyed by array), and one index buffer per mapper
 * (4 bytes per triangle corner). Texture coordinates, edges and the window's framebuffers are not
 * counted.
 */
double EstimateVtkBufferBytes(const Scene& scene)
{
  std::set<vtkDataArray*> arrays;
  double bytes = 0.0;
  for (const auto& actor : scene.Actors)
  {
    auto data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
    for (vtkDataArray* array : { data->GetPoints()->GetData(), data->GetPointData()->GetNormals() })
    {
      if (array && arrays.insert(array).second)
      {
        bytes += 12.0 * array->GetNumberOfTuples();
      }
    }
    bytes += 12.0 * CountTriangles(data);
  }
  return bytes;
}

//--------------------------------------------------------------------------------------------------
// One method on one scene.
//--------------------------------------------------------------------------------------------------
struct Row
{
  std::string Scene, Method;
  int FramesOrbit = 0, FramesLight = 0;
  double FirstMs = 0.0;
  Timing Orbit, Light;
  double SilhouettesOrbit = 0.0, SilhouettesLight = 0.0; ///< silhouette updates per frame
  ProcessMemory Memory;
  double RssGrowthMiB = 0.0;
  double PassGpuMiB = 0.0, VtkGpuMiB = 0.0;
  vtkIdType Triangles = 0, ShadowTriangles = 0, Wedges = 0, FullViewportWedges = 0;
  int Culled = 0, ZFail = 0;
  int ExpectedLights = 0, ShadowingLights = 0, LightsWithShadow = 0;
  long long ShadowedPixels = 0, NanPixels = 0, OutOfRangePixels = 0;
  long long IsolatedPixels = 0; ///< single-pixel speckles in the visibility, summed over lights
  int Errors = 0, Warnings = 0, GLErrors = 0;
  std::string FirstMessage;
  bool ShadowsOn = false;
};

/**
 * Pixels whose visibility is more than 0.25 above, or below, all 8 of their neighbours: speckles
 * that no smooth shadow (hard edge, penumbra) produces, such as a sample counted twice or missed
 * where two volumes or wedges share a plane.
 */
long long CountIsolatedPixels(const float* v, int width, int height)
{
  long long count = 0;
  for (int y = 1; y + 1 < height; ++y)
  {
    for (int x = 1; x + 1 < width; ++x)
    {
      const float c = v[static_cast<std::size_t>(y) * width + x];
      bool above = true, below = true;
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          if (dx || dy)
          {
            const float n = v[static_cast<std::size_t>(y + dy) * width + x + dx];
            above = above && c > n + 0.25f;
            below = below && c < n - 0.25f;
          }
        }
      }
      count += above || below;
    }
  }
  return count;
}

vtkSmartPointer<vtkSoftShadowPass> MakePass(const std::string& method, bool reuse)
{
  auto pass = vtkSmartPointer<vtkSoftShadowPass>::New();
  pass->SetReuseUnchangedShadows(reuse);
  if (method == "none")
    pass->SetShadowsEnabled(false);
  else if (method == "hard_volumes")
    pass->SetMethodToHardVolumes();
  else if (method == "averaged_16")
  {
    pass->SetMethodToAveragedHardShadows();
    pass->SetLightSamples(16);
  }
  else if (method == "wedges")
    pass->SetMethodToPenumbraWedges();
  else
    pass->SetMethodToAutomatic();
  return pass;
}

/// Turns every light `degrees` about the vertical axis through the origin, from its start pose.
void TurnLights(const Scene& scene, double degrees)
{
  const double c = std::cos(vtkMath::RadiansFromDegrees(degrees));
  const double s = std::sin(vtkMath::RadiansFromDegrees(degrees));
  for (std::size_t i = 0; i < scene.Lights.size(); ++i)
  {
    const penumbra::scene::Point& p = scene.LightPoses[i].Position;
    scene.Lights[i]->SetPosition(c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]);
  }
}

double RenderTimed(vtkRenderWindow* window)
{
  const auto start = Clock::now();
  window->Render();
  window->WaitForCompletion();
  return MillisecondsSince(start);
}

Row RunMethod(const std::string& method, const Scene& scene, vtkRenderWindow* window,
  vtkRenderer* renderer, vtkCountingOutputWindow* log, const Options& options, int frames,
  double baselineRss, double vtkGpuBytes, std::vector<unsigned char>* image)
{
  Row row;
  row.Scene = scene.Name;
  row.Method = method;
  row.Triangles = scene.Triangles;
  row.VtkGpuMiB = vtkGpuBytes / MiB;
  row.ExpectedLights = method == "none" ? 0 : static_cast<int>(scene.Lights.size());
  row.ShadowsOn = method != "none";

  auto pass = MakePass(method, options.Reuse);
  renderer->SetPass(pass);
  scene.ResetLights();
  scene.ResetCamera(renderer);
  // VTK has drawn the scene once already (the baseline): the first frame is what switching
  // shadows on costs (shader rebuilds, topology, silhouettes, uploads), not VTK's own upload.
  DrainGLErrors(window);
  log->Reset();

  row.FirstMs = RenderTimed(window);
  row.GLErrors += DrainGLErrors(window);
  row.ShadowingLights = pass->GetNumberOfShadowingLights();
  row.ShadowTriangles = pass->GetNumberOfShadowVolumeTriangles();
  row.Wedges = pass->GetNumberOfPenumbraWedges();
  row.FullViewportWedges = pass->GetNumberOfFullViewportWedges();
  row.Culled = static_cast<int>(pass->GetNumberOfCulledShadows());
  row.ZFail = static_cast<int>(pass->GetNumberOfZFailVolumes());

  // Visibility of every shadowing light at the starting view: finite, in [0, 1], and dark
  // somewhere (a light whose shadow never lands in view would be a broken scene or pass).
  if (row.ShadowsOn)
  {
    const std::size_t pixels = static_cast<std::size_t>(options.Width) * options.Height;
    std::vector<bool> shadowed(pixels, false);
    for (std::size_t i = 0; i < scene.Lights.size(); ++i)
    {
      vtkImageData* visibility = pass->GetVisibilityImage(static_cast<int>(i));
      auto values = visibility
        ? vtkFloatArray::SafeDownCast(visibility->GetPointData()->GetScalars())
        : nullptr;
      if (!values || static_cast<std::size_t>(values->GetNumberOfValues()) != pixels)
      {
        continue;
      }
      const float* v = values->GetPointer(0);
      bool any = false;
      for (std::size_t p = 0; p < pixels; ++p)
      {
        if (std::isnan(v[p]))
        {
          ++row.NanPixels;
          continue;
        }
        row.OutOfRangePixels += v[p] < -1e-4f || v[p] > 1.0f + 1e-4f;
        if (v[p] < 0.5f)
        {
          any = true;
          shadowed[p] = true;
        }
      }
      row.LightsWithShadow += any;
      row.IsolatedPixels += CountIsolatedPixels(v, options.Width, options.Height);
    }
    row.ShadowedPixels = std::count(shadowed.begin(), shadowed.end(), true);
  }
  if (image)
  {
    *image = GrabFrame(window, options.Width, options.Height).RGB;
  }
  row.GLErrors += DrainGLErrors(window);

  // Orbit: the casters and lights stand still, so silhouettes stay cached.
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    const vtkIdType before = pass->GetNumberOfSilhouetteUpdates();
    std::vector<double> ms;
    const auto begin = Clock::now();
    for (int i = 0; i < frames && (i == 0 || SecondsSince(begin) < options.MaxSeconds); ++i)
    {
      camera->Azimuth(2.0);
      renderer->ResetCameraClippingRange();
      ms.push_back(RenderTimed(window));
    }
    row.Orbit = Summarize(ms);
    row.SilhouettesOrbit =
      double(pass->GetNumberOfSilhouetteUpdates() - before) / std::max<int>(1, row.Orbit.Frames);
  }
  scene.ResetCamera(renderer);
  // Moving lights: every (caster, light sample) silhouette is recomputed every frame.
  {
    const vtkIdType before = pass->GetNumberOfSilhouetteUpdates();
    std::vector<double> ms;
    const auto begin = Clock::now();
    for (int i = 0; i < frames && (i == 0 || SecondsSince(begin) < options.MaxSeconds); ++i)
    {
      TurnLights(scene, 2.0 * (i + 1));
      ms.push_back(RenderTimed(window));
    }
    row.Light = Summarize(ms);
    row.SilhouettesLight =
      double(pass->GetNumberOfSilhouetteUpdates() - before) / std::max<int>(1, row.Light.Frames);
  }
  row.GLErrors += DrainGLErrors(window);

  row.Memory = ReadProcessMemory();
  row.RssGrowthMiB = row.Memory.RssMiB - baselineRss;
  row.PassGpuMiB = pass->GetGraphicsMemoryBytes() / MiB;
  row.Errors = log->Errors;
  row.Warnings = log->Warnings;
  row.FirstMessage = log->First;

  renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window);
  scene.ResetLights();
  return row;
}

//--------------------------------------------------------------------------------------------------
// Output
//--------------------------------------------------------------------------------------------------
void PrintHeader()
{
  std::printf("  %-12s %9s %9s %9s %6s %7s %7s %7s %7s %9s %9s %7s %6s %5s %6s %8s %5s %5s\n",
    "method", "first ms", "orbit ms", "light ms", "sil/fr", "RSS MiB", "HWM MiB", "+RSS", "GPU MiB",
    "triangles", "sv tris", "wedges", "culled", "zfail", "lights", "shadowpx", "speck", "err/w");
}

void PrintRow(const Row& r)
{
  char lights[32] = "-";
  if (r.ShadowsOn)
  {
    std::snprintf(lights, sizeof(lights), "%d/%d", r.ShadowingLights, r.ExpectedLights);
  }
  std::printf("  %-12s %9.0f %9.1f %9.1f %6.1f %7.0f %7.0f %7.0f %7.1f %9lld %9lld %7lld %6d %5d "
              "%6s %8lld %5lld %2d/%-2d\n",
    r.Method.c_str(), r.FirstMs, r.Orbit.Median, r.Light.Median, r.SilhouettesLight,
    r.Memory.RssMiB, r.Memory.HwmMiB, r.RssGrowthMiB, r.PassGpuMiB,
    static_cast<long long>(r.Triangles), static_cast<long long>(r.ShadowTriangles),
    static_cast<long long>(r.Wedges), r.Culled, r.ZFail, lights, r.ShadowedPixels, r.IsolatedPixels,
    r.Errors + r.GLErrors, r.Warnings);
  std::fflush(stdout);
}

std::string CsvQuote(const std::string& text)
{
  std::string quoted = "\"";
  for (char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' || c == '\r' ? ' ' : c);
  }
  return quoted + "\"";
}

const char* CsvTag = "@csv ";

const char* CsvHeader =
  "scene,method,width,height,triangles,lights_expected,lights_shadowing,"
  "lights_with_shadow,first_ms,orbit_frames,orbit_ms_median,orbit_ms_min,"
  "orbit_silhouette_updates_per_frame,light_frames,light_ms_median,"
  "light_ms_min,light_silhouette_updates_per_frame,rss_mib,hwm_mib,"
  "rss_growth_mib,pass_gpu_mib,vtk_gpu_estimate_mib,shadow_volume_triangles,"
  "wedges,full_viewport_wedges,culled_shadows,zfail_volumes,shadowed_pixels,"
  "nan_pixels,out_of_range_pixels,isolated_pixels,vtk_errors,vtk_warnings,gl_errors,"
  "first_message";

void WriteCsvRow(std::FILE* file, const Row& r, const Options& o)
{
  std::fprintf(file,
    "%s,%s,%d,%d,%lld,%d,%d,%d,%.1f,%d,%.2f,%.2f,%.2f,%d,%.2f,%.2f,%.2f,%.1f,%.1f,%.1f,%.2f,%.2f,"
    "%lld,%lld,%lld,%d,%d,%lld,%lld,%lld,%lld,%d,%d,%d,%s\n",
    r.Scene.c_str(), r.Method.c_str(), o.Width, o.Height, static_cast<long long>(r.Triangles),
    r.ExpectedLights, r.ShadowingLights, r.LightsWithShadow, r.FirstMs, r.Orbit.Frames,
    r.Orbit.Median, r.Orbit.Min, r.SilhouettesOrbit, r.Light.Frames, r.Light.Median, r.Light.Min,
    r.SilhouettesLight, r.Memory.RssMiB, r.Memory.HwmMiB, r.RssGrowthMiB, r.PassGpuMiB, r.VtkGpuMiB,
    static_cast<long long>(r.ShadowTriangles), static_cast<long long>(r.Wedges),
    static_cast<long long>(r.FullViewportWedges), r.Culled, r.ZFail, r.ShadowedPixels, r.NanPixels,
    r.OutOfRangePixels, r.IsolatedPixels, r.Errors, r.Warnings, r.GLErrors,
    CsvQuote(r.FirstMessage).c_str());
  std::fflush(file);
}

/// The X connection, retried: Xvfb refuses a few percent of rapid reconnects, and every
/// child process opens its own (a connection cannot cross fork()).
Display* OpenDisplay()
{
  for (int attempt = 0; attempt < 50; ++attempt)
  {
    if (Display* display = XOpenDisplay(nullptr))
    {
      return display;
    }
    usleep(100000);
  }
  return nullptr;
}

/**
 * One scene with one method, in a process of its own (a child of main), so that VmRSS and VmHWM
 * are that configuration's alone: under llvmpipe the "GPU" buffers and textures and the compiled
 * shaders live in the process's memory, and what one method frees is not reliably returned before
 * the next starts. Prints the row (and the scene's header when `first`), appends it to load.csv,
 * writes the PNG when `picture`. Returns 0, or 1 when a check failed, 3 without a display.
 */
int RunChild(const std::string& sceneName, const std::string& method, bool first, bool picture,
  const Options& options)
{
  vtkNew<vtkCountingOutputWindow> log;
  vtkOutputWindow::SetInstance(log);
  Display* display = OpenDisplay();
  if (!display)
  {
    std::printf("  %-12s cannot open the X display (DISPLAY=%s)\n", method.c_str(),
      std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "");
    return 3;
  }

  const ProcessMemory beforeBuild = ReadProcessMemory();
  const auto buildStart = Clock::now();
  Scene scene = MakeScene(sceneName, options.Smoke);
  const double buildSeconds = SecondsSince(buildStart);
  const ProcessMemory afterBuild = ReadProcessMemory();
  const int frames = options.Frames > 0 ? options.Frames : scene.DefaultFrames;

  vtkNew<vtkRenderer> renderer;
  renderer->AutomaticLightCreationOff();
  renderer->SetBackground(0.12, 0.14, 0.18);
  renderer->SetBackground2(0.35, 0.40, 0.48);
  renderer->GradientBackgroundOn();
  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(display);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(options.Width, options.Height);
  window->AddRenderer(renderer);
  scene.AddTo(renderer);
  // A dim headlight after the scene lights: fill light for the images, and a light the pass
  // must skip (it casts no shadow) among the shadowing ones in VTK's numbering.
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  headlight->SetIntensity(0.2);
  renderer->AddLight(headlight);

  // Baseline: VTK alone (no pass) with the scene drawn once, in this process.
  log->Reset();
  const double baselineMs = RenderTimed(window);
  int setupGLErrors = DrainGLErrors(window);
  const ProcessMemory baseline = ReadProcessMemory();
  const double vtkGpuBytes = EstimateVtkBufferBytes(scene);
  const int setupErrors = log->Errors;
  const std::string setupMessage = log->First;

  if (first)
  {
    std::printf("\nscene %s: %zu actors (%zu datasets), %lld triangles, %zu shadowing lights "
                "(+ a headlight); %d frames per phase\n"
                "  built in %.1f s; VTK alone drew its first frame in %.0f ms; RSS %.0f MiB at "
                "start, +%.0f MiB scene data, +%.0f MiB once VTK drew it: baseline %.0f MiB; "
                "VTK buffers (estimate) %.1f MiB\n",
      scene.Name.c_str(), scene.Actors.size(), scene.CountDatasets(),
      static_cast<long long>(scene.Triangles), scene.Lights.size(), frames, buildSeconds,
      baselineMs, beforeBuild.RssMiB, afterBuild.RssMiB - beforeBuild.RssMiB,
      baseline.RssMiB - afterBuild.RssMiB, baseline.RssMiB, vtkGpuBytes / MiB);
    PrintHeader();
  }

  std::vector<unsigned char> frame;
  Row row = RunMethod(method, scene, window, renderer, log, options, frames, baseline.RssMiB,
    vtkGpuBytes, picture ? &frame : nullptr);
  row.Errors += setupErrors;
  row.GLErrors += setupGLErrors;
  if (row.FirstMessage.empty())
  {
    row.FirstMessage = setupMessage;
  }
  PrintRow(row);

  std::vector<std::string> failures;
  if (row.Errors || row.GLErrors)
  {
    failures.push_back(std::to_string(row.Errors) + " VTK errors, " + std::to_string(row.GLErrors) +
      " GL errors; first message: " + row.FirstMessage);
  }
  if (row.ShadowsOn && row.ShadowingLights < row.ExpectedLights)
  {
    failures.push_back(std::to_string(row.ShadowingLights) + " of " +
      std::to_string(row.ExpectedLights) + " lights shadowed");
  }
  if (row.ShadowsOn && row.LightsWithShadow < row.ExpectedLights)
  {
    failures.push_back("only " + std::to_string(row.LightsWithShadow) + " of " +
      std::to_string(row.ExpectedLights) + " lights left a shadowed pixel in view");
  }
  if (row.ShadowsOn && row.ShadowedPixels == 0)
  {
    failures.push_back("no shadowed pixel at all");
  }
  if (row.NanPixels)
  {
    failures.push_back(std::to_string(row.NanPixels) + " NaN visibility pixels");
  }
  if (row.Warnings && failures.empty())
  {
    std::printf("    warning: %s\n", row.FirstMessage.c_str());
  }
  for (const std::string& line : failures)
  {
    std::printf("    FAIL %s %s: %s\n", scene.Name.c_str(), method.c_str(), line.c_str());
  }

  if (!options.Output.empty())
  {
    std::fputs(CsvTag, stdout); // the parent writes tagged lines to load.csv, in job order
    WriteCsvRow(stdout, row, options);
    if (picture)
    {
      const std::string path = options.Output + "/" + scene.Name + ".png";
      if (WriteRGB(frame, options.Width, options.Height, path))
      {
        std::printf("    wrote %s (%s, first frame)\n", path.c_str(), method.c_str());
      }
      else
      {
        failures.push_back("png");
      }
    }
  }
  std::fflush(stdout);
  return failures.empty() ? 0 : 1;
}

std::string DescribeStatus(int status)
{
  if (WIFEXITED(status))
  {
    const int code = WEXITSTATUS(status);
    return code == 1 ? "a check failed" : "exit status " + std::to_string(code);
  }
  if (WIFSIGNALED(status))
  {
    return std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
      strsignal(WTERMSIG(status)) + ")";
  }
  return "stopped";
}

/// One child process: a scene with a method.
struct Job
{
  std::string Scene, Method;
  bool First = false, Picture = false;
  pid_t Pid = -1;
  int Fd = -1; ///< read end of the pipe that carries the child's stdout and stderr
  std::string Output;
  bool Done = false;
  int ExitStatus = 0; // "Status" is a macro of Xlib.h
};

bool StartJob(Job& job, const Options& options)
{
  int fds[2];
  if (pipe(fds) != 0)
  {
    std::perror("pipe");
    return false;
  }
  std::fflush(stdout);
  std::fflush(stderr);
  job.Pid = fork();
  if (job.Pid < 0)
  {
    std::perror("fork");
    return false;
  }
  if (job.Pid == 0)
  {
    close(fds[0]);
    dup2(fds[1], STDOUT_FILENO);
    dup2(fds[1], STDERR_FILENO); // VTK's messages land next to the row they belong to
    close(fds[1]);
    setvbuf(stdout, nullptr, _IOLBF, 0);
    const int code = RunChild(job.Scene, job.Method, job.First, job.Picture, options);
    std::fflush(stdout);
    std::fflush(stderr);
    _exit(code); // skip static destructors: the parent owns the process's exit
  }
  close(fds[1]);
  job.Fd = fds[0];
  return true;
}

/// Prints a finished job's output, sends its tagged line to load.csv, records a failure.
void EmitJob(const Job& job, std::FILE* csv, std::vector<std::string>& failures)
{
  std::istringstream lines(job.Output);
  const std::size_t tag = std::strlen(CsvTag);
  for (std::string line; std::getline(lines, line);)
  {
    if (line.compare(0, tag, CsvTag) == 0)
    {
      if (csv)
      {
        std::fprintf(csv, "%s\n", line.c_str() + tag);
      }
      continue;
    }
    std::printf("%s\n", line.c_str());
  }
  if (!WIFEXITED(job.ExitStatus) || WEXITSTATUS(job.ExitStatus) != 0)
  {
    if (!WIFEXITED(job.ExitStatus))
    {
      std::printf("  %-12s %s\n", job.Method.c_str(), DescribeStatus(job.ExitStatus).c_str());
    }
    failures.push_back(job.Scene + " " + job.Method + ": " + DescribeStatus(job.ExitStatus));
  }
  std::fflush(stdout);
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

  if (!options.Output.empty())
  {
    std::error_code error;
    std::filesystem::create_directories(options.Output, error);
    std::FILE* csv = std::fopen((options.Output + "/load.csv").c_str(), "w");
    if (error || !csv)
    {
      std::fprintf(stderr, "error: cannot write %s/load.csv\n", options.Output.c_str());
      return EXIT_FAILURE;
    }
    std::fprintf(csv, "%s\n", CsvHeader);
    std::fclose(csv);
  }
  std::printf("PenumbraLoad: %dx%d%s, timed phases capped at %.0f s; one process per scene and "
              "method, %d at a time\n",
    options.Width, options.Height, options.Smoke ? " (smoke)" : "", options.MaxSeconds,
    options.Jobs);

  // The parent opens no window and builds nothing: each child starts from the same small
  // process, and nothing (X connection, GL context, threads) is shared across fork().
  std::vector<Job> jobs;
  const bool hasAutomatic =
    std::find(options.Methods.begin(), options.Methods.end(), "automatic") != options.Methods.end();
  for (const std::string& scene : options.Scenes)
  {
    for (std::size_t m = 0; m < options.Methods.size(); ++m)
    {
      Job job;
      job.Scene = scene;
      job.Method = options.Methods[m];
      job.First = m == 0;
      // The PNG: automatic's frame, or the last method's when automatic is not run.
      job.Picture = !options.Output.empty() &&
        (job.Method == "automatic" || (!hasAutomatic && m + 1 == options.Methods.size()));
      jobs.push_back(job);
    }
  }
  std::FILE* csv =
    options.Output.empty() ? nullptr : std::fopen((options.Output + "/load.csv").c_str(), "a");
  std::vector<std::string> failures;
  std::size_t started = 0, emitted = 0;
  int running = 0;
  while (emitted < jobs.size())
  {
    while (running < options.Jobs && started < jobs.size())
    {
      if (!StartJob(jobs[started], options))
      {
        return EXIT_FAILURE;
      }
      ++started;
      ++running;
    }
    // Collect output from the running children until one of them ends.
    std::vector<pollfd> polls;
    std::vector<Job*> owners;
    for (Job& job : jobs)
    {
      if (job.Fd >= 0)
      {
        polls.push_back({ job.Fd, POLLIN, 0 });
        owners.push_back(&job);
      }
    }
    if (poll(polls.data(), polls.size(), -1) < 0 && errno != EINTR)
    {
      std::perror("poll");
      return EXIT_FAILURE;
    }
    for (std::size_t k = 0; k < polls.size(); ++k)
    {
      if (!(polls[k].revents & (POLLIN | POLLHUP | POLLERR)))
      {
        continue;
      }
      Job& job = *owners[k];
      char buffer[4096];
      const ssize_t n = read(job.Fd, buffer, sizeof(buffer));
      if (n > 0)
      {
        job.Output.append(buffer, static_cast<std::size_t>(n));
        continue;
      }
      if (n < 0 && errno == EINTR)
      {
        continue;
      }
      close(job.Fd);
      job.Fd = -1;
      while (waitpid(job.Pid, &job.ExitStatus, 0) < 0 && errno == EINTR)
      {
      }
      job.Done = true;
      --running;
    }
    // In job order, whatever order they finished in.
    while (emitted < jobs.size() && jobs[emitted].Done)
    {
      EmitJob(jobs[emitted++], csv, failures);
    }
  }
  if (csv)
  {
    std::fclose(csv);
    std::printf("\nwrote %s/load.csv\n", options.Output.c_str());
  }
  std::printf(
    "\ncolumns: first = first frame with the pass, after VTK alone drew the scene once (shader "
    "rebuilds, topology, silhouettes, the pass's uploads); orbit, light = median ms per frame with "
    "the camera orbiting / the "
    "lights turning; sil/fr = silhouette updates per frame with the lights turning; RSS = VmRSS "
    "after the frames, HWM = VmHWM (the process's peak), +RSS = RSS over the same process's "
    "baseline (VTK alone, scene drawn); GPU = the pass's GetGraphicsMemoryBytes; sv tris, wedges, "
    "culled, zfail, lights (shadowing/expected) = the pass's counters on the first frame; "
    "shadowpx = pixels below 0.5 visibility for some light; speck = visibility pixels more than "
    "0.25 above or below all 8 neighbours (summed over lights); err/w = VTK and GL errors / VTK "
    "warnings\n");
  std::printf("total %.1f s\n", SecondsSince(programStart));
  if (!failures.empty())
  {
    std::printf("\nFAILED:\n");
    for (const std::string& line : failures)
    {
      std::printf("  %s\n", line.c_str());
    }
    return EXIT_FAILURE;
  }
  std::printf("all scenes rendered without error; every light shadowed\n");
  return EXIT_SUCCESS;
}
