#include "penumbraWedge.h"

#include "penumbraCulling.h"
#include "penumbraLightSamples.h"

#include <cmath>

namespace penumbra
{
namespace
{

constexpr double Pi = 3.14159265358979323846;

/// Signed area of (triangle(origin, A, B) inside the disk) minus the disk sector between OA and
/// OB: only the part of segment AB inside the disk contributes, so it vanishes outside it.
double InsideCorrection(const glm::dvec2& A, const glm::dvec2& B, double R)
{
  const glm::dvec2 AB = B - A;
  const double length = glm::length(AB);
  if (!(length > 0.0))
  {
    return 0.0;
  }
  // Chord through the closest point to the centre: stable when an end projects far away.
  const glm::dvec2 u = AB / length;
  const double closest = -glm::dot(A, u);
  const glm::dvec2 nearest = A + closest * u;
  const double halfChord2 = R * R - glm::dot(nearest, nearest);
  if (!(halfChord2 > 0.0))
  {
    return 0.0;
  }
  const double halfChord = std::sqrt(halfChord2);
  const double s0 = std::max(0.0, closest - halfChord), s1 = std::min(length, closest + halfChord);
  if (!(s1 > s0))
  {
    return 0.0;
  }
  const glm::dvec2 P = A + s0 * u, Q = A + s1 * u;
  const double cross = P.x * Q.y - P.y * Q.x;
  const double angle = std::atan2(cross, glm::dot(P, Q));
  return 0.5 * cross - 0.5 * R * R * angle;
}

/// Inward normal of the side plane at `end` (pointing along `along`): every ray from the light
/// through the edge stays on its positive side. `away` is the unit direction from the light
/// through `end`, `s` the sine of the light's angular radius seen from there.
bool SidePlane(const glm::dvec3& along, const glm::dvec3& away, double s, glm::dvec3& normal)
{
  const double du = glm::dot(along, away);
  const double lambda = -du + s * std::sqrt(std::max(0.0, (1.0 - du * du) / (1.0 - s * s)));
  const glm::dvec3 m = along + lambda * away;
  const double length = glm::length(m);
  if (!(length > 1e-9))
  {
    return false;
  }
  normal = m / length;
  return glm::dot(normal, along) >= -1e-12 && glm::dot(normal, away) >= s - 1e-9;
}

} // namespace

double EdgeOcclusion(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
  const glm::dvec4& light, double radius)
{
  glm::dvec3 towards;
  double distance, diskRadius;
  if (light.w != 0.0)
  {
    towards = glm::dvec3(light) - p;
    distance = glm::length(towards);
    if (!(distance > radius * (1.0 + 1e-9)))
    {
      return 0.0; // inside the light: nothing between
    }
    towards /= distance;
    diskRadius = distance * radius / std::sqrt(distance * distance - radius * radius);
  }
  else
  {
    towards = UnitDirection(glm::dvec3(light));
    distance = 1.0;
    diskRadius = std::tan(radius);
  }
  if (!(diskRadius > 0.0) || !std::isfinite(diskRadius))
  {
    return 0.0;
  }
  glm::dvec3 e1, e2;
  PlaneBasis(towards, e1, e2);

  // Keep the part of the edge in front of p (towards the light); the rest cannot occlude.
  glm::dvec3 from = a - p, to = b - p;
  double hFrom = glm::dot(from, towards), hTo = glm::dot(to, towards);
  const double hMin = 1e-9 * distance;
  if (hFrom < hMin && hTo < hMin)
  {
    return 0.0;
  }
  if (hFrom < hMin)
  {
    from += (to - from) * ((hMin - hFrom) / (hTo - hFrom));
    hFrom = hMin;
  }
  else if (hTo < hMin)
  {
    to += (from - to) * ((hMin - hTo) / (hFrom - hTo));
    hTo = hMin;
  }
  // Gnomonic projection from p onto the light's plane, centred on the light.
  const glm::dvec3 fromPlane = from * (distance / hFrom), toPlane = to * (distance / hTo);
  const glm::dvec2 A(glm::dot(fromPlane, e1), glm::dot(fromPlane, e2));
  const glm::dvec2 B(glm::dot(toPlane, e1), glm::dot(toPlane, e2));
  // A disk so small (or large) that its area underflows (or overflows) would give 0 / 0: such a
  // light has no penumbra worth a correction.
  const double diskArea = Pi * diskRadius * diskRadius;
  if (!(diskArea > 0.0) || !std::isfinite(diskArea))
  {
    return 0.0;
  }
  return InsideCorrection(A, B, diskRadius) / diskArea;
}

Wedge Wedge::Build(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light, double radius)
{
  Wedge wedge;
  const glm::dvec3 edge = b - a;
  const double length = glm::length(edge);
  if (!(length > 0.0) || !(radius > 0.0))
  {
    return wedge;
  }
  const glm::dvec3 d = edge / length;
  const bool positional = light.w != 0.0;
  const glm::dvec3 centre(light);

  // Front and back planes contain the edge and touch the light: a sphere of `radius` around the
  // centre, or the cone of directions of half-angle `radius` (then "distance" is a sine).
  glm::dvec3 perpendicular;
  double reach;
  if (positional)
  {
    perpendicular = (centre - a) - glm::dot(centre - a, d) * d;
    reach = radius;
  }
  else
  {
    // A cone of half-angle 90 degrees or more has no tangent planes, and past pi the sine below
    // turns negative and would pass the test after it with h = 0 (NaN planes, Valid true).
    if (!(radius < 0.5 * Pi))
    {
      return wedge;
    }
    const glm::dvec3 l = glm::normalize(centre);
    perpendicular = l - glm::dot(l, d) * d;
    reach = std::sin(radius);
  }
  const double h = glm::length(perpendicular);
  if (!(h > reach * (1.0 + 1e-9)))
  {
    return wedge; // the edge's line touches the light
  }
  const glm::dvec3 up = perpendicular / h, side = glm::cross(d, up);
  const double cosBeta = reach / h, sinBeta = std::sqrt(1.0 - cosBeta * cosBeta);
  const glm::dvec3 front = cosBeta * up + sinBeta * side, back = cosBeta * up - sinBeta * side;

  // Side planes: every ray from the light through the edge must stay inside.
  auto away = [&](const glm::dvec3& end)
  { return positional ? glm::normalize(end - centre) : -glm::normalize(centre); };
  auto sine = [&](const glm::dvec3& end)
  { return positional ? radius / glm::length(end - centre) : std::sin(radius); };
  glm::dvec3 sideA, sideB;
  if (sine(a) >= 1.0 || sine(b) >= 1.0 || !SidePlane(d, away(a), sine(a), sideA) ||
    !SidePlane(-d, away(b), sine(b), sideB))
  {
    return wedge;
  }

  wedge.Normals = { front, back, -sideA, -sideB };
  wedge.Offsets = { glm::dot(front, a), glm::dot(back, a), -glm::dot(sideA, a),
    -glm::dot(sideB, b) };
  auto farEdge = [&](const glm::dvec3& plane, const glm::dvec3& sidePlane, const glm::dvec3& end)
  {
    glm::dvec3 direction = glm::normalize(glm::cross(plane, sidePlane));
    return glm::dot(direction, away(end)) < 0.0 ? -direction : direction;
  };
  wedge.Vertices = { glm::dvec4(a, 1.0), glm::dvec4(b, 1.0),
    glm::dvec4(farEdge(front, sideA, a), 0.0), glm::dvec4(farEdge(front, sideB, b), 0.0),
    glm::dvec4(farEdge(back, sideA, a), 0.0), glm::dvec4(farEdge(back, sideB, b), 0.0) };
  // The far edges must leave through the far end, not cross another plane (side planes crossing
  // behind the edge would make the region a different polyhedron).
  for (int v = 2; v < 6; ++v)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (glm::dot(wedge.Normals[k], glm::dvec3(wedge.Vertices[v])) > 1e-9)
      {
        return wedge;
      }
    }
  }
  // Far beyond the edge's scale (a light near 1e200) squared lengths overflow: h or a side
  // direction becomes Inf or 0 and the planes come out zero or NaN. Such planes are no wedge.
  for (int k = 0; k < 4; ++k)
  {
    const glm::dvec3& n = wedge.Normals[k];
    if (!std::isfinite(wedge.Offsets[k]) || !(std::abs(glm::dot(n, n) - 1.0) < 1e-6))
    {
      return wedge;
    }
  }
  for (const glm::dvec4& v : wedge.Vertices)
  {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    {
      return wedge;
    }
  }
  wedge.Valid = true;
  return wedge;
}

