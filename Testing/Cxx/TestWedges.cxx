// Unit tests of the penumbra-wedge geometry and light-intensity function, without OpenGL.
//
// The reference is a Monte Carlo integral over the light's disk (the same gnomonic disk that
// EdgeOcclusion integrates over) by ray casting against the caster: what is left between the
// two is the one approximation of the method, a single silhouette seen from the light's centre.
#include "penumbraCasterTopology.h"
#include "penumbraCheck.h"
#include "penumbraLightSamples.h"
#include "penumbraShadowVolume.h"
#include "penumbraWedge.h"
#include "penumbraWedgeBound.h"

#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace penumbra;
using penumbra_test::Check;

namespace
{

bool SegmentHitsTriangle(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 dir = q - p, e1 = b - a, e2 = c - a, h = glm::cross(dir, e2);
  const double det = glm::dot(e1, h);
  if (std::abs(det) < 1e-300)
  {
    return false;
  }
  const glm::dvec3 s = p - a;
  const double u = glm::dot(s, h) / det;
  const glm::dvec3 k = glm::cross(s, e1);
  const double v = glm::dot(dir, k) / det, t = glm::dot(e2, k) / det;
  return u >= 0 && v >= 0 && u + v <= 1 && t > 1e-9 && t < 1 - 1e-9;
}

bool Blocked(const CasterTopology& topo, const glm::dvec3& p, const glm::dvec3& q)
{
  for (const glm::uvec3& t : topo.Triangles)
  {
    if (SegmentHitsTriangle(p, q, topo.Points[t.x], topo.Points[t.y], topo.Points[t.z]))
    {
      return true;
    }
  }
  return false;
}

/// The wedge method's visibility: hard shadow of the centre minus the edges' corrections.
double WedgeVisibility(const CasterTopology& topo, const ShadowVolume& centreVolume,
  const glm::dvec3& centre, double radius, const glm::dvec3& p)
{
  double occluded = Blocked(topo, p, centre) ? 1.0 : 0.0;
  for (const SilhouetteEdge& e : centreVolume.Silhouette)
  {
    occluded += e.Multiplicity *
      EdgeOcclusion(p, topo.Points[e.From], topo.Points[e.To], glm::dvec4(centre, 1.0), radius);
  }
  return std::min(1.0, std::max(0.0, 1.0 - occluded));
}

/// Fraction of the light's gnomonic disk seen from p (stratified sunflower samples).
double MonteCarloVisibility(
  const CasterTopology& topo, const glm::dvec3& centre, double radius, const glm::dvec3& p, int n)
{
  const glm::dvec3 axis = glm::normalize(centre - p);
  const double distance = glm::length(centre - p);
  const double disk = distance * radius / std::sqrt(distance * distance - radius * radius);
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(helper, axis)), e2 = glm::cross(axis, e1);
  int visible = 0;
  for (int k = 0; k < n; ++k)
  {
    const double rho = disk * std::sqrt((k + 0.5) / n), phi = k * 2.399963229728653;
    const glm::dvec3 q = centre + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
    visible += Blocked(topo, p, q) ? 0 : 1;
  }
  return double(visible) / n;
}

CasterTopology Mesh(vtkPolyDataAlgorithm* source)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  return CasterTopology::Build(triangles->GetOutput());
}

/// Ground points below a caster, compared with Monte Carlo where either is in penumbra.
void CompareWithMonteCarlo(const std::string& name, const CasterTopology& topo,
  const glm::dvec3& centre, double radius, double meanTolerance, double maxTolerance)
{
  const ShadowVolume volume = ShadowVolume::Build(topo, glm::dvec4(centre, 1.0), false);
  double sum = 0, worst = 0;
  int count = 0;
  for (int i = 0; i < 40; ++i)
  {
    for (int j = 0; j < 40; ++j)
    {
      const glm::dvec3 p(-2.0 + 4.0 * i / 39.0, -1.5, -2.0 + 4.0 * j / 39.0);
      const double wedge = WedgeVisibility(topo, volume, centre, radius, p);
      if (wedge > 0.999 && WedgeVisibility(topo, volume, centre, 1.5 * radius, p) > 0.999)
      {
        continue; // far outside the penumbra: skip the expensive reference
      }
      const double reference = MonteCarloVisibility(topo, centre, radius, p, 1024);
      if (wedge > 0.999 && reference > 0.999)
      {
        continue;
      }
      const double error = std::abs(wedge - reference);
      sum += error;
      worst = penumbra_test::Worse(worst, error);
      ++count;
    }
  }
  const double mean = count ? sum / count : 1.0;
  std::printf("     %s: %d ground points in shadow or penumbra, mean error %.4f, max %.4f\n",
    name.c_str(), count, mean, worst);
  Check(count > 150, name + ": penumbra in the sampled region");
  Check(mean < meanTolerance && worst < maxTolerance, name + ": matches Monte Carlo");
}

