/**
 * @file   penumbraSceneBounds.h
 * @brief  The world boxes vtkSoftShadowPass narrows its work to: the scene's, each prop's and
 *         the receivers'.
 *
 * The scene box holds every visible prop (UseBounds or not), so every pixel's visible point:
 * the shadows' depth range and the volumes' scissors are narrowed to it. The prop boxes split
 * it where VTK's own bounds would hold empty space: an assembly's parts, a composite mapper's
 * blocks and, where the eye stands inside the box of one mesh (a room, a vessel), the grid
 * cells that mesh occupies, so that the range keeps the space around the eye out. The receiver
 * bounds hold every receiver, with a piece round each, and the counting and penumbra wedges are
 * cut to them.
 *
 * Props outside the shadows (widgets' representations, light markers) add nothing.
 */
#ifndef penumbraSceneBounds_h
#define penumbraSceneBounds_h

#include "penumbraConvexClip.h"

#include "vtkType.h"

#include <glm/glm.hpp>

#include <map>
#include <vector>

class vtkDataSet;
class vtkProp;
class vtkRenderer;

namespace penumbra
{

/// The scene's, the visible props' and the receivers' world boxes, rebuilt each frame (the
/// occupancy grids kept while their data is unchanged). See the file's description.
class SceneBounds
{
public:
  /// Rebuilds the scene and prop boxes from `renderer`'s visible props; both are left empty
  /// (the scene box invalid) when one prop's bounds are not finite.
  void UpdateScene(vtkRenderer* renderer);
  /// Holds every visible prop; invalid where one is unbounded.
  const Box& Scene() const { return this->SceneBox; }
  /// Each visible prop's (assembly part's, block's, occupied cell's) world box.
  const std::vector<Box>& Props() const { return this->PropBoxes; }

  /// Rebuilds the receivers' bounds (penumbra::StableReceiverBox, so that small moves keep the
  /// wedges cut as they were); empty when a receiver's extent is unknown.
  void UpdateReceivers(const std::vector<vtkProp*>& receivers);
  /// Every receiver's box and the disjoint pieces round each receiver, from UpdateReceivers.
  const ReceiverBounds& Receivers() const { return this->ReceiverBoxes; }

  /// The distance from `point` to the nearest surface of a visible prop's box: to the box from
  /// outside it, to its nearest face from inside (a light inside a room is as far from the walls
  /// as from their box's faces). Infinite when no prop has finite bounds.
  static double NearestPropSurface(vtkRenderer* renderer, const glm::dvec3& point);

private:
  /// A dataset's occupied grid cells (penumbra::OccupancyGrid), in its own coordinates, kept
  /// while the dataset is unchanged.
  struct Occupancy
  {
    vtkMTimeType Time = 0;
    std::vector<Box> Boxes;
    bool Finite = true; ///< false where a cell's box was not: the data's bounds stand for it
  };
  /// Adds to `boxes`, in place of the box of `data` (which `dataToWorld` places), the world
  /// boxes of the grid cells its cells occupy. False for data of more than a million cells,
  /// which is not walked each time it changes, or with a cell whose box is not finite (a NaN
  /// point, of which VTK may draw the rest of the cell). Entries of data not asked about in a frame
  /// are dropped (`used`).
  bool OccupiedBoxes(vtkDataSet* data, const glm::dmat4& dataToWorld, std::vector<Box>& boxes,
    std::map<vtkDataSet*, Occupancy>& used);

  Box SceneBox;
  std::vector<Box> PropBoxes;
  std::map<vtkDataSet*, Occupancy> Occupancies;
  ReceiverBounds ReceiverBoxes;
};

} // namespace penumbra

#endif