bool Wedge::Contains(const glm::dvec3& x, double tolerance) const
{
  for (int k = 0; k < 4; ++k)
  {
    if (glm::dot(this->Normals[k], x) > this->Offsets[k] + tolerance)
    {
      return false;
    }
  }
  return this->Valid;
}

std::vector<HalfSpace> Wedge::HalfSpaces() const
{
  std::vector<HalfSpace> halfSpaces;
  for (int k = 0; k < 4; ++k)
  {
    halfSpaces.push_back({ this->Normals[k], this->Offsets[k] });
  }
  return halfSpaces;
}

const std::array<unsigned int, 24>& Wedge::Triangles()
{
  // Vertices: 0 a, 1 b, 2 front-a, 3 front-b, 4 back-a, 5 back-b (2..5 at infinity).
  static const std::array<unsigned int, 24> triangles = { 1, 0, 2, 1, 2, 3, // front
    0, 1, 5, 0, 5, 4,                                                       // back
    0, 4, 2,                                                                // side at a
    1, 3, 5,                                                                // side at b
    2, 4, 5, 2, 5, 3 };                                                     // far end
  return triangles;
}

namespace
{
/// A positional light's pyramid: apex at the centre, around the edge's directions from it.
bool PositionalPyramidCone(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& centre,
  double radius, glm::dvec3& apex, glm::dvec3& axis, double& halfAngle)
{
  const glm::dvec3 toA = a - centre, toB = b - centre;
  // The nearest point of the edge to the centre bounds the widening angle.
  const glm::dvec3 edge = b - a;
  const double edgeLength2 = glm::dot(edge, edge);
  const double t =
    edgeLength2 > 0.0 ? glm::clamp(-glm::dot(toA, edge) / edgeLength2, 0.0, 1.0) : 0.0;
  const double nearest = glm::length(toA + t * edge);
  if (!(nearest > radius) || !(glm::length(toA) > 0.0) || !(glm::length(toB) > 0.0))
  {
    return false;
  }
  const glm::dvec3 dirA = glm::normalize(toA), dirB = glm::normalize(toB);
  const glm::dvec3 sum = dirA + dirB;
  if (!(glm::length(sum) > 1e-12))
  {
    return false; // the edge spans the centre: no cone holds it
  }
  apex = centre;
  axis = glm::normalize(sum);
  const double spread = std::acos(glm::clamp(glm::dot(axis, dirA), -1.0, 1.0));
  halfAngle = spread + std::atan(radius / (nearest - radius));
  return true;
}

/// A directional light's pyramid. The points that see the edge cross the light are the edge
/// swept along the cone of directions away from the light; where the edge itself runs within a
/// cone of that axis from its end nearer the light, the sweep of that end holds the others'.
bool DirectionalPyramidCone(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& towards,
  double radius, glm::dvec3& apex, glm::dvec3& axis, double& halfAngle)
{
  if (!(glm::length(towards) > 0.0))
  {
    return false;
  }
  axis = -glm::normalize(towards);
  const bool aNearer = glm::dot(a, axis) <= glm::dot(b, axis);
  apex = aNearer ? a : b;
  const glm::dvec3 along = (aNearer ? b : a) - apex;
  const double length = glm::length(along);
  const double edgeAngle =
    length > 0.0 ? std::acos(glm::clamp(glm::dot(along / length, axis), -1.0, 1.0)) : 0.0;
  // Widened a little so that an edge on the cone's side stays inside against rounding.
  halfAngle = std::max(radius, edgeAngle) * (1.0 + 1e-6) + 1e-9;
  return true;
}
} // namespace

