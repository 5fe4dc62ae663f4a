// libFuzzer target on Penumbra::Geometry: caster topology, silhouettes, shadow volumes, penumbra
// wedges and EdgeOcclusion, fed random and malformed meshes and lights. The byte format is in
// penumbraFuzzInput.h; the invariants are listed in Documentation/fuzzing.md. A violated
// invariant prints what broke and aborts, so libFuzzer (or the smoke driver) reports the input.
#include "penumbraCasterTopology.h"
#include "penumbraConvexClip.h"
#include "penumbraCulling.h"
#include "penumbraFuzzInput.h"
#include "penumbraGlyphs.h"
#include "penumbraLightSamples.h"
#include "penumbraPlateaus.h"
#include "penumbraSampleCounting.h"
#include "penumbraShadowVolume.h"
#include "penumbraWedge.h"
#include "penumbraWedgeBound.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
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

/// The faces around an edge, as the counting passes them: each triangle's normal and walk.
std::vector<EdgeFace> FacesOf(const CasterTopology& topo, const Edge& edge)
{
  std::vector<EdgeFace> faces;
  for (std::uint32_t u = edge.FirstUse; u < edge.FirstUse + edge.UseCount; ++u)
  {
    const glm::uvec3& tri = topo.Triangles[topo.Uses[u].Triangle];
    faces.push_back({ glm::cross(topo.Points[tri.y] - topo.Points[tri.x],
                        topo.Points[tri.z] - topo.Points[tri.x]),
      topo.Uses[u].Sign });
  }
  return faces;
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
    const std::vector<EdgeFace> faces = FacesOf(topo, edge);
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

// ---- Receiver boxes, their disjoint pieces and the convex cuts of wedges to them ----

/// The largest magnitude among the box's coordinates, for tolerances that follow rounding.
double Magnitude(const Box& box)
{
  const glm::dvec3 m = glm::max(glm::abs(box.Min), glm::abs(box.Max));
  return std::max({ m.x, m.y, m.z });
}

bool IsFinite(const Box& box)
{
  return box.Valid && IsFinite(box.Min) && IsFinite(box.Max) && std::isfinite(box.Diagonal());
}

/// A box from two points (ordered as Box::Extend orders them), or an invalid one.
Box DecodeBox(ByteReader& in)
{
  const bool invalid = (in.U8() & 1) != 0;
  const glm::dvec3 a = DecodePoint(in), b = DecodePoint(in);
  Box box;
  if (!invalid)
  {
    box.Extend(glm::min(a, b), glm::max(a, b));
  }
  return box;
}

/// Closed containment, with `slack` beyond each face.
bool Holds(const Box& box, const glm::dvec3& p, double slack = 0.0)
{
  return glm::all(glm::lessThanEqual(box.Min - slack, p)) &&
    glm::all(glm::lessThanEqual(p, box.Max + slack));
}

/// Half-open containment, as the counting shader tests a pixel's point against a piece.
bool HoldsHalfOpen(const Box& box, const glm::dvec3& p)
{
  return glm::all(glm::lessThanEqual(box.Min, p)) && glm::all(glm::lessThan(p, box.Max));
}

/// Up to `most` values of each axis where pieces can disagree: the boxes' faces, the middles
/// between them and a value beyond each end.
std::array<std::vector<double>, 3> ProbeCoordinates(const std::vector<Box>& boxes, std::size_t most)
{
  std::array<std::vector<double>, 3> probes;
  for (int axis = 0; axis < 3; ++axis)
  {
    std::vector<double> faces;
    for (const Box& box : boxes)
    {
      faces.push_back(box.Min[axis]);
      faces.push_back(box.Max[axis]);
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    std::vector<double> all = { faces.front() - 1.0, faces.back() + 1.0 };
    for (std::size_t i = 0; i < faces.size(); ++i)
    {
      all.push_back(faces[i]);
      if (i + 1 < faces.size())
      {
        all.push_back(0.5 * faces[i] + 0.5 * faces[i + 1]);
      }
    }
    const std::size_t stride = (all.size() + most - 1) / most;
    for (std::size_t i = 0; i < all.size(); i += stride)
    {
      probes[axis].push_back(all[i]);
    }
  }
  return probes;
}

/// DisjointPieces of finite boxes: no two pieces overlap, and a point lies in exactly one piece
/// where it lies in a box (half-open, as the pieces), in none elsewhere; past `maxBoxes` boxes,
/// one piece holding them all.
void CheckDisjointPieces(const std::vector<Box>& boxes, std::size_t maxBoxes)
{
  const std::vector<Box> pieces = DisjointPieces(boxes, maxBoxes);
  std::vector<Box> valid;
  std::copy_if(boxes.begin(), boxes.end(), std::back_inserter(valid),
    [](const Box& b) { return IsFinite(b); });
  if (valid.empty())
  {
    Require(pieces.empty(), "no pieces without finite boxes");
    return;
  }
  if (valid.size() > maxBoxes)
  {
    Require(pieces.size() == 1, "past maxBoxes, one piece");
    for (const Box& box : valid)
    {
      Require(pieces[0].Contains(box), "the one piece holds every box");
    }
    return;
  }
  for (std::size_t i = 0; i < pieces.size(); ++i)
  {
    Require(pieces[i].Valid && glm::all(glm::lessThan(pieces[i].Min, pieces[i].Max)),
      "pieces have a volume");
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
    {
      const glm::dvec3 lo = glm::max(pieces[i].Min, pieces[j].Min);
      const glm::dvec3 hi = glm::min(pieces[i].Max, pieces[j].Max);
      Require(!glm::all(glm::lessThan(lo, hi)), "pieces do not overlap");
    }
  }
  auto check = [&](const glm::dvec3& p)
  {
    const bool inBox =
      std::any_of(valid.begin(), valid.end(), [&p](const Box& b) { return HoldsHalfOpen(b, p); });
    const auto holding = std::count_if(
      pieces.begin(), pieces.end(), [&p](const Box& b) { return HoldsHalfOpen(b, p); });
    Require(holding == (inBox ? 1 : 0), "a point in a box lies in exactly one piece");
  };
  // Every box's corners, then a grid of faces and the middles between them.
  for (const Box& box : valid)
  {
    for (int corner = 0; corner < 8; ++corner)
    {
      check(BoxCorner(box.Min, box.Max, corner));
    }
  }
  const std::array<std::vector<double>, 3> probes = ProbeCoordinates(valid, 9);
  for (double x : probes[0])
  {
    for (double y : probes[1])
    {
      for (double z : probes[2])
      {
        check({ x, y, z });
      }
    }
  }
}

/// StableReceiverBox and ReceiverPieceBox: the stable box holds the receivers, and each piece
/// lies in it and holds its receiver (where coordinates resolve the 1% margins).
Box CheckReceiverBoxes(const std::vector<Box>& receivers, const Box& kept, std::vector<Box>& pieces)
{
  Box current; // as the pass gathers it: a receiver of unknown extent leaves none
  for (const Box& box : receivers)
  {
    if (IsFinite(box))
    {
      current.Extend(box.Min, box.Max);
    }
    else if (box.Valid)
    {
      current = Box();
      break;
    }
  }
  const Box stable = StableReceiverBox(kept, current);
  if (!IsFinite(current))
  {
    return stable;
  }
  Require(stable.Contains(current), "the stable box holds the receivers");
  const bool resolved = current.Diagonal() > 1e-9 * Magnitude(current);
  for (const Box& box : receivers)
  {
    const Box piece = ReceiverPieceBox(stable, box);
    Require(piece.Valid == (IsFinite(box) && IsFinite(stable) && stable.Diagonal() > 0.0),
      "a piece for each finite receiver");
    if (piece.Valid)
    {
      Require(stable.Contains(piece), "pieces lie in the stable box");
      Require(!resolved || piece.Contains(box), "a piece holds its receiver");
      pieces.push_back(piece);
    }
  }
  return stable;
}

/// A closed surface: every directed edge of its triangles comes back once the other way.
bool IsClosed(const ConvexPolyhedron& shape)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> forward, backward;
  for (std::size_t t = 0; t + 2 < shape.Triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = shape.Triangles[t + k], b = shape.Triangles[t + (k + 1) % 3];
      forward.emplace_back(a, b);
      backward.emplace_back(b, a);
    }
  }
  std::sort(forward.begin(), forward.end());
  std::sort(backward.begin(), backward.end());
  return forward == backward;
}

