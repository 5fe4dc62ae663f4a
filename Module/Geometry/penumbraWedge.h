/**
 * @file penumbraWedge.h
 * @brief Penumbra wedges of silhouette edges and the light they let through, without OpenGL.
 *
 * Akenine-Möller and Assarsson's penumbra wedges, with the light-intensity function written
 * exactly (their later soft shadow volumes): seen from a receiver point p, an area light is a
 * disk (a sphere's gnomonic image on the plane through its centre, or a directional light's cone
 * of directions on the plane at unit distance) and the silhouette from the light's centre
 * projects to a closed polygon. By Green's theorem the occluded part of the disk is
 *
 *   occluded(p) = [centre occluded] + sum over silhouette edges of m_e * c_e(p),
 *
 * c_e = (area of triangle(centre, a', b') inside the disk - the disk sector it spans) / disk area,
 * with a'b' the projected edge. c_e is exactly zero unless a'b' crosses the disk, i.e. unless p
 * lies in the edge's wedge, and it is continuous in p: neighbouring wedges agree on their shared
 * side planes by construction, with no interpolation. The centre term is the hard shadow volume.
 * Approximations (documented): one silhouette, the one seen from the light's centre, and
 * overlapping occluders add before clamping.
 */
#ifndef penumbraWedge_h
#define penumbraWedge_h

#include "penumbraConvexClip.h"
#include "vtkPenumbraGeometryModule.h" // for export macro

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace penumbra
{

/**
 * The signed occlusion correction c_e of edge a -> b (walked counter-clockwise as seen from the
 * light) for receiver point p, as a fraction of the light's disk. `light` is (centre, 1) with
 * `radius` in world units, or (direction towards the light, 0) with `radius` its angular radius
 * in radians. Returns 0 when the edge cannot cover part of the light from p (outside the wedge,
 * behind p, or p inside the light).
 */
VTKPENUMBRAGEOMETRY_EXPORT double EdgeOcclusion(const glm::dvec3& p, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec4& light, double radius);

/**
 * The wedge of edge a -> b: the convex region of points that can see the edge cross the light,
 * bounded by the two planes through the edge tangent to the light (front, back) and one plane at
 * each end. Valid is false when the edge is too close to the light, or points straight at it,
 * for the planes to exist; such an edge projects to (almost) a point and its correction is
 * negligible (EdgeOcclusion still computes it exactly where asked).
 */
struct VTKPENUMBRAGEOMETRY_EXPORT Wedge
{
  bool Valid = false;
  /// Outward unit normals and offsets: inside means dot(n, x) <= d for all four planes.
  std::array<glm::dvec3, 4> Normals;
  std::array<double, 4> Offsets;
  /// a, b, then the directions (w = 0) of the four far edges: front-a, front-b, back-a, back-b.
  std::array<glm::dvec4, 6> Vertices;

  static Wedge Build(
    const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light, double radius);
  bool Contains(const glm::dvec3& x, double tolerance = 0.0) const;
  /// The four planes as half-spaces, for ClipBox.
  std::vector<HalfSpace> HalfSpaces() const;
  /// The wedge's boundary as 8 outward triangles (indices into Vertices): front, back, two sides
  /// and the far end at infinity; a ray meets it once leaving, whatever its origin.
  static const std::array<unsigned int, 24>& Triangles();
};

/**
 * A convex bound for an edge that has no Wedge because its line passes through the light (the
 * edge points at the light): every point from which the edge can be seen crossing the light lies
 * in this square pyramid, open to infinity away from the light.
 * - Positional light: apex at the light's centre. A point p that sees edge point E in front of
 *   light point X lies on the ray from X through E, and the angle at the centre between p and E is
 *   below atan(r / (|E - c| - r)); the pyramid circumscribes the cone of the edge's directions
 *   from the centre widened by that angle.
 * - Directional light (radius an angle): such points are the edge swept along the cone of
 *   directions away from the light. Apex at the edge's end nearer the light, axis away from it,
 *   half-angle the larger of the radius and the edge's angle to the axis: the pyramid holds both
 *   the cone and the edge, so their sum. It is as narrow as the light's own cone, where the
 *   receivers' box (all the viewport, for a terrain) was the only bound before.
 * Valid is false for an edge reaching into a positional light or a bound wider than 60 degrees:
 * then the whole viewport is the only bound.
 */
struct VTKPENUMBRAGEOMETRY_EXPORT LightPyramid
{
  bool Valid = false;
  /// The apex (the light's centre, w = 1), then the four edge directions (w = 0).
  std::array<glm::dvec4, 5> Vertices;
  /// Outward unit normals of the four side planes, all through the apex.
  std::array<glm::dvec3, 4> Normals;

  static LightPyramid Build(
    const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light, double radius);
  bool Contains(const glm::dvec3& x, double tolerance = 0.0) const;
  /// The four side planes as half-spaces, for ClipBox.
  std::vector<HalfSpace> HalfSpaces() const;
  /// Six outward triangles (indices into Vertices): four sides and the far end at infinity.
  static const std::array<unsigned int, 18>& Triangles();
};

} // namespace penumbra

#endif
