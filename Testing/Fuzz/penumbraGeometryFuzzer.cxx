// libFuzzer target on Penumbra::Geometry: caster topology, silhouettes, shadow volumes, penumbra
// wedges and EdgeOcclusion, fed random and malformed meshes and lights. The byte format is in
// penumbraFuzzInput.h; the invariants are listed in Documentation/fuzzing.md. A violated
// invariant prints what broke and aborts, so libFuzzer (or the smoke driver) reports the input.
#include "penumbraCasterTopology.h"
#include "penumbraCulling.h"
#include "penumbraFuzzInput.h"
#include "penumbraLightSamples.h"
#include "penumbraSampleCounting.h"
#include "penumbraShadowVolume.h"
#include "penumbraWedge.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace
{
using namespace penumbra;
using fuzz::ByteReader;

// Bounds that keep every execution short, whatever the input.
constexpr std::size_t MaxPoints = 256;
constexpr std::size_t MaxTriangles = 512;
constexpr int MaxCellPoints = 16;

[[noreturn]] void Fail(const char* what)
{
  std::fprintf(stderr, "penumbraGeometryFuzzer: invariant violated: %s\n", what);
  std::fflush(stderr);
  std::abort();
}

void Require(bool condition, const char* what)
{
  if (!condition)
  {
    Fail(what);
  }
}

bool IsFinite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool IsFinite(const glm::dvec4& v)
{
  return IsFinite(glm::dvec3(v)) && std::isfinite(v.w);
}

double DecodeScalar(ByteReader& in)
{
  const std::uint8_t tag = in.U8();
  const double sign = (tag & fuzz::TagNegative) ? -1.0 : 1.0;
  switch (tag % 16)
  {
    case fuzz::TagHuge:
      return sign * 1e30;
    case fuzz::TagTiny:
      return sign * 1e-30;
    case fuzz::TagZero:
      return sign * 0.0;
    case fuzz::TagNaN:
      return std::numeric_limits<double>::quiet_NaN();
    case fuzz::TagInf:
      return sign * std::numeric_limits<double>::infinity();
    case fuzz::TagRaw:
      return in.RawDouble();
    default:
      return static_cast<std::int16_t>(in.U16()) / 64.0;
  }
}

glm::dvec3 DecodePoint(ByteReader& in)
{
  const std::uint8_t sel = in.U8();
  if (sel < 192)
  {
    const int k = sel % 27;
    glm::dvec3 p(k % 3 - 1, (k / 3) % 3 - 1, k / 9 - 1);
    if (sel >= 128)
    {
      // Offsets around the default weld tolerance (1e-7 of the diagonal).
      for (int a = 0; a < 3; ++a)
      {
        p[a] += static_cast<std::int8_t>(in.U8()) * 1e-9;
      }
    }
    return p;
  }
  glm::dvec3 p;
  for (int a = 0; a < 3; ++a)
  {
    p[a] = sel < 240 ? static_cast<std::int8_t>(in.U8()) / 32.0
                     : (sel < 255 ? DecodeScalar(in) : in.RawDouble());
  }
  return p;
}

std::uint32_t DecodeRawIndex(ByteReader& in, std::size_t pointCount)
{
  const std::uint8_t s = in.U8();
  const auto n = static_cast<std::uint32_t>(pointCount);
  if (s < 248)
  {
    return n > 0 ? s % n : 0;
  }
  switch (s)
  {
    case 252:
      return ~std::uint32_t(0);
    case 253:
      return std::uint32_t(1) << 31;
    case 254:
      return in.U32();
    case 255:
      return in.U8();
    default:
      return n + (s - 248); // just past the end
  }
}

vtkIdType DecodeCellId(ByteReader& in, vtkIdType pointCount)
{
  const std::uint8_t s = in.U8();
  if (s < 250)
  {
    return pointCount > 0 ? s % pointCount : 0;
  }
  switch (s)
  {
    case 250:
      return -1;
    case 251:
      return pointCount;
    case 252:
      return pointCount + in.U8();
    case 253:
      // Aliases a valid id once truncated to 32 bits.
      return (vtkIdType(1) << 32) + (pointCount > 0 ? in.U8() % pointCount : 0);
    case 254:
      return std::numeric_limits<vtkIdType>::max();
    default:
      return static_cast<vtkIdType>(in.U64());
  }
}

double DecodeWeldTolerance(std::uint8_t flags)
{
  switch ((flags >> 2) & 3)
  {
    case 1:
      return 0.0;
    case 2:
      return 1e-3;
    case 3:
      return 0.25;
    default:
      return CasterTopology::DefaultWeldTolerance;
  }
}

CasterTopology BuildRaw(ByteReader& in, double tolerance)
{
  std::vector<glm::dvec3> points(in.U8());
  for (glm::dvec3& p : points)
  {
    p = DecodePoint(in);
  }
  std::vector<glm::uvec3> triangles(in.U16() % (MaxTriangles + 1));
  for (glm::uvec3& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      t[k] = DecodeRawIndex(in, points.size());
    }
  }
  CasterTopology topo = CasterTopology::Build(points, triangles, tolerance);
  Require(topo.Report.InputPoints == points.size(), "report counts the input points");
  Require(topo.Report.InputTriangles == triangles.size(), "report counts the input triangles");
  return topo;
}

