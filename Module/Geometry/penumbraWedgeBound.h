/**
 * @file penumbraWedgeBound.h
 * @brief The geometry the GPU rasterizes for one silhouette edge: the bound of the pixels whose
 * view of the edge can cross the light, as triangles ready to upload.
 *
 * Wedges (the 2002 method) and per-sample counting both draw it. It is the edge's Wedge, or its
 * LightPyramid where the edge points at the light, or the whole viewport where it has
 * neither; with a receivers' box it is cut to that box and to the edge's silhouette sector.
 */
#ifndef penumbraWedgeBound_h
#define penumbraWedgeBound_h

#include "penumbraConvexClip.h"
#include "vtkPenumbraGeometryModule.h" // for export macro

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace penumbra
{

struct EdgeFace;

/// What bounds one edge's wedge fragments (see AppendWedgeBound).
enum class WedgeShape
{
  Planes,       ///< a Wedge: four planes around the edge
  Enlarged,     ///< a Wedge cut to the receivers with a cut left out (ClipBox's CutsLeftOut):
                ///< it may reach beyond the wedge, towards the eye, so draw it by back faces
  Pyramid,      ///< a LightPyramid: the edge points at the light
  FullViewport, ///< no bound of its own: the receivers' box, or a triangle over the viewport
  Nothing       ///< the bound misses the receivers' box
};

/**
 * Appends edge from -> to's fragments' bound, from `light` ((position, 1) or (direction, 0)) of
 * `radius`, every vertex (x, y, z, w) followed by `attributes`. With a valid receivers' box
 * (same coordinates as the edge) it is the bound cut to the box (and, given the edge's two
 * `faces`, to its silhouette sector, SilhouetteSector with `frontFacesOnly`): a closed convex
 * polyhedron of outward triangles. Without one, the wedge or pyramid whole, reaching to infinity,
 * or, for an edge with neither, a clockwise full-viewport triangle (w = 2, clip space, on the
 * far plane) that back-face culling keeps: exact but costly. Returns which it was.
 */
VTKPENUMBRAGEOMETRY_EXPORT WedgeShape AppendWedgeBound(const glm::dvec3& from, const glm::dvec3& to,
  const glm::dvec4& light, double radius, const Box& receivers, const EdgeFace* faces,
  bool frontFacesOnly, const float* attributes, int attributeCount, std::vector<float>& vertices,
  std::vector<std::uint32_t>& indices);

/**
 * As AppendWedgeBound with a valid `receivers` box, but cut to each of `pieces` (disjoint boxes
 * in the same coordinates, DisjointPieces of the receivers' own boxes) rather than to the whole
 * box: one closed convex polyhedron for each piece the bound meets, so that the space between
 * receivers (the air between a caster and the ground) draws nothing. Each vertex's attributes
 * are followed by its piece's min and max corners (6 floats): a pixel's view ray can cross
 * several pieces' polyhedra, and only the one whose piece holds the pixel's point may count it
 * (min <= p < max, which no two pieces share). The sector's margin follows `receivers`. Returns
 * Nothing when the bound meets no piece.
 */
VTKPENUMBRAGEOMETRY_EXPORT WedgeShape AppendWedgeBoundInPieces(const glm::dvec3& from,
  const glm::dvec3& to, const glm::dvec4& light, double radius, const Box& receivers,
  const std::vector<Box>& pieces, const EdgeFace* faces, bool frontFacesOnly,
  const float* attributes, int attributeCount, std::vector<float>& vertices,
  std::vector<std::uint32_t>& indices);

} // namespace penumbra

#endif
