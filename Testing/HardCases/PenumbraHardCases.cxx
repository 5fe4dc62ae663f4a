// PenumbraHardCases: runs the hard-case suite (penumbraHardCaseScenes.cxx) with every method of
// vtkSoftShadowPass, compares each with the ray-traced truth and prints one row per case and
// method. With --check it is a test: it fails on a leak, a NaN, a VTK error, an error above the
// stated limits or an image that no longer matches its baseline.
//
//   PenumbraHardCases [--group N]... [--case NAME]... [--check] [--baselines DIR]
//                     [--output DIR] [--report FILE.md] [--write-baselines]
//                     [--camera-offset D]
//
// --camera-offset moves every camera by (D, D/2, -D): a pixel-sized artefact that moves or
// vanishes under a tiny offset is numerical, one that stays is geometry.
// Metrics, per case and method, over every shadowing light of every renderer, at the pixels where
// the rasterized and the ray-traced surface agree and no neighbour lies across an object
// silhouette:
// - MAE: mean |visibility - truth| over the pixels where either is below 0.999; the truth has 256
//   samples per light, or one ray to the light's centre for the hard method;
// - >0.1: share of those pixels off by more than 0.1;
// - leaks: pixels off by more than 0.5 with no 3x3 neighbour whose truth is within 0.5 of the
//   pass's value (a shadow edge displaced by one pixel is rasterization, not a leak);
// - NaN: non-finite values in the light-intensity buffer (all pixels);
// - VTK errors and warnings logged while the case rendered;
// - worst step (temporal cases): the largest share of pixels, over the frame steps, whose
//   visibility changed by more than the truth's change + 0.1 (0.05 of it for the truth's noise);
// - vs ref (far-coordinate cases and tiles): share of pixels off by more than 0.1 from the
//   reference: the origin scene's visibility, or the untiled frame's luminance away from its
//   edges (VTK's tiles move edges by a fraction of a pixel).
//
// Pixels whose surface faces away from a light's centre, or is within 1 degree of edge-on, are
// not compared for that light: VTK's shading gives them nothing from it, whatever the visibility.
#include "penumbraHardCases.h"

#include "penumbraBenchSupport.h"
#include "penumbraMetrics.h"
#include "penumbraOptions.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageDifference.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkRayTracedVisibility.h"
#include "vtkRenderLargeImage.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <sys/stat.h>

using namespace penumbra_hard;

