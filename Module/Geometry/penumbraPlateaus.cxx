#include "penumbraPlateaus.h"

#include "penumbraLightSamples.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace penumbra
{

namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Projections onto the plane along rays from the light, for one light.
class Projector
{
public:
  Projector(const ReceiverPlane& plane, const glm::dvec4& light, double radius)
    : Plane(plane)
    , Light(light)
    , Radius(radius)
  {
  }

  /// Whether the light can shadow the plane at all (above it, or shining down on it).
  bool LightAbovePlane() const
  {
    return this->Light.w != 0.0 ? this->Plane.Height(glm::dvec3(this->Light)) > 0.0
                                : glm::dot(this->Plane.Normal, glm::dvec3(this->Light)) > 0.0;
  }

  /// Whether x lies strictly between the plane's level and the light's (it can cast).
  bool CanCast(const glm::dvec3& x) const
  {
    if (this->Light.w == 0.0)
    {
      return true;
    }
    return this->Plane.Height(x) < (1.0 - 1e-6) * this->Plane.Height(glm::dvec3(this->Light));
  }

  /// The hard shadow of x from the light's centre, in plane coordinates. Points below the plane
  /// project to where the ray from the light crosses it.
  glm::dvec2 Centre(const glm::dvec3& x) const
  {
    if (this->Light.w == 0.0)
    {
      return this->Along(x, glm::dvec3(this->Light));
    }
    return this->Along(x, glm::dvec3(this->Light) - x);
  }

  /// The light's rim projected through x onto the plane: the outer edge of x's penumbra.
  std::vector<glm::dvec2> Rim(const glm::dvec3& x, int segments) const
  {
    glm::dvec3 axis = this->Light.w != 0.0 ? glm::dvec3(this->Light) - x : glm::dvec3(this->Light);
    const double distance = glm::length(axis);
    axis /= distance;
    glm::dvec3 e1, e2;
    PlaneBasis(axis, e1, e2);
    std::vector<glm::dvec2> rim(static_cast<std::size_t>(segments));
    for (int k = 0; k < segments; ++k)
    {
      const double phi = 2.0 * Pi * k / segments;
      const glm::dvec3 offset = std::cos(phi) * e1 + std::sin(phi) * e2;
      // Towards a point of the rim: the positional light's circle facing x, or the cone edge.
      const glm::dvec3 towards = this->Light.w != 0.0
        ? axis * distance + this->Radius * offset
        : std::cos(this->Radius) * axis + std::sin(this->Radius) * offset;
      rim[static_cast<std::size_t>(k)] = this->Along(x, towards);
    }
    return rim;
  }

private:
  /// Where the ray from x away from `towards` meets the plane. A rim direction at or below the
  /// horizon never meets it: the point is pushed out to a bounded distance instead (the
  /// penumbra of a light on the horizon is unbounded).
  glm::dvec2 Along(const glm::dvec3& x, const glm::dvec3& towards) const
  {
    const double h = std::max(this->Plane.Height(x), 0.0);
    const double rise = glm::dot(this->Plane.Normal, towards);
    const double length = glm::length(towards);
    const double minimumRise = 1e-3 * length; // about 0.06 degrees above the horizon
    const glm::dvec3 foot = x - this->Plane.Normal * this->Plane.Height(x);
    // The horizontal part of -towards, scaled so that it descends h over the way.
    const glm::dvec3 horizontal = towards - this->Plane.Normal * rise;
    const glm::dvec3 hit = foot - horizontal * (h / std::max(rise, minimumRise));
    return this->Plane.ToPlane(hit);
  }

  const ReceiverPlane& Plane;
  glm::dvec4 Light;
  double Radius;
};

void Emit(std::vector<PlateauVertex>& out, const glm::dvec2& p, double t)
{
  out.push_back({ static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(t) });
}

/// Extent of `points` around `centre` along `direction` (0 if all lie behind).
double Support(
  const std::vector<glm::dvec2>& points, const glm::dvec2& centre, const glm::dvec2& direction)
{
  double extent = 0.0;
  for (const glm::dvec2& q : points)
  {
    extent = std::max(extent, glm::dot(q - centre, direction));
  }
  return extent;
}
} // namespace