void TestAgainstMonteCarlo()
{
  // A box: sharp edges, so the silhouette barely changes over the light: nearly exact.
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(1.0);
  cube->SetYLength(0.6);
  cube->SetZLength(0.8);
  const CasterTopology box = Mesh(cube);
  // Light over the top face: every point of the light sees the same silhouette, so the method
  // is exact and only Monte Carlo noise is left.
  CompareWithMonteCarlo(
    "box, silhouette stable over the light", box, { 0.0, 3.0, 0.0 }, 0.3, 0.003, 0.02);
  // Off-axis: part of the light sees a side face the centre does not (the single-silhouette
  // approximation, Akenine-Moller and Assarsson's Section 8). Stated tolerance: mean 0.01 and
  // max 0.15 (small light), mean 0.025 and max 0.35 (a light as large as the box).
  CompareWithMonteCarlo("box, small off-axis light", box, { 0.4, 3.0, 0.3 }, 0.3, 0.01, 0.15);
  CompareWithMonteCarlo("box, large off-axis light", box, { 0.4, 3.0, 0.3 }, 0.9, 0.025, 0.35);

  // A sphere: the silhouette seen from the centre differs from the one seen from the light's
  // rim, the method's known approximation.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(12);
  const CasterTopology ball = Mesh(sphere);
  CompareWithMonteCarlo("sphere, small light", ball, { 0.4, 3.0, 0.3 }, 0.3, 0.01, 0.06);
}

void TestContinuityAndMonotonicity()
{
  // A long straight edge above a line of receivers: visibility must fall monotonically and
  // continuously from lit to umbra as the receiver crosses the penumbra.
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(1.0);
  cube->SetYLength(0.2);
  cube->SetZLength(6.0);
  const CasterTopology slab = Mesh(cube);
  const glm::dvec3 centre(0.0, 3.0, 0.0);
  const double radius = 0.5;
  const ShadowVolume volume = ShadowVolume::Build(slab, glm::dvec4(centre, 1.0), false);
  double previous = WedgeVisibility(slab, volume, centre, radius, { 2.0, -1.0, 0.1 });
  double largestStep = 0.0;
  bool monotone = true;
  for (int i = 1; i <= 2000; ++i)
  {
    const glm::dvec3 p(2.0 - 2.0 * i / 2000.0, -1.0, 0.1);
    const double v = WedgeVisibility(slab, volume, centre, radius, p);
    monotone = monotone && v <= previous + 1e-12;
    largestStep = penumbra_test::Worse(largestStep, std::abs(v - previous));
    previous = v;
  }
  std::printf("     largest step over 1 mm: %.5f, ends at %.3f\n", largestStep, previous);
  Check(monotone, "visibility falls monotonically into the umbra");
  Check(
    largestStep < 0.01, "visibility is continuous (no step above 0.01 per 1/1000 of the width)");
  Check(previous == 0.0, "umbra reached");

  // Across the shared side planes of neighbouring wedges, at a silhouette corner.
  vtkNew<vtkCubeSource> box;
  const CasterTopology corner = Mesh(box);
  const glm::dvec3 light(1.5, 4.0, 1.2);
  const ShadowVolume cornerVolume = ShadowVolume::Build(corner, glm::dvec4(light, 1.0), false);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-2.5, 2.5), tiny(-1e-5, 1e-5);
  double worstJump = 0.0;
  for (int i = 0; i < 4000; ++i)
  {
    const glm::dvec3 p(coordinate(rng), -1.2, coordinate(rng));
    const glm::dvec3 q = p + glm::dvec3(tiny(rng), 0.0, tiny(rng));
    worstJump = penumbra_test::Worse(worstJump,
      std::abs(WedgeVisibility(corner, cornerVolume, light, 0.8, p) -
        WedgeVisibility(corner, cornerVolume, light, 0.8, q)));
  }
  std::printf("     largest change over 1e-5 around a box: %.2e\n", worstJump);
  Check(worstJump < 1e-3, "no cracks: continuous everywhere around a box's corners");
}

