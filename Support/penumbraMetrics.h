// penumbraMetrics.h: error metrics of a shadowing method against ray-traced ground truth, shared by
// PenumbraBench, PenumbraDemo, the tests and the hard-case suite. Header-only, plain arrays (no
// VTK, no GLM), so that anything holding images as rows of floats or bytes can use it.
//
// Two comparisons, both restricted to pixels where the rasterized surface and the ray-traced one
// are the same (truth depth and window z-buffer both below 1 and within a tolerance):
//
// - CompareVisibility: |method visibility - truth visibility| over the pixels where either is
//   below 1 (minus a small threshold), for methods that expose their light visibility;
// - CompareLuminance: |lum(method image) - lum(reference)| where reference = A + v (D - A) per
//   pixel in float, A the image with the light's intensity at 0 (ambient only), D the image lit
//   and unshadowed, v the truth visibility; over the pixels where v < 1 (minus the threshold) or
//   the method's luminance is below lum(D) by more than 1/255. For methods whose only output is
//   the final image (shadow maps, no shadows at all).
//
// Luminance is Rec. 709 (0.2126, 0.7152, 0.0722) of RGB in [0, 1].
//
// The tests judge pixel by pixel, with two more helpers: ComparablePixels (the same surface and
// no object silhouette next to it) and NearTruthValue (a difference that a shadow edge displaced
// by one pixel explains).
#ifndef penumbraMetrics_h
#define penumbraMetrics_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace penumbra
{
namespace metrics
{

/// Summary of per-pixel absolute errors.
struct ErrorStats
{
  std::size_t Pixels = 0;  ///< pixels compared
  std::size_t Skipped = 0; ///< candidate pixels left out: background or different surfaces
  double MAE = 0.0;        ///< mean absolute error
  double RMSE = 0.0;       ///< root mean square error
  double P99 = 0.0;        ///< 99th percentile (nearest rank)
  double Max = 0.0;        ///< largest error
  double FracGt01 = 0.0;   ///< fraction of compared pixels with error > 0.1
  double FracGt05 = 0.0;   ///< fraction of compared pixels with error > 0.5
};

/// Statistics of a list of absolute errors (the list is reordered).
inline ErrorStats Summarize(std::vector<float>& errors)
{
  ErrorStats stats;
  stats.Pixels = errors.size();
  if (errors.empty())
  {
    return stats;
  }
  double sum = 0.0, sum2 = 0.0, maximum = 0.0;
  std::size_t over01 = 0, over05 = 0;
  for (float e : errors)
  {
    sum += e;
    sum2 += static_cast<double>(e) * e;
    maximum = std::max(maximum, static_cast<double>(e));
    over01 += e > 0.1f;
    over05 += e > 0.5f;
  }
  const double n = static_cast<double>(errors.size());
  stats.MAE = sum / n;
  stats.RMSE = std::sqrt(sum2 / n);
  stats.Max = maximum;
  stats.FracGt01 = over01 / n;
  stats.FracGt05 = over05 / n;
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.99 * n)) - 1;
  std::nth_element(errors.begin(), errors.begin() + rank, errors.end());
  stats.P99 = errors[rank];
  return stats;
}

