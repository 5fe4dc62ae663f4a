// Unit tests of Haines' plateau geometry (penumbraPlateaus.h), without OpenGL: the triangles are
// rasterized on the CPU (smallest depth wins, as the depth test does) and checked against the
// closed forms of the method: hard shadow at depth 0, penumbra width r h / (H - h) for a light of
// radius r at height H over a caster edge at height h, growing with h, elongated for a light
// near the horizon, and nothing non-finite on bad input.
#include "penumbraCasterTopology.h"
#include "penumbraCheck.h"
#include "penumbraLightSamples.h"
#include "penumbraPlateaus.h"
#include "penumbraShadowVolume.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace penumbra;
using penumbra_test::Check;

namespace
{

/// The plateau depth at q: the smallest interpolated depth of the triangles covering it, or 1.
double DepthAt(const std::vector<PlateauVertex>& triangles, const glm::dvec2& q)
{
  double best = 1.0;
  for (std::size_t i = 0; i + 2 < triangles.size(); i += 3)
  {
    const glm::dvec2 a(triangles[i].U, triangles[i].V), b(triangles[i + 1].U, triangles[i + 1].V),
      c(triangles[i + 2].U, triangles[i + 2].V);
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (std::abs(area) < 1e-14)
    {
      continue;
    }
    const double wb = ((q.x - a.x) * (c.y - a.y) - (q.y - a.y) * (c.x - a.x)) / area;
    const double wc = ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / area;
    const double wa = 1.0 - wb - wc;
    if (wa >= -1e-9 && wb >= -1e-9 && wc >= -1e-9)
    {
      best =
        std::min(best, wa * triangles[i].T + wb * triangles[i + 1].T + wc * triangles[i + 2].T);
    }
  }
  return best;
}

/// A horizontal square of side 1 centred above the origin at height h (y up), facing up.
CasterTopology Square(double h)
{
  return CasterTopology::Build(
    { { -0.5, h, -0.5 }, { 0.5, h, -0.5 }, { 0.5, h, 0.5 }, { -0.5, h, 0.5 } },
    { { 0, 3, 2 }, { 0, 2, 1 } });
}

std::vector<PlateauVertex> Plateaus(const CasterTopology& topo, const glm::dvec4& light,
  double radius, PlateauReport* report = nullptr)
{
  ReceiverPlane plane;
  ReceiverPlane::Make(glm::dvec3(0.0), glm::dvec3(0, 1, 0), plane);
  const glm::dmat4 toWorld(1.0);
  const glm::dvec4 lightObject(
    glm::dvec3(light) - (light.w != 0.0 ? topo.Origin : glm::dvec3(0.0)), light.w);
  const ShadowVolume volume = ShadowVolume::Build(topo, lightObject, false, true);
  std::vector<PlateauVertex> triangles;
  const PlateauReport r = BuildPlateaus(
    topo, volume, glm::translate(toWorld, topo.Origin), light, radius, plane, triangles);
  if (report)
  {
    *report = r;
  }
  return triangles;
}

/// Where the depth along the ray from `start` in `direction` (plane coordinates) first reaches
/// 1: the outer edge of the penumbra, found by bisection.
double PenumbraEdge(
  const std::vector<PlateauVertex>& triangles, const glm::dvec2& start, const glm::dvec2& direction)
{
  double lo = 0.0, hi = 10.0;
  for (int i = 0; i < 50; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (DepthAt(triangles, start + mid * direction) < 1.0 - 1e-9 ? lo : hi) = mid;
  }
  return lo;
}

void TestHardShadowAndWidth()
{
  // Light of radius 0.5 at height 5 above a square at height 1: the hard shadow is the square
  // scaled by 5 / 4, and the penumbra reaches r h / (H - h) = 0.125 beyond it, about.
  const double r = 0.5, H = 5.0;
  for (const double h : { 1.0, 2.0 })
  {
    const auto triangles = Plateaus(Square(h), glm::dvec4(0, H, 0, 1), r);
    const double halfShadow = 0.5 * H / (H - h);
    // The plane basis is arbitrary: find the axis along which the shadow's edge lies (U, V
    // span the ground, so the hard shadow is a square in them too, possibly rotated 90 deg).
    Check(DepthAt(triangles, glm::dvec2(0.0)) == 0.0, "centre of the hard shadow at depth 0");
    Check(DepthAt(triangles, glm::dvec2(0.9 * halfShadow, 0.0)) == 0.0,
      "hard shadow reaches its outline");
    const double expected = r * h / (H - h);
    const double width = PenumbraEdge(triangles, glm::dvec2(halfShadow, 0.0), glm::dvec2(1, 0));
    std::printf("     h = %.0f: penumbra width %.4f, expected about %.4f\n", h, width, expected);
    Check(std::abs(width - expected) < 0.15 * expected, "penumbra width r h / (H - h)");
    const double half = DepthAt(triangles, glm::dvec2(halfShadow + 0.5 * width, 0.0));
    Check(std::abs(half - 0.5) < 0.1, "depth grows linearly across the sheet");
    Check(DepthAt(triangles, glm::dvec2(halfShadow + 1.2 * width, 0.0)) == 1.0,
      "lit beyond the penumbra");
  }
}

void TestLowLightIsElongated()
{
  // A directional light 15 degrees above the horizon, 2 degrees wide: the penumbra stretches
  // along the light's direction far more than across it (elliptical cones).
  const double elevation = 15.0 * 3.14159265358979 / 180.0;
  const glm::dvec4 light(std::cos(elevation), std::sin(elevation), 0.0, 0.0);
  const auto triangles = Plateaus(Square(1.0), light, 2.0 * 3.14159265358979 / 180.0);
  // The shadow falls towards -x; measure beyond its far edge (-x) and beyond a side edge (+z).
  const double shift = 1.0 / std::tan(elevation);
  const glm::dvec2 farEdge(-0.5 - shift, 0.0);
  // Plane coordinates of ground points: recover them with the plane's own basis.
  ReceiverPlane plane;
  ReceiverPlane::Make(glm::dvec3(0.0), glm::dvec3(0, 1, 0), plane);
  const glm::dvec2 far = plane.ToPlane(glm::dvec3(farEdge.x, 0, 0));
  const glm::dvec2 towardsFar =
    plane.ToPlane(glm::dvec3(-1, 0, 0)) - plane.ToPlane(glm::dvec3(0.0));
  const glm::dvec2 side = plane.ToPlane(glm::dvec3(-shift, 0, 0.5));
  const glm::dvec2 towardsSide =
    plane.ToPlane(glm::dvec3(0, 0, 1)) - plane.ToPlane(glm::dvec3(0.0));
  const double along = PenumbraEdge(triangles, far, towardsFar);
  const double across = PenumbraEdge(triangles, side, towardsSide);
  std::printf("     penumbra along the light %.4f, across %.4f\n", along, across);
  Check(along > 2.5 * across, "a light near the horizon gives an elongated penumbra");
  Check(std::abs(across - std::tan(2.0 * 3.14159265358979 / 180.0) / std::sin(elevation)) <
      0.3 * across,
    "across the light, width h tan(radius) / sin(elevation)");
}

void TestBadInput()
{
  PlateauReport report;
  // A light below the caster's plane side: nothing; a caster above the light: skipped.
  Check(Plateaus(Square(1.0), glm::dvec4(0, -3, 0, 1), 0.3).empty(),
    "light below the plane: no plateau");
  Plateaus(Square(6.0), glm::dvec4(0, 5, 0, 1), 0.3, &report);
  Check(report.SkippedAboveLight == 2 && report.Cones == 0, "caster above the light casts nothing");
  // A light at the height of the caster's top and a huge radius: finite output only.
  const CasterTopology box = CasterTopology::Build(
    { { -0.5, 0.5, -0.5 }, { 0.5, 0.5, -0.5 }, { 0.5, 0.5, 0.5 }, { -0.5, 0.5, 0.5 },
      { -0.5, 1.5, -0.5 }, { 0.5, 1.5, -0.5 }, { 0.5, 1.5, 0.5 }, { -0.5, 1.5, 0.5 } },
    { { 0, 1, 2 }, { 0, 2, 3 }, { 4, 6, 5 }, { 4, 7, 6 }, { 0, 4, 5 }, { 0, 5, 1 }, { 1, 5, 6 },
      { 1, 6, 2 }, { 2, 6, 7 }, { 2, 7, 3 }, { 3, 7, 4 }, { 3, 4, 0 } });
  bool finite = true;
  for (const double radius : { 0.0, 1e-9, 3.0, 1e6 })
  {
    for (const auto& t : Plateaus(box, glm::dvec4(3, 1.5, 0, 1), radius))
    {
      finite = finite && std::isfinite(t.U) && std::isfinite(t.V) && t.T >= 0.0f && t.T <= 1.0f;
    }
  }
  Check(finite, "grazing light, radii 0 to 1e6: finite vertices, depths in [0, 1]");
  // A plane given by an origin far along it is the same plane: taken near the scene, its points
  // keep small in-plane coordinates (a user's trial: no plateau at all for an origin of (1e8, 0,
  // 0) or (1e300, 0, 0) with the normal (0, 1, 0)), in a scene far from the world's origin too.
  for (const glm::dvec3& scene : { glm::dvec3(0.0), glm::dvec3(5e5, 0, 4e6) })
  {
    for (const double far : { 1e8, 1e300 })
    {
      ReceiverPlane plane;
      const bool made = ReceiverPlane::MakeNear(
        glm::dvec3(far, 0, 0), glm::dvec3(0, 2, 0), scene + glm::dvec3(0, 7, 0), plane);
      const glm::dvec2 uv = plane.ToPlane(scene + glm::dvec3(1, 0, 2));
      Check(made && std::abs(plane.Height(scene + glm::dvec3(1, 3, 2)) - 3.0) < 1e-6 &&
          std::abs(glm::length(uv) - std::sqrt(5.0)) < 1e-6,
        "a receiver plane's origin far along the plane: the same plane, small coordinates");
    }
  }
  Check(std::abs(PlateauIntensity(0.5, PlateauFalloff::Sinusoidal) - 0.5) < 1e-12 &&
      PlateauIntensity(0.25, PlateauFalloff::Sinusoidal) < 0.25 &&
      PlateauIntensity(2.0, PlateauFalloff::Linear) == 1.0,
    "falloffs: sinusoidal symmetric about 0.5, clamped");
}

} // namespace

