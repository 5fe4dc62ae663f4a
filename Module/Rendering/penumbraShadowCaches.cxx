#include "penumbraShadowCaches.h"

#include "vtkActor.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"

#include "penumbraSampleCounting.h"
#include "penumbraShadowVolume.h"
#include "penumbraWedge.h"
#include "penumbraWedgeBound.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <sstream>
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

/// A stamp no earlier build of any mesh or volume had. The caches kept per actor compare it, so
/// the mesh of an actor's new data (built once, as the mesh it replaces was) never passes for the
/// old one.
std::size_t NewGeneration()
{
  static std::atomic<std::size_t> last{ 0 };
  return ++last;
}

} // namespace

bool MeshCache::Update(
  vtkDataObject* data, vtkProp* prop, vtkProp* viewProp, vtkObject* owner, DataWarnings& warned)
{
  this->Used = true;
  if (this->Data == data && this->BuiltAt >= data->GetMTime() && this->Builds > 0)
  {
    return false;
  }
  this->Data = data;
  this->BuiltAt = data->GetMTime();
  ++this->Builds;
  this->Generation = NewGeneration();
  this->Uploaded = false;
  this->TrianglesUploaded = false;

  vtkSmartPointer<vtkPolyData> surface = SurfaceOf(data);
  if (this->Builds > 1 && !this->Builder)
  {
    // Data that changed once will likely change again (a simulation played back): keep the
    // builder's scratch so that later rebuilds allocate nothing. Static data holds none.
    this->Builder.reset(new TopologyBuilder);
  }
  if (this->Builder)
  {
    this->Builder->Build(surface, this->Topology);
  }
  else
  {
    this->Topology = CasterTopology::Build(surface);
  }
  // One warning per data object and kind: data that changes every frame (a simulation played
  // back) warns once, not every frame, and data with nothing to cast says what it had instead
  // (points and lines only, or every triangle dropped) in the same sentence.
  const std::string problems = this->Topology.Report.Describe(this->Topology.Empty());
  std::ostringstream caster;
  caster << "Shadow caster " << (prop ? prop->GetClassName() : "prop") << " (" << prop << "), ";
  if (viewProp && viewProp != prop)
  {
    caster << "part of " << viewProp->GetClassName() << " (" << viewProp << "), ";
  }
  caster << "its " << data->GetClassName() << " (" << data << ")";
  if (this->Topology.Empty() && warned.First(data, "empty"))
  {
    vtkWarningWithObjectMacro(owner, << caster.str()
                                     << " has no surface triangles, so it casts no shadow"
                                     << (problems.empty() ? "" : ": " + problems) << ".");
    warned.First(data, "problems"); // said with it
  }
  else if (!problems.empty() && warned.First(data, "problems"))
  {
    vtkWarningWithObjectMacro(
      owner, << caster.str() << ": " << problems
             << (this->Builds > 1 ? " (not repeated for later versions)." : "."));
  }
  return true;
}

void MeshCache::Bind(vtkShaderProgram* program)
{
  if (!this->Uploaded)
  {
    const std::vector<glm::dvec3>& points = this->Topology.Points;
    const std::size_t count = points.size();
    WriteBuffer(this->Vertices, vtkOpenGLBufferObject::ArrayBuffer, 8 * count * sizeof(float),
      [&points, count](void* destination)
      {
        auto* vertices = static_cast<glm::vec4*>(destination);
        for (std::size_t i = 0; i < count; ++i)
        {
          const glm::vec3 point(points[i]);
          vertices[i] = glm::vec4(point, 1.0f);
          vertices[count + i] = glm::vec4(point, 0.0f);
        }
      });
    this->Uploaded = true;
    this->VAOProgram = nullptr;
  }
  BindVertexArray(this->VAO, program, this->VAOProgram, this->Vertices, { { "vertexMC", 0, 4 } });
}

void MeshCache::BindTriangles()
{
  if (!this->TrianglesUploaded)
  {
    const std::vector<glm::uvec3>& triangles = this->Topology.Triangles;
    static_assert(sizeof(glm::uvec3) == 3 * sizeof(std::uint32_t), "packed triangles");
    this->TriangleIndices->Upload(reinterpret_cast<const std::uint32_t*>(triangles.data()),
      3 * triangles.size(), vtkOpenGLBufferObject::ElementArrayBuffer);
    this->TrianglesUploaded = true;
  }
  this->TriangleIndices->Bind();
}

