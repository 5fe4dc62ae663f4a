// Unit tests of per-light-sample counting (penumbraSampleCounting.h), without a window.
//
// For random receiver points p and the light samples of SpreadLightSamples, the depth complexity
// predicted from the centre, D(p, c) + sum over the potential silhouette of -m_e(p) x crossing,
// must equal the brute-force count of casting triangles on the segment p -> s, for closed,
// open, non-manifold, non-orientable and mirrored casters, positional and directional lights.
// A sign mutation of the edge term must make the check fail.
#include "penumbraCasterTopology.h"
#include "penumbraCheck.h"
#include "penumbraConvexClip.h"
#include "penumbraLightSamples.h"
#include "penumbraSampleCounting.h"
#include "penumbraShadowVolume.h"
#include "penumbraWedge.h"

#include "vtkConeSource.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricMobius.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace penumbra;
using penumbra_test::Check;

namespace
{

/// Whether segment origin -> origin + dir (t in (0, 1)) crosses triangle abc; `nearEdge` is set
/// when the hit is too close to the triangle's edges or the segment's ends to count robustly.
bool SegmentCrosses(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec3& c, bool& nearEdge)
{
  const glm::dvec3 e1 = b - a, e2 = c - a, h = glm::cross(dir, e2);
  const double det = glm::dot(e1, h);
  if (std::abs(det) < 1e-300)
  {
    return false;
  }
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, h) / det;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(dir, q) / det, t = glm::dot(e2, q) / det;
  const double eps = 1e-7;
  if (u < -eps || v < -eps || u + v > 1 + eps || t < -eps || t > 1 + eps)
  {
    return false;
  }
  if (u < eps || v < eps || u + v > 1 - eps || t < eps || t > 1 - eps)
  {
    nearEdge = true;
  }
  return true;
}

struct Caster
{
  std::string Name;
  CasterTopology Topology;
  glm::dmat4 ObjectToWorld{ 1.0 };
};

/// Casting triangles (world space) crossed by the segment from p to the light point s, by the
/// rule of the centre's volume: all triangles, or those facing s when front faces suffice.
int DepthComplexity(const Caster& caster, const std::vector<glm::dvec3>& world, bool frontOnly,
  bool mirrored, const glm::dvec3& p, const glm::dvec4& s, bool& nearEdge)
{
  const glm::dvec3 dir = s.w != 0.0 ? glm::dvec3(s) - p : 1e3 * glm::dvec3(s);
  int count = 0;
  for (const glm::uvec3& tri : caster.Topology.Triangles)
  {
    const glm::dvec3 &a = world[tri.x], &b = world[tri.y], &c = world[tri.z];
    const glm::dvec3 normal = glm::cross(b - a, c - a) * (mirrored ? -1.0 : 1.0);
    const double facing = glm::dot(normal, glm::dvec3(s) - s.w * a);
    if (frontOnly && !(facing > 0.0))
    {
      continue;
    }
    count += SegmentCrosses(p, dir, a, b, c, nearEdge) ? 1 : 0;
  }
  return count;
}

/// Random points around the caster's world bounds, grown by half their size.
glm::dvec3 RandomPoint(const std::vector<glm::dvec3>& world, std::mt19937& rng)
{
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : world)
  {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 grow = 0.5 * (hi - lo) + 0.1;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  return lo - grow + glm::dvec3(unit(rng), unit(rng), unit(rng)) * (hi - lo + 2.0 * grow);
}

/// Mismatches between predicted and brute-force depth complexity; `edgeSign` is +1 for the
/// rule as documented, -1 for the mutation that must fail.
int CountMismatches(const Caster& caster, const glm::dvec4& light, double radius, int edgeSign,
  int trials, std::mt19937& rng, int& compared, int& nonZero)
{
  const CasterTopology& topo = caster.Topology;
  std::vector<glm::dvec3> world(topo.Points.size());
  for (std::size_t i = 0; i < world.size(); ++i)
  {
    world[i] = glm::dvec3(caster.ObjectToWorld * glm::dvec4(topo.Points[i], 1.0));
  }
  const bool mirrored = glm::determinant(glm::dmat3(caster.ObjectToWorld)) < 0.0;
  const glm::dvec4 lightObject = glm::inverse(caster.ObjectToWorld) * light;
  const bool frontOnly = ShadowVolume::FrontFacesSuffice(topo, lightObject);
  const std::vector<std::uint32_t> potential =
    PotentialSilhouette(topo, caster.ObjectToWorld, light, radius, frontOnly);
  glm::dvec3 target(0.0);
  for (const glm::dvec3& p : world)
  {
    target += p / static_cast<double>(world.size());
  }
  const std::vector<glm::dvec4> samples =
    SpreadLightSamples(light, light.w != 0.0 ? radius : glm::degrees(radius), 16, target);

  int mismatches = 0;
  for (int trial = 0; trial < trials; ++trial)
  {
    const glm::dvec3 p = RandomPoint(world, rng);
    bool nearEdge = false;
    const int centreCount = DepthComplexity(caster, world, frontOnly, mirrored, p, light, nearEdge);
    for (const glm::dvec4& s : samples)
    {
      const int truth = DepthComplexity(caster, world, frontOnly, mirrored, p, s, nearEdge);
      if (nearEdge)
      {
        break;
      }
      int predicted = centreCount;
      for (std::uint32_t e : potential)
      {
        const Edge& edge = topo.Edges[e];
        const glm::dvec3 &a = world[edge.A], &b = world[edge.B];
        std::vector<EdgeFace> faces;
        for (std::uint32_t u = edge.FirstUse; u < edge.FirstUse + edge.UseCount; ++u)
        {
          const glm::uvec3& tri = topo.Triangles[topo.Uses[u].Triangle];
          const glm::dvec3 normal =
            glm::cross(world[tri.y] - world[tri.x], world[tri.z] - world[tri.x]);
          const double flip = mirrored ? -1.0 : 1.0;
          faces.push_back({ flip * normal, static_cast<int>(flip) * topo.Uses[u].Sign });
        }
        const int m =
          MultiplicityFrom(p, a, faces.data(), static_cast<int>(faces.size()), frontOnly);
        predicted -= edgeSign * m * SampleCrossing(p, a, b, light, s);
      }
      ++compared;
      nonZero += truth != 0;
      mismatches += predicted != truth;
    }
  }
  return mismatches;
}

