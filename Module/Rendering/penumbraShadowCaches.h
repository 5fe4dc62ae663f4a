/**
 * @file    penumbraShadowCaches.h
 * @brief   What vtkSoftShadowPass keeps between frames: caster meshes, and per caster and light
 *          its shadow volumes and wedges, on the CPU and in GPU buffers.
 *
 * Everything here is rebuilt only when its inputs change: a mesh when its data's MTime moves, a
 * volume when the light seen from the caster's object space (or the mesh) changes. A camera
 * orbit therefore costs no CPU geometry work and no upload.
 */
#ifndef penumbraShadowCaches_h
#define penumbraShadowCaches_h

#include "penumbraCasterTopology.h"
#include "penumbraConvexClip.h"
#include "penumbraSampleCounting.h"
#include "penumbraShadowVolume.h"

#include "penumbraOpenGLHelpers.h"
#include "penumbraPropWarnings.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <set>
#include <tuple>

class vtkActor;
class vtkDataObject;
class vtkLight;
class vtkObject;
class vtkPolyData;
class vtkProp;
class vtkShaderProgram;

namespace penumbra
{

/// Topology and vertex buffer of one data object, shared by every actor that shows it.
struct MeshCache
{
  vtkWeakPointer<vtkDataObject> Data;
  vtkMTimeType BuiltAt = 0;
  std::size_t Builds = 0;     ///< how often the topology was built
  std::size_t Generation = 0; ///< unique to each build of any mesh, so volumes know they are stale
  CasterTopology Topology;
  /// Created on the second build: only data that changes keeps scratch between builds.
  std::unique_ptr<TopologyBuilder> Builder;
  vtkNew<vtkOpenGLBufferObject> Vertices;
  vtkNew<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* VAOProgram = nullptr;
  bool Uploaded = false;
  /// Every triangle, for its depth (penumbra::CasterDepth); uploaded on first use.
  vtkNew<vtkOpenGLBufferObject> TriangleIndices;
  bool TrianglesUploaded = false;
  int Winding = 0;
  std::size_t WindingGeneration = 0; ///< the Generation Winding was worked out for; 0: none
  bool Used = false;

  /// Rebuilds the topology when `data` changed. Returns true when it did; warns via `owner`,
  /// once per data object and kind (problems, no triangles: `warned` keeps which, beyond this
  /// mesh's life), naming `prop`, the first prop found drawing it, and `viewProp`, the
  /// renderer's prop it is part of where that is another (an assembly, a vtkAxesActor).
  bool Update(
    vtkDataObject* data, vtkProp* prop, vtkProp* viewProp, vtkObject* owner, DataWarnings& warned);
  /// Uploads the doubled vertex buffer (w = 1 points, then w = 0 swept copies) if needed and
  /// binds the VAO for `program`.
  void Bind(vtkShaderProgram* program);
  /// Uploads the index buffer of every triangle if needed and binds it; after Bind.
  void BindTriangles();
  /// Topology.OutwardWinding(), worked out once per build, on first use.
  int OutwardWinding();
  void ReleaseGraphicsResources();
};

/// One caster's shadow volume for one light, on the CPU and in an index buffer.
struct VolumeCache
{
  glm::dvec4 Light{ 0.0 };
  bool Mirrored = false;
  CountingRule Rule = CountingRule::FrontFacesWhereTheySuffice;
  std::size_t MeshGeneration = ~std::size_t(0);
  std::size_t Generation = 0; ///< unique to each silhouette build, so wedges know they are stale
  ShadowVolume Volume;
  bool HasCaps = false;
  vtkNew<vtkOpenGLBufferObject> Indices;
  bool Uploaded = false;
  bool Used = false;

  /// Rebuilds the silhouette when the light (object space), the mesh or the counting rule
  /// changed. Returns true when it did. Caps are left out until a z-fail draw asks for them.
  bool Update(
    const MeshCache& mesh, const glm::dvec4& lightObject, bool mirrored, CountingRule rule);
  /// Adds the light and dark caps (z-fail needs them), once per silhouette update.
  void EnsureCaps(const MeshCache& mesh);
  void Upload();
  void ReleaseGraphicsResources();
  /// Bytes of the uploaded index buffer.
  std::size_t UploadedBytes() const
  {
    return this->Uploaded
      ? (this->SideCount() + this->CapCount() + this->DarkCapCount()) * sizeof(std::uint32_t)
      : 0;
  }
  std::size_t SideCount() const { return this->Volume.Sides.size(); }
  std::size_t CapCount() const { return this->Volume.LightCap.size(); }
  std::size_t DarkCapCount() const { return this->Volume.DarkCap.size(); }
};

/// Wedge vertices and triangles with what they hold, built for a run of edges.
struct WedgeGeometry
{
  std::size_t Wedges = 0;       ///< edges with a proper wedge
  std::size_t Fallbacks = 0;    ///< edges drawn by back faces: a light pyramid, the viewport,
                                ///< or a cut that left a plane out (WedgeShape::Enlarged)
  std::size_t FullViewport = 0; ///< of those, drawn over the whole viewport
  std::vector<float> Vertices;
  std::vector<std::uint32_t> Indices;

