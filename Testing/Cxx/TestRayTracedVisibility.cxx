// Self-checks of vtkRayTracedVisibility against closed forms: a sphere over a ground plane lit by
// a point light (hard shadow), a spherical light (penumbra given by the solid angle of two
// intersecting spherical caps) and a directional light with an angular radius; casters excluded
// with vtkSoftShadowPass::SetCastsShadows; thread-count independence; a scene far from the origin.
// Prints every measured error; returns EXIT_FAILURE when one is out of tolerance.

#include "penumbraTestHarness.h"
#include "vtkRayTracedVisibility.h"
#include "vtkSoftShadowPass.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace
{

constexpr int Width = 160;
constexpr int Height = 120;
constexpr double Pi = 3.14159265358979323846;

int Failures = 0;

void Check(bool ok, const char* what)
{
  std::printf("  [%s] %s\n", ok ? "ok" : "FAIL", what);
  if (!ok)
  {
    ++Failures;
  }
}

// ---------------------------------------------------------------------------------------------
// Closed forms.

/// Solid angle of a spherical cap of angular radius a.
double CapSolidAngle(double a)
{
  const double s = std::sin(0.5 * a);
  return 4.0 * Pi * s * s;
}

double ClampedAcos(double x)
{
  return std::acos(std::max(-1.0, std::min(1.0, x)));
}

/// Solid angle of the intersection of two spherical caps of angular radii a1, a2 whose axes are
/// theta apart. By Gauss-Bonnet on the lens bounded by the two small circles: area = 2 pi - (sum
/// of the exterior angles at the two corners, 2 gamma) - (integral of the geodesic curvature of
/// each arc, cos(a_i) times its azimuthal span 2 beta_i), with gamma, beta_i from the spherical
/// law of cosines in the triangle (axis 1, axis 2, corner).
double CapIntersectionSolidAngle(double a1, double a2, double theta)
{
  if (theta >= a1 + a2)
  {
    return 0.0;
  }
  if (theta <= std::abs(a1 - a2))
  {
    return CapSolidAngle(std::min(a1, a2));
  }
  const double c1 = std::cos(a1), c2 = std::cos(a2), s1 = std::sin(a1), s2 = std::sin(a2);
  const double ct = std::cos(theta), st = std::sin(theta);
  const double gamma = ClampedAcos((ct - c1 * c2) / (s1 * s2));
  const double beta1 = ClampedAcos((c2 - ct * c1) / (st * s1));
  const double beta2 = ClampedAcos((c1 - ct * c2) / (st * s2));
  return 2.0 * (Pi - gamma - beta1 * c1 - beta2 * c2);
}

/// Fraction of a light cap (half-angle aL around unit lightAxis) not covered by an occluder cap
/// (half-angle aO around unit occluderAxis).
double VisibleFraction(
  const glm::dvec3& lightAxis, double aL, const glm::dvec3& occluderAxis, double aO)
{
  const double theta = ClampedAcos(glm::dot(lightAxis, occluderAxis));
  return 1.0 - CapIntersectionSolidAngle(aL, aO, theta) / CapSolidAngle(aL);
}

/// Monte Carlo check of CapIntersectionSolidAngle, so that a wrong formula cannot pass the
/// penumbra tests by agreeing with a wrong ray tracer.
void CheckCapFormula()
{
  std::printf("Cap intersection closed form vs Monte Carlo (2e6 samples each):\n");
  const double configs[][3] = { { 0.10, 0.08, 0.12 }, { 0.30, 0.10, 0.25 }, { 0.05, 0.20, 0.18 },
    { 0.50, 0.40, 0.20 }, { 0.20, 0.20, 0.39 }, { 0.40, 0.15, 0.30 } };
  std::mt19937_64 engine(12345);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  double worst = 0.0;
  for (const auto& c : configs)
  {
    const double a1 = c[0], a2 = c[1], theta = c[2];
    const glm::dvec3 axis2(std::sin(theta), 0.0, std::cos(theta));
    const double cos2 = std::cos(a2);
    const int n = 2000000;
    int inside = 0;
    for (int k = 0; k < n; ++k)
    {
      const double z = 1.0 - uniform(engine) * (1.0 - std::cos(a1));
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = 2.0 * Pi * uniform(engine);
      inside += glm::dot(glm::dvec3(r * std::cos(phi), r * std::sin(phi), z), axis2) >= cos2;
    }
    const double monteCarlo = static_cast<double>(inside) / n;
    const double closed = CapIntersectionSolidAngle(a1, a2, theta) / CapSolidAngle(a1);
    worst = penumbra_test::Worse(worst, std::abs(monteCarlo - closed));
    std::printf("    a1 %.2f a2 %.2f theta %.2f: closed %.5f, Monte Carlo %.5f\n", a1, a2, theta,
      closed, monteCarlo);
  }
  std::printf("    largest difference %.2e (tolerance 2e-3, ~6 sigma)\n", worst);
  Check(worst < 2e-3, "closed-form cap intersection matches Monte Carlo");
}

// ---------------------------------------------------------------------------------------------
// The scene: a ground quad at z = 0 and a sphere above it, seen from above.

enum PixelClass
{
  Background = 0,
  SphereClass = 1,
  GroundLit = 2,
  GroundShadowed = 3
};

struct Ray
{
  glm::dvec3 Origin;
  glm::dvec3 Direction; // unit
};

/// First hit of a ray with an exact sphere, or -1.
double HitSphere(const Ray& ray, const glm::dvec3& centre, double radius)
{
  const glm::dvec3 oc = ray.Origin - centre;
  const double b = glm::dot(oc, ray.Direction);
  const double c = glm::dot(oc, oc) - radius * radius;
  const double disc = b * b - c;
  if (disc < 0.0)
  {
    return -1.0;
  }
  const double t = -b - std::sqrt(disc);
  return t > 0.0 ? t : -1.0;
}

/// Does the segment a -> b pass through the exact sphere?
bool SegmentHitsSphere(
  const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& centre, double radius)
{
  const glm::dvec3 d = b - a;
  const double t = std::max(0.0, std::min(1.0, glm::dot(centre - a, d) / glm::dot(d, d)));
  const glm::dvec3 closest = a + t * d;
  return glm::dot(closest - centre, closest - centre) < radius * radius;
}

/// The ray tracer's own fixture: a sphere over a square ground whose shadows the test computes
/// analytically. It draws no vtkSoftShadowPass: the truth is tested apart from the pass.
struct AnalyticScene
{
  vtkSmartPointer<vtkRenderWindow> Window = penumbra_test::NewRenderWindow();
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkSphereSource> SphereSource;
  vtkNew<vtkPlaneSource> PlaneSource;
  vtkNew<vtkActor> Sphere;
  vtkNew<vtkActor> Ground;
  glm::dvec3 Offset{ 0.0 }; ///< everything (actors, camera, lights) is moved by it
  glm::dvec3 SphereCentre{ 0.0, 0.0, 1.0 };
  double SphereRadius = 0.6;
  double GroundHalf = 3.0;

  AnalyticScene()
  {
    this->SphereSource->SetCenter(0.0, 0.0, 0.0);
    this->SphereSource->SetRadius(this->SphereRadius);
    this->SphereSource->SetThetaResolution(128);
    this->SphereSource->SetPhiResolution(128);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(this->SphereSource->GetOutputPort());
    this->Sphere->SetMapper(sphereMapper);

    this->PlaneSource->SetOrigin(-this->GroundHalf, -this->GroundHalf, 0.0);
    this->PlaneSource->SetPoint1(this->GroundHalf, -this->GroundHalf, 0.0);
    this->PlaneSource->SetPoint2(-this->GroundHalf, this->GroundHalf, 0.0);
    vtkNew<vtkPolyDataMapper> planeMapper;
    planeMapper->SetInputConnection(this->PlaneSource->GetOutputPort());
    this->Ground->SetMapper(planeMapper);

    this->Renderer->AddActor(this->Ground);
    this->Renderer->AddActor(this->Sphere);
    this->Renderer->AutomaticLightCreationOff();
    this->Window->SetOffScreenRendering(1);
    // Multisampled depth resolves to one sample, off the pixel centre: compare single-sampled.
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(Width, Height);
    this->Window->AddRenderer(this->Renderer);
    this->Place(glm::dvec3(0.0));
  }

  /// Moves the whole scene by `offset`; the image stays the same.
  void Place(const glm::dvec3& offset)
  {
    this->Offset = offset;
    const glm::dvec3 sphere = this->SphereCentre + offset;
    this->Sphere->SetPosition(sphere.x, sphere.y, sphere.z);
    this->Ground->SetPosition(offset.x, offset.y, offset.z);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(offset.x, offset.y, offset.z + 8.0);
    camera->SetFocalPoint(offset.x, offset.y, offset.z);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(40.0);
  }

  void Render()
  {
    this->Renderer->ResetCameraClippingRange();
    this->Window->Render();
  }

  /// Ray through the centre of pixel (i, j), from VTK's own display -> world conversion
  /// (independent of the class's matrices), in scene coordinates (offset removed).
  Ray PixelRay(int i, int j)
  {
    auto unproject = [this](double x, double y, double z)
    {
      this->Renderer->SetDisplayPoint(x, y, z);
      this->Renderer->DisplayToWorld();
      const double* w = this->Renderer->GetWorldPoint();
      return glm::dvec3(w[0], w[1], w[2]) / (w[3] != 0.0 ? w[3] : 1.0);
    };
    const glm::dvec3 a = unproject(i + 0.5, j + 0.5, 0.0);
    const glm::dvec3 b = unproject(i + 0.5, j + 0.5, 1.0);
    return { a - this->Offset, glm::normalize(b - a) };
  }

  /// Ground point seen at pixel (i, j) (scene coordinates) and its class, ignoring shadows.
  PixelClass Classify(int i, int j, glm::dvec3& ground)
  {
    const Ray ray = this->PixelRay(i, j);
    const double t = -ray.Origin.z / ray.Direction.z;
    ground = ray.Origin + t * ray.Direction;
    if (HitSphere(ray, this->SphereCentre, this->SphereRadius) > 0.0)
    {
      return SphereClass;
    }
    if (t <= 0.0 || std::abs(ground.x) > this->GroundHalf || std::abs(ground.y) > this->GroundHalf)
    {
      return Background;
    }
    return GroundLit;
  }

  /// Window depth VTK assigns to a scene point.
  double Depth(const glm::dvec3& p)
  {
    const glm::dvec3 w = p + this->Offset;
    this->Renderer->SetWorldPoint(w.x, w.y, w.z, 1.0);
    this->Renderer->WorldToDisplay();
    return this->Renderer->GetDisplayPoint()[2];
  }
};

/// Per-pixel classes and ground points of the scene as it is placed now.
struct Analytic
{
  std::vector<int> Class;
  std::vector<glm::dvec3> Ground;

  explicit Analytic(AnalyticScene& scene)
    : Class(Width * Height)
    , Ground(Width * Height)
  {
    for (int j = 0; j < Height; ++j)
    {
      for (int i = 0; i < Width; ++i)
      {
        this->Class[j * Width + i] = scene.Classify(i, j, this->Ground[j * Width + i]);
      }
    }
  }

  /// True when every pixel within `margin` pixels (square) has the same class.
  bool Interior(int i, int j, int margin) const
  {
    const int c = this->Class[j * Width + i];
    for (int dj = -margin; dj <= margin; ++dj)
    {
      for (int di = -margin; di <= margin; ++di)
      {
        const int x = i + di, y = j + dj;
        if (x < 0 || y < 0 || x >= Width || y >= Height || this->Class[y * Width + x] != c)
        {
          return false;
        }
      }
    }
    return true;
  }
};

const float* Values(vtkImageData* image)
{
  return static_cast<const float*>(image->GetScalarPointer());
}

vtkSmartPointer<vtkLight> NewLight(const glm::dvec3& position, bool positional, double radius)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPositional(positional);
  light->SetPosition(position.x, position.y, position.z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetConeAngle(90.0);
  vtkSoftShadowPass::SetLightRadius(light, radius);
  return light;
}

/// Sets the only shadowing light of the scene (placed relative to the scene's offset).
void SetLight(
  AnalyticScene& scene, vtkLight* light, const glm::dvec3& position, const glm::dvec3& focal)
{
  scene.Renderer->RemoveAllLights();
  const glm::dvec3 p = position + scene.Offset, f = focal + scene.Offset;
  light->SetPosition(p.x, p.y, p.z);
  light->SetFocalPoint(f.x, f.y, f.z);
  scene.Renderer->AddLight(light);
}

void Progress(vtkObject*, unsigned long, void* clientData, void* callData)
{
  static_cast<std::vector<double>*>(clientData)->push_back(*static_cast<double*>(callData));
}

// ---------------------------------------------------------------------------------------------
// 1. Hard shadow of a sphere from a point light (also checks depth, light indices, progress).

const glm::dvec3 PointLightPosition(2.5, 1.5, 4.0);

struct HardResult
{
  long Shadowed = 0;
  std::vector<float> Visibility;
  std::vector<float> Depth;
};

HardResult TestHardShadow(AnalyticScene& scene, bool verbose)
{
  // Light 0 a headlight, light 2 switched off, light 3 without intensity and light 4 with a
  // shadow attenuation of 0: none gets an image.
  scene.Renderer->RemoveAllLights();
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  auto point = NewLight(PointLightPosition + scene.Offset, true, 0.0);
  point->SetFocalPoint(scene.Offset.x, scene.Offset.y, scene.Offset.z);
  auto off = NewLight(PointLightPosition + scene.Offset, true, 0.0);
  off->SwitchOff();
  auto dark = NewLight(PointLightPosition + scene.Offset, true, 0.0);
  dark->SetIntensity(0.0);
  auto unshadowing = NewLight(PointLightPosition + scene.Offset, true, 0.0);
  unshadowing->SetShadowAttenuation(0.0);
  scene.Renderer->AddLight(headlight);
  scene.Renderer->AddLight(point);
  scene.Renderer->AddLight(off);
  scene.Renderer->AddLight(dark);
  scene.Renderer->AddLight(unshadowing);
  scene.Render();

  vtkNew<vtkRayTracedVisibility> tracer;
  tracer->SetRenderer(scene.Renderer);
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetCallback(Progress);
  observer->SetClientData(&progress);
  tracer->AddObserver(vtkCommand::ProgressEvent, observer);
  const bool updated = tracer->Update();

  HardResult result;
  if (verbose)
  {
    Check(updated, "Update() succeeds");
    Check(tracer->GetVisibilityImage(0) == nullptr, "headlight (light 0) has no image");
    Check(tracer->GetVisibilityImage(2) == nullptr, "switched-off light (light 2) has no image");
    Check(tracer->GetVisibilityImage(3) == nullptr, "light of intensity 0 (light 3) has no image");
    Check(tracer->GetVisibilityImage(4) == nullptr,
      "light of shadow attenuation 0 (light 4) has no image");
    Check(tracer->GetVisibilityImage(5) == nullptr, "index past the lights has no image");
    Check(tracer->GetNumberOfShadowingLights() == 1, "one shadowing light");
    std::printf("    triangles %lld (casters %lld)\n",
      static_cast<long long>(tracer->GetNumberOfTriangles()),
      static_cast<long long>(tracer->GetNumberOfCasterTriangles()));
    scene.SphereSource->Update();
    Check(tracer->GetNumberOfTriangles() == 2 + scene.SphereSource->GetOutput()->GetNumberOfPolys(),
      "every sphere and ground triangle traced");
    bool monotone = progress.size() >= 2 && progress.front() == 0.0 && progress.back() == 1.0;
    for (std::size_t k = 1; k < progress.size(); ++k)
    {
      monotone = monotone && progress[k] >= progress[k - 1];
    }
    std::printf("    %zu progress events\n", progress.size());
    Check(monotone, "progress events rise from 0 to 1");
  }
  vtkImageData* image = tracer->GetVisibilityImage(1);
  if (!updated || !image || !tracer->GetDepthImage())
  {
    Check(false, "point light (light 1) has a visibility image");
    return result;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (verbose)
  {
    Check(dims[0] == Width && dims[1] == Height && dims[2] == 1 &&
        image->GetScalarType() == VTK_FLOAT && image->GetNumberOfScalarComponents() == 1,
      "visibility image is 1-component float of the viewport's size");
  }
  const float* visibility = Values(image);
  const float* depth = Values(tracer->GetDepthImage());
  result.Visibility.assign(visibility, visibility + Width * Height);
  result.Depth.assign(depth, depth + Width * Height);

  Analytic analytic(scene);
  const glm::dvec3 light = PointLightPosition;
  for (int p = 0; p < Width * Height; ++p)
  {
    if (analytic.Class[p] == GroundLit &&
      SegmentHitsSphere(analytic.Ground[p], light, scene.SphereCentre, scene.SphereRadius))
    {
      analytic.Class[p] = GroundShadowed;
    }
  }
  long expectedShadowed = 0, shadowed = 0, compared = 0, mismatched = 0, notBinary = 0;
  long backgroundWrong = 0;
  double depthError = 0.0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      const int p = j * Width + i;
      const int c = analytic.Class[p];
      notBinary += visibility[p] != 0.0f && visibility[p] != 1.0f;
      if (c == Background && analytic.Interior(i, j, 2))
      {
        backgroundWrong += visibility[p] != 1.0f || depth[p] != 1.0f;
      }
      if (c != GroundLit && c != GroundShadowed)
      {
        continue;
      }
      expectedShadowed += c == GroundShadowed;
      shadowed += visibility[p] < 0.5f;
      if (analytic.Interior(i, j, 2))
      {
        ++compared;
        mismatched += (visibility[p] < 0.5f) != (c == GroundShadowed);
        depthError =
          penumbra_test::Worse(depthError, std::abs(depth[p] - scene.Depth(analytic.Ground[p])));
      }
    }
  }
  result.Shadowed = shadowed;
  if (!verbose)
  {
    return result;
  }
  const double areaError =
    std::abs(static_cast<double>(shadowed - expectedShadowed)) / std::max(1L, expectedShadowed);
  std::printf("    shadowed ground pixels: traced %ld, analytic %ld (relative error %.4f, "
              "tolerance 0.02)\n",
    shadowed, expectedShadowed, areaError);
  Check(expectedShadowed > 500 && areaError < 0.02, "shadow area matches the exact sphere");
  std::printf("    pixels >2 px from any boundary: %ld compared, %ld disagree (tolerance 0)\n",
    compared, mismatched);
  Check(compared > 5000 && mismatched == 0, "per-pixel hard shadow away from boundaries");
  std::printf("    values other than 0 and 1: %ld (tolerance 0)\n", notBinary);
  Check(notBinary == 0, "a light of radius 0 gives only 0 and 1");
  std::printf("    background pixels not (visibility 1, depth 1): %ld\n", backgroundWrong);
  Check(backgroundWrong == 0, "background pixels have visibility 1 and depth 1");
  std::printf(
    "    ground depth vs VTK's WorldToDisplay: max error %.3g (tolerance 1e-6)\n", depthError);
  Check(depthError < 1e-6, "depth image holds window depth of the ground plane");

  // The rasterizer must have put the same surfaces at the same depths in the same pixels.
  const std::vector<float> zbuffer = penumbra_test::WindowDepth(scene.Window, scene.Renderer);
  double groundZ = 0.0, sphereZ = 0.0;
  long coverage = 0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      const int p = j * Width + i;
      coverage += (depth[p] < 1.0f) != (zbuffer[p] < 1.0f);
      if (!analytic.Interior(i, j, 1) || analytic.Class[p] == Background)
      {
        continue;
      }
      double& worst = analytic.Class[p] == SphereClass ? sphereZ : groundZ;
      worst = penumbra_test::Worse(worst, static_cast<double>(std::abs(depth[p] - zbuffer[p])));
    }
  }
  std::printf("    depth vs rasterized z-buffer away from edges: ground max %.3g, sphere max "
              "%.3g (tolerance 1e-5)\n",
    groundZ, sphereZ);
  Check(groundZ < 1e-5 && sphereZ < 1e-5, "traced depth lines up with the rasterized depth");
  std::printf("    pixels covered by one of rasterizer and tracer only: %ld (tolerance 0.1%% = "
              "%d)\n",
    coverage, Width * Height / 1000);
  Check(coverage <= Width * Height / 1000, "traced coverage matches the rasterized coverage");
  return result;
}

