/**
 * @file penumbraSampleCounting.h
 * @brief Exact soft shadows by per-light-sample depth complexity, without OpenGL.
 *
 * Seen from a receiver point p, an area light is N sample points s_i (SpreadLightSamples, the
 * same points the averaged method uses). The depth complexity D(p, s) is the number of casting
 * triangles that the segment p -> s crosses; s is visible exactly when D(p, s) = 0. As s moves
 * from the light's centre c to s_i, D changes only when the segment sweeps across an edge, so
 *
 *   D(p, s_i) = D(p, c) + sum over edges e of  -m_e(p) * Crossing(p, e, c, s_i),
 *
 * where m_e(p) is the edge's multiplicity seen from p (the counting rule of silhouettes.md, with
 * facing taken from p rather than from the light) and Crossing is +-1 when the path c -> s_i
 * crosses the edge's projection from p (the sign says to which side of the plane (p, e) s_i
 * lies), else 0. D(p, c) is the centre's shadow-volume count (Laine et al. 2005; Forest, Barthe
 * and Paulin 2008). Both terms must count by the same rule: every casting triangle (weights
 * +-1), or, for a closed oriented caster lit from outside, front faces only (weights 1/0), which
 * halves both.
 *
 * Only edges that are a silhouette from some point of the light can cross: the potential
 * silhouette, found once per light, actor matrix and data change by PotentialSilhouette.
 */
#ifndef penumbraSampleCounting_h
#define penumbraSampleCounting_h

