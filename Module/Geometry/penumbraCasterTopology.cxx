#include "penumbraCasterTopology.h"
#include "penumbraLargeArrays.h"

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

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <sstream>
#include <type_traits>
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

/// Runs body(chunk, begin, end) over [0, count) cut into ChunkCount(count) consecutive ranges,
/// in parallel (vtkSMPTools). The ranges do not depend on the threads, so per-chunk results
/// combined in chunk order give the same answer as one loop would.
std::size_t ChunkCount(std::size_t count)
{
  // Below a few thousand elements a chunk costs more to hand out than to run.
  return std::max<std::size_t>(1, std::min<std::size_t>(64, count / 16384));
}

/// The storage to allocate for `count` elements where `capacity` is too small: a first
/// allocation fits (static data keeps its mesh for good), a rebuild that outgrows its storage
/// gets a quarter more. Data played back grows by a few triangles now and then, and an exact
/// fit would move every array of the build to fresh pages each time, which on this kind of data
/// costs more than the build (PenumbraGeometryBench's "grown" column).
std::size_t GrownCapacity(std::size_t capacity, std::size_t count)
{
  return capacity > 0 ? count + count / 4 : count;
}

/// Resizes `values` to `count` elements, growing its storage by GrownCapacity, on huge pages
/// where it is large (ReserveLarge). What it held is not kept where the storage grows: every
/// build overwrites what it uses.
template <typename T>
void ResizeWithHeadroom(std::vector<T>& values, std::size_t count)
{
  if (count > values.capacity())
  {
    ReserveLarge(values, GrownCapacity(values.capacity(), count));
  }
  values.resize(count);
}

template <typename Body>
void ForEachChunk(std::size_t count, const Body& body)
{
  const std::size_t chunks = ChunkCount(count);
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks), 1,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType c = first; c < last; ++c)
      {
        const std::size_t chunk = static_cast<std::size_t>(c);
        body(chunk, count * chunk / chunks, count * (chunk + 1) / chunks);
      }
    });
}

/// An axis-aligned box being grown, and the points it left out.
struct Extent
{
  glm::dvec3 Lo{ std::numeric_limits<double>::max() };
  glm::dvec3 Hi{ -std::numeric_limits<double>::max() };
  std::size_t NonFinite = 0;

  void Add(const glm::dvec3& p)
  {
    if (IsFinite(p))
    {
      this->Lo = glm::min(this->Lo, p);
      this->Hi = glm::max(this->Hi, p);
    }
    else
    {
      ++this->NonFinite;
    }
  }
  void Add(const Extent& other)
  {
    this->Lo = glm::min(this->Lo, other.Lo);
    this->Hi = glm::max(this->Hi, other.Hi);
    this->NonFinite += other.NonFinite;
  }
};

/// The extent of get(i) over [0, count), in parallel.
template <typename Get>
Extent ExtentOf(std::size_t count, const Get& get)
{
  std::vector<Extent> parts(ChunkCount(count));
  ForEachChunk(count,
    [&](std::size_t chunk, std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        get(i, parts[chunk]);
      }
    });
  Extent all;
  for (const Extent& part : parts)
  {
    all.Add(part);
  }
  return all;
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

/// Whether the corners at `local` positions t, t + 1, t + 2 form a triangle of the fan from
/// corner 0 (0, k, k + 1), the triangles VTK's mapper draws a polygon as.
bool IsFanTriangle(vtkIdList* local, vtkIdType t)
{
  vtkIdType corners[3] = { local->GetId(t), local->GetId(t + 1), local->GetId(t + 2) };
  std::sort(corners, corners + 3);
  return corners[0] == 0 && corners[2] == corners[1] + 1;
}

