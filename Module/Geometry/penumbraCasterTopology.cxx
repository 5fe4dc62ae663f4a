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
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
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

/// Empties `topo` but keeps the capacity of its arrays.
void ClearKeepingStorage(CasterTopology& topo)
{
  topo.Origin = topo.BoundsMin = topo.BoundsMax = glm::dvec3(0.0);
  topo.Points.clear();
  topo.Triangles.clear();
  topo.Edges.clear();
  topo.Uses.clear();
  topo.ClosedAndOriented = false;
  topo.Report = TopologyReport();
}

/// Sorts a vertex's few half-edges as integers (the other end, then the triangle): groups
/// average six entries, where std::sort's set-up costs more than the sort.
void InsertionSort(std::uint64_t* first, std::uint64_t* last)
{
  for (std::uint64_t* i = first + 1; i < last; ++i)
  {
    const std::uint64_t key = *i;
    std::uint64_t* j = i;
    for (; j > first && *(j - 1) > key; --j)
    {
      *j = *(j - 1);
    }
    *j = key;
  }
}

/// Whether the edge's uses, [first, first + count) of `uses`, make it boundary, manifold,
/// inconsistently wound or non-manifold.
EdgeKind ClassifyEdge(const EdgeUse* uses, std::uint32_t count)
{
  if (count == 1)
  {
    return EdgeKind::Boundary;
  }
  if (count == 2)
  {
    return uses[0].Sign != uses[1].Sign ? EdgeKind::Manifold : EdgeKind::Inconsistent;
  }
  return EdgeKind::NonManifold;
}

/// Values that every build overwrites: grows, never shrinks, never initialized (a vector's
/// resize would write each element once more before the build does).
template <typename T>
class ScratchArray
{
public:
  T* Get(std::size_t count)
  {
    if (count > this->Capacity)
    {
      this->Values.reset(new T[count]);
      this->Capacity = count;
    }
    return this->Values.get();
  }
  std::size_t GetBytes() const { return this->Capacity * sizeof(T); }

private:
  std::unique_ptr<T[]> Values;
  std::size_t Capacity = 0;
};

} // namespace

struct TopologyScratch
{
  std::vector<glm::dvec3> InputPoints;
  std::vector<glm::uvec3> InputTriangles;
  std::vector<std::uint32_t> PointMap;
  std::vector<std::uint32_t> GroupStart; ///< per point: its first half-edge
  ScratchArray<std::uint32_t> GroupFill;
  ScratchArray<std::uint32_t> EdgeStart; ///< per point: its first edge
  /// Half-edges grouped by their smaller end: the other end << 32 | triangle << 1 | reversed.
  ScratchArray<std::uint64_t> HalfEdges;
};

namespace
{

/// Groups topo's half-edges by their smaller end, with a counting sort: linear, and stable, so
/// each group stays in triangle order (a comparison sort of all of them cost most of a rebuild).
void GroupHalfEdges(TopologyScratch& scratch, const CasterTopology& topo)
{
  std::vector<std::uint32_t>& start = scratch.GroupStart;
  start.assign(topo.Points.size() + 1, 0);
  for (const glm::uvec3& tri : topo.Triangles)
  {
    ++start[std::min(tri.x, tri.y) + 1];
    ++start[std::min(tri.y, tri.z) + 1];
    ++start[std::min(tri.z, tri.x) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::uint32_t* fill = scratch.GroupFill.Get(topo.Points.size());
  std::copy(start.begin(), start.end() - 1, fill);
  std::uint64_t* halves = scratch.HalfEdges.Get(3 * topo.Triangles.size());
  for (std::uint32_t t = 0; t < topo.Triangles.size(); ++t)
  {
    const glm::uvec3& tri = topo.Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t from = tri[k], to = tri[(k + 1) % 3];
      const bool reversed = to < from;
      const std::uint32_t low = reversed ? to : from, high = reversed ? from : to;
      halves[fill[low]++] =
        std::uint64_t(high) << 32 | std::uint64_t(t) << 1 | std::uint64_t(reversed);
    }
  }
}

std::uint32_t OtherEnd(std::uint64_t half)
{
  return static_cast<std::uint32_t>(half >> 32);
}

/// Edges and uses from the grouped half-edges. Every half-edge is one use, at its own index, and
/// every point's edges start at a prefix sum of the edges before it: the points are independent
/// and run in parallel, and the result does not depend on how they were split.
void BuildEdges(TopologyScratch& scratch, CasterTopology& topo)
{
  GroupHalfEdges(scratch, topo);
  const std::vector<std::uint32_t>& start = scratch.GroupStart;
  const vtkIdType pointCount = static_cast<vtkIdType>(topo.Points.size());
  std::uint64_t* const halves = scratch.HalfEdges.Get(3 * topo.Triangles.size());
  std::uint32_t* const edgeStart = scratch.EdgeStart.Get(topo.Points.size() + 1);
  topo.Uses.resize(3 * topo.Triangles.size());
  vtkSMPTools::For(0, pointCount,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType a = begin; a < end; ++a)
      {
        InsertionSort(halves + start[a], halves + start[a + 1]);
        std::uint32_t edges = 0;
        for (std::uint32_t h = start[a]; h < start[a + 1]; ++h)
        {
          const std::uint32_t low = static_cast<std::uint32_t>(halves[h]);
          topo.Uses[h].Triangle = low >> 1;
          topo.Uses[h].Sign = (low & 1u) ? -1 : +1;
          edges += h == start[a] || OtherEnd(halves[h]) != OtherEnd(halves[h - 1]);
        }
        edgeStart[a + 1] = edges;
      }
    });
  edgeStart[0] = 0;
  std::partial_sum(edgeStart, edgeStart + pointCount + 1, edgeStart);

