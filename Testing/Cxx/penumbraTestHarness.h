// Shared helpers of the rendering tests: scene building and comparison of the pass's visibility
// with the ray-traced truth.
#ifndef penumbraTestHarness_h
#define penumbraTestHarness_h

#include "penumbraCheck.h"
#include "penumbraMetrics.h"
#include "penumbraSceneDescription.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRayTracedVisibility.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowPass.h"
#include "vtkSphereSource.h"
#include "vtkTrivialProducer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

// Xlib's own header defines macros (None, Status, Bool...) that the tests' code must not see.
extern "C"
{
  struct _XDisplay;
  _XDisplay* XOpenDisplay(const char* name);
}

namespace penumbra_test
{

/**
 * The process's X connection, retried: Xvfb refuses a few percent of rapid connects, the first
 * one of a test process included (seen as "bad X server connection ... Aborting" from VTK, which
 * does not retry). Null after 50 tries, 100 ms apart; VTK then reports it.
 */
inline void* OpenDisplayWithRetries()
{
  for (int attempt = 0; attempt < 50; ++attempt)
  {
    if (_XDisplay* display = XOpenDisplay(nullptr))
    {
      return display;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return nullptr;
}

/**
 * An offscreen render window sharing one X connection with every other window of the process.
 * VTK opens a connection per window, and Xvfb refuses a few percent of rapid reconnects
 * ("connection reset by peer"; measured 17 of 300 here), which would make tests flaky.
 */
inline vtkSmartPointer<vtkRenderWindow> NewRenderWindow()
{
  static vtkSmartPointer<vtkRenderWindow> anchor;
  if (!anchor)
  {
    anchor = vtkSmartPointer<vtkRenderWindow>::New();
    if (void* display = OpenDisplayWithRetries())
    {
      anchor->SetDisplayId(display);
    }
    anchor->SetOffScreenRendering(1);
    anchor->SetSize(1, 1);
    anchor->Render();
  }
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetDisplayId(anchor->GetGenericDisplayId());
  window->SetOffScreenRendering(1);
  return window;
}

inline vtkSmartPointer<vtkActor> MakeActor(vtkAlgorithm* source, double r, double g, double b)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetAmbient(0.2);
  actor->GetProperty()->SetDiffuse(0.8);
  return actor;
}

/// A positional scene light at `position` shining all round (cone 180), added to `renderer`.
inline vtkSmartPointer<vtkLight> AddSceneLight(vtkRenderer* renderer, double x, double y, double z)
{
  auto light = penumbra::scene::MakeLight(true, { x, y, z }, 0.0);
  renderer->AddLight(light);
  return light;
}

/// A square ground of half-width `half` in the plane y = height, 4 x 4 quads.
inline vtkSmartPointer<vtkPlaneSource> GroundSource(double half, double height = 0.0)
{
  auto plane = vtkSmartPointer<vtkPlaneSource>::New();
  plane->SetOrigin(-half, height, -half);
  plane->SetPoint1(half, height, -half);
  plane->SetPoint2(-half, height, half);
  plane->SetResolution(4, 4);
  return plane;
}

inline vtkSmartPointer<vtkSphereSource> SphereSource(
  double x, double y, double z, double radius, int thetaResolution, int phiResolution)
{
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetThetaResolution(thetaResolution);
  sphere->SetPhiResolution(phiResolution);
  sphere->SetRadius(radius);
  sphere->SetCenter(x, y, z);
  return sphere;
}

inline vtkSmartPointer<vtkCubeSource> BoxSource(
  double x, double y, double z, double sx, double sy, double sz)
{
  auto cube = vtkSmartPointer<vtkCubeSource>::New();
  cube->SetCenter(x, y, z);
  cube->SetXLength(sx);
  cube->SetYLength(sy);
  cube->SetZLength(sz);
  return cube;
}

/// The warnings (or, given vtkCommand::ErrorEvent, the errors) an object sends from construction
/// on, and how many of them contain a text.
struct WarningLog
{
  std::vector<std::string> Messages;
  vtkNew<vtkCallbackCommand> Callback;

  explicit WarningLog(vtkObject* source, unsigned long event = vtkCommand::WarningEvent)
  {
    this->Callback->SetClientData(&this->Messages);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long, void* client, void* text) {
        static_cast<std::vector<std::string>*>(client)->push_back(static_cast<const char*>(text));
      });
    source->AddObserver(event, this->Callback);
  }
  std::ptrdiff_t Count(const std::string& needle) const
  {
    return std::count_if(this->Messages.begin(), this->Messages.end(),
      [&](const std::string& message) { return message.find(needle) != std::string::npos; });
  }
};