bool ReceiverPlane::Make(const glm::dvec3& origin, const glm::dvec3& normal, ReceiverPlane& plane)
{
  const double length = glm::length(normal);
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(origin.x) ||
    !std::isfinite(origin.y) || !std::isfinite(origin.z))
  {
    return false;
  }
  plane.Origin = origin;
  plane.Normal = normal / length;
  PlaneBasis(plane.Normal, plane.U, plane.V);
  return true;
}

bool ReceiverPlane::MakeNear(
  const glm::dvec3& origin, const glm::dvec3& normal, const glm::dvec3& near, ReceiverPlane& plane)
{
  if (!Make(origin, normal, plane))
  {
    return false;
  }
  const glm::dvec3 nearest = near - plane.Height(near) * plane.Normal;
  if (std::isfinite(nearest.x) && std::isfinite(nearest.y) && std::isfinite(nearest.z))
  {
    plane.Origin = nearest;
  }
  return true;
}

bool FitReceiverPlane(const std::vector<glm::dvec3>& points, PlaneFit& fit)
{
  std::vector<glm::dvec3> finite;
  for (const glm::dvec3& p : points)
  {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
    {
      finite.push_back(p);
    }
  }
  glm::dvec3 normal(0.0);
  if (finite.size() >= 3)
  {
    const glm::dvec3 a = finite.front();
    glm::dvec3 b = a;
    for (const glm::dvec3& p : finite)
    {
      b = glm::distance(p, a) > glm::distance(b, a) ? p : b;
    }
    for (const glm::dvec3& p : finite)
    {
      const glm::dvec3 n = glm::cross(b - a, p - a);
      normal = glm::dot(n, n) > glm::dot(normal, normal) ? n : normal;
    }
  }
  glm::dvec3 centre(0.0);
  for (const glm::dvec3& p : finite)
  {
    centre += p / static_cast<double>(finite.size());
  }
  if (!ReceiverPlane::Make(centre, normal, fit.Plane))
  {
    return false;
  }
  fit.Min = glm::dvec2(std::numeric_limits<double>::max());
  fit.Max = -fit.Min;
  fit.Thickness = 0.0;
  for (const glm::dvec3& p : finite)
  {
    fit.Min = glm::min(fit.Min, fit.Plane.ToPlane(p));
    fit.Max = glm::max(fit.Max, fit.Plane.ToPlane(p));
    fit.Thickness = std::max(fit.Thickness, std::abs(fit.Plane.Height(p)));
  }
  fit.Extent = glm::length(fit.Max - fit.Min);
  return true;
}

double PlateauIntensity(double t, PlateauFalloff falloff)
{
  t = std::min(1.0, std::max(0.0, t));
  return falloff == PlateauFalloff::Linear ? t : 0.5 * (1.0 - std::cos(Pi * t));
}

