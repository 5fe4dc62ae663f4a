#include "penumbraShadowVolume.h"
#include "penumbraLargeArrays.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>

namespace penumbra
{
namespace
{

/// A positional light strictly outside the caster's bounds sees the whole caster inside an open
/// half-space, so a fan over the silhouette at infinity equals the projected light cap.
bool LightOutsideBounds(const CasterTopology& topo, const glm::dvec4& light)
{
  const glm::dvec3 p(light);
  const glm::dvec3 margin = 1e-9 * (topo.BoundsMax - topo.BoundsMin) + 1e-300;
  return glm::any(glm::lessThan(p, topo.BoundsMin - margin)) ||
    glm::any(glm::greaterThan(p, topo.BoundsMax + margin));
}

void AppendTriangle(
  std::vector<std::uint32_t>& out, std::uint32_t a, std::uint32_t b, std::uint32_t c)
{
  out.push_back(a);
  out.push_back(b);
  out.push_back(c);
}

/// The silhouette's edges in ascending multiplicity, in their order within each multiplicity.
std::vector<std::uint32_t> MultiplicityOrder(const std::vector<SilhouetteEdge>& silhouette)
{
  std::vector<std::uint32_t> order(silhouette.size());
  std::iota(order.begin(), order.end(), 0u);
  const auto byMultiplicity = [&](std::uint32_t a, std::uint32_t b)
  { return silhouette[a].Multiplicity < silhouette[b].Multiplicity; };
  if (!std::is_sorted(order.begin(), order.end(), byMultiplicity)) // mostly one multiplicity
  {
    std::stable_sort(order.begin(), order.end(), byMultiplicity);
  }
  return order;
}

/// Appends, through `append`, the triangles of every silhouette edge: first one copy of each,
/// in `order` (MultiplicityOrder), in runs of equal multiplicity recorded in `runs`, then the
/// further copies.
template <typename AppendEdge>
void AppendByMultiplicity(const std::vector<SilhouetteEdge>& silhouette,
  const std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& out,
  std::vector<TriangleRun>& runs, AppendEdge append)
{
  for (std::uint32_t i : order)
  {
    const SilhouetteEdge& e = silhouette[i];
    if (runs.empty() || runs.back().Multiplicity != e.Multiplicity)
    {
      runs.push_back({ e.Multiplicity, out.size(), 0 });
    }
    const std::size_t before = out.size();
    append(e, out);
    runs.back().Count += out.size() - before;
  }
  for (const SilhouetteEdge& e : silhouette)
  {
    for (std::uint32_t k = 1; k < e.Multiplicity; ++k)
    {
      append(e, out);
    }
  }
}

/// RunsCoverEveryCopy for one list.
bool RunsCover(const std::vector<TriangleRun>& runs, std::size_t size)
{
  std::size_t next = 0, copies = 0;
  std::uint32_t previous = 0;
  for (const TriangleRun& run : runs)
  {
    if (run.First != next || run.Count % 3 != 0 || run.Multiplicity <= previous)
    {
      return false;
    }
    next = run.First + run.Count;
    previous = run.Multiplicity;
    copies += run.Count * run.Multiplicity;
  }
  return copies == size;
}

} // namespace

bool ShadowVolume::FrontFacesSuffice(const CasterTopology& topo, const glm::dvec4& light)
{
  // From inside a closed mesh, rays leave through back faces only: then every face must count.
  return topo.ClosedAndOriented && (light.w == 0.0 || LightOutsideBounds(topo, light));
}

int ShadowVolume::Facing(
  const CasterTopology& topo, std::uint32_t triangle, const glm::dvec4& light)
{
  const glm::uvec3& tri = topo.Triangles[triangle];
  const glm::dvec3& p0 = topo.Points[tri.x];
  const double d =
    LightSide(glm::cross(topo.Points[tri.y] - p0, topo.Points[tri.z] - p0), p0, light);
  return d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
}

double ShadowVolume::LightSide(
  const glm::dvec3& normal, const glm::dvec3& point, const glm::dvec4& light)
{
  return glm::dot(normal, glm::dvec3(light) - light.w * point);
}

ShadowVolume ShadowVolume::Build(const CasterTopology& topo, const glm::dvec4& light, bool mirrored,
  bool withCaps, CountingRule rule)
{
  ShadowVolume volume;
  const auto n = static_cast<std::uint32_t>(topo.Points.size());
  const bool directional = light.w == 0.0;

  // Facing weight per triangle; see the counting rule in the header.
  const bool frontFacesOnly =
    rule == CountingRule::FrontFacesWhereTheySuffice && FrontFacesSuffice(topo, light);
  std::vector<std::int8_t> weight(topo.Triangles.size());
  for (std::uint32_t t = 0; t < topo.Triangles.size(); ++t)
  {
    const int facing = Facing(topo, t, light);
    weight[t] = static_cast<std::int8_t>(frontFacesOnly ? (facing > 0 ? 1 : 0) : facing);
    volume.CastingTriangles += weight[t] != 0;
  }
  if (withCaps)
  {
    // Sized once, on huge pages where large: grown by appends, a cap of millions of triangles
    // spent most of its build faulting in fresh pages (PenumbraGeometryBench's volume column).
    ReserveLarge(volume.LightCap, 3 * volume.CastingTriangles);
    for (std::uint32_t t = 0; t < topo.Triangles.size(); ++t)
    {
      if (weight[t] != 0)
      {
        const glm::uvec3& tri = topo.Triangles[t];
        const bool flip = (weight[t] < 0) != mirrored;
        AppendTriangle(volume.LightCap, tri.x, flip ? tri.z : tri.y, flip ? tri.y : tri.z);
      }
    }
  }

  for (const Edge& edge : topo.Edges)
  {
    int multiplicity = 0;
    for (std::uint32_t u = edge.FirstUse; u < edge.FirstUse + edge.UseCount; ++u)
    {
      multiplicity += topo.Uses[u].Sign * weight[topo.Uses[u].Triangle];
    }
    if (mirrored)
    {
      multiplicity = -multiplicity;
    }
    if (multiplicity == 0)
    {
      continue;
    }
    const bool forward = multiplicity > 0;
    volume.Silhouette.push_back({ forward ? edge.A : edge.B, forward ? edge.B : edge.A,
      static_cast<std::uint32_t>(std::abs(multiplicity)) });
  }

  // Side of edge a->b (walked counter-clockwise as seen from the light): outward-facing quad
  // (b, a, a_inf, b_inf). Towards a directional light every point sweeps to the same point at
  // infinity, so there is no dark cap and the quad's second triangle has no area there; it is
  // kept for z-pass volumes that stop on a plane short of infinity (VolumeEndPlane).
  const std::vector<std::uint32_t> order = MultiplicityOrder(volume.Silhouette);
  AppendByMultiplicity(volume.Silhouette, order, volume.Sides, volume.SideRuns,
    [n](const SilhouetteEdge& e, std::vector<std::uint32_t>& out)
    {
      AppendTriangle(out, e.To, e.From, e.From + n);
      AppendTriangle(out, e.To, e.From + n, e.To + n);
    });

  // A light inside a closed mesh sees no silhouette at all: the caps alone bound its volume.
  if (!directional && !volume.LightCap.empty())
  {
    if (LightOutsideBounds(topo, light))
    {
      const std::uint32_t centre =
        volume.Silhouette.empty() ? 0 : volume.Silhouette.front().From + n;
      AppendByMultiplicity(volume.Silhouette, order, volume.DarkCap, volume.DarkCapRuns,
        [n, centre](const SilhouetteEdge& e, std::vector<std::uint32_t>& out)
        {
          if (e.From + n != centre && e.To + n != centre) // else a degenerate fan triangle
          {
            AppendTriangle(out, centre, e.To + n, e.From + n);
          }
        });
    }
    else
    {
      ReserveLarge(volume.DarkCap, volume.LightCap.size());
      for (std::size_t i = 0; i < volume.LightCap.size(); i += 3)
      {
        AppendTriangle(volume.DarkCap, volume.LightCap[i] + n, volume.LightCap[i + 2] + n,
          volume.LightCap[i + 1] + n);
      }
      volume.DarkCapRuns.push_back({ 1, 0, volume.DarkCap.size() });
    }
  }
  return volume;
}

std::size_t ShadowVolume::RepeatedSideIndices() const
{
  std::size_t firstCopies = 0;
  for (const TriangleRun& run : this->SideRuns)
  {
    firstCopies += run.Count;
  }
  return this->Sides.size() - firstCopies;
}

bool ShadowVolume::RunsCoverEveryCopy() const
{
  return RunsCover(this->SideRuns, this->Sides.size()) &&
    RunsCover(this->DarkCapRuns, this->DarkCap.size());
}

bool ShadowVolume::SilhouetteIsBalanced(std::size_t pointCount) const
{
  std::vector<long long> degree(pointCount, 0);
  for (const SilhouetteEdge& e : this->Silhouette)
  {
    if (e.From >= pointCount || e.To >= pointCount)
    {
      return false;
    }
    degree[e.From] += e.Multiplicity;
    degree[e.To] -= e.Multiplicity;
  }
  for (long long d : degree)
  {
    if (d != 0)
    {
      return false;
    }
  }
  return true;
}

} // namespace penumbra