/// Pixels where two visibility images are more than 0.5 apart; a pixel one of them lacks counts.
inline int PixelsApart(const std::vector<float>& a, const std::vector<float>& b)
{
  int apart = static_cast<int>(std::max(a.size(), b.size()) - std::min(a.size(), b.size()));
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    apart += std::abs(a[i] - b[i]) > 0.5f;
  }
  return apart;
}

/// The values of a float image (a visibility or depth image), in VTK's point order.
inline std::vector<float> ImageValues(vtkImageData* image)
{
  auto values = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  return std::vector<float>(
    values->GetPointer(0), values->GetPointer(0) + values->GetNumberOfValues());
}

/// Of the pixels either of two visibility images shadows (`Shadowed`), the shares where they
/// differ by more than 1/N and by more than one half: how two methods that sample a light at
/// the same N points are held to each other; and the share where they differ at all (by more
/// than 1e-3), which a pixel-boundary flip of one sample does too.
struct SampleAgreement
{
  int Shadowed = 0;
  double Step = 1.0;
  double Half = 1.0;
  double Any = 1.0;
};

inline SampleAgreement CompareSampledVisibility(
  const std::vector<float>& a, const std::vector<float>& b, int samples)
{
  SampleAgreement agreement;
  int offStep = 0, offHalf = 0, offAny = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    if (!(a[i] < 1.0f || b[i] < 1.0f))
    {
      continue;
    }
    ++agreement.Shadowed;
    const float difference = std::abs(a[i] - b[i]);
    offStep += difference > 1.0f / samples + 1e-4f;
    offHalf += difference > 0.5f;
    offAny += difference > 1e-3f;
  }
  if (agreement.Shadowed)
  {
    agreement.Step = double(offStep) / agreement.Shadowed;
    agreement.Half = double(offHalf) / agreement.Shadowed;
    agreement.Any = double(offAny) / agreement.Shadowed;
  }
  return agreement;
}

/// The window's depth buffer over the renderer's viewport, in the truth's depth image's order.
inline std::vector<float> WindowDepth(vtkRenderWindow* window, vtkRenderer* renderer)
{
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  std::vector<float> zbuffer(static_cast<std::size_t>(size[0]) * size[1]);
  window->GetZbufferData(
    origin[0], origin[1], origin[0] + size[0] - 1, origin[1] + size[1] - 1, zbuffer.data());
  return zbuffer;
}

/// The window's colours over the renderer's viewport, 3 bytes a pixel, row 0 at the bottom.
inline std::vector<unsigned char> WindowColours(vtkRenderWindow* window, vtkRenderer* renderer)
{
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(
    origin[0], origin[1], origin[0] + size[0] - 1, origin[1] + size[1] - 1, 0, rgb);
  return std::vector<unsigned char>(
    rgb->GetPointer(0), rgb->GetPointer(0) + rgb->GetNumberOfValues());
}

/// The error of a light's visibility image against the truth's image of that light, over the
/// pixels either shadows where the window's surface (`zbuffer`) is the truth's: the
/// benchmark's measure (penumbra::metrics::CompareVisibility).
inline penumbra::metrics::ErrorStats VisibilityError(const std::vector<float>& visibility,
  vtkRayTracedVisibility* truth, int lightIndex, const std::vector<float>& zbuffer)
{
  const std::vector<float> expected = ImageValues(truth->GetVisibilityImage(lightIndex));
  const std::vector<float> depth = ImageValues(truth->GetDepthImage());
  if (expected.size() != visibility.size() || depth.size() != visibility.size() ||
    zbuffer.size() != visibility.size())
  {
    Check(false, "visibility, truth and depth images of one size");
    return penumbra::metrics::ErrorStats();
  }
  penumbra::metrics::ErrorStats stats = penumbra::metrics::CompareVisibility(
    visibility.data(), expected.data(), depth.data(), zbuffer.data(), visibility.size());
  if (stats.Pixels == 0)
  {
    Check(false, "pixels to compare with the truth");
    stats.MAE = 1.0; // nothing compared is no evidence of agreement
  }
  return stats;
}

/// Result of comparing the pass's hard-shadow visibility with the ray-traced truth.
struct Comparison
{
  int Compared = 0;   ///< pixels where both see the same surface
  int Shadowed = 0;   ///< of those, in shadow according to the truth
  int Boundary = 0;   ///< disagreements within one pixel of a truth shadow boundary
  int Mismatched = 0; ///< disagreements elsewhere: wrong shadows
  double MismatchFraction() const
  {
    return this->Compared ? double(this->Mismatched) / this->Compared : 1.0;
  }
};

