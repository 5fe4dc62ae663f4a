// Unit tests of the GPU-free geometry core: topology, silhouettes and shadow volumes.
//
// The central check emulates the stencil on the CPU. For a query point q the shadow volume's
// winding number (signed crossings of a ray from q with the volume's triangles, infinity replaced
// by a far finite distance) must equal the number of casting triangles that the segment from q
// to the light crosses: every triangle occludes whatever its orientation, and for closed,
// consistently oriented meshes the front faces alone count. This covers sides, caps, the dark-cap
// fan, multiplicities and mirrored matrices at once.
//
// A z-pass volume cut short on VolumeEndPlane must count like the whole one: the signed
// crossings of its sides with segments from the near rectangle to points of the scene box are
// compared for both.
#include "penumbraCasterTopology.h"
#include "penumbraCheck.h"
#include "penumbraCulling.h"
#include "penumbraShadowVolume.h"

#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkParametricBoy.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricKlein.h"
#include "vtkParametricMobius.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>

using namespace penumbra;
using penumbra_test::Check;

namespace
{

/// Möller-Trumbore; returns the ray parameter or -1, and whether the hit is too close to an
/// edge to count robustly.
double RayTriangle(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec3& c, bool& nearEdge)
{
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-300)
  {
    return -1.0;
  }
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, p) / det;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(dir, q) / det;
  const double t = glm::dot(e2, q) / det;
  const double eps = 1e-9;
  if (u < -eps || v < -eps || u + v > 1 + eps || t < -eps)
  {
    return -1.0;
  }
  if (u < eps || v < eps || u + v > 1 - eps || t < eps)
  {
    nearEdge = true;
  }
  return t;
}

glm::dvec3 VolumePoint(
  const CasterTopology& topo, std::uint32_t index, const glm::dvec4& light, double far)
{
  const std::size_t n = topo.Points.size();
  if (index < n)
  {
    return topo.Points[index];
  }
  const glm::dvec3& p = topo.Points[index - n];
  if (light.w == 0.0)
  {
    // Towards a directional light every point sweeps to one point at infinity (w = 0 on the
    // GPU); a shared far apex keeps the emulated volume closed too.
    // Far enough that the emulated cone is a prism near the caster to 1e-9.
    return -1e4 * far * glm::normalize(glm::dvec3(light));
  }
  const glm::dvec3 away = p - glm::dvec3(light);
  return p + far * away / glm::length(away);
}

/// Triangles [First, First + Count) of a volume's index list, each counted Multiplicity times.
struct CountedList
{
  const std::vector<std::uint32_t>* Indices;
  std::vector<TriangleRun> Runs;
};

/// What Winding counts: every copy once (as the stencil), or only the runs of first copies, each
/// weighted by its multiplicity (as counting in colour draws them).
std::vector<CountedList> VolumeLists(const ShadowVolume& volume, bool weighted)
{
  const auto whole = [](const std::vector<std::uint32_t>& list) {
    return std::vector<TriangleRun>{ { 1, 0, list.size() } };
  };
  return { { &volume.Sides, weighted ? volume.SideRuns : whole(volume.Sides) },
    { &volume.LightCap, whole(volume.LightCap) },
    { &volume.DarkCap, weighted ? volume.DarkCapRuns : whole(volume.DarkCap) } };
}

/// Winding number of the closed volume (sides + dark cap + light cap) at q, or INT_MIN when
/// every tried ray grazed an edge; `weighted` counts the multiplicity runs instead of every copy.
int Winding(const CasterTopology& topo, const ShadowVolume& volume, const glm::dvec4& light,
  const glm::dvec3& q, std::mt19937& rng, bool weighted = false)
{
  const double far = 1e4 * (1.0 + glm::length(topo.BoundsMax - topo.BoundsMin));
  std::normal_distribution<double> normal;
  for (int attempt = 0; attempt < 20; ++attempt)
  {
    const glm::dvec3 dir = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    int winding = 0;
    bool nearEdge = false;
    for (const CountedList& list : VolumeLists(volume, weighted))
    {
      const std::vector<std::uint32_t>& indices = *list.Indices;
      for (const TriangleRun& run : list.Runs)
      {
        for (std::size_t i = run.First; i < run.First + run.Count; i += 3)
        {
          const glm::dvec3 a = VolumePoint(topo, indices[i], light, far);
          const glm::dvec3 b = VolumePoint(topo, indices[i + 1], light, far);
          const glm::dvec3 c = VolumePoint(topo, indices[i + 2], light, far);
          if (RayTriangle(q, dir, a, b, c, nearEdge) >= 0.0)
          {
            // Outward (counter-clockwise) normal along the ray: the ray leaves the volume.
            const int multiplicity = static_cast<int>(run.Multiplicity);
            winding += glm::dot(glm::cross(b - a, c - a), dir) > 0 ? multiplicity : -multiplicity;
          }
        }
      }
    }
    if (!nearEdge)
    {
      return winding;
    }
  }
  return std::numeric_limits<int>::min();
}

/// Casting triangles crossed by the segment from q to the light, per the counting rule.
int Occluders(const CasterTopology& topo, const glm::dvec4& light, const glm::dvec3& q,
  bool& nearEdge, CountingRule rule)
{
  const bool frontFacesOnly = rule == CountingRule::FrontFacesWhereTheySuffice &&
    ShadowVolume::FrontFacesSuffice(topo, light);
  const glm::dvec3 toLight = light.w != 0.0 ? glm::dvec3(light) - q : glm::dvec3(light) * 1e6;
  int count = 0;
  for (std::uint32_t t = 0; t < topo.Triangles.size(); ++t)
  {
    const int facing = ShadowVolume::Facing(topo, t, light);
    if (facing == 0 || (frontFacesOnly && facing < 0))
    {
      continue;
    }
    const glm::uvec3& tri = topo.Triangles[t];
    const double hit =
      RayTriangle(q, toLight, topo.Points[tri.x], topo.Points[tri.y], topo.Points[tri.z], nearEdge);
    if (hit >= 0.0 && hit <= 1.0)
    {
      ++count;
    }
  }
  return count;
}