/// Calls visit(a, b, light, radius) for every silhouette edge of a 12 x 8 sphere, from a
/// positional light of radius 0.4 and a directional one of 0.15 radians.
template <typename Visit>
void ForEachBallEdge(Visit&& visit)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  const CasterTopology ball = Mesh(sphere);
  for (const glm::dvec4& light : { glm::dvec4(0.3, 2.5, 0.2, 1.0), glm::dvec4(0.2, 1.0, 0.1, 0.0) })
  {
    const double radius = light.w != 0.0 ? 0.4 : 0.15;
    const ShadowVolume volume = ShadowVolume::Build(ball, light, false);
    for (const SilhouetteEdge& e : volume.Silhouette)
    {
      visit(ball.Points[e.From], ball.Points[e.To], light, radius);
    }
  }
}

/// Calls check(p) for each of 400 random points below the sphere where edge a -> b's
/// correction is non-zero: the points its bounds must hold.
template <typename CheckPoint>
void ForEachSupportPoint(std::mt19937& rng, const glm::dvec3& a, const glm::dvec3& b,
  const glm::dvec4& light, double radius, CheckPoint&& check)
{
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  for (int i = 0; i < 400; ++i)
  {
    const glm::dvec3 p(coordinate(rng), coordinate(rng) - 2.0, coordinate(rng));
    if (std::abs(EdgeOcclusion(p, a, b, light, radius)) > 1e-12)
    {
      check(p);
    }
  }
}

void TestWedgeContainsItsSupport()
{
  // Wherever an edge's correction is non-zero, the point lies inside that edge's wedge.
  std::mt19937 rng(3);
  int checked = 0, outside = 0, invalid = 0;
  ForEachBallEdge(
    [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light, double radius)
    {
      const Wedge wedge = Wedge::Build(a, b, light, radius);
      invalid += wedge.Valid ? 0 : 1;
      if (wedge.Valid)
      {
        ForEachSupportPoint(rng, a, b, light, radius,
          [&](const glm::dvec3& p)
          {
            ++checked;
            outside += wedge.Contains(p, 1e-9) ? 0 : 1;
          });
      }
    });
  std::printf("     %d points with a correction, %d outside their wedge, %d invalid wedges\n",
    checked, outside, invalid);
  Check(checked > 100 && outside == 0, "valid wedges contain their support");
  Check(invalid <= 2, "edges nearly parallel to the light are the only wedges without planes");
}