namespace
{

using penumbra::bench::vtkCountingOutputWindow;
using penumbra_test::ImageValues;
using penumbra_test::WindowDepth;

constexpr double DefaultMAE[METHOD_COUNT] = { 0.05, 0.04, 0.04, 0.04, 0.04, 0.04 };
constexpr double TemporalLimit = 0.005; ///< share of pixels popping in the worst step
constexpr double ReferenceLimit = 0.01; ///< share of pixels off by > 0.1 from the reference
/// Fewer compared pixels than this (either side shadowing) is no evidence of agreement: every
/// case has at least 262 (light_in_face_plane, hard).
constexpr std::size_t MinComparedPixels = 100;
constexpr double ImageThreshold = 10.0; ///< vtkTesting's usual image-difference threshold
/// vtkImageDifference averages and forgives shifted pixels: a baseline up to 140 levels off on
/// 7% of a panel's pixels passed it (2.6 against its limit of 10). Besides it, at most this share
/// of pixels may differ by more than ChangedLevels in a channel: that baseline has 2.9% (a shadow
/// edge moved by a pixel on another CPU stays far below).
constexpr double ChangedPixelsLimit = 0.01;
constexpr int ChangedLevels = 16;
constexpr int TruthSamples = 256;

struct Row
{
  std::size_t Pixels = 0, Over01 = 0, Leaks = 0, NonFinite = 0;
  double ErrorSum = 0.0;
  int Errors = 0, Warnings = 0, ShadowingLights = 0;
  double WorstStep = -1.0, Reference = -1.0;
  std::string FirstError;
  double MAE() const { return this->Pixels ? this->ErrorSum / this->Pixels : 0.0; }
};

/// What one renderer's frame holds for the comparison: images of the viewport's size.
struct View
{
  int Width = 0, Height = 0;
  std::vector<float> Depth;                   ///< truth window depth
  std::vector<float> ZBuffer;                 ///< rasterized depth
  std::vector<std::vector<float>> Soft, Hard; ///< truth per shadowing light
  std::vector<int> Lights;                    ///< light indices that shadow
  /// Per shadowing light: the surface faces the light's centre by more than 1 degree. Elsewhere
  /// VTK's shading gives the pixel no diffuse or specular light from it, so its visibility
  /// cannot change the image (and is undefined where the surface is edge-on to a point light).
  std::vector<std::vector<char>> Facing;
};

/// Ray-traced truth of one renderer: `samples` per light, or the lights' centres when hard.
std::vector<std::vector<float>> Truth(
  vtkRenderer* renderer, const std::vector<int>& lights, bool hard, std::vector<float>* depth)
{
  std::vector<double> radii;
  vtkLightCollection* collection = renderer->GetLights();
  if (hard)
  {
    for (int i = 0; i < collection->GetNumberOfItems(); ++i)
    {
      auto light = vtkLight::SafeDownCast(collection->GetItemAsObject(i));
      radii.push_back(vtkSoftShadowPass::GetLightRadius(light));
      vtkSoftShadowPass::SetLightRadius(light, 0.0);
    }
  }
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(renderer);
  truth->SetSamplesPerLight(TruthSamples);
  std::vector<std::vector<float>> images;
  if (truth->Update())
  {
    for (int index : lights)
    {
      images.push_back(ImageValues(truth->GetVisibilityImage(index)));
    }
    if (depth)
    {
      *depth = ImageValues(truth->GetDepthImage());
    }
  }
  for (std::size_t i = 0; i < radii.size(); ++i)
  {
    vtkSoftShadowPass::SetLightRadius(
      vtkLight::SafeDownCast(collection->GetItemAsObject(int(i))), radii[i]);
  }
  return images;
}

/// Which pixels face each shadowing light, from the surface positions the truth's depth gives.
void ComputeFacing(vtkRenderer* renderer, View& view)
{
  const int w = view.Width, h = view.Height;
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkNew<vtkMatrix4x4> toWorld;
  toWorld->DeepCopy(camera->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1));
  toWorld->Invert();
  std::vector<glm::dvec3> world(view.Depth.size());
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const std::size_t p = static_cast<std::size_t>(y) * w + x;
      const double ndc[4] = { 2.0 * (x + 0.5) / w - 1.0, 2.0 * (y + 0.5) / h - 1.0,
        2.0 * view.Depth[p] - 1.0, 1.0 };
      double out[4];
      toWorld->MultiplyPoint(ndc, out);
      world[p] = glm::dvec3(out[0], out[1], out[2]) / out[3];
    }
  }
  const glm::dvec3 eye(
    camera->GetPosition()[0], camera->GetPosition()[1], camera->GetPosition()[2]);
  const double minimumSine = std::sin(1.0 * 3.14159265358979 / 180.0);
  for (int index : view.Lights)
  {
    auto light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(index));
    double position[3], focal[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    const glm::dvec3 at(position[0], position[1], position[2]);
    const glm::dvec3 direction = glm::normalize(at - glm::dvec3(focal[0], focal[1], focal[2]));
    std::vector<char> facing(view.Depth.size(), 0);
    for (int y = 1; y + 1 < h; ++y)
    {
      for (int x = 1; x + 1 < w; ++x)
      {
        const std::size_t p = static_cast<std::size_t>(y) * w + x;
        if (view.Depth[p] >= 1.0f)
        {
          continue;
        }
        // Every one-sided normal must face the light: on a crease next to a face that does not,
        // the pixel's own face cannot be told from the depth alone.
        const glm::dvec3 toLight =
          light->GetPositional() ? glm::normalize(at - world[p]) : direction;
        bool faces = true;
        for (const std::size_t dx : { p + 1, p - 1 })
        {
          for (const std::size_t dy : { p + w, p - w })
          {
            glm::dvec3 normal = glm::cross(world[dx] - world[p], world[dy] - world[p]);
            if (!(glm::length(normal) > 0.0))
            {
              faces = false;
              continue;
            }
            normal = glm::normalize(normal);
            // VTK lights both sides of a surface (two-sided lighting): the side facing the eye.
            normal = glm::dot(normal, eye - world[p]) < 0.0 ? -normal : normal;
            faces = faces && glm::dot(normal, toLight) > minimumSine;
          }
        }
        facing[p] = faces;
      }
    }
    view.Facing.push_back(std::move(facing));
  }
}

