#include "penumbraCulling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

namespace penumbra
{
namespace
{
struct Plane
{
  glm::dvec3 Normal;
  double Offset;
  double Distance(const glm::dvec3& p) const { return glm::dot(this->Normal, p) - this->Offset; }
};

/// The six planes of the view frustum of `worldToClip` (OpenGL's clip space, -w <= x, y, z <= w)
/// as (n, d) with n.x + d >= 0 inside: left, right, bottom, top, near, far.
std::array<glm::dvec4, 6> FrustumPlanes(const glm::dmat4& worldToClip)
{
  const glm::dmat4 rows = glm::transpose(worldToClip);
  return { rows[3] + rows[0], rows[3] - rows[0], rows[3] + rows[1], rows[3] - rows[1],
    rows[3] + rows[2], rows[3] - rows[2] };
}

/**
 * The (nearest, farthest) view depths of the part of `box` inside the half-spaces of `frustum`
 * (whose corners `frustumBox` holds): (inf, -inf) where none is, NaN where the box is not
 * finite. Where the whole box lies in front
 * of the eye the nearest is its own nearest corner's: a near plane moved up to the nearest point
 * in view would cut shadow volumes that the box's nearest depth leaves whole, and those would
 * need z-fail.
 */
glm::dvec2 DepthsInView(const Box& box, const std::vector<HalfSpace>& frustum,
  const Box& frustumBox, const glm::dmat4& worldToView)
{
  const double none = std::numeric_limits<double>::infinity();
  const auto finite = [](const glm::dvec3& p)
  { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
  if (!finite(box.Min) || !finite(box.Max))
  {
    return glm::dvec2(std::nan(""));
  }
  std::array<glm::dvec3, 8> corners;
  double cornerNearest = none, cornerFarthest = -none;
  for (int i = 0; i < 8; ++i)
  {
    corners[i] = BoxCorner(box.Min, box.Max, i);
    const double depth = -(worldToView * glm::dvec4(corners[i], 1.0)).z;
    cornerNearest = std::min(cornerNearest, depth);
    cornerFarthest = std::max(cornerFarthest, depth);
  }
  if (!std::isfinite(cornerNearest + cornerFarthest))
  {
    return glm::dvec2(std::nan(""));
  }
  bool allInside = true;
  for (const HalfSpace& half : frustum)
  {
    int outside = 0;
    for (const glm::dvec3& corner : corners)
    {
      outside += glm::dot(half.Normal, corner) > half.Offset;
    }
    if (outside == 8)
    {
      return glm::dvec2(none, -none);
    }
    allInside = allInside && outside == 0;
  }
  if (allInside)
  {
    return glm::dvec2(cornerNearest, cornerFarthest);
  }
  // Grown a little, so that a flat box (a single plane) still leaves a solid to cut, and cut to
  // the frustum's box: ClipBox works to 1e-12 of the box it cuts, and a box reaching 1e30 away
  // (a stray point) would lose the view's few units to that.
  Box grown = box;
  const glm::dvec3 margin(1e-6 * box.Diagonal());
  // Generous: the far corners of a range of 1e14 or more (from the inverse of the projection)
  // are off by a good share of the far plane, and the cut is only there to bring boxes 1e30
  // wide down to the view's scale (a review).
  const glm::dvec3 frustumMargin(0.5 * frustumBox.Diagonal());
  grown.Min = glm::max(grown.Min - margin, frustumBox.Min - frustumMargin);
  grown.Max = glm::min(grown.Max + margin, frustumBox.Max + frustumMargin);
  if (!glm::all(glm::lessThan(grown.Min, grown.Max)))
  {
    return glm::dvec2(none, -none);
  }
  glm::dvec2 depths(none, -none);
  for (const glm::dvec3& point : ClipBox(grown, frustum).Points)
  {
    const double depth = -(worldToView * glm::dvec4(point, 1.0)).z;
    depths = glm::dvec2(std::min(depths.x, depth), std::max(depths.y, depth));
  }
  if (cornerNearest > 0.0 && depths.y >= depths.x)
  {
    depths.x = cornerNearest;
  }
  return depths;
}

} // namespace

bool ProjectsInfinityToInfinity(const glm::dmat4& worldToClip)
{
  // Clip w of (d, 0) is row 3 of the matrix times d (GLM: column-major).
  return worldToClip[0][3] == 0.0 && worldToClip[1][3] == 0.0 && worldToClip[2][3] == 0.0;
}

double ParallelSweepLength(const glm::dmat4& objectToWorld, const glm::dvec3& casterMin,
  const glm::dvec3& casterMax, const glm::dvec4& light, const Box& scene,
  const std::array<glm::dvec3, 4>& nearCorners)
{
  if (!scene.Valid)
  {
    return 0.0;
  }
  std::array<glm::dvec3, 20> points;
  std::copy(nearCorners.begin(), nearCorners.end(), points.begin());
  for (int corner = 0; corner < 8; ++corner)
  {
    points[4 + 2 * corner] = BoxCorner(scene.Min, scene.Max, corner);
    points[5 + 2 * corner] = BoxCorner(casterMin, casterMax, corner);
  }
  // From the light, or across the points for a directional light's parallel sweep.
  double reach = 0.0;
  for (const glm::dvec3& a : points)
  {
    if (light.w != 0.0)
    {
      reach = std::max(reach, glm::distance(a, glm::dvec3(light)));
      continue;
    }
    for (const glm::dvec3& b : points)
    {
      reach = std::max(reach, glm::distance(a, b));
    }
  }
  // A world length is at least an object length over the Frobenius norm of the inverse.
  const glm::dmat3 toObject = glm::inverse(glm::dmat3(objectToWorld));
  double norm = 0.0;
  for (int column = 0; column < 3; ++column)
  {
    norm += glm::dot(toObject[column], toObject[column]);
  }
  const double length = 1e3 * reach * std::sqrt(norm);
  return std::isfinite(length) && length > 0.0 ? length : 0.0;
}

bool VolumeMayReachNearPlane(const glm::dvec3& boxMin, const glm::dvec3& boxMax,
  const glm::dvec4& light, const std::array<glm::dvec3, 4>& nearCorners)
{
  const glm::dvec3 centre =
    0.25 * (nearCorners[0] + nearCorners[1] + nearCorners[2] + nearCorners[3]);
  const double size = glm::length(nearCorners[2] - nearCorners[0]);
  const glm::dvec3 apex = light.w != 0.0 ? glm::dvec3(light) / light.w : glm::dvec3(0.0);
  const glm::dvec3 towardsLight =
    light.w != 0.0 ? apex - centre : UnitDirection(glm::dvec3(light)) * size;
  // Each plane is oriented by difference vectors, never by a point's coordinates: the near plane
  // towards the light, each side plane towards the rectangle's centre. A point halfway to a light
  // 1e30 away, or near a rectangle 1e10 from the origin under a grazing light, had its distances
  // to the planes drown in the rounding of its coordinates, and a plane could face the wrong way
  // (the fuzzer; a review).
  std::array<Plane, 5> planes;
  auto makePlane = [&](const glm::dvec3& a, const glm::dvec3& edge, const glm::dvec3& along,
                     const glm::dvec3& inward, Plane& plane)
  {
    glm::dvec3 n = glm::cross(edge, along);
    const double length = glm::length(n);
    if (!(length > 1e-12 * glm::length(edge) * glm::length(along)))
    {
      return false; // light on the near plane, or swept parallel to it
    }
    n /= length;
    double side = glm::dot(n, inward);
    if (side < 0.0)
    {
      n = -n;
      side = -side;
    }
    plane = { n, glm::dot(n, a) };
    return side > 1e-9 * glm::length(inward);
  };
  if (!makePlane(nearCorners[0], nearCorners[1] - nearCorners[0], nearCorners[2] - nearCorners[0],
        towardsLight, planes[0]))
  {
    return true;
  }
  for (int i = 0; i < 4; ++i)
  {
    const glm::dvec3& a = nearCorners[i];
    const glm::dvec3& b = nearCorners[(i + 1) % 4];
    // A directional light's side planes hold its direction itself: a + towardsLight, at the
    // rectangle's coordinates, would tilt them by their rounding.
    const glm::dvec3 along = light.w != 0.0 ? apex - a : towardsLight;
    if (!makePlane(a, b - a, along, centre - (0.5 * a + 0.5 * b), planes[i + 1]))
    {
      return true;
    }
  }
  const glm::dvec3 margin = 1e-6 * (boxMax - boxMin) + 1e-9 * size;
  const glm::dvec3 lo = boxMin - margin, hi = boxMax + margin;
  for (const Plane& plane : planes)
  {
    // The box corner furthest along the plane normal decides whether the box is all outside.
    const glm::dvec3 furthest(plane.Normal.x > 0 ? hi.x : lo.x, plane.Normal.y > 0 ? hi.y : lo.y,
      plane.Normal.z > 0 ? hi.z : lo.z);
    if (plane.Distance(furthest) < 0.0)
    {
      return false;
    }
  }
  return true;
}

VolumeDrawPlan PlanVolumeDraw(const glm::dvec3& boxMin, const glm::dvec3& boxMax,
  const glm::dvec4& light, const std::array<glm::dvec3, 4>& nearCorners, bool seenThrough,
  bool facesCulled)
{
  VolumeDrawPlan plan;
  plan.ZFail = facesCulled || VolumeMayReachNearPlane(boxMin, boxMax, light, nearCorners);
  plan.LightCap = plan.ZFail || seenThrough;
  return plan;
}

bool WedgesDrawnByFrontFaces(const glm::dvec3& boxMin, const glm::dvec3& boxMax,
  const glm::dvec4& light, double radius, const std::array<glm::dvec3, 4>& nearCorners,
  bool anyFallback)
{
  if (light.w == 0.0 || anyFallback)
  {
    return false;
  }
  const glm::dvec3 grow(radius);
  return !VolumeMayReachNearPlane(boxMin - grow, boxMax + grow, light, nearCorners);
}

bool ShadowMayReachView(const glm::dvec3& boxMin, const glm::dvec3& boxMax, const glm::dvec4& light,
  double radius, const glm::dmat4& worldToClip)
{
  for (const glm::dvec4& plane : FrustumPlanes(worldToClip))
  {
    const glm::dvec3 n(plane);
    const double length = glm::length(n);
    if (!(length > 0.0))
    {
      continue;
    }
    // Largest signed distance of the box inside this plane (inside: dot(n, x) + w >= 0).
    const glm::dvec3 furthest(
      n.x > 0 ? boxMax.x : boxMin.x, n.y > 0 ? boxMax.y : boxMin.y, n.z > 0 ? boxMax.z : boxMin.z);
    const double boxReach = glm::dot(n, furthest);
    if (boxReach + plane.w >= 0.0)
    {
      continue;
    }
    bool sweptOutside;
    if (light.w != 0.0)
    {
      // Sweep directions b - q for b in the box, q in the light's sphere.
      sweptOutside = boxReach <= glm::dot(n, glm::dvec3(light)) - radius * length;
    }
    else
    {
      // Sweep directions within the angular radius of the direction away from the light.
      const glm::dvec3 away = -UnitDirection(glm::dvec3(light));
      const double cosine = glm::dot(n, away) / length;
      sweptOutside = cosine <= -std::sin(std::min(radius, 1.5707963267948966));
    }
    if (sweptOutside)
    {
      return false;
    }
  }
  return true;
}

OccupancyGrid::OccupancyGrid(const Box& bounds)
  : Bounds(bounds)
  , Cells(static_cast<std::size_t>(Resolution * Resolution * Resolution))
{
}

double OccupancyGrid::Face(int index, int axis) const
{
  const double size = this->Bounds.Max[axis] - this->Bounds.Min[axis];
  return index == Resolution ? this->Bounds.Max[axis]
                             : this->Bounds.Min[axis] + size * index / Resolution;
}

bool OccupancyGrid::Add(const glm::dvec3& min, const glm::dvec3& max)
{
  // A box that is not finite would make its grid cells' boxes NaN.
  const glm::dvec3 both = min - max;
  if (!std::isfinite(both.x) || !std::isfinite(both.y) || !std::isfinite(both.z))
  {
    return false;
  }
  if (!this->Bounds.Valid)
  {
    return true;
  }
  const glm::dvec3 size = this->Bounds.Max - this->Bounds.Min;
  // The grid cell [Face(c), Face(c + 1)) of a coordinate, clamped to the grid; a flat axis is
  // one cell. The quotient can round a coordinate next to a face into the cell beside, whose
  // cut would then leave out the sliver between: the faces, as cut, decide.
  auto cell = [&](const glm::dvec3& p, int axis)
  {
    const double t = size[axis] > 0.0 ? (p[axis] - this->Bounds.Min[axis]) / size[axis] : 0.0;
    const double scaled = std::floor(t * Resolution);
    int c =
      static_cast<int>(std::clamp(std::isfinite(scaled) ? scaled : 0.0, 0.0, Resolution - 1.0));
    while (c > 0 && p[axis] < this->Face(c, axis))
    {
      --c;
    }
    while (c < Resolution - 1 && p[axis] >= this->Face(c + 1, axis))
    {
      ++c;
    }
    return c;
  };
  glm::ivec3 from, to;
  for (int axis = 0; axis < 3; ++axis)
  {
    from[axis] = cell(min, axis);
    to[axis] = cell(max, axis);
  }
  const glm::dvec3 low = glm::clamp(min, this->Bounds.Min, this->Bounds.Max);
  const glm::dvec3 high = glm::clamp(max, this->Bounds.Min, this->Bounds.Max);
  const glm::dvec3 extent = high - low;
  const int thinnest =
    extent.x <= extent.y ? (extent.x <= extent.z ? 0 : 2) : (extent.y <= extent.z ? 1 : 2);
  for (int z = from.z; z <= to.z; ++z)
  {
    for (int y = from.y; y <= to.y; ++y)
    {
      for (int x = from.x; x <= to.x; ++x)
      {
        const glm::dvec3 cellMin(this->Face(x, 0), this->Face(y, 1), this->Face(z, 2));
        const glm::dvec3 cellMax(this->Face(x + 1, 0), this->Face(y + 1, 1), this->Face(z + 1, 2));
        // Cut to the cell; a box that only touches it leaves a flat box on the shared face.
        const glm::dvec3 cutMin = glm::min(glm::max(low, cellMin), cellMax);
        const glm::dvec3 cutMax = glm::max(glm::min(high, cellMax), cutMin);
        this->Cells[static_cast<std::size_t>((z * Resolution + y) * Resolution + x)][thinnest]
          .Extend(cutMin, cutMax);
      }
    }
  }
  return true;
}

std::vector<Box> OccupancyGrid::Boxes() const
{
  if (!this->Bounds.Valid)
  {
    return { Box() };
  }
  std::vector<Box> boxes;
  for (const std::array<Box, 3>& cell : this->Cells)
  {
    std::copy_if(cell.begin(), cell.end(), std::back_inserter(boxes),
      [](const Box& box) { return box.Valid; });
  }
  return boxes;
}

glm::dvec2 TightClippingRange(const std::vector<Box>& props, const glm::dmat4& worldToView,
  const glm::dmat4& worldToClip, const glm::dvec2& current)
{
  if (!(current.x > 0.0) || !(current.y > current.x) || !std::isfinite(current.y))
  {
    return current;
  }
  // The frustum as half-spaces of world points, and the box of its corners.
  const glm::dmat4 clipToWorld = glm::inverse(worldToClip);
  Box frustumBox;
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec4 p =
      clipToWorld * glm::dvec4(BoxCorner(glm::dvec3(-1.0), glm::dvec3(1.0), corner), 1.0);
    const glm::dvec3 point = glm::dvec3(p) / p.w;
    // Box::Extend's min and max would pass over a NaN corner (w = 0) after the first.
    if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
    {
      return current;
    }
    frustumBox.Extend(point, point);
  }
  if (!std::isfinite(frustumBox.Diagonal()))
  {
    return current;
  }
  std::vector<HalfSpace> frustum;
  for (const glm::dvec4& plane : FrustumPlanes(worldToClip))
  {
    if (!std::isfinite(plane.x + plane.y + plane.z + plane.w))
    {
      return current;
    }
    frustum.push_back(HalfSpace{ -glm::dvec3(plane), plane.w });
  }
  glm::dvec2 depths(
    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
  for (const Box& box : props)
  {
    const glm::dvec2 inView =
      box.Valid ? DepthsInView(box, frustum, frustumBox, worldToView) : glm::dvec2(std::nan(""));
    if (std::isnan(inView.x))
    {
      return current;
    }
    depths = glm::dvec2(std::min(depths.x, inView.x), std::max(depths.y, inView.y));
  }
  const double nearest = depths.x, farthest = depths.y;
  if (!(nearest > 0.0) || !std::isfinite(farthest))
  {
    return current; // nothing in view: a box at the eye is cut at the near plane
  }
  const double tightFar = std::min(current.y, farthest * (1.0 + 1e-3));
  // No nearer to the far plane than 0.8 of it: float depth from the vertex transforms loses
  // about (far + near) / (far - near) times its precision, here at most 9.
  const double tightNear = std::max(current.x, std::min(nearest * (1.0 - 1e-3), 0.8 * tightFar));
  if (tightNear > 0.8 * tightFar)
  {
    return current;
  }
  return tightFar > tightNear ? glm::dvec2(tightNear, tightFar) : current;
}

glm::dvec4 VolumeEndPlane(const glm::dvec3& casterMin, const glm::dvec3& casterMax,
  const glm::dvec4& light, const Box& scene, const std::array<glm::dvec3, 4>& nearCorners)
{
  if (!scene.Valid)
  {
    return glm::dvec4(0.0);
  }
  // Every swept direction lies within `spread` radians of `axis`: the sweep through the caster's
  // centre, and for a point light the cone around it that holds the caster's bounding sphere.
  const glm::dvec3 centre = 0.5 * (casterMin + casterMax);
  glm::dvec3 axis = -UnitDirection(glm::dvec3(light));
  double spread = 0.0;
  if (light.w != 0.0)
  {
    const glm::dvec3 away = centre - glm::dvec3(light);
    const double distance = glm::length(away);
    // The farthest corner from the centre as computed, not half the diagonal: where the box is
    // a few units in the last place wide (coordinates of 1e18), the centre rounds onto a face
    // and half the diagonal would leave the far corners outside the sphere.
    const double radius = glm::length(glm::max(casterMax - centre, centre - casterMin));
    if (!(distance > radius) || !std::isfinite(distance))
    {
      return glm::dvec4(0.0);
    }
    axis = away / distance;
    spread = std::asin(radius / distance);
  }
  if (!std::isfinite(axis.x + axis.y + axis.z))
  {
    return glm::dvec4(0.0);
  }
  // A margin, so that float rounding in the vertex shader cannot pull a cut end into the scene.
  const double margin = 1e-3 * (scene.Diagonal() + glm::length(casterMax - casterMin));
  auto offsetAlong = [&](const glm::dvec3& normal)
  {
    double offset = -std::numeric_limits<double>::infinity();
    for (int corner = 0; corner < 8; ++corner)
    {
      offset = std::max(offset, glm::dot(normal, BoxCorner(scene.Min, scene.Max, corner)));
      offset = std::max(offset, glm::dot(normal, BoxCorner(casterMin, casterMax, corner)));
    }
    for (const glm::dvec3& corner : nearCorners)
    {
      offset = std::max(offset, glm::dot(normal, corner));
    }
    return offset + margin;
  };
  // Candidates: the axis, and the scene box's faces, one of which often holds the receivers (a
  // ground under a tilted light). A face qualifies where every swept direction meets it at least
  // 11.5 degrees from edge-on (cos >= 0.2), so that no swept point goes more than five times its
  // distance to the plane. The plane kept is the one the sweep through the centre meets first.
  glm::dvec4 best(0.0);
  double bestReach = std::numeric_limits<double>::infinity();
  auto consider = [&](const glm::dvec3& normal)
  {
    const double tilt = std::acos(std::clamp(glm::dot(normal, axis), -1.0, 1.0));
    if (tilt + spread > std::acos(0.2))
    {
      return;
    }
    const double offset = offsetAlong(normal);
    const double reach = (offset - glm::dot(normal, centre)) / glm::dot(normal, axis);
    if (std::isfinite(offset) && reach < bestReach)
    {
      bestReach = reach;
      best = glm::dvec4(normal, -offset);
    }
  };
  consider(axis);
  for (int face = 0; face < 6; ++face)
  {
    glm::dvec3 normal(0.0);
    normal[face / 2] = face % 2 ? 1.0 : -1.0;
    consider(normal);
  }
  return best;
}

PixelRect ShadowScissor(const glm::dvec3& casterMin, const glm::dvec3& casterMax,
  const glm::dvec4& light, const Box& scene, const glm::dmat4& worldToClip, int width, int height)
{
  const PixelRect whole{ 0, 0, width, height };
  if (!scene.Valid)
  {
    return whole;
  }
  // The cone's sides: planes through the light and each edge of the caster's box between a face
  // that faces the light and one that does not (for a direction, planes along it).
  const glm::dvec3 centre = 0.5 * (casterMin + casterMax);
  const glm::dvec3 towardsLight(light);
  std::vector<HalfSpace> cone;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      // Face (axis, side) faces the light when the light lies beyond its plane.
      auto faces = [&](int a, int s)
      {
        const double plane = s ? casterMax[a] : casterMin[a];
        const double beyond = light.w != 0.0 ? towardsLight[a] - plane : towardsLight[a];
        return s ? beyond > 0.0 : beyond < 0.0;
      };
      for (int other = axis + 1; other < 3; ++other)
      {
        for (int otherSide = 0; otherSide < 2; ++otherSide)
        {
          if (faces(axis, side) == faces(other, otherSide))
          {
            continue;
          }
          // The edge shared by the two faces runs along the third axis.
          const int along = 3 - axis - other;
          glm::dvec3 a, b;
          a[axis] = b[axis] = side ? casterMax[axis] : casterMin[axis];
          a[other] = b[other] = otherSide ? casterMax[other] : casterMin[other];
          a[along] = casterMin[along];
          b[along] = casterMax[along];
          const glm::dvec3 spread = light.w != 0.0 ? a - towardsLight : towardsLight;
          glm::dvec3 normal = glm::cross(b - a, spread);
          if (glm::dot(normal, centre - a) > 0.0)
          {
            normal = -normal;
          }
          cone.push_back({ normal, glm::dot(normal, a) });
        }
      }
    }
  }
  if (cone.empty())
  {
    return whole; // the light inside the box, or on its faces' planes: the shadow is anywhere
  }
  // The shadow lies beyond the caster: along the axis away from the light, not before the box's
  // nearest corner (for a point light, when no corner lies behind it).
  const glm::dvec3 origin = light.w != 0.0 ? towardsLight : glm::dvec3(0.0);
  const glm::dvec3 away = light.w != 0.0 ? centre - towardsLight : -towardsLight;
  double start = std::numeric_limits<double>::infinity();
  for (int corner = 0; corner < 8; ++corner)
  {
    start = std::min(start, glm::dot(away, BoxCorner(casterMin, casterMax, corner) - origin));
  }
  if (light.w == 0.0 || start >= 0.0)
  {
    cone.push_back({ -away, -(start + glm::dot(away, origin)) });
  }
  const ConvexPolyhedron shadow = ClipBox(scene, cone);
  if (shadow.Empty())
  {
    return {};
  }
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& point : shadow.Points)
  {
    const glm::dvec4 clip = worldToClip * glm::dvec4(point, 1.0);
    if (!(clip.w > 0.0))
    {
      return whole;
    }
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  auto pixel = [](double ndc, int size) { return (0.5 * ndc + 0.5) * size; };
  PixelRect rect;
  rect.X0 = static_cast<int>(std::max(0.0, std::floor(pixel(lo.x, width)) - 1.0));
  rect.Y0 = static_cast<int>(std::max(0.0, std::floor(pixel(lo.y, height)) - 1.0));
  rect.X1 = static_cast<int>(std::min<double>(width, std::ceil(pixel(hi.x, width)) + 1.0));
  rect.Y1 = static_cast<int>(std::min<double>(height, std::ceil(pixel(hi.y, height)) + 1.0));
  return rect.Empty() ? PixelRect{} : rect;
}

