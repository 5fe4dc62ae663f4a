#include "penumbraCasterTopology.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

namespace penumbra
{
namespace
{

constexpr std::uint32_t InvalidIndex = ~std::uint32_t(0);

bool IsFinite(const glm::dvec3& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

/// Welds points closer than `tolerance` (grid hashing, each point checked against its 27 cells).
/// Returns, for every input point, its welded index or InvalidIndex for non-finite points.
std::vector<std::uint32_t> WeldPoints(
  const std::vector<glm::dvec3>& points, double tolerance, std::vector<glm::dvec3>& welded)
{
  struct CellHash
  {
    std::size_t operator()(const glm::i64vec3& c) const
    {
      // Unsigned: the products wrap (signed overflow is undefined for far cells).
      return std::size_t(std::uint64_t(c.x) * 73856093ULL) ^
        std::size_t(std::uint64_t(c.y) * 19349663ULL) ^
        std::size_t(std::uint64_t(c.z) * 83492791ULL);
    }
  };
  std::unordered_map<glm::i64vec3, std::vector<std::uint32_t>, CellHash> grid;
  grid.reserve(points.size());
  const double cellSize = tolerance > 0.0 ? tolerance : 1.0;
  const double tolerance2 = tolerance * tolerance;

  std::vector<std::uint32_t> map(points.size(), InvalidIndex);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const glm::dvec3& p = points[i];
    if (!IsFinite(p))
    {
      continue;
    }
    // Clamped before the conversion: with a zero tolerance (cell size 1) a point at 1e30 would
    // overflow int64 (undefined behaviour). Clamping keeps neighbours in neighbouring cells.
    const double limit = 4e18;
    const glm::i64vec3 cell(glm::clamp(glm::floor(p / cellSize), -limit, limit));
    std::uint32_t found = InvalidIndex;
    for (int dz = -1; dz <= 1 && found == InvalidIndex; ++dz)
    {
      for (int dy = -1; dy <= 1 && found == InvalidIndex; ++dy)
      {
        for (int dx = -1; dx <= 1 && found == InvalidIndex; ++dx)
        {
          auto it = grid.find(cell + glm::i64vec3(dx, dy, dz));
          if (it == grid.end())
          {
            continue;
          }
          for (std::uint32_t candidate : it->second)
          {
            const glm::dvec3 d = welded[candidate] - p;
            if (glm::dot(d, d) <= tolerance2)
            {
              found = candidate;
              break;
            }
          }
        }
      }
    }
    if (found == InvalidIndex)
    {
      found = static_cast<std::uint32_t>(welded.size());
      welded.push_back(p);
      grid[cell].push_back(found);
    }
    map[i] = found;
  }
  return map;
}

/// Appends the triangles of one polygon, ear-cut when it has more than three corners.
void TriangulatePolygon(vtkPolyData* input, vtkIdType npts, const vtkIdType* ids,
  vtkPolygon* polygon, vtkIdList* local, std::vector<glm::uvec3>& triangles)
{
  if (npts < 3)
  {
    return;
  }
  if (npts == 3)
  {
    triangles.emplace_back(ids[0], ids[1], ids[2]);
    return;
  }
  polygon->Initialize(static_cast<int>(npts), ids, input->GetPoints());
  local->Reset();
  if (polygon->Triangulate(local) && local->GetNumberOfIds() == 3 * (npts - 2))
  {
    for (vtkIdType t = 0; t + 2 < local->GetNumberOfIds(); t += 3)
    {
      triangles.emplace_back(
        ids[local->GetId(t)], ids[local->GetId(t + 1)], ids[local->GetId(t + 2)]);
    }
    return;
  }
  // Ear cutting gives up on degenerate polygons: a fan still covers what they cover.
  for (vtkIdType k = 1; k + 1 < npts; ++k)
  {
    triangles.emplace_back(ids[0], ids[k], ids[k + 1]);
  }
}

void AppendStrip(vtkIdType npts, const vtkIdType* ids, std::vector<glm::uvec3>& triangles)
{
  for (vtkIdType k = 0; k + 2 < npts; ++k)
  {
    // Every other triangle of a strip is wound backwards.
    if (k % 2 == 0)
    {
      triangles.emplace_back(ids[k], ids[k + 1], ids[k + 2]);
    }
    else
    {
      triangles.emplace_back(ids[k + 1], ids[k], ids[k + 2]);
    }
  }
}

void BuildEdges(CasterTopology& topo)
{
  struct HalfEdge
  {
    std::uint32_t A, B, Triangle;
    std::int32_t Sign;
  };
  // Half-edges grouped by their smaller end with a counting sort (linear in the mesh), then
  // each group (a vertex's few edges) sorted by the other end: a comparison sort of all of them
  // cost most of a rebuild on time-varying data.
  std::vector<std::uint32_t> groupStart(topo.Points.size() + 1, 0);
  for (const glm::uvec3& tri : topo.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++groupStart[std::min(tri[k], tri[(k + 1) % 3]) + 1];
    }
  }
  for (std::size_t v = 1; v < groupStart.size(); ++v)
  {
    groupStart[v] += groupStart[v - 1];
  }
  std::vector<HalfEdge> halfEdges(topo.Triangles.size() * 3);
  std::vector<std::uint32_t> next(groupStart.begin(), groupStart.end() - 1);
  for (std::uint32_t t = 0; t < topo.Triangles.size(); ++t)
  {
    const glm::uvec3& tri = topo.Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t from = tri[k], to = tri[(k + 1) % 3];
      const HalfEdge half = from < to ? HalfEdge{ from, to, t, +1 } : HalfEdge{ to, from, t, -1 };
      halfEdges[next[half.A]++] = half;
    }
  }
  for (std::size_t v = 0; v + 1 < groupStart.size(); ++v)
  {
    std::sort(halfEdges.begin() + groupStart[v], halfEdges.begin() + groupStart[v + 1],
      [](const HalfEdge& l, const HalfEdge& r)
      { return l.B != r.B ? l.B < r.B : l.Triangle < r.Triangle; });
  }