/// The cut holds what it must: every point of a 5^3 lattice in the box that lies inside every
/// half-space by a margin lies on the inner side of each of the cut's faces (those with an area
/// above rounding; the cut has slivers between near-duplicate points).
void CheckCovers(const ConvexPolyhedron& shape, const Box& box,
  const std::vector<HalfSpace>& halfSpaces, double rounding)
{
  const double margin = 1e3 * rounding;
  for (int k = 0; k < 125; ++k)
  {
    const glm::dvec3 t(
      0.05 + 0.225 * (k % 5), 0.05 + 0.225 * ((k / 5) % 5), 0.05 + 0.225 * (k / 25));
    const glm::dvec3 p = box.Min + t * (box.Max - box.Min);
    const bool kept = std::all_of(halfSpaces.begin(), halfSpaces.end(),
      [&](const HalfSpace& half)
      {
        const double length = glm::length(half.Normal);
        return !(length > 0.0 && std::isfinite(length) && std::isfinite(half.Offset / length)) ||
          glm::dot(half.Normal / length, p) - half.Offset / length < -margin;
      });
    if (!kept || glm::any(glm::lessThan(p - box.Min, glm::dvec3(margin))) ||
      glm::any(glm::lessThan(box.Max - p, glm::dvec3(margin))))
    {
      continue;
    }
    for (std::size_t t3 = 0; t3 + 2 < shape.Triangles.size(); t3 += 3)
    {
      const glm::dvec3& a = shape.Points[shape.Triangles[t3]];
      const glm::dvec3 n = glm::cross(
        shape.Points[shape.Triangles[t3 + 1]] - a, shape.Points[shape.Triangles[t3 + 2]] - a);
      const double area = glm::length(n);
      if (area > margin * box.Diagonal())
      {
        Require(glm::dot(n / area, p - a) <= rounding, "cut: holds the box cut by the half-spaces");
      }
    }
  }
}