// ---------------------------------------------------------------------------------------------
// 2./3. Penumbrae against the cap-intersection closed form.

struct PenumbraStats
{
  double MeanError = 0.0;
  double MaxError = 0.0;
  long Pixels = 0;    ///< compared (analytic strictly inside the penumbra)
  long Penumbra = 0;  ///< traced values strictly between 0 and 1 in the band
  long NotBinary = 0; ///< traced values other than 0 and 1 anywhere
};

/// Compares a band of rows through the image centre with `expected(groundPoint)`.
template <typename Expected>
PenumbraStats MeasurePenumbra(const Analytic& analytic, vtkImageData* image, Expected expected)
{
  PenumbraStats stats;
  if (!image)
  {
    return stats;
  }
  const float* visibility = Values(image);
  double sum = 0.0;
  for (int p = 0; p < Width * Height; ++p)
  {
    stats.NotBinary += visibility[p] != 0.0f && visibility[p] != 1.0f;
  }
  for (int j = Height / 2 - 8; j < Height / 2 + 8; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      const int p = j * Width + i;
      if (analytic.Class[p] != GroundLit || !analytic.Interior(i, j, 1))
      {
        continue;
      }
      stats.Penumbra += visibility[p] > 0.0f && visibility[p] < 1.0f;
      const double v = expected(analytic.Ground[p]);
      if (v <= 1e-9 || v >= 1.0 - 1e-9)
      {
        continue;
      }
      const double e = std::abs(visibility[p] - v);
      sum += e;
      stats.MaxError = penumbra_test::Worse(stats.MaxError, e);
      ++stats.Pixels;
    }
  }
  stats.MeanError = stats.Pixels ? sum / stats.Pixels : 1.0;
  return stats;
}