  topo.Uses.reserve(halfEdges.size());
  topo.Edges.reserve(halfEdges.size() / 2 + 1); // about two uses an edge
  TopologyReport& report = topo.Report;
  for (std::size_t i = 0; i < halfEdges.size();)
  {
    std::size_t j = i;
    Edge edge{ halfEdges[i].A, halfEdges[i].B, static_cast<std::uint32_t>(topo.Uses.size()), 0,
      EdgeKind::Boundary };
    for (; j < halfEdges.size() && halfEdges[j].A == edge.A && halfEdges[j].B == edge.B; ++j)
    {
      topo.Uses.push_back({ halfEdges[j].Triangle, halfEdges[j].Sign });
    }
    edge.UseCount = static_cast<std::uint32_t>(j - i);
    if (edge.UseCount == 1)
    {
      edge.Kind = EdgeKind::Boundary;
      ++report.BoundaryEdges;
    }
    else if (edge.UseCount == 2)
    {
      const bool opposite = topo.Uses[edge.FirstUse].Sign != topo.Uses[edge.FirstUse + 1].Sign;
      edge.Kind = opposite ? EdgeKind::Manifold : EdgeKind::Inconsistent;
      report.InconsistentEdges += opposite ? 0 : 1;
    }
    else
    {
      edge.Kind = EdgeKind::NonManifold;
      ++report.NonManifoldEdges;
    }
    topo.Edges.push_back(edge);
    i = j;
  }
  topo.ClosedAndOriented = !topo.Edges.empty() && report.BoundaryEdges == 0 &&
    report.InconsistentEdges == 0 && report.NonManifoldEdges == 0;
}

