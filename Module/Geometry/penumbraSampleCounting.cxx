#include "penumbraSampleCounting.h"

#include "penumbraShadowVolume.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace penumbra
{

LightFacing FacingOverLight(
  const glm::dvec3& normal, const glm::dvec3& point, const glm::dvec4& light, double radius)
{
  // The sign is ShadowVolume::Facing's, so that a radius of 0 gives exactly the centre's
  // silhouette and any radius a superset of it.
  const double d = ShadowVolume::LightSide(normal, point, light);
  const LightFacing sign =
    d > 0.0 ? LightFacing::Towards : (d < 0.0 ? LightFacing::Away : LightFacing::EdgeOn);
  if (!(radius > 0.0))
  {
    return sign;
  }
  // Within the light's reach of the plane: |d| <= r |n| for a sphere of radius r, and
  // |d| <= sin(r) |n| |l| for a cone of half-angle r around direction l. Undecidable lengths
  // (overflow, underflow, NaN) count as mixed: a potential silhouette too many costs a wedge.
  const double normalLength = glm::length(normal);
  const double reach = light.w != 0.0
    ? radius
    : std::sin(std::min(radius, 1.5707963267948966)) * glm::length(glm::dvec3(light));
  const double bound = reach * normalLength;
  if (!(normalLength > 0.0) || !std::isfinite(bound) || !std::isfinite(d) || !(bound > 0.0))
  {
    return LightFacing::Mixed;
  }
  return std::abs(d) <= bound ? LightFacing::Mixed : sign;
}

std::vector<std::uint32_t> PotentialSilhouette(const CasterTopology& topo,
  const glm::dmat4& objectToWorld, const glm::dvec4& light, double radius, bool frontFacesOnly)
{
  std::vector<glm::dvec3> world(topo.Points.size());
  for (std::size_t i = 0; i < world.size(); ++i)
  {
    world[i] = glm::dvec3(objectToWorld * glm::dvec4(topo.Points[i], 1.0));
  }
  // A mirroring matrix turns outward normals inward: "front" must follow the true orientation.
  const bool mirrored = glm::determinant(glm::dmat3(objectToWorld)) < 0.0;
  std::vector<LightFacing> facing(topo.Triangles.size());
  for (std::size_t t = 0; t < facing.size(); ++t)
  {
    const glm::uvec3& tri = topo.Triangles[t];
    const glm::dvec3 normal = glm::cross(world[tri.y] - world[tri.x], world[tri.z] - world[tri.x]);
    facing[t] = FacingOverLight(mirrored ? -normal : normal, world[tri.x], light, radius);
  }
  std::vector<std::uint32_t> edges;
  for (std::uint32_t e = 0; e < topo.Edges.size(); ++e)
  {
    const Edge& edge = topo.Edges[e];
    int multiplicity = 0;
    bool mixed = false;
    for (std::uint32_t u = edge.FirstUse; u < edge.FirstUse + edge.UseCount; ++u)
    {
      const LightFacing f = facing[topo.Uses[u].Triangle];
      mixed = mixed || f == LightFacing::Mixed;
      const int weight = frontFacesOnly ? (f == LightFacing::Towards ? 1 : 0) : static_cast<int>(f);
      multiplicity += topo.Uses[u].Sign * weight;
    }
    if (mixed || multiplicity != 0)
    {
      edges.push_back(e);
    }
  }
  return edges;
}

int MultiplicityFrom(const glm::dvec3& p, const glm::dvec3& a, const EdgeFace* faces, int faceCount,
  bool frontFacesOnly)
{
  int multiplicity = 0;
  for (int k = 0; k < faceCount; ++k)
  {
    const double side = glm::dot(faces[k].Normal, p - a);
    const int weight = frontFacesOnly ? (side > 0.0 ? 1 : 0) : (side > 0.0) - (side < 0.0);
    multiplicity += faces[k].Sign * weight;
  }
  return multiplicity;
}

std::vector<HalfSpace> SilhouetteSector(const Wedge& wedge, const glm::dvec3& a,
  const glm::dvec3& b, const EdgeFace* faces, int faceCount, bool frontFacesOnly, double margin)
{
  const glm::dvec3 edge = b - a;
  const double length = glm::length(edge);
  if (!wedge.Valid || faceCount != 2 || !(length > 0.0) || !std::isfinite(length))
  {
    return {};
  }
  // Every plane here contains the edge's line: work in the plane across it.
  const glm::dvec3 d = edge / length;
  const glm::dvec3 seed = std::abs(d.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(d, seed)), e2 = glm::cross(d, e1);
  auto across = [&](const glm::dvec3& n)
  {
    const glm::dvec2 v(glm::dot(n, e1), glm::dot(n, e2));
    const double l = glm::length(v);
    return l > 0.0 ? v / l : glm::dvec2(0.0);
  };
  const glm::dvec2 f0 = across(faces[0].Normal), f1 = across(faces[1].Normal);
  const double det = f0.x * f1.y - f0.y * f1.x;
  if (!(std::abs(det) > 1e-9))
  {
    return {};
  }
  auto perpendicular = [](const glm::dvec2& n) { return glm::dvec2(-n.y, n.x); };
  int found = 0;
  glm::ivec2 chosen(0);
  for (int s0 : { -1, 1 })
  {
    for (int s1 : { -1, 1 })
    {
      // The point across the edge with f0.x = s0 and f1.x = s1 lies inside this sector.
      const glm::dvec2 x((s0 * f1.y - s1 * f0.y) / det, (s1 * f0.x - s0 * f1.x) / det);
      const glm::dvec3 p = a + length * (x.x * e1 + x.y * e2);
      if (MultiplicityFrom(p, a, faces, faceCount, frontFacesOnly) == 0)
      {
        continue;
      }
      // Sector and wedge meet in a cone of the plane: inside means h.x < 0 for all four. Its
      // extreme rays lie on the lines, so some bisector of two of them is strictly inside.
      const std::array<glm::dvec2, 4> bounds = { across(wedge.Normals[0]), across(wedge.Normals[1]),
        -double(s0) * f0, -double(s1) * f1 };
      std::vector<glm::dvec2> rays;
      for (const glm::dvec2& h : bounds)
      {
        rays.push_back(perpendicular(h));
        rays.push_back(-perpendicular(h));
      }
      bool meets = false;
      for (std::size_t i = 0; i < rays.size() && !meets; ++i)
      {
        for (std::size_t j = i + 1; j < rays.size() && !meets; ++j)
        {
          const glm::dvec2 c = rays[i] + rays[j];
          meets = glm::length(c) > 1e-9 &&
            std::all_of(bounds.begin(), bounds.end(),
              [&](const glm::dvec2& h) { return glm::dot(h, c) < -1e-9 * glm::length(c); });
        }
      }
      if (meets)
      {
        ++found;
        chosen = glm::ivec2(s0, s1);
      }
    }
  }
  if (found != 1)
  {
    return {};
  }
  std::vector<HalfSpace> halfSpaces;
  for (int k = 0; k < 2; ++k)
  {
    const glm::dvec3 outward = -double(chosen[k]) * glm::normalize(faces[k].Normal);
    halfSpaces.push_back({ outward, glm::dot(outward, a) + margin });
  }
  return halfSpaces;
}

double SideOfEdgePlane(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& throughLight)
{
  return glm::dot(a - p, throughLight);
}

glm::dvec3 EdgeLightNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light)
{
  return glm::cross(b - a, glm::dvec3(light) - light.w * a);
}