const glm::dvec3 SphericalLightPosition(3.0, 0.0, 4.0);
constexpr double SphericalLightRadius = 0.5;

void TestSphericalLight(AnalyticScene& scene)
{
  std::printf("2. Spherical light (radius %.2f) over a sphere occluder:\n", SphericalLightRadius);
  auto light = NewLight(glm::dvec3(0.0), true, SphericalLightRadius);
  SetLight(scene, light, SphericalLightPosition, glm::dvec3(0.0));
  scene.Render();
  Analytic analytic(scene);
  auto expected = [&](const glm::dvec3& q)
  {
    const glm::dvec3 toLight = SphericalLightPosition - q, toSphere = scene.SphereCentre - q;
    const double dL = glm::length(toLight), dO = glm::length(toSphere);
    return VisibleFraction(toLight / dL, std::asin(SphericalLightRadius / dL), toSphere / dO,
      std::asin(scene.SphereRadius / dO));
  };
  vtkNew<vtkRayTracedVisibility> tracer;
  tracer->SetRenderer(scene.Renderer);
  const int counts[] = { 16, 64, 256 };
  double mae[3];
  for (int k = 0; k < 3; ++k)
  {
    tracer->SetSamplesPerLight(counts[k]);
    tracer->Update();
    const PenumbraStats stats = MeasurePenumbra(analytic, tracer->GetVisibilityImage(0), expected);
    mae[k] = stats.MeanError;
    std::printf("    %3d samples: %ld penumbra pixels, mean abs error %.5f, max %.4f\n", counts[k],
      stats.Pixels, stats.MeanError, stats.MaxError);
    if (k == 0)
    {
      Check(stats.Pixels > 100, "the band crosses a wide penumbra");
    }
  }
  Check(mae[1] < mae[0] && mae[2] < mae[1], "error shrinks as samples grow (16 > 64 > 256)");
  std::printf("    tolerance: MAE(256) < 0.01\n");
  Check(mae[2] < 0.01, "256-sample penumbra matches the closed form");
}

