// CPU geometry throughput of the pass on time-varying data: what a frame costs when the data
// changed, per triangle. Flying-edges isosurfaces of a wavelet (shared points, open at the
// extent) of about 0.25M and 1M triangles, and a 4M-triangle vtkParametricTorus (its seam's
// duplicated points weld); per mesh, the median of 5 runs of:
//   first     CasterTopology::Build (points, triangles, welding, edges), fresh storage
//   rebuild   the same through a TopologyBuilder kept between builds, as for changing data
//   grown     the kept builder on meshes each larger than any it built before (a simulation
//             whose surface grows: the isosurface's value lowered, the torus' resolution
//             raised), each mesh made before its build is timed
//   volume    ShadowVolume::Build for one point light (silhouette, sides, caps)
//   winding   CasterTopology::OutwardWinding (closed meshes only: the torus)
// and, once a frame whatever the data, the tight depth range (TightClippingRange) of 1,001 unit
// boxes spread over 100 units and a ground of 120, seen from above at 30 degrees (actors1000's
// layout in PenumbraLoad): a share of the boxes straddle the frustum and are cut by ClipBox.
//
//   build/bin/PenumbraGeometryBench [--runs N] [--depth-range-only]
#include "penumbraCasterTopology.h"
#include "penumbraCulling.h"
#include "penumbraOptions.h"
#include "penumbraShadowVolume.h"

