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

std::vector<DiskPoint> SunflowerPoints(int count)
{
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  std::vector<DiskPoint> points;
  for (int k = 0; k < count; ++k)
  {
    points.push_back({ (k + 0.5) / count, k * golden });
  }
  return points;
}

std::vector<DiskPoint> PolarRingPoints(int count)
{
  if (count <= 0)
  {
    return {};
  }
  const int rings = std::max(1, static_cast<int>(std::lround(std::sqrt(count / 3.14159265358979))));
  std::vector<int> perRing(rings);
  int assigned = 0;
  for (int i = 0; i < rings; ++i)
  {
    // Ring i has area share (2i + 1) / rings^2; the remainder goes to the outer rings.
    perRing[i] = static_cast<int>(std::floor(count * (2.0 * i + 1.0) / (rings * rings)));
    assigned += perRing[i];
  }
  for (int i = rings - 1; assigned < count; i = (i + rings - 1) % rings)
  {
    ++perRing[i];
    ++assigned;
  }
  std::vector<DiskPoint> points;
  int before = 0;
  for (int i = 0; i < rings; ++i)
  {
    // At the middle of the ring's area, so that each sample stands for an equal area.
    const double area = (before + 0.5 * perRing[i]) / count;
    for (int j = 0; j < perRing[i]; ++j)
    {
      points.push_back({ area, 2.0 * 3.14159265358979 * (j + 0.5 * (i % 2)) / perRing[i] });
    }
    before += perRing[i];
  }
  return points;
}

std::vector<glm::dvec4> PlaceOnLight(const glm::dvec4& light, double radius,
  const std::vector<DiskPoint>& points, const glm::dvec3& target)
{
  std::vector<glm::dvec4> samples;
  samples.reserve(points.size());
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
    for (const DiskPoint& q : points)
    {
      const double rho = radius * std::sqrt(q.AreaFraction), phi = q.Angle;
      samples.emplace_back(centre + rho * (std::cos(phi) * u + std::sin(phi) * v), 1.0);
    }
    return samples;
  }
  const double cosMax = std::cos(glm::radians(radius));
  for (const DiskPoint& q : points)
  {
    const double cosTheta = 1.0 - q.AreaFraction * (1.0 - cosMax);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta)), phi = q.Angle;
    samples.emplace_back(cosTheta * axis + sinTheta * (std::cos(phi) * u + std::sin(phi) * v), 0.0);
  }
  return samples;
}

std::vector<glm::dvec4> SpreadLightSamples(
  const glm::dvec4& light, double radius, int count, const glm::dvec3& target)
{
  return PlaceOnLight(light, radius, SunflowerPoints(count), target);
}

glm::dvec4 CountingReference(const glm::dvec4& light, double radius)
{
  // Irrational-looking ratios: no plane of a scene built from round numbers holds it.
  const glm::dvec3 off = glm::normalize(glm::dvec3(0.5773502, 0.6180340, -0.5320889));
  const double offset = CountingReferenceOffset * radius;
  if (light.w != 0.0)
  {
    return glm::dvec4(glm::dvec3(light) + offset * off, 1.0);
  }
  const glm::dvec3 direction(light);
  const glm::dvec3 across = glm::normalize(off - glm::dot(off, direction) * direction);
  return glm::dvec4(std::cos(offset) * direction + std::sin(offset) * across, 0.0);
}

} // namespace penumbra