const glm::dvec3 DirectionalToward(1.0, 0.0, 1.0);

void TestDirectionalLight(AnalyticScene& scene)
{
  std::printf("3. Directional light with an angular radius:\n");
  auto light = NewLight(glm::dvec3(0.0), false, 0.0);
  SetLight(scene, light, DirectionalToward, glm::dvec3(0.0));
  scene.Render();
  Analytic analytic(scene);
  const glm::dvec3 toward = glm::normalize(DirectionalToward);
  vtkNew<vtkRayTracedVisibility> tracer;
  tracer->SetRenderer(scene.Renderer);
  tracer->SetSamplesPerLight(256);
  const double angles[] = { 0.0, 2.0, 5.0, 10.0 };
  long penumbra[4];
  for (int k = 0; k < 4; ++k)
  {
    vtkSoftShadowPass::SetLightRadius(light, angles[k]);
    tracer->Update();
    const double aL = angles[k] * Pi / 180.0;
    auto expected = [&](const glm::dvec3& q)
    {
      const glm::dvec3 toSphere = scene.SphereCentre - q;
      const double dO = glm::length(toSphere);
      if (aL == 0.0)
      {
        // Hard: blocked iff the ray toward the light meets the exact sphere.
        return SegmentHitsSphere(q, q + 100.0 * toward, scene.SphereCentre, scene.SphereRadius)
          ? 0.0
          : 1.0;
      }
      return VisibleFraction(toward, aL, toSphere / dO, std::asin(scene.SphereRadius / dO));
    };
    const PenumbraStats stats = MeasurePenumbra(analytic, tracer->GetVisibilityImage(0), expected);
    penumbra[k] = stats.Penumbra;
    if (k == 0)
    {
      std::printf("    %4.1f deg: %ld band pixels in penumbra, %ld image values other than 0 "
                  "and 1 (tolerance 0)\n",
        angles[k], stats.Penumbra, stats.NotBinary);
      Check(stats.NotBinary == 0, "angular radius 0 gives only 0 and 1");
    }
    else
    {
      std::printf("    %4.1f deg: %ld band pixels in penumbra, %ld compared, mean abs error %.5f, "
                  "max %.4f\n",
        angles[k], stats.Penumbra, stats.Pixels, stats.MeanError, stats.MaxError);
      Check(stats.Pixels > 20 && stats.MeanError < 0.01,
        "penumbra matches the closed form (256 samples, MAE tolerance 0.01)");
    }
  }
  Check(penumbra[0] == 0 && penumbra[1] < penumbra[2] && penumbra[2] < penumbra[3],
    "penumbra widens with the angular radius");
}

