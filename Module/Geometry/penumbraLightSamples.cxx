#include "penumbraLightSamples.h"

#include <algorithm>
#include <cmath>

namespace penumbra
{

void PlaneBasis(const glm::dvec3& axis, glm::dvec3& e1, glm::dvec3& e2)
{
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  e1 = glm::normalize(glm::cross(helper, axis));
  e2 = glm::cross(axis, e1);
}

std::vector<glm::dvec4> SpreadLightSamples(
  const glm::dvec4& light, double radius, int count, const glm::dvec3& target)
{
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  std::vector<glm::dvec4> samples;
  samples.reserve(count);
  glm::dvec3 axis;
  if (light.w != 0.0)
  {
    axis = target - glm::dvec3(light);
    axis = glm::length(axis) > 0.0 ? glm::normalize(axis) : glm::dvec3(0, 0, 1);
  }
  else
  {
    axis = glm::dvec3(light);
  }
  // The pattern turns from -e1 towards -e2 (the orientation every figure was measured with).
  glm::dvec3 e1, e2;
  PlaneBasis(axis, e1, e2);
  const glm::dvec3 u = -e1, v = -e2;
  if (light.w != 0.0)
  {
    const glm::dvec3 centre(light);
    for (int k = 0; k < count; ++k)
    {
      const double rho = radius * std::sqrt((k + 0.5) / count), phi = k * golden;
      samples.emplace_back(centre + rho * (std::cos(phi) * u + std::sin(phi) * v), 1.0);
    }
    return samples;
  }
  const double cosMax = std::cos(glm::radians(radius));
  for (int k = 0; k < count; ++k)
  {
    const double cosTheta = 1.0 - (k + 0.5) / count * (1.0 - cosMax);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta)), phi = k * golden;
    samples.emplace_back(cosTheta * axis + sinTheta * (std::cos(phi) * u + std::sin(phi) * v), 0.0);
  }
  return samples;
}

} // namespace penumbra