/// Appends the triangles of `triangles` whose points `map` sends to three distinct finite
/// points of topo.Points, counting the others in `report`.
void AddTriangles(const std::vector<glm::uvec3>& triangles, const std::vector<std::uint32_t>& map,
  CasterTopology& topo, TopologyReport& report)
{
  topo.Triangles.reserve(triangles.size());
  for (const glm::uvec3& tri : triangles)
  {
    // Out-of-range indices (malformed input) are dropped and reported apart from NaN points.
    if (tri.x >= map.size() || tri.y >= map.size() || tri.z >= map.size())
    {
      ++report.InvalidIndexTriangles;
      continue;
    }
    if (map[tri.x] == InvalidIndex || map[tri.y] == InvalidIndex || map[tri.z] == InvalidIndex)
    {
      ++report.NonFiniteTriangles;
      continue;
    }
    const glm::uvec3 w(map[tri.x], map[tri.y], map[tri.z]);
    const glm::dvec3 e1 = topo.Points[w.y] - topo.Points[w.x];
    const glm::dvec3 e2 = topo.Points[w.z] - topo.Points[w.x];
    const glm::dvec3 n = glm::cross(e1, e2);
    // Zero-area triangles occlude nothing and have no facing; relative test keeps slivers.
    // Written as !(area > ...) so that a NaN normal (inf - inf in the cross product of points
    // near 1e300) counts as degenerate instead of passing every comparison.
    const double scale = std::max(glm::dot(e1, e1), glm::dot(e2, e2));
    if (w.x == w.y || w.y == w.z || w.z == w.x || !(glm::dot(n, n) > 1e-28 * scale * scale))
    {
      ++report.DegenerateTriangles;
      continue;
    }
    topo.Triangles.push_back(w);
  }
}

/// The points in double, read straight from float or double storage.
void ReadPoints(vtkPoints* pts, std::vector<glm::dvec3>& points)
{
  const std::size_t count = static_cast<std::size_t>(pts->GetNumberOfPoints());
  points.resize(count);
  vtkDataArray* data = pts->GetData();
  if (auto floats = vtkFloatArray::FastDownCast(data))
  {
    const float* p = floats->GetPointer(0);
    for (std::size_t i = 0; i < count; ++i, p += 3)
    {
      points[i] = glm::dvec3(p[0], p[1], p[2]);
    }
  }
  else if (auto doubles = vtkDoubleArray::FastDownCast(data))
  {
    std::copy_n(reinterpret_cast<const glm::dvec3*>(doubles->GetPointer(0)), count, points.begin());
  }
  else
  {
    for (std::size_t i = 0; i < count; ++i)
    {
      pts->GetPoint(static_cast<vtkIdType>(i), &points[i].x);
    }
  }
}

/// The triangles of a triangles-only cell array's connectivity; a triangle naming a point that
/// does not exist is dropped (ids >= 2^32 would alias valid points once narrowed).
template <typename ConnectivityArray>
void ReadTriangles(ConnectivityArray* connectivity, vtkIdType pointCount,
  std::vector<glm::uvec3>& triangles, TopologyReport& report)
{
  const auto* ids = connectivity->GetPointer(0);
  const vtkIdType count = connectivity->GetNumberOfValues() / 3;
  triangles.reserve(triangles.size() + static_cast<std::size_t>(count));
  for (vtkIdType t = 0; t < count; ++t, ids += 3)
  {
    const vtkIdType a = ids[0], b = ids[1], c = ids[2];
    if (a < 0 || b < 0 || c < 0 || a >= pointCount || b >= pointCount || c >= pointCount)
    {
      ++report.InvalidIndexTriangles;
      continue;
    }
    triangles.emplace_back(a, b, c);
  }
}

/// Keeps the points that `map` sends to themselves (finite, not welded into another), in
/// order, and renumbers the triangles (already in mapped indices) to match.
void KeepRepresentatives(CasterTopology& topo, const std::vector<std::uint32_t>& map)
{
  std::vector<std::uint32_t> renumber(topo.Points.size(), InvalidIndex);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < topo.Points.size(); ++i)
  {
    if (map[i] == i)
    {
      renumber[i] = static_cast<std::uint32_t>(kept);
      topo.Points[kept++] = topo.Points[i];
    }
  }
  topo.Points.resize(kept);
  for (glm::uvec3& tri : topo.Triangles)
  {
    tri = glm::uvec3(renumber[tri.x], renumber[tri.y], renumber[tri.z]);
  }
}