/// The receiver-plane fit: a tilted grid, the same grid bent, collinear and too few points.
void TestPlaneFit()
{
  const glm::dvec3 normal = glm::normalize(glm::dvec3(0.2, 1.0, -0.3));
  glm::dvec3 e1, e2;
  penumbra::PlaneBasis(normal, e1, e2);
  const glm::dvec3 origin(3.0, -1.0, 2.0);
  std::vector<glm::dvec3> grid;
  for (int i = 0; i <= 10; ++i)
  {
    for (int j = 0; j <= 10; ++j)
    {
      grid.push_back(origin + (i - 5.0) * 0.4 * e1 + (j - 5.0) * 0.3 * e2);
    }
  }
  grid.push_back(glm::dvec3(std::numeric_limits<double>::quiet_NaN()));
  penumbra::PlaneFit fit;
  Check(penumbra::FitReceiverPlane(grid, fit), "a tilted grid fits a plane");
  Check(std::abs(std::abs(glm::dot(fit.Plane.Normal, normal)) - 1.0) < 1e-12 &&
      std::abs(fit.Plane.Height(origin)) < 1e-12 && fit.Thickness < 1e-12,
    "the grid's own plane, through its points, NaN ignored");
  Check(std::abs(fit.Extent - std::sqrt(4.0 * 4.0 + 3.0 * 3.0)) < 1e-9,
    "its extent is the grid's diagonal");
  std::vector<glm::dvec3> bent = grid;
  bent[60] += 0.25 * normal;
  Check(penumbra::FitReceiverPlane(bent, fit) && fit.Thickness > 0.2,
    "a bent grid fits, with its thickness reported");
  Check(!penumbra::FitReceiverPlane({ origin, origin + e1, origin + 2.0 * e1 }, fit),
    "collinear points fit no plane");
  Check(!penumbra::FitReceiverPlane({ origin, origin + e1 }, fit), "two points fit no plane");
}

int main()
{
  TestPlaneFit();
  TestHardShadowAndWidth();
  TestLowLightIsElongated();
  TestBadInput();
  return penumbra_test::Finish();
}
