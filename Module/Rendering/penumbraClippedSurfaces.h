/**
 * @file   penumbraClippedSurfaces.h
 * @brief  A mapper's clipping planes applied to the surface it draws, as VTK's shaders apply
 *         them, and kept between frames.
 *
 * vtkOpenGLPolyDataMapper (and so vtkCompositePolyDataMapper2) discards every fragment on the
 * negative side of any of its first six clipping planes (world coordinates; the normal points to
 * what is kept). Casting the whole surface would shadow with parts VTK does not draw, and, as the
 * depth of those parts is missing, leave volumes open where they enter them. So the caster is the
 * surface cut by each plane in turn (vtkClipPolyData in the data's coordinates, the plane carried
 * there by the actor's matrix as vtkAbstractMapper3D::GetClippingPlaneInDataCoords does): the
 * surface VTK draws, up to rounding. One chain of filters per (actor, part) keeps its output, so
 * the caster built from it is rebuilt only when the data, a plane or the matrix changes.
 */
#ifndef penumbraClippedSurfaces_h
#define penumbraClippedSurfaces_h

#include "vtkSmartPointer.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

class vtkActor;
class vtkClipPolyData;
class vtkDataObject;
class vtkDataSetSurfaceFilter;
class vtkMapper;
class vtkPlane;

namespace penumbra
{

/// The planes VTK clips `mapper`'s fragments by (at most six), as (normal, offset) in world
/// coordinates: a point x is drawn where dot(normal, x) + offset >= 0 for every plane.
std::vector<glm::dvec4> DrawnClippingPlanes(vtkMapper* mapper);

class ClippedSurfaces
{
public:
  /// `data` as `actor`'s mapper draws it at `objectToWorld` under `planes` (its
  /// DrawnClippingPlanes): `data` itself without planes, else its surface cut by them; nullptr
  /// where nothing of it is left.
  vtkDataObject* Apply(vtkActor* actor, std::size_t part, vtkDataObject* data,
    const glm::dmat4& objectToWorld, const std::vector<glm::dvec4>& planes);
  /// Drops the chains not applied since the last call: props removed, hidden or unclipped. Ends
  /// the walk: the next Apply of an actor's part is its first place again.
  void PurgeUnused();

private:
  struct Chain
  {
    vtkDataObject* Input = nullptr;
    vtkSmartPointer<vtkDataSetSurfaceFilter> Surface; ///< for datasets that are not polydata
    std::vector<vtkSmartPointer<vtkPlane>> Planes;
    std::vector<vtkSmartPointer<vtkClipPolyData>> Clips;
    bool Used = false;
  };
  void Connect(Chain& chain, vtkDataObject* data, std::size_t planes);

  /// Keyed by actor, part and place in the walk: an actor drawn twice (added to the renderer
  /// and a part of an assembly) is cut at each place's matrix.
  std::map<std::tuple<vtkActor*, std::size_t, std::size_t>, Chain> Chains;
  std::map<std::pair<vtkActor*, std::size_t>, std::size_t> AppliedThisWalk;
};

} // namespace penumbra

#endif