#include "penumbraCasterTopology.h"
#include "penumbraConvexClip.h"
#include "penumbraShadowVolume.h"
#include "penumbraWedge.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace penumbra
{

/// How a plane faces every point of an area light.
enum class LightFacing : std::int8_t
{
  Away = -1,   ///< the whole light is behind the plane
  EdgeOn = 0,  ///< the light is a point in the plane (radius 0)
  Towards = 1, ///< the whole light is in front
  Mixed = 2    ///< the plane cuts the light
};

/**
 * Facing of the plane through `point` with normal `normal` (not necessarily unit) over a light:
 * (centre, 1) with `radius` in world units, or (direction towards it, 0) with `radius` its
 * angular radius in radians. With radius 0 it is ShadowVolume::Facing's sign; where the lengths
 * involved overflow, underflow or are NaN it says Mixed (a potential silhouette too many).
 */
VTKPENUMBRAGEOMETRY_EXPORT LightFacing FacingOverLight(
  const glm::dvec3& normal, const glm::dvec3& point, const glm::dvec4& light, double radius);

/**
 * Edges of `topo` (indices into topo.Edges) that are a silhouette, by the counting rule, for
 * some point of the light: boundary and non-manifold edges, and edges with a face whose plane
 * cuts the light or whose faces' facings do not cancel. `objectToWorld` places the caster; the
 * light is in world space as for FacingOverLight. `frontFacesOnly` is the rule of the centre's
 * shadow volume (ShadowVolume::FrontFacesSuffice).
 */
VTKPENUMBRAGEOMETRY_EXPORT std::vector<std::uint32_t> PotentialSilhouette(
  const CasterTopology& topo, const glm::dmat4& objectToWorld, const glm::dvec4& light,
  double radius, bool frontFacesOnly);

/**
 * One triangle's use of an edge a -> b, as the per-pixel evaluation needs it: the triangle's
 * normal as wound (any length) and +1 when it walks a -> b, -1 when b -> a.
 */
struct EdgeFace
{
  glm::dvec3 Normal;
  int Sign;
};

/**
 * Multiplicity of edge a -> b seen from p: the sum over its faces of Sign x weight, weight the
 * face's facing from p (+1, -1, 0 on its plane) or, front faces only, 1 when it faces p.
 */
VTKPENUMBRAGEOMETRY_EXPORT int MultiplicityFrom(const glm::dvec3& p, const glm::dvec3& a,
  const EdgeFace* faces, int faceCount, bool frontFacesOnly);

/**
 * Half-spaces outside which edge a -> b cannot change a sample's count inside its wedge. The
 * planes of its two faces cut space around the edge's line into four dihedral sectors, in each
 * of which MultiplicityFrom is constant; on a smooth mesh two of them are thin and hold every
 * point that sees the edge as a silhouette. When the wedge meets exactly one sector of non-zero
 * multiplicity, that sector's two planes, each pushed out by `margin` so that points on the
 * caster's own faces near the edge stay well inside. Otherwise (one or more than two faces,
 * faces in one plane, a light that both sectors see) none: the wedge alone bounds the edge.
 */
VTKPENUMBRAGEOMETRY_EXPORT std::vector<HalfSpace> SilhouetteSector(const Wedge& wedge,
  const glm::dvec3& a, const glm::dvec3& b, const EdgeFace* faces, int faceCount,
  bool frontFacesOnly, double margin);

/**
 * The normal of the plane through edge a -> b and a light point (x, y, z, 1), or parallel to a
 * light direction (x, y, z, 0): cross(b - a, light - a). For the light's centre it is the side
 * plane of the edge's shadow volume.
 */
VTKPENUMBRAGEOMETRY_EXPORT glm::dvec3 EdgeLightNormal(
  const glm::dvec3& a, const glm::dvec3& b, const glm::dvec4& light);

/**
 * p's side of the plane through edge point a with normal `throughLight` (EdgeLightNormal). It
 * equals the light point's side of the plane (p, edge), computed without p's large component
 * along the ray towards the light.
 */
VTKPENUMBRAGEOMETRY_EXPORT double SideOfEdgePlane(
  const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& throughLight);

/**
 * Whether the path on the light from `centre` to `sample` crosses the projection from p of the
 * edge a -> b: +1 or -1 (the side of the plane (p, a, b) that the sample lies on, sign of
 * cross(a - p, b - p) . (sample - p)) when it does, 0 otherwise. Light points are (x, y, z, 1),
 * or directions (x, y, z, 0) at infinity; for a point the edge must lie between p and the light.
 * Degenerate input (p on the edge's line, the path in the plane) gives 0, never NaN.
 */
VTKPENUMBRAGEOMETRY_EXPORT int SampleCrossing(const glm::dvec3& p, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec4& centre, const glm::dvec4& sample);

/**
 * Whether no light sample within `spread` of `centre` (|sample - centre|: both points, or both
 * directions) can cross the edge a -> b as seen from p: the plane (p, a, b) passes farther than
 * `spread` from the centre, so every sample lies on the centre's side of it and SampleCrossing
 * is 0 for all. A float margin of 1e-5 of the centre's distance keeps the counting shader's own
 * copy of this test on the safe side of rounding. Degenerate input gives false.
 */
VTKPENUMBRAGEOMETRY_EXPORT bool EdgePlaneMissesSamples(const glm::dvec3& p, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec4& centre, double spread);

/**
 * Whether a point p on an opaque surface can see the light point (x, y, z, 1) or direction
 * (x, y, z, 0): only in front of its own plane, on the side that `towardsEye` (from p towards
 * the eye) shows. `normal` is the plane's normal, either way round; a zero normal (no plane
 * known) sees every sample. Counting needs this beside its counts: it takes p a little off its
 * surface towards the eye (float rounding), from where the segment to a sample just behind the
 * plane can pass the surface's next edge.
 */
VTKPENUMBRAGEOMETRY_EXPORT bool SeesAboveSurface(const glm::dvec3& normal,
  const glm::dvec3& towardsEye, const glm::dvec3& p, const glm::dvec4& light);

/**
 * Whether every light sample within `spread` of the reference lies in front of a surface's
 * plane (1), none does (-1), or some may (0; each is then tested with SeesAboveSurface):
 * `unitNormal` is the plane's unit normal on the seen side, `towardsReference` the reference
 * point minus the surface point (spread: the samples' largest distance from it) or the
 * reference direction (spread: the largest |direction - reference direction|). A resolve tests
 * each sample only where the plane cuts the light (penumbraSurfaceSideDec.glsl). The margin of
 * 1e-4 of the spread keeps the shader's float copy on the safe side.
 */
VTKPENUMBRAGEOMETRY_EXPORT int SurfaceCutsLight(
  const glm::dvec3& unitNormal, const glm::dvec3& towardsReference, double spread);

/// A pixel's view ray, as CountingPointDepth takes it: its points at window depth 0 and 1 (on
/// the near and far planes) about some origin, and their clip-space w (equal under a parallel
/// projection).
struct ViewRay
{
  glm::dvec3 Near{ 0.0 };
  glm::dvec3 Far{ 0.0 };
  double NearW = 1.0;
  double FarW = 1.0;
};

/**
 * The window depth at which counting takes a pixel's point: both the wedges' edge terms and the
 * centre's rasterized count read it (penumbraCountingDepthFS.glsl is the shader's copy), so both
 * judge one point (the wedges move it two float steps further, for their own frame's rounding).
 * It lies on the view ray in front of the visible surface, on the side the eye sees, so that
 * the sides of the surface's own shadow volume start behind it:
 * - `depthBias` (window depth) in front of the scene depth;
 * - where the surface's plane is known (`plane`: unit normal and offset, n . x = w, about the
 *   ray's origin; zero where unknown), `depthBias` in front of the plane's exact depth on the
 *   ray instead, and at least `planeBias` times the ray's ends' distances from the origin off
 *   the plane along its normal.
 *
 * A rasterized depth at a grazing view can be off by more than depthBias, and a move along the
 * view ray barely leaves the plane there. A plane whose depth is not within 1% of the scene
 * depth's distance from the far plane (or 16 depthBias) is not the pixel's and is ignored. The
 * background (sceneDepth >= 1) stays 1, and the result is never below 0.
 */
VTKPENUMBRAGEOMETRY_EXPORT double CountingPointDepth(double sceneDepth, const ViewRay& ray,
  const glm::dvec4& plane, double depthBias, double planeBias);

/// What the choice between counting and averaging the same light samples needs of one caster.
struct CountingCost
{
  std::size_t PotentialEdges = 0;  ///< potential silhouette edges: counting draws one wedge each
  std::size_t SilhouetteEdges = 0; ///< the centre silhouette's distinct edges: averaging draws
                                   ///< about as many sides for every sample, each once
  double AngularRadius = 0.0;      ///< the light's radius over its distance, or a sun's radius
};

/**
 * A positional light's angular radius seen from one caster, for CountingCost: `radius` over the
 * distance from `light` to the centre of the caster's world box [boxMin, boxMax], as the model
 * was fitted. With the light inside the box (a lamp in a room, in a torus's hole, amid glyphs)
 * the centre may lie next to it however far the surfaces are: then over the mean distance to
 * the caster's centre silhouette (`silhouette`, between `points` mapped by `toWorld`), or, with
 * none, half the box's diagonal. 1e300 where the distance is within the radius: the light
 * reaches the caster, and its wedges would cover the view.
 */
VTKPENUMBRAGEOMETRY_EXPORT double CasterAngularRadius(const glm::dvec3& light, double radius,
  const glm::dvec3& boxMin, const glm::dvec3& boxMax, const std::vector<glm::dvec3>& points,
  const std::vector<SilhouetteEdge>& silhouette, const glm::dmat4& toWorld);

/**
 * Whether counting `samples` light samples (one volume pass and the potential silhouette's
 * wedges, cut to the receivers and to the edges' silhouette sectors) should take less time than
 * averaging as many hard shadows (one volume pass each). Both give the same image, so a wrong
 * guess costs time, never accuracy. Fitted to the benchmark on llvmpipe at 1024x768
 * (Documentation/wedges.md, "Cost": 24 rows, six scenes, two radii, 16 and 64 samples, after
 * the counting wedges were cut to each receiver's piece), to lose the least time on the rows
 * it gets wrong: the ratio grows with the
 * potential silhouette P against the centre silhouette's distinct edges E, and with the light's
 * angular radius rho (the penumbra, and how many edges cross the light seen from a pixel), and
 * falls with the samples N (averaging pays for each one, counting for each sample of each pixel
 * a wedge reaches):
 *
 *   counting / averaging = 0.61 (P / E)^0.67 (rho / 0.016)^0.72 (16 / N)^0.70,
 *
 * P and E summed over the casters, rho averaged over them weighted by E.
 */
VTKPENUMBRAGEOMETRY_EXPORT double CountingToAveraging(
  const std::vector<CountingCost>& casters, int samples);

/// What a light drew in its last frame, for CountingIsCheaper's hysteresis.
enum class LastChoice
{
  None,     ///< nothing yet (or not chosen by the model)
  Counted,  ///< counted its samples
  Averaged, ///< averaged them
};

/**
 * Whether to count rather than average: CountingToAveraging below 1, or, after a choice, below
 * 1.1 to go on counting and below 0.9 to start. Casters whose data changes every frame (a
 * simulation played back) move P and E a little each frame; near the boundary the light would
 * change method every few frames, and as the two methods differ on pixel boundaries (wedges.md),
 * its terminator's dots would flicker.
 */
VTKPENUMBRAGEOMETRY_EXPORT bool CountingIsCheaper(
  const std::vector<CountingCost>& casters, int samples, LastChoice last = LastChoice::None);

} // namespace penumbra

#endif