  /// Appends `part`, built on its own, its indices moved past this geometry's
  /// `floatsPerVertex`-float vertices.
  void Append(const WedgeGeometry& part, int floatsPerVertex);
};

/// Wedges of one caster for one light, as drawn, indexed, every vertex carrying the edge's data
/// for the fragment shader. Each edge's wedge (or light pyramid) is cut to the receivers' box,
/// where there is one, and drawn as the closed convex polyhedron left; without a box it is drawn
/// whole, to infinity: 8 outward triangles over 6 vertices (a light pyramid's 6 over 5, or a
/// full-viewport triangle).
/// Vertices are in wedge coordinates: world space relative to Origin, the caster mesh's origin
/// (penumbra::CasterTopology::Origin, where most of the mesh is), so that float precision follows
/// the caster, not the world origin or a far light (whose centre, 700,000 away, would leave edges
/// and points float steps of 0.06).
struct WedgeBuffer : WedgeGeometry
{
  glm::dvec3 Origin{ 0.0 };
  glm::dmat4 ObjectToWorld{ 0.0 };
  glm::dvec4 LightWorld{ 0.0 };
  double Radius = -1.0;
  ReceiverBounds Receivers;            ///< world space; no receiver lies outside them
  std::vector<Box> PiecesInWedgeSpace; ///< Receivers.Pieces relative to Origin
  vtkNew<vtkOpenGLBufferObject> Buffer;
  vtkNew<vtkOpenGLBufferObject> IndexBuffer;
  vtkNew<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* VAOProgram = nullptr;
  bool Uploaded = false;
  bool Used = false;

  /// The light in wedge coordinates, as the wedge shaders want it.
  glm::dvec4 LightInWedgeSpace() const;
  /// Uploads the vertices and indices if needed and binds the VAO and index buffer for
  /// `program`; DrawWedgeBuffer releases both.
  void Bind(vtkShaderProgram* program, const std::vector<VertexAttribute>& attributes);
  void ReleaseGraphicsResources();
  /// Whether the buffer was built for this caster matrix and light (its Receivers say for which
  /// box).
  bool BuiltFor(const glm::dmat4& objectToWorld, const glm::dvec4& lightWorld, double radius) const;
  /// Sets Origin from the matrix, and empties the buffer for a rebuild.
  void Reset(const glm::dmat4& objectToWorld, const glm::dvec4& lightWorld, double radius,
    const ReceiverBounds& receivers);
  /// Appends the wedge of edge from -> to (wedge coordinates) to `geometry` (this buffer's, or
  /// one of several built at once), each vertex carrying `attributes`. With `faces` (a two-faced
  /// edge of a counting wedge), the wedge is also cut to the sector where the edge is a
  /// silhouette (penumbra::SilhouetteSector). With `pieceBounds` (counting wedges), it is cut
  /// to each of the receivers' pieces where there are some, every vertex followed by its
  /// piece's corners (AppendWedgeBoundInPieces), or by corners that hold everything.
  void AppendEdgeTo(WedgeGeometry& geometry, const glm::dvec3& from, const glm::dvec3& to,
    const float* attributes, int attributeCount, const EdgeFace* faces = nullptr,
    bool frontFacesOnly = false, bool pieceBounds = false) const;
  std::size_t IndexCount() const { return this->Indices.size(); }
  /// Bytes of the uploaded vertex and index buffers.
  std::size_t UploadedBytes() const
  {
    return this->Uploaded
      ? this->Vertices.size() * sizeof(float) + this->Indices.size() * sizeof(std::uint32_t)
      : 0;
  }
};

/// Penumbra wedges of one caster's centre silhouette for one light.
struct WedgeCache : WedgeBuffer
{
  std::size_t VolumeGeneration = ~std::size_t(0);
  /// position (4), edge from (3), edge to (3), weight (1)
  static constexpr int FloatsPerVertex = 11;
  static const std::vector<VertexAttribute>& Attributes();