/// Whether p lies inside the closed convex polyhedron of outward triangles that
/// AppendWedgeBound wrote (vertices of `stride` floats, w = 1), within `tolerance`.
bool InsideBound(const glm::dvec3& p, const std::vector<float>& vertices, int stride,
  const std::vector<std::uint32_t>& indices, double tolerance)
{
  auto point = [&](std::uint32_t i)
  {
    const float* v = &vertices[static_cast<std::size_t>(i) * stride];
    return glm::dvec3(v[0], v[1], v[2]);
  };
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
  {
    const glm::dvec3 a = point(indices[t]), b = point(indices[t + 1]), c = point(indices[t + 2]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (length > 0.0 && glm::dot(n, p - a) > tolerance * length)
    {
      return false;
    }
  }
  return !indices.empty();
}

void TestWedgeBound()
{
  // The geometry drawn for an edge, cut to the receivers' box, holds every point of the box
  // where the edge's correction is non-zero; each vertex carries the edge's attributes.
  std::mt19937 rng(5);
  Box receivers;
  receivers.Extend({ -3.0, -5.0, -3.0 }, { 3.0, 1.0, 3.0 });
  const float attributes[2] = { 7.0f, -2.0f };
  int checked = 0, outside = 0, badVertices = 0, cut = 0;
  ForEachBallEdge(
    [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light, double radius)
    {
      std::vector<float> vertices;
      std::vector<std::uint32_t> indices;
      if (AppendWedgeBound(a, b, light, radius, receivers, nullptr, false, attributes, 2, vertices,
            indices) == WedgeShape::Nothing)
      {
        return;
      }
      ++cut;
      for (std::size_t v = 0; v + 5 < vertices.size() + 1; v += 6)
      {
        badVertices +=
          (vertices[v + 3] != 1.0f || vertices[v + 4] != 7.0f || vertices[v + 5] != -2.0f) ? 1 : 0;
      }
      for (std::uint32_t index : indices)
      {
        badVertices += index * 6 >= vertices.size() ? 1 : 0;
      }
      ForEachSupportPoint(rng, a, b, light, radius,
        [&](const glm::dvec3& p)
        {
          ++checked;
          outside += InsideBound(p, vertices, 6, indices, 1e-5) ? 0 : 1;
        });
    });
  std::printf("     %d edges' bounds cut to the box, %d points with a correction, %d outside\n",
    cut, checked, outside);
  Check(cut > 20 && checked > 100 && outside == 0,
    "the bound cut to the receivers holds every point the edge shades");
  Check(badVertices == 0, "every vertex carries w = 1 and the edge's attributes");

  // A box the wedge misses: nothing drawn. No box: the wedge whole; no wedge: the viewport.
  Box far;
  far.Extend({ 50.0, 50.0, 50.0 }, { 51.0, 51.0, 51.0 });
  const glm::dvec4 above(0.0, 3.0, 0.0, 1.0);
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
  Check(AppendWedgeBound({ -1, 0, 0 }, { 1, 0, 0 }, above, 0.2, far, nullptr, false, nullptr, 0,
          vertices, indices) == WedgeShape::Nothing &&
      vertices.empty() && indices.empty(),
    "a receivers' box the wedge misses: nothing appended");
  Check(AppendWedgeBound({ -1, 0, 0 }, { 1, 0, 0 }, above, 0.2, Box(), nullptr, false, nullptr, 0,
          vertices, indices) == WedgeShape::Planes &&
      indices.size() == Wedge::Triangles().size(),
    "no receivers' box: the whole wedge");
  vertices.clear();
  indices.clear();
  Check(AppendWedgeBound({ 0, 0, 0 }, { 0, 4, 0 }, above, 0.2, Box(), nullptr, false, nullptr, 0,
          vertices, indices) == WedgeShape::FullViewport &&
      indices.size() == 3 && vertices.size() == 12 && vertices[3] == 2.0f,
    "an edge reaching into the light (no wedge, no pyramid): the full-viewport triangle");
}

void TestWedgeBoundInPieces()
{
  // Cut to disjoint pieces (a slab round a ground, a box round a block on it), the bound is one
  // polyhedron per piece it meets; each point an edge shades inside a piece lies inside that
  // piece's polyhedron, whose vertices carry the piece's corners after the edge's attributes.
  std::mt19937 rng(5);
  Box ground, block;
  ground.Extend({ -3.0, -3.2, -3.0 }, { 3.0, -3.0, 3.0 });
  block.Extend({ -1.0, -3.0, -1.0 }, { 1.0, -1.5, 1.0 });
  Box receivers;
  receivers.Extend(ground.Min, ground.Max);
  receivers.Extend(block.Min, block.Max);
  const std::vector<Box> pieces =
    DisjointPieces({ ReceiverPieceBox(receivers, ground), ReceiverPieceBox(receivers, block) });
  const float attributes[2] = { 7.0f, -2.0f };
  constexpr int Stride = 4 + 2 + 6;
  int checked = 0, outside = 0, badVertices = 0, cut = 0;
  ForEachBallEdge(
    [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light, double radius)
    {
      std::vector<float> vertices;
      std::vector<std::uint32_t> indices;
      if (AppendWedgeBoundInPieces(a, b, light, radius, receivers, pieces, nullptr, false,
            attributes, 2, vertices, indices) == WedgeShape::Nothing)
      {
        return;
      }
      ++cut;
      // Each piece's triangles, by the corners their vertices carry (all three the same).
      auto pieceOf = [&](std::uint32_t index)
      {
        const float* v = &vertices[static_cast<std::size_t>(index) * Stride];
        const glm::dvec3 min(v[6], v[7], v[8]), max(v[9], v[10], v[11]);
        std::size_t piece = 0;
        while (piece < pieces.size() &&
          !(glm::all(glm::lessThan(glm::abs(min - pieces[piece].Min), glm::dvec3(1e-5))) &&
            glm::all(glm::lessThan(glm::abs(max - pieces[piece].Max), glm::dvec3(1e-5)))))
        {
          ++piece;
        }
        const bool carries = v[3] == 1.0f && v[4] == 7.0f && v[5] == -2.0f;
        return carries ? piece : pieces.size();
      };
      std::vector<std::vector<std::uint32_t>> byPiece(pieces.size());
      for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
      {
        const std::size_t piece = pieceOf(indices[t]);
        const bool same = pieceOf(indices[t + 1]) == piece && pieceOf(indices[t + 2]) == piece;
        badVertices += piece == pieces.size() || !same;
        if (piece < pieces.size())
        {
          byPiece[piece].insert(byPiece[piece].end(), &indices[t], &indices[t] + 3);
        }
      }
      // The pieces are thin: five batches of random points for enough inside them.
      for (int batch = 0; batch < 5; ++batch)
      {
        ForEachSupportPoint(rng, a, b, light, radius,
          [&](const glm::dvec3& p)
          {
            for (std::size_t piece = 0; piece < pieces.size(); ++piece)
            {
              if (glm::all(glm::greaterThanEqual(p, pieces[piece].Min)) &&
                glm::all(glm::lessThan(p, pieces[piece].Max)))
              {
                ++checked;
                outside += InsideBound(p, vertices, Stride, byPiece[piece], 1e-5) ? 0 : 1;
              }
            }
          });
      }
    });
  std::printf("     %zu pieces; %d edges' bounds cut to them, %d points with a correction in a "
              "piece, %d outside its polyhedron\n",
    pieces.size(), cut, checked, outside);
  Check(pieces.size() >= 2 && cut > 20 && checked > 100 && outside == 0,
    "each piece's bound holds every point in it the edge shades");
  Check(badVertices == 0, "every vertex carries w = 1, the edge's attributes and its piece");

  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
  Box far;
  far.Extend({ 50.0, 50.0, 50.0 }, { 51.0, 51.0, 51.0 });
  Check(AppendWedgeBoundInPieces({ -1, 0, 0 }, { 1, 0, 0 }, { 0, 5, 0, 1 }, 0.2, receivers, { far },
          nullptr, false, nullptr, 0, vertices, indices) == WedgeShape::Nothing &&
      indices.empty(),
    "pieces the wedge misses: nothing drawn");
}

void TestDegenerateEdges()
{
  const glm::dvec4 light(0, 2, 0, 1), sun(0, 1, 0, 0);
  const glm::dvec3 p(0.3, -1, 0.2);
  bool finite = true;
  auto probe = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& q,
                 const glm::dvec4& l, double r)
  {
    const double value = EdgeOcclusion(q, a, b, l, r);
    finite = finite && std::isfinite(value) && std::abs(value) <= 1.0;
    const Wedge wedge = Wedge::Build(a, b, l, r);
    for (const glm::dvec4& v : wedge.Vertices)
    {
      finite = finite &&
        (!wedge.Valid || (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)));
    }
  };
  probe({ 0, 0, 0 }, { 0, 0, 0 }, p, light, 0.5); // zero-length edge
  probe({ 0, 0, 0 }, { 0, 1, 0 }, p, light, 0.5); // pointing at the light
  probe({ 0, 0, 0 }, { 0, 1e-12, 1e-12 }, p, light, 0.5);
  probe({ 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 0, 0 }, light, 0.5); // receiver on the edge
  probe({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 2, 0 }, light, 0.5);   // receiver at the light
  probe({ 0, 0, 0 }, { 1, 0, 0 }, p, light, 0.0);             // no radius
  probe({ 0, 0, 0 }, { 1, 0, 0 }, p, light, 50.0);            // light swallowing everything
  probe({ 0, 0, 0 }, { 0, 1, 0 }, p, sun, 0.05);              // parallel to a directional light
  probe({ 0, 0, 0 }, { 1, 0, 0 }, p, sun, 1.5);               // a huge sun
  Check(finite, "no NaN or out-of-range correction on degenerate edges");
  Check(!Wedge::Build({ 0, 0, 0 }, { 0, 1, 0 }, light, 0.5).Valid,
    "an edge pointing at the light has no wedge");
  Check(EdgeOcclusion(p, { 0, 0, 0 }, { 1, 0, 0 }, light, 0.0) == 0.0, "radius 0: no penumbra");
}

