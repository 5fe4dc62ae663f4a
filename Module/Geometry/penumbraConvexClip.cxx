#include "penumbraConvexClip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace penumbra
{

namespace
{
using Polygon = std::vector<glm::dvec3>;

/// The six outward, counter-clockwise faces of the box.
std::vector<Polygon> BoxFaces(const Box& box)
{
  auto corner = [&](int i) { return BoxCorner(box.Min, box.Max, i); };
  static const int faces[6][4] = { { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 } };
  std::vector<Polygon> polygons;
  for (const auto& face : faces)
  {
    polygons.push_back({ corner(face[0]), corner(face[1]), corner(face[2]), corner(face[3]) });
  }
  return polygons;
}

/// The points in the plane's cut, ordered counter-clockwise seen from outside (along +normal).
Polygon CapPolygon(Polygon points, const glm::dvec3& normal, double tolerance)
{
  Polygon unique;
  for (const glm::dvec3& p : points)
  {
    if (std::none_of(unique.begin(), unique.end(),
          [&](const glm::dvec3& q) { return glm::length(p - q) <= tolerance; }))
    {
      unique.push_back(p);
    }
  }
  if (unique.size() < 3)
  {
    return {};
  }
  glm::dvec3 centre(0.0);
  for (const glm::dvec3& p : unique)
  {
    centre += p;
  }
  centre /= static_cast<double>(unique.size());
  const glm::dvec3 u = glm::normalize(unique[0] - centre);
  const glm::dvec3 v = glm::cross(normal, u);
  std::sort(unique.begin(), unique.end(),
    [&](const glm::dvec3& a, const glm::dvec3& b)
    {
      return std::atan2(glm::dot(a - centre, v), glm::dot(a - centre, u)) <
        std::atan2(glm::dot(b - centre, v), glm::dot(b - centre, u));
    });
  return unique;
}

/// Cuts every polygon by the half-space and closes the cut with a cap; false when nothing is left.
bool Cut(std::vector<Polygon>& polygons, const HalfSpace& half, double tolerance)
{
  std::vector<Polygon> kept;
  Polygon cut;
  bool anyOutside = false;
  std::vector<double> sides;
  for (const Polygon& polygon : polygons)
  {
    Polygon inside;
    bool inPlane = true;
    // Each corner's side once, by one expression, so that every face holding it agrees (two
    // expressions could be contracted to fused multiply-adds differently).
    sides.resize(polygon.size());
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
      sides[i] = glm::dot(half.Normal, polygon[i]) - half.Offset;
    }
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
      const glm::dvec3& p = polygon[i];
      const glm::dvec3& q = polygon[(i + 1) % polygon.size()];
      const double sp = sides[i];
      const double sq = sides[(i + 1) % polygon.size()];
      anyOutside = anyOutside || sp > tolerance;
      inPlane = inPlane && std::abs(sp) <= tolerance;
      if (sp <= tolerance)
      {
        inside.push_back(p);
        if (sp >= -tolerance)
        {
          cut.push_back(p);
        }
      }
      if ((sp < -tolerance && sq > tolerance) || (sp > tolerance && sq < -tolerance))
      {
        // From the lesser end, so that the two faces sharing this side (which walk it in
        // opposite directions) get the same point to the last bit.
        const bool fromP = std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
        const glm::dvec3 &from = fromP ? p : q, &to = fromP ? q : p;
        const double sFrom = fromP ? sp : sq, sTo = fromP ? sq : sp;
        const glm::dvec3 crossing = from + (to - from) * (sFrom / (sFrom - sTo));
        inside.push_back(crossing);
        cut.push_back(crossing);
      }
    }
    // A face in the plane is the cap's: kept, a ray would cross that face twice.
    if (inside.size() >= 3 && !inPlane)
    {
      kept.push_back(std::move(inside));
    }
  }
  if (!anyOutside)
  {
    return true; // the half-space holds all of it
  }
  Polygon cap = CapPolygon(std::move(cut), half.Normal, tolerance);
  if (!cap.empty())
  {
    kept.push_back(std::move(cap));
  }
  polygons = std::move(kept);
  return polygons.size() >= 4;
}

/// Shared points and fan triangles of the polygons, dropping slivers below `tolerance`.
ConvexPolyhedron Triangulate(const std::vector<Polygon>& polygons, double tolerance)
{
  ConvexPolyhedron shape;
  auto index = [&](const glm::dvec3& p)
  {
    for (std::size_t i = 0; i < shape.Points.size(); ++i)
    {
      if (glm::length(shape.Points[i] - p) <= tolerance)
      {
        return static_cast<std::uint32_t>(i);
      }
    }
    shape.Points.push_back(p);
    return static_cast<std::uint32_t>(shape.Points.size() - 1);
  };
  for (const Polygon& polygon : polygons)
  {
    std::vector<std::uint32_t> corners;
    for (const glm::dvec3& p : polygon)
    {
      const std::uint32_t i = index(p);
      if (corners.empty() || (corners.back() != i && corners.front() != i))
      {
        corners.push_back(i);
      }
    }
    for (std::size_t k = 1; k + 1 < corners.size(); ++k)
    {
      shape.Triangles.insert(shape.Triangles.end(), { corners[0], corners[k], corners[k + 1] });
    }
  }
  return shape;
}

