#include "penumbraClippedSurfaces.h"

#include "vtkClipPolyData.h"
#include "vtkDataSet.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkMapper.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPolyData.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra
{

std::vector<glm::dvec4> DrawnClippingPlanes(vtkMapper* mapper)
{
  std::vector<glm::dvec4> planes;
  vtkPlaneCollection* collection = mapper ? mapper->GetClippingPlanes() : nullptr;
  const int count = collection ? std::min(collection->GetNumberOfItems(), 6) : 0;
  for (int i = 0; i < count; ++i)
  {
    vtkPlane* plane = collection->GetItem(i);
    const glm::dvec3 normal = glm::make_vec3(plane->GetNormal());
    planes.emplace_back(normal, -glm::dot(normal, glm::make_vec3(plane->GetOrigin())));
  }
  return planes;
}

void ClippedSurfaces::Connect(Chain& chain, vtkDataObject* data, std::size_t planes)
{
  chain.Input = data;
  chain.Surface = nullptr;
  chain.Planes.clear();
  chain.Clips.clear();
  vtkAlgorithmOutput* upstream = nullptr;
  if (!vtkPolyData::SafeDownCast(data))
  {
    chain.Surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    chain.Surface->SetInputData(data);
    upstream = chain.Surface->GetOutputPort();
  }
  for (std::size_t i = 0; i < planes; ++i)
  {
    auto plane = vtkSmartPointer<vtkPlane>::New();
    auto clip = vtkSmartPointer<vtkClipPolyData>::New();
    clip->SetClipFunction(plane);
    if (upstream)
    {
      clip->SetInputConnection(upstream);
    }
    else
    {
      clip->SetInputData(data);
    }
    upstream = clip->GetOutputPort();
    chain.Planes.push_back(plane);
    chain.Clips.push_back(clip);
  }
}

vtkDataObject* ClippedSurfaces::Apply(vtkActor* actor, std::size_t part, vtkDataObject* data,
  const glm::dmat4& objectToWorld, const std::vector<glm::dvec4>& planes)
{
  if (planes.empty() || !vtkDataSet::SafeDownCast(data))
  {
    return data;
  }
  Chain& chain = this->Chains[{ actor, part, this->AppliedThisWalk[{ actor, part }]++ }];
  chain.Used = true;
  // Reconnecting marks the filters modified, so only a new input or plane count does.
  if (chain.Input != data || chain.Planes.size() != planes.size())
  {
    this->Connect(chain, data, planes.size());
  }
  for (std::size_t i = 0; i < planes.size(); ++i)
  {
    // The plane in the data's coordinates; vtkClipPolyData keeps where normal . (x - origin)
    // is positive, as VTK's shader keeps a non-negative distance (equality has no area).
    const glm::dvec4 local = glm::transpose(objectToWorld) * planes[i];
    const glm::dvec3 normal(local);
    const double length2 = glm::dot(normal, normal);
    if (!(length2 > 0.0) || !std::isfinite(length2) || !std::isfinite(local.w))
    {
      return nullptr; // a degenerate matrix or plane: VTK draws all or nothing; cast nothing
    }
    const glm::dvec3 origin = -local.w / length2 * normal;
    // vtkPlane's setters mark it modified only when the values change.
    chain.Planes[i]->SetNormal(normal.x, normal.y, normal.z);
    chain.Planes[i]->SetOrigin(origin.x, origin.y, origin.z);
  }
  vtkClipPolyData* last = chain.Clips.back();
  last->Update();
  // Wholly clipped away: VTK draws nothing of it, and there is nothing to warn about.
  return last->GetOutput()->GetNumberOfCells() > 0 ? last->GetOutput() : nullptr;
}

void ClippedSurfaces::PurgeUnused()
{
  this->AppliedThisWalk.clear();
  for (auto it = this->Chains.begin(); it != this->Chains.end();)
  {
    if (!it->second.Used)
    {
      it = this->Chains.erase(it);
    }
    else
    {
      it->second.Used = false;
      ++it;
    }
  }
}

} // namespace penumbra
