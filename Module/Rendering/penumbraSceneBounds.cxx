#include "penumbraSceneBounds.h"

#include "penumbraCulling.h"
#include "penumbraMatrices.h"
#include "penumbraSceneWalk.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkDataSet.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkProp3D.h"
#include "vtkRenderer.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra
{
namespace
{
/// What a prop's bounds add to a box: nothing (no bounds: 2D props, empty data), their extent,
/// or nothing because they are not finite (Unknown).
enum class PropExtent
{
  None,
  Finite,
  Unknown
};

/// What VTK's `bounds` (xmin, xmax, ymin, ...; null where there are none) grown by `reach` on
/// every side add to `box`.
PropExtent ExtendByBounds(Box& box, const double* bounds, double reach)
{
  if (!bounds || !vtkMath::AreBoundsInitialized(bounds))
  {
    return PropExtent::None;
  }
  if (!std::all_of(bounds, bounds + 6, [](double b) { return std::isfinite(b); }) ||
    !std::isfinite(reach))
  {
    return PropExtent::Unknown;
  }
  box.Extend(glm::dvec3(bounds[0], bounds[2], bounds[4]) - reach,
    glm::dvec3(bounds[1], bounds[3], bounds[5]) + reach);
  return PropExtent::Finite;
}

PropExtent ExtendByProp(Box& box, vtkProp* prop)
{
  // Imposter spheres and sticks reach beyond the bounds VTK gives for them.
  return ExtendByBounds(box, prop->GetBounds(), ImposterReach(prop));
}

/// A world box around part of what a prop draws and, where it is the box of one dataset whose
/// cells VTK draws as they are, that dataset and its matrix to world (for OccupiedBoxes).
struct PropBox
{
  Box World;
  vtkDataSet* Data = nullptr;
  glm::dmat4 DataToWorld{ 1.0 };
};

/// The dataset whose cells `mapper` draws, as they are: a polydata or dataset mapper's input.
/// Null for mappers that draw something else at their input's points (glyphs, imposters).
vtkDataSet* DrawnCells(vtkMapper* mapper)
{
  const bool cells =
    IsExactly(mapper, "vtkOpenGLPolyDataMapper") || IsExactly(mapper, "vtkDataSetMapper");
  return cells ? vtkDataSet::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
}

/// More blocks than this give a composite prop one box: the range's cost grows with the boxes.
constexpr std::size_t MaxBlockBoxes = 4096;

/// Adds the boxes of what `part` (a prop, or an assembly's part) draws at `toWorld` (its
/// matrix, or its path's): one per block of a composite mapper's data, up to MaxBlockBoxes
/// (hidden blocks too: they only widen the range), else, or where a block's bounds are not
/// finite, its bounds in world space as VTK gives them (`worldBounds`), grown by `reach`.
PropExtent AddDrawnBoxes(vtkProp3D* part, const glm::dmat4& toWorld, const double* worldBounds,
  double reach, std::vector<PropBox>& boxes)
{
  auto* actor = vtkActor::SafeDownCast(part);
  vtkMapper* mapper = actor && reach == 0.0 ? MapperDrawn(actor) : nullptr;
  auto* tree = IsExactly(mapper, "vtkCompositePolyDataMapper2")
    ? vtkDataObjectTree::SafeDownCast(mapper->GetInputDataObject(0, 0))
    : nullptr;
  if (tree)
  {
    std::vector<PropBox> blocks;
    bool finite = true;
    for (vtkDataObject* leaf : vtk::Range(tree, EveryLeaf()))
    {
      auto* data = vtkDataSet::SafeDownCast(leaf);
      Box box;
      const PropExtent extent =
        data ? ExtendByBounds(box, data->GetBounds(), 0.0) : PropExtent::None;
      if (extent == PropExtent::Unknown)
      {
        finite = false; // perhaps a hidden block's: VTK's bounds of the visible ones decide
        break;
      }
      if (extent == PropExtent::Finite)
      {
        blocks.push_back({ TransformedBox(box, toWorld), data, toWorld });
      }
      if (blocks.size() > MaxBlockBoxes)
      {
        break;
      }
    }
    if (finite && blocks.size() <= MaxBlockBoxes)
    {
      boxes.insert(boxes.end(), blocks.begin(), blocks.end());
      return blocks.empty() ? PropExtent::None : PropExtent::Finite;
    }
  }
  Box box;
  const PropExtent extent = ExtendByBounds(box, worldBounds, reach);
  if (extent == PropExtent::Finite)
  {
    boxes.push_back({ box, mapper ? DrawnCells(mapper) : nullptr, toWorld });
  }
  return extent;
}

/// Adds the world boxes of what `prop` draws to `boxes`: an assembly's, those of each visible
/// part (VTK's own bounds of the assembly would hold the space between its parts, and the eye
/// when a part lies behind it); any other prop's, AddDrawnBoxes'. Unknown where a box is not
/// finite.
PropExtent AddPropBoxes(vtkProp* prop, std::vector<PropBox>& boxes)
{
  const double reach = ImposterReach(prop);
  auto* assembly = vtkAssembly::SafeDownCast(prop);
  if (!assembly)
  {
    auto* prop3D = vtkProp3D::SafeDownCast(prop);
    if (!prop3D)
    {
      Box box;
      const PropExtent extent = ExtendByProp(box, prop);
      if (extent == PropExtent::Finite)
      {
        boxes.push_back({ box });
      }
      return extent;
    }
    return AddDrawnBoxes(prop3D, ToGlm(prop3D->GetMatrix()), prop3D->GetBounds(), reach, boxes);
  }
  vtkAssemblyPath* path;
  for (assembly->InitPathTraversal(); (path = assembly->GetNextPath());)
  {
    vtkAssemblyNode* node = path->GetLastNode();
    auto* part = vtkProp3D::SafeDownCast(node->GetViewProp());
    if (!part || !part->GetVisibility())
    {
      continue;
    }
    // As vtkAssembly::GetBounds takes them: the part at the path's matrix.
    part->PokeMatrix(node->GetMatrix());
    const PropExtent extent =
      AddDrawnBoxes(part, ToGlm(node->GetMatrix()), part->GetBounds(), reach, boxes);
    part->PokeMatrix(nullptr);
    if (extent == PropExtent::Unknown)
    {
      return extent;
    }
  }
  return PropExtent::Finite;
}
} // namespace

bool SceneBounds::OccupiedBoxes(vtkDataSet* data, const glm::dmat4& dataToWorld,
  std::vector<Box>& boxes, std::map<vtkDataSet*, Occupancy>& used)
{
  if (data->GetNumberOfCells() > 1000000)
  {
    return false;
  }
  // A dataset that another prop drew this frame has its grid in `used` already.
  auto taken = used.try_emplace(data);
  Occupancy& occupancy = taken.first->second;
  if (taken.second)
  {
    auto kept = this->Occupancies.find(data);
    if (kept != this->Occupancies.end() && kept->second.Time == data->GetMTime())
    {
      occupancy = std::move(kept->second);
    }
    else
    {
      Box bounds;
      if (ExtendByBounds(bounds, data->GetBounds(), 0.0) != PropExtent::Finite)
      {
        used.erase(taken.first);
        return false;
      }
      OccupancyGrid grid(bounds);
      double cell[6];
      bool finite = true;
      for (vtkIdType i = 0; i < data->GetNumberOfCells() && finite; ++i)
      {
        data->GetCellBounds(i, cell);
        finite =
          grid.Add(glm::dvec3(cell[0], cell[2], cell[4]), glm::dvec3(cell[1], cell[3], cell[5]));
      }
      occupancy = Occupancy{ data->GetMTime(), grid.Boxes(), finite };
    }
  }
  if (!occupancy.Finite)
  {
    return false;
  }
  for (const Box& box : occupancy.Boxes)
  {
    boxes.push_back(TransformedBox(box, dataToWorld));
  }
  return true;
}

void SceneBounds::UpdateScene(vtkRenderer* renderer)
{
  this->SceneBox = Box();
  this->PropBoxes.clear();
  const glm::dvec3 eye = glm::make_vec3(renderer->GetActiveCamera()->GetPosition());
  std::map<vtkDataSet*, Occupancy> used;
  std::vector<PropBox> drawn;
  for (vtkProp* prop : VisiblePropsInTheShadows(renderer))
  {
    // Empty props add nothing in depth; one of unknown extent, no box at all.
    drawn.clear();
    if (AddPropBoxes(prop, drawn) == PropExtent::Unknown)
    {
      this->SceneBox = Box();
      this->PropBoxes.clear();
      this->Occupancies = std::move(used);
      return;
    }
    for (const PropBox& box : drawn)
    {
      this->SceneBox.Extend(box.World.Min, box.World.Max);
      const bool holdsEye = glm::all(glm::greaterThanEqual(eye, box.World.Min)) &&
        glm::all(glm::lessThanEqual(eye, box.World.Max));
      if (!holdsEye || !box.Data ||
        !this->OccupiedBoxes(box.Data, box.DataToWorld, this->PropBoxes, used))
      {
        this->PropBoxes.push_back(box.World);
      }
    }
  }
  this->Occupancies = std::move(used);
}

void SceneBounds::UpdateReceivers(const std::vector<vtkProp*>& receivers)
{
  Box current;
  std::vector<Box> each(receivers.size());
  for (std::size_t r = 0; r < receivers.size(); ++r)
  {
    if (ExtendByProp(each[r], receivers[r]) != PropExtent::Finite)
    {
      this->ReceiverBoxes = {}; // a receiver of unknown extent: nothing to cut to
      return;
    }
    current.Extend(each[r].Min, each[r].Max);
  }
  ReceiverBounds& bounds = this->ReceiverBoxes;
  bounds.Whole = StableReceiverBox(bounds.Whole, current);
  for (Box& box : each)
  {
    box = ReceiverPieceBox(bounds.Whole, box);
  }
  bounds.Pieces = DisjointPieces(each);
}

double SceneBounds::NearestPropSurface(vtkRenderer* renderer, const glm::dvec3& point)
{
  double nearest = std::numeric_limits<double>::infinity();
  for (vtkProp* prop : VisiblePropsInTheShadows(renderer))
  {
    Box box;
    if (ExtendByProp(box, prop) != PropExtent::Finite)
    {
      continue;
    }
    const glm::dvec3 outside = point - glm::clamp(point, box.Min, box.Max);
    const glm::dvec3 inside = glm::min(point - box.Min, box.Max - point);
    nearest = std::min(nearest,
      glm::dot(outside, outside) > 0.0 ? glm::length(outside)
                                       : std::min({ inside.x, inside.y, inside.z }));
  }
  return nearest;
}

} // namespace penumbra
