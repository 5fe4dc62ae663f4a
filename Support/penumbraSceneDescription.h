// One description of a shadowed scene for the benchmark, the load test and the rendering tests:
// the actors and the triangles they draw, the shadowing lights and the poses they start from,
// the camera, and for data that changes every frame how to go to a frame.
#ifndef penumbraSceneDescription_h
#define penumbraSceneDescription_h

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkLight.h"
#include "vtkMapper.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowPass.h"

#include <algorithm>
#include <array>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace penumbra
{
namespace scene
{

using Point = std::array<double, 3>;

/// Triangles a polydata draws (polygons and strips fanned into triangles).
inline vtkIdType CountTriangles(vtkPolyData* data)
{
  vtkIdType triangles = 0;
  for (vtkCellArray* cells : { data->GetPolys(), data->GetStrips() })
  {
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      triangles += std::max<vtkIdType>(0, cells->GetCellSize(c) - 2);
    }
  }
  return triangles;
}

/// A scene light shining all round (cone 180) from `position` towards `focal`, or a directional
/// one from `position` towards it; `radius` in world units, or degrees for a directional light:
/// the one way the benchmarks, the load test and the tests make a shadowing light.
inline vtkSmartPointer<vtkLight> MakeLight(bool positional, const Point& position, double radius,
  const Point& focal = Point{ 0.0, 0.0, 0.0 })
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPositional(positional);
  light->SetConeAngle(180.0);
  light->SetPosition(position.data());
  light->SetFocalPoint(focal.data());
  vtkSoftShadowPass::SetLightRadius(light, radius);
  return light;
}

/// Where a light or the camera starts; a benchmark or test that moves it puts it back from here.
struct Pose
{
  Point Position{ 0.0, 0.0, 1.0 };
  Point FocalPoint{ 0.0, 0.0, 0.0 };
};

struct CameraPose : Pose
{
  Point ViewUp{ 0.0, 1.0, 0.0 };
  double ViewAngle = 30.0;
};

/**
 * A scene as every benchmark and rendering test builds it. Lights[i] becomes the renderer's
 * light i (the pass's light index i); AddTo puts the whole scene into a renderer. Actors keep
 * their graphics resources: a description is put into one window at a time.
 */
struct Description
{
  std::string Name;
  std::vector<vtkSmartPointer<vtkActor>> Actors;
  vtkIdType Triangles = 0; ///< drawn by Actors' polydata
  std::vector<vtkSmartPointer<vtkLight>> Lights;
  std::vector<Pose> LightPoses; ///< Lights' start poses
  CameraPose Camera;
  /// For data that changes as a simulation played back: puts the data of frame `frame` in
  /// place (frame 0 is the data as built). Empty for a static scene.
  std::function<void(int frame)> Advance;

  /// Adds an actor, its triangles counted once its input is up to date.
  void Add(vtkSmartPointer<vtkActor> actor)
  {
    vtkMapper* mapper = actor->GetMapper();
    if (vtkAlgorithm* producer = mapper->GetInputAlgorithm())
    {
      producer->Update();
    }
    if (auto* data = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)))
    {
      this->Triangles += CountTriangles(data);
    }
    this->Actors.push_back(actor);
  }

  /// Adds MakeLight's light; returns it for further settings (colour, intensity, cone).
  vtkLight* AddLight(bool positional, const Point& position, double radius,
    const Point& focal = Point{ 0.0, 0.0, 0.0 })
  {
    auto light = MakeLight(positional, position, radius, focal);
    this->Lights.push_back(light);
    this->LightPoses.push_back(Pose{ position, focal });
    return light;
  }

  void SetCamera(const Point& position, const Point& focal, const Point& viewUp, double angle)
  {
    this->Camera.Position = position;
    this->Camera.FocalPoint = focal;
    this->Camera.ViewUp = viewUp;
    this->Camera.ViewAngle = angle;
  }

  /// Puts every light back at its start pose.
  void ResetLights() const
  {
    for (std::size_t i = 0; i < this->Lights.size(); ++i)
    {
      this->Lights[i]->SetPosition(this->LightPoses[i].Position.data());
      this->Lights[i]->SetFocalPoint(this->LightPoses[i].FocalPoint.data());
    }
  }

  /// Puts the renderer's camera at the start pose and fits its clipping range to the scene.
  void ResetCamera(vtkRenderer* renderer) const
  {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(this->Camera.Position.data());
    camera->SetFocalPoint(this->Camera.FocalPoint.data());
    camera->SetViewUp(this->Camera.ViewUp.data());
    camera->SetViewAngle(this->Camera.ViewAngle);
    camera->OrthogonalizeViewUp();
    // Setting a value a camera already has does not mark it modified; the mappers would keep
    // the lighting uniforms of the last view (vtkCamera::DeepCopy has the same habit).
    camera->Modified();
    renderer->ResetCameraClippingRange();
  }

  /// Replaces the renderer's props and lights with the scene's, at their start poses.
  void AddTo(vtkRenderer* renderer) const
  {
    renderer->RemoveAllViewProps();
    renderer->RemoveAllLights();
    for (const auto& actor : this->Actors)
    {
      renderer->AddActor(actor);
    }
    this->ResetLights();
    for (const auto& light : this->Lights)
    {
      renderer->AddLight(light);
    }
    this->ResetCamera(renderer);
  }

  /// Distinct datasets the actors draw (many actors may share one polydata).
  std::size_t CountDatasets() const
  {
    std::set<vtkDataObject*> datasets;
    for (const auto& actor : this->Actors)
    {
      datasets.insert(actor->GetMapper()->GetInputDataObject(0, 0));
    }
    return datasets.size();
  }
};

} // namespace scene
} // namespace penumbra

#endif