// ---------------------------------------------------------------------------------------------
// 4. Caster exclusion, thread independence, errors.

void TestCasterExclusion(AnalyticScene& scene)
{
  std::printf("4. Sphere excluded from casting:\n");
  auto light = NewLight(glm::dvec3(0.0), true, SphericalLightRadius);
  SetLight(scene, light, SphericalLightPosition, glm::dvec3(0.0));
  vtkSoftShadowPass::SetCastsShadows(scene.Sphere, false);
  scene.Render();
  Analytic analytic(scene);
  vtkNew<vtkRayTracedVisibility> tracer;
  tracer->SetRenderer(scene.Renderer);
  tracer->SetSamplesPerLight(16);
  tracer->Update();
  vtkSoftShadowPass::SetCastsShadows(scene.Sphere, true);
  vtkImageData* image = tracer->GetVisibilityImage(0);
  if (!image)
  {
    Check(false, "light has an image");
    return;
  }
  const float* visibility = Values(image);
  const float* depth = Values(tracer->GetDepthImage());
  long shadowedGround = 0, spherePixels = 0, sphereSeen = 0;
  for (int j = 0; j < Height; ++j)
  {
    for (int i = 0; i < Width; ++i)
    {
      const int p = j * Width + i;
      if (analytic.Class[p] == GroundLit && analytic.Interior(i, j, 1))
      {
        shadowedGround += visibility[p] < 1.0f;
      }
      if (analytic.Class[p] == SphereClass && analytic.Interior(i, j, 1))
      {
        // The non-caster is still seen: nearer than the ground behind it.
        ++spherePixels;
        sphereSeen += depth[p] < scene.Depth(analytic.Ground[p]) - 1e-4;
      }
    }
  }
  std::printf("    shadowed ground pixels %ld (tolerance 0); caster triangles %lld\n",
    shadowedGround, static_cast<long long>(tracer->GetNumberOfCasterTriangles()));
  Check(shadowedGround == 0, "no ground pixel shadowed by a non-caster");
  Check(tracer->GetNumberOfCasterTriangles() == 2, "only the ground casts");
  std::printf("    sphere pixels seen by primary rays: %ld of %ld\n", sphereSeen, spherePixels);
  Check(
    sphereSeen == spherePixels && spherePixels > 100, "non-casters are still hit by primary rays");
}