CasterTopology FromSource(vtkPolyDataAlgorithm* source)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  return CasterTopology::Build(triangles->GetOutput());
}

std::vector<Caster> MakeCasters(std::mt19937& rng)
{
  std::vector<Caster> casters;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  casters.push_back({ "closed sphere", FromSource(sphere) });
  casters.push_back({ "mirrored, scaled sphere", FromSource(sphere),
    glm::scale(
      glm::translate(glm::dmat4(1.0), glm::dvec3(0.2, -0.1, 0.3)), glm::dvec3(-1.0, 0.7, 1.3)) });
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(24);
  cone->SetHeight(1.6);
  cone->SetDirection(0, 1, 0);
  casters.push_back({ "capped cone", FromSource(cone) });
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(3, 2);
  casters.push_back({ "open sheet", FromSource(plane) });
  vtkNew<vtkParametricMobius> mobius;
  vtkNew<vtkParametricFunctionSource> mobiusSource;
  mobiusSource->SetParametricFunction(mobius);
  mobiusSource->SetUResolution(12);
  mobiusSource->SetVResolution(3);
  casters.push_back({ "Moebius strip", FromSource(mobiusSource) });
  // Three fins on one edge and a flipped triangle: non-manifold and inconsistently wound.
  casters.push_back({ "non-manifold fins",
    CasterTopology::Build({ { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0.8, 0.1 }, { 0.5, -0.7, 0.2 },
                            { 0.4, 0.1, 0.9 }, { 1.4, 0.6, 0.3 } },
      { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 }, { 1, 5, 2 } }) });
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<glm::dvec3> points;
  std::vector<glm::uvec3> soup;
  for (unsigned int t = 0; t < 12; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    }
    soup.emplace_back(3 * t, 3 * t + 1, 3 * t + 2);
  }
  casters.push_back({ "random soup", CasterTopology::Build(points, soup) });
  return casters;
}

/// Whether x is inside the closed convex mesh (on the inner side of every triangle's plane).
bool InsidePolyhedron(const ConvexPolyhedron& shape, const glm::dvec3& x, double tolerance)
{
  for (std::size_t t = 0; t < shape.Triangles.size(); t += 3)
  {
    const glm::dvec3& a = shape.Points[shape.Triangles[t]];
    const glm::dvec3 n = glm::cross(
      shape.Points[shape.Triangles[t + 1]] - a, shape.Points[shape.Triangles[t + 2]] - a);
    if (glm::dot(n, x - a) > tolerance * glm::length(n))
    {
      return false;
    }
  }
  return !shape.Empty();
}

/**
 * The region the pass draws for a two-faced potential silhouette edge, its wedge cut to a box
 * and to SilhouetteSector, must hold every point where the edge changes some sample's count.
 * Points are thrown along rays from random light points through the edge, where the wedge is.
 * `flipSector` reverses the sector's half-spaces: the mutation that must be caught. Returns the
 * points outside that the edge changes; `volumeRatio` the cut region's volume over the wedge's.
 */