/// Whether the polygon of `npts` corners `ids` turns the same way at every corner, seen along
/// its Newell normal (`corners` is scratch). VTK's fan from its first corner then covers it as
/// it is, planar or warped.
bool IsConvex(
  vtkPoints* points, vtkIdType npts, const vtkIdType* ids, std::vector<glm::dvec3>& corners)
{
  corners.resize(static_cast<std::size_t>(npts));
  for (vtkIdType k = 0; k < npts; ++k)
  {
    points->GetPoint(ids[k], glm::value_ptr(corners[static_cast<std::size_t>(k)]));
  }
  const std::size_t n = corners.size();
  glm::dvec3 normal(0.0);
  for (std::size_t k = 1; k + 1 < n; ++k)
  {
    normal += glm::cross(corners[k] - corners[0], corners[k + 1] - corners[0]);
  }
  if (!(glm::dot(normal, normal) > 0.0))
  {
    return false; // no area, or not finite
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    const glm::dvec3& a = corners[k];
    const glm::dvec3& b = corners[(k + 1) % n];
    const glm::dvec3& c = corners[(k + 2) % n];
    // Not finite or turning back: left to the ear cut. A straight corner (collinear) is fine.
    if (!(glm::dot(glm::cross(b - a, c - b), normal) >= 0.0))
    {
      return false;
    }
  }
  return true;
}