/// The truth of every renderer of the scene for its current frame.
std::vector<View> TrueViews(CaseScene& scene)
{
  std::vector<View> views;
  for (vtkRenderer* renderer : scene.Renderers)
  {
    View view;
    int origin[2];
    renderer->GetTiledSizeAndOrigin(&view.Width, &view.Height, &origin[0], &origin[1]);
    vtkLightCollection* collection = renderer->GetLights();
    bool soft = false;
    for (int i = 0; i < collection->GetNumberOfItems(); ++i)
    {
      auto light = vtkLight::SafeDownCast(collection->GetItemAsObject(i));
      if (vtkSoftShadowPass::LightCastsShadows(light))
      {
        view.Lights.push_back(i);
        soft = soft || vtkSoftShadowPass::GetLightRadius(light) > 0.0;
      }
    }
    view.Hard = Truth(renderer, view.Lights, true, &view.Depth);
    view.Soft = soft ? Truth(renderer, view.Lights, false, nullptr) : view.Hard;
    ComputeFacing(renderer, view);
    views.push_back(std::move(view));
  }
  return views;
}

/// The pass's visibility of every shadowing light of every renderer, and the rasterized depth.
std::vector<std::vector<std::vector<float>>> PassVisibility(
  CaseScene& scene, std::vector<View>& views)
{
  std::vector<std::vector<std::vector<float>>> result;
  for (std::size_t r = 0; r < scene.Renderers.size(); ++r)
  {
    View& view = views[r];
    view.ZBuffer = WindowDepth(scene.Window, scene.Renderers[r]);
    std::vector<std::vector<float>> lights;
    for (int index : view.Lights)
    {
      vtkImageData* image = scene.Passes[r]->GetVisibilityImage(index);
      lights.push_back(image ? ImageValues(image) : std::vector<float>(view.ZBuffer.size(), 1.0f));
    }
    result.push_back(std::move(lights));
  }
  return result;
}

/// Pixels compared: same surface in both, no object silhouette in the 3x3 neighbourhood.
std::vector<char> CompareMask(const View& view)
{
  return penumbra::metrics::ComparablePixels(view.Depth, view.ZBuffer, view.Width, view.Height);
}

void Accumulate(Row& row, const View& view, const std::vector<char>& mask,
  const std::vector<std::vector<float>>& ours, const std::vector<std::vector<float>>& truth)
{
  const int w = view.Width;
  for (std::size_t l = 0; l < ours.size() && l < truth.size(); ++l)
  {
    const std::vector<float>& v = ours[l];
    const std::vector<float>& t = truth[l];
    for (std::size_t p = 0; p < v.size(); ++p)
    {
      if (!std::isfinite(v[p]))
      {
        ++row.NonFinite;
        continue;
      }
      if (!mask[p] || !view.Facing[l][p] || (v[p] > 0.999f && t[p] > 0.999f))
      {
        continue;
      }
      const float error = std::abs(v[p] - t[p]);
      ++row.Pixels;
      row.ErrorSum += error;
      row.Over01 += error > 0.1f;
      row.Leaks += error > 0.5f && !penumbra::metrics::NearTruthValue(t, w, p, v[p], 0.5f);
    }
  }
}

/// Share of compared pixels whose change between two frames exceeds the truth's by > 0.1.
double PoppingShare(const View& view, const std::vector<char>& mask,
  const std::vector<std::vector<float>>& ours, const std::vector<std::vector<float>>& oursBefore,
  const std::vector<std::vector<float>>& truth, const std::vector<std::vector<float>>& truthBefore)
{
  std::size_t compared = 0, popped = 0;
  for (std::size_t l = 0; l < ours.size(); ++l)
  {
    for (std::size_t p = 0; p < view.Depth.size(); ++p)
    {
      if (!mask[p] || !view.Facing[l][p])
      {
        continue;
      }
      ++compared;
      const double excess =
        std::abs(ours[l][p] - oursBefore[l][p]) - std::abs(truth[l][p] - truthBefore[l][p]) - 0.05;
      popped += excess > 0.1;
    }
  }
  return compared ? double(popped) / compared : 0.0;
}

/// Share of pixels, compared where the reference's mask allows, off by more than 0.1.
double ReferenceShare(const std::vector<char>& mask, const std::vector<std::vector<float>>& ours,
  const std::vector<std::vector<float>>& reference)
{
  std::size_t compared = 0, off = 0;
  for (std::size_t l = 0; l < ours.size() && l < reference.size(); ++l)
  {
    for (std::size_t p = 0; p < mask.size(); ++p)
    {
      if (mask[p] && (ours[l][p] < 0.999f || reference[l][p] < 0.999f))
      {
        ++compared;
        off += !(std::abs(ours[l][p] - reference[l][p]) <= 0.1f);
      }
    }
  }
  return compared ? double(off) / compared : 1.0;
}