int CountRegionMisses(const Caster& caster, const glm::dvec4& light, double radius, bool flipSector,
  std::mt19937& rng, int& changed, double& volumeRatio)
{
  const CasterTopology& topo = caster.Topology;
  std::vector<glm::dvec3> world(topo.Points.size());
  Box box;
  box.Valid = true;
  box.Min = glm::dvec3(1e300);
  box.Max = glm::dvec3(-1e300);
  for (std::size_t i = 0; i < world.size(); ++i)
  {
    world[i] = glm::dvec3(caster.ObjectToWorld * glm::dvec4(topo.Points[i], 1.0));
    box.Min = glm::min(box.Min, world[i]);
    box.Max = glm::max(box.Max, world[i]);
  }
  box.Min -= glm::dvec3(2.0);
  box.Max += glm::dvec3(2.0);
  const bool mirrored = glm::determinant(glm::dmat3(caster.ObjectToWorld)) < 0.0;
  const bool frontOnly =
    ShadowVolume::FrontFacesSuffice(topo, glm::inverse(caster.ObjectToWorld) * light);
  const std::vector<glm::dvec4> samples =
    SpreadLightSamples(light, light.w != 0.0 ? radius : glm::degrees(radius), 16, box.Min);
  std::uniform_real_distribution<double> unit(0.0, 1.0), signedUnit(-1.0, 1.0);
  int misses = 0;
  double cutVolume = 0.0, wedgeVolume = 0.0;
  std::size_t cuts = 0, cutPoints = 0, cutTriangles = 0;
  for (std::uint32_t e : PotentialSilhouette(topo, caster.ObjectToWorld, light, radius, frontOnly))
  {
    const Edge& edge = topo.Edges[e];
    if (edge.UseCount != 2)
    {
      continue;
    }
    const glm::dvec3 &a = world[edge.A], &b = world[edge.B];
    EdgeFace faces[2];
    for (int k = 0; k < 2; ++k)
    {
      const EdgeUse& use = topo.Uses[edge.FirstUse + k];
      const glm::uvec3& tri = topo.Triangles[use.Triangle];
      const double flip = mirrored ? -1.0 : 1.0;
      faces[k] = { flip * glm::cross(world[tri.y] - world[tri.x], world[tri.z] - world[tri.x]),
        static_cast<int>(flip) * use.Sign };
    }
    const Wedge wedge = Wedge::Build(a, b, light, radius);
    if (!wedge.Valid)
    {
      continue;
    }
    std::vector<HalfSpace> planes = wedge.HalfSpaces();
    wedgeVolume += ClipBox(box, planes).Volume();
    for (HalfSpace half : SilhouetteSector(wedge, a, b, faces, 2, frontOnly, 1e-6))
    {
      if (flipSector)
      {
        half = { -half.Normal, -half.Offset };
      }
      planes.push_back(half);
    }
    const ConvexPolyhedron region = ClipBox(box, planes);
    cutVolume += region.Volume();
    ++cuts;
    cutPoints += region.Points.size();
    cutTriangles += region.Triangles.size() / 3;
    for (int trial = 0; trial < 40; ++trial)
    {
      const glm::dvec3 onEdge = a + unit(rng) * (b - a);
      glm::dvec3 towardsLight;
      const glm::dvec3 jitter(signedUnit(rng), signedUnit(rng), signedUnit(rng));
      if (light.w != 0.0)
      {
        towardsLight = glm::dvec3(light) + radius * jitter - onEdge;
      }
      else
      {
        towardsLight = glm::dvec3(light) + std::tan(radius) * jitter;
      }
      const glm::dvec3 p = onEdge - (0.02 + 2.0 * unit(rng)) * glm::normalize(towardsLight);
      const int m = MultiplicityFrom(p, a, faces, 2, frontOnly);
      bool changes = false;
      for (const glm::dvec4& s : samples)
      {
        changes = changes || (m != 0 && SampleCrossing(p, a, b, light, s) != 0);
      }
      changed += changes;
      misses += changes && !InsidePolyhedron(region, p, 1e-9);
    }
  }
  volumeRatio = wedgeVolume > 0.0 ? cutVolume / wedgeVolume : 1.0;
  if (cuts > 0)
  {
    std::printf("  %zu cut wedges: %.1f points and %.1f triangles each\n", cuts,
      cutPoints / static_cast<double>(cuts), cutTriangles / static_cast<double>(cuts));
  }
  return misses;
}

void TestWedgeRegions(const std::vector<Caster>& casters,
  const std::vector<std::pair<glm::dvec4, double>>& lights, std::mt19937& rng)
{
  for (const Caster& caster : casters)
  {
    for (const auto& light : lights)
    {
      int changed = 0;
      double ratio = 1.0;
      const int misses =
        CountRegionMisses(caster, light.first, light.second, false, rng, changed, ratio);
      std::printf("%-24s light w=%g: %d changing points, %d outside the cut wedge; cut volume "
                  "%.2f of the wedge's\n",
        caster.Name.c_str(), light.first.w, changed, misses, ratio);
      Check(misses == 0, caster.Name + ": the cut wedge holds every point the edge changes");
    }
  }
  int changed = 0;
  double ratio = 1.0;
  const int misses =
    CountRegionMisses(casters[0], { 0.4, 0.3, 3.0, 1.0 }, 0.6, false, rng, changed, ratio);
  Check(changed > 200 && ratio < 0.7,
    "on the sphere the sector cuts the wedges (volume " + std::to_string(ratio) + ")");
  const int flipped =
    CountRegionMisses(casters[0], { 0.4, 0.3, 3.0, 1.0 }, 0.6, true, rng, changed, ratio);
  Check(flipped > 0 && misses == 0,
    "reversed sector half-spaces are detected (" + std::to_string(flipped) + " misses)");
}