CasterTopology BuildPolyData(ByteReader& in, double tolerance)
{
  const std::uint8_t polyFlags = in.U8();
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  if (polyFlags & 0x20)
  {
    points->SetDataTypeToFloat(); // 1e30 survives, larger values become Inf
  }
  const vtkIdType pointCount = in.U8();
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    const glm::dvec3 p = DecodePoint(in);
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  if (!(polyFlags & 0x10))
  {
    poly->SetPoints(points);
  }

  vtkNew<vtkCellArray> cells[4]; // verts, lines, polys, strips
  const int cellCount = in.U8();
  std::size_t triangleBudget = MaxTriangles;
  std::vector<vtkIdType> ids;
  for (int c = 0; c < cellCount; ++c)
  {
    const std::uint8_t head = in.U8();
    const int type = head & 3;
    const int count = (head >> 2) % (MaxCellPoints + 1);
    ids.resize(static_cast<std::size_t>(count));
    for (vtkIdType& id : ids)
    {
      id = DecodeCellId(in, pointCount);
    }
    if (type >= 2)
    {
      const std::size_t produced = count > 2 ? static_cast<std::size_t>(count - 2) : 0;
      if (produced > triangleBudget)
      {
        continue;
      }
      triangleBudget -= produced;
    }
    cells[type]->InsertNextCell(count, ids.data());
  }
  poly->SetVerts(cells[0]);
  poly->SetLines(cells[1]);
  poly->SetPolys(cells[2]);
  poly->SetStrips(cells[3]);

  const bool nullInput = (polyFlags & 0x0f) == 0x0f;
  CasterTopology topo = CasterTopology::Build(nullInput ? nullptr : poly.Get(), tolerance);
  if (!nullInput && !(polyFlags & 0x10))
  {
    Require(topo.Report.InputPoints == static_cast<std::size_t>(pointCount),
      "report counts the input points");
    Require(topo.Report.SkippedVerts == static_cast<std::size_t>(cells[0]->GetNumberOfCells()) &&
        topo.Report.SkippedLines == static_cast<std::size_t>(cells[1]->GetNumberOfCells()),
      "report counts the skipped verts and lines");
  }
  return topo;
}