/**
 * Compares the last frame's visibility of light `lightIndex` with a fresh ray-traced truth.
 * Pixels are compared where the rasterized and ray-traced depths agree and no neighbour sits
 * across an object silhouette. A disagreement within one pixel of a truth shadow boundary is
 * rasterization, not an error (sampling and tessellation move edges by up to a pixel).
 * `zbuffer`, when given, is the rasterized depth (when the window's is not the scene's: a pass
 * around this one kept it in a framebuffer of its own).
 */
/// Compares `actual`, a visibility image of the viewport's size, with the truth's for light
/// `lightIndex`, where `zbuffer` (the viewport's depth) shows the truth's surfaces.
inline Comparison CompareValuesWithTruth(vtkRenderer* renderer, const std::vector<float>& actual,
  int lightIndex, const std::vector<float>& zbuffer)
{
  Comparison result;
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(renderer);
  truth->SetSamplesPerLight(1);
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  if (!truth->Update() || !truth->GetVisibilityImage(lightIndex) ||
    actual.size() != std::size_t(size[0]) * size[1])
  {
    Check(false, "visibility images available for light " + std::to_string(lightIndex));
    return result;
  }
  const std::vector<float> expected = ImageValues(truth->GetVisibilityImage(lightIndex));
  const std::vector<char> comparable = penumbra::metrics::ComparablePixels(
    ImageValues(truth->GetDepthImage()), zbuffer, size[0], size[1]);
  for (std::size_t p = 0; p < comparable.size(); ++p)
  {
    if (!comparable[p])
    {
      continue;
    }
    ++result.Compared;
    result.Shadowed += expected[p] < 0.5f;
    if (std::abs(expected[p] - actual[p]) > 0.5f)
    {
      const bool displaced =
        penumbra::metrics::NearTruthValue(expected, size[0], p, actual[p], 0.5f);
      ++(displaced ? result.Boundary : result.Mismatched);
    }
  }
  return result;
}

/// The pass's visibility image for light `lightIndex` against the truth, where the window's
/// depth (or `zbuffer`, where the window does not keep the scene's) shows the truth's surfaces.
inline Comparison CompareWithTruth(vtkRenderWindow* window, vtkRenderer* renderer,
  vtkSoftShadowPass* pass, int lightIndex, const std::vector<float>* zbuffer = nullptr)
{
  vtkImageData* image = pass->GetVisibilityImage(lightIndex);
  if (!image)
  {
    Check(false, "visibility images available for light " + std::to_string(lightIndex));
    return Comparison();
  }
  return CompareValuesWithTruth(
    renderer, ImageValues(image), lightIndex, zbuffer ? *zbuffer : WindowDepth(window, renderer));
}

/// Checks a comparison against the stated tolerance: at most 0.2% of the compared pixels wrong
/// away from shadow boundaries, and a scene that really has shadow in view.
inline void CheckAgainstTruth(
  const std::string& name, const Comparison& c, double minShadowed = 0.01)
{
  std::printf("     %s: compared %d px, shadowed %d, boundary %d, wrong %d (%.3f%%)\n",
    name.c_str(), c.Compared, c.Shadowed, c.Boundary, c.Mismatched, 100.0 * c.MismatchFraction());
  Check(c.Compared > 0 && c.Shadowed >= minShadowed * c.Compared,
    name + ": shadow in view (" + std::to_string(c.Shadowed) + " px)");
  Check(c.MismatchFraction() <= 0.002, name + ": agrees with ray-traced truth");
}

/// Adds an actor of `source` in the tests' material (MakeActor) to `renderer`; `keep` holds the
/// source for as long as the scene lives.
inline vtkActor* AddActor(vtkRenderer* renderer, vtkAlgorithm* source, double r, double g, double b,
  std::vector<vtkSmartPointer<vtkObject>>& keep)
{
  auto actor = MakeActor(source, r, g, b);
  renderer->AddActor(actor);
  keep.push_back(source);
  return actor;
}

/// Puts the renderer's camera at p looking at f, y up, and resets its clipping range.
inline void PlaceCamera(
  vtkRenderer* renderer, double px, double py, double pz, double fx, double fy, double fz)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(px, py, pz);
  camera->SetFocalPoint(fx, fy, fz);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange();
}