/// Rec. 709 luminance of an RGB colour in [0, 1].
inline double Luminance(double r, double g, double b)
{
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

/// Luminance of the pixel `p` of an 8-bit image with `components` (>= 3) interleaved channels.
inline double Luminance8(const unsigned char* rgb, std::size_t p, int components)
{
  const unsigned char* c = rgb + p * static_cast<std::size_t>(components);
  return Luminance(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
}

/// True where the rasterized and the ray-traced surface are one and the same (not background).
inline bool SameSurface(float truthDepth, float zbuffer, float depthTolerance)
{
  return truthDepth < 1.0f && zbuffer < 1.0f && std::abs(truthDepth - zbuffer) < depthTolerance;
}

/// Thresholds of the comparisons.
struct Options
{
  float DepthTolerance = 1e-3f;         ///< |truth depth - z-buffer| below this: same surface
  float SilhouetteStep = 5e-3f;         ///< truth depth step to a neighbour above this: silhouette
  float LitThreshold = 1e-3f;           ///< visibility below 1 - this counts as (partly) shadowed
  double DarkerThreshold = 1.0 / 255.0; ///< method darker than D by more than this: shadowed
};

/**
 * Visibility error of a method against the truth. All arrays hold `pixels` floats in the same
 * pixel order (VTK's: row 0 at the bottom); depths are window depths, 1 for background.
 */
inline ErrorStats CompareVisibility(const float* method, const float* truth,
  const float* truthDepth, const float* zbuffer, std::size_t pixels,
  const Options& options = Options())
{
  std::vector<float> errors;
  std::size_t skipped = 0;
  const float lit = 1.0f - options.LitThreshold;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    if (!(truth[p] < lit || method[p] < lit))
    {
      continue;
    }
    if (!SameSurface(truthDepth[p], zbuffer[p], options.DepthTolerance))
    {
      ++skipped;
      continue;
    }
    errors.push_back(std::abs(method[p] - truth[p]));
  }
  ErrorStats stats = Summarize(errors);
  stats.Skipped = skipped;
  return stats;
}

/**
 * Luminance of the reference image at pixel p: A + v (D - A) per channel, in float.
 * `lit` (D) and `ambient` (A) are 8-bit images with `components` interleaved channels.
 */
inline double ReferenceLuminance(const unsigned char* lit, const unsigned char* ambient,
  float visibility, std::size_t p, int components)
{
  const std::size_t o = p * static_cast<std::size_t>(components);
  double c[3];
  for (int k = 0; k < 3; ++k)
  {
    const double a = ambient[o + k] / 255.0, d = lit[o + k] / 255.0;
    c[k] = a + visibility * (d - a);
  }
  return Luminance(c[0], c[1], c[2]);
}

/**
 * Luminance error of a method's final image against the reference shaded with the true
 * visibility. `image`, `lit` (D) and `ambient` (A) are 8-bit images with `components`
 * interleaved channels; `truth`, `truthDepth` and `zbuffer` floats as in CompareVisibility
 * (zbuffer: the method's frame).
 */
inline ErrorStats CompareLuminance(const unsigned char* image, const unsigned char* lit,
  const unsigned char* ambient, int components, const float* truth, const float* truthDepth,
  const float* zbuffer, std::size_t pixels, const Options& options = Options())
{
  std::vector<float> errors;
  std::size_t skipped = 0;
  const float litVisibility = 1.0f - options.LitThreshold;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    const double method = Luminance8(image, p, components);
    const double unshadowed = Luminance8(lit, p, components);
    if (!(truth[p] < litVisibility || method < unshadowed - options.DarkerThreshold))
    {
      continue;
    }
    if (!SameSurface(truthDepth[p], zbuffer[p], options.DepthTolerance))
    {
      ++skipped;
      continue;
    }
    const double reference = ReferenceLuminance(lit, ambient, truth[p], p, components);
    errors.push_back(static_cast<float>(std::abs(method - reference)));
  }
  ErrorStats stats = Summarize(errors);
  stats.Skipped = skipped;
  return stats;
}

/**
 * Per-pixel difference of two truth images made with different seeds, over pixels where either
 * is below 1: the truth's own sampling noise (its error is about this / sqrt(2)).
 */
inline ErrorStats CompareTruths(const float* truthA, const float* truthB, const float* depth,
  std::size_t pixels, const Options& options = Options())
{
  std::vector<float> errors;
  const float lit = 1.0f - options.LitThreshold;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    if (depth[p] >= 1.0f || !(truthA[p] < lit || truthB[p] < lit))
    {
      continue;
    }
    errors.push_back(std::abs(truthA[p] - truthB[p]));
  }
  return Summarize(errors);
}

/**
 * The pixels of a width x height view where a method can be judged pixel by pixel against the
 * truth: the rasterized and ray-traced surface are the same, and no neighbour (3x3) lies across
 * an object silhouette, where one pixel of rasterization moves the surface itself. The border is
 * left out. Empty (nothing comparable) when the sizes disagree.
 */
inline std::vector<char> ComparablePixels(const std::vector<float>& truthDepth,
  const std::vector<float>& zbuffer, int width, int height, const Options& options = Options())
{
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<char> mask(pixels, 0);
  if (truthDepth.size() != pixels || zbuffer.size() != pixels)
  {
    return mask;
  }
  for (int y = 1; y + 1 < height; ++y)
  {
    for (int x = 1; x + 1 < width; ++x)
    {
      const std::size_t p = static_cast<std::size_t>(y) * width + x;
      const float d = truthDepth[p];
      if (!SameSurface(d, zbuffer[p], options.DepthTolerance))
      {
        continue;
      }
      bool silhouette = false;
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          silhouette |= std::abs(truthDepth[p + dy * width + dx] - d) > options.SilhouetteStep;
        }
      }
      mask[p] = !silhouette;
    }
  }
  return mask;
}

/**
 * True when some truth value in the 3x3 neighbourhood of the interior pixel p is within
 * `tolerance` of `value`: the method's value there is a shadow edge displaced by up to a pixel
 * (sampling and tessellation move edges that much), not a wrong shadow.
 */
inline bool NearTruthValue(
  const std::vector<float>& truth, int width, std::size_t p, float value, float tolerance)
{
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      if (std::abs(truth[p + dy * width + dx] - value) <= tolerance)
      {
        return true;
      }
    }
  }
  return false;
}

} // namespace metrics
} // namespace penumbra

#endif