/// Whether any non-degenerate triangle, whatever its orientation, blocks q from the light.
bool AnyOccluder(
  const CasterTopology& topo, const glm::dvec4& light, const glm::dvec3& q, bool& nearEdge)
{
  const glm::dvec3 toLight = light.w != 0.0 ? glm::dvec3(light) - q : glm::dvec3(light) * 1e6;
  for (const glm::uvec3& tri : topo.Triangles)
  {
    const double hit =
      RayTriangle(q, toLight, topo.Points[tri.x], topo.Points[tri.y], topo.Points[tri.z], nearEdge);
    if (hit >= 0.0 && hit <= 1.0)
    {
      return true;
    }
  }
  return false;
}

/// Compares winding and occluder counts at random points around the caster, and the winding
/// counted over the multiplicity runs with the one over every copy.
void CheckVolume(const std::string& name, const CasterTopology& topo, const glm::dvec4& light,
  std::mt19937& rng, int samples = 300,
  CountingRule rule = CountingRule::FrontFacesWhereTheySuffice)
{
  const ShadowVolume volume = ShadowVolume::Build(topo, light, false, true, rule);
  Check(volume.SilhouetteIsBalanced(topo.Points.size()), name + ": silhouette balanced");
  Check(volume.RunsCoverEveryCopy(),
    name + ": multiplicity runs lead the lists and account for every copy");
  const glm::dvec3 lo = topo.BoundsMin, hi = topo.BoundsMax;
  const glm::dvec3 size = hi - lo + glm::dvec3(1e-3);
  std::uniform_real_distribution<double> unit(-0.5, 1.5);
  int compared = 0, mismatches = 0, weightedCompared = 0, weightedMismatches = 0;
  for (int i = 0; i < samples; ++i)
  {
    // Points around and behind the caster, where its shadow lies.
    glm::dvec3 q = lo + size * glm::dvec3(unit(rng), unit(rng), unit(rng));
    const glm::dvec3 away = light.w != 0.0 ? q - glm::dvec3(light) : -glm::dvec3(light);
    q +=
      glm::normalize(away) * glm::length(size) * std::uniform_real_distribution<double>(0, 1)(rng);
    bool nearEdge = false;
    const int expected = Occluders(topo, light, q, nearEdge, rule);
    const int winding = Winding(topo, volume, light, q, rng);
    if (nearEdge || winding == std::numeric_limits<int>::min())
    {
      continue;
    }
    ++compared;
    // Independent of the counting rule: shadowed iff any triangle blocks the segment.
    bool anyEdge = false;
    const bool blocked = AnyOccluder(topo, light, q, anyEdge);
    if (!anyEdge && (winding > 0) != blocked)
    {
      if (mismatches++ < 3)
      {
        std::printf("  %s: q=(%g,%g,%g) winding %d but blocked=%d (light %g %g %g %g)\n",
          name.c_str(), q.x, q.y, q.z, winding, int(blocked), light.x, light.y, light.z, light.w);
      }
      continue;
    }
    if (winding != expected)
    {
      if (mismatches++ < 3)
      {
        std::printf("  %s: q=(%g,%g,%g) winding %d, occluders %d\n", name.c_str(), q.x, q.y, q.z,
          winding, expected);
      }
    }
    const int weighted = Winding(topo, volume, light, q, rng, true);
    if (weighted != std::numeric_limits<int>::min())
    {
      ++weightedCompared;
      weightedMismatches += weighted != winding ? 1 : 0;
    }
  }
  Check(weightedCompared > compared / 2 && weightedMismatches == 0,
    name + ": multiplicity runs weighted wind as every copy does (" +
      std::to_string(weightedMismatches) + " of " + std::to_string(weightedCompared) + " differ)");
  Check(compared > samples / 2, name + ": enough robust samples");
  Check(mismatches == 0,
    name + ": volume winding equals occluder count (" + std::to_string(mismatches) + " of " +
      std::to_string(compared) + " differ)");
}

CasterTopology FromSource(vtkPolyDataAlgorithm* source)
{
  source->Update();
  return CasterTopology::Build(source->GetOutput());
}

CasterTopology Parametric(vtkParametricFunction* function, int resolution)
{
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(function);
  source->SetUResolution(resolution);
  source->SetVResolution(resolution);
  source->SetWResolution(resolution);
  source->GenerateTextureCoordinatesOff();
  return FromSource(source);
}

std::vector<glm::dvec4> Lights(const CasterTopology& topo)
{
  const double r = glm::length(topo.BoundsMax - topo.BoundsMin);
  return { { 0.3 * r, 2.0 * r, 0.7 * r, 1.0 }, { -1.5 * r, 0.2 * r, 0.1 * r, 1.0 },
    { 0.1, 0.3, 1.0, 0.0 }, { 0.8, 0.1, -0.2, 0.0 } };
}

void TestClosedSphere(std::mt19937& rng)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(12);
  const CasterTopology topo = FromSource(sphere);
  Check(topo.ClosedAndOriented, "sphere is closed and oriented");
  Check(topo.Report.BoundaryEdges == 0, "sphere has no boundary");
  for (const glm::dvec4& light : Lights(topo))
  {
    const ShadowVolume volume = ShadowVolume::Build(topo, light, false);
    // Brute force: an edge is a silhouette edge iff exactly one of its faces faces the light.
    std::size_t expected = 0;
    for (const Edge& e : topo.Edges)
    {
      const int f0 = ShadowVolume::Facing(topo, topo.Uses[e.FirstUse].Triangle, light) > 0;
      const int f1 = ShadowVolume::Facing(topo, topo.Uses[e.FirstUse + 1].Triangle, light) > 0;
      expected += f0 != f1;
    }
    Check(volume.Silhouette.size() == expected, "sphere silhouette edges match brute force");
    bool unit = true;
    for (const SilhouetteEdge& e : volume.Silhouette)
    {
      unit = unit && e.Multiplicity == 1;
    }
    Check(unit, "closed mesh silhouette multiplicities are 1");
    CheckVolume("sphere", topo, light, rng);
    // Translucent casters count every surface: two behind a closed sphere, one inside it.
    CheckVolume("sphere, every triangle", topo, light, rng, 300, CountingRule::EveryTriangle);
    const ShadowVolume every =
      ShadowVolume::Build(topo, light, false, true, CountingRule::EveryTriangle);
    const glm::dvec3 centre = 0.5 * (topo.BoundsMin + topo.BoundsMax);
    const glm::dvec3 away =
      glm::normalize(light.w != 0.0 ? centre - glm::dvec3(light) : -glm::dvec3(light));
    Check(Winding(topo, every, light, centre + 3.0 * away, rng) == 2 &&
        Winding(topo, every, light, centre + 0.01 * away, rng) == 1 &&
        Winding(topo, volume, light, centre + 3.0 * away, rng) == 1,
      "every triangle: two surfaces behind the sphere, one inside; front faces: one behind");
    // Counted with every triangle each silhouette edge is walked twice: a weighted count draws
    // each side once, sparing half the side indices; front faces walk each once, sparing none.
    Check(every.Silhouette.size() == volume.Silhouette.size() &&
        every.Sides.size() == 2 * volume.Sides.size() &&
        every.RepeatedSideIndices() == volume.Sides.size() && volume.RepeatedSideIndices() == 0,
      "every triangle: the second copy of each side is repeated; front faces: none");
  }
  // A light inside a closed mesh: nothing outside it sees the light.
  Check(!ShadowVolume::FrontFacesSuffice(topo, { 0.1, 0.05, -0.1, 1.0 }),
    "light inside: all faces count");
  CheckVolume("light inside sphere", topo, { 0.1, 0.05, -0.1, 1.0 }, rng);
}