/// ClipBox: indices in range, points finite, in the box and, unless it left cuts out, in every
/// half-space, a closed surface of non-negative volume no larger than the box's; the box itself
/// without half-spaces.
void CheckClipBox(const Box& box, const std::vector<HalfSpace>& halfSpaces)
{
  const ConvexPolyhedron shape = ClipBox(box, halfSpaces);
  if (!IsFinite(box) || !(box.Diagonal() > 0.0))
  {
    Require(shape.Empty(), "no cut of a box that is not finite");
    return;
  }
  Require(shape.Triangles.size() % 3 == 0, "cut: whole triangles");
  Require(shape.CutsLeftOut <= halfSpaces.size(), "cut: left out no more cuts than given");
  for (std::uint32_t i : shape.Triangles)
  {
    Require(i < shape.Points.size(), "cut: indices in range");
  }
  const double size = box.Diagonal();
  const double rounding = 1e-9 * (size + Magnitude(box));
  for (const glm::dvec3& p : shape.Points)
  {
    Require(IsFinite(p), "cut: finite points");
    Require(Holds(box, p, rounding), "cut: points in the box");
    for (const HalfSpace& half : halfSpaces)
    {
      const double length = glm::length(half.Normal);
      if (length > 0.0 && std::isfinite(length) && std::isfinite(half.Offset) &&
        shape.CutsLeftOut == 0)
      {
        const double side = glm::dot(half.Normal / length, p) - half.Offset / length;
        Require(side <= rounding + 1e-9 * std::abs(half.Offset / length),
          "cut: points in every half-space");
      }
    }
  }
  const glm::dvec3 extent = box.Max - box.Min;
  if (shape.Empty())
  {
    // A box thinner than its coordinates' rounding is a sliver, cut or not.
    Require(!halfSpaces.empty() || std::min({ extent.x, extent.y, extent.z }) <= rounding,
      "the box itself without half-spaces");
    return;
  }
  Require(IsClosed(shape), "cut: a closed surface");
  CheckCovers(shape, box, halfSpaces, rounding);
  if (size > 1e-6 * Magnitude(box))
  {
    // About the box's centre and in units of its diagonal, where the volume's products keep
    // their digits and do not overflow.
    const glm::dvec3 centre = 0.5 * box.Min + 0.5 * box.Max;
    auto scaled = [&](std::uint32_t i) { return (shape.Points[i] - centre) / size; };
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < shape.Triangles.size(); t += 3)
    {
      volume += glm::dot(scaled(shape.Triangles[t]),
                  glm::cross(scaled(shape.Triangles[t + 1]), scaled(shape.Triangles[t + 2]))) /
        6.0;
    }
    const double boxVolume = extent.x / size * extent.y / size * extent.z / size;
    const double slack = 1e-6;
    Require(volume >= -slack && volume <= boxVolume + slack, "cut: volume within the box's");
    Require(!halfSpaces.empty() || std::abs(volume - boxVolume) <= slack,
      "cut: the box itself without half-spaces");
  }
}

/// A wedge cut to a box and drawn by its front faces must not reach beyond the wedge, where the
/// eye may stand (ClipBox's left-out cuts make it Enlarged instead): its points lie in the
/// wedge's half-spaces, to float rounding.
void CheckInsideWedge(
  const std::vector<float>& vertices, int floatsPerVertex, const Wedge& wedge, const Box& box)
{
  if (!wedge.Valid || !IsFinite(box) || Magnitude(box) > 1e15)
  {
    return;
  }
  const double rounding = 1e-5 * (box.Diagonal() + Magnitude(box));
  for (std::size_t v = 0; v < vertices.size(); v += floatsPerVertex)
  {
    const glm::dvec3 p(vertices[v], vertices[v + 1], vertices[v + 2]);
    for (const HalfSpace& half : wedge.HalfSpaces())
    {
      Require(glm::dot(half.Normal, p) - half.Offset <= rounding * glm::length(half.Normal),
        "wedge bound: a wedge's cut lies in the wedge");
    }
  }
}