  topo.Edges.resize(edgeStart[pointCount]);
  std::atomic<std::size_t> boundary{ 0 }, inconsistent{ 0 }, nonManifold{ 0 };
  vtkSMPTools::For(0, pointCount,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::size_t counts[4] = { 0, 0, 0, 0 };
      for (vtkIdType a = begin; a < end; ++a)
      {
        Edge* edge = topo.Edges.data() + edgeStart[a];
        for (std::uint32_t h = start[a]; h < start[a + 1]; ++edge)
        {
          // Fields written in place: an Edge temporary went through the stack in 32-bit stores
          // reloaded as wider ones, a store-forwarding stall that took half the build.
          edge->A = static_cast<std::uint32_t>(a);
          edge->B = OtherEnd(halves[h]);
          edge->FirstUse = h;
          while (h < start[a + 1] && OtherEnd(halves[h]) == edge->B)
          {
            ++h;
          }
          edge->UseCount = h - edge->FirstUse;
          edge->Kind = ClassifyEdge(topo.Uses.data() + edge->FirstUse, edge->UseCount);
          ++counts[static_cast<int>(edge->Kind)];
        }
      }
      boundary += counts[static_cast<int>(EdgeKind::Boundary)];
      inconsistent += counts[static_cast<int>(EdgeKind::Inconsistent)];
      nonManifold += counts[static_cast<int>(EdgeKind::NonManifold)];
    });
  TopologyReport& report = topo.Report;
  report.BoundaryEdges = boundary;
  report.InconsistentEdges = inconsistent;
  report.NonManifoldEdges = nonManifold;
  topo.ClosedAndOriented = !topo.Edges.empty() && report.BoundaryEdges == 0 &&
    report.InconsistentEdges == 0 && report.NonManifoldEdges == 0;
}

/// Welds the ends of topo's boundary edges closer than `tolerance`; when any merge, builds the
/// triangles and edges again (counting the merged points in `report`).
void WeldSeams(
  TopologyScratch& scratch, CasterTopology& topo, double tolerance, TopologyReport& report)
{
  // Sorted rather than flagged: an array over all points would cost a full-size allocation on
  // every rebuild of an open mesh, where the boundary is a small part of it.
  std::vector<std::uint32_t> seamPoints;
  for (const Edge& edge : topo.Edges)
  {
    if (edge.Kind == EdgeKind::Boundary)
    {
      seamPoints.push_back(edge.A);
      seamPoints.push_back(edge.B);
    }
  }
  std::sort(seamPoints.begin(), seamPoints.end());
  seamPoints.erase(std::unique(seamPoints.begin(), seamPoints.end()), seamPoints.end());
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
  // Welding is rare (seams, soups): its copies are not worth keeping between builds.
  std::vector<glm::uvec3> triangles;
  triangles.swap(topo.Triangles);
  topo.Edges.clear();
  topo.Uses.clear();
  topo.Report = TopologyReport();
  AddTriangles(triangles, map, topo, report); // merged corners make some degenerate
  KeepRepresentatives(topo, map);
  BuildEdges(scratch, topo);
}

void BuildFromSoup(TopologyScratch& scratch, const std::vector<glm::dvec3>& points,
  const std::vector<glm::uvec3>& triangles, double relativeWeldTolerance, TopologyReport report,
  CasterTopology& topo)
{
  ClearKeepingStorage(topo);
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
    return;
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
  std::vector<std::uint32_t>& map = scratch.PointMap;
  map.resize(points.size());
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
  BuildEdges(scratch, topo);
  const double tolerance = relativeWeldTolerance * diagonal;
  if (topo.Report.BoundaryEdges > 0 && tolerance > 0.0)
  {
    WeldSeams(scratch, topo, tolerance, report);
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
  CasterTopology topology;
  TopologyBuilder().Build(points, triangles, topology, relativeWeldTolerance);
  return topology;
}

CasterTopology CasterTopology::Build(vtkPolyData* input, double relativeWeldTolerance)
{
  CasterTopology topology;
  TopologyBuilder().Build(input, topology, relativeWeldTolerance);
  return topology;
}

void TopologyBuilder::Build(const std::vector<glm::dvec3>& points,
  const std::vector<glm::uvec3>& triangles, CasterTopology& topology, double relativeWeldTolerance)
{
  BuildFromSoup(
    *this->Scratch, points, triangles, relativeWeldTolerance, TopologyReport(), topology);
}

void TopologyBuilder::Build(
  vtkPolyData* input, CasterTopology& topology, double relativeWeldTolerance)
{
  TopologyReport report;
  std::vector<glm::dvec3>& points = this->Scratch->InputPoints;
  std::vector<glm::uvec3>& triangles = this->Scratch->InputTriangles;
  points.clear();
  triangles.clear();
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
  BuildFromSoup(*this->Scratch, points, triangles, relativeWeldTolerance, report, topology);
}

TopologyBuilder::TopologyBuilder()
  : Scratch(new TopologyScratch)
{
}

TopologyBuilder::~TopologyBuilder() = default;

std::size_t TopologyBuilder::GetScratchBytes() const
{
  const TopologyScratch& scratch = *this->Scratch;
  return scratch.InputPoints.capacity() * sizeof(glm::dvec3) +
    scratch.InputTriangles.capacity() * sizeof(glm::uvec3) +
    (scratch.PointMap.capacity() + scratch.GroupStart.capacity()) * sizeof(std::uint32_t) +
    scratch.GroupFill.GetBytes() + scratch.EdgeStart.GetBytes() + scratch.HalfEdges.GetBytes();
}

} // namespace penumbra