void TestFacingOverLight()
{
  const glm::dvec4 point(0, 0, 2, 1), direction(0, 0, 1, 0);
  Check(FacingOverLight({ 0, 0, 1 }, { 0, 0, 0 }, point, 0.5) == LightFacing::Towards, "towards");
  Check(FacingOverLight({ 0, 0, -1 }, { 0, 0, 0 }, point, 0.5) == LightFacing::Away, "away");
  Check(FacingOverLight({ 1, 0, 0 }, { 0, 0, 0 }, point, 0.5) == LightFacing::Mixed, "mixed");
  Check(FacingOverLight({ 1, 0, 0 }, { 0, 0, 0 }, point, 0.0) == LightFacing::EdgeOn, "edge-on");
  Check(FacingOverLight({ 0, 1, 0.1 }, { 0, 0, 0 }, direction, 0.2) == LightFacing::Mixed,
    "directional mixed");
  Check(FacingOverLight({ 0, 1, 0.5 }, { 0, 0, 0 }, direction, 0.2) == LightFacing::Towards,
    "directional towards");
  Check(FacingOverLight({ 0, 0, 0 }, { 0, 0, 0 }, point, 0.0) == LightFacing::EdgeOn,
    "zero normal, point light: edge-on");
  Check(FacingOverLight({ 0, 0, 0 }, { 0, 0, 0 }, point, 0.5) == LightFacing::Mixed,
    "zero normal, area light: undecidable counts as mixed");
}

void TestDegenerate()
{
  // p on the edge's line, the path in the plane, NaN input: 0, never a crash or NaN.
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0);
  Check(SampleCrossing({ 2, 0, 0 }, a, b, { 0, 0, 3, 1 }, { 0.1, 0, 3, 1 }) == 0, "p on line");
  Check(SampleCrossing({ 0.5, -1, 0 }, a, b, { 0, 1, 0, 1 }, { 1, 2, 0, 1 }) == 0, "path in plane");
  const double nan = std::nan("");
  Check(SampleCrossing({ nan, 0, 0 }, a, b, { 0, 0, 3, 1 }, { 0.1, 0, 3, 1 }) == 0, "NaN p");
  const EdgeFace face{ { nan, 0, 0 }, 1 };
  Check(MultiplicityFrom({ 0, 0, 1 }, a, &face, 1, false) == 0, "NaN normal");
}