void TestLightSamples()
{
  // Positional: on the disk of radius r through the centre, facing the target, centred on it.
  const glm::dvec3 centre(1, 4, 2), target(0, 0, 0);
  const glm::dvec3 axis = glm::normalize(target - centre);
  const std::vector<glm::dvec4> disk = SpreadLightSamples(glm::dvec4(centre, 1), 0.5, 64, target);
  bool onDisk = disk.size() == 64;
  glm::dvec3 mean(0.0);
  for (const glm::dvec4& q : disk)
  {
    const glm::dvec3 d = glm::dvec3(q) - centre;
    onDisk = onDisk && q.w == 1.0 && std::abs(glm::dot(d, axis)) < 1e-12 && glm::length(d) <= 0.5;
    mean += glm::dvec3(q) / 64.0;
  }
  Check(onDisk, "positional light samples lie on the disk facing the casters");
  Check(glm::length(mean - centre) < 0.02, "positional light samples are centred on the light");
  // Directional: unit directions within the cone of 5 degrees around the light's direction.
  const glm::dvec3 towards = glm::normalize(glm::dvec3(0.2, 1, 0.1));
  bool inCone = true;
  for (const glm::dvec4& q : SpreadLightSamples(glm::dvec4(towards, 0), 5.0, 32, target))
  {
    inCone = inCone && q.w == 0.0 && std::abs(glm::length(glm::dvec3(q)) - 1.0) < 1e-12 &&
      glm::dot(glm::dvec3(q), towards) >= std::cos(glm::radians(5.0)) - 1e-12;
  }
  Check(inCone, "directional light samples lie within the light's cone");
  // The filter's polar rings: N points, each standing for an equal share of the disk.
  for (int count : { 1, 7, 16, 64, 100 })
  {
    const std::vector<DiskPoint> rings = PolarRingPoints(count);
    double meanArea = 0.0;
    bool inside = rings.size() == static_cast<std::size_t>(count);
    for (const DiskPoint& q : rings)
    {
      inside = inside && q.AreaFraction > 0.0 && q.AreaFraction < 1.0;
      meanArea += q.AreaFraction / count;
    }
    Check(inside && std::abs(meanArea - 0.5) < 1e-12,
      std::to_string(count) + " polar-ring points lie in the disk, equal areas each");
  }
  Check(PolarRingPoints(0).empty(), "no polar-ring points for no samples");
  const std::vector<glm::dvec4> placed =
    PlaceOnLight(glm::dvec4(centre, 1), 0.5, SunflowerPoints(64), target);
  Check(std::equal(placed.begin(), placed.end(), disk.begin()),
    "SpreadLightSamples is the sunflower placed on the light");
}