/// Whether every directed edge of the triangles comes back once the other way: the surface is
/// closed, without cracks or T-junctions that could let a view ray through.
bool Closed(const ConvexPolyhedron& shape)
{
  // Each side as its two indices, lower first, and whether it is walked from the higher: sorted,
  // every side's walks must split evenly between the two directions.
  std::vector<std::uint64_t> sides;
  sides.reserve(shape.Triangles.size());
  for (std::size_t t = 0; t + 2 < shape.Triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint64_t a = shape.Triangles[t + k], b = shape.Triangles[t + (k + 1) % 3];
      sides.push_back((std::min(a, b) << 33) | (std::max(a, b) << 1) | (a > b ? 1 : 0));
    }
  }
  std::sort(sides.begin(), sides.end());
  for (std::size_t first = 0; first < sides.size();)
  {
    std::size_t last = first, reversed = 0;
    for (; last < sides.size() && (sides[last] >> 1) == (sides[first] >> 1); ++last)
    {
      reversed += sides[last] & 1;
    }
    if (2 * reversed != last - first)
    {
      return false;
    }
    first = last;
  }
  return true;
}
} // namespace

double ConvexPolyhedron::Volume() const
{
  double volume = 0.0;
  for (std::size_t t = 0; t + 2 < this->Triangles.size(); t += 3)
  {
    const glm::dvec3 &a = this->Points[this->Triangles[t]],
                     &b = this->Points[this->Triangles[t + 1]],
                     &c = this->Points[this->Triangles[t + 2]];
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return volume;
}

bool Box::Contains(const Box& other) const
{
  return this->Valid && other.Valid && glm::all(glm::lessThanEqual(this->Min, other.Min)) &&
    glm::all(glm::greaterThanEqual(this->Max, other.Max));
}

void Box::Extend(const glm::dvec3& min, const glm::dvec3& max)
{
  this->Min = this->Valid ? glm::min(this->Min, min) : min;
  this->Max = this->Valid ? glm::max(this->Max, max) : max;
  this->Valid = true;
}

Box TransformedBox(const Box& box, const glm::dmat4& matrix)
{
  Box moved;
  for (int corner = 0; box.Valid && corner < 8; ++corner)
  {
    const glm::dvec3 p(matrix * glm::dvec4(BoxCorner(box.Min, box.Max, corner), 1.0));
    moved.Extend(p, p);
  }
  return moved;
}

Box StableReceiverBox(const Box& kept, const Box& current)
{
  const double size = current.Diagonal();
  if (!current.Valid || !std::isfinite(size))
  {
    return {};
  }
  // A flat receiver (a ground plane) has a box of no thickness: grow it by its size, not by zero.
  const glm::dvec3 floor(0.01 * size + 1e-300);
  Box inner = current;
  inner.Min -= floor;
  inner.Max += floor;
  if (kept.Contains(inner) && kept.Diagonal() <= 2.0 * size)
  {
    return kept;
  }
  Box grown = current;
  grown.Min -= glm::dvec3(0.1 * size) + floor;
  grown.Max += glm::dvec3(0.1 * size) + floor;
  return grown;
}

Box ReceiverPieceBox(const Box& receivers, const Box& receiver)
{
  const double size = receivers.Diagonal();
  if (!receivers.Valid || !receiver.Valid || !(size > 0.0) || !std::isfinite(size) ||
    !std::isfinite(receiver.Diagonal()))
  {
    return {};
  }
  const double step = 0.02 * size;
  const glm::dvec3 lo = glm::floor((receiver.Min - 0.01 * size - receivers.Min) / step);
  const glm::dvec3 hi = glm::ceil((receiver.Max + 0.01 * size - receivers.Min) / step);
  Box piece;
  piece.Valid = true;
  piece.Min = glm::max(receivers.Min + lo * step, receivers.Min);
  piece.Max = glm::min(receivers.Min + hi * step, receivers.Max);
  return piece;
}

std::vector<Box> DisjointPieces(const std::vector<Box>& boxes, std::size_t maxBoxes)
{
  std::vector<Box> valid;
  Box bounds;
  for (const Box& box : boxes)
  {
    // Sorting faces with a NaN among them would be undefined.
    if (box.Valid && std::isfinite(box.Diagonal()))
    {
      valid.push_back(box);
      bounds.Extend(box.Min, box.Max);
    }
  }
  if (valid.empty())
  {
    return {};
  }
  if (valid.size() > maxBoxes)
  {
    return { bounds };
  }
  // The grid of every box's faces, per axis.
  std::array<std::vector<double>, 3> cuts;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (const Box& box : valid)
    {
      cuts[axis].push_back(box.Min[axis]);
      cuts[axis].push_back(box.Max[axis]);
    }
    std::sort(cuts[axis].begin(), cuts[axis].end());
    cuts[axis].erase(std::unique(cuts[axis].begin(), cuts[axis].end()), cuts[axis].end());
  }
  // By the cell's faces, not its centre: the centre of a cell one rounding step wide is one of
  // its faces.
  auto inside = [&](std::size_t i, std::size_t j, std::size_t k)
  {
    const glm::dvec3 low(cuts[0][i], cuts[1][j], cuts[2][k]);
    const glm::dvec3 high(cuts[0][i + 1], cuts[1][j + 1], cuts[2][k + 1]);
    return std::any_of(valid.begin(), valid.end(),
      [&](const Box& box)
      {
        return glm::all(glm::lessThanEqual(box.Min, low)) &&
          glm::all(glm::lessThanEqual(high, box.Max));
      });
  };
  // Cells as index ranges [x0, x1) x [y0, y1) x [z0, z1): runs along x, then merged along y
  // with the run above of the same x range, then along z likewise.
  using Range = std::array<std::size_t, 6>;
  std::vector<Range> runs;
  const std::size_t nx = cuts[0].size() - 1, ny = cuts[1].size() - 1, nz = cuts[2].size() - 1;
  for (std::size_t k = 0; k < nz; ++k)
  {
    for (std::size_t j = 0; j < ny; ++j)
    {
      for (std::size_t i = 0; i < nx;)
      {
        if (!inside(i, j, k))
        {
          ++i;
          continue;
        }
        const std::size_t start = i;
        while (i < nx && inside(i, j, k))
        {
          ++i;
        }
        runs.push_back({ start, i, j, j + 1, k, k + 1 });
      }
    }
  }
  // Merges b into a where they differ only along `axis` and b starts where a ends.
  auto mergeAlong = [](std::vector<Range>& ranges, int axis)
  {
    std::vector<Range> merged;
    for (const Range& range : ranges)
    {
      auto joins = [&](const Range& other)
      {
        for (int a = 0; a < 3; ++a)
        {
          if (a != axis && (other[2 * a] != range[2 * a] || other[2 * a + 1] != range[2 * a + 1]))
          {
            return false;
          }
        }
        return other[2 * axis + 1] == range[2 * axis];
      };
      auto found = std::find_if(merged.begin(), merged.end(), joins);
      if (found != merged.end())
      {
        (*found)[2 * axis + 1] = range[2 * axis + 1];
      }
      else
      {
        merged.push_back(range);
      }
    }
    ranges.swap(merged);
  };
  mergeAlong(runs, 1);
  mergeAlong(runs, 2);
  std::vector<Box> pieces;
  for (const Range& range : runs)
  {
    Box piece;
    piece.Valid = true;
    piece.Min = glm::dvec3(cuts[0][range[0]], cuts[1][range[2]], cuts[2][range[4]]);
    piece.Max = glm::dvec3(cuts[0][range[1]], cuts[1][range[3]], cuts[2][range[5]]);
    pieces.push_back(piece);
  }
  return pieces;
}