LightPyramid LightPyramid::Build(
  const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light, double radius)
{
  LightPyramid pyramid;
  if (!(radius >= 0.0))
  {
    return pyramid;
  }
  glm::dvec3 apex, axis;
  double halfAngle = 0.0;
  const bool cone = light.w != 0.0
    ? PositionalPyramidCone(a, b, glm::dvec3(light), radius, apex, axis, halfAngle)
    : DirectionalPyramidCone(a, b, glm::dvec3(light), radius, apex, axis, halfAngle);
  constexpr double MaximumHalfAngle = Pi / 3.0;
  if (!cone || !(halfAngle < MaximumHalfAngle))
  {
    return pyramid;
  }
  glm::dvec3 e1, e2;
  PlaneBasis(axis, e1, e2);
  const double reach = std::tan(halfAngle);
  const glm::dvec3 corners[4] = { axis + reach * (e1 + e2), axis + reach * (-e1 + e2),
    axis + reach * (-e1 - e2), axis + reach * (e1 - e2) };
  pyramid.Vertices[0] = glm::dvec4(apex, 1.0);
  for (int k = 0; k < 4; ++k)
  {
    pyramid.Vertices[k + 1] = glm::dvec4(glm::normalize(corners[k]), 0.0);
    // The corners turn counter-clockwise about the axis: the cross product points outwards.
    pyramid.Normals[k] = glm::normalize(glm::cross(corners[(k + 1) % 4], corners[k]));
  }
  for (const glm::dvec3& n : pyramid.Normals)
  {
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
    {
      return pyramid;
    }
  }
  pyramid.Valid = true;
  return pyramid;
}

bool LightPyramid::Contains(const glm::dvec3& x, double tolerance) const
{
  const glm::dvec3 relative = x - glm::dvec3(this->Vertices[0]);
  for (const glm::dvec3& n : this->Normals)
  {
    if (glm::dot(n, relative) > tolerance)
    {
      return false;
    }
  }
  return this->Valid;
}

std::vector<HalfSpace> LightPyramid::HalfSpaces() const
{
  const glm::dvec3 apex(this->Vertices[0]);
  std::vector<HalfSpace> halfSpaces;
  for (const glm::dvec3& normal : this->Normals)
  {
    halfSpaces.push_back({ normal, glm::dot(normal, apex) });
  }
  return halfSpaces;
}

const std::array<unsigned int, 18>& LightPyramid::Triangles()
{
  // Vertices: 0 apex, 1..4 directions counter-clockwise about the axis.
  static const std::array<unsigned int, 18> triangles = { 0, 2, 1, 0, 3, 2, 0, 4, 3, 0, 1, 4, 1, 2,
    3, 1, 3, 4 };
  return triangles;
}

} // namespace penumbra