/**
 * A window drawn through vtkSoftShadowPass, as every rendering test and the hard-case suite
 * build it: a first renderer (more with AddRenderer, each over its viewport with its own pass),
 * by default lit by the tests' positional scene light at (-2, 6, 3), helpers to add casters,
 * lights and a scene description, and the comparison of light `i`'s shadows with the truth.
 */
struct PassScene
{
  enum class StartLight
  {
    Default, ///< one positional scene light at (-2, 6, 3), without a radius: Light
    None     ///< no light: the test adds its own
  };

  vtkSmartPointer<vtkRenderWindow> Window = NewRenderWindow();
  std::vector<vtkSmartPointer<vtkRenderer>> Renderers;
  std::vector<vtkSmartPointer<vtkSoftShadowPass>> Passes;
  vtkRenderer* Renderer = nullptr;   ///< the first renderer
  vtkSoftShadowPass* Pass = nullptr; ///< its pass
  vtkSmartPointer<vtkLight> Light;   ///< the start light; null with StartLight::None
  std::vector<vtkSmartPointer<vtkObject>> Keep;

  explicit PassScene(int width = 200, int height = 150, StartLight start = StartLight::Default)
  {
    this->Window->SetSize(width, height);
    this->Renderer = this->AddRenderer(0, 0, 1, 1);
    this->Pass = this->Passes.front();
    if (start == StartLight::Default)
    {
      this->Light = AddSceneLight(this->Renderer, -2, 6, 3);
    }
  }

  /// Adds a renderer with its own pass over `viewport` (xmin, ymin, xmax, ymax).
  vtkRenderer* AddRenderer(double xmin, double ymin, double xmax, double ymax)
  {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    auto pass = vtkSmartPointer<vtkSoftShadowPass>::New();
    renderer->SetViewport(xmin, ymin, xmax, ymax);
    renderer->SetBackground(0.1, 0.1, 0.2);
    renderer->SetPass(pass);
    this->Window->AddRenderer(renderer);
    this->Renderers.push_back(renderer);
    this->Passes.push_back(pass);
    return renderer;
  }

  /// Puts a scene description's actors, lights and camera into the first renderer, in place of
  /// what it had; Light becomes the description's first light.
  void AddDescription(const penumbra::scene::Description& description)
  {
    description.AddTo(this->Renderer);
    this->Light = description.Lights.empty() ? nullptr : description.Lights.front();
  }

  /// A positional scene light with radius `radius` (0: point light), added to `renderer`.
  vtkLight* PointLight(double x, double y, double z, double radius, vtkRenderer* renderer = nullptr)
  {
    auto light = AddSceneLight(renderer ? renderer : this->Renderer, x, y, z);
    vtkSoftShadowPass::SetLightRadius(light, radius);
    return light;
  }

  /// A directional light from the direction (x, y, z), angular radius in degrees.
  vtkLight* DirectionalLight(double x, double y, double z, double degrees)
  {
    auto light = penumbra::scene::MakeLight(false, { x, y, z }, degrees);
    this->Renderer->AddLight(light);
    return light;
  }

  vtkActor* Add(vtkAlgorithm* source, double r, double g, double b, vtkRenderer* renderer = nullptr)
  {
    return AddActor(renderer ? renderer : this->Renderer, source, r, g, b, this->Keep);
  }

  vtkActor* AddData(vtkPolyData* data, double r, double g, double b)
  {
    vtkNew<vtkTrivialProducer> producer;
    producer->SetOutput(data);
    return this->Add(producer, r, g, b);
  }

  vtkActor* Ground(double half = 5.0, double height = 0.0)
  {
    return this->Add(GroundSource(half, height), 0.85, 0.85, 0.8);
  }

  /// A sphere of `resolution` segments round and half as many from pole to pole.
  vtkActor* Sphere(double x, double y, double z, double radius, int resolution = 40)
  {
    return this->Add(SphereSource(x, y, z, radius, resolution, resolution / 2), 0.9, 0.3, 0.3);
  }

  vtkActor* Box(double x, double y, double z, double sx, double sy, double sz)
  {
    return this->Add(BoxSource(x, y, z, sx, sy, sz), 0.3, 0.5, 0.9);
  }

  void Camera(double px, double py, double pz, double fx, double fy, double fz,
    vtkRenderer* renderer = nullptr)
  {
    PlaceCamera(renderer ? renderer : this->Renderer, px, py, pz, fx, fy, fz);
  }

  Comparison Render(int lightIndex = 0)
  {
    this->Window->Render();
    return CompareWithTruth(this->Window, this->Renderer, this->Pass, lightIndex);
  }
};

} // namespace penumbra_test

#endif