/// Share of pixels whose luminance differs by more than 0.1 between two RGB images, away from
/// edges of `a` (VTK's tiles shift edges by a fraction of a pixel; a shadow's interior must not
/// change).
double LuminanceShare(const std::vector<unsigned char>& a, const unsigned char* b, int w, int h)
{
  auto lum = [](const unsigned char* rgb, std::size_t p)
  { return penumbra::metrics::Luminance8(rgb, p, 3); };
  std::size_t compared = 0, off = 0;
  for (int y = 1; y + 1 < h; ++y)
  {
    for (int x = 1; x + 1 < w; ++x)
    {
      const std::size_t p = static_cast<std::size_t>(y) * w + x;
      double low = 1.0, high = 0.0;
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          const double l = lum(a.data(), p + dy * w + dx);
          low = std::min(low, l);
          high = std::max(high, l);
        }
      }
      if (high - low < 0.1)
      {
        ++compared;
        off += std::abs(lum(a.data(), p) - lum(b, p)) > 0.1;
      }
    }
  }
  return compared ? double(off) / compared : 1.0;
}

/// The frame through vtkRenderLargeImage at half the window size and magnification 2.
double CompareWithTiles(
  CaseScene& scene, const std::vector<unsigned char>& direct, const std::string& path)
{
  const int w = scene.Window->GetSize()[0], h = scene.Window->GetSize()[1];
  scene.Window->SetSize(w / 2, h / 2);
  vtkNew<vtkRenderLargeImage> large;
  large->SetInput(scene.Renderer);
  large->SetMagnification(2);
  large->Update();
  vtkImageData* image = large->GetOutput();
  double share = 1.0;
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] == w && dims[1] == h && image->GetNumberOfScalarComponents() == 3)
  {
    share = LuminanceShare(direct, static_cast<unsigned char*>(image->GetScalarPointer()), w, h);
  }
  penumbra::bench::WritePNG(image, path);
  scene.Window->SetSize(w, h);
  return share;
}

struct Options
{
  std::set<int> Groups;
  std::set<std::string> Names;
  bool Check = false, WriteBaselines = false;
  std::string Baselines, Output = ".", Report;
  double CameraOffset = 0.0;
};

struct CaseResult
{
  Row Rows[METHOD_COUNT];
  bool ImageMatches = true;
  std::string ImageNote;
};

/// The images a reference case leaves for the cases that compare with it.
struct Stored
{
  std::vector<View> Views;
  std::vector<std::vector<std::vector<float>>> Visibility[METHOD_COUNT];
};

bool FileExists(const std::string& path)
{
  struct stat info;
  return stat(path.c_str(), &info) == 0;
}

/// The share of pixels whose colour differs from the baseline's by more than ChangedLevels in
/// some channel; 1 where the images' sizes or formats differ.
double ChangedPixelShare(vtkImageData* image, vtkImageData* baseline)
{
  int size[3], baselineSize[3];
  image->GetDimensions(size);
  baseline->GetDimensions(baselineSize);
  auto* ours = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  auto* theirs = vtkUnsignedCharArray::SafeDownCast(baseline->GetPointData()->GetScalars());
  if (!ours || !theirs || !std::equal(size, size + 3, baselineSize) ||
    ours->GetNumberOfTuples() != theirs->GetNumberOfTuples() || ours->GetNumberOfTuples() == 0)
  {
    return 1.0;
  }
  const int channels =
    std::min(3, std::min(ours->GetNumberOfComponents(), theirs->GetNumberOfComponents()));
  vtkIdType changed = 0;
  for (vtkIdType i = 0; i < ours->GetNumberOfTuples(); ++i)
  {
    bool differs = false;
    for (int c = 0; c < channels; ++c)
    {
      differs = differs ||
        std::abs(int(ours->GetTypedComponent(i, c)) - int(theirs->GetTypedComponent(i, c))) >
          ChangedLevels;
    }
    changed += differs ? 1 : 0;
  }
  return double(changed) / double(ours->GetNumberOfTuples());
}