bool BoxBeyondNearPlane(
  const glm::dvec3& boxMin, const glm::dvec3& boxMax, const glm::dmat4& worldToClip)
{
  for (int corner = 0; corner < 8; ++corner)
  {
    // The clip-space depth minus the near plane's is affine in the point: positive at every
    // corner means positive in the whole box.
    const glm::dvec4 clip = worldToClip * glm::dvec4(BoxCorner(boxMin, boxMax, corner), 1.0);
    if (!(clip.z + clip.w > 0.0))
    {
      return false;
    }
  }
  return true;
}

ClipSide ClipBoxByPlanes(const glm::dvec3& boxMin, const glm::dvec3& boxMax,
  const glm::dmat4& objectToWorld, const std::vector<glm::dvec4>& planes)
{
  bool kept = true;
  for (const glm::dvec4& plane : planes)
  {
    int inside = 0, outside = 0;
    for (int corner = 0; corner < 8; ++corner)
    {
      const glm::dvec3 world(objectToWorld * glm::dvec4(BoxCorner(boxMin, boxMax, corner), 1.0));
      const double distance = glm::dot(glm::dvec3(plane), world) + plane.w;
      inside += distance >= 0.0;
      outside += distance < 0.0;
    }
    if (outside == 8)
    {
      return ClipSide::Removed;
    }
    kept = kept && inside == 8; // NaN distances count neither way: Cut
  }
  return kept ? ClipSide::Kept : ClipSide::Cut;
}

} // namespace penumbra
