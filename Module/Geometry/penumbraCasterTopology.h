/**
 * @file penumbraCasterTopology.h
 * @brief Triangle and edge topology of a shadow caster, built from any vtkPolyData.
 *
 * Shadow volumes need every edge of the caster linked to the triangles that use it and the
 * direction in which each triangle walks it. This header builds that once per data change:
 * polygons and strips are triangulated, coincident points welded (split normals and texture
 * seams duplicate points), non-finite points and degenerate triangles dropped, and every edge
 * classified as manifold, boundary or non-manifold.
 *
 * Positions are stored relative to the centre of the caster's bounds so that float uploads and
 * facing tests keep their precision far from the origin.
 */
#ifndef penumbraCasterTopology_h
#define penumbraCasterTopology_h

#include "vtkPenumbraGeometryModule.h" // for export macro

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkPolyData;

namespace penumbra
{
struct TopologyScratch;

enum class EdgeKind : std::uint8_t
{
  Boundary,     ///< one triangle
  Manifold,     ///< two triangles walking it in opposite directions
  Inconsistent, ///< two triangles walking it in the same direction (flipped winding)
  NonManifold   ///< three or more triangles
};

/// One triangle's use of an edge: +1 when it walks Edge::A -> Edge::B, -1 otherwise.
struct EdgeUse
{
  std::uint32_t Triangle;
  std::int32_t Sign;
};

/// An undirected edge, A < B, with its uses at [FirstUse, FirstUse + UseCount) in Uses.
struct Edge
{
  std::uint32_t A;
  std::uint32_t B;
  std::uint32_t FirstUse;
  std::uint32_t UseCount;
  EdgeKind Kind;
};

/// What the build met in the input, so that callers can warn about it.
struct TopologyReport
{
  std::size_t InputPoints = 0;
  std::size_t WeldedPoints = 0;
  std::size_t NonFinitePoints = 0;
  std::size_t InputTriangles = 0; ///< after triangulating polygons and strips
  std::size_t DegenerateTriangles = 0;
  std::size_t NonFiniteTriangles = 0;
  /// Triangles (or the triangles of polygons and strips) naming a point that does not exist.
  std::size_t InvalidIndexTriangles = 0;
  /// Polygons of four or more corners ear-cut into other triangles than the fan VTK's mapper
  /// draws them as (concave ones: convex polygons, planar or warped, are cut as that fan). Not a
  /// problem for the shadows; it tells that the depth of these triangles is not VTK's.
  std::size_t PolygonsCutUnlikeVTK = 0;
  std::size_t SkippedVerts = 0;
  std::size_t SkippedLines = 0;
  std::size_t BoundaryEdges = 0;
  std::size_t InconsistentEdges = 0;
  std::size_t NonManifoldEdges = 0;

  /// One line per problem worth a warning; empty when the input was a clean surface. Zero-area
  /// triangles are named only with `withDegenerate`: VTK draws nothing for them either, so
  /// beside other triangles dropping them changes no image (vtkTexturedSphereSource's poles and a
  /// parametric torus's seams hold dozens), but they say why a mesh casts nothing at all.
  std::string Describe(bool withDegenerate = true) const;
};

struct VTKPENUMBRAGEOMETRY_EXPORT CasterTopology
{
  /// The bounds' centre, moved along an axis where a few stray points stretch the bounds to the
  /// middle of the rest: Points, and the floats uploaded from them, are relative to it.
  glm::dvec3 Origin{ 0.0 };
  std::vector<glm::dvec3> Points;    ///< welded, relative to Origin
  std::vector<glm::uvec3> Triangles; ///< indices into Points, none degenerate
  std::vector<Edge> Edges;
  std::vector<EdgeUse> Uses;
  glm::dvec3 BoundsMin{ 0.0 }, BoundsMax{ 0.0 }; ///< relative to Origin
  /// Every edge manifold and consistently oriented: front faces alone bound the shadow.
  bool ClosedAndOriented = false;
  TopologyReport Report;

  bool Empty() const { return this->Triangles.empty(); }
  /// +1 when the mesh is ClosedAndOriented and each of its connected pieces winds its triangles
  /// counter-clockwise seen from outside (encloses a positive volume), -1 when each winds them
  /// clockwise, 0 otherwise (open, inconsistently wound, pieces wound both ways, or flat): where
  /// it is not 0, only triangles facing away from inside can be seen from outside. One pass over
  /// the edges and triangles; not kept by Build.
  int OutwardWinding() const;
  /// Relative weld tolerance used by Build (times the bounds diagonal).
  static constexpr double DefaultWeldTolerance = 1e-7;

  /// One-off builds (a TopologyBuilder each); data rebuilt often should keep a builder.
  static CasterTopology Build(
    vtkPolyData* input, double relativeWeldTolerance = DefaultWeldTolerance);
  /// Same, from raw triangles (used by tests and fuzzing).
  static CasterTopology Build(const std::vector<glm::dvec3>& points,
    const std::vector<glm::uvec3>& triangles, double relativeWeldTolerance = DefaultWeldTolerance);
};

/**
 * Builds CasterTopology into storage kept between builds. Data that changes every frame (a
 * simulation played back) then rebuilds without allocating once its size has settled: fresh
 * pages cost about as much as the build itself at a million triangles. The point and triangle
 * passes and the edge work run in parallel (vtkSMPTools), in fixed chunks, so the result does
 * not depend on the threads. Triangles-only data with float or double points is read in place
 * and the scratch held is 1 byte a triangle and 12 bytes a point, plus 4 a point for each part
 * the half-edge grouping counts in parallel (one per thread, at most four): about 9 to 15 bytes
 * a triangle. Other cells and point types add their triangulated or converted copy.
 */
class VTKPENUMBRAGEOMETRY_EXPORT TopologyBuilder
{
public:
  TopologyBuilder();
  ~TopologyBuilder();
  TopologyBuilder(const TopologyBuilder&) = delete;
  TopologyBuilder& operator=(const TopologyBuilder&) = delete;

  /// Replaces `topology` with that of `input`, reusing its storage. The inputs must not be
  /// `topology`'s own arrays: they are cleared first.
  void Build(vtkPolyData* input, CasterTopology& topology,
    double relativeWeldTolerance = CasterTopology::DefaultWeldTolerance);
  void Build(const std::vector<glm::dvec3>& points, const std::vector<glm::uvec3>& triangles,
    CasterTopology& topology, double relativeWeldTolerance = CasterTopology::DefaultWeldTolerance);

  /// Bytes of scratch held for the next build.
  std::size_t GetScratchBytes() const;

private:
  std::unique_ptr<TopologyScratch> Scratch;
};

} // namespace penumbra

#endif