int SampleCrossing(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
  const glm::dvec4& centre, const glm::dvec4& sample)
{
  // Sides of the plane (p, edge), as p's side of the planes through the edge and each light
  // point: the centre's is the side plane of its shadow volume, so the sign agrees with the
  // rasterized count wherever p is not within rounding of that plane.
  const double dc = SideOfEdgePlane(p, a, EdgeLightNormal(a, b, centre));
  const double ds = SideOfEdgePlane(p, a, EdgeLightNormal(a, b, sample));
  if (!((dc < 0.0 && ds > 0.0) || (dc > 0.0 && ds < 0.0)))
  {
    return 0; // same side of the plane (p, a, b), on it, or degenerate
  }
  // The edge's ends on opposite sides of the plane through p and the path: a predicate of p, the
  // path and one end alone, so that edges meeting at a vertex decide it alike.
  const glm::dvec3 towardsCentre = glm::dvec3(centre) - centre.w * p;
  const glm::dvec3 towardsSample = glm::dvec3(sample) - sample.w * p;
  const glm::dvec3 pathNormal = glm::cross(towardsCentre, towardsSample);
  const double sa = glm::dot(a - p, pathNormal), sb = glm::dot(b - p, pathNormal);
  if (!((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0)))
  {
    return 0;
  }
  // The crossing x seen from p is alpha (a - p) + beta (b - p); alpha + beta (times |n|^2) must
  // be positive (in front of p) and, for a light point, at least 1 (the edge nearer than it).
  const glm::dvec3 u = a - p, e = b - a, n = glm::cross(u, e);
  const double t = dc / (dc - ds);
  const glm::dvec3 x = towardsCentre + t * (towardsSample - towardsCentre);
  const double along = glm::dot(x, glm::cross(e, n));
  if (!(centre.w != 0.0 ? along >= glm::dot(n, n) : along > 0.0))
  {
    return 0;
  }
  return ds > 0.0 ? 1 : -1;
}

bool EdgePlaneMissesSamples(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
  const glm::dvec4& centre, double spread)
{
  // cross(a - p, b - a) . (centre - w a) is the centre's side of the plane (p, a, b) times its
  // normal's length; a sample moves it by at most spread times that length.
  const glm::dvec3 sampleSide = glm::cross(a - p, b - a);
  const glm::dvec3 edgeToCentre = glm::dvec3(centre) - centre.w * a;
  return std::abs(glm::dot(edgeToCentre, sampleSide)) >
    (spread + 1e-5 * glm::length(edgeToCentre)) * glm::length(sampleSide);
}