/// Appends the triangles of one polygon: the fan from its first corner, as VTK's mapper draws
/// it, where the polygon is convex (IsConvex), else ear-cut. Returns whether they are that fan:
/// only then is the depth of the cut the depth VTK draws.
bool TriangulatePolygon(vtkPolyData* input, vtkIdType npts, const vtkIdType* ids,
  vtkPolygon* polygon, vtkIdList* local, std::vector<glm::dvec3>& corners,
  std::vector<glm::uvec3>& triangles)
{
  if (npts < 3)
  {
    return true;
  }
  if (npts == 3)
  {
    triangles.emplace_back(ids[0], ids[1], ids[2]);
    return true;
  }
  if (IsConvex(input->GetPoints(), npts, ids, corners))
  {
    for (vtkIdType k = 1; k + 1 < npts; ++k)
    {
      triangles.emplace_back(ids[0], ids[k], ids[k + 1]);
    }
    return true;
  }
  polygon->Initialize(static_cast<int>(npts), ids, input->GetPoints());
  local->Reset();
  if (polygon->Triangulate(local) && local->GetNumberOfIds() == 3 * (npts - 2))
  {
    bool fan = true;
    for (vtkIdType t = 0; t + 2 < local->GetNumberOfIds(); t += 3)
    {
      triangles.emplace_back(
        ids[local->GetId(t)], ids[local->GetId(t + 1)], ids[local->GetId(t + 2)]);
      fan = fan && IsFanTriangle(local, t);
    }
    return fan;
  }
  // Ear cutting gives up on degenerate polygons: a fan still covers what they cover.
  for (vtkIdType k = 1; k + 1 < npts; ++k)
  {
    triangles.emplace_back(ids[0], ids[k], ids[k + 1]);
  }
  return true;
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

/// Zero-area triangles occlude nothing and have no facing; the relative test keeps slivers.
/// Written as !(area > ...) so that a NaN normal (inf - inf in the cross product of points near
/// 1e300) counts as degenerate instead of passing every comparison.
bool IsDegenerate(const std::vector<glm::dvec3>& points, const glm::uvec3& tri)
{
  const glm::dvec3 e1 = points[tri.y] - points[tri.x];
  const glm::dvec3 e2 = points[tri.z] - points[tri.x];
  const glm::dvec3 n = glm::cross(e1, e2);
  const double scale = std::max(glm::dot(e1, e1), glm::dot(e2, e2));
  return tri.x == tri.y || tri.y == tri.z || tri.z == tri.x ||
    !(glm::dot(n, n) > 1e-28 * scale * scale);
}

/// What AddTriangles does with one triangle.
enum class TriangleFate : std::uint8_t
{
  Kept,
  InvalidIndex,
  NonFinite,
  Degenerate
};

/// Appends the triangles of `triangles` whose points `map` sends to three distinct finite
/// points of topo.Points, counting the others in `report`. Two parallel passes over chunks: each
/// triangle's fate into `fates`, then the kept ones written at their chunk's offset, in order.
template <typename Triangles>
void AddTriangles(const Triangles& triangles, const std::vector<std::uint32_t>& map,
  TriangleFate* fates, CasterTopology& topo, TopologyReport& report)
{
  auto mapped = [&](std::size_t t, glm::uvec3& w)
  {
    const glm::uvec3 tri = triangles[t];
    // Out-of-range indices (malformed input) are dropped and reported apart from NaN points.
    if (tri.x >= map.size() || tri.y >= map.size() || tri.z >= map.size())
    {
      return TriangleFate::InvalidIndex;
    }
    w = glm::uvec3(map[tri.x], map[tri.y], map[tri.z]);
    if (w.x == InvalidIndex || w.y == InvalidIndex || w.z == InvalidIndex)
    {
      return TriangleFate::NonFinite;
    }
    return IsDegenerate(topo.Points, w) ? TriangleFate::Degenerate : TriangleFate::Kept;
  };
  const std::size_t chunks = ChunkCount(triangles.size());
  std::vector<std::array<std::size_t, 4>> counts(chunks);
  ForEachChunk(triangles.size(),
    [&](std::size_t chunk, std::size_t begin, std::size_t end)
    {
      std::array<std::size_t, 4> count = { 0, 0, 0, 0 };
      glm::uvec3 w;
      for (std::size_t t = begin; t < end; ++t)
      {
        fates[t] = mapped(t, w);
        ++count[static_cast<int>(fates[t])];
      }
      counts[chunk] = count;
    });
  std::vector<std::size_t> offsets(chunks + 1, 0);
  for (std::size_t c = 0; c < chunks; ++c)
  {
    offsets[c + 1] = offsets[c] + counts[c][static_cast<int>(TriangleFate::Kept)];
    report.InvalidIndexTriangles += counts[c][static_cast<int>(TriangleFate::InvalidIndex)];
    report.NonFiniteTriangles += counts[c][static_cast<int>(TriangleFate::NonFinite)];
    report.DegenerateTriangles += counts[c][static_cast<int>(TriangleFate::Degenerate)];
  }
  ResizeWithHeadroom(topo.Triangles, offsets[chunks]);
  ForEachChunk(triangles.size(),
    [&](std::size_t chunk, std::size_t begin, std::size_t end)
    {
      glm::uvec3* out = topo.Triangles.data() + offsets[chunk];
      for (std::size_t t = begin; t < end; ++t)
      {
        if (fates[t] == TriangleFate::Kept)
        {
          const glm::uvec3 tri = triangles[t];
          *out++ = glm::uvec3(map[tri.x], map[tri.y], map[tri.z]);
        }
      }
    });
}

/// Sends topo's triangles through `map` (welded points) in place, dropping those that become
/// degenerate.
void RemapTriangles(
  CasterTopology& topo, const std::vector<std::uint32_t>& map, TopologyReport& report)
{
  std::size_t kept = 0;
  for (const glm::uvec3& tri : topo.Triangles)
  {
    const glm::uvec3 w(map[tri.x], map[tri.y], map[tri.z]);
    if (IsDegenerate(topo.Points, w))
    {
      ++report.DegenerateTriangles;
      continue;
    }
    topo.Triangles[kept++] = w;
  }
  topo.Triangles.resize(kept);
}

/// A vtkPoints' float or double storage, read in place as doubles: a copy would cost as many
/// fresh pages as the points themselves.
template <typename Real>
struct StoredPoints
{
  const Real* Values;
  std::size_t Count;

  std::size_t size() const { return this->Count; }
  glm::dvec3 operator[](std::size_t i) const
  {
    const Real* p = this->Values + 3 * i;
    return glm::dvec3(p[0], p[1], p[2]);
  }
};

/// A triangles-only cell array's connectivity, read in place. A triangle naming a point that
/// does not exist reads as InvalidIndex corners, which AddTriangles drops and reports (ids >=
/// 2^32 would alias valid points once narrowed).
template <typename Id>
struct StoredTriangles
{
  const Id* Ids;
  std::size_t Count;
  vtkIdType PointCount;

  std::size_t size() const { return this->Count; }
  glm::uvec3 operator[](std::size_t t) const
  {
    const Id* ids = this->Ids + 3 * t;
    const bool valid = std::all_of(ids, ids + 3,
      [this](Id id) { return id >= 0 && static_cast<vtkIdType>(id) < this->PointCount; });
    return valid ? glm::uvec3(ids[0], ids[1], ids[2]) : glm::uvec3(InvalidIndex);
  }
};

template <typename ConnectivityArray>
StoredTriangles<typename ConnectivityArray::ValueType> TrianglesOf(
  ConnectivityArray* connectivity, vtkIdType pointCount)
{
  return { connectivity->GetPointer(0),
    static_cast<std::size_t>(connectivity->GetNumberOfValues() / 3), pointCount };
}

/// Calls `use` with the triangles of a triangles-only cell array, read in place from its 32- or
/// 64-bit connectivity.
template <typename Use>
void WithStoredTriangles(vtkCellArray* triangles, vtkIdType pointCount, const Use& use)
{
  if (triangles->IsStorage64Bit())
  {
    use(TrianglesOf(triangles->GetConnectivityArray64(), pointCount));
  }
  else
  {
    use(TrianglesOf(triangles->GetConnectivityArray32(), pointCount));
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

/// Resets `topo`'s origin, bounds and report. Its arrays keep their size and storage: each
/// step of a build resizes the array it writes, which initializes only the elements beyond the
/// last build's (emptied first, every element would be written twice: a tenth of a rebuild).
void ResetSummary(CasterTopology& topo)
{
  topo.Origin = topo.BoundsMin = topo.BoundsMax = glm::dvec3(0.0);
  topo.ClosedAndOriented = false;
  topo.Report = TopologyReport();
}

/// Empties `topo` but keeps the capacity of its arrays.
void ClearKeepingStorage(CasterTopology& topo)
{
  ResetSummary(topo);
  topo.Points.clear();
  topo.Triangles.clear();
  topo.Edges.clear();
  topo.Uses.clear();
}

// While the edges are built, each use's slot holds its half-edge as one 64-bit key: the other
// end << 32 | triangle << 1 | reversed. Sorting a vertex's keys as integers orders its edges
// by their other end, and the keys need no storage of their own (24 bytes a triangle, fresh
// pages that cost more than the build itself at millions of triangles). Accessed through
// memcpy, which compiles to one move and keeps the aliasing rules.
static_assert(
  sizeof(EdgeUse) == sizeof(std::uint64_t) && std::is_trivially_copyable<EdgeUse>::value,
  "an edge use's slot holds a 64-bit half-edge key during the build");

std::uint64_t LoadKey(const EdgeUse& slot)
{
  std::uint64_t key;
  std::memcpy(&key, &slot, sizeof(key));
  return key;
}

void StoreKey(EdgeUse& slot, std::uint64_t key)
{
  std::memcpy(&slot, &key, sizeof(key));
}

std::uint32_t OtherEnd(std::uint64_t key)
{
  return static_cast<std::uint32_t>(key >> 32);
}

/// Sorts a vertex's keys: by insertion for the usual few (six on average, where std::sort's
/// set-up costs more than the sort), by std::sort for a hub (a large fan), which insertion would
/// take quadratic time over.
void SortKeys(EdgeUse* first, EdgeUse* last)
{
  if (last - first < 2)
  {
    return; // also keeps first + 1 off a null pointer when there are no uses at all
  }
  if (last - first > 32)
  {
    std::vector<std::uint64_t> keys(static_cast<std::size_t>(last - first));
    std::transform(first, last, keys.begin(), LoadKey);
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size(); ++i)
    {
      StoreKey(first[i], keys[i]);
    }
    return;
  }
  for (EdgeUse* i = first + 1; i < last; ++i)
  {
    const std::uint64_t key = LoadKey(*i);
    EdgeUse* j = i;
    for (; j > first && LoadKey(*(j - 1)) > key; --j)
    {
      *j = *(j - 1);
    }
    StoreKey(*j, key);
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

/// Values that every build overwrites: grows (by GrownCapacity), never shrinks, never
/// initialized (a vector's resize would write each element once more before the build does).
template <typename T>
class ScratchArray
{
public:
  T* Get(std::size_t count)
  {
    if (count > this->Capacity)
    {
      this->Capacity = GrownCapacity(this->Capacity, count);
      this->Values.reset(); // freed first: its values are not kept
      this->Values.reset(new T[this->Capacity]);
      AdviseHugePages(this->Values.get(), this->GetBytes());
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
  ScratchArray<std::uint32_t> GroupFill; ///< per part of the triangles and point (GroupHalfEdges)
  ScratchArray<std::uint32_t> EdgeStart; ///< per point: its first edge
  ScratchArray<TriangleFate> TriangleFates;         ///< per input triangle: AddTriangles' verdict
  std::array<std::vector<double>, 3> OriginSamples; ///< per axis: coordinates MeshOrigin sorts
};

namespace
{

/// Groups topo's half-edges by their smaller end into topo.Uses, as keys, with a counting sort:
/// linear, and stable, so each group stays in triangle order (a comparison sort of all of them
/// cost most of a rebuild). The triangles are cut into a few consecutive parts, each counted
/// and scattered in parallel into its own share of every group: part p's keys of a group follow
/// parts 0 .. p - 1's, so the order is the triangles' whatever the parts.
void GroupHalfEdges(TopologyScratch& scratch, CasterTopology& topo)
{
  const std::size_t pointCount = topo.Points.size(), triangleCount = topo.Triangles.size();
  // A histogram a part: a few parts only, or their memory would outgrow the mesh's.
  const std::size_t parts = std::min<std::size_t>({ ChunkCount(triangleCount), 4,
    static_cast<std::size_t>(std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads())) });
  auto partBegin = [&](std::size_t part) { return triangleCount * part / parts; };
  auto lowEnd = [&](std::uint32_t t, int k)
  {
    const glm::uvec3& tri = topo.Triangles[t];
    return std::min(tri[k], tri[(k + 1) % 3]);
  };
  // counts[part * pointCount + a]: part's half-edges whose smaller end is a; then, in place,
  // where part's next key of group a goes.
  std::uint32_t* counts = scratch.GroupFill.Get(parts * pointCount);
  vtkSMPTools::For(0, static_cast<vtkIdType>(parts), 1,
    [&](vtkIdType first, vtkIdType last)
    {
      for (std::size_t part = first; part < static_cast<std::size_t>(last); ++part)
      {
        std::uint32_t* count = counts + part * pointCount;
        std::fill(count, count + pointCount, 0u);
        for (std::uint32_t t = partBegin(part); t < partBegin(part + 1); ++t)
        {
          ++count[lowEnd(t, 0)];
          ++count[lowEnd(t, 1)];
          ++count[lowEnd(t, 2)];
        }
      }
    });
  std::vector<std::uint32_t>& start = scratch.GroupStart;
  ResizeWithHeadroom(start, pointCount + 1);
  start[0] = 0;
  for (std::size_t a = 0; a < pointCount; ++a)
  {
    std::uint32_t next = start[a];
    for (std::size_t part = 0; part < parts; ++part)
    {
      const std::uint32_t count = counts[part * pointCount + a];
      counts[part * pointCount + a] = next;
      next += count;
    }
    start[a + 1] = next;
  }
  ResizeWithHeadroom(topo.Uses, 3 * triangleCount);
  vtkSMPTools::For(0, static_cast<vtkIdType>(parts), 1,
    [&](vtkIdType first, vtkIdType last)
    {
      for (std::size_t part = first; part < static_cast<std::size_t>(last); ++part)
      {
        std::uint32_t* fill = counts + part * pointCount;
        for (std::uint32_t t = partBegin(part); t < partBegin(part + 1); ++t)
        {
          const glm::uvec3& tri = topo.Triangles[t];
          for (int k = 0; k < 3; ++k)
          {
            const std::uint32_t from = tri[k], to = tri[(k + 1) % 3];
            const bool reversed = to < from;
            const std::uint32_t low = reversed ? to : from, high = reversed ? from : to;
            StoreKey(topo.Uses[fill[low]++],
              std::uint64_t(high) << 32 | std::uint64_t(t) << 1 | std::uint64_t(reversed));
          }
        }
      }
    });
}

/// Edges and uses from the grouped keys. Every half-edge is one use, in its own slot, and every
/// point's edges start at a prefix sum of the edges before it: the points are independent and
/// run in parallel, and the result does not depend on how they were split.
void BuildEdges(TopologyScratch& scratch, CasterTopology& topo)
{
  topo.Report.BoundaryEdges = topo.Report.InconsistentEdges = topo.Report.NonManifoldEdges = 0;
  topo.ClosedAndOriented = false;
  if (topo.Triangles.empty())
  {
    topo.Edges.clear();
    topo.Uses.clear();
    return;
  }
  GroupHalfEdges(scratch, topo);
  const std::vector<std::uint32_t>& start = scratch.GroupStart;
  const vtkIdType pointCount = static_cast<vtkIdType>(topo.Points.size());
  EdgeUse* const slots = topo.Uses.data();
  std::uint32_t* const edgeStart = scratch.EdgeStart.Get(topo.Points.size() + 1);
  vtkSMPTools::For(0, pointCount,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType a = begin; a < end; ++a)
      {
        SortKeys(slots + start[a], slots + start[a + 1]);
        std::uint32_t edges = 0;
        for (std::uint32_t h = start[a]; h < start[a + 1]; ++h)
        {
          edges += h == start[a] || OtherEnd(LoadKey(slots[h])) != OtherEnd(LoadKey(slots[h - 1]));
        }
        edgeStart[a + 1] = edges;
      }
    });
  edgeStart[0] = 0;
  std::partial_sum(edgeStart, edgeStart + pointCount + 1, edgeStart);

  ResizeWithHeadroom(topo.Edges, edgeStart[pointCount]);
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
          edge->B = OtherEnd(LoadKey(slots[h]));
          edge->FirstUse = h;
          for (; h < start[a + 1]; ++h)
          {
            const std::uint64_t key = LoadKey(slots[h]);
            if (OtherEnd(key) != edge->B)
            {
              break;
            }
            const std::uint32_t low = static_cast<std::uint32_t>(key);
            slots[h].Triangle = low >> 1;
            slots[h].Sign = (low & 1u) ? -1 : +1;
          }
          edge->UseCount = h - edge->FirstUse;
          edge->Kind = ClassifyEdge(slots + edge->FirstUse, edge->UseCount);
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
  RemapTriangles(topo, map, report); // merged corners make some degenerate
  KeepRepresentatives(topo, map);
  BuildEdges(scratch, topo);
}

/**
 * The bounds' centre, except along an axis where the middle 90% of the mesh's points span less
 * than a tenth of the bounds (of up to 1,024 of its finite points, taken evenly through them):
 * there, the centre of that middle span. Points are stored, and later uploaded as floats,
 * relative to it, so that float coordinates keep their precision where most of the surface is.
 * A stray vertex 1,000 units off would otherwise move the origin 500 units from the rest, where
 * float steps are 6e-5 and volumes and wedges drawn from them disagree at shadow boundaries.
 * Only the bounds' centre where their size is not finite, so that no point relative to it
 * overflows.
 */
template <typename Points>
glm::dvec3 MeshOrigin(const Points& points, const glm::dvec3& lo, const glm::dvec3& hi,
  std::array<std::vector<double>, 3>& samples)
{
  glm::dvec3 origin = 0.5 * lo + 0.5 * hi; // halves first: lo + hi may overflow
  if (!IsFinite(hi - lo))
  {
    return origin;
  }
  const std::size_t stride = std::max<std::size_t>(1, points.size() / 1024);
  for (std::vector<double>& axis : samples)
  {
    axis.clear();
  }
  for (std::size_t i = 0; i < points.size(); i += stride)
  {
    const glm::dvec3 p = points[i];
    if (IsFinite(p))
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        samples[axis].push_back(p[axis]);
      }
    }
  }
  for (int axis = 0; axis < 3 && !samples[axis].empty(); ++axis)
  {
    std::vector<double>& values = samples[axis];
    const auto at = [&](double share)
    {
      const auto nth = values.begin() + static_cast<std::ptrdiff_t>(share * (values.size() - 1));
      std::nth_element(values.begin(), nth, values.end());
      return *nth;
    };
    const double low = at(0.05), high = at(0.95);
    if (high - low < 0.1 * (hi[axis] - lo[axis]))
    {
      origin[axis] = 0.5 * low + 0.5 * high;
    }
  }
  return origin;
}

/// The build from any indexable points (glm::dvec3) and triangles (glm::uvec3).
template <typename Points, typename Triangles>
void BuildFromSoup(TopologyScratch& scratch, const Points& points, const Triangles& triangles,
  double relativeWeldTolerance, TopologyReport report, CasterTopology& topo)
{
  ResetSummary(topo);
  report.InputPoints = points.size();
  // Cells the vtkPolyData path dropped for bad ids were counted there.
  report.InputTriangles = triangles.size() + report.InvalidIndexTriangles;

  const Extent input =
    ExtentOf(points.size(), [&](std::size_t i, Extent& part) { part.Add(points[i]); });
  const glm::dvec3 lo = input.Lo, hi = input.Hi;
  report.NonFinitePoints = input.NonFinite;
  if (report.NonFinitePoints == points.size())
  {
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      const glm::uvec3 tri = triangles[t];
      const bool inRange = tri.x < points.size() && tri.y < points.size() && tri.z < points.size();
      ++(inRange ? report.NonFiniteTriangles : report.InvalidIndexTriangles);
    }
    ClearKeepingStorage(topo);
    topo.Report = report;
    return;
  }
  topo.Origin = MeshOrigin(points, lo, hi, scratch.OriginSamples);
  const double diagonal = glm::length(hi - lo);

  // Points are taken as they are indexed first. Only the ends of boundary edges can be seams
  // (coincident points that split a surface): those alone are welded, and the triangles and
  // edges built again if any merged. Data whose points are already shared (contour output, any
  // closed mesh) pays for no welding at all; a triangle soup welds every point, as before.
  ResizeWithHeadroom(topo.Points, points.size());
  std::vector<std::uint32_t>& map = scratch.PointMap;
  ResizeWithHeadroom(map, points.size());
  const glm::dvec3 origin = topo.Origin;
  ForEachChunk(points.size(),
    [&](std::size_t, std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        topo.Points[i] = points[i] - origin;
        map[i] = IsFinite(topo.Points[i]) ? static_cast<std::uint32_t>(i) : InvalidIndex;
      }
    });
  AddTriangles(triangles, map, scratch.TriangleFates.Get(triangles.size()), topo, report);
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
    const Extent used = ExtentOf(topo.Triangles.size(),
      [&](std::size_t t, Extent& part)
      {
        for (int k = 0; k < 3; ++k)
        {
          part.Add(topo.Points[topo.Triangles[t][k]]);
        }
      });
    topo.BoundsMin = used.Lo;
    topo.BoundsMax = used.Hi;
  }
  topo.Report = report;
}