void TestWelding(std::mt19937& rng)
{
  // A cube with split normals has 24 points; welded it is closed with 8.
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  const CasterTopology topo = FromSource(triangles);
  Check(topo.Points.size() == 8,
    "cube welds to 8 points (got " + std::to_string(topo.Points.size()) + ")");
  Check(topo.ClosedAndOriented, "welded cube is closed");
  Check(topo.Triangles.size() == 12, "cube has 12 triangles");
  for (const glm::dvec4& light : Lights(topo))
  {
    CheckVolume("cube", topo, light, rng);
  }
}

void TestOpenSheet(std::mt19937& rng)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(4, 3);
  const CasterTopology topo = FromSource(plane);
  Check(!topo.ClosedAndOriented, "sheet is open");
  Check(topo.Report.BoundaryEdges == 14, "sheet boundary edges");
  for (const glm::dvec4& light : Lights(topo))
  {
    CheckVolume("sheet", topo, light, rng);
  }
  // Lit from below (back side): the sheet still casts, the same outline reversed.
  const glm::dvec4 below(0.1, 0.2, -3.0, 1.0), above(0.1, 0.2, 3.0, 1.0);
  const ShadowVolume back = ShadowVolume::Build(topo, below, false);
  const ShadowVolume front = ShadowVolume::Build(topo, above, false);
  Check(back.Silhouette.size() == 14 && front.Silhouette.size() == 14, "sheet outline both sides");
  CheckVolume("sheet-from-below", topo, below, rng);
}

void TestNonManifoldAndInconsistent(std::mt19937& rng)
{
  // Three fins on one edge, one wound the other way, plus a flipped neighbour.
  const std::vector<glm::dvec3> points = { { 0, 0, 0 }, { 0, 0, 1 }, { 1, 0, 0.5 },
    { -0.5, 0.8, 0.5 }, { -0.5, -0.8, 0.5 }, { 1, 1, 0.5 } };
  const std::vector<glm::uvec3> tris = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 }, { 1, 2, 5 } };
  const CasterTopology topo = CasterTopology::Build(points, tris);
  Check(topo.Report.NonManifoldEdges == 1, "one non-manifold edge");
  Check(topo.Report.InconsistentEdges == 1, "one inconsistently wound edge");
  for (const glm::dvec4& light : Lights(topo))
  {
    CheckVolume("fins", topo, light, rng);
  }
}

void TestNonOrientable(std::mt19937& rng)
{
  vtkNew<vtkParametricMobius> mobius;
  vtkNew<vtkParametricKlein> klein;
  vtkNew<vtkParametricBoy> boy;
  const std::pair<const char*, vtkParametricFunction*> surfaces[] = { { "mobius", mobius },
    { "klein", klein }, { "boy", boy } };
  for (const auto& surface : surfaces)
  {
    const CasterTopology topo = Parametric(surface.second, 24);
    Check(!topo.Empty(), std::string(surface.first) + " has triangles");
    for (const glm::dvec4& light : Lights(topo))
    {
      CheckVolume(surface.first, topo, light, rng, 150);
    }
  }
}

void TestMirrored(std::mt19937& rng)
{
  // Mirroring the mesh (negative determinant) must give the same volume as mirroring the
  // world-space result: build in object space with mirrored=true and compare windings.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  const CasterTopology topo = FromSource(sphere);
  CasterTopology mirrored = topo;
  for (glm::dvec3& p : mirrored.Points)
  {
    p.x = -p.x;
  }
  const glm::dvec4 light(2.0, 3.0, 1.0, 1.0), lightObject(-2.0, 3.0, 1.0, 1.0);
  const ShadowVolume volume = ShadowVolume::Build(topo, lightObject, true);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  int mismatches = 0, compared = 0, shadowed = 0;
  for (int i = 0; i < 100; ++i)
  {
    const glm::dvec3 q(coord(rng), coord(rng) - 1.5, coord(rng));
    // Winding in world space: evaluate with the mirrored points, the volume indices unchanged.
    const int winding = Winding(mirrored, volume, light, q, rng);
    bool nearEdge = false;
    const int expected =
      Occluders(mirrored, light, q, nearEdge, CountingRule::FrontFacesWhereTheySuffice) > 0 ? 1 : 0;
    if (!nearEdge && winding != std::numeric_limits<int>::min())
    {
      ++compared;
      shadowed += expected;
      mismatches += winding != expected;
    }
  }
  std::printf(
    "     mirrored: %d of 100 points compared, %d of them shadowed\n", compared, shadowed);
  Check(compared >= 80 && shadowed >= 10 && compared - shadowed >= 10,
    "mirrored caster: points both in and out of the shadow are compared");
  Check(mismatches == 0, "mirrored caster keeps positive volumes");
}