double CasterAngularRadius(const glm::dvec3& light, double radius, const glm::dvec3& boxMin,
  const glm::dvec3& boxMax, const std::vector<glm::dvec3>& points,
  const std::vector<SilhouetteEdge>& silhouette, const glm::dmat4& toWorld)
{
  const bool inside =
    glm::all(glm::greaterThanEqual(light, boxMin)) && glm::all(glm::lessThanEqual(light, boxMax));
  double distance = glm::length(0.5 * (boxMin + boxMax) - light);
  if (inside)
  {
    double sum = 0.0;
    for (const SilhouetteEdge& edge : silhouette)
    {
      const glm::dvec3 middle = 0.5 * (points[edge.From] + points[edge.To]);
      sum += glm::length(glm::dvec3(toWorld * glm::dvec4(middle, 1.0)) - light);
    }
    distance = silhouette.empty() ? 0.5 * glm::length(boxMax - boxMin)
                                  : sum / static_cast<double>(silhouette.size());
  }
  return distance > radius ? radius / distance : 1e300;
}

double CountingToAveraging(const std::vector<CountingCost>& casters, int samples)
{
  double potential = 0.0, weighted = 0.0, silhouettes = 0.0;
  for (const CountingCost& caster : casters)
  {
    const double spread = std::pow(std::max(caster.AngularRadius, 0.0) / 0.016, 0.72);
    const double weight = std::max(static_cast<double>(caster.SilhouetteEdges), 1.0);
    potential += static_cast<double>(caster.PotentialEdges);
    weighted += weight * (std::isfinite(spread) ? spread : 1e300);
    silhouettes += weight;
  }
  if (potential == 0.0)
  {
    return 0.0; // nothing to draw beyond the centre's volume
  }
  const double edges = std::pow(potential / silhouettes, 0.67);
  const double perSample = std::pow(16.0 / std::max(samples, 1), 0.70);
  return 0.61 * edges * (weighted / silhouettes) * perSample;
}

bool CountingIsCheaper(const std::vector<CountingCost>& casters, int samples, LastChoice last)
{
  const double limit = last == LastChoice::Counted ? 1.1 : last == LastChoice::Averaged ? 0.9 : 1.0;
  return CountingToAveraging(casters, samples) < limit;
}

bool SeesAboveSurface(const glm::dvec3& normal, const glm::dvec3& towardsEye, const glm::dvec3& p,
  const glm::dvec4& light)
{
  const double seenSide = glm::dot(normal, towardsEye) < 0.0 ? -1.0 : 1.0;
  return normal == glm::dvec3(0.0) ||
    seenSide * glm::dot(normal, glm::dvec3(light) - light.w * p) > 0.0;
}

int SurfaceCutsLight(
  const glm::dvec3& unitNormal, const glm::dvec3& towardsReference, double spread)
{
  const double side = glm::dot(unitNormal, towardsReference);
  const double reach = 1.0001 * spread;
  return side > reach ? 1 : (side < -reach ? -1 : 0);
}

double CountingPointDepth(double sceneDepth, const ViewRay& ray, const glm::dvec4& plane,
  double depthBias, double planeBias)
{
  if (!(sceneDepth < 1.0))
  {
    return 1.0;
  }
  const double moved = sceneDepth - std::min(depthBias, sceneDepth);
  const glm::dvec3 normal(plane);
  // Heights above the plane of the ray's ends, the near one on the seen side: between the eye
  // and the visible point the ray does not cross the plane.
  double nearHeight = glm::dot(normal, ray.Near) - plane.w;
  double farHeight = glm::dot(normal, ray.Far) - plane.w;
  if (nearHeight < 0.0)
  {
    nearHeight = -nearHeight;
    farHeight = -farHeight;
  }
  if (normal == glm::dvec3(0.0) || !(farHeight < 0.0 && nearHeight > 0.0))
  {
    return moved;
  }
  // Window depth - 1 at the share u of the way from the far end back to the near one: the clip
  // coordinates are linear along the ray, NDC z is their ratio.
  const double wRatio = ray.FarW / ray.NearW;
  const auto depthMinusOne = [&](double u) { return -u / (u + (1.0 - u) * wRatio); };
  const double span = nearHeight - farHeight;
  const double onPlane = depthMinusOne(-farHeight / span);
  const double tolerance = std::max(16.0 * depthBias, 0.01 * (1.0 - sceneDepth));
  if (!(std::abs(1.0 + onPlane - sceneDepth) <= tolerance))
  {
    return moved;
  }
  const double clearance = planeBias * (glm::length(ray.Near) + glm::length(ray.Far));
  const double offPlane = depthMinusOne(std::min((clearance - farHeight) / span, 1.0));
  return std::max(1.0 + std::min(onPlane - depthBias, offPlane), 0.0);
}

} // namespace penumbra
