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

/**
 * Samples spread evenly over an area light (Vogel's sunflower: equal-area rings, golden-angle
 * turns), so each carries weight 1/N. A positional light (centre, 1) of radius r is sampled on
 * the disk through its centre facing `target` (the light as the casters see it); a directional
 * light (unit direction towards it, 0) of angular radius `radius` degrees on the cone of
 * directions of that half-angle, uniformly in solid angle.
 */
VTKPENUMBRAGEOMETRY_EXPORT std::vector<glm::dvec4> SpreadLightSamples(
  const glm::dvec4& light, double radius, int count, const glm::dvec3& target);

} // namespace penumbra

#endif