  /// Rebuilds when the silhouette, the actor's matrix, the light, its radius or the receivers'
  /// box changed.
  bool Update(const MeshCache& mesh, const VolumeCache& centre, const glm::dmat4& objectToWorld,
    const glm::dvec4& lightWorld, double radius, const Box& receivers);
};

/// Potential-silhouette wedges of one caster for one light, for per-light-sample counting
/// (penumbraSampleCounting.h): one wedge per (edge, up to two of its faces), each vertex carrying
/// the edge and its faces' normals and walk signs so that the fragment shader can take the
/// edge's multiplicity from the pixel's point.
struct CountingWedgeCache : WedgeBuffer
{
  bool FrontFacesOnly = false;
  std::size_t MeshGeneration = ~std::size_t(0);
  /// Edges of the mesh that are a silhouette from some point of the light.
  std::vector<std::uint32_t> Potential;
  bool VerticesBuilt = false;

  /// position (4), edge from (3), edge to (3), two face normals (3 + 3), their signs (2), the
  /// normal of the plane through the edge and the light's centre (3), the min and max corners
  /// of the receivers' piece the vertex's polyhedron lies in (3 + 3)
  static constexpr int FloatsPerVertex = 27;
  static const std::vector<VertexAttribute>& Attributes();
  /// Finds the potential silhouette again when the mesh, the actor's matrix, the light, its
  /// radius or the counting rule changed, and drops the wedges when the receivers' box did too;
  /// returns true when it found it again. The wedges themselves wait for BuildVertices, so that
  /// a light that ends up averaging never builds them.
  bool Update(const MeshCache& mesh, const glm::dmat4& objectToWorld, const glm::dvec4& lightWorld,
    double radius, bool frontFacesOnly, const ReceiverBounds& receivers);
  /// Builds the wedges of the potential silhouette, on all threads.
  void BuildVertices(const MeshCache& mesh);

private:
  /// Appends edge e's wedges (one per pair of its faces) to `geometry`; `world` holds the mesh's
  /// points in wedge coordinates.
  void AppendPotentialEdge(WedgeGeometry& geometry, const CasterTopology& topo,
    const std::vector<glm::dvec3>& world, const glm::dvec4& light, double flip,
    std::uint32_t e) const;
};

/// A surface that casts shadows this frame: an actor's, or one of its blocks or glyphs.
struct CasterCache
{
  vtkWeakPointer<vtkActor> Actor;
  MeshCache* Mesh = nullptr;
  glm::dmat4 ObjectToWorld{ 1.0 }; ///< actor matrix with the mesh origin folded in
  glm::dvec3 WorldMin{ 0.0 }, WorldMax{ 0.0 };
  /// As VTK draws it (penumbra::DrawnSurface::Opacity). Below 1 the caster lets
  /// (1 - Opacity) of the light through at each of its surfaces (a translucent caster).
  double Opacity = 1.0;
  bool Translucent() const { return this->Opacity < 1.0; }
  /// Not in the depth pass (VTK draws it translucent): points behind it are seen through it.
  bool SeenThrough = false;
  /// The faces VTK culls as it draws it: GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, or 0.
  unsigned int CulledFaces = 0;
  /// Per light and light sample (one sample for hard shadows).
  std::map<std::pair<vtkLight*, int>, VolumeCache> Volumes;
  std::map<vtkLight*, WedgeCache> Wedges;
  std::map<vtkLight*, CountingWedgeCache> CountingWedges;
  /// Lights whose shadow of this caster cannot reach the view this frame: nothing is done.
  std::set<vtkLight*> Culled;
  bool Used = false;
};

/// Every mesh and caster the pass keeps between frames, found by data object and by actor.
struct ShadowCaches
{
  std::map<vtkDataObject*, std::unique_ptr<MeshCache>> Meshes;
  /// What each live data object's mesh warned of, kept when the mesh is freed: a prop hidden
  /// and shown again is not warned again.
  DataWarnings Warned;
  /// Keyed by actor, part (penumbra::DrawnSurface: a block or glyph of it) and occurrence in the
  /// frame: an actor VTK draws twice (added to the renderer and a part of an assembly) casts
  /// from each place.
  std::map<std::tuple<vtkActor*, std::size_t, std::size_t>, std::unique_ptr<CasterCache>> Casters;
  /// How often each actor and part was found this frame.
  std::map<std::pair<vtkActor*, std::size_t>, std::size_t> FoundThisFrame;

  /// Finds or creates the mesh of `data` and brings it up to date.
  MeshCache* FindMesh(vtkDataObject* data, vtkProp* prop, vtkProp* viewProp, vtkObject* owner);
  /// Finds or creates the cache of the next occurrence this frame of `actor`'s `part`.
  CasterCache* FindCaster(vtkActor* actor, std::size_t part);
  /// Marks everything unused before a frame; PurgeUnused frees what the frame did not touch.
  void BeginFrame();
  void PurgeUnused();
  void ReleaseGraphicsResources();
  /// Bytes of the vertex and index buffers uploaded to the GPU.
  std::size_t GraphicsBufferBytes() const;
};

} // namespace penumbra

#endif