void CheckTopology(const CasterTopology& topo)
{
  const TopologyReport& r = topo.Report;
  Require(IsFinite(topo.Origin), "finite origin");
  for (const glm::dvec3& p : topo.Points)
  {
    Require(IsFinite(p), "no NaN or Inf in topology points");
  }
  Require(r.InputTriangles ==
      topo.Triangles.size() + r.DegenerateTriangles + r.NonFiniteTriangles +
        r.InvalidIndexTriangles,
    "every input triangle kept or counted as dropped");
  Require(topo.Points.size() + r.WeldedPoints + r.NonFinitePoints == r.InputPoints,
    "every input point kept, welded or counted as dropped");
  for (const glm::uvec3& t : topo.Triangles)
  {
    Require(t.x < topo.Points.size() && t.y < topo.Points.size() && t.z < topo.Points.size(),
      "topology triangles index existing points");
    Require(t.x != t.y && t.y != t.z && t.z != t.x, "topology triangles have three corners");
    const glm::dvec3 n =
      glm::cross(topo.Points[t.y] - topo.Points[t.x], topo.Points[t.z] - topo.Points[t.x]);
    Require(glm::dot(n, n) > 0.0, "topology triangles have an area");
    for (int k = 0; k < 3; ++k)
    {
      Require(glm::all(glm::greaterThanEqual(topo.Points[t[k]], topo.BoundsMin)) &&
          glm::all(glm::lessThanEqual(topo.Points[t[k]], topo.BoundsMax)),
        "bounds contain the triangles");
    }
  }
  std::size_t uses = 0;
  for (const Edge& e : topo.Edges)
  {
    Require(e.A < e.B && e.B < topo.Points.size(), "edges index existing points, A < B");
    Require(e.UseCount > 0 && e.FirstUse == uses, "edge uses are contiguous");
    uses += e.UseCount;
    Require(uses <= topo.Uses.size(), "edge uses in range");
    for (std::uint32_t u = e.FirstUse; u < e.FirstUse + e.UseCount; ++u)
    {
      const EdgeUse& use = topo.Uses[u];
      Require(use.Triangle < topo.Triangles.size(), "edge uses index existing triangles");
      const glm::uvec3& t = topo.Triangles[use.Triangle];
      bool walks = false;
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t from = use.Sign > 0 ? e.A : e.B, to = use.Sign > 0 ? e.B : e.A;
        walks = walks || (t[k] == from && t[(k + 1) % 3] == to);
      }
      Require(walks, "edge use sign matches the triangle's walk");
    }
  }
  Require(uses == topo.Uses.size() && uses == 3 * topo.Triangles.size(),
    "every triangle side is one edge use");
  Require(!topo.ClosedAndOriented || (r.BoundaryEdges == 0 && r.NonManifoldEdges == 0),
    "closed meshes have no boundary");
  // Turning every triangle turns the winding; only a closed mesh has one.
  const int winding = topo.OutwardWinding();
  Require(winding >= -1 && winding <= 1 && (topo.ClosedAndOriented || winding == 0),
    "only closed meshes wind outward or inward");
  CasterTopology turned = topo;
  for (glm::uvec3& t : turned.Triangles)
  {
    std::swap(t.y, t.z);
  }
  for (EdgeUse& use : turned.Uses)
  {
    use.Sign = -use.Sign;
  }
  Require(turned.OutwardWinding() == -winding, "turning every triangle turns the winding");
}

void CheckIndices(
  const std::vector<std::uint32_t>& indices, std::size_t pointCount, const char* what)
{
  Require(indices.size() % 3 == 0, what);
  for (std::uint32_t i : indices)
  {
    Require(i < 2 * pointCount, what);
  }
}

void CheckVolume(
  const CasterTopology& topo, const ShadowVolume& volume, const glm::dvec4& light, bool withCaps)
{
  const std::size_t n = topo.Points.size();
  CheckIndices(volume.Sides, n, "side indices < 2N");
  CheckIndices(volume.LightCap, n, "light cap indices < 2N");
  CheckIndices(volume.DarkCap, n, "dark cap indices < 2N");
  Require(volume.SilhouetteIsBalanced(n), "silhouette balanced");
  std::size_t sideTriangles = 0;
  for (const SilhouetteEdge& e : volume.Silhouette)
  {
    Require(e.From != e.To && e.Multiplicity > 0, "silhouette edges are proper edges");
    sideTriangles += 2 * e.Multiplicity;
  }
  Require(volume.Sides.size() == 3 * sideTriangles, "sides: one quad per edge use");
  Require(volume.RunsCoverEveryCopy(), "multiplicity runs account for every copy");
  Require(volume.CastingTriangles <= topo.Triangles.size(), "casting triangles counted once");
  if (withCaps)
  {
    Require(
      volume.LightCap.size() == 3 * volume.CastingTriangles, "light cap: the casting triangles");
    Require(light.w != 0.0 || volume.DarkCap.empty(), "no dark cap for a directional light");
  }
  else
  {
    Require(volume.LightCap.empty() && volume.DarkCap.empty(), "no caps unless asked");
  }
}