/// EdgePlaneMissesSamples may skip an edge only where no sample crosses it, and must skip a fair
/// share of random points (most planes through a random point and edge miss a small light);
/// with the spread understated tenfold (the mutation) it must skip crossings.
void TestEdgePlaneMisses(
  const std::vector<std::pair<glm::dvec4, double>>& lights, std::mt19937& rng)
{
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  auto point = [&]() { return glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  for (const auto& light : lights)
  {
    const glm::dvec4 centre = light.first;
    const std::vector<glm::dvec4> samples = SpreadLightSamples(
      centre, centre.w != 0.0 ? light.second : glm::degrees(light.second), 16, glm::dvec3(0.0));
    double spread = 0.0;
    for (const glm::dvec4& s : samples)
    {
      spread = std::max(spread, glm::length(glm::dvec3(s) - glm::dvec3(centre)));
    }
    int skipped = 0, wronglySkipped = 0, understatedMisses = 0;
    const int trials = 4000;
    for (int trial = 0; trial < trials; ++trial)
    {
      const glm::dvec3 p = point(), a = point(), b = a + 0.3 * (point() - a);
      bool crosses = false;
      for (const glm::dvec4& s : samples)
      {
        crosses = crosses || SampleCrossing(p, a, b, centre, s) != 0;
      }
      const bool skip = EdgePlaneMissesSamples(p, a, b, centre, spread);
      skipped += skip;
      wronglySkipped += skip && crosses;
      understatedMisses += crosses && EdgePlaneMissesSamples(p, a, b, centre, 0.1 * spread);
    }
    std::printf("light w=%g: %d of %d edges skipped, %d wrongly; understated spread: %d\n",
      centre.w, skipped, trials, wronglySkipped, understatedMisses);
    Check(wronglySkipped == 0, "an edge is skipped only where no sample crosses it");
    Check(skipped > trials / 4, "the test skips most edges a small light cannot see");
    Check(understatedMisses > 0, "an understated spread is caught");
  }
  const double nan = std::nan("");
  Check(!EdgePlaneMissesSamples({ nan, 0, 0 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 3, 1 }, 0.1),
    "NaN p: not skipped");
  Check(!EdgePlaneMissesSamples({ 2, 0, 0 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0, 3, 1 }, 0.1),
    "p on the edge's line: not skipped");
}

void TestPotentialSilhouetteIsSmall()
{
  // A far small light sees few potential silhouette edges on a fine closed sphere, and the
  // centre silhouette is among them.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  const CasterTopology topo = FromSource(sphere);
  const glm::dvec4 light(0, 0, 20, 1);
  const std::vector<std::uint32_t> potential =
    PotentialSilhouette(topo, glm::dmat4(1.0), light, 0.5, true);
  const ShadowVolume centre = ShadowVolume::Build(topo, light, false, false);
  Check(potential.size() >= centre.Silhouette.size(), "contains the centre silhouette");
  Check(potential.size() < topo.Edges.size() / 8,
    "potential silhouette " + std::to_string(potential.size()) + " of " +
      std::to_string(topo.Edges.size()) + " edges");
  const std::vector<std::uint32_t> none =
    PotentialSilhouette(topo, glm::dmat4(1.0), light, 0.0, true);
  Check(none.size() == centre.Silhouette.size(), "radius 0: the centre silhouette exactly");
}
void TestCostModel()
{
  // The benchmark's rows (wedges.md, "Cost", 2026-12-06, after the counting wedges were cut to
  // each receiver's piece) as the chooser sees them: P potential and E distinct centre
  // silhouette edges, and the angular radius that gives its E-weighted spread term (each
  // caster's own distance to the light), with the answer the measured times give. The model is
  // wrong on two rows of the 24, both within 14% of equal times (the glyphs at r = 1 with 16
  // samples, 0.95 of averaging's time, and the stream tubes at r = 0.2 with 16 samples, 1.14),
  // and exactly on the boundary on a third (the time-varying isosurface at r = 0.2 with 16
  // samples, 1.30, whose P and E change with its data): they are left out. The model before
  // averaged the glyphs at r = 1 with 64 samples at 2.3 times counting's time, and the classic
  // scene, the isosurface and the glyphs at r = 0.2 with 16 samples.
  Check(CountingIsCheaper({ { 504, 296, 0.01727 } }, 16), "classic, r 0.2, 16 samples: counting");
  Check(CountingIsCheaper({ { 504, 296, 0.01727 } }, 64), "classic, r 0.2, 64 samples: counting");
  Check(!CountingIsCheaper({ { 1418, 296, 0.08634 } }, 16), "classic, r 1, 16 samples: averaging");
  Check(!CountingIsCheaper({ { 1418, 296, 0.08634 } }, 64), "classic, r 1, 64 samples: averaging");
  Check(
    CountingIsCheaper({ { 4391, 3538, 0.01915 } }, 16), "isosurface, r 0.2, 16 samples: counting");
  Check(
    CountingIsCheaper({ { 4391, 3538, 0.01915 } }, 64), "isosurface, r 0.2, 64 samples: counting");
  Check(
    !CountingIsCheaper({ { 7893, 3538, 0.09576 } }, 16), "isosurface, r 1, 16 samples: averaging");
  Check(
    !CountingIsCheaper({ { 7893, 3538, 0.09576 } }, 64), "isosurface, r 1, 64 samples: averaging");
  Check(CountingIsCheaper({ { 9869, 9179, 0.01748 } }, 16), "glyphs, r 0.2, 16 samples: counting");
  Check(CountingIsCheaper({ { 9869, 9179, 0.01748 } }, 64), "glyphs, r 0.2, 64 samples: counting");
  Check(CountingIsCheaper({ { 12770, 9179, 0.08739 } }, 64), "glyphs, r 1, 64 samples: counting");
  Check(!CountingIsCheaper({ { 21139, 2243, 0.01935 } }, 16),
    "large mesh, r 0.2, 16 samples: averaging");
  Check(!CountingIsCheaper({ { 21139, 2243, 0.01935 } }, 64),
    "large mesh, r 0.2, 64 samples: averaging");
  Check(
    !CountingIsCheaper({ { 96582, 2243, 0.09675 } }, 16), "large mesh, r 1, 16 samples: averaging");
  Check(
    !CountingIsCheaper({ { 96582, 2243, 0.09675 } }, 64), "large mesh, r 1, 64 samples: averaging");
  Check(CountingIsCheaper({ { 51234, 46396, 0.01847 } }, 64),
    "stream tubes, r 0.2, 64 samples: counting");
  Check(!CountingIsCheaper({ { 71326, 46396, 0.09237 } }, 16),
    "stream tubes, r 1, 16 samples: averaging");
  Check(!CountingIsCheaper({ { 71326, 46396, 0.09237 } }, 64),
    "stream tubes, r 1, 64 samples: averaging");
  Check(CountingIsCheaper({ { 19988, 11592, 0.01916 } }, 64),
    "time-varying, r 0.2, 64 samples: counting");
  Check(!CountingIsCheaper({ { 53574, 11592, 0.09578 } }, 16),
    "time-varying, r 1, 16 samples: averaging");
  Check(!CountingIsCheaper({ { 53574, 11592, 0.09578 } }, 64),
    "time-varying, r 1, 64 samples: averaging");
  Check(!CountingIsCheaper({ { 504, 296, 0.016 } }, 4), "few samples favour averaging");
  Check(CountingIsCheaper({ { 1000, 1000, 0.016 }, { 10, 10, 0.08 } }, 16),
    "casters weigh by their silhouettes: the large one near the light decides");
  Check(CountingIsCheaper({ { 0, 0, 0.5 } }, 16), "no wedges: counting");
  Check(!CountingIsCheaper({ { 10, 0, 1e300 } }, 16), "huge angular radius: averaging");

  // Hysteresis: near the boundary the last choice stands; beyond 10% the model decides.
  const std::vector<CountingCost> even = { { 504, 296, 0.0175 } };
  const double ratio = CountingToAveraging(even, 16);
  std::printf("classic, r 0.2, 16 samples, rho 0.0175: counting / averaging %.3f\n", ratio);
  Check(ratio > 0.9 && ratio < 1.0, "a row just below the boundary");
  Check(CountingIsCheaper(even, 16) && CountingIsCheaper(even, 16, LastChoice::Counted) &&
      !CountingIsCheaper(even, 16, LastChoice::Averaged),
    "just below the boundary: the last choice stands");
  const std::vector<CountingCost> above = { { 504, 296, 0.0215 } };
  const double over = CountingToAveraging(above, 16);
  Check(over > 1.0 && over < 1.1 && CountingIsCheaper(above, 16, LastChoice::Counted) &&
      !CountingIsCheaper(above, 16),
    "just above the boundary: counting goes on once chosen");
  Check(!CountingIsCheaper({ { 504, 296, 0.08 } }, 16, LastChoice::Counted),
    "far above the boundary: averaging, whatever the last choice");
}
void TestCasterAngularRadius()
{
  // A ring of 16 silhouette edges of radius 2 around the origin, in a box from -2 to 2 (z from
  // -0.5 to 0.5), placed by a translation of 10 along x.
  std::vector<glm::dvec3> points;
  std::vector<SilhouetteEdge> ring;
  for (std::uint32_t i = 0; i < 16; ++i)
  {
    const double angle = 2.0 * 3.14159265358979 * i / 16.0;
    points.emplace_back(2.0 * std::cos(angle), 2.0 * std::sin(angle), 0.0);
    ring.push_back({ i, (i + 1) % 16, 1 });
  }
  const glm::dmat4 moved = glm::translate(glm::dmat4(1.0), glm::dvec3(10.0, 0.0, 0.0));
  const glm::dvec3 lo(8.0, -2.0, -0.5), hi(12.0, 2.0, 0.5);
  const double outside = CasterAngularRadius({ 10.0, 0.0, 5.0 }, 0.1, lo, hi, points, ring, moved);
  Check(
    std::abs(outside - 0.02) < 1e-12, "a light outside the box: radius over the centre's distance");
  // A lamp in the ring's hole: the box's centre lies next to it (1e300 before: averaging at up
  // to 9 times counting's time, a user trial), its silhouette about 2 away.
  const double hole = CasterAngularRadius({ 10.05, 0.0, 0.0 }, 0.1, lo, hi, points, ring, moved);
  std::printf("a lamp in a ring's hole: angular radius %.4f\n", hole);
  Check(
    hole > 0.045 && hole < 0.055, "a lamp inside the box: radius over its silhouette's distance");
  Check(CasterAngularRadius({ 10.0, 0.0, 0.0 }, 0.1, lo, hi, points, {}, moved) ==
      0.1 / (0.5 * glm::length(hi - lo)),
    "inside the box, no silhouette: radius over half the box's diagonal");
  Check(CasterAngularRadius({ 10.0, 0.0, 0.0 }, 2.5, lo, hi, points, ring, moved) == 1e300 &&
      CasterAngularRadius({ 10.0, 0.0, 0.6 }, 0.7, lo, hi, points, ring, moved) == 1e300,
    "a light reaching its caster, inside the box or out: averaging");
}
} // namespace

