/**
 * @file penumbraPlateaus.h
 * @brief Haines' plateau soft shadows on a receiver plane, as triangles, without OpenGL.
 *
 * Haines ("Soft planar shadows using plateaus", 2001) draws, seen straight down the plane's
 * normal, the hard drop shadow of a caster at depth 0 and around it one primitive per silhouette
 * element whose depth grows from 0 at the hard shadow's outline to 1 at the edge of the
 * penumbra: a cone at every silhouette vertex and a sheet along every silhouette edge. With a
 * depth test keeping the smallest value the darkest primitive wins at every point; the depth
 * t then gives the light intensity through a falloff (linear or sinusoidal).
 *
 * The penumbra's outer edge here is exact for a vertex: the light's rim (a circle of the
 * light's radius facing the vertex, or the cone of a directional light's angular radius)
 * projected through the vertex onto the plane. For a light high above, that is Haines' circular
 * cone of radius r h / (H - h) (light radius r at height H, vertex at height h); for a light
 * near the horizon it becomes the elongated (elliptical) cone. Sheets take at each of their
 * sample points the extent of that projected rim across the edge, so their width varies along
 * the edge (Haines' hyperbolic sheets, tessellated).
 *
 * Known approximations, by design of the method: the umbra is the hard shadow of the light's
 * centre (too large: no inner penumbra), and intensity falls off with the fraction of the way
 * across the outer penumbra, not with the visible area of the light.
 */
#ifndef penumbraPlateaus_h
#define penumbraPlateaus_h

#include "penumbraCasterTopology.h"
#include "penumbraShadowVolume.h"

#include <glm/glm.hpp>

#include <vector>

namespace penumbra
{

/// A receiver plane: a point on it, its unit normal (towards the lit side) and a basis (U, V).
struct VTKPENUMBRAGEOMETRY_EXPORT ReceiverPlane
{
  glm::dvec3 Origin{ 0.0 };
  glm::dvec3 Normal{ 0.0, 0.0, 1.0 };
  glm::dvec3 U{ 1.0, 0.0, 0.0 }, V{ 0.0, 1.0, 0.0 };

  /// A plane through `origin` with normal `normal` (normalized here); false if it has none.
  static bool Make(const glm::dvec3& origin, const glm::dvec3& normal, ReceiverPlane& plane);
  /// The same plane, its Origin taken as its point nearest `near` (the scene), where that is
  /// finite: an origin given far along the plane would make every in-plane coordinate huge.
  static bool MakeNear(const glm::dvec3& origin, const glm::dvec3& normal, const glm::dvec3& near,
    ReceiverPlane& plane);
  double Height(const glm::dvec3& x) const { return glm::dot(this->Normal, x - this->Origin); }
  glm::dvec2 ToPlane(const glm::dvec3& x) const
  {
    return { glm::dot(x - this->Origin, this->U), glm::dot(x - this->Origin, this->V) };
  }
};

enum class PlateauFalloff
{
  Linear,    ///< intensity = t
  Sinusoidal ///< intensity = (1 - cos(pi t)) / 2: no crease where the penumbra meets light
};

/// Light intensity (0 shadow, 1 lit) of plateau depth t in [0, 1].
/// A receiver plane fitted to a flat actor's points (world space), and how far it reaches.
struct PlaneFit
{
  ReceiverPlane Plane;
  glm::dvec2 Min{ 0.0 }, Max{ 0.0 }; ///< the points' extent in the plane's coordinates
  double Thickness = 0.0;            ///< largest distance of a point from the plane
  double Extent = 0.0;               ///< diagonal of Min..Max
};

/**
 * Fits the plane through three spread points (the first, the farthest from it, and the one
 * farthest from their line), centred on the points' mean. Non-finite points are ignored.
 * Returns false when the points span no plane (fewer than three, or all on a line).
 */
VTKPENUMBRAGEOMETRY_EXPORT bool FitReceiverPlane(
  const std::vector<glm::dvec3>& points, PlaneFit& fit);

VTKPENUMBRAGEOMETRY_EXPORT double PlateauIntensity(double t, PlateauFalloff falloff);

/// A vertex of a plateau triangle: plane coordinates (U, V) and plateau depth T in [0, 1].
struct PlateauVertex
{
  float U, V, T;
};

/// What a plateau build met, for warnings and statistics.
struct PlateauReport
{
  std::size_t ShadowTriangles = 0; ///< hard drop shadow
  std::size_t Cones = 0;
  std::size_t Sheets = 0;
  std::size_t SkippedAboveLight = 0; ///< caster points at or above the light: cast no plateau
};

/// Tessellation of the plateau primitives.
struct PlateauOptions
{
  int RimSegments = 24;  ///< segments of a cone's rim
  int SheetSegments = 4; ///< segments along a sheet (its width varies along the edge)
};

/**
 * Appends the plateau triangles of one caster to `triangles`: `volume` must be the caster's
 * volume for the light's centre, built with caps (its light cap is the set of casting
 * triangles, its silhouette the outline). `objectToWorld` maps the topology's points to world
 * space; `light` is (position, 1) or (direction towards the light, 0) in world space and
 * `radius` the light's radius in world units, or its angular radius in radians.
 */
VTKPENUMBRAGEOMETRY_EXPORT PlateauReport BuildPlateaus(const CasterTopology& topo,
  const ShadowVolume& volume, const glm::dmat4& objectToWorld, const glm::dvec4& light,
  double radius, const ReceiverPlane& plane, std::vector<PlateauVertex>& triangles,
  const PlateauOptions& options = PlateauOptions());

} // namespace penumbra

#endif