void CheckWedgeAndOcclusion(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light,
  double radius, const std::vector<glm::dvec3>& receivers)
{
  const Wedge wedge = Wedge::Build(a, b, light, radius);
  if (wedge.Valid)
  {
    for (int k = 0; k < 4; ++k)
    {
      Require(IsFinite(wedge.Normals[k]) && std::abs(glm::length(wedge.Normals[k]) - 1.0) < 1e-6,
        "valid wedges have finite unit normals");
      Require(std::isfinite(wedge.Offsets[k]), "valid wedges have finite offsets");
    }
    for (const glm::dvec4& v : wedge.Vertices)
    {
      Require(IsFinite(v), "valid wedges have finite vertices");
    }
  }
  const bool finiteInputs = IsFinite(a) && IsFinite(b) && IsFinite(light) && std::isfinite(radius);
  for (const glm::dvec3& p : receivers)
  {
    const double c = EdgeOcclusion(p, a, b, light, radius);
    if (finiteInputs && IsFinite(p))
    {
      Require(std::isfinite(c), "EdgeOcclusion is finite");
      Require(std::abs(c) <= 1.0 + 1e-9, "EdgeOcclusion is a fraction of the light, |c| <= 1");
    }
    (void)wedge.Contains(p);
  }
}

/// Per-light-sample counting on the same mesh, light and receivers: indices in range, the centre
/// silhouette among the potential one, crossings in {-1, 0, 1}, multiplicities bounded by the
/// faces, pyramids finite; no NaN and no crash whatever the input.
void CheckCounting(const CasterTopology& topo, const glm::dvec4& light, double radius,
  bool frontOnly, const ShadowVolume& centre, const std::vector<glm::dvec4>& samples,
  const std::vector<glm::dvec3>& receivers)
{
  const std::vector<std::uint32_t> potential =
    PotentialSilhouette(topo, glm::dmat4(1.0), light, radius, frontOnly);
  for (std::uint32_t e : potential)
  {
    Require(e < topo.Edges.size(), "potential silhouette edges exist");
  }
  if (radius >= 0.0 && IsFinite(light) && std::isfinite(radius))
  {
    Require(potential.size() >= centre.Silhouette.size(),
      "the centre silhouette is among the potential one");
  }
  std::size_t checked = 0;
  for (std::uint32_t e : potential)
  {
    if (++checked > 64)
    {
      break; // bounded work per input
    }
    const Edge& edge = topo.Edges[e];
    const glm::dvec3 a = topo.Points[edge.A], b = topo.Points[edge.B];
    std::vector<EdgeFace> faces;
    for (std::uint32_t u = edge.FirstUse; u < edge.FirstUse + edge.UseCount; ++u)
    {
      const glm::uvec3& tri = topo.Triangles[topo.Uses[u].Triangle];
      faces.push_back({ glm::cross(topo.Points[tri.y] - topo.Points[tri.x],
                          topo.Points[tri.z] - topo.Points[tri.x]),
        topo.Uses[u].Sign });
    }
    const LightPyramid pyramid = LightPyramid::Build(a, b, light, radius);
    if (pyramid.Valid)
    {
      for (const glm::dvec3& n : pyramid.Normals)
      {
        Require(IsFinite(n), "valid pyramids have finite normals");
      }
    }
    for (const glm::dvec3& p : receivers)
    {
      const int m = MultiplicityFrom(p, a, faces.data(), static_cast<int>(faces.size()), frontOnly);
      Require(std::abs(m) <= static_cast<int>(faces.size()), "multiplicity bounded by the faces");
      for (const glm::dvec4& s : samples)
      {
        const int crossing = SampleCrossing(p, a, b, light, s);
        Require(crossing >= -1 && crossing <= 1, "a crossing is -1, 0 or 1");
      }
    }
  }
  (void)CountingIsCheaper({ { potential.size(), centre.Silhouette.size(), radius } }, 16);
}

} // namespace