void TestThreadsAndErrors(AnalyticScene& scene)
{
  std::printf("5. Threads, seeds and errors:\n");
  auto light = NewLight(glm::dvec3(0.0), true, SphericalLightRadius);
  SetLight(scene, light, SphericalLightPosition, glm::dvec3(0.0));
  scene.Render();
  vtkNew<vtkRayTracedVisibility> one, two;
  for (vtkRayTracedVisibility* tracer : { one.Get(), two.Get() })
  {
    tracer->SetRenderer(scene.Renderer);
    tracer->SetSamplesPerLight(9);
  }
  one->SetNumberOfThreads(1);
  two->SetNumberOfThreads(3);
  one->Update();
  two->Update();
  const float* a = Values(one->GetVisibilityImage(0));
  const float* b = Values(two->GetVisibilityImage(0));
  long differ = 0;
  for (int p = 0; p < Width * Height; ++p)
  {
    differ += a[p] != b[p];
  }
  std::printf("    1 vs 3 threads: %ld pixels differ\n", differ);
  Check(differ == 0, "results do not depend on the number of threads");
  two->SetSeed(2);
  two->Update();
  b = Values(two->GetVisibilityImage(0));
  differ = 0;
  for (int p = 0; p < Width * Height; ++p)
  {
    differ += a[p] != b[p];
  }
  std::printf("    seed 1 vs seed 2: %ld pixels differ\n", differ);
  Check(differ > 0, "the seed drives the jitter");

  vtkNew<vtkRayTracedVisibility> lonely;
  const int warnings = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  const bool updated = lonely->Update();
  vtkObject::SetGlobalWarningDisplay(warnings);
  Check(!updated && lonely->GetDepthImage() == nullptr, "Update() without a renderer fails");
}

} // namespace