PlateauReport BuildPlateaus(const CasterTopology& topo, const ShadowVolume& volume,
  const glm::dmat4& objectToWorld, const glm::dvec4& light, double radius,
  const ReceiverPlane& plane, std::vector<PlateauVertex>& triangles, const PlateauOptions& options)
{
  PlateauReport report;
  const Projector project(plane, light, radius);
  if (!project.LightAbovePlane() || !(radius >= 0.0))
  {
    return report;
  }
  const std::size_t n = topo.Points.size();
  auto world = [&](std::uint32_t i)
  { return glm::dvec3(objectToWorld * glm::dvec4(topo.Points[i], 1.0)); };
  // Geometry on (or under) the plane cannot shadow it: the receiver itself, when it casts too.
  const double onPlane = 1e-6 *
    glm::length(glm::dvec3(objectToWorld * glm::dvec4(topo.BoundsMax - topo.BoundsMin, 0.0)));
  auto above = [&](const glm::dvec3& x) { return plane.Height(x) > onPlane; };

  // The hard drop shadow: the casting triangles (the light cap) at depth 0.
  const std::vector<std::uint32_t>& cap = volume.LightCap;
  for (std::size_t i = 0; i + 2 < cap.size(); i += 3)
  {
    const glm::dvec3 a = world(cap[i] % n), b = world(cap[i + 1] % n), c = world(cap[i + 2] % n);
    if (!above(a) && !above(b) && !above(c))
    {
      continue;
    }
    if (!project.CanCast(a) || !project.CanCast(b) || !project.CanCast(c))
    {
      ++report.SkippedAboveLight;
      continue;
    }
    Emit(triangles, project.Centre(a), 0.0);
    Emit(triangles, project.Centre(b), 0.0);
    Emit(triangles, project.Centre(c), 0.0);
    ++report.ShadowTriangles;
  }
  if (!(radius > 0.0))
  {
    return report;
  }

  // Cones: at every silhouette vertex, from its hard shadow (t = 0) to its projected rim (1).
  std::map<std::uint32_t, std::vector<glm::dvec2>> rims;
  for (const SilhouetteEdge& edge : volume.Silhouette)
  {
    for (const std::uint32_t v : { edge.From, edge.To })
    {
      const glm::dvec3 x = world(v);
      if (rims.count(v) || !above(x) || !project.CanCast(x))
      {
        continue;
      }
      const std::vector<glm::dvec2>& rim = rims[v] = project.Rim(x, options.RimSegments);
      const glm::dvec2 centre = project.Centre(x);
      for (std::size_t k = 0; k < rim.size(); ++k)
      {
        Emit(triangles, centre, 0.0);
        Emit(triangles, rim[k], 1.0);
        Emit(triangles, rim[(k + 1) % rim.size()], 1.0);
      }
      ++report.Cones;
    }
  }

  // Sheets: along every silhouette edge, on both sides of its hard shadow (the side towards the
  // umbra is hidden by the drop shadow at depth 0), as wide as the projected rim at each sample.
  const int segments = std::max(1, options.SheetSegments);
  for (const SilhouetteEdge& edge : volume.Silhouette)
  {
    const glm::dvec3 a = world(edge.From), b = world(edge.To);
    if ((!above(a) && !above(b)) || !project.CanCast(a) || !project.CanCast(b))
    {
      continue;
    }
    const glm::dvec2 pa = project.Centre(a), pb = project.Centre(b);
    const glm::dvec2 along = pb - pa;
    if (!(glm::dot(along, along) > 0.0))
    {
      continue; // the edge points at the light: its cones cover it
    }
    const glm::dvec2 across = glm::normalize(glm::dvec2(-along.y, along.x));
    std::vector<glm::dvec2> centres, outer[2];
    for (int i = 0; i <= segments; ++i)
    {
      const glm::dvec3 x = glm::mix(a, b, double(i) / segments);
      const glm::dvec2 centre = project.Centre(x);
      const std::vector<glm::dvec2> rim = project.Rim(x, options.RimSegments);
      centres.push_back(centre);
      outer[0].push_back(centre + across * Support(rim, centre, across));
      outer[1].push_back(centre - across * Support(rim, centre, -across));
    }
    for (const auto& side : outer)
    {
      for (int i = 0; i < segments; ++i)
      {
        Emit(triangles, centres[i], 0.0);
        Emit(triangles, centres[i + 1], 0.0);
        Emit(triangles, side[i + 1], 1.0);
        Emit(triangles, centres[i], 0.0);
        Emit(triangles, side[i + 1], 1.0);
        Emit(triangles, side[i], 1.0);
      }
    }
    ++report.Sheets;
  }
  return report;
}

} // namespace penumbra