void TestDegenerateInput()
{
  // NaN points, zero-area and repeated-vertex triangles, lines and vertices.
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(1, 0, 0);
  pts->InsertNextPoint(0, 1, 0);
  pts->InsertNextPoint(std::nan(""), 0, 0);
  pts->InsertNextPoint(2, 0, 0); // collinear with 0 and 1
  vtkNew<vtkCellArray> polys, lines, verts;
  const vtkIdType good[3] = { 0, 1, 2 }, nan[3] = { 0, 3, 2 }, flat[3] = { 0, 1, 4 },
                  repeated[3] = { 0, 0, 2 }, line[2] = { 0, 1 }, vert[1] = { 2 };
  polys->InsertNextCell(3, good);
  polys->InsertNextCell(3, nan);
  polys->InsertNextCell(3, flat);
  polys->InsertNextCell(3, repeated);
  lines->InsertNextCell(2, line);
  verts->InsertNextCell(1, vert);
  vtkNew<vtkPolyData> data;
  data->SetPoints(pts);
  data->SetPolys(polys);
  data->SetLines(lines);
  data->SetVerts(verts);
  const CasterTopology topo = CasterTopology::Build(data);
  Check(topo.Triangles.size() == 1, "only the good triangle survives");
  Check(topo.Report.NonFinitePoints == 1 && topo.Report.NonFiniteTriangles == 1, "NaN reported");
  Check(topo.Report.DegenerateTriangles == 2, "degenerate triangles reported");
  Check(topo.Report.SkippedLines == 1 && topo.Report.SkippedVerts == 1, "lines and verts reported");
  Check(!topo.Report.Describe().empty(), "problems described");
  Check(topo.Report.Describe().find("2 degenerate") != std::string::npos &&
      topo.Report.Describe(false).find("degenerate") == std::string::npos,
    "zero-area triangles named only when asked for");

  vtkNew<vtkPolyData> empty;
  Check(CasterTopology::Build(empty).Empty(), "empty polydata gives no triangles");
  Check(CasterTopology::Build(nullptr).Empty(), "null polydata gives no triangles");
  const ShadowVolume none =
    ShadowVolume::Build(CasterTopology::Build(empty), { 0, 1, 0, 1 }, false);
  Check(none.Sides.empty() && none.LightCap.empty(), "empty caster casts nothing");
}

/// The triangles of one arrowhead quad whose reflex corner is `reflex` (0 to 3).
CasterTopology ArrowheadQuad(vtkIdType reflex)
{
  // Counter-clockwise (0, 0), (2, 1), (0, 2), then the reflex corner (0.5, 1): only the diagonal
  // from the reflex corner stays inside.
  const double corners[4][3] = { { 0, 0, 0 }, { 2, 1, 0 }, { 0, 2, 0 }, { 0.5, 1, 0 } };
  vtkNew<vtkPoints> pts;
  vtkIdType ids[4];
  for (vtkIdType k = 0; k < 4; ++k)
  {
    ids[k] = pts->InsertNextPoint(corners[(k + 7 - reflex) % 4]);
  }
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(4, ids);
  vtkNew<vtkPolyData> data;
  data->SetPoints(pts);
  data->SetPolys(polys);
  return CasterTopology::Build(data);
}

void TestPolygonsCutAsVTKDraws()
{
  // VTK's mapper draws a polygon as the fan from its first corner; the pass takes a caster's
  // depth from its mesh only where the ear cut gave those same triangles.
  const CasterTopology fan = ArrowheadQuad(0);
  Check(fan.Triangles.size() == 2 && fan.Report.PolygonsCutUnlikeVTK == 0,
    "a polygon whose only inside diagonal starts at its first corner is cut as VTK's fan");
  const CasterTopology other = ArrowheadQuad(1);
  Check(other.Triangles.size() == 2 && other.Report.PolygonsCutUnlikeVTK == 1,
    "a polygon cut along another diagonal than the fan's is counted");
  Check(other.Report.Describe().empty(), "a cut unlike VTK's is not a mesh problem");
  vtkNew<vtkSphereSource> triangles;
  Check(FromSource(triangles).Report.PolygonsCutUnlikeVTK == 0, "triangles are VTK's own");
  // Convex polygons, planar (a plane's and a cube's quads, which the ear cut took along the other
  // diagonal) or warped, are cut as the fan: their depth, and their shadow, are what VTK draws.
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(4, 3);
  vtkNew<vtkCubeSource> cube;
  const CasterTopology quads = FromSource(plane), box = FromSource(cube);
  Check(quads.Triangles.size() == 24 && quads.Report.PolygonsCutUnlikeVTK == 0 &&
      box.Triangles.size() == 12 && box.Report.PolygonsCutUnlikeVTK == 0,
    "a plane's and a cube's quads are cut as VTK's fan");
  vtkNew<vtkPoints> pts;
  const double warped[4][3] = { { 0, 0, 0 }, { 1, 0, 0.3 }, { 1, 1, 0 }, { 0, 1, 0.3 } };
  vtkIdType ids[4];
  for (vtkIdType k = 0; k < 4; ++k)
  {
    ids[k] = pts->InsertNextPoint(warped[k]);
  }
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(4, ids);
  vtkNew<vtkPolyData> data;
  data->SetPoints(pts);
  data->SetPolys(polys);
  const CasterTopology saddle = CasterTopology::Build(data);
  auto namesFirstCorner = [](const glm::uvec3& t) { return t.x == 0 || t.y == 0 || t.z == 0; };
  const bool fromFirstCorner = saddle.Triangles.size() == 2 &&
    namesFirstCorner(saddle.Triangles[0]) && namesFirstCorner(saddle.Triangles[1]);
  Check(fromFirstCorner && saddle.Report.PolygonsCutUnlikeVTK == 0,
    "a warped convex quad is cut along the fan's diagonal, from its first corner");
}