int MeshCache::OutwardWinding()
{
  if (this->WindingGeneration != this->Generation)
  {
    this->Winding = this->Topology.OutwardWinding();
    this->WindingGeneration = this->Generation;
  }
  return this->Winding;
}

void MeshCache::ReleaseGraphicsResources()
{
  this->Vertices->ReleaseGraphicsResources();
  this->VAO->ReleaseGraphicsResources();
  this->TriangleIndices->ReleaseGraphicsResources();
  this->TrianglesUploaded = false;
  this->Uploaded = false;
  this->VAOProgram = nullptr;
}

bool VolumeCache::Update(
  const MeshCache& mesh, const glm::dvec4& lightObject, bool mirrored, CountingRule rule)
{
  this->Used = true;
  if (this->MeshGeneration == mesh.Generation && this->Light == lightObject &&
    this->Mirrored == mirrored && this->Rule == rule)
  {
    return false;
  }
  this->Light = lightObject;
  this->Mirrored = mirrored;
  this->Rule = rule;
  this->MeshGeneration = mesh.Generation;
  this->Volume = ShadowVolume::Build(mesh.Topology, lightObject, mirrored, false, rule);
  this->Generation = NewGeneration();
  this->HasCaps = false;
  this->Uploaded = false;
  return true;
}

