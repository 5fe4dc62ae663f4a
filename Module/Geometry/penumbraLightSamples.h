/**
 * @file penumbraLightSamples.h
 * @brief Points spread evenly over an area light, and the plane basis the light math shares.
 */
#ifndef penumbraLightSamples_h
#define penumbraLightSamples_h

#include "vtkPenumbraGeometryModule.h" // for export macro

#include <glm/glm.hpp>

#include <vector>

namespace penumbra
{

/// Two unit vectors with e1 x e2 = axis (a unit vector).
VTKPENUMBRAGEOMETRY_EXPORT void PlaneBasis(const glm::dvec3& axis, glm::dvec3& e1, glm::dvec3& e2);

/// A point of the unit disk: the share of the disk's area within its radius (rho^2), and its
/// angle. Patterns are written this way so that the disk and the cone take them exactly.
struct DiskPoint
{
  double AreaFraction;
  double Angle;
};

/// N equal-weight points of Vogel's sunflower: equal-area steps, golden-angle turns.
VTKPENUMBRAGEOMETRY_EXPORT std::vector<DiskPoint> SunflowerPoints(int count);

/**
 * N equal-weight points on concentric equal-area rings (about sqrt(N / pi) of them), each ring
 * with samples in proportion to its area, evenly spaced, every ring turned by half a step
 * against its neighbour so that no two rings line up along a spoke.
 */
VTKPENUMBRAGEOMETRY_EXPORT std::vector<DiskPoint> PolarRingPoints(int count);

/**
 * Places unit-disk points on an area light: a positional light (centre, 1) of radius r on the
 * disk through its centre facing `target`, a directional light (unit direction towards it, 0)
 * of angular radius `radius` degrees on the cone of directions of that half-angle, uniformly in
 * solid angle (the area fraction maps to 1 - cos(theta)).
 */
VTKPENUMBRAGEOMETRY_EXPORT std::vector<glm::dvec4> PlaceOnLight(const glm::dvec4& light,
  double radius, const std::vector<DiskPoint>& points, const glm::dvec3& target);

/**
 * Samples spread evenly over an area light (Vogel's sunflower: equal-area rings, golden-angle
 * turns), so each carries weight 1/N. A positional light (centre, 1) of radius r is sampled on
 * the disk through its centre facing `target` (the light as the casters see it); a directional
 * light (unit direction towards it, 0) of angular radius `radius` degrees on the cone of
 * directions of that half-angle, uniformly in solid angle: PlaceOnLight of SunflowerPoints.
 */
VTKPENUMBRAGEOMETRY_EXPORT std::vector<glm::dvec4> SpreadLightSamples(
  const glm::dvec4& light, double radius, int count, const glm::dvec3& target);

/// The share of a light's radius by which counting's reference point lies off its centre.
constexpr double CountingReferenceOffset = 0.01;

/**
 * The point on a light from which soft shadow volumes count (the centre's volume and the edges'
 * crossings start there): any point of the light gives the same counts, and this one lies off
 * every plane through the centre that round numbers make (the light at a box's top, a ground at
 * the light's height), where the centre's volume has faces edge-on to it and its count ties.
 * A positional light (centre, 1) of radius r: the centre moved by CountingReferenceOffset * r
 * along a fixed direction with no zero component; a directional light (unit direction, 0) of
 * angular radius `radius` radians: its direction turned by about that share of the radius.
 */
VTKPENUMBRAGEOMETRY_EXPORT glm::dvec4 CountingReference(const glm::dvec4& light, double radius);

} // namespace penumbra

#endif