/// Whether two builds gave the same topology, field by field.
bool SameTopology(const CasterTopology& a, const CasterTopology& b)
{
  auto sameEdges = [](const std::vector<Edge>& l, const std::vector<Edge>& r)
  {
    return std::equal(l.begin(), l.end(), r.begin(), r.end(),
      [](const Edge& x, const Edge& y)
      {
        return x.A == y.A && x.B == y.B && x.FirstUse == y.FirstUse && x.UseCount == y.UseCount &&
          x.Kind == y.Kind;
      });
  };
  auto sameUses = [](const std::vector<EdgeUse>& l, const std::vector<EdgeUse>& r)
  {
    return std::equal(l.begin(), l.end(), r.begin(), r.end(),
      [](const EdgeUse& x, const EdgeUse& y)
      { return x.Triangle == y.Triangle && x.Sign == y.Sign; });
  };
  const TopologyReport &ra = a.Report, &rb = b.Report;
  return a.Origin == b.Origin && a.Points == b.Points && a.Triangles == b.Triangles &&
    sameEdges(a.Edges, b.Edges) && sameUses(a.Uses, b.Uses) && a.BoundsMin == b.BoundsMin &&
    a.BoundsMax == b.BoundsMax && a.ClosedAndOriented == b.ClosedAndOriented &&
    ra.InputPoints == rb.InputPoints && ra.WeldedPoints == rb.WeldedPoints &&
    ra.NonFinitePoints == rb.NonFinitePoints && ra.InputTriangles == rb.InputTriangles &&
    ra.DegenerateTriangles == rb.DegenerateTriangles &&
    ra.NonFiniteTriangles == rb.NonFiniteTriangles &&
    ra.InvalidIndexTriangles == rb.InvalidIndexTriangles && ra.BoundaryEdges == rb.BoundaryEdges &&
    ra.InconsistentEdges == rb.InconsistentEdges && ra.NonManifoldEdges == rb.NonManifoldEdges;
}

/// A torus of 2 * u * v triangles whose seams are duplicated points (they weld), with a NaN
/// point, degenerate triangles and a triangle naming a point that does not exist scattered
/// through it.
void AwkwardTorus(int u, int v, std::vector<glm::dvec3>& points, std::vector<glm::uvec3>& triangles)
{
  points.clear();
  triangles.clear();
  for (int i = 0; i <= u; ++i)
  {
    for (int j = 0; j <= v; ++j)
    {
      const double a = 2.0 * 3.141592653589793 * i / u, b = 2.0 * 3.141592653589793 * j / v;
      points.emplace_back((2.0 + 0.7 * std::cos(b)) * std::cos(a),
        (2.0 + 0.7 * std::cos(b)) * std::sin(a), 0.7 * std::sin(b));
    }
  }
  const std::uint32_t nan = static_cast<std::uint32_t>(points.size());
  points.emplace_back(std::nan(""), 0.0, 0.0);
  auto id = [v](int i, int j) { return static_cast<std::uint32_t>(i * (v + 1) + j); };
  for (int i = 0; i < u; ++i)
  {
    for (int j = 0; j < v; ++j)
    {
      triangles.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      triangles.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
      if ((i * v + j) % 9973 == 0)
      {
        triangles.emplace_back(id(i, j), id(i, j), id(i + 1, j));
        triangles.emplace_back(id(i, j), nan, id(i + 1, j));
        triangles.emplace_back(id(i, j), nan + 7, id(i + 1, j));
      }
    }
  }
}

void TestOutwardWinding()
{
  // Whether the faces turned away from outside are hidden: only for closed pieces that all
  // enclose their volume the same way.
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  const CasterTopology outward = CasterTopology::Build(sphere->GetOutput());
  std::vector<glm::dvec3> points(outward.Points);
  std::vector<glm::uvec3> inward(outward.Triangles);
  for (glm::uvec3& tri : inward)
  {
    std::swap(tri.y, tri.z);
  }
  // Two spheres, the second shifted: both outward, then the second turned inward.
  std::vector<glm::dvec3> twoPoints(points);
  for (const glm::dvec3& p : points)
  {
    twoPoints.push_back(p + glm::dvec3(3.0, 0.0, 0.0));
  }
  const std::uint32_t shift = static_cast<std::uint32_t>(points.size());
  std::vector<glm::uvec3> bothOut(outward.Triangles), mixed(outward.Triangles);
  for (std::size_t t = 0; t < outward.Triangles.size(); ++t)
  {
    bothOut.push_back(outward.Triangles[t] + shift);
    mixed.push_back(inward[t] + shift);
  }
  // The second sphere listed from its triangle that faces the first most: seen from the pair's
  // centre (the origin of the volumes) that triangle is turned inward, so only the sum over its
  // whole piece says which way the piece winds.
  std::vector<glm::uvec3> facingFirst(bothOut);
  const auto second = facingFirst.begin() + static_cast<std::ptrdiff_t>(outward.Triangles.size());
  const auto normalX = [&](const glm::uvec3& tri)
  {
    const glm::dvec3& p0 = twoPoints[tri.x];
    return glm::cross(twoPoints[tri.y] - p0, twoPoints[tri.z] - p0).x;
  };
  std::rotate(second,
    std::min_element(second, facingFirst.end(),
      [&](const glm::uvec3& a, const glm::uvec3& b) { return normalX(a) < normalX(b); }),
    facingFirst.end());
  vtkNew<vtkPlaneSource> sheet;
  Check(outward.OutwardWinding() == 1, "vtkSphereSource winds outward");
  Check(CasterTopology::Build(points, inward).OutwardWinding() == -1, "turned, it winds inward");
  Check(CasterTopology::Build(twoPoints, bothOut).OutwardWinding() == 1,
    "two pieces wound outward wind outward");
  Check(CasterTopology::Build(twoPoints, facingFirst).OutwardWinding() == 1,
    "two pieces wound outward, one listed from a triangle facing the other, wind outward");
  Check(CasterTopology::Build(twoPoints, mixed).OutwardWinding() == 0,
    "pieces wound both ways have no one outside");
  Check(FromSource(sheet).OutwardWinding() == 0, "an open sheet has no outside");
}

void TestSameWithAnyThreads()
{
  // The parallel passes cut their work into fixed chunks and parts: one thread or two must
  // build the same topology, to the order of every array.
  std::vector<glm::dvec3> points;
  std::vector<glm::uvec3> triangles;
  AwkwardTorus(300, 200, points, triangles);
  // Two threads first: once limited to one, TBB may keep that limit.
  vtkSMPTools::Initialize(2);
  const CasterTopology two = CasterTopology::Build(points, triangles);
  vtkSMPTools::Initialize(1);
  const CasterTopology one = CasterTopology::Build(points, triangles);
  vtkSMPTools::Initialize(0);
  // (i * 200 + j) % 9973 == 0 for 7 of the 60000 quads: 7 bad triangles of each kind.
  const std::size_t quads = 300 * 200, bad = 7;
  Check(one.Points.size() == quads && one.Triangles.size() == 2 * quads &&
      one.Edges.size() == 3 * quads && one.ClosedAndOriented &&
      one.Report.WeldedPoints == 301 + 201 - 1 && one.Report.NonFiniteTriangles == bad &&
      one.Report.DegenerateTriangles == bad && one.Report.InvalidIndexTriangles == bad,
    "the awkward torus welds its seams and drops its bad triangles into a closed surface");
  const glm::dvec3 reach(2.7, 2.7, 0.7);
  Check(glm::all(glm::lessThan(glm::abs(one.BoundsMax + one.Origin - reach), glm::dvec3(1e-9))) &&
      glm::all(glm::lessThan(glm::abs(one.BoundsMin + one.Origin + reach), glm::dvec3(1e-3))),
    "the awkward torus's bounds are the torus's");
  Check(SameTopology(one, two), "one and two threads build the same topology");
}