void VolumeCache::EnsureCaps(const MeshCache& mesh)
{
  if (!this->HasCaps)
  {
    this->Volume =
      ShadowVolume::Build(mesh.Topology, this->Light, this->Mirrored, true, this->Rule);
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
  const std::vector<std::uint32_t>* parts[] = { &this->Volume.Sides, &this->Volume.DarkCap,
    &this->Volume.LightCap };
  std::size_t count = 0;
  for (const std::vector<std::uint32_t>* part : parts)
  {
    count += part->size();
  }
  if (count > 0)
  {
    WriteBuffer(this->Indices, vtkOpenGLBufferObject::ElementArrayBuffer,
      count * sizeof(std::uint32_t),
      [&parts](void* destination)
      {
        auto* index = static_cast<std::uint32_t*>(destination);
        for (const std::vector<std::uint32_t>* part : parts)
        {
          index = std::copy(part->begin(), part->end(), index);
        }
      });
  }
  this->Uploaded = true;
}

namespace
{
/// Calls append(geometry, k) for every k in [0, count): cutting wedges is the costly part of
/// building them, so runs of k are cut on all threads, each into a geometry of its own, and
/// joined into `into` in order, so that the result does not depend on the thread count.
template <typename AppendOne>
void AppendInRuns(WedgeGeometry& into, std::size_t count, int floatsPerVertex, AppendOne&& append)
{
  const std::size_t runs = std::min<std::size_t>(count, 64);
  std::vector<WedgeGeometry> parts(runs);
  vtkSMPTools::For(0, static_cast<vtkIdType>(runs),
    [&](vtkIdType beginRun, vtkIdType endRun)
    {
      for (vtkIdType run = beginRun; run < endRun; ++run)
      {
        const std::size_t first = count * run / runs, last = count * (run + 1) / runs;
        for (std::size_t k = first; k < last; ++k)
        {
          append(parts[run], k);
        }
      }
    });
  for (const WedgeGeometry& part : parts)
  {
    into.Append(part, floatsPerVertex);
  }
}
} // namespace

glm::dvec4 WedgeBuffer::LightInWedgeSpace() const
{
  return this->LightWorld.w != 0.0 ? glm::dvec4(glm::dvec3(this->LightWorld) - this->Origin, 1.0)
                                   : this->LightWorld;
}

bool WedgeBuffer::BuiltFor(
  const glm::dmat4& objectToWorld, const glm::dvec4& lightWorld, double radius) const
{
  return this->ObjectToWorld == objectToWorld && this->LightWorld == lightWorld &&
    this->Radius == radius;
}

void WedgeBuffer::Reset(const glm::dmat4& objectToWorld, const glm::dvec4& lightWorld,
  double radius, const ReceiverBounds& receivers)
{
  this->ObjectToWorld = objectToWorld;
  this->LightWorld = lightWorld;
  this->Radius = radius;
  this->Receivers = receivers;
  this->Origin = glm::dvec3(objectToWorld * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  this->PiecesInWedgeSpace = receivers.Pieces;
  for (Box& piece : this->PiecesInWedgeSpace)
  {
    piece.Min -= this->Origin;
    piece.Max -= this->Origin;
  }
  this->Vertices.clear();
  this->Indices.clear();
  this->Wedges = this->Fallbacks = this->FullViewport = 0;
  this->Uploaded = false;
}

void WedgeGeometry::Append(const WedgeGeometry& part, int floatsPerVertex)
{
  const auto offset = static_cast<std::uint32_t>(this->Vertices.size() / floatsPerVertex);
  this->Vertices.insert(this->Vertices.end(), part.Vertices.begin(), part.Vertices.end());
  this->Indices.reserve(this->Indices.size() + part.Indices.size());
  for (std::uint32_t index : part.Indices)
  {
    this->Indices.push_back(offset + index);
  }
  this->Wedges += part.Wedges;
  this->Fallbacks += part.Fallbacks;
  this->FullViewport += part.FullViewport;
}

void WedgeBuffer::AppendEdgeTo(WedgeGeometry& geometry, const glm::dvec3& from,
  const glm::dvec3& to, const float* attributes, int attributeCount, const EdgeFace* faces,
  bool frontFacesOnly, bool pieceBounds) const
{
  Box receivers = this->Receivers.Whole;
  receivers.Min -= this->Origin;
  receivers.Max -= this->Origin;
  WedgeShape shape;
  if (pieceBounds && receivers.Valid && !this->PiecesInWedgeSpace.empty())
  {
    shape = AppendWedgeBoundInPieces(from, to, this->LightInWedgeSpace(), this->Radius, receivers,
      this->PiecesInWedgeSpace, faces, frontFacesOnly, attributes, attributeCount,
      geometry.Vertices, geometry.Indices);
  }
  else if (pieceBounds)
  {
    // No pieces: corners that hold every point, so that the fragment shader keeps them all.
    constexpr float huge = std::numeric_limits<float>::max();
    std::vector<float> withCorners(attributes, attributes + attributeCount);
    withCorners.insert(withCorners.end(), { -huge, -huge, -huge, huge, huge, huge });
    shape = AppendWedgeBound(from, to, this->LightInWedgeSpace(), this->Radius, receivers, faces,
      frontFacesOnly, withCorners.data(), attributeCount + 6, geometry.Vertices, geometry.Indices);
  }
  else
  {
    shape = AppendWedgeBound(from, to, this->LightInWedgeSpace(), this->Radius, receivers, faces,
      frontFacesOnly, attributes, attributeCount, geometry.Vertices, geometry.Indices);
  }
  if (shape == WedgeShape::Nothing)
  {
    return; // the bound misses the receivers' box: nothing to draw
  }
  // Pyramids, edges with no bound of their own and wedges whose cut had to leave a plane out
  // (Enlarged) are fallbacks: their caster's wedges are drawn by back faces.
  ++(shape == WedgeShape::Planes ? geometry.Wedges : geometry.Fallbacks);
  geometry.FullViewport += shape == WedgeShape::FullViewport;
}

void WedgeBuffer::Bind(vtkShaderProgram* program, const std::vector<VertexAttribute>& attributes)
{
  if (!this->Uploaded)
  {
    this->Buffer->Upload(this->Vertices, vtkOpenGLBufferObject::ArrayBuffer);
    this->IndexBuffer->Upload(this->Indices, vtkOpenGLBufferObject::ElementArrayBuffer);
    this->Uploaded = true;
    this->VAOProgram = nullptr;
  }
  BindVertexArray(this->VAO, program, this->VAOProgram, this->Buffer, attributes);
  this->IndexBuffer->Bind();
}

void VolumeCache::ReleaseGraphicsResources()
{
  this->Indices->ReleaseGraphicsResources();
  this->Uploaded = false;
}

void WedgeBuffer::ReleaseGraphicsResources()
{
  this->Buffer->ReleaseGraphicsResources();
  this->IndexBuffer->ReleaseGraphicsResources();
  this->VAO->ReleaseGraphicsResources();
  this->VAOProgram = nullptr;
  this->Uploaded = false;
}

const std::vector<VertexAttribute>& WedgeCache::Attributes()
{
  static const std::vector<VertexAttribute> attributes = { { "vertexMC", 0, 4 },
    { "edgeFrom", 4, 3 }, { "edgeTo", 7, 3 }, { "edgeWeight", 10, 1 } };
  return attributes;
}

bool WedgeCache::Update(const MeshCache& mesh, const VolumeCache& centre,
  const glm::dmat4& objectToWorld, const glm::dvec4& lightWorld, double radius,
  const Box& receivers)
{
  this->Used = true;
  const ReceiverBounds whole{ receivers, {} }; // its shader takes no pieces
  if (this->VolumeGeneration == centre.Generation &&
    this->BuiltFor(objectToWorld, lightWorld, radius) && this->Receivers == whole)
  {
    return false;
  }
  this->VolumeGeneration = centre.Generation;
  this->Reset(objectToWorld, lightWorld, radius, whole);
  const std::vector<SilhouetteEdge>& silhouette = centre.Volume.Silhouette;
  AppendInRuns(*this, silhouette.size(), FloatsPerVertex,
    [&](WedgeGeometry& geometry, std::size_t k)
    {
      const SilhouetteEdge& edge = silhouette[k];
      const glm::dvec3 from =
        glm::dvec3(objectToWorld * glm::dvec4(mesh.Topology.Points[edge.From], 1.0)) - this->Origin;
      const glm::dvec3 to =
        glm::dvec3(objectToWorld * glm::dvec4(mesh.Topology.Points[edge.To], 1.0)) - this->Origin;
      const glm::vec3 fromF = glm::vec3(from), toF = glm::vec3(to);
      const float attributes[FloatsPerVertex - 4] = { fromF.x, fromF.y, fromF.z, toF.x, toF.y,
        toF.z, static_cast<float>(edge.Multiplicity) };
      this->AppendEdgeTo(geometry, from, to, attributes, FloatsPerVertex - 4);
    });
  return true;
}

const std::vector<VertexAttribute>& CountingWedgeCache::Attributes()
{
  static const std::vector<VertexAttribute> attributes = { { "vertexMC", 0, 4 },
    { "edgeFrom", 4, 3 }, { "edgeTo", 7, 3 }, { "faceNormal0", 10, 3 }, { "faceNormal1", 13, 3 },
    { "faceSigns", 16, 2 }, { "centreNormal", 18, 3 }, { "pieceMin", 21, 3 },
    { "pieceMax", 24, 3 } };
  return attributes;
}

bool CountingWedgeCache::Update(const MeshCache& mesh, const glm::dmat4& objectToWorld,
  const glm::dvec4& lightWorld, double radius, bool frontFacesOnly, const ReceiverBounds& receivers)
{
  this->Used = true;
  const bool sameSilhouette = this->MeshGeneration == mesh.Generation &&
    this->BuiltFor(objectToWorld, lightWorld, radius) && this->FrontFacesOnly == frontFacesOnly;
  if (sameSilhouette && this->Receivers == receivers)
  {
    return false;
  }
  this->Reset(objectToWorld, lightWorld, radius, receivers);
  this->VerticesBuilt = false;
  if (sameSilhouette)
  {
    return false; // the receivers' box changes the wedges, not which edges are potential
  }
  this->MeshGeneration = mesh.Generation;
  this->FrontFacesOnly = frontFacesOnly;
  this->Potential =
    PotentialSilhouette(mesh.Topology, objectToWorld, lightWorld, radius, frontFacesOnly);
  return true;
}

void CountingWedgeCache::AppendPotentialEdge(WedgeGeometry& geometry, const CasterTopology& topo,
  const std::vector<glm::dvec3>& world, const glm::dvec4& light, double flip, std::uint32_t e) const
{
  const Edge& edge = topo.Edges[e];
  const glm::dvec3 &from = world[edge.A], &to = world[edge.B];
  const glm::vec3 fromF = glm::vec3(from), toF = glm::vec3(to);
  const glm::vec3 centreNormal = glm::vec3(EdgeLightNormal(from, to, light));
  for (std::uint32_t first = 0; first < edge.UseCount; first += 2)
  {
    // The piece's corners follow, added per piece by AppendEdgeTo.
    float attributes[FloatsPerVertex - 10] = { fromF.x, fromF.y, fromF.z, toF.x, toF.y, toF.z, 0, 0,
      0, 0, 0, 0, 0, 0, centreNormal.x, centreNormal.y, centreNormal.z };
    EdgeFace faces[2];
    std::uint32_t faceCount = 0;
    for (; faceCount < 2 && first + faceCount < edge.UseCount; ++faceCount)
    {
      const EdgeUse& use = topo.Uses[edge.FirstUse + first + faceCount];
      const glm::uvec3& tri = topo.Triangles[use.Triangle];
      faces[faceCount] = { flip *
          glm::cross(world[tri.y] - world[tri.x], world[tri.z] - world[tri.x]),
        static_cast<int>(flip) * use.Sign };
      for (int c = 0; c < 3; ++c)
      {
        attributes[6 + 3 * faceCount + c] = static_cast<float>(faces[faceCount].Normal[c]);
      }
      attributes[12 + faceCount] = static_cast<float>(faces[faceCount].Sign);
    }
    this->AppendEdgeTo(geometry, from, to, attributes, FloatsPerVertex - 10,
      faceCount == 2 ? faces : nullptr, this->FrontFacesOnly, true);
  }
}

void CountingWedgeCache::BuildVertices(const MeshCache& mesh)
{
  if (this->VerticesBuilt)
  {
    return;
  }
  const glm::dvec4 light = this->LightInWedgeSpace();
  const CasterTopology& topo = mesh.Topology;
  std::vector<glm::dvec3> world(topo.Points.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(world.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        world[i] = glm::dvec3(this->ObjectToWorld * glm::dvec4(topo.Points[i], 1.0)) - this->Origin;
      }
    });
  // With a mirroring matrix the stored winding faces inward: flip normal and walk together, which
  // leaves the general rule's products unchanged and keeps "front" outward for the closed rule.
  const double flip = glm::determinant(glm::dmat3(this->ObjectToWorld)) < 0.0 ? -1.0 : 1.0;
  // One wedge per edge and pair of its faces.
  AppendInRuns(*this, this->Potential.size(), FloatsPerVertex,
    [&](WedgeGeometry& geometry, std::size_t k)
    { this->AppendPotentialEdge(geometry, topo, world, light, flip, this->Potential[k]); });
  this->VerticesBuilt = true;
  this->Uploaded = false;
}

MeshCache* ShadowCaches::FindMesh(
  vtkDataObject* data, vtkProp* prop, vtkProp* viewProp, vtkObject* owner)
{
  std::unique_ptr<MeshCache>& mesh = this->Meshes[data];
  if (!mesh || mesh->Data != data)
  {
    mesh.reset(new MeshCache);
  }
  mesh->Update(data, prop, viewProp, owner, this->Warned);
  return mesh.get();
}

CasterCache* ShadowCaches::FindCaster(vtkActor* actor, std::size_t part)
{
  const std::size_t occurrence = this->FoundThisFrame[{ actor, part }]++;
  std::unique_ptr<CasterCache>& caster = this->Casters[{ actor, part, occurrence }];
  if (!caster || caster->Actor != actor)
  {
    caster.reset(new CasterCache);
    caster->Actor = actor;
  }
  caster->Used = true;
  return caster.get();
}

namespace
{
/// Calls `visit` with each of a caster's per-light caches: its volumes, wedges and counting
/// wedges (a CasterCache, const or not).
template <typename Caster, typename Visit>
void ForEachLightCache(Caster& caster, Visit&& visit)
{
  for (auto& entry : caster.Volumes)
  {
    visit(entry.second);
  }
  for (auto& entry : caster.Wedges)
  {
    visit(entry.second);
  }
  for (auto& entry : caster.CountingWedges)
  {
    visit(entry.second);
  }
}

/// Erases the entries of `caches` not used this frame.
template <typename Map>
void EraseUnused(Map& caches)
{
  for (auto it = caches.begin(); it != caches.end();)
  {
    it = it->second.Used ? std::next(it) : caches.erase(it);
  }
}
} // namespace

void ShadowCaches::BeginFrame()
{
  this->FoundThisFrame.clear();
  for (auto& mesh : this->Meshes)
  {
    mesh.second->Used = false;
  }
  for (auto& caster : this->Casters)
  {
    caster.second->Used = false;
    ForEachLightCache(*caster.second, [](auto& cache) { cache.Used = false; });
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
    EraseUnused(it->second->Volumes);
    EraseUnused(it->second->Wedges);
    EraseUnused(it->second->CountingWedges);
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
    ForEachLightCache(*caster.second, [](auto& cache) { cache.ReleaseGraphicsResources(); });
  }
}

std::size_t ShadowCaches::GraphicsBufferBytes() const
{
  std::size_t bytes = 0;
  for (const auto& mesh : this->Meshes)
  {
    // Two float4 copies of every point (see MeshCache::Bind).
    bytes += mesh.second->Uploaded ? mesh.second->Topology.Points.size() * 8 * sizeof(float) : 0;
    // Three indices a triangle, for the depth drawn from the mesh.
    bytes += mesh.second->TrianglesUploaded
      ? mesh.second->Topology.Triangles.size() * 3 * sizeof(std::uint32_t)
      : 0;
  }
  for (const auto& caster : this->Casters)
  {
    const CasterCache& constCaster = *caster.second;
    ForEachLightCache(constCaster, [&bytes](const auto& cache) { bytes += cache.UploadedBytes(); });
  }
  return bytes;
}

} // namespace penumbra