ConvexPolyhedron ClipBox(const Box& box, const std::vector<HalfSpace>& halfSpaces)
{
  const double size = box.Diagonal();
  if (!box.Valid || !(size > 0.0) || !std::isfinite(size))
  {
    return {};
  }
  // Points closer than this are one, and a point this near a plane lies in it. Far from the
  // origin the coordinates' own rounding sets it (a box 8 wide at 1e6 rounds by 1e-10).
  const glm::dvec3 magnitude = glm::max(glm::abs(box.Min), glm::abs(box.Max));
  const double tolerance = 1e-12 * (size + std::max({ magnitude.x, magnitude.y, magnitude.z }));
  std::vector<HalfSpace> units;
  for (const HalfSpace& half : halfSpaces)
  {
    const double length = glm::length(half.Normal);
    if (!(length > 0.0) || !std::isfinite(length))
    {
      continue;
    }
    const HalfSpace unit{ half.Normal / length, half.Offset / length };
    if (std::isfinite(unit.Offset))
    {
      units.push_back(unit);
    }
  }
  std::vector<Polygon> polygons = BoxFaces(box);
  for (const HalfSpace& unit : units)
  {
    if (!Cut(polygons, unit, tolerance))
    {
      return {};
    }
  }
  ConvexPolyhedron shape = Triangulate(polygons, tolerance);
  if (Closed(shape))
  {
    return shape;
  }
  // Nearly parallel planes (or a cap whose points lie nearly on a line) can still leave faces
  // disagreeing on their shared corners. Cut again, leaving out each cut that opens the surface:
  // the bound is larger, which the caller must allow for (a wedge so cut is drawn by its back
  // faces), and a crack would let view rays through.
  polygons = BoxFaces(box);
  shape = Triangulate(polygons, tolerance);
  std::size_t leftOut = 0;
  for (const HalfSpace& unit : units)
  {
    std::vector<Polygon> cut = polygons;
    if (!Cut(cut, unit, tolerance))
    {
      return {};
    }
    ConvexPolyhedron candidate = Triangulate(cut, tolerance);
    if (Closed(candidate))
    {
      polygons = std::move(cut);
      shape = std::move(candidate);
    }
    else
    {
      ++leftOut;
    }
  }
  shape.CutsLeftOut = leftOut;
  return shape;
}

} // namespace penumbra
