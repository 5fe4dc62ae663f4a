/**
 * @file penumbraCulling.h
 * @brief What vtkSoftShadowPass decides per caster and light before drawing: whether its shadow
 * volume may reach the near plane (z-fail needed) and whether its shadow may reach the view at
 * all. Both are conservative: "true" may be a false alarm (some work for nothing), "false" is
 * never wrong (TestCulling checks both by brute force).
 */
#ifndef penumbraCulling_h
#define penumbraCulling_h

#include "penumbraConvexClip.h"
#include "vtkPenumbraGeometryModule.h" // for export macro

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace penumbra
{

/**
 * `v` scaled to unit length, to rounding, for any finite non-zero `v`: glm::normalize squares
 * the components, which fall into subnormals below about 1e-154 (a light direction of 1e-158 in
 * each component came out 1.5e-8 short of unit length) and overflow above 1e154. Not finite for
 * a zero or non-finite `v`.
 */
inline glm::dvec3 UnitDirection(const glm::dvec3& v)
{
  const double scale = std::max({ std::abs(v.x), std::abs(v.y), std::abs(v.z) });
  return glm::normalize(v / scale);
}

/**
 * Whether `worldToClip` takes every point at infinity (w = 0) to clip w = 0: a parallel
 * projection, under which a shadow volume's far end at infinity is drawn nowhere, although it
 * lies behind every pixel or none. (A perspective projection takes only the directions parallel
 * to the image plane there.)
 */
VTKPENUMBRAGEOMETRY_EXPORT bool ProjectsInfinityToInfinity(const glm::dmat4& worldToClip);

/**
 * Whether a caster's shadow volume may reach the near-plane rectangle (McGuire et al.): true when
 * the caster's bounds meet the convex hull of that rectangle and the light (for a directional
 * light, the rectangle swept towards it). Only separating planes of the hull are tried, so "true"
 * may be a false alarm, which costs z-fail but never correctness. The light is (position, 1) or
 * (direction towards it, 0), world space like the box and the corners.
 */
VTKPENUMBRAGEOMETRY_EXPORT bool VolumeMayReachNearPlane(const glm::dvec3& boxMin,
  const glm::dvec3& boxMax, const glm::dvec4& light, const std::array<glm::dvec3, 4>& nearCorners);

/// How one caster's shadow volume is drawn for one light sample (McGuire et al.'s choice).
struct VolumeDrawPlan
{
  /// Count faces behind the point, caps at infinity included: the volume may reach the near
  /// plane, or the caster's faces are culled. Otherwise z-pass counts the sides only.
  bool ZFail = false;
  /// Draw the cap on the lit faces: z-fail, or a caster points are seen through (they lie
  /// behind that cap, so z-pass must count it).
  bool LightCap = false;
};

/// The plan for a caster's volume from `light`: z-pass wherever VolumeMayReachNearPlane allows,
/// unless the caster's front or back faces are culled (`facesCulled`). Culling hides faces from
/// the eye, not from the light, so a point may then be seen through the caster's lit faces from
/// outside its volume's sides: z-pass, which counts on those faces hiding what lies behind them,
/// would leave it lit.
VTKPENUMBRAGEOMETRY_EXPORT VolumeDrawPlan PlanVolumeDraw(const glm::dvec3& boxMin,
  const glm::dvec3& boxMax, const glm::dvec4& light, const std::array<glm::dvec3, 4>& nearCorners,
  bool seenThrough, bool facesCulled);

/**
 * Whether a caster's penumbra wedges are rasterized by their front faces. A point inside a wedge
 * lies behind its front faces and in front of its back faces. When neither the eye nor the near
 * plane can be inside the wedges (the caster's bounds grown by the light's `radius` miss the near
 * plane's hull with the light, as for z-pass), front faces tested against the scene depth skip
 * every point in front of the wedge. Otherwise, and for a directional light or when some edge had
 * no wedge planes (`anyFallback`: its wedge is a light pyramid or the viewport), back faces, which
 * every ray meeting the wedge crosses once, skip the points behind it.
 */
VTKPENUMBRAGEOMETRY_EXPORT bool WedgesDrawnByFrontFaces(const glm::dvec3& boxMin,
  const glm::dvec3& boxMax, const glm::dvec4& light, double radius,
  const std::array<glm::dvec3, 4>& nearCorners, bool anyFallback);

/**
 * Whether a caster's shadow can reach the view: false when, for one frustum plane, the caster's
 * bounds lie outside it and every direction it is swept in (away from any point of the light:
 * a sphere of `radius` world units around a positional light, a cone of `radius` radians around
 * a directional one) leads further outside.
 */
VTKPENUMBRAGEOMETRY_EXPORT bool ShadowMayReachView(const glm::dvec3& boxMin,
  const glm::dvec3& boxMax, const glm::dvec4& light, double radius, const glm::dmat4& worldToClip);

/// Whether every point of the box lies strictly beyond the near plane of `worldToClip` (clip
/// z > -w, the camera's side of it excluded): then a closed surface inside it is seen from
/// outside only. False for a box that holds the eye, reaches behind it or is cut by the plane.
VTKPENUMBRAGEOMETRY_EXPORT bool BoxBeyondNearPlane(
  const glm::dvec3& boxMin, const glm::dvec3& boxMax, const glm::dmat4& worldToClip);

/// Where a placed box lies against clipping planes (ClipBoxByPlanes).
enum class ClipSide
{
  Kept,    ///< every point of it is kept by every plane
  Removed, ///< every point of it is discarded by one plane
  Cut      ///< anything else: it may be cut
};

/**
 * Where the box [boxMin, boxMax], placed by `objectToWorld` (affine), lies against `planes`,
 * each (normal, offset) in world coordinates and keeping the points where
 * dot(normal, x) + offset >= 0, as VTK's shaders clip a mapper's fragments. Decided at the
 * corners: an affine map takes the box to the hull of its corners. Non-finite values give Cut.
 */
VTKPENUMBRAGEOMETRY_EXPORT ClipSide ClipBoxByPlanes(const glm::dvec3& boxMin,
  const glm::dvec3& boxMax, const glm::dmat4& objectToWorld, const std::vector<glm::dvec4>& planes);

/// A rectangle of pixels [X0, X1) x [Y0, Y1) of a viewport.
struct PixelRect
{
  int X0 = 0, Y0 = 0, X1 = 0, Y1 = 0;
  bool Empty() const { return this->X1 <= this->X0 || this->Y1 <= this->Y0; }
  /// The smallest rectangle holding both (an empty one adds nothing).
  PixelRect United(const PixelRect& other) const
  {
    if (other.Empty())
    {
      return *this;
    }
    if (this->Empty())
    {
      return other;
    }
    return { std::min(this->X0, other.X0), std::min(this->Y0, other.Y0),
      std::max(this->X1, other.X1), std::max(this->Y1, other.Y1) };
  }
  bool operator==(const PixelRect& other) const
  {
    return this->X0 == other.X0 && this->Y0 == other.Y0 && this->X1 == other.X1 &&
      this->Y1 == other.Y1;
  }
};

/**
 * The pixels of a `width` x `height` viewport whose visible point can lie in the shadow that the
 * box casterMin..casterMax casts from one light point (position, 1) or direction (towards it, 0),
 * given that every visible point lies in `scene`: the projection of `scene` cut to the cone (or
 * prism) from the light through the caster's box, grown by a pixel. A shadow volume drawn with
 * this scissor counts the same at every pixel that matters, since outside the cone its count is
 * zero. The whole viewport where the light is inside the caster's box, `scene` is invalid, or
 * the cut reaches behind the eye; an empty rectangle where the cone misses `scene`.
 */
VTKPENUMBRAGEOMETRY_EXPORT PixelRect ShadowScissor(const glm::dvec3& casterMin,
  const glm::dvec3& casterMax, const glm::dvec4& light, const Box& scene,
  const glm::dmat4& worldToClip, int width, int height);

/**
 * Where a z-pass shadow volume may stop instead of at infinity (after Lloyd et al.'s CC shadow
 * volumes): a world plane (n, -d), n.x = d, that every point of `scene`, of the caster's box and
 * of the near rectangle lies in front of (n.x < d), and that every direction the volume sweeps in
 * from the caster away from `light` (position, 1) or (direction towards it, 0) crosses (n.dir >=
 * 0.2). The volume cut by it counts the same at every visible point: z-pass counts the crossings
 * on the segment from the near plane to the point, which lies in front of the plane, where the
 * cut volume's sides are the whole volume's. Cutting each swept point to a plane of its own would
 * not do: the cut sides' far edges could then pass through the scene. Of the planes normal to the
 * sweep through the caster's centre or to a face of `scene`, the one nearest the caster along
 * that sweep. (0, 0, 0, 0) when none qualifies (the volume then goes to infinity): `scene`
 * invalid, or a point light so near the caster's box that its swept directions spread too far.
 */
VTKPENUMBRAGEOMETRY_EXPORT glm::dvec4 VolumeEndPlane(const glm::dvec3& casterMin,
  const glm::dvec3& casterMax, const glm::dvec4& light, const Box& scene,
  const std::array<glm::dvec3, 4>& nearCorners);

/**
 * How far a z-fail shadow volume's swept points go under a parallel projection, which draws a
 * far end at infinity nowhere (ProjectsInfinityToInfinity) although it lies behind every pixel
 * or none: object-space length along each swept direction (the shader scales each direction to
 * it), so that every swept point lies 1000 times farther from the light (positional) or from
 * the caster (directional) than any point of `scene`, the caster's box and the near rectangle
 * lies from it. The volume, closed by its dark cap there, then holds the same visible points
 * as the volume to infinity, unless a caster triangle spans within 0.1 degrees of a half turn
 * seen from the light. (1e4 put swept points so far out that llvmpipe's clipping drew slivers
 * along the window's edge.) 0 (to infinity) where the matrix cannot be inverted or a box is
 * invalid.
 */
VTKPENUMBRAGEOMETRY_EXPORT double ParallelSweepLength(const glm::dmat4& objectToWorld,
  const glm::dvec3& casterMin, const glm::dvec3& casterMax, const glm::dvec4& light,
  const Box& scene, const std::array<glm::dvec3, 4>& nearCorners);

/**
 * Where a prop's cells are, finer than its bounds: a grid of Resolution^3 cells over the bounds,
 * each holding the bounds of what the boxes added put inside it, three of them: one for the
 * boxes thinnest along x, one along y, one along z. A room's walls fill thin boxes along them,
 * its corners too, and leave its inside empty, so that an eye inside the room, even in a corner,
 * still has geometry at a distance for the tight depth range, where the room's bounds would hold
 * the eye (TightClippingRange).
 */
class VTKPENUMBRAGEOMETRY_EXPORT OccupancyGrid
{
public:
  static constexpr int Resolution = 8;

  /// A grid over `bounds`; every box added later is clamped to them.
  explicit OccupancyGrid(const Box& bounds);
  /// Adds the box min..max to the grid cells it overlaps (its faces included), cut to each.
  /// False, adding nothing, for a box that is not finite: a cell with a NaN point, of which VTK
  /// may still draw the parts (a polygon's triangles, a polyline's segments) that avoid it, so
  /// the caller should fall back to the data's bounds.
  bool Add(const glm::dvec3& min, const glm::dvec3& max);
  /// The filled cells' boxes: together they hold every box added. Invalid bounds give one
  /// invalid box: nothing is known.
  std::vector<Box> Boxes() const;

private:
  /// Cell `index`'s face along `axis` (index 0 to Resolution): the bounds' exactly at the ends.
  double Face(int index, int axis) const;

  Box Bounds;
  /// Resolution^3, x fastest: per cell, the boxes thinnest along x, y and z; invalid where none
  std::vector<std::array<Box, 3>> Cells;
};

/**
 * The camera clipping range (near, far) narrowed to the view depths of what the view frustum
 * holds of the boxes of the props drawn (`props`, one box each): `worldToView` is VTK's view
 * matrix (looking down -z), `worldToClip` the projection (with `current` as its range) times it,
 * in OpenGL's clip space. Only those parts can reach the depth buffer, so props behind the eye
 * or out of view, and a prop whose bounds reach far out of view, do not widen the range. A prop
 * wholly in front of the eye keeps its box's nearest depth: a near plane moved up to the nearest
 * point in view would cut more shadow volumes, which then need z-fail. A relative margin of
 * 1e-3 keeps everything in view unclipped, and the range is never wider than `current`;
 * `current` itself where nothing is in view (a box holding the eye is cut at the near plane,
 * which its range then keeps), or where a box or the matrix is invalid or not finite. A 24-bit
 * depth buffer's steps then span the visible scene's depth, not VTK's range, which is expanded by
 * half its length and has its near plane clamped to 1/1000 of the far one. The near plane stays at
 * most 0.8 of the far one, so that a thin or distant scene's (far + near) / (far - near), by which
 * the vertex transforms' float depth loses precision, is at most 9.
 */
VTKPENUMBRAGEOMETRY_EXPORT glm::dvec2 TightClippingRange(const std::vector<Box>& props,
  const glm::dmat4& worldToView, const glm::dmat4& worldToClip, const glm::dvec2& current);

} // namespace penumbra

#endif