/// AppendWedgeBound (cut to the box, and whole) and AppendWedgeBoundInPieces: whole vertices,
/// indices in range, finite floats for finite inputs; cuts inside their box.
void CheckWedgeBounds(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light,
  double radius, const Box& receivers, const std::vector<Box>& pieces, const EdgeFace* faces,
  bool frontOnly)
{
  const float attributes[3] = { 1.0f, 2.0f, 3.0f };
  const bool finite = IsFinite(a) && IsFinite(b) && IsFinite(light) && std::isfinite(radius) &&
    std::max({ glm::length(a), glm::length(b), glm::length(glm::dvec3(light)) }) < 1e30;
  auto check = [&](const std::vector<float>& vertices, const std::vector<std::uint32_t>& indices,
                 int floatsPerVertex, const Box* inside)
  {
    Require(vertices.size() % floatsPerVertex == 0 && indices.size() % 3 == 0,
      "wedge bound: whole vertices and triangles");
    for (std::uint32_t i : indices)
    {
      Require(i < vertices.size() / floatsPerVertex, "wedge bound: indices in range");
    }
    const bool smallBox = !inside || (IsFinite(*inside) && Magnitude(*inside) < 1e30);
    for (std::size_t v = 0; finite && smallBox && v < vertices.size(); v += floatsPerVertex)
    {
      const glm::dvec3 p(vertices[v], vertices[v + 1], vertices[v + 2]);
      Require(IsFinite(p) && std::isfinite(vertices[v + 3]), "wedge bound: finite vertices");
      if (inside)
      {
        // Float's relative rounding, and its step between subnormals.
        const double rounding = 1e-6 * (inside->Diagonal() + Magnitude(*inside)) + 1e-44;
        Require(Holds(*inside, p, rounding), "wedge bound: cut inside the receivers' box");
      }
    }
  };
  for (const Box& box : { receivers, Box() })
  {
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices;
    const WedgeShape shape = AppendWedgeBound(
      a, b, light, radius, box, faces, frontOnly, attributes, 3, vertices, indices);
    Require((shape == WedgeShape::Nothing) == vertices.empty(), "wedge bound: nothing or a shape");
    check(vertices, indices, 7, box.Valid ? &box : nullptr);
    if (shape == WedgeShape::Planes && box.Valid && finite)
    {
      CheckInsideWedge(vertices, 7, Wedge::Build(a, b, light, radius), box);
    }
  }
  if (receivers.Valid)
  {
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices;
    const WedgeShape shape = AppendWedgeBoundInPieces(
      a, b, light, radius, receivers, pieces, faces, frontOnly, attributes, 3, vertices, indices);
    Require((shape == WedgeShape::Nothing) == vertices.empty(), "pieces: nothing or a shape");
    check(vertices, indices, 13, &receivers);
  }
}

/// The receivers' boxes, their pieces and the cuts of the silhouette edges' wedges to them, as
/// counting builds them; then DisjointPieces and ClipBox on the decoded boxes and half-spaces.
/// Returns the decoded boxes.
std::vector<Box> CheckReceiverCuts(ByteReader& in, const CasterTopology& topo,
  const ShadowVolume& centre, const glm::dvec4& light, double radius, bool frontOnly)
{
  std::vector<Box> receivers(in.U8() % 11);
  for (Box& box : receivers)
  {
    box = DecodeBox(in);
  }
  const Box kept = DecodeBox(in);
  std::vector<HalfSpace> halfSpaces(in.U8() % 5);
  for (HalfSpace& half : halfSpaces)
  {
    half.Normal = DecodePoint(in);
    half.Offset = DecodeScalar(in);
  }
  CheckDisjointPieces(receivers, 8);
  CheckDisjointPieces(receivers, 2);
  std::vector<Box> pieceBoxes;
  const Box stable = CheckReceiverBoxes(receivers, kept, pieceBoxes);
  const std::vector<Box> pieces = DisjointPieces(pieceBoxes);
  CheckDisjointPieces(pieceBoxes, 8);
  CheckClipBox(stable, halfSpaces);
  CheckClipBox(stable, {});
  std::size_t checked = 0;
  for (const SilhouetteEdge& e : centre.Silhouette)
  {
    if (++checked > 16)
    {
      break; // bounded work per input
    }
    const glm::dvec3 a = topo.Points[e.From], b = topo.Points[e.To];
    const auto edge = std::find_if(topo.Edges.begin(), topo.Edges.end(),
      [&e](const Edge& x)
      { return x.A == std::min(e.From, e.To) && x.B == std::max(e.From, e.To); });
    Require(edge != topo.Edges.end(), "silhouette edges are edges of the mesh");
    const std::vector<EdgeFace> faces = FacesOf(topo, *edge);
    const Wedge wedge = Wedge::Build(a, b, light, radius);
    if (wedge.Valid)
    {
      std::vector<HalfSpace> cut = wedge.HalfSpaces();
      cut.insert(cut.end(), halfSpaces.begin(), halfSpaces.end());
      CheckClipBox(stable, cut);
    }
    CheckWedgeBounds(
      a, b, light, radius, stable, pieces, faces.size() == 2 ? faces.data() : nullptr, frontOnly);
  }
  return receivers;
}

// ---- Culling: what the pass decides per caster and light before drawing ----

/// A camera as the pass sees it: its view and projection (OpenGL clip space), clipping range
/// and near-plane rectangle; Valid where they are finite.
struct FuzzCamera
{
  glm::dmat4 WorldToView{ 1.0 }, WorldToClip{ 1.0 };
  glm::dvec2 Range{ 0.1, 10.0 };
  std::array<glm::dvec3, 4> NearCorners;
  bool Valid = false;
};

bool IsFinite(const glm::dmat4& m)
{
  return IsFinite(m[0]) && IsFinite(m[1]) && IsFinite(m[2]) && IsFinite(m[3]);
}

/// A point of clip space (x, y, z in [-1, 1]) in the world.
glm::dvec3 FromClip(const glm::dmat4& clipToWorld, const glm::dvec3& clip)
{
  const glm::dvec4 p = clipToWorld * glm::dvec4(clip, 1.0);
  return glm::dvec3(p) / p.w;
}