/// Welds the ends of topo's boundary edges closer than `tolerance`; when any merge, builds the
/// triangles and edges again (counting the merged points in `report`).
void WeldSeams(CasterTopology& topo, double tolerance, TopologyReport& report)
{
  std::vector<std::uint32_t> seamPoints;
  std::vector<char> isSeam(topo.Points.size(), 0);
  for (const Edge& edge : topo.Edges)
  {
    if (edge.Kind != EdgeKind::Boundary)
    {
      continue;
    }
    for (const std::uint32_t end : { edge.A, edge.B })
    {
      if (!isSeam[end])
      {
        isSeam[end] = 1;
        seamPoints.push_back(end);
      }
    }
  }
  std::vector<glm::dvec3> seamPositions(seamPoints.size()), welded;
  for (std::size_t i = 0; i < seamPoints.size(); ++i)
  {
    seamPositions[i] = topo.Points[seamPoints[i]];
  }
  const std::vector<std::uint32_t> seamMap = WeldPoints(seamPositions, tolerance, welded);
  if (welded.size() == seamPoints.size())
  {
    return;
  }
  // Each seam point becomes the first seam point of its weld group.
  std::vector<std::uint32_t> map(topo.Points.size());
  for (std::size_t i = 0; i < map.size(); ++i)
  {
    map[i] = static_cast<std::uint32_t>(i);
  }
  std::vector<std::uint32_t> first(welded.size(), InvalidIndex);
  for (std::size_t i = 0; i < seamPoints.size(); ++i)
  {
    std::uint32_t& group = first[seamMap[i]];
    group = group == InvalidIndex ? seamPoints[i] : group;
    map[seamPoints[i]] = group;
  }
  report.WeldedPoints += seamPoints.size() - welded.size();
  const std::vector<glm::uvec3> triangles = std::move(topo.Triangles);
  std::vector<glm::dvec3> points = std::move(topo.Points);
  const glm::dvec3 origin = topo.Origin;
  topo = CasterTopology();
  topo.Origin = origin;
  topo.Points = std::move(points);
  AddTriangles(triangles, map, topo, report); // merged corners make some degenerate
  KeepRepresentatives(topo, map);
  BuildEdges(topo);
}

CasterTopology BuildFromSoup(const std::vector<glm::dvec3>& points,
  const std::vector<glm::uvec3>& triangles, double relativeWeldTolerance, TopologyReport report)
{
  CasterTopology topo;
  report.InputPoints = points.size();
  // Cells the vtkPolyData path dropped for bad ids were counted there.
  report.InputTriangles = triangles.size() + report.InvalidIndexTriangles;

  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : points)
  {
    if (IsFinite(p))
    {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    else
    {
      ++report.NonFinitePoints;
    }
  }
  if (report.NonFinitePoints == points.size())
  {
    for (const glm::uvec3& tri : triangles)
    {
      const bool inRange = tri.x < points.size() && tri.y < points.size() && tri.z < points.size();
      ++(inRange ? report.NonFiniteTriangles : report.InvalidIndexTriangles);
    }
    topo.Report = report;
    return topo;
  }
  // Halves first: lo + hi overflows to Inf for points near the largest doubles, and an infinite
  // origin would drop every point as non-finite (and reach the renderer's matrices).
  topo.Origin = 0.5 * lo + 0.5 * hi;
  const double diagonal = glm::length(hi - lo);

  // Points are taken as they are indexed first. Only the ends of boundary edges can be seams
  // (coincident points that split a surface): those alone are welded, and the triangles and
  // edges built again if any merged. Data whose points are already shared (contour output, any
  // closed mesh) pays for no welding at all; a triangle soup welds every point, as before.
  topo.Points.resize(points.size());
  std::vector<std::uint32_t> map(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    topo.Points[i] = points[i] - topo.Origin;
    map[i] = IsFinite(topo.Points[i]) ? static_cast<std::uint32_t>(i) : InvalidIndex;
  }
  AddTriangles(triangles, map, topo, report);
  if (report.NonFinitePoints > 0)
  {
    KeepRepresentatives(topo, map); // no NaN or infinite point stays in the mesh
  }
  BuildEdges(topo);
  const double tolerance = relativeWeldTolerance * diagonal;
  if (topo.Report.BoundaryEdges > 0 && tolerance > 0.0)
  {
    WeldSeams(topo, tolerance, report);
  }
  report.BoundaryEdges = topo.Report.BoundaryEdges;
  report.InconsistentEdges = topo.Report.InconsistentEdges;
  report.NonManifoldEdges = topo.Report.NonManifoldEdges;

  if (!topo.Triangles.empty())
  {
    glm::dvec3 rlo(std::numeric_limits<double>::max()), rhi(-std::numeric_limits<double>::max());
    for (const glm::uvec3& tri : topo.Triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        rlo = glm::min(rlo, topo.Points[tri[k]]);
        rhi = glm::max(rhi, topo.Points[tri[k]]);
      }
    }
    topo.BoundsMin = rlo;
    topo.BoundsMax = rhi;
  }
  topo.Report = report;
  return topo;
}

} // namespace