#include "vtkFlyingEdges3D.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricTorus.h"
#include "vtkPolyData.h"
#include "vtkRTAnalyticSource.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace
{
double MedianMs(int runs, const std::function<void()>& work)
{
  std::vector<double> ms;
  for (int i = 0; i < runs; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    work();
    ms.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

/// The median over `runs` builds by `builder` (already used) into `topology` of `source`'s output
/// after `change(step)` for step = 1, 2, ..., each taken only where the mesh has more triangles
/// than any before it; the source runs outside the timing.
double GrownMs(int runs, penumbra::TopologyBuilder& builder, penumbra::CasterTopology& topology,
  vtkPolyDataAlgorithm* source, const std::function<void(int)>& change)
{
  vtkIdType largest = source->GetOutput()->GetNumberOfPolys();
  std::vector<double> ms;
  for (int step = 1; static_cast<int>(ms.size()) < runs && step <= 50 * runs; ++step)
  {
    change(step);
    source->Update();
    vtkPolyData* mesh = source->GetOutput();
    if (mesh->GetNumberOfPolys() <= largest)
    {
      continue;
    }
    largest = mesh->GetNumberOfPolys();
    ms.push_back(MedianMs(1, [&] { builder.Build(mesh, topology); }));
  }
  std::sort(ms.begin(), ms.end());
  return ms.empty() ? 0.0 : ms[ms.size() / 2];
}

void Usage(const char* program)
{
  std::fprintf(stderr,
    "usage: %s [--runs N] [--depth-range-only]\n"
    "  CPU geometry per triangle on time-varying data: the median of N runs (default 5)\n"
    "  of a first topology build, a rebuild, a rebuild on a grown mesh, a shadow volume and\n"
    "  the outward winding, per mesh; then the tight depth range of 1,002 props a frame.\n",
    program);
}

/// The median time of TightClippingRange for 1,001 unit boxes scattered over 100 x 100 units
/// and a 120-unit ground, seen from (30, 20, 30) towards the origin at 30 degrees.
void PrintDepthRangeTime(int runs)
{
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> spread(-50.0, 50.0);
  std::vector<penumbra::Box> boxes;
  for (int i = 0; i < 1001; ++i)
  {
    const glm::dvec3 centre(spread(rng), 0.5, spread(rng));
    boxes.push_back({ true, centre - 0.5, centre + 0.5 });
  }
  boxes.push_back({ true, { -60, -0.1, -60 }, { 60, 0, 60 } });
  const glm::dmat4 view = glm::lookAt(glm::dvec3(30, 20, 30), glm::dvec3(0), glm::dvec3(0, 1, 0));
  const glm::dvec2 current(0.1, 200.0);
  const glm::dmat4 toClip =
    glm::perspective(glm::radians(30.0), 4.0 / 3.0, current.x, current.y) * view;
  glm::dvec2 range;
  const double ms =
    MedianMs(runs, [&] { range = penumbra::TightClippingRange(boxes, view, toClip, current); });
  std::printf("tight depth range of %zu props: %.3f ms (range %.2f to %.2f)\n", boxes.size(), ms,
    range.x, range.y);
}
} // namespace

int main(int argc, char* argv[])
{
  int runs = 5;
  bool depthRangeOnly = false;
  using namespace penumbra::bench;
  if (!ParseOptions(argc, argv,
        { IntOption("--runs", 1, 1000, runs),
          FlagOption("--depth-range-only", [&] { depthRangeOnly = true; }) },
        Usage))
  {
    return 2;
  }
  if (depthRangeOnly)
  {
    PrintDepthRangeTime(runs);
    return 0;
  }
  std::printf("%-8s %10s %10s %8s %11s %8s %10s %8s %10s %8s %11s\n", "extent", "triangles",
    "first ms", "ns/tri", "rebuild ms", "ns/tri", "grown ms", "ns/tri", "volume ms", "ns/tri",
    "winding ms");
  // The two isosurfaces, then the torus (extent 0): a large mesh's first build, with a seam.
  for (const int extent : { 60, 120, 0 })
  {
    vtkNew<vtkRTAnalyticSource> wavelet;
    wavelet->SetWholeExtent(-extent, extent, -extent, extent, -extent, extent);
    vtkNew<vtkFlyingEdges3D> contour;
    contour->SetInputConnection(wavelet->GetOutputPort());
    contour->SetValue(0, 160.0);
    contour->ComputeNormalsOff();
    vtkNew<vtkParametricTorus> torus;
    vtkNew<vtkParametricFunctionSource> surface;
    surface->SetParametricFunction(torus);
    surface->SetUResolution(1414);
    surface->SetVResolution(1414);
    surface->GenerateTextureCoordinatesOff();
    vtkPolyDataAlgorithm* source = extent > 0 ? static_cast<vtkPolyDataAlgorithm*>(contour)
                                              : static_cast<vtkPolyDataAlgorithm*>(surface);
    source->Update();
    vtkPolyData* mesh = source->GetOutput();
    const double triangles = static_cast<double>(mesh->GetNumberOfPolys());

    penumbra::CasterTopology topology;
    const double firstMs =
      MedianMs(runs, [&] { topology = penumbra::CasterTopology::Build(mesh); });
    penumbra::TopologyBuilder builder;
    const double rebuildMs = MedianMs(runs, [&] { builder.Build(mesh, topology); });
    const glm::dvec4 light(-extent, 5.0 * extent, extent, 1.0);
    const double volumeMs = MedianMs(runs,
      [&]
      {
        penumbra::ShadowVolume volume =
          penumbra::ShadowVolume::Build(topology, light - glm::dvec4(topology.Origin, 0.0), false);
        (void)volume;
      });
    // Asked once per rebuild of a closed caster (its depth culls hidden faces); 0 when open.
    const double windingMs = MedianMs(runs, [&] { (void)topology.OutwardWinding(); });
    // After the volume, which is timed on the first mesh as the rows before.
    const double grownMs = GrownMs(runs, builder, topology, source,
      [&](int step)
      {
        contour->SetValue(0, 160.0 - 0.5 * step);
        surface->SetUResolution(1414 + step);
      });
    std::printf("%-8s %10.0f %10.1f %8.0f %11.1f %8.0f %10.1f %8.0f %10.1f %8.0f %11.1f\n",
      extent > 0 ? std::to_string(extent).c_str() : "torus", triangles, firstMs,
      1e6 * firstMs / triangles, rebuildMs, 1e6 * rebuildMs / triangles, grownMs,
      1e6 * grownMs / triangles, volumeMs, 1e6 * volumeMs / triangles, windingMs);
  }
  PrintDepthRangeTime(runs);
  return 0;
}