/// CasterTopology::Origin: a mesh's bounds centre, except along an axis where a few stray points
/// stretch the bounds: there it stays with the rest, so that float coordinates relative to it keep
/// their precision. Two equal parts far apart keep the centre; bounds of no finite size too.
void TestMeshOrigin()
{
  std::vector<glm::dvec3> points;
  std::vector<glm::uvec3> triangles;
  AwkwardTorus(60, 40, points, triangles);
  const CasterTopology alone = CasterTopology::Build(points, triangles);
  // `points` and `triangles` with `extra` points and triangles (indices from 0) added.
  auto with = [&](
                const std::vector<glm::dvec3>& extra, const std::vector<glm::uvec3>& extraTriangles)
  {
    std::vector<glm::dvec3> morePoints = points;
    std::vector<glm::uvec3> moreTriangles = triangles;
    const auto base = glm::uvec3(static_cast<std::uint32_t>(points.size()));
    morePoints.insert(morePoints.end(), extra.begin(), extra.end());
    for (const glm::uvec3& triangle : extraTriangles)
    {
      moreTriangles.push_back(triangle + base);
    }
    return CasterTopology::Build(morePoints, moreTriangles);
  };
  // One 0.01-unit triangle 1,000 units off along x.
  const CasterTopology stray =
    with({ { 1000, 0, 0 }, { 1000.01, 0, 0 }, { 1000, 0.01, 0 } }, { { 0, 1, 2 } });
  std::printf("     origin: %.4f %.4f %.4f alone, %.4f %.4f %.4f with a stray triangle\n",
    alone.Origin.x, alone.Origin.y, alone.Origin.z, stray.Origin.x, stray.Origin.y, stray.Origin.z);
  Check(glm::length(stray.Origin - alone.Origin) < 0.3,
    "a stray triangle 1,000 units off leaves the origin with the rest of the mesh");
  Check(stray.Triangles.size() == alone.Triangles.size() + 1 &&
      stray.BoundsMax.x + stray.Origin.x > 1000.0,
    "the stray triangle stays in the mesh and its bounds");
  // The torus again, 1,000 units off along x.
  std::vector<glm::dvec3> copy;
  for (const glm::dvec3& p : points)
  {
    copy.push_back(p + glm::dvec3(1000, 0, 0));
  }
  const CasterTopology halves = with(copy, triangles);
  Check(
    std::abs(halves.Origin.x - 500.0) < 1.0, "two equal parts far apart keep the bounds' centre");
  const CasterTopology huge =
    with({ { 1e308, 0, 0 }, { -1e308, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 } });
  Check(huge.Origin.x == 0.0 && std::isfinite(huge.Origin.y) && std::isfinite(huge.Origin.z),
    "bounds of no finite size keep their centre");
}

void TestBuilderReuse()
{
  // A builder kept between builds (time-varying data) must give what a fresh build gives,
  // whatever it built before: larger and smaller meshes, welded soups, NaN points, nothing.
  vtkNew<vtkSphereSource> big;
  big->SetThetaResolution(64);
  big->SetPhiResolution(48);
  vtkNew<vtkPlaneSource> sheet;
  sheet->SetResolution(5, 3);
  vtkNew<vtkTriangleFilter> sheetTriangles;
  sheetTriangles->SetInputConnection(sheet->GetOutputPort());
  vtkNew<vtkCubeSource> cube; // split normals: its corners weld
  vtkNew<vtkTriangleFilter> cubeTriangles;
  cubeTriangles->SetInputConnection(cube->GetOutputPort());
  const std::vector<glm::dvec3> soupPoints = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { std::nan(""), 0, 0 }, { 0, 0, 1 }, { 1e-12, 0, 0 } };
  const std::vector<glm::uvec3> soup = { { 0, 1, 2 }, { 0, 3, 2 }, { 5, 2, 4 }, { 1, 2, 4 },
    { 0, 0, 1 }, { 9, 1, 2 } };

  TopologyBuilder builder;
  CasterTopology reused;
  int same = 0, builds = 0;
  for (int round = 0; round < 2; ++round)
  {
    for (vtkPolyDataAlgorithm* source :
      std::initializer_list<vtkPolyDataAlgorithm*>{ big, sheetTriangles, cubeTriangles })
    {
      source->Update();
      builder.Build(source->GetOutput(), reused);
      same += SameTopology(reused, CasterTopology::Build(source->GetOutput()));
      ++builds;
    }
    builder.Build(soupPoints, soup, reused);
    same += SameTopology(reused, CasterTopology::Build(soupPoints, soup));
    builder.Build(nullptr, reused);
    same += reused.Empty() && reused.Edges.empty() && reused.Uses.empty() && reused.Points.empty();
    builds += 2;
  }
  Check(same == builds, "a reused builder gives what a fresh build gives");

  // Data played back that grows by a little, build after build: the storage that grows keeps a
  // margin, so that the next small growth builds in place instead of on fresh pages.
  vtkNew<vtkSphereSource> growing;
  growing->SetPhiResolution(48);
  int grownSame = 0, inPlace = 0;
  const glm::uvec3* storage = nullptr;
  for (int theta = 64; theta <= 67; ++theta)
  {
    growing->SetThetaResolution(theta);
    growing->Update();
    builder.Build(growing->GetOutput(), reused);
    grownSame += SameTopology(reused, CasterTopology::Build(growing->GetOutput()));
    inPlace += theta > 65 && reused.Triangles.data() == storage;
    storage = reused.Triangles.data();
  }
  Check(grownSame == 4, "a reused builder on a growing mesh gives what a fresh build gives");
  Check(inPlace == 2, "after one growth, the next two small ones build in place");

  // A hub: a disc fanned from point 0 in 200 triangles, in shuffled order, so that one vertex
  // groups 400 half-edges (sorted by std::sort, not by insertion).
  std::vector<glm::dvec3> hubPoints = { { 0.0, 0.0, 0.0 } };
  std::vector<glm::uvec3> fan;
  for (std::uint32_t k = 0; k < 200; ++k)
  {
    const double angle = 2.0 * 3.141592653589793 * k / 200.0;
    hubPoints.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    fan.emplace_back(0u, 1u + k, 1u + (k + 1) % 200);
  }
  std::shuffle(fan.begin(), fan.end(), std::mt19937(5));
  builder.Build(hubPoints, fan, reused);
  const bool spokesManifold = std::all_of(reused.Edges.begin(), reused.Edges.end(),
    [](const Edge& e) { return (e.A == 0) == (e.Kind == EdgeKind::Manifold); });
  Check(reused.Edges.size() == 400 && reused.Report.BoundaryEdges == 200 && spokesManifold &&
      SameTopology(reused, CasterTopology::Build(hubPoints, fan)),
    "a hub of 200 triangles: 200 manifold spokes, 200 boundary rim edges");
  Check(builder.GetScratchBytes() > 0, "the builder keeps its scratch");
}