std::string TopologyReport::Describe() const
{
  std::ostringstream os;
  if (this->SkippedVerts || this->SkippedLines)
  {
    os << "ignored " << this->SkippedVerts << " vertex and " << this->SkippedLines
       << " line cells (they cast no shadow); ";
  }
  if (this->NonFinitePoints)
  {
    os << this->NonFinitePoints << " points with NaN or infinite coordinates dropped with "
       << this->NonFiniteTriangles << " triangles; ";
  }
  if (this->InvalidIndexTriangles)
  {
    os << this->InvalidIndexTriangles << " triangles naming points that do not exist dropped; ";
  }
  if (this->DegenerateTriangles)
  {
    os << this->DegenerateTriangles << " degenerate (zero-area) triangles dropped; ";
  }
  std::string text = os.str();
  if (text.size() >= 2)
  {
    text.resize(text.size() - 2);
  }
  return text;
}

CasterTopology CasterTopology::Build(const std::vector<glm::dvec3>& points,
  const std::vector<glm::uvec3>& triangles, double relativeWeldTolerance)
{
  return BuildFromSoup(points, triangles, relativeWeldTolerance, TopologyReport());
}

CasterTopology CasterTopology::Build(vtkPolyData* input, double relativeWeldTolerance)
{
  TopologyReport report;
  std::vector<glm::dvec3> points;
  std::vector<glm::uvec3> triangles;
  if (input && input->GetPoints())
  {
    vtkPoints* pts = input->GetPoints();
    ReadPoints(pts, points);
    report.SkippedVerts = static_cast<std::size_t>(input->GetNumberOfVerts());
    report.SkippedLines = static_cast<std::size_t>(input->GetNumberOfLines());

    vtkNew<vtkPolygon> polygon;
    vtkNew<vtkIdList> local;
    vtkIdType npts;
    const vtkIdType* ids;
    // A malformed cell naming a point that does not exist would make vtkPolygon read past the
    // points, and ids >= 2^32 would alias valid points once narrowed: drop the whole cell.
    const vtkIdType pointCount = pts->GetNumberOfPoints();
    auto validIds = [&](vtkIdType count, const vtkIdType* cellIds)
    {
      const bool valid = std::all_of(cellIds, cellIds + count,
        [pointCount](vtkIdType id) { return id >= 0 && id < pointCount; });
      if (!valid)
      {
        report.InvalidIndexTriangles += static_cast<std::size_t>(std::max<vtkIdType>(count - 2, 0));
      }
      return valid;
    };
    vtkCellArray* cells = input->GetPolys();
    if (cells->IsHomogeneous() == 3)
    {
      // Triangles only (contour and flying-edges output): the connectivity read directly.
      if (cells->IsStorage64Bit())
      {
        ReadTriangles(cells->GetConnectivityArray64(), pointCount, triangles, report);
      }
      else
      {
        ReadTriangles(cells->GetConnectivityArray32(), pointCount, triangles, report);
      }
      cells = nullptr;
    }
    auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
    for (polys->GoToFirstCell(); cells && !polys->IsDoneWithTraversal(); polys->GoToNextCell())
    {
      polys->GetCurrentCell(npts, ids);
      if (validIds(npts, ids))
      {
        TriangulatePolygon(input, npts, ids, polygon, local, triangles);
      }
    }
    auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
    for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
    {
      strips->GetCurrentCell(npts, ids);
      if (validIds(npts, ids))
      {
        AppendStrip(npts, ids, triangles);
      }
    }
  }
  return BuildFromSoup(points, triangles, relativeWeldTolerance, report);
}

} // namespace penumbra