int TestRayTracedVisibility(int, char*[])
{
  const auto start = std::chrono::steady_clock::now();
  CheckCapFormula();

  AnalyticScene scene;
  std::printf("1. Hard shadow of a sphere from a point light:\n");
  const HardResult near = TestHardShadow(scene, true);
  TestSphericalLight(scene);
  TestDirectionalLight(scene);
  TestCasterExclusion(scene);
  TestThreadsAndErrors(scene);

  // 6. Parallel projection: the same unprojection must give rays along the view direction.
  std::printf("6. Parallel projection (all of test 1 again):\n");
  scene.Renderer->GetActiveCamera()->ParallelProjectionOn();
  scene.Renderer->GetActiveCamera()->SetParallelScale(3.0);
  TestHardShadow(scene, true);
  scene.Renderer->GetActiveCamera()->ParallelProjectionOff();

  // 7. The same hard shadow a million units away: Embree's float must not see the offset.
  std::printf("7. Scene moved by (1e6, -2e6, 5e5):\n");
  scene.Place(glm::dvec3(1e6, -2e6, 5e5));
  const HardResult far = TestHardShadow(scene, false);
  long differ = 0;
  double depthDiff = 0.0;
  if (far.Visibility.size() == near.Visibility.size())
  {
    for (std::size_t p = 0; p < near.Visibility.size(); ++p)
    {
      differ += near.Visibility[p] != far.Visibility[p];
      depthDiff = penumbra_test::Worse(
        depthDiff, static_cast<double>(std::abs(near.Depth[p] - far.Depth[p])));
    }
  }
  std::printf("    shadowed pixels %ld (at origin %ld); %ld pixels differ (tolerance 0.5%% of "
              "shadowed); depth max diff %.3g (tolerance 1e-5)\n",
    far.Shadowed, near.Shadowed, differ, depthDiff);
  Check(!far.Visibility.empty() && differ <= near.Shadowed / 200 && depthDiff < 1e-5,
    "far from the origin the image is the same");

  // 8. Points that no triangle uses, a million units away (as PLY, OBJ and scanner files hold):
  // the traced box, and the origin and epsilon taken from it, must ignore them (4,051 pixels
  // lost their shadow in a user trial when the epsilon grew to 16 units).
  std::printf("8. The sphere's data with two unused points 1e6 away:\n");
  scene.Place(glm::dvec3(0.0));
  scene.SphereSource->Update();
  vtkNew<vtkPolyData> strays;
  strays->DeepCopy(scene.SphereSource->GetOutput());
  strays->GetPoints()->InsertNextPoint(1e6, 0.0, 0.0);
  strays->GetPoints()->InsertNextPoint(-1e6, 1e6, 0.0);
  auto sphereMapper = vtkPolyDataMapper::SafeDownCast(scene.Sphere->GetMapper());
  sphereMapper->SetInputData(strays);
  const HardResult unused = TestHardShadow(scene, false);
  sphereMapper->SetInputConnection(scene.SphereSource->GetOutputPort());
  long unusedDiffer = 0;
  for (std::size_t p = 0; p < unused.Visibility.size() && p < near.Visibility.size(); ++p)
  {
    unusedDiffer += unused.Visibility[p] != near.Visibility[p];
  }
  std::printf("    shadowed pixels %ld (without them %ld); %ld pixels differ (tolerance 0.5%% of "
              "shadowed)\n",
    unused.Shadowed, near.Shadowed, unusedDiffer);
  Check(unused.Visibility.size() == near.Visibility.size() && unusedDiffer <= near.Shadowed / 200,
    "unused far points change nothing");

  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%d failure(s), %.1f s\n", Failures, seconds);
  return Failures ? EXIT_FAILURE : EXIT_SUCCESS;
}

int main(int argc, char* argv[])
{
  return TestRayTracedVisibility(argc, argv);
}