/// Counting's reference lies on the light, a small share of its radius from the centre, and off
/// the axis planes through the centre, where round numbers put faces.
void TestCountingReference()
{
  const glm::dvec4 positional(4.6, 0.8, -1.0, 1.0);
  const glm::dvec4 reference = penumbra::CountingReference(positional, 0.37);
  const glm::dvec3 off = glm::dvec3(reference) - glm::dvec3(positional);
  const double offset = penumbra::CountingReferenceOffset * 0.37;
  Check(reference.w == 1.0 && std::abs(glm::length(off) - offset) < 1e-12 &&
      std::abs(off.x) > 0.3 * offset && std::abs(off.y) > 0.3 * offset &&
      std::abs(off.z) > 0.3 * offset,
    "a positional light's reference lies off its centre's axis planes, inside the light");
  const glm::dvec4 directional(glm::normalize(glm::dvec3(0.0, 0.5, 1.0)), 0.0);
  const double radius = glm::radians(4.6);
  const glm::dvec4 turned = penumbra::CountingReference(directional, radius);
  const double angle =
    std::acos(std::min(1.0, glm::dot(glm::dvec3(turned), glm::dvec3(directional))));
  Check(turned.w == 0.0 && std::abs(glm::length(glm::dvec3(turned)) - 1.0) < 1e-12 &&
      std::abs(angle - penumbra::CountingReferenceOffset * radius) < 1e-9 &&
      std::abs(turned.x) > 1e-4,
    "a directional light's reference is its direction turned off the planes holding it");
}

/// The view ray of NDC (x, y) under `clip` (world to clip), about the world's origin.
ViewRay RayAt(const glm::dmat4& clip, double x, double y)
{
  const glm::dmat4 toWorld = glm::inverse(clip);
  const glm::dvec4 nearPoint = toWorld * glm::dvec4(x, y, -1.0, 1.0);
  const glm::dvec4 farPoint = toWorld * glm::dvec4(x, y, 1.0, 1.0);
  ViewRay ray;
  ray.Near = glm::dvec3(nearPoint) / nearPoint.w;
  ray.Far = glm::dvec3(farPoint) / farPoint.w;
  ray.NearW = (clip * glm::dvec4(ray.Near, 1.0)).w;
  ray.FarW = (clip * glm::dvec4(ray.Far, 1.0)).w;
  return ray;
}