/// Appends the triangles of `input`'s polygons (TriangulatePolygon: VTK's fan where convex, else
/// ear-cut) and strips.
void TriangulateCells(
  vtkPolyData* input, std::vector<glm::uvec3>& triangles, TopologyReport& report)
{
  const vtkIdType pointCount = input->GetNumberOfPoints();
  // A malformed cell naming a point that does not exist would make vtkPolygon read past the
  // points, and ids >= 2^32 would alias valid points once narrowed: drop the whole cell.
  auto validIds = [&](vtkIdType count, const vtkIdType* cellIds)
  {
    const bool valid = std::all_of(
      cellIds, cellIds + count, [pointCount](vtkIdType id) { return id >= 0 && id < pointCount; });
    if (!valid)
    {
      report.InvalidIndexTriangles += static_cast<std::size_t>(std::max<vtkIdType>(count - 2, 0));
    }
    return valid;
  };
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> local;
  std::vector<glm::dvec3> corners;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* polys = input->GetPolys();
  if (polys->IsHomogeneous() == 3)
  {
    WithStoredTriangles(polys, pointCount,
      [&](const auto& stored)
      {
        for (std::size_t t = 0; t < stored.size(); ++t)
        {
          triangles.push_back(stored[t]);
        }
      });
  }
  else
  {
    auto cells = vtk::TakeSmartPointer(polys->NewIterator());
    for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
    {
      cells->GetCurrentCell(npts, ids);
      if (validIds(npts, ids))
      {
        if (!TriangulatePolygon(input, npts, ids, polygon, local, corners, triangles))
        {
          ++report.PolygonsCutUnlikeVTK;
        }
      }
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

/// Calls `build` with the points of `pts`, read in place from float or double storage and
/// copied into `copy` otherwise.
template <typename Build>
void WithPoints(vtkPoints* pts, std::vector<glm::dvec3>& copy, const Build& build)
{
  const std::size_t count = static_cast<std::size_t>(pts->GetNumberOfPoints());
  vtkDataArray* data = pts->GetData();
  if (auto floats = vtkFloatArray::FastDownCast(data))
  {
    build(StoredPoints<float>{ floats->GetPointer(0), count });
  }
  else if (auto doubles = vtkDoubleArray::FastDownCast(data))
  {
    build(StoredPoints<double>{ doubles->GetPointer(0), count });
  }
  else
  {
    copy.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
      pts->GetPoint(static_cast<vtkIdType>(i), &copy[i].x);
    }
    build(copy);
  }
}

} // namespace

std::string TopologyReport::Describe(bool withDegenerate) const
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
  if (this->DegenerateTriangles && withDegenerate)
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

int CasterTopology::OutwardWinding() const
{
  if (!this->ClosedAndOriented)
  {
    return 0;
  }
  // Connected pieces: union-find over the triangles, joined across each (manifold) edge. A
  // root is its piece's first triangle, as a union points the later root at the earlier one, so
  // parent[t] <= t throughout. Data that changes asks for this on every rebuild: its storage
  // is asked for huge pages (four bytes a triangle, written at once).
  const std::size_t triangleCount = this->Triangles.size();
  std::vector<std::uint32_t> parent;
  ReserveLarge(parent, triangleCount);
  parent.resize(triangleCount);
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&parent](std::uint32_t t)
  {
    while (parent[t] != t)
    {
      parent[t] = parent[parent[t]];
      t = parent[t];
    }
    return t;
  };
  for (const Edge& edge : this->Edges)
  {
    const std::uint32_t a = root(this->Uses[edge.FirstUse].Triangle),
                        b = root(this->Uses[edge.FirstUse + 1].Triangle);
    parent[std::max(a, b)] = std::min(a, b);
  }
  // Each triangle's piece, numbered in the order of their first triangles, in place: parent[t]
  // is an earlier triangle, already relabelled with its piece.
  std::uint32_t pieces = 0;
  for (std::uint32_t t = 0; t < triangleCount; ++t)
  {
    parent[t] = parent[t] == t ? pieces++ : parent[parent[t]];
  }
  // Six times each piece's signed volume, relative to the origin (the bounds' centre), and the
  // size of its terms: a volume lost in their rounding is flat, with no outside to tell.
  std::vector<double> volume(pieces, 0.0), terms(pieces, 0.0);
  for (std::uint32_t t = 0; t < triangleCount; ++t)
  {
    const glm::uvec3& tri = this->Triangles[t];
    const double term =
      glm::dot(this->Points[tri.x], glm::cross(this->Points[tri.y], this->Points[tri.z]));
    volume[parent[t]] += term;
    terms[parent[t]] += std::abs(term);
  }
  int winding = 0;
  for (std::uint32_t piece = 0; piece < pieces; ++piece)
  {
    const double v = volume[piece];
    const int sign = !(std::abs(v) > 1e-9 * terms[piece]) ? 0 : v > 0.0 ? 1 : -1;
    if (sign == 0 || (winding != 0 && sign != winding))
    {
      return 0;
    }
    winding = sign;
  }
  return winding;
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
  TopologyScratch& scratch = *this->Scratch;
  TopologyReport report;
  if (!input || !input->GetPoints())
  {
    BuildFromSoup(scratch, std::vector<glm::dvec3>(), std::vector<glm::uvec3>(),
      relativeWeldTolerance, report, topology);
    return;
  }
  report.SkippedVerts = static_cast<std::size_t>(input->GetNumberOfVerts());
  report.SkippedLines = static_cast<std::size_t>(input->GetNumberOfLines());
  vtkCellArray* polys = input->GetPolys();
  const vtkIdType pointCount = input->GetNumberOfPoints();
  // Triangles only (contour and flying-edges output, most meshes): the connectivity is read in
  // place. Anything else is triangulated into scratch first.
  const bool trianglesOnly = polys->IsHomogeneous() == 3 && input->GetNumberOfStrips() == 0;
  if (!trianglesOnly)
  {
    scratch.InputTriangles.clear();
    TriangulateCells(input, scratch.InputTriangles, report);
  }
  WithPoints(input->GetPoints(), scratch.InputPoints,
    [&](const auto& points)
    {
      if (!trianglesOnly)
      {
        BuildFromSoup(
          scratch, points, scratch.InputTriangles, relativeWeldTolerance, report, topology);
        return;
      }
      WithStoredTriangles(polys, pointCount,
        [&](const auto& triangles)
        { BuildFromSoup(scratch, points, triangles, relativeWeldTolerance, report, topology); });
    });
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
    scratch.GroupFill.GetBytes() + scratch.EdgeStart.GetBytes() + scratch.TriangleFates.GetBytes();
}

} // namespace penumbra
