#include "vtkSoftShadowPassInternals.h"

#include "vtkActor.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkPolyData.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <vector>

namespace penumbra
{
namespace
{

/// Caster surfaces come from polydata directly, or from the outer surface of any other dataset.
vtkSmartPointer<vtkPolyData> SurfaceOf(vtkDataObject* data)
{
  if (auto polyData = vtkPolyData::SafeDownCast(data))
  {
    return polyData;
  }
  if (auto dataSet = vtkDataSet::SafeDownCast(data))
  {
    vtkNew<vtkDataSetSurfaceFilter> surface;
    surface->SetInputData(dataSet);
    surface->Update();
    return surface->GetOutput();
  }
  return nullptr;
}

} // namespace

bool MeshCache::Update(vtkDataObject* data, vtkObject* owner)
{
  this->Used = true;
  if (this->Data == data && this->BuiltAt >= data->GetMTime() && this->Generation > 0)
  {
    return false;
  }
  this->Data = data;
  this->BuiltAt = data->GetMTime();
  ++this->Generation;
  this->Uploaded = false;

  vtkSmartPointer<vtkPolyData> surface = SurfaceOf(data);
  this->Topology = CasterTopology::Build(surface);
  const std::string problems = this->Topology.Report.Describe();
  if (!problems.empty())
  {
    vtkWarningWithObjectMacro(owner, "Shadow caster " << data->GetClassName() << " (" << data
                                                      << "): " << problems << ".");
  }
  if (this->Topology.Empty())
  {
    vtkWarningWithObjectMacro(owner, "Shadow caster " << data->GetClassName() << " (" << data
                                                      << ") has no surface triangles: it casts "
                                                         "no shadow.");
  }
  return true;
}

void MeshCache::Bind(vtkShaderProgram* program)
{
  if (!this->Uploaded)
  {
    const std::vector<glm::dvec3>& points = this->Topology.Points;
    std::vector<float> buffer(points.size() * 8);
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        buffer[4 * i + k] = static_cast<float>(points[i][k]);
        buffer[4 * (points.size() + i) + k] = static_cast<float>(points[i][k]);
      }
      buffer[4 * i + 3] = 1.0f;
      buffer[4 * (points.size() + i) + 3] = 0.0f;
    }
    this->Vertices->Upload(buffer, vtkOpenGLBufferObject::ArrayBuffer);
    this->Uploaded = true;
    this->VAOProgram = nullptr;
  }
  if (this->VAOProgram != program)
  {
    // Releases the old VAO: must come before Bind.
    this->VAO->ShaderProgramChanged();
    this->VAO->Bind();
    this->VAO->AddAttributeArray(
      program, this->Vertices, "vertexMC", 0, 4 * sizeof(float), VTK_FLOAT, 4, false);
    this->VAOProgram = program;
  }
  this->VAO->Bind();
}

void MeshCache::ReleaseGraphicsResources()
{
  this->Vertices->ReleaseGraphicsResources();
  this->VAO->ReleaseGraphicsResources();
  this->Uploaded = false;
  this->VAOProgram = nullptr;
}

bool VolumeCache::Update(const MeshCache& mesh, const glm::dvec4& lightObject, bool mirrored)
{
  this->Used = true;
  if (this->MeshGeneration == mesh.Generation && this->Light == lightObject &&
    this->Mirrored == mirrored)
  {
    return false;
  }
  this->Light = lightObject;
  this->Mirrored = mirrored;
  this->MeshGeneration = mesh.Generation;
  this->Volume = ShadowVolume::Build(mesh.Topology, lightObject, mirrored, false);
  this->HasCaps = false;
  this->Uploaded = false;
  return true;
}

void VolumeCache::EnsureCaps(const MeshCache& mesh)
{
  if (!this->HasCaps)
  {
    this->Volume = ShadowVolume::Build(mesh.Topology, this->Light, this->Mirrored, true);
    this->HasCaps = true;
    this->Uploaded = false;
  }
}

void VolumeCache::Upload()
{
  if (this->Uploaded)
  {
    return;
  }
  // One buffer: [sides | dark cap | light cap], drawn as ranges (z-pass: sides only; z-fail:
  // sides and dark cap, then the light cap with its depth bias).
  std::vector<std::uint32_t> indices;
  indices.reserve(this->SideCount() + this->CapCount() + this->DarkCapCount());
  indices.insert(indices.end(), this->Volume.Sides.begin(), this->Volume.Sides.end());
  indices.insert(indices.end(), this->Volume.DarkCap.begin(), this->Volume.DarkCap.end());
  indices.insert(indices.end(), this->Volume.LightCap.begin(), this->Volume.LightCap.end());
  if (!indices.empty())
  {
    this->Indices->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  this->Uploaded = true;
}

MeshCache* ShadowCaches::FindMesh(vtkDataObject* data, vtkObject* owner, bool& rebuilt)
{
  std::unique_ptr<MeshCache>& mesh = this->Meshes[data];
  if (!mesh || mesh->Data != data)
  {
    mesh.reset(new MeshCache);
  }
  rebuilt = mesh->Update(data, owner);
  return mesh.get();
}

CasterCache* ShadowCaches::FindCaster(vtkActor* actor)
{
  std::unique_ptr<CasterCache>& caster = this->Casters[actor];
  if (!caster || caster->Actor != actor)
  {
    caster.reset(new CasterCache);
    caster->Actor = actor;
  }
  caster->Used = true;
  return caster.get();
}

void ShadowCaches::BeginFrame()
{
  for (auto& mesh : this->Meshes)
  {
    mesh.second->Used = false;
  }
  for (auto& caster : this->Casters)
  {
    caster.second->Used = false;
    for (auto& volume : caster.second->Volumes)
    {
      volume.second.Used = false;
    }
  }
}

void ShadowCaches::PurgeUnused()
{
  for (auto it = this->Casters.begin(); it != this->Casters.end();)
  {
    if (!it->second->Used)
    {
      it = this->Casters.erase(it);
      continue;
    }
    auto& volumes = it->second->Volumes;
    for (auto v = volumes.begin(); v != volumes.end();)
    {
      v = v->second.Used ? std::next(v) : volumes.erase(v);
    }
    ++it;
  }
  for (auto it = this->Meshes.begin(); it != this->Meshes.end();)
  {
    it = it->second->Used ? std::next(it) : this->Meshes.erase(it);
  }
}

void ShadowCaches::ReleaseGraphicsResources()
{
  for (auto& mesh : this->Meshes)
  {
    mesh.second->ReleaseGraphicsResources();
  }
  for (auto& caster : this->Casters)
  {
    for (auto& volume : caster.second->Volumes)
    {
      volume.second.Indices->ReleaseGraphicsResources();
      volume.second.Uploaded = false;
    }
  }
}

} // namespace penumbra