/// Compares the case's panel image with its baseline (or writes the baseline).
void CheckImage(
  const Options& options, const std::string& name, vtkImageData* panel, CaseResult& result)
{
  if (options.Baselines.empty())
  {
    return;
  }
  const std::string baseline = options.Baselines + "/" + name + ".png";
  if (options.WriteBaselines)
  {
    penumbra::bench::WritePNG(panel, baseline);
    return;
  }
  if (!FileExists(baseline))
  {
    result.ImageMatches = false;
    result.ImageNote = "no baseline " + baseline;
    return;
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(baseline.c_str());
  reader->Update();
  vtkNew<vtkImageDifference> difference;
  difference->SetInputData(panel);
  difference->SetImageData(reader->GetOutput());
  difference->Update();
  const double error = difference->GetThresholdedError();
  const double changed = ChangedPixelShare(panel, reader->GetOutput());
  result.ImageMatches = error <= ImageThreshold && changed <= ChangedPixelsLimit;
  std::ostringstream note;
  note << "image difference " << error << " (limit " << ImageThreshold << "), " << 100.0 * changed
       << "% of pixels more than " << ChangedLevels << " levels off (limit "
       << 100.0 * ChangedPixelsLimit << "%)";
  result.ImageNote = note.str();
}

CaseResult RunCase(const HardCase& c, const Options& options, std::map<std::string, Stored>& stored)
{
  CaseResult result;
  vtkNew<vtkCountingOutputWindow> log;
  vtkOutputWindow::SetInstance(log);

  CaseScene scene(c.Width, c.Height, CaseScene::StartLight::None);
  // Single-sampled, as the truth is traced: one ray through each pixel centre.
  scene.Window->SetMultiSamples(0);
  c.Build(scene);
  if (options.CameraOffset != 0.0)
  {
    for (vtkRenderer* renderer : scene.Renderers)
    {
      double position[3];
      renderer->GetActiveCamera()->GetPosition(position);
      renderer->GetActiveCamera()->SetPosition(position[0] + options.CameraOffset,
        position[1] + 0.5 * options.CameraOffset, position[2] - options.CameraOffset);
    }
  }
  const Stored* reference = c.Reference.empty() ? nullptr : &stored[c.Reference];
  if (reference && reference->Views.size() != scene.Renderers.size())
  {
    std::fprintf(stderr, "%s: reference %s has not run\n", c.Name.c_str(), c.Reference.c_str());
    reference = nullptr;
  }
  std::vector<View> views, previousViews;
  std::vector<std::vector<std::vector<float>>> previous[METHOD_COUNT];
  std::vector<unsigned char> colour[METHOD_COUNT];
  int errorsBefore = 0, warningsBefore = 0;
  for (int frame = 0; frame < c.Frames; ++frame)
  {
    if (c.Frame)
    {
      c.Frame(scene, frame);
    }
    for (int m = 0; m < METHOD_COUNT; ++m)
    {
      for (vtkSoftShadowPass* pass : scene.Passes)
      {
        pass->SetMethod(m == HARD ? vtkSoftShadowPass::METHOD_HARD_VOLUMES
            : m == AVERAGED       ? vtkSoftShadowPass::METHOD_AVERAGED_HARD_SHADOWS
            : m == WEDGES         ? vtkSoftShadowPass::METHOD_PENUMBRA_WEDGES
            : m == AUTOMATIC      ? vtkSoftShadowPass::METHOD_AUTOMATIC
                                  : vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES);
        pass->SetLightSamples(16);
        pass->SetHalfResolutionCounting(m == HALF_RESOLUTION);
      }
      scene.Window->Render();
      if (m == 0)
      {
        // The truth of this frame (after the first render: lights follow the camera by then).
        previousViews = views;
        views = TrueViews(scene);
      }
      auto visibility = PassVisibility(scene, views);
      Row& row = result.Rows[m];
      row.ShadowingLights = 0;
      for (vtkSoftShadowPass* pass : scene.Passes)
      {
        row.ShadowingLights += pass->GetNumberOfShadowingLights();
      }
      for (std::size_t r = 0; r < views.size(); ++r)
      {
        const View& truthView = reference ? reference->Views[r] : views[r];
        View judged = truthView;
        judged.ZBuffer = reference ? truthView.ZBuffer : views[r].ZBuffer;
        const std::vector<char> mask = CompareMask(judged);
        Accumulate(row, judged, mask, visibility[r], m == HARD ? truthView.Hard : truthView.Soft);
        if (reference)
        {
          row.Reference = penumbra_test::Worse(
            row.Reference, ReferenceShare(mask, visibility[r], reference->Visibility[m][r]));
        }
        if (c.Temporal && frame > 0)
        {
          row.WorstStep = penumbra_test::Worse(row.WorstStep,
            PoppingShare(views[r], CompareMask(views[r]), visibility[r], previous[m][r],
              m == HARD ? views[r].Hard : views[r].Soft,
              m == HARD ? previousViews[r].Hard : previousViews[r].Soft));
        }
      }
      previous[m] = visibility;
      const int w = scene.Window->GetSize()[0], h = scene.Window->GetSize()[1];
      colour[m] = penumbra::bench::GrabFrame(scene.Window, w, h).RGB;
      if (c.LargeImageTiles && frame + 1 == c.Frames)
      {
        row.Reference = CompareWithTiles(
          scene, colour[m], options.Output + "/" + c.Name + "_" + MethodName(m) + ".png");
        scene.Window->Render();
      }
      row.Errors += log->Errors - errorsBefore;
      row.Warnings += log->Warnings - warningsBefore;
      if (row.Errors && row.FirstError.empty())
      {
        row.FirstError = log->FirstError;
      }
      errorsBefore = log->Errors;
      warningsBefore = log->Warnings;
    }
  }
  if (c.Name == "origin")
  {
    Stored& keep = stored[c.Name];
    keep.Views = views;
    for (int m = 0; m < METHOD_COUNT; ++m)
    {
      keep.Visibility[m] = previous[m];
    }
  }

  // The regression image: every method's frame and the truth's visibility, side by side;
  // and, for looking, the methods' visibility beside the truth's.
  const int w = scene.Window->GetSize()[0], h = scene.Window->GetSize()[1];
  const int Columns = METHOD_COUNT + 1;
  vtkNew<vtkImageData> panel, visibilityPanel;
  for (vtkImageData* image : { panel.GetPointer(), visibilityPanel.GetPointer() })
  {
    image->SetDimensions(Columns * w, h, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto bytes = static_cast<unsigned char*>(image->GetScalarPointer());
    std::fill(bytes, bytes + 3 * Columns * static_cast<std::size_t>(w) * h, 0);
  }
  auto bytes = static_cast<unsigned char*>(panel->GetScalarPointer());
  for (int y = 0; y < h; ++y)
  {
    for (int m = 0; m < METHOD_COUNT; ++m)
    {
      std::copy_n(colour[m].data() + 3 * static_cast<std::size_t>(y) * w, 3 * w,
        bytes + 3 * (static_cast<std::size_t>(y) * Columns * w + m * w));
    }
  }
  // Grey panels of renderer 0: the darkest light at each pixel, background dark grey. In the
  // visibility panel, pixels left out of the comparison are tinted blue and leaks are red.
  const View& first = views.front();
  const std::vector<char> firstMask = CompareMask(first);
  int origin[2], size[2];
  scene.Renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  auto greyPanel = [&](vtkImageData* image, int column,
                     const std::vector<std::vector<float>>& lights,
                     const std::vector<std::vector<float>>* truth)
  {
    auto out = static_cast<unsigned char*>(image->GetScalarPointer());
    for (int y = 0; y < first.Height; ++y)
    {
      for (int x = 0; x < first.Width; ++x)
      {
        const std::size_t p = static_cast<std::size_t>(y) * first.Width + x;
        float v = 1.0f;
        bool compared = false, leak = false;
        for (std::size_t l = 0; l < lights.size(); ++l)
        {
          v = std::isfinite(lights[l][p]) ? std::min(v, lights[l][p]) : 0.0f;
          compared |= firstMask[p] && first.Facing[l][p];
          leak |= truth && firstMask[p] && first.Facing[l][p] &&
            std::abs(lights[l][p] - (*truth)[l][p]) > 0.5f;
        }
        const double grey = 255.0 * (first.Depth[p] < 1.0f ? v : 0.2);
        double rgb[3] = { grey, grey, grey };
        if (truth && first.Depth[p] < 1.0f && !compared)
        {
          rgb[0] *= 0.6;
          rgb[1] *= 0.7;
          rgb[2] = 0.6 * rgb[2] + 100;
        }
        if (leak)
        {
          rgb[0] = 255;
          rgb[1] = rgb[2] = 0;
        }
        unsigned char* pixel = out +
          3 *
            ((static_cast<std::size_t>(y) + origin[1]) * Columns * w + column * w + x + origin[0]);
        for (int k = 0; k < 3; ++k)
        {
          pixel[k] = static_cast<unsigned char>(std::lround(rgb[k]));
        }
      }
    }
  };
  greyPanel(panel, METHOD_COUNT, first.Soft, nullptr);
  for (int m = 0; m < METHOD_COUNT; ++m)
  {
    greyPanel(visibilityPanel, m, previous[m].front(), m == HARD ? &first.Hard : &first.Soft);
  }
  greyPanel(visibilityPanel, METHOD_COUNT, first.Soft, nullptr);
  penumbra::bench::WritePNG(visibilityPanel, options.Output + "/" + c.Name + "_visibility.png");
  penumbra::bench::WritePNG(panel, options.Output + "/" + c.Name + ".png");
  CheckImage(options, c.Name, panel, result);
  vtkOutputWindow::SetInstance(nullptr);
  return result;
}

/// The limits of one row and whether it meets them; `why` explains an allowance.
bool Judge(const HardCase& c, int method, const Row& row, std::string& verdict)
{
  double maeLimit = DefaultMAE[method], poppingLimit = TemporalLimit;
  std::size_t leakLimit = 0;
  std::string why;
  for (const Allowance& known : c.Known)
  {
    if (known.Method == method)
    {
      maeLimit = known.MAE >= 0.0 ? known.MAE : maeLimit;
      leakLimit = static_cast<std::size_t>(known.Leaks);
      poppingLimit = std::max(poppingLimit, known.Popping);
      why = known.Why;
    }
  }
  std::vector<std::string> failures;
  if (row.MAE() > maeLimit)
  {
    failures.push_back("MAE above " + std::to_string(maeLimit));
  }
  if (row.Leaks > leakLimit)
  {
    failures.push_back("leaks above " + std::to_string(leakLimit));
  }
  if (row.NonFinite)
  {
    failures.push_back("NaN in the LI buffer");
  }
  if (row.Errors)
  {
    failures.push_back("VTK error: " + row.FirstError);
  }
  if (row.ShadowingLights == 0)
  {
    failures.push_back("no shadowing light");
  }
  if (c.ExpectWarnings && row.Warnings == 0 && method == HARD)
  {
    failures.push_back("bad input without a warning");
  }
  if (c.Temporal && row.WorstStep > poppingLimit)
  {
    failures.push_back("popping above " + std::to_string(poppingLimit));
  }
  if (row.Pixels < MinComparedPixels)
  {
    failures.push_back("no shadow in view (" + std::to_string(row.Pixels) + " px compared)");
  }
  if ((!c.Reference.empty() || c.LargeImageTiles) && !(row.Reference >= 0.0))
  {
    failures.push_back(
      std::isnan(row.Reference) ? "NaN against its reference" : "not compared with its reference");
  }
  else if ((!c.Reference.empty() || c.LargeImageTiles) && row.Reference > ReferenceLimit)
  {
    failures.push_back("differs from its reference");
  }
  if (c.Temporal && !(row.WorstStep >= 0.0))
  {
    failures.push_back(
      std::isnan(row.WorstStep) ? "NaN between frames" : "no step between frames compared");
  }
  std::ostringstream text;
  for (const std::string& f : failures)
  {
    text << (text.tellp() ? "; " : "") << f;
  }
  if (failures.empty() && !why.empty())
  {
    text << "known limitation: " << why;
  }
  verdict = text.str();
  return failures.empty();
}

std::string Format(double value, const char* format)
{
  if (value < 0)
  {
    return "-";
  }
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

} // namespace

void Usage(const char* program)
{
  std::fprintf(stderr,
    "usage: %s [--group N]... [--case NAME]... [--check] [--baselines DIR] "
    "[--write-baselines] [--output DIR] [--report FILE.md] [--camera-offset D]\n"
    "  runs the hard cases (all, or those of the groups and names given) with every method\n"
    "  against the ray-traced truth; --check makes a failure the exit status.\n",
    program);
}

bool ParseArguments(int argc, char* argv[], Options& options)
{
  using namespace penumbra::bench;
  return ParseOptions(argc, argv,
    { ValueOption("--group",
        [&](const char* value)
        {
          int group = 0;
          const bool ok = ParseInt(value, 1, 1000, group);
          options.Groups.insert(group);
          return ok;
        }),
      ValueOption("--case",
        [&](const char* value)
        {
          options.Names.insert(value);
          return true;
        }),
      FlagOption("--check", [&] { options.Check = true; }),
      TextOption("--baselines", options.Baselines),
      FlagOption("--write-baselines", [&] { options.WriteBaselines = true; }),
      TextOption("--output", options.Output), TextOption("--report", options.Report),
      DoubleOption("--camera-offset", -std::numeric_limits<double>::max(), options.CameraOffset) },
    Usage);
}

int main(int argc, char* argv[])
{
  Options options;
  if (!ParseArguments(argc, argv, options))
  {
    return 2;
  }
  mkdir(options.Output.c_str(), 0755);

  std::ofstream report;
  if (!options.Report.empty())
  {
    report.open(options.Report);
    report << "### Cases\n\n| # | case | expected |\n|---|---|---|\n";
    for (const HardCase& c : AllCases())
    {
      report << "| " << c.Group << " | " << c.Name << " | " << c.Expected << " |\n";
    }
    report << "\n### Results\n\n"
           << "| # | case | method | pixels | MAE | >0.1 | leaks | NaN | VTK errors (warnings) | "
              "worst step | vs ref | verdict |\n"
           << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  }
  std::vector<std::string> notes; // known limitations, numbered in the report
  std::printf("%-2s %-34s %-10s %6s %7s %7s %6s %4s %9s %7s %7s  %s\n", "#", "case", "method",
    "pixels", "MAE", ">0.1", "leaks", "NaN", "err(warn)", "step", "vs ref", "verdict");
  std::map<std::string, Stored> stored;
  int failures = 0;
  for (const HardCase& c : AllCases())
  {
    const bool wanted = (options.Groups.empty() && options.Names.empty()) ||
      options.Groups.count(c.Group) || options.Names.count(c.Name);
    // A reference case runs whenever a case that needs it does.
    const bool needed = std::any_of(AllCases().begin(), AllCases().end(),
      [&](const HardCase& o)
      {
        return o.Reference == c.Name &&
          ((options.Groups.empty() && options.Names.empty()) || options.Groups.count(o.Group) ||
            options.Names.count(o.Name));
      });
    if (!wanted && !needed)
    {
      continue;
    }
    const CaseResult result = RunCase(c, options, stored);
    for (int m = 0; m < METHOD_COUNT; ++m)
    {
      const Row& row = result.Rows[m];
      std::string verdict;
      const bool ok = Judge(c, m, row, verdict);
      failures += !ok;
      std::printf("%-2d %-34s %-10s %6zu %7.4f %6.2f%% %6zu %4zu %5d(%d) %7s %7s  %s%s%s\n",
        c.Group, c.Name.c_str(), MethodName(m), row.Pixels, row.MAE(),
        row.Pixels ? 100.0 * row.Over01 / row.Pixels : 0.0, row.Leaks, row.NonFinite, row.Errors,
        row.Warnings, Format(100 * row.WorstStep, "%.2f%%").c_str(),
        Format(100 * row.Reference, "%.2f%%").c_str(), ok ? "ok" : "FAIL",
        verdict.empty() ? "" : ": ", verdict.c_str());
      if (report.is_open())
      {
        const std::string prefix = "known limitation: ";
        if (ok && verdict.compare(0, prefix.size(), prefix) == 0)
        {
          const std::string why = verdict.substr(prefix.size());
          auto at = std::find(notes.begin(), notes.end(), why);
          if (at == notes.end())
          {
            at = notes.insert(notes.end(), why);
          }
          verdict = "known limitation [" + std::to_string(at - notes.begin() + 1) + "]";
        }
        report << "| " << c.Group << " | " << c.Name << " | " << MethodName(m) << " | "
               << row.Pixels << " | " << Format(row.MAE(), "%.4f") << " | "
               << Format(row.Pixels ? 100.0 * row.Over01 / row.Pixels : 0.0, "%.2f%%") << " | "
               << row.Leaks << " | " << row.NonFinite << " | " << row.Errors << " (" << row.Warnings
               << ") | " << Format(100 * row.WorstStep, "%.2f%%") << " | "
               << Format(100 * row.Reference, "%.2f%%") << " | " << (ok ? "ok" : "**FAIL**")
               << (verdict.empty() ? "" : ": " + verdict) << " |\n";
      }
    }
    if (!result.ImageMatches)
    {
      ++failures;
      std::printf("FAIL: %s regression image: %s\n", c.Name.c_str(), result.ImageNote.c_str());
    }
    else if (!result.ImageNote.empty())
    {
      std::printf("   %s: %s\n", c.Name.c_str(), result.ImageNote.c_str());
    }
    std::fflush(stdout);
  }
  if (report.is_open())
  {
    report << "\n";
    for (std::size_t i = 0; i < notes.size(); ++i)
    {
      report << "[" << i + 1 << "] " << notes[i] << "\n\n";
    }
  }
  std::printf("%d failure(s)\n", failures);
  return options.Check && failures ? 1 : 0;
}
