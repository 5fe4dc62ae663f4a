/**
 * @file penumbraShadowVolume.h
 * @brief Silhouettes and shadow-volume meshes of a caster for one light, without OpenGL.
 *
 * Counting rule (see Documentation/silhouettes.md): every triangle that is not edge-on to the
 * light bounds its own volume (the triangle, wound to face the light, swept away from it). The
 * caster's volume is the sum of those volumes, so a point's stencil count is the number of
 * triangles between it and the light: zero means lit, whatever the mesh's orientation or
 * manifoldness. Edges shared by two triangles whose swept sides cancel drop out; what is left on
 * an edge is its multiplicity m_e = sum over its triangles of (walk sign x facing weight), drawn
 * |m_e| times. For a closed, consistently oriented mesh lit from outside its bounds the back faces
 * shadow nothing that the front faces do not, so only front faces count (weight 1/0 instead of
 * +1/-1) and m_e is +-1.
 *
 * Sides and DarkCap hold each triangle of an edge |m_e| times, as the stencil counts them (one
 * per crossing). They begin with one copy of every edge's triangles, grouped by multiplicity
 * (SideRuns, DarkCapRuns): a count that can add m_e at once (additive blending into a float
 * target) draws those runs, each weighted by its multiplicity, and fills every side once. On an
 * open mesh, where the general rule gives most silhouette edges m_e = 2, that halves the fill.
 *
 * Vertex indices refer to a buffer of 2N vertices: i < N is caster point i, N + i the same point
 * swept to infinity away from the light (w = 0 in the vertex shader).
 */
#ifndef penumbraShadowVolume_h
#define penumbraShadowVolume_h

#include "penumbraCasterTopology.h"

namespace penumbra
{

/// A silhouette edge walked From -> To, Multiplicity (> 0) times.
struct SilhouetteEdge
{
  std::uint32_t From;
  std::uint32_t To;
  std::uint32_t Multiplicity;
};

/// Which triangles a volume counts: front faces alone where they suffice (FrontFacesSuffice), a
/// point's count then being 0 or 1 behind a closed mesh, or every triangle, the count then being
/// the number of surfaces between the point and the light, as a translucent caster's
/// transmission needs.
enum class CountingRule
{
  FrontFacesWhereTheySuffice,
  EveryTriangle
};

/// Indices [First, First + Count) of Sides or DarkCap whose triangles stand for Multiplicity
/// copies each.
struct TriangleRun
{
  std::uint32_t Multiplicity;
  std::size_t First;
  std::size_t Count;
};

struct VTKPENUMBRAGEOMETRY_EXPORT ShadowVolume
{
  std::vector<SilhouetteEdge> Silhouette;
  /// Triangles of the swept silhouette (indices into the 2N buffer): enough for z-pass.
  std::vector<std::uint32_t> Sides;
  /// The first copies in Sides, by multiplicity (ascending); the rest of Sides repeats them.
  std::vector<TriangleRun> SideRuns;
  /// The casting triangles wound to face the light: the light cap, z-fail only.
  std::vector<std::uint32_t> LightCap;
  /// The far end of the volume at infinity (empty for directional lights): z-fail only.
  std::vector<std::uint32_t> DarkCap;
  /// The first copies in DarkCap, by multiplicity, as SideRuns.
  std::vector<TriangleRun> DarkCapRuns;
  /// Triangles that cast (for statistics and tests).
  std::size_t CastingTriangles = 0;

  /**
   * Builds the volume of `topo` for a light given in the caster's object space relative to
   * topo.Origin: (x, y, z, 1) for a positional light, (dx, dy, dz, 0) for the direction towards
   * a directional light. `mirrored` (actor matrix with negative determinant) reverses every
   * winding so that world-space volumes stay positively oriented. Without `withCaps` only the
   * silhouette and sides are built (enough for z-pass, and a fraction of the memory).
   */
  static ShadowVolume Build(const CasterTopology& topo, const glm::dvec4& light, bool mirrored,
    bool withCaps = true, CountingRule rule = CountingRule::FrontFacesWhereTheySuffice);

  /// Whether front faces alone bound the shadow: a closed, oriented mesh lit from outside.
  static bool FrontFacesSuffice(const CasterTopology& topo, const glm::dvec4& light);

  /// +1 when the triangle faces the light, -1 when it faces away, 0 when edge-on.
  static int Facing(const CasterTopology& topo, std::uint32_t triangle, const glm::dvec4& light);
  /// What Facing takes the sign of: the light's side of the plane through `point` with
  /// `normal` (any length, as wound), times the normal's length.
  static double LightSide(
    const glm::dvec3& normal, const glm::dvec3& point, const glm::dvec4& light);

  /// The side indices beyond the first copies (SideRuns): what a weighted count spares.
  std::size_t RepeatedSideIndices() const;

  /// True when SideRuns and DarkCapRuns lead their lists in ascending multiplicity and, times
  /// their multiplicity, account for every copy in them.
  bool RunsCoverEveryCopy() const;

  /// True when every vertex has as many silhouette edges leaving as entering (closed loops).
  bool SilhouetteIsBalanced(std::size_t pointCount) const;
};

} // namespace penumbra

#endif