void TestLightPyramid()
{
  // Edges whose line passes through the light: every point that sees the edge in front of some
  // light point lies in the pyramid, whose triangles face outwards.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const glm::dvec3 centre(0.5, 6.0, -1.0);
  const double radius = 0.8;
  int built = 0, inside = 0, tried = 0;
  bool outward = true;
  for (int trial = 0; trial < 200; ++trial)
  {
    // An edge on a line through a random point of the light's sphere.
    const glm::dvec3 through = centre +
      radius * 0.9 * glm::normalize(glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
    const glm::dvec3 direction =
      glm::normalize(glm::dvec3(unit(rng) - 0.5, -1.0 - unit(rng), unit(rng) - 0.5));
    const glm::dvec3 a = through + (2.0 + 3.0 * unit(rng)) * direction;
    const glm::dvec3 b = a + (0.05 + 0.5 * unit(rng)) * direction;
    const LightPyramid pyramid = LightPyramid::Build(a, b, glm::dvec4(centre, 1.0), radius);
    Check(!Wedge::Build(a, b, glm::dvec4(centre, 1.0), radius).Valid, "no wedge for such an edge");
    if (!pyramid.Valid)
    {
      continue;
    }
    ++built;
    for (int k = 0; k < 50; ++k)
    {
      const glm::dvec3 x = centre +
        radius * std::cbrt(unit(rng)) *
          glm::normalize(glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
      const glm::dvec3 e = a + unit(rng) * (b - a);
      const glm::dvec3 p = x + (1.0 + 20.0 * unit(rng)) * (e - x);
      ++tried;
      inside += pyramid.Contains(p, 1e-9 * glm::length(p - centre));
    }
    // Outward: every triangle's normal points away from a point inside (apex + axis).
    glm::dvec3 axis(0.0);
    for (int v = 1; v < 5; ++v)
    {
      axis += glm::dvec3(pyramid.Vertices[v]);
    }
    const glm::dvec3 interior = centre + glm::normalize(axis);
    const auto& triangles = LightPyramid::Triangles();
    for (std::size_t t = 0; t < triangles.size(); t += 3)
    {
      glm::dvec3 v[3];
      for (int k = 0; k < 3; ++k)
      {
        const glm::dvec4& q = pyramid.Vertices[triangles[t + k]];
        v[k] = q.w != 0.0 ? glm::dvec3(q) : centre + 10.0 * glm::dvec3(q);
      }
      const glm::dvec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
      outward = outward && glm::dot(normal, (v[0] + v[1] + v[2]) / 3.0 - interior) > 0.0;
    }
  }
  std::printf("light pyramids: %d built of 200, %d of %d points inside\n", built, inside, tried);
  Check(built > 100, "pyramids are built for edges pointing at the light");
  Check(inside == tried, "every point that can see such an edge cross the light is inside");
  Check(outward, "pyramid triangles face outwards");
  Check(!LightPyramid::Build({ 0, 0, 0 }, { 0, 1, 0 }, glm::dvec4(0, 0.5, 0, 1), 0.6).Valid,
    "no pyramid for an edge reaching into the light");
}

void TestDirectionalLightPyramid()
{
  // A directional light's edges at up to twice its angular radius from its direction (those
  // within it have no wedge): every point from which some direction of the light's cone meets
  // the edge lies in the pyramid, and the pyramid stays as narrow as that cone.
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const glm::dvec3 towards = glm::normalize(glm::dvec3(0.3, 0.15, 1.0));
  const double radius = 0.05;
  glm::dvec3 e1, e2;
  PlaneBasis(towards, e1, e2);
  auto within = [&](double angle)
  {
    const double turn = 6.283185307179586 * unit(rng), tilt = angle * std::sqrt(unit(rng));
    return std::cos(tilt) * towards + std::sin(tilt) * (std::cos(turn) * e1 + std::sin(turn) * e2);
  };
  int withoutWedge = 0, inside = 0, tried = 0;
  bool narrow = true;
  for (int trial = 0; trial < 200; ++trial)
  {
    const glm::dvec3 a(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
    const glm::dvec3 b =
      a + (0.05 + unit(rng)) * (unit(rng) < 0.5 ? 1.0 : -1.0) * within(2.0 * radius);
    const glm::dvec4 light(3.0 * towards, 0.0); // a direction of any length
    withoutWedge += !Wedge::Build(a, b, light, radius).Valid;
    const LightPyramid pyramid = LightPyramid::Build(a, b, light, radius);
    if (!pyramid.Valid)
    {
      narrow = false;
      continue;
    }
    for (int v = 1; v < 5; ++v)
    {
      narrow = narrow && glm::dot(glm::dvec3(pyramid.Vertices[v]), -towards) > std::cos(0.15);
    }
    for (int k = 0; k < 50; ++k)
    {
      const glm::dvec3 e = a + unit(rng) * (b - a);
      const glm::dvec3 p = e - (0.01 + 30.0 * unit(rng)) * within(radius);
      ++tried;
      inside += pyramid.Contains(p, 1e-12);
    }
  }
  std::printf("directional light pyramids: %d of 200 edges without a wedge, %d of %d points "
              "inside\n",
    withoutWedge, inside, tried);
  Check(withoutWedge > 30, "edges within the light's cone of its direction have no wedge");
  Check(narrow, "a directional light's pyramid is built, within 3 radii of its direction");
  Check(inside == tried, "every point that can see such an edge cross the light is inside");
}

} // namespace

int main()
{
  TestAgainstMonteCarlo();
  TestContinuityAndMonotonicity();
  TestWedgeContainsItsSupport();
  TestWedgeBound();
  TestWedgeBoundInPieces();
  TestDegenerateEdges();
  TestLightSamples();
  TestLightPyramid();
  TestDirectionalLightPyramid();
  return penumbra_test::Finish();
}