void FuzzRandomMeshes(std::mt19937& rng)
{
  // Random soups over a small shared point set: every kind of non-manifoldness, slivers,
  // duplicates and flipped triangles, lit from random positions and directions.
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  int nanFree = 0, balanced = 0, reusedSame = 0;
  const int meshes = 150;
  TopologyBuilder builder;
  CasterTopology reused;
  for (int m = 0; m < meshes; ++m)
  {
    const int pointCount = 4 + static_cast<int>(rng() % 12);
    std::vector<glm::dvec3> points(pointCount);
    for (auto& p : points)
    {
      p = { coord(rng), coord(rng), coord(rng) };
      if (rng() % 7 == 0)
      {
        p = points[rng() % points.size()]; // coincident points to weld
      }
    }
    std::vector<glm::uvec3> tris(1 + rng() % 20);
    for (auto& t : tris)
    {
      t = { rng() % pointCount, rng() % pointCount, rng() % pointCount };
    }
    const CasterTopology topo = CasterTopology::Build(points, tris);
    builder.Build(points, tris, reused);
    reusedSame += SameTopology(topo, reused);
    const glm::dvec4 light = rng() % 2
      ? glm::dvec4(3 * coord(rng), 3 * coord(rng), 3 * coord(rng), 1.0)
      : glm::dvec4(coord(rng), coord(rng), coord(rng), 0.0);
    const ShadowVolume volume = ShadowVolume::Build(topo, light, rng() % 2 == 0);
    balanced += volume.SilhouetteIsBalanced(topo.Points.size());
    bool finite = true;
    for (const glm::dvec3& p : topo.Points)
    {
      finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    }
    nanFree += finite;
    if (m % 10 == 0 && !topo.Empty())
    {
      CheckVolume("fuzz" + std::to_string(m), topo, light, rng, 40);
    }
  }
  Check(balanced == meshes, "fuzz: every silhouette balanced");
  Check(nanFree == meshes, "fuzz: no NaN in topology");
  Check(reusedSame == meshes, "fuzz: a reused builder gives what a fresh build gives");
}

/// Signed crossings of the segment q -> p with the volume's sides, the swept copies placed by
/// `swept`; INT_MIN when the segment grazes an edge.
int SideCrossings(const CasterTopology& topo, const ShadowVolume& volume, const glm::dvec3& q,
  const glm::dvec3& p, const std::function<glm::dvec3(std::uint32_t)>& swept)
{
  const std::size_t n = topo.Points.size();
  auto point = [&](std::uint32_t i) { return i < n ? topo.Points[i] : swept(i); };
  int crossings = 0;
  bool nearEdge = false;
  for (std::size_t i = 0; i < volume.Sides.size(); i += 3)
  {
    const glm::dvec3 a = point(volume.Sides[i]), b = point(volume.Sides[i + 1]),
                     c = point(volume.Sides[i + 2]);
    const double t = RayTriangle(q, p - q, a, b, c, nearEdge);
    if (t >= 0.0 && t <= 1.0)
    {
      crossings += glm::dot(glm::cross(b - a, c - a), p - q) > 0 ? 1 : -1;
    }
  }
  return nearEdge ? std::numeric_limits<int>::min() : crossings;
}