/// The window depth of `point` under `clip`.
double WindowDepth(const glm::dmat4& clip, const glm::dvec3& point)
{
  const glm::dvec4 p = clip * glm::dvec4(point, 1.0);
  return 0.5 * (p.z / p.w + 1.0);
}

/// Counting's point stays on the seen side of its surface's plane wherever the rasterized depth
/// is off, at grazing views too (where a move along the view ray barely leaves the plane), and
/// takes the scene depth moved towards the eye where no plane is known, or where the plane is
/// not the pixel's; the background stays at the far plane.
void TestCountingPointDepth(std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double step = 1.0 / 16777216.0; // a 24-bit depth step
  const double depthBias = 4.0 * step, planeBias = 4.0 * step;
  const glm::dvec3 eye(0.0, -20.0, 3.0);
  const glm::dmat4 view = glm::lookAt(eye, glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(0.0, 0.0, 1.0));
  const glm::dmat4 clips[2] = { glm::perspective(glm::radians(30.0), 4.0 / 3.0, 0.5, 60.0) * view,
    glm::ortho(-8.0, 8.0, -6.0, 6.0, 0.5, 60.0) * view };
  int below = 0, belowWithoutPlane = 0, tooFar = 0, tried = 0;
  for (int i = 0; i < 4000; ++i)
  {
    const glm::dmat4& clip = clips[i % 2];
    const ViewRay ray = RayAt(clip, 0.9 * unit(rng), 0.9 * unit(rng));
    // A plane through a point on the ray, tilted from head-on to 0.5 degrees off edge-on.
    const glm::dvec3 along = glm::normalize(ray.Far - ray.Near);
    const double t = 0.2 + 0.6 * std::abs(unit(rng));
    const glm::dvec3 hit = ray.Near + t * (ray.Far - ray.Near);
    const double grazing = glm::radians(0.5 + 89.0 * std::pow(std::abs(unit(rng)), 3.0));
    glm::dvec3 across = glm::normalize(glm::cross(along, glm::dvec3(unit(rng), unit(rng), 1.0)));
    const glm::dvec3 normal = std::sin(grazing) * -along + std::cos(grazing) * across;
    const glm::dvec4 plane(normal, glm::dot(normal, hit));
    // The rasterized depth, off by up to 40 steps either way.
    const double exact = WindowDepth(clip, hit);
    const double scene = exact + std::round(40.0 * unit(rng)) * step;
    const auto height = [&](double depth)
    {
      // The point at that depth on this ray: clip coordinates are linear along it.
      const double u = (1.0 - depth) * ray.FarW / ((1.0 - depth) * ray.FarW + depth * ray.NearW);
      const glm::dvec3 point = ray.Far + u * (ray.Near - ray.Far);
      return glm::dot(normal, point) - plane.w; // positive on the eye's side
    };
    const double counted = CountingPointDepth(scene, ray, plane, depthBias, planeBias);
    const double clearance = planeBias * (glm::length(ray.Near) + glm::length(ray.Far));
    ++tried;
    below += height(counted) >= 0.9 * clearance ? 0 : 1;
    belowWithoutPlane +=
      height(CountingPointDepth(scene, ray, glm::dvec4(0.0), depthBias, planeBias)) > 0.0 ? 0 : 1;
    // Not further towards the eye than the bias, or the clearance, ask.
    tooFar += counted >= exact - depthBias - 1e-12 ||
        std::abs(height(counted) - clearance) <= 1e-3 * clearance + 1e-12
      ? 0
      : 1;
  }
  char text[200];
  std::snprintf(text, sizeof(text),
    "counting's point clears its plane on the seen side: %d of %d below (%d from the scene "
    "depth alone), %d farther than asked",
    below, tried, belowWithoutPlane, tooFar);
  Check(below == 0 && tooFar == 0 && belowWithoutPlane > 100, text);

  const ViewRay ray = RayAt(clips[0], 0.1, -0.2);
  const glm::dvec3 hit = ray.Near + 0.5 * (ray.Far - ray.Near);
  const glm::dvec3 normal = glm::normalize(ray.Near - ray.Far);
  const double exact = WindowDepth(clips[0], hit);
  const glm::dvec4 elsewhere(normal, glm::dot(normal, ray.Near + 0.3 * (ray.Far - ray.Near)));
  // A plane along the ray (seen exactly edge-on) gives no depth of its own.
  const glm::dvec3 along = glm::normalize(glm::cross(ray.Far - ray.Near, glm::dvec3(0, 0, 1)));
  const glm::dvec4 edgeOn(along, glm::dot(along, hit));
  Check(CountingPointDepth(1.0, ray, glm::dvec4(normal, 0.0), depthBias, planeBias) == 1.0 &&
      CountingPointDepth(exact, ray, glm::dvec4(0.0), depthBias, planeBias) == exact - depthBias &&
      CountingPointDepth(exact, ray, elsewhere, depthBias, planeBias) == exact - depthBias &&
      CountingPointDepth(exact, ray, edgeOn, depthBias, planeBias) == exact - depthBias &&
      CountingPointDepth(0.5 * depthBias, ray, glm::dvec4(0.0), depthBias, planeBias) == 0.0,
    "the background stays at the far plane; no plane, another surface's or one seen edge-on "
    "takes the scene depth moved; never below 0");
}

