/**
 * @file penumbraConvexClip.h
 * @brief A box cut by half-spaces, as a closed triangle mesh, without OpenGL.
 *
 * Wedges and shadow volumes reach to infinity, but no receiver lies outside the receivers'
 * bounds: cutting a wedge to that box (Lloyd et al., "CC Shadow Volumes", 2004, clamp volumes to
 * the receivers' extent the same way) and to the half-spaces where its edge can matter leaves a
 * bounded convex polyhedron whose faces cover fewer pixels. Drawn like the wedge it replaces
 * (front faces against the scene depth, or back faces), it still meets every ray into it once.
 */
#ifndef penumbraConvexClip_h
#define penumbraConvexClip_h

#include "vtkPenumbraGeometryModule.h" // for export macro

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace penumbra
{

/// The points x with dot(Normal, x) <= Offset.
struct HalfSpace
{
  glm::dvec3 Normal{ 0.0 };
  double Offset = 0.0;
};

/// A closed convex polyhedron as outward triangles over shared points.
struct ConvexPolyhedron
{
  std::vector<glm::dvec3> Points;
  std::vector<std::uint32_t> Triangles; ///< three indices into Points per triangle
  std::size_t CutsLeftOut = 0;          ///< half-spaces ClipBox left out to keep it closed
  bool Empty() const { return this->Triangles.empty(); }
  /// The enclosed volume (positive for outward triangles), by the divergence theorem.
  VTKPENUMBRAGEOMETRY_EXPORT double Volume() const;
};

/// Corner `i` (0 to 7) of the box min..max: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
inline glm::dvec3 BoxCorner(const glm::dvec3& min, const glm::dvec3& max, int i)
{
  return glm::dvec3((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
}

/// An axis-aligned box; Valid is false for the unbounded case (no box to cut to).
struct Box
{
  bool Valid = false;
  glm::dvec3 Min{ 0.0 }, Max{ 0.0 };

  bool Contains(const Box& other) const;
  bool operator==(const Box& other) const
  {
    return this->Valid == other.Valid && this->Min == other.Min && this->Max == other.Max;
  }
  double Diagonal() const { return this->Valid ? glm::length(this->Max - this->Min) : 0.0; }
  /// Grows the box to hold [min, max] (the first call sets it).
  void Extend(const glm::dvec3& min, const glm::dvec3& max);
};

/// The axis-aligned box that holds `box` moved by `matrix` (its eight corners'); invalid when
/// `box` is.
VTKPENUMBRAGEOMETRY_EXPORT Box TransformedBox(const Box& box, const glm::dmat4& matrix);

/**
 * The box to cut wedges to this frame: `kept` while it holds `current` and is not more than
 * twice its size, so that receivers moving a little do not rebuild every wedge; else `current`
 * grown by a tenth of its size on every side. Either way at least 1% larger than `current`, so
 * that no receiver lies on a face of the box (where a cut face and the receiver would fight in
 * the depth test). Invalid when `current` is.
 */
VTKPENUMBRAGEOMETRY_EXPORT Box StableReceiverBox(const Box& kept, const Box& current);

/// Where receiver points can be: Whole holds every receiver (StableReceiverBox; invalid when
/// nothing bounds them) and Pieces, where built, are disjoint boxes inside it around each
/// receiver (DisjointPieces of ReceiverPieceBox), to which counting wedges are cut.
struct ReceiverBounds
{
  Box Whole;
  std::vector<Box> Pieces;
  bool operator==(const ReceiverBounds& other) const
  {
    return this->Whole == other.Whole && this->Pieces == other.Pieces;
  }
};

/**
 * One receiver's box for DisjointPieces: `receiver` grown by 1% of the size of `receivers` (the
 * stable box that holds every receiver, StableReceiverBox) on every side, so that no receiver
 * point lies on a piece's face, then out to a grid of 2% of that size from its min corner, so
 * that a receiver moving a little keeps its box (and every caster its wedges); clamped to
 * `receivers`. Invalid when either is invalid or not finite (its diagonal included), or
 * `receivers` has no size.
 */
VTKPENUMBRAGEOMETRY_EXPORT Box ReceiverPieceBox(const Box& receivers, const Box& receiver);

/**
 * Disjoint boxes whose union is the union of the valid, finite `boxes`: the cells of the grid of
 * the boxes' faces that lie in some box, merged into runs along x, then along y and z where their
 * extents agree. Pieces are half-open ([min, max)), so a point on a face two pieces share belongs
 * to one; a box of no volume holds no point of them. More than `maxBoxes` valid boxes give one
 * piece, their bounds; none gives none.
 */
VTKPENUMBRAGEOMETRY_EXPORT std::vector<Box> DisjointPieces(
  const std::vector<Box>& boxes, std::size_t maxBoxes = 8);

/**
 * The box cut by every half-space: a closed surface. Empty when nothing of the box is left (or
 * less than a sliver of 1e-12 of its size plus its distance from the origin). Half-spaces with a
 * zero or non-finite normal (or an offset that overflows once the normal is made unit) are
 * ignored, and so is a cut whose rounding would leave the surface open (nearly parallel planes,
 * a cap whose points lie nearly on a line; counted in CutsLeftOut): the result then holds the
 * exact cut but is larger, which a caller must allow for (AppendWedgeBound reports such a wedge
 * as Enlarged).
 */
VTKPENUMBRAGEOMETRY_EXPORT ConvexPolyhedron ClipBox(
  const Box& box, const std::vector<HalfSpace>& halfSpaces);

} // namespace penumbra

#endif