/// A caster point's sweep away from the light crosses the end plane at least 11.5 degrees from
/// edge-on, beyond the point and at a finite place.
void CheckSweepCrossesEndPlane(
  const glm::dvec3& v, const glm::dvec4& light, const glm::dvec4& plane)
{
  glm::dvec3 away = light.w != 0.0 ? v - glm::dvec3(light) : -glm::dvec3(light);
  // Over its largest component: a directional light's direction may have any length, and the
  // squares in glm::length overflow past 1e154 or vanish below 1e-154.
  const double largest = std::max({ std::abs(away.x), std::abs(away.y), std::abs(away.z) });
  if (largest > 0.0)
  {
    away /= largest;
  }
  const double crossing = glm::dot(glm::dvec3(plane), away);
  Require(crossing >= (0.2 - 1e-9) * glm::length(away), "every sweep crosses the end plane");
  const double reach = -glm::dot(plane, glm::dvec4(v, 1.0)) / crossing;
  // Not before the point, but for rounding at the scale of its coordinates.
  const double slack = 1e-9 * (glm::length(v) + std::abs(plane.w));
  Require(std::isfinite(reach) && reach * glm::length(away) >= -slack,
    "swept points land beyond the caster");
}

/// VolumeEndPlane: none, or a finite plane that the scene box, the caster's box and the near
/// corners lie in front of, and that the sweep of every point of a triangle crosses.
void CheckEndPlane(
  const CasterTopology& topo, const glm::dvec4& light, const std::vector<glm::dvec3>& receivers)
{
  if (topo.Points.empty())
  {
    return;
  }
  Box scene;
  scene.Extend(topo.BoundsMin, topo.BoundsMax);
  for (const glm::dvec3& p : receivers)
  {
    if (std::isfinite(p.x + p.y + p.z))
    {
      scene.Extend(p, p);
    }
  }
  const glm::dvec3 size = scene.Max - scene.Min + glm::dvec3(1.0);
  const std::array<glm::dvec3, 4> nearCorners = { scene.Max + size, scene.Max + 2.0 * size,
    scene.Min - size, scene.Min - glm::dvec3(size.x, 0.0, 0.0) };
  const glm::dvec4 plane =
    VolumeEndPlane(topo.BoundsMin, topo.BoundsMax, light, scene, nearCorners);
  if (plane == glm::dvec4(0.0))
  {
    return;
  }
  const glm::dvec3 normal(plane);
  Require(std::isfinite(plane.x + plane.y + plane.z + plane.w) &&
      std::abs(glm::length(normal) - 1.0) < 1e-9,
    "end plane finite, unit normal");
  auto inFront = [&](const glm::dvec3& p)
  { return glm::dot(plane, glm::dvec4(p, 1.0)) < 1e-9 * (1.0 + std::abs(plane.w)); };
  for (int corner = 0; corner < 8; ++corner)
  {
    Require(
      inFront(BoxCorner(scene.Min, scene.Max, corner)), "the scene lies in front of the end plane");
  }
  for (const glm::dvec3& c : nearCorners)
  {
    Require(inFront(c), "the near rectangle lies in front of the end plane");
  }
  for (const glm::uvec3& triangle : topo.Triangles)
  {
    for (int corner = 0; corner < 3; ++corner)
    {
      CheckSweepCrossesEndPlane(topo.Points[triangle[corner]], light, plane);
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ByteReader in(data, size);
  const std::uint8_t flags = in.U8();
  const bool mirrored = (flags & 2) != 0;
  const double tolerance = DecodeWeldTolerance(flags);

  const bool positional = (in.U8() & 1) != 0;
  glm::dvec4 light;
  light.x = DecodeScalar(in);
  light.y = DecodeScalar(in);
  light.z = DecodeScalar(in);
  light.w = positional ? 1.0 : 0.0;
  const double radius = DecodeScalar(in);

  const CasterTopology topo = (flags & 1) ? BuildPolyData(in, tolerance) : BuildRaw(in, tolerance);
  Require(topo.Points.size() <= MaxPoints, "point cap");
  CheckTopology(topo);

  // The volume's light is relative to the caster's origin, as vtkSoftShadowPass passes it.
  const glm::dvec4 local = positional ? glm::dvec4(glm::dvec3(light) - topo.Origin, 1.0) : light;
  const ShadowVolume capped = ShadowVolume::Build(topo, local, mirrored, true);
  const ShadowVolume sides = ShadowVolume::Build(topo, local, mirrored, false);
  const ShadowVolume flipped = ShadowVolume::Build(topo, local, !mirrored, false);
  CheckVolume(topo, capped, local, true);
  CheckVolume(topo, sides, local, false);
  CheckVolume(topo, flipped, local, false);
  Require(capped.Silhouette.size() == sides.Silhouette.size() && capped.Sides == sides.Sides,
    "caps do not change the silhouette");
  Require(flipped.Silhouette.size() == sides.Silhouette.size(), "mirroring keeps the silhouette");
  for (std::size_t i = 0; i < sides.Silhouette.size(); ++i)
  {
    const SilhouetteEdge &e = sides.Silhouette[i], &f = flipped.Silhouette[i];
    Require(e.From == f.To && e.To == f.From && e.Multiplicity == f.Multiplicity,
      "mirroring reverses the silhouette");
  }
  const bool frontOnly = ShadowVolume::FrontFacesSuffice(topo, local);
  Require(!frontOnly || topo.ClosedAndOriented, "front faces suffice only for closed meshes");

  // Receivers: free points, or points beyond an edge as seen from the light (the penumbra).
  struct Receiver
  {
    bool Free;
    glm::dvec3 Point;
    double T, Distance;
  };
  std::vector<Receiver> receivers(in.U8() % 5);
  for (Receiver& r : receivers)
  {
    r.Free = (in.U8() & 1) != 0;
    if (r.Free)
    {
      r.Point = DecodePoint(in);
    }
    else
    {
      r.T = in.U8() / 255.0;
      r.Distance = DecodeScalar(in);
    }
  }
  std::vector<glm::dvec3> points(receivers.size());
  for (const SilhouetteEdge& e : capped.Silhouette)
  {
    const glm::dvec3 a = topo.Points[e.From], b = topo.Points[e.To];
    for (std::size_t i = 0; i < receivers.size(); ++i)
    {
      const Receiver& r = receivers[i];
      const glm::dvec3 onEdge = a + r.T * (b - a);
      const glm::dvec3 away = positional ? onEdge - glm::dvec3(local) : -glm::dvec3(local);
      points[i] = r.Free ? r.Point : onEdge + r.Distance * away;
    }
    CheckWedgeAndOcclusion(a, b, local, radius, points);
  }
  CheckEndPlane(topo, local, points);

  // Light samples: the light math the averaged hard shadows share.
  const int sampleCount = in.U8() % 17;
  const glm::dvec3 target = DecodePoint(in);
  // A directional light is given as a unit direction, as the API asks.
  const double towards = glm::length(glm::dvec3(light));
  const bool unit = !positional && towards > 1e-100 && towards < 1e100;
  const glm::dvec4 sampled = unit ? glm::dvec4(glm::dvec3(light) / towards, 0.0) : light;
  const std::vector<glm::dvec4> samples = SpreadLightSamples(sampled, radius, sampleCount, target);
  Require(samples.size() == static_cast<std::size_t>(sampleCount), "one sample per request");
  const bool sane = IsFinite(light) && IsFinite(target) && std::abs(radius) < 1e100 &&
    (positional ? glm::length(target - glm::dvec3(light)) < 1e100 : unit);
  for (const glm::dvec4& s : samples)
  {
    Require(!sane || (IsFinite(s) && s.w == sampled.w), "light samples finite for a finite light");
  }
  // In the caster's frame, as the centre: positional samples relative to its origin.
  std::vector<glm::dvec4> localSamples;
  for (const glm::dvec4& sample : samples)
  {
    localSamples.push_back(
      sample.w != 0.0 ? glm::dvec4(glm::dvec3(sample) - topo.Origin, 1.0) : sample);
  }
  CheckCounting(topo, local, radius, frontOnly, sides, localSamples, points);
  return 0;
}