/// VolumeEndPlane: the volume cut on it counts like the whole one along every segment from the
/// near rectangle to a point of the scene, for closed, open and one-sided casters, positional
/// and directional lights, and random scenes and eyes.
void TestVolumeEndPlane(std::mt19937& rng)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  vtkNew<vtkPlaneSource> sheet;
  sheet->SetResolution(4, 3);
  vtkNew<vtkParametricMobius> mobius;
  const std::pair<const char*, CasterTopology> casters[] = { { "sphere", FromSource(sphere) },
    { "open sheet", FromSource(sheet) }, { "Moebius strip", Parametric(mobius, 16) } };
  std::uniform_real_distribution<double> unit(0.0, 1.0), signed1(-1.0, 1.0);
  int cut = 0, uncut = 0, compared = 0, counted = 0, differ = 0, tried = 0;
  for (const auto& [name, topo] : casters)
  {
    const glm::dvec3 lo = topo.BoundsMin, hi = topo.BoundsMax;
    const double size = glm::length(hi - lo);
    for (const glm::dvec4& light : Lights(topo))
    {
      const ShadowVolume volume = ShadowVolume::Build(topo, light, false, false);
      for (int trial = 0; trial < 40; ++trial)
      {
        Box scene;
        scene.Extend(lo - size * glm::dvec3(2.0 * unit(rng), 2.0 * unit(rng), 2.0 * unit(rng)),
          hi + size * glm::dvec3(2.0 * unit(rng), 2.0 * unit(rng), 2.0 * unit(rng)));
        const glm::dvec3 eye = 0.5 * (scene.Min + scene.Max) +
          3.0 * size * glm::dvec3(signed1(rng), signed1(rng), signed1(rng));
        const glm::dvec3 across = 0.05 * size * glm::dvec3(1.0, 0.0, 0.0),
                         up = 0.05 * size * glm::dvec3(0.0, 1.0, 0.0);
        const std::array<glm::dvec3, 4> nearCorners = { eye - across - up, eye + across - up,
          eye + across + up, eye - across + up };
        const glm::dvec4 plane = VolumeEndPlane(lo, hi, light, scene, nearCorners);
        if (plane == glm::dvec4(0.0))
        {
          ++uncut;
          continue;
        }
        ++cut;
        const std::size_t n = topo.Points.size();
        const double far = 1e4 * (1.0 + size);
        auto infinite = [&](std::uint32_t i) { return VolumePoint(topo, i, light, far); };
        auto truncated = [&](std::uint32_t i)
        {
          const glm::dvec3 v = topo.Points[i - n];
          const glm::dvec3 away = light.w != 0.0 ? v - glm::dvec3(light) : -glm::dvec3(light);
          const double reach =
            -glm::dot(plane, glm::dvec4(v, 1.0)) / glm::dot(glm::dvec3(plane), away);
          return v + reach * away;
        };
        for (int k = 0; k < 30; ++k)
        {
          const glm::dvec3 p =
            scene.Min + (scene.Max - scene.Min) * glm::dvec3(unit(rng), unit(rng), unit(rng));
          const double s = unit(rng), t = unit(rng);
          const glm::dvec3 q = (1 - s) * (1 - t) * nearCorners[0] + s * (1 - t) * nearCorners[1] +
            s * t * nearCorners[2] + (1 - s) * t * nearCorners[3];
          ++tried;
          const int whole = SideCrossings(topo, volume, q, p, infinite);
          const int short_ = SideCrossings(topo, volume, q, p, truncated);
          if (whole == std::numeric_limits<int>::min() || short_ == std::numeric_limits<int>::min())
          {
            continue;
          }
          ++compared;
          counted += whole != 0;
          if (whole != short_ && differ++ < 3)
          {
            std::printf("  %s: segment (%g,%g,%g) -> (%g,%g,%g): %d crossings, %d when cut\n", name,
              q.x, q.y, q.z, p.x, p.y, p.z, whole, short_);
          }
        }
      }
    }
  }
  std::printf("     end plane: %d volumes cut, %d not; %d segments compared (%d crossing the "
              "volume), %d differ\n",
    cut, uncut, compared, counted, differ);
  Check(cut > 200 && compared > tried / 2 && counted > compared / 50,
    "volumes are cut, and the compared segments often cross them");
  Check(differ == 0, "a volume cut on its end plane counts like the whole one");
  Box unit_box;
  unit_box.Extend(glm::dvec3(-1.0), glm::dvec3(1.0));
  const std::array<glm::dvec3, 4> corners = { glm::dvec3(5, 0, 0), glm::dvec3(5, 1, 0),
    glm::dvec3(5, 1, 1), glm::dvec3(5, 0, 1) };
  Check(VolumeEndPlane(glm::dvec3(-0.5), glm::dvec3(0.5), { 0.6, 0.0, 0.0, 1.0 }, unit_box,
          corners) == glm::dvec4(0.0) &&
      VolumeEndPlane(glm::dvec3(-0.5), glm::dvec3(0.5), { 0, 5, 0, 1 }, Box(), corners) ==
        glm::dvec4(0.0),
    "no end plane for a light next to its caster, or without a scene box");
}

} // namespace

/// Light directions of any length are made unit: UnitDirection at 1e-158 (whose squares are
/// subnormal: glm::normalize left the fuzzer's end-plane normal 1.5e-8 short of unit length),
/// 1e-300 and 1e200 (whose squares overflow), and a directional light's end plane, which for
/// the last two did not exist or was not the unit direction's before.
void TestEndPlaneOfAnyDirectionLength()
{
  for (const double length : { 1e-158, 1e-300, 1e200 })
  {
    const glm::dvec3 unit = UnitDirection(glm::dvec3(length, length, length));
    char label[64];
    std::snprintf(label, sizeof(label), "a direction %g long made unit", length);
    Check(std::abs(glm::length(unit) - 1.0) < 1e-15 && std::abs(unit.x - unit.z) < 1e-15, label);
  }
  Box scene;
  scene.Extend(glm::dvec3(-4.0, -4.0, -1.0), glm::dvec3(4.0, 4.0, 3.0));
  const glm::dvec3 lo(-1.0), hi(1.0);
  const std::array<glm::dvec3, 4> nearCorners = { glm::dvec3(9.0, 9.0, 9.0),
    glm::dvec3(9.5, 9.0, 9.0), glm::dvec3(9.5, 9.5, 9.0), glm::dvec3(9.0, 9.5, 9.0) };
  const glm::dvec4 unit =
    VolumeEndPlane(lo, hi, glm::dvec4(0.2, 0.3, 1.0, 0.0), scene, nearCorners);
  Check(unit != glm::dvec4(0.0), "a directional light's volume ends on a plane");
  for (const double length : { 1e-158, 1e-300, 1e200 })
  {
    const glm::dvec4 light(0.2 * length, 0.3 * length, 1.0 * length, 0.0);
    const glm::dvec4 plane = VolumeEndPlane(lo, hi, light, scene, nearCorners);
    char label[96];
    std::snprintf(
      label, sizeof(label), "the end plane of a direction %g long is the unit one's", length);
    Check(glm::length(plane - unit) < 1e-12 * (1.0 + std::abs(unit.w)), label);
  }
}

int main()
{
  std::mt19937 rng(12345);
  TestClosedSphere(rng);
  TestWelding(rng);
  TestOpenSheet(rng);
  TestNonManifoldAndInconsistent(rng);
  TestNonOrientable(rng);
  TestMirrored(rng);
  TestDegenerateInput();
  TestPolygonsCutAsVTKDraws();
  TestMeshOrigin();
  TestBuilderReuse();
  TestSameWithAnyThreads();
  TestOutwardWinding();
  FuzzRandomMeshes(rng);
  TestVolumeEndPlane(rng);
  TestEndPlaneOfAnyDirectionLength();
  return penumbra_test::Finish();
}