FuzzCamera DecodeCamera(ByteReader& in)
{
  FuzzCamera camera;
  const glm::dvec3 eye = DecodePoint(in), focal = DecodePoint(in);
  const std::uint8_t flags = in.U8();
  const glm::dvec3 up = flags % 3 == 0
    ? glm::dvec3(0, 1, 0)
    : (flags % 3 == 1 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0));
  camera.Range.x = 1e-3 * (1 + in.U8()) * ((flags & 8) ? 1e-3 : 1.0);
  camera.Range.y = camera.Range.x * (1.5 + in.U16());
  camera.WorldToView = glm::lookAt(eye, focal, up);
  const double aspect = 0.5 + in.U8() / 64.0;
  const double angle = glm::radians(5.0 + in.U8() % 160);
  const double half = 0.5 * glm::length(focal - eye) + 1e-3;
  const glm::dmat4 projection = (flags & 4)
    ? glm::ortho(-aspect * half, aspect * half, -half, half, camera.Range.x, camera.Range.y)
    : glm::perspective(angle, aspect, camera.Range.x, camera.Range.y);
  camera.WorldToClip = projection * camera.WorldToView;
  const glm::dmat4 clipToWorld = glm::inverse(camera.WorldToClip);
  for (int i = 0; i < 4; ++i)
  {
    camera.NearCorners[i] =
      FromClip(clipToWorld, { (i == 1 || i == 2) ? 1.0 : -1.0, i >= 2 ? 1.0 : -1.0, -1.0 });
  }
  camera.Valid = IsFinite(camera.WorldToClip) && IsFinite(clipToWorld) &&
    std::all_of(camera.NearCorners.begin(), camera.NearCorners.end(),
      [](const glm::dvec3& c) { return IsFinite(c); });
  return camera;
}

/// Whether the camera's near rectangle lies within 1e12 of the origin: the near plane of an eye
/// 1e30 away, or of a view 1e30 wide, drowns in the rounding of its corners, and what lies in
/// its view is no longer decided to the precision the checks need.
bool NearBy(const FuzzCamera& camera)
{
  return std::all_of(camera.NearCorners.begin(), camera.NearCorners.end(),
    [](const glm::dvec3& c) { return glm::length(c) < 1e12; });
}

/// Whether the segment from the light point `from` to `q` meets the box (slab test, the box
/// already shrunk by the caller's margin so that touching it does not count). Measured from the
/// end nearer the box along the unit direction to the other: from an end 1e30 away, the
/// crossings of a box a few units wide round together.
bool SegmentMeetsBox(const glm::dvec3& from, const glm::dvec3& to, const Box& box)
{
  const glm::dvec3 centre = 0.5 * box.Min + 0.5 * box.Max;
  const bool fromNearer = glm::length(from - centre) < glm::length(to - centre);
  const glm::dvec3 q = fromNearer ? from : to;
  const glm::dvec3 towards = (fromNearer ? to : from) - q;
  const double length = glm::length(towards);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return Holds(box, q);
  }
  const glm::dvec3 d = towards / length;
  double enter = 0.0, leave = length;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (d[axis] == 0.0)
    {
      if (q[axis] < box.Min[axis] || q[axis] > box.Max[axis])
      {
        return false;
      }
      continue;
    }
    double t0 = (box.Min[axis] - q[axis]) / d[axis], t1 = (box.Max[axis] - q[axis]) / d[axis];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter <= leave;
}

/// The caster's box shrunk by a margin beyond rounding, or invalid where it has no inside.
Box Shrunk(const glm::dvec3& min, const glm::dvec3& max)
{
  Box box;
  box.Extend(min, max);
  const double margin = 1e-6 * (box.Diagonal() + Magnitude(box));
  box.Min += margin;
  box.Max -= margin;
  box.Valid = IsFinite(box) && glm::all(glm::lessThan(box.Min, box.Max));
  return box;
}