/// The own-surface test keeps the samples on the side the eye sees, whichever way the normal
/// points.
void TestSurfaceSide(std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int wrong = 0;
  for (int i = 0; i < 500; ++i)
  {
    const glm::dvec3 p(unit(rng), unit(rng), unit(rng));
    const glm::dvec3 normal = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
    const double eyeSide = i % 2 == 0 ? 1.0 : -1.0;
    const glm::dvec3 eye = p + 3.0 * eyeSide * normal + glm::dvec3(unit(rng), unit(rng), unit(rng));
    const bool eyeAbove = glm::dot(normal, eye - p) > 0.0;
    const glm::dvec3 seen = eyeAbove ? normal : -normal;
    const glm::dvec4 front(p + seen + 0.5 * glm::cross(seen, glm::dvec3(0.3, 0.1, 0.9)), 1.0);
    const glm::dvec4 behind(p - seen, 1.0);
    for (const double flip : { 1.0, -1.0 })
    {
      wrong += SeesAboveSurface(flip * normal, eye - p, p, front) &&
          !SeesAboveSurface(flip * normal, eye - p, p, behind) &&
          SeesAboveSurface(flip * normal, eye - p, p, glm::dvec4(seen, 0.0)) &&
          !SeesAboveSurface(flip * normal, eye - p, p, glm::dvec4(-seen, 0.0))
        ? 0
        : 1;
    }
  }
  // The shortcut: where it says all or none, every sample within the spread agrees.
  int cuts[3] = { 0, 0, 0 }, disagree = 0;
  for (int i = 0; i < 3000; ++i)
  {
    const glm::dvec3 normal = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
    const bool positional = i % 2 == 0;
    const glm::dvec3 p(unit(rng), unit(rng), unit(rng));
    const glm::dvec3 reference = positional ? p + 2.0 * glm::dvec3(unit(rng), unit(rng), unit(rng))
                                            : glm::normalize(glm::dvec3(unit(rng), unit(rng), 1.0));
    const double spread = 0.3 * std::abs(unit(rng));
    const glm::dvec3 towards = positional ? reference - p : reference;
    const int cut = SurfaceCutsLight(normal, towards, spread);
    ++cuts[cut + 1];
    for (int k = 0; k < 16 && cut != 0; ++k)
    {
      // A sample at the spread's edge, in any direction.
      const glm::dvec3 off = spread * glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
      const glm::dvec4 sample =
        positional ? glm::dvec4(reference + off, 1.0) : glm::dvec4(reference + off, 0.0);
      disagree += SeesAboveSurface(normal, normal, p, sample) != (cut > 0) ? 1 : 0;
    }
  }
  Check(disagree == 0 && cuts[0] > 100 && cuts[1] > 100 && cuts[2] > 100,
    "the all-or-none shortcut agrees with every sample it skips (" + std::to_string(disagree) +
      " disagree)");
  Check(wrong == 0 &&
      SeesAboveSurface(
        glm::dvec3(0.0), { 0.0, 0.0, 1.0 }, glm::dvec3(0.0), { 0.0, 0.0, -1.0, 0.0 }),
    "the own-surface test keeps the eye's side whichever way the normal points (" +
      std::to_string(wrong) + " wrong); no plane known sees all");
}

int main()
{
  std::mt19937 rng(7);
  TestCasterAngularRadius();
  TestCountingReference();
  TestSurfaceSide(rng);
  TestCountingPointDepth(rng);
  TestFacingOverLight();
  TestDegenerate();
  TestPotentialSilhouetteIsSmall();
  TestCostModel();
  const std::vector<Caster> casters = MakeCasters(rng);
  const std::vector<std::pair<glm::dvec4, double>> lights = { { { 0.4, 0.3, 3.0, 1.0 }, 0.6 },
    { { 0.2, 2.5, 1.0, 1.0 }, 0.9 },
    { glm::dvec4(glm::normalize(glm::dvec3(0.3, 0.2, 1.0)), 0.0), 0.3 } };
  int total = 0, totalNonZero = 0;
  for (const Caster& caster : casters)
  {
    for (const auto& light : lights)
    {
      int compared = 0, nonZero = 0;
      const int mismatches =
        CountMismatches(caster, light.first, light.second, 1, 150, rng, compared, nonZero);
      std::printf("%-24s light w=%g: %d samples compared (%d occluded), %d mismatches\n",
        caster.Name.c_str(), light.first.w, compared, nonZero, mismatches);
      Check(mismatches == 0, caster.Name + ": predicted depth complexity equals brute force");
      Check(compared > 1000, caster.Name + ": enough samples compared");
      total += compared;
      totalNonZero += nonZero;
    }
  }
  Check(totalNonZero > total / 20, "enough occluded samples to test the edge terms");
  TestWedgeRegions(casters, lights, rng);
  TestEdgePlaneMisses(lights, rng);
  // The mutation: the edge term with the wrong sign must be caught.
  int compared = 0, nonZero = 0;
  const int mutated =
    CountMismatches(casters[0], lights[0].first, lights[0].second, -1, 150, rng, compared, nonZero);
  Check(
    mutated > 0, "a flipped edge term is detected (" + std::to_string(mutated) + " mismatches)");
  return penumbra_test::Finish();
}