/// Where the light stands for a point: its centre and, for a radius, six points of its sphere
/// (positional) or directions at its angular radius (directional); unit directions towards a
/// directional light, reached at `far`.
std::vector<glm::dvec3> LightPoints(
  const glm::dvec4& light, double radius, const glm::dvec3& from, double far)
{
  std::vector<glm::dvec3> points;
  if (light.w != 0.0)
  {
    points.push_back(glm::dvec3(light));
    for (int k = 0; k < 6; ++k)
    {
      glm::dvec3 offset(0.0);
      offset[k / 2] = (k % 2 ? -radius : radius);
      points.push_back(glm::dvec3(light) + offset);
    }
    return points;
  }
  const glm::dvec3 towards = UnitDirection(glm::dvec3(light));
  const glm::dvec3 side = UnitDirection(
    glm::cross(towards, std::abs(towards.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 other = glm::cross(towards, side);
  const double r = std::min(radius, 1.5);
  for (const glm::dvec3& d : { towards, std::cos(r) * towards + std::sin(r) * side,
         std::cos(r) * towards - std::sin(r) * side, std::cos(r) * towards + std::sin(r) * other,
         std::cos(r) * towards - std::sin(r) * other })
  {
    points.push_back(from + far * d);
  }
  return points;
}

/// VolumeMayReachNearPlane and ShadowMayReachView may be false alarms, never wrong: where a
/// point of the near rectangle (of the view) lies in the caster box's shadow from a point of the
/// light, they must say so.
void CheckCulling(
  const FuzzCamera& camera, const CasterTopology& topo, const glm::dvec4& light, double radius)
{
  const std::array<glm::dvec3, 4>& near = camera.NearCorners;
  const bool reaches = VolumeMayReachNearPlane(topo.BoundsMin, topo.BoundsMax, light, near);
  const bool inView =
    ShadowMayReachView(topo.BoundsMin, topo.BoundsMax, light, radius, camera.WorldToClip);
  (void)WedgesDrawnByFrontFaces(topo.BoundsMin, topo.BoundsMax, light, radius, near, false);
  (void)BoxBeyondNearPlane(topo.BoundsMin, topo.BoundsMax, camera.WorldToClip);
  const Box caster = Shrunk(topo.BoundsMin, topo.BoundsMax);
  const double reach = 4.0 * (Magnitude(caster) + camera.Range.y + glm::length(glm::dvec3(light)));
  if (!camera.Valid || !NearBy(camera) || topo.Points.empty() || !caster.Valid ||
    !IsFinite(light) || !(radius >= 0.0) || radius > 1e6 || !(reach < 1e100) ||
    (light.w == 0.0 && !(glm::length(glm::dvec3(light)) > 1e-100)))
  {
    return;
  }
  for (int i = 0; i <= 4 && !reaches; ++i)
  {
    for (int j = 0; j <= 4; ++j)
    {
      const glm::dvec3 q = (1.0 - j / 4.0) * ((1.0 - i / 4.0) * near[0] + i / 4.0 * near[1]) +
        j / 4.0 * ((1.0 - i / 4.0) * near[3] + i / 4.0 * near[2]);
      const glm::dvec3 from = LightPoints(light, 0.0, q, reach)[0];
      Require(!SegmentMeetsBox(from, q, caster), "a volume reaching the near plane is seen");
    }
  }
  const glm::dmat4 clipToWorld = glm::inverse(camera.WorldToClip);
  for (int k = 0; k < 27 && !inView; ++k)
  {
    const glm::dvec3 q = FromClip(clipToWorld, { k % 3 - 1.0, (k / 3) % 3 - 1.0, k / 9 - 1.0 });
    for (const glm::dvec3& from : LightPoints(light, radius, q, reach))
    {
      Require(!IsFinite(q) || !SegmentMeetsBox(from, q, caster), "a shadow in view is seen");
    }
  }
}

/// TightClippingRange: finite, within the camera's, near at most 0.8 of far, and every corner
/// and centre of a prop's box in view, and every point of a 5^3 lattice of the view inside a
/// box (a ground across the view has no corner in it), within it.
void CheckTightRange(const FuzzCamera& camera, const std::vector<Box>& props)
{
  const glm::dvec2 range =
    TightClippingRange(props, camera.WorldToView, camera.WorldToClip, camera.Range);
  if (!camera.Valid || !NearBy(camera))
  {
    return;
  }
  Require(std::isfinite(range.x) && std::isfinite(range.y) && range.x > 0.0 && range.x < range.y,
    "tight range: finite, positive and ordered");
  Require(
    range.x >= camera.Range.x && range.y <= camera.Range.y, "tight range: within the camera's");
  Require(range == camera.Range || range.x <= 0.8 * range.y, "tight range: near at most 0.8 far");
  const glm::dmat4 clipToWorld = glm::inverse(camera.WorldToClip);
  for (int k = 0; k < 125; ++k)
  {
    const glm::dvec3 p =
      FromClip(clipToWorld, glm::dvec3(k % 5 - 2.0, (k / 5) % 5 - 2.0, k / 25 - 2.0) * 0.45);
    const bool inBox = std::any_of(
      props.begin(), props.end(), [&p](const Box& b) { return b.Valid && Holds(b, p); });
    const double depth = -(camera.WorldToView * glm::dvec4(p, 1.0)).z;
    const double slack = 1e-6 * (std::abs(depth) + camera.Range.y);
    Require(!inBox || !IsFinite(p) || (depth >= range.x - slack && depth <= range.y + slack),
      "tight range: a point in view inside a box stays in it");
  }
  for (const Box& box : props)
  {
    if (!IsFinite(box))
    {
      continue;
    }
    for (int k = 0; k < 9; ++k)
    {
      const glm::dvec3 p = k < 8 ? BoxCorner(box.Min, box.Max, k) : 0.5 * box.Min + 0.5 * box.Max;
      if (glm::length(p) > 1e12)
      {
        continue; // whether a point 1e30 away is in view drowns in the matrix's rounding
      }
      const glm::dvec4 clip = camera.WorldToClip * glm::dvec4(p, 1.0);
      const bool seen =
        std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w && std::abs(clip.z) <= clip.w;
      const double depth = -(camera.WorldToView * glm::dvec4(p, 1.0)).z;
      const double slack = 1e-9 * (std::abs(depth) + camera.Range.y);
      Require(!seen || (depth >= range.x - slack && depth <= range.y + slack),
        "tight range: what is in view stays in it");
    }
  }
}

/// OccupancyGrid: its boxes together hold every box added, cut to its bounds.
void CheckOccupancy(const Box& bounds, const std::vector<Box>& added)
{
  OccupancyGrid grid(bounds);
  for (const Box& box : added)
  {
    if (box.Valid)
    {
      grid.Add(box.Min, box.Max);
    }
  }
  const std::vector<Box> cells = grid.Boxes();
  if (!IsFinite(bounds) || Magnitude(bounds) > 1e300)
  {
    return;
  }
  for (const Box& box : added)
  {
    if (!IsFinite(box))
    {
      continue;
    }
    const glm::dvec3 low = glm::clamp(box.Min, bounds.Min, bounds.Max);
    const glm::dvec3 high = glm::clamp(box.Max, bounds.Min, bounds.Max);
    for (int k = 0; k < 9; ++k)
    {
      // (The middle held to the box: halving a subnormal rounds.)
      const glm::dvec3 p =
        k < 8 ? BoxCorner(low, high, k) : glm::clamp(0.5 * low + 0.5 * high, low, high);
      Require(
        std::any_of(cells.begin(), cells.end(), [&p](const Box& cell) { return Holds(cell, p); }),
        "the occupancy grid holds every box added");
    }
  }
}

// ---- Glyph and imposter matrices, receiver planes and plateaus ----

/// GlyphScale, GlyphMatrix and the imposters' matrices: finite for finite input, no zero scale
/// (VTK's 1e-10), the glyph at its position with the volume its scales give, a false return
/// exactly for the input the headers name.
void CheckGlyphs(ByteReader& in)
{
  GlyphSettings settings;
  const std::uint8_t flags = in.U8();
  settings.Scaling = (flags & 1) != 0;
  settings.ScaleMode = (flags >> 1) % 3;
  settings.Clamping = (flags & 8) != 0;
  settings.OrientationMode = (flags >> 4) % 3;
  settings.ScaleFactor = DecodeScalar(in);
  settings.Range[0] = DecodeScalar(in);
  settings.Range[1] = DecodeScalar(in);
  const glm::dvec3 tuple = DecodePoint(in), position = DecodePoint(in);
  const double orientation[4] = { DecodeScalar(in), DecodeScalar(in), DecodeScalar(in),
    DecodeScalar(in) };
  const int components = in.U8() % 4;
  const glm::dvec3 scale = GlyphScale(settings, components ? &tuple.x : nullptr, components);
  const bool finiteSettings = std::isfinite(settings.ScaleFactor) &&
    std::isfinite(settings.Range[0]) && std::isfinite(settings.Range[1]) &&
    std::abs(settings.ScaleFactor) < 1e100 && glm::length(tuple) < 1e100;
  if (finiteSettings && IsFinite(tuple))
  {
    Require(IsFinite(scale) && glm::all(glm::notEqual(scale, glm::dvec3(0.0))),
      "glyph scale finite, never zero");
  }
  glm::dmat4 matrix(0.0);
  const int count = settings.OrientationMode == GlyphSettings::Quaternion ? 4 : 3;
  const bool finiteOrientation =
    std::all_of(orientation, orientation + count, [](double v) { return std::isfinite(v); });
  const bool placed = GlyphMatrix(settings, position, orientation, scale, matrix);
  Require(!placed || finiteOrientation, "a glyph is placed only where its orientation is finite");
  // A direction of moderate length always gives a rotation.
  const double directionLength =
    glm::length(glm::dvec3(orientation[0], orientation[1], orientation[2]));
  Require(placed || !finiteOrientation || settings.OrientationMode != GlyphSettings::Direction ||
      !(directionLength > 1e-100 && directionLength < 1e100),
    "a glyph with a finite direction of moderate length is placed");
  if (placed && IsFinite(position) && IsFinite(scale) && glm::length(position) < 1e100 &&
    glm::length(scale) < 1e100 &&
    glm::length(glm::dvec3(orientation[0], orientation[1], orientation[2])) < 1e100 &&
    std::abs(orientation[3]) < 1e100)
  {
    Require(IsFinite(matrix), "glyph matrix finite");
    Require(glm::length(glm::dvec3(matrix[3]) - position) <= 1e-9 * (1.0 + glm::length(position)),
      "the glyph stands at its point");
    const glm::dvec3 scaled = settings.Scaling ? scale : glm::dvec3(1.0);
    const double volume = std::abs(scaled.x * scaled.y * scaled.z);
    if (volume > 1e-200 && volume < 1e200)
    {
      Require(std::abs(std::abs(glm::determinant(glm::dmat3(matrix))) - volume) <= 1e-6 * volume,
        "a glyph's matrix keeps the volume its scales give");
    }
  }

  const glm::dvec3 centre = DecodePoint(in), axis = DecodePoint(in);
  const double radius = DecodeScalar(in), length = DecodeScalar(in);
  glm::dmat4 actor(1.0);
  const glm::dvec3 moved = DecodePoint(in);
  actor[3] = glm::dvec4(IsFinite(moved) ? moved : glm::dvec3(0.0), 1.0);
  glm::dmat4 sphere(0.0), stick(0.0);
  const bool sphereOk = ImposterSphereMatrix(actor, centre, radius, sphere);
  Require(
    sphereOk == (IsFinite(centre) && IsFinite(actor) && std::isfinite(radius) && radius > 0.0),
    "an imposter sphere is placed exactly for a finite centre and a positive radius");
  if (sphereOk && glm::length(centre) < 1e100 && radius < 1e100 && glm::length(actor[3]) < 1e100)
  {
    Require(IsFinite(sphere) && sphere[0][0] == radius && sphere[1][1] == radius &&
        sphere[2][2] == radius,
      "an imposter sphere has its radius, unscaled");
  }
  const bool stickOk = ImposterStickMatrix(actor, centre, axis, length, radius, stick);
  if (stickOk && glm::length(centre) < 1e100 && glm::length(axis) < 1e100 &&
    std::abs(length) < 1e100 && radius < 1e100 && glm::length(actor[3]) < 1e100)
  {
    Require(IsFinite(stick), "an imposter stick's matrix is finite");
  }
  Require(
    !stickOk || (std::isfinite(length) && length > 0.0 && std::isfinite(radius) && radius > 0.0),
    "an imposter stick needs a positive length and radius");
}

/// FitReceiverPlane: a unit normal, every finite point within the thickness of the plane and
/// within the extent along it; PlateauIntensity within [0, 1] and rising; BuildPlateaus finite,
/// its depths in [0, 1], whole triangles.
void CheckPlateaus(
  ByteReader& in, const CasterTopology& topo, const glm::dvec4& light, double radius)
{
  std::vector<glm::dvec3> points(in.U8() % 9);
  for (glm::dvec3& p : points)
  {
    p = DecodePoint(in);
  }
  PlaneFit fit;
  if (FitReceiverPlane(points, fit))
  {
    Require(std::abs(glm::length(fit.Plane.Normal) - 1.0) < 1e-9, "a fitted plane's unit normal");
    for (const glm::dvec3& p : points)
    {
      if (!IsFinite(p) || glm::length(p) > 1e100)
      {
        continue;
      }
      const double rounding = 1e-9 * (glm::length(p) + glm::length(fit.Plane.Origin) + 1.0);
      Require(std::abs(fit.Plane.Height(p)) <= fit.Thickness + rounding,
        "points within the fitted plane's thickness");
      const glm::dvec2 uv = fit.Plane.ToPlane(p);
      Require(glm::all(glm::lessThanEqual(fit.Min - rounding, uv)) &&
          glm::all(glm::lessThanEqual(uv, fit.Max + rounding)),
        "points within the fitted plane's extent");
    }
  }
  double previous = 0.0;
  for (int k = 0; k <= 8; ++k)
  {
    const double intensity = PlateauIntensity(k / 8.0, PlateauFalloff::Sinusoidal);
    Require(intensity >= 0.0 && intensity <= 1.0 && intensity >= previous,
      "plateau intensity within [0, 1], rising");
    previous = intensity;
  }

  ReceiverPlane plane;
  if (!ReceiverPlane::MakeNear(DecodePoint(in), DecodePoint(in), topo.Origin, plane))
  {
    return;
  }
  // As the pass gives them: a directional light as a unit direction.
  const glm::dvec4 world = light.w != 0.0 ? glm::dvec4(glm::dvec3(light) + topo.Origin, 1.0)
                                          : glm::dvec4(UnitDirection(glm::dvec3(light)), 0.0);
  const ShadowVolume volume = ShadowVolume::Build(topo, light, false, true);
  std::vector<PlateauVertex> triangles;
  const glm::dmat4 toWorld = glm::translate(glm::dmat4(1.0), topo.Origin);
  (void)BuildPlateaus(topo, volume, toWorld, world, radius, plane, triangles);
  Require(triangles.size() % 3 == 0, "plateaus: whole triangles");
  const bool sane = IsFinite(world) && std::isfinite(radius) && std::abs(radius) < 1e100 &&
    (world.w != 0.0 || std::abs(radius) < 1.5) && glm::length(glm::dvec3(world)) < 1e100 &&
    Magnitude(Box{ true, topo.BoundsMin, topo.BoundsMax }) < 1e30 &&
    glm::length(plane.Origin) < 1e30; // a plane 1e283 away puts every shadow beyond float range
  for (const PlateauVertex& v : triangles)
  {
    Require(!sane || (std::isfinite(v.U) && std::isfinite(v.V)), "plateau vertices finite");
    Require(!(v.T < 0.0f) && !(v.T > 1.0f) && (!sane || std::isfinite(v.T)),
      "plateau depth within [0, 1]");
  }
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
  const std::vector<Box> boxes = CheckReceiverCuts(in, topo, sides, local, radius, frontOnly);

  const FuzzCamera camera = DecodeCamera(in);
  CheckCulling(camera, topo, local, radius);
  CheckTightRange(camera, boxes);
  if (!boxes.empty())
  {
    CheckOccupancy(boxes.front(), std::vector<Box>(boxes.begin() + 1, boxes.end()));
  }
  CheckGlyphs(in);
  CheckPlateaus(in, topo, local, radius);
  return 0;
}
