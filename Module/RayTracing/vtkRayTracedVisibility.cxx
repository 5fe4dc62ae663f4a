#include "vtkRayTracedVisibility.h"

#include "vtkSoftShadowPass.h"

#include "vtkAbstractMapper3D.h"
#include "vtkActor.h"
#include "vtkAnnotatedCubeActor.h"
#include "vtkAppendPolyData.h"
#include "vtkAssembly.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkAxesActor.h"
#include "vtkBitArray.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkCylinderSource.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSetMapper.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkExecutive.h"
#include "vtkGlyph3D.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationExecutivePortVectorKey.h"
#include "vtkLODActor.h"
#include "vtkLODProp3D.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMapperCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiPieceDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLMoleculeMapper.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkOpenGLStickMapper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkQuadricClustering.h"
#include "vtkQuadricLODActor.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkSkybox.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

namespace
{

/// One actor's (or composite leaf's) triangles in world space, relative to the scene origin, or
/// its spheres (a vtkOpenGLSphereMapper's), traced as Embree's analytic spheres.
struct Mesh
{
  std::vector<glm::dvec3> Points;
  std::vector<glm::uvec3> Triangles;
  std::vector<glm::dvec4> Spheres; ///< centre, radius
  bool Casts = true;
  /// Below 1: a translucent surface, invisible to the eye rays (the pass shadows the nearest
  /// opaque surface) and letting 1 - Opacity of a shadow ray through at each crossing.
  double Opacity = 1.0;
  /// The mapper's clipping planes as (n, offset), world coordinates until the scene is moved
  /// next to the origin, then relative to it: VTK draws no point where n . x + offset < 0, so
  /// no ray hits one (HiddenHit).
  std::vector<glm::dvec4> ClipPlanes;
  /// The property culls the faces whose corners the eye sees counter-clockwise (front) or
  /// clockwise (back): eye rays pass through them, shadow rays do not.
  bool CullFront = false;
  bool CullBack = false;
  bool CullsFaces() const { return this->CullFront || this->CullBack; }
};

/// Whether a hit on `mesh`'s triangle `primitive` is one VTK does not draw: on a clipped side
/// (VTK's fragment shader discards it) or, for an eye ray along `direction`, on a culled face.
bool HiddenHit(const Mesh& mesh, unsigned int primitive, const glm::dvec3& hit,
  const glm::dvec3& direction, bool eyeRay)
{
  for (const glm::dvec4& plane : mesh.ClipPlanes)
  {
    if (glm::dot(glm::dvec3(plane), hit) + plane.w < 0.0)
    {
      return true;
    }
  }
  if (!eyeRay || !mesh.CullsFaces())
  {
    return false;
  }
  const glm::uvec3& triangle = mesh.Triangles[primitive];
  const glm::dvec3& a = mesh.Points[triangle.x];
  // Counter-clockwise in the window: the corners' right-handed normal faces the eye.
  const bool front =
    glm::dot(glm::cross(mesh.Points[triangle.y] - a, mesh.Points[triangle.z] - a), direction) < 0.0;
  return front ? mesh.CullFront : mesh.CullBack;
}

/// Embree's filter for meshes with hits VTK does not draw (HiddenHit). During the filter a ray's
/// tfar is the candidate hit's distance.
void FilterHits(const RTCFilterFunctionNArguments* args, bool eyeRays)
{
  const auto* mesh = static_cast<const Mesh*>(args->geometryUserPtr);
  for (unsigned int i = 0; i < args->N; ++i)
  {
    if (args->valid[i] != -1)
    {
      continue;
    }
    const double t = RTCRayN_tfar(args->ray, args->N, i);
    const glm::dvec3 direction(RTCRayN_dir_x(args->ray, args->N, i),
      RTCRayN_dir_y(args->ray, args->N, i), RTCRayN_dir_z(args->ray, args->N, i));
    const glm::dvec3 hit =
      glm::dvec3(RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
        RTCRayN_org_z(args->ray, args->N, i)) +
      t * direction;
    if (HiddenHit(*mesh, RTCHitN_primID(args->hit, args->N, i), hit, direction, eyeRays))
    {
      args->valid[i] = 0;
    }
  }
}

void FilterEyeHits(const RTCFilterFunctionNArguments* args)
{
  FilterHits(args, true);
}

void FilterShadowHits(const RTCFilterFunctionNArguments* args)
{
  FilterHits(args, false);
}

/// What the shadow rays of one light need, positions relative to the scene origin.
struct ShadowLight
{
  int Index = 0; ///< in the renderer's light collection
  bool Positional = true;
  glm::dvec3 Position{ 0.0 };         ///< positional lights
  double Radius = 0.0;                ///< positional lights, world units
  glm::dvec3 Toward{ 0.0, 0.0, 1.0 }; ///< directional lights: unit direction toward the light
  double OneMinusCosMax = 0.0;        ///< directional lights: 1 - cos(angular radius)
  glm::dvec3 T{ 1.0, 0.0, 0.0 }, B{ 0.0, 1.0, 0.0 }; ///< directional lights: frame around Toward
  float* Values = nullptr;
};

/// splitmix64: tiny, fast and good enough for jitter; one stream per (seed, pixel, light).
struct Random
{
  std::uint64_t State;
  explicit Random(std::uint64_t seed)
    : State(seed)
  {
  }
  std::uint64_t Next()
  {
    std::uint64_t z = (this->State += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double Uniform() { return static_cast<double>(this->Next() >> 11) * 0x1.0p-53; }
};

std::uint64_t StreamSeed(unsigned int seed, std::uint64_t pixel, int light)
{
  Random mix(static_cast<std::uint64_t>(seed) * 0xD1B54A32D192ED03ULL);
  mix.State ^= pixel * 0x9E3779B97F4A7C15ULL;
  mix.Next();
  mix.State ^= static_cast<std::uint64_t>(light + 1) * 0xC2B2AE3D27D4EB4FULL;
  return mix.Next();
}

/// Orthonormal frame around unit n (Duff et al. 2017), branch-free and continuous enough.
void Frame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b)
{
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::dvec3(c, sign + n.y * n.y * a, -n.y);
}

/// The k-th of n stratified points of the unit square: ceil(sqrt(n)) rows whose heights follow
/// how many strata each holds, so that all n strata have the same area 1/n.
glm::dvec2 Stratum(int k, int n, int rows, Random& random)
{
  // Row r holds the samples [floor(r n / rows), floor((r + 1) n / rows)).
  int row = static_cast<int>((static_cast<std::int64_t>(k) * rows) / n);
  while (row + 1 < rows && (static_cast<std::int64_t>(row + 1) * n) / rows <= k)
  {
    ++row;
  }
  while (row > 0 && (static_cast<std::int64_t>(row) * n) / rows > k)
  {
    --row;
  }
  const int first = static_cast<int>((static_cast<std::int64_t>(row) * n) / rows);
  const int last = static_cast<int>((static_cast<std::int64_t>(row + 1) * n) / rows);
  const int count = last - first;
  const double u = (first + random.Uniform() * count) / n;
  const double v = (k - first + random.Uniform()) / count;
  return { u, v };
}

/// Shirley-Chiu concentric map of the unit square onto the unit disk: area preserving and with
/// little distortion, so square strata stay compact on the light.
glm::dvec2 ConcentricDisk(const glm::dvec2& s)
{
  const double a = 2.0 * s.x - 1.0, b = 2.0 * s.y - 1.0;
  if (a == 0.0 && b == 0.0)
  {
    return { 0.0, 0.0 };
  }
  constexpr double quarterPi = 0.78539816339744830962;
  double r, phi;
  if (std::abs(a) > std::abs(b))
  {
    r = a;
    phi = quarterPi * (b / a);
  }
  else
  {
    r = b;
    phi = 2.0 * quarterPi - quarterPi * (a / b);
  }
  return { r * std::cos(phi), r * std::sin(phi) };
}

/// Direction uniform in solid angle inside the cone around w (frame t, b, w) whose half-angle
/// has 1 - cos = oneMinusCosMax: the disk radius squared maps linearly onto 1 - cos(theta).
glm::dvec3 ConeDirection(const glm::dvec2& square, double oneMinusCosMax, const glm::dvec3& t,
  const glm::dvec3& b, const glm::dvec3& w)
{
  const glm::dvec2 d = ConcentricDisk(square);
  const double rho2 = glm::dot(d, d);
  if (rho2 <= 0.0)
  {
    return w;
  }
  const double oneMinusCos = rho2 * oneMinusCosMax;
  const double cosTheta = 1.0 - oneMinusCos;
  const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
  const double scale = sinTheta / std::sqrt(rho2);
  return glm::normalize(d.x * scale * t + d.y * scale * b + cosTheta * w);
}

glm::dvec4 Multiply(const double m[16], const glm::dvec4& v)
{
  // vtkMatrix4x4 is row-major and acts on column vectors.
  return { m[0] * v.x + m[1] * v.y + m[2] * v.z + m[3] * v.w,
    m[4] * v.x + m[5] * v.y + m[6] * v.z + m[7] * v.w,
    m[8] * v.x + m[9] * v.y + m[10] * v.z + m[11] * v.w,
    m[12] * v.x + m[13] * v.y + m[14] * v.z + m[15] * v.w };
}

glm::dvec3 Project(const double m[16], const glm::dvec3& p)
{
  const glm::dvec4 h = Multiply(m, glm::dvec4(p, 1.0));
  return glm::dvec3(h) / h.w;
}

/// World to NDC exactly as the rasterizer sees it, and back, for a viewport of Width x Height.
struct PixelCamera
{
  double ToNDC[16];
  double FromNDC[16];
  int Width = 0;
  int Height = 0;
};

} // namespace

class vtkRayTracedVisibility::vtkInternals
{
public:
  RTCDevice Device = nullptr;
  RTCScene Primary = nullptr;
  RTCScene Shadow = nullptr;      ///< opaque casters
  RTCScene Translucent = nullptr; ///< translucent casters
  bool HasTranslucentCasters = false;
  std::vector<Mesh> Meshes; ///< indexed by primary geometry ID
  glm::dvec3 Origin{ 0.0 };
  double Epsilon = 0.0;
  std::vector<vtkSmartPointer<vtkImageData>> Visibility; ///< per light of the collection
  vtkSmartPointer<vtkImageData> Depth;

  ~vtkInternals()
  {
    this->ReleaseScenes();
    if (this->Device)
    {
      rtcReleaseDevice(this->Device);
    }
  }

  void ReleaseScenes()
  {
    if (this->Primary)
    {
      rtcReleaseScene(this->Primary);
      this->Primary = nullptr;
    }
    for (RTCScene* scene : { &this->Shadow, &this->Translucent })
    {
      if (*scene)
      {
        rtcReleaseScene(*scene);
        *scene = nullptr;
      }
    }
  }

  /// Adds `mesh` to `scene`, the eye rays' (`eyeRays`) or a shadow rays' one. `mesh` must stay
  /// where it is while the scene lives: its filter reads it.
  void AddGeometry(RTCScene scene, unsigned int id, const Mesh& mesh, bool eyeRays)
  {
    RTCGeometry geometry = mesh.Spheres.empty() ? this->NewTriangles(mesh) : this->NewSpheres(mesh);
    const bool culls = eyeRays && mesh.CullsFaces() && mesh.Spheres.empty();
    if (!mesh.ClipPlanes.empty() || culls)
    {
      RTCFilterFunctionN filter = eyeRays ? FilterEyeHits : FilterShadowHits;
      rtcSetGeometryUserData(geometry, const_cast<Mesh*>(&mesh));
      rtcSetGeometryIntersectFilterFunction(geometry, filter);
      rtcSetGeometryOccludedFilterFunction(geometry, filter);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene, geometry, id);
    rtcReleaseGeometry(geometry);
  }

  RTCGeometry NewSpheres(const Mesh& mesh)
  {
    RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    float* spheres = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX,
      0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), mesh.Spheres.size()));
    for (std::size_t i = 0; i < mesh.Spheres.size(); ++i)
    {
      for (int k = 0; k < 4; ++k)
      {
        spheres[4 * i + k] = static_cast<float>(mesh.Spheres[i][k]);
      }
    }
    return geometry;
  }

  RTCGeometry NewTriangles(const Mesh& mesh)
  {
    RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    float* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX,
      0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.Points.size()));
    for (std::size_t i = 0; i < mesh.Points.size(); ++i)
    {
      vertices[3 * i + 0] = static_cast<float>(mesh.Points[i].x);
      vertices[3 * i + 1] = static_cast<float>(mesh.Points[i].y);
      vertices[3 * i + 2] = static_cast<float>(mesh.Points[i].z);
    }
    unsigned int* indices = static_cast<unsigned int*>(rtcSetNewGeometryBuffer(geometry,
      RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned int), mesh.Triangles.size()));
    for (std::size_t i = 0; i < mesh.Triangles.size(); ++i)
    {
      indices[3 * i + 0] = mesh.Triangles[i].x;
      indices[3 * i + 1] = mesh.Triangles[i].y;
      indices[3 * i + 2] = mesh.Triangles[i].z;
    }
    return geometry;
  }

  /// Update's stages, in order: the scene's meshes, Embree's scenes of them (moved next to the
  /// origin), the lights with their images, then every pixel.
  /// Creates the Embree device on first use; false (an error reported on `owner`) if Embree
  /// cannot.
  bool EnsureDevice(vtkObject* owner);
  void CollectMeshes(vtkRenderer* renderer);
  bool BuildScenes(vtkObject* owner, vtkIdType& triangles, vtkIdType& casterTriangles);
  std::vector<ShadowLight> CollectLights(
    vtkRenderer* renderer, int width, int height, vtkObject* owner);
  /// The primary hit of pixel (i, j), its depth, and every light's visibility from it.
  void TracePixel(const PixelCamera& camera, int i, int j, const std::vector<ShadowLight>& lights,
    int samples, unsigned int seed, float* depth) const;

  /// What the translucent casters let through along a shadow ray that no opaque caster blocks:
  /// the product of 1 - opacity over every translucent surface it crosses, each found by
  /// tracing on from just past the last one.
  double Transmission(RTCRay ray) const
  {
    double transmission = 1.0;
    const float farEnd = ray.tfar;
    for (int crossing = 0; crossing < 256 && transmission > 0.0; ++crossing)
    {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit rayHit;
      rayHit.ray = ray;
      rayHit.ray.tfar = farEnd;
      rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(this->Translucent, &context, &rayHit);
      if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
      {
        break;
      }
      transmission *= 1.0 - this->Meshes[rayHit.hit.geomID].Opacity;
      ray.tnear = rayHit.ray.tfar + static_cast<float>(this->Epsilon);
    }
    return transmission;
  }

  /// Fraction of `light` seen from surface point p (relative to Origin) with unit normal n
  /// facing the viewer.
  double Trace(const glm::dvec3& p, const glm::dvec3& n, const ShadowLight& light, int samples,
    Random& random) const
  {
    const glm::dvec3 origin = p + this->Epsilon * n;
    glm::dvec3 w, t, b;
    double oneMinusCosMax = 0.0;
    double distance = 0.0;
    if (light.Positional)
    {
      const glm::dvec3 toCentre = light.Position - p;
      distance = glm::length(toCentre);
      if (distance <= light.Radius || distance <= 0.0)
      {
        // Inside the light (or on a point light): nothing can come between.
        return 1.0;
      }
      w = toCentre / distance;
      if (light.Radius <= 0.0)
      {
        samples = 1;
      }
      else
      {
        // 1 - cos(asin(s)) without cancellation for small lights.
        const double s = light.Radius / distance;
        oneMinusCosMax = s * s / (1.0 + std::sqrt(std::max(0.0, 1.0 - s * s)));
        Frame(w, t, b);
      }
    }
    else
    {
      w = light.Toward;
      t = light.T;
      b = light.B;
      oneMinusCosMax = light.OneMinusCosMax;
      if (oneMinusCosMax <= 0.0)
      {
        samples = 1;
      }
    }

    const int rows = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(samples))));
    double visible = 0.0;
    for (int k = 0; k < samples; ++k)
    {
      glm::dvec3 direction = w;
      if (samples > 1)
      {
        direction = ConeDirection(Stratum(k, samples, rows, random), oneMinusCosMax, t, b, w);
      }
      if (glm::dot(direction, n) <= 0.0)
      {
        continue; // below the surface's own plane: the surface hides it
      }
      double tfar = std::numeric_limits<double>::infinity();
      if (light.Positional)
      {
        // First intersection with the light's sphere along the direction from p.
        const double along = distance * glm::dot(direction, w);
        const double across2 = std::max(0.0, distance * distance - along * along);
        const double inside = std::max(0.0, light.Radius * light.Radius - across2);
        const glm::dvec3 target = p + (along - std::sqrt(inside)) * direction;
        const glm::dvec3 toTarget = target - origin;
        tfar = glm::length(toTarget);
        direction = toTarget / tfar;
        tfar *= 1.0 - 1e-6; // stop just short of the light itself
      }
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRay ray;
      ray.org_x = static_cast<float>(origin.x);
      ray.org_y = static_cast<float>(origin.y);
      ray.org_z = static_cast<float>(origin.z);
      ray.dir_x = static_cast<float>(direction.x);
      ray.dir_y = static_cast<float>(direction.y);
      ray.dir_z = static_cast<float>(direction.z);
      ray.tnear = static_cast<float>(this->Epsilon);
      ray.tfar = static_cast<float>(tfar);
      ray.time = 0.0f;
      ray.mask = ~0u;
      ray.id = 0;
      ray.flags = 0;
      rtcOccluded1(this->Shadow, &context, &ray);
      // rtcOccluded1 sets tfar to -inf on a hit.
      if (ray.tfar >= 0.0f)
      {
        ray.tfar = static_cast<float>(tfar);
        visible += this->HasTranslucentCasters ? this->Transmission(ray) : 1.0;
      }
    }
    return visible / samples;
  }
};

vtkStandardNewMacro(vtkRayTracedVisibility);
vtkCxxSetObjectMacro(vtkRayTracedVisibility, Renderer, vtkRenderer);

vtkRayTracedVisibility::vtkRayTracedVisibility()
  : Internals(new vtkInternals)
{
}

vtkRayTracedVisibility::~vtkRayTracedVisibility()
{
  this->SetRenderer(nullptr);
}

void vtkRayTracedVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer << "\n";
  os << indent << "SamplesPerLight: " << this->SamplesPerLight << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "NumberOfTriangles: " << this->NumberOfTriangles << "\n";
  os << indent << "NumberOfCasterTriangles: " << this->NumberOfCasterTriangles << "\n";
  os << indent << "NumberOfShadowingLights: " << this->NumberOfShadowingLights << "\n";
}

vtkImageData* vtkRayTracedVisibility::GetVisibilityImage(int lightIndex)
{
  const auto& images = this->Internals->Visibility;
  if (lightIndex < 0 || static_cast<std::size_t>(lightIndex) >= images.size())
  {
    return nullptr;
  }
  return images[static_cast<std::size_t>(lightIndex)];
}

vtkImageData* vtkRayTracedVisibility::GetDepthImage()
{
  return this->Internals->Depth;
}

namespace
{

vtkSmartPointer<vtkImageData> NewImage(int width, int height, const char* name, float value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  scalars->SetName(name);
  float* values = static_cast<float*>(image->GetScalarPointer());
  std::fill(values, values + static_cast<std::size_t>(width) * height, value);
  return image;
}

/// `poly` with each convex polygon of more than three corners (vtkPolygon::IsConvex, planar or
/// warped) replaced by the fan from its first corner, the triangles VTK's mapper draws it as. The
/// others are left to vtkTriangleFilter's ear cut: a concave polygon casts as itself, not as the
/// fan VTK shows (limitations.md). Cell data is dropped: the counts no longer match.
vtkSmartPointer<vtkPolyData> FannedConvexPolygons(vtkPolyData* poly)
{
  vtkCellArray* polygons = poly->GetPolys();
  if (!poly->GetPoints() || polygons->GetNumberOfCells() == 0 || polygons->IsHomogeneous() == 3)
  {
    return poly;
  }
  vtkNew<vtkCellArray> cut;
  auto cells = vtk::TakeSmartPointer(polygons->NewIterator());
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  std::vector<vtkIdType> corners;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    cells->GetCurrentCell(count, ids);
    corners.assign(ids, ids + count);
    if (count > 3 &&
      vtkPolygon::IsConvex(poly->GetPoints(), static_cast<int>(count), corners.data()))
    {
      for (vtkIdType k = 1; k + 1 < count; ++k)
      {
        const vtkIdType triangle[3] = { ids[0], ids[k], ids[k + 1] };
        cut->InsertNextCell(3, triangle);
      }
    }
    else
    {
      cut->InsertNextCell(count, ids);
    }
  }
  auto fanned = vtkSmartPointer<vtkPolyData>::New();
  fanned->ShallowCopy(poly);
  fanned->GetCellData()->Initialize();
  fanned->SetPolys(cut);
  return fanned;
}

/// Appends the surface triangles of one dataset, transformed by `matrix`, to `meshes`.
void CollectDataSet(vtkDataObject* data, const double matrix[16], bool casts, double opacity,
  std::vector<Mesh>& meshes, const std::vector<glm::dvec4>& clipPlanes = {})
{
  vtkSmartPointer<vtkPolyData> poly = vtkPolyData::SafeDownCast(data);
  if (!poly)
  {
    vtkDataSet* dataSet = vtkDataSet::SafeDownCast(data);
    if (!dataSet)
    {
      return;
    }
    vtkNew<vtkDataSetSurfaceFilter> surface;
    surface->SetInputData(dataSet);
    surface->Update();
    poly = surface->GetOutput();
  }
  // VTK's own triangulation of polygons and strips, not the pass's (penumbra::CasterTopology),
  // so that a mistake in either shows against the other. Lines and vertices cast nothing.
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(FannedConvexPolygons(poly));
  triangulate->PassLinesOff();
  triangulate->PassVertsOff();
  triangulate->Update();
  vtkPolyData* triangles = triangulate->GetOutput();
  vtkPoints* points = triangles->GetPoints();
  if (!points || triangles->GetNumberOfPolys() == 0)
  {
    return;
  }
  Mesh mesh;
  mesh.Casts = casts;
  mesh.Opacity = opacity;
  mesh.ClipPlanes = clipPlanes;
  mesh.Points.reserve(static_cast<std::size_t>(points->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    mesh.Points.push_back(Project(matrix, glm::dvec3(p[0], p[1], p[2])));
  }
  auto finite = [&](vtkIdType i)
  {
    const glm::dvec3& p = mesh.Points[static_cast<std::size_t>(i)];
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  };
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = triangles->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    // A corner that is not finite: VTK draws nothing there that a ray could meet.
    if (count == 3 && finite(ids[0]) && finite(ids[1]) && finite(ids[2]))
    {
      mesh.Triangles.emplace_back(static_cast<unsigned int>(ids[0]),
        static_cast<unsigned int>(ids[1]), static_cast<unsigned int>(ids[2]));
    }
  }
  if (!mesh.Triangles.empty())
  {
    meshes.push_back(std::move(mesh));
  }
}

/// Reads the name of the array of radii a vtkOpenGLSphereMapper reads (it has no getter), the
/// arrays of a vtkOpenGLStickMapper, and a vtkOpenGLMoleculeMapper's bond mapper.
struct SphereArrays : vtkOpenGLSphereMapper
{
  static constexpr const char* vtkOpenGLSphereMapper::*Scale = &SphereArrays::ScaleArray;
};
struct StickArrays : vtkOpenGLStickMapper
{
  static constexpr const char* vtkOpenGLStickMapper::*Scale = &StickArrays::ScaleArray;
  static constexpr const char* vtkOpenGLStickMapper::*Orientation = &StickArrays::OrientationArray;
};
struct MoleculeParts : vtkOpenGLMoleculeMapper
{
  static constexpr vtkNew<vtkOpenGLStickMapper> vtkOpenGLMoleculeMapper::*Bonds =
    &MoleculeParts::FastBondMapper;
};

/// Whether `array` holds `components` floats for each of `points` points: how VTK's imposter
/// mappers read their arrays (GetVoidPointer), so that anything else they draw from garbage.
bool ReadableAsVTKReadsIt(vtkDataArray* array, int components, vtkIdType points)
{
  return array->GetDataType() == VTK_FLOAT && array->GetNumberOfComponents() == components &&
    array->GetNumberOfTuples() >= points;
}

/// Appends the sticks a vtkOpenGLStickMapper draws, each a fine capped vtkCylinderSource placed
/// by a vtkTransform: centred on the actor-moved point, along the actor's normal matrix times
/// the orientation, as long as the scale array's first component times the orientation's norm
/// and as wide as its second, neither scaled by the actor (VTK's stick shaders).
void CollectSticks(vtkOpenGLStickMapper* mapper, const double matrix[16], bool casts,
  double opacity, std::vector<Mesh>& meshes)
{
  vtkPolyData* input = mapper->GetInput();
  const char* scaleName = mapper->*StickArrays::Scale;
  const char* orientationName = mapper->*StickArrays::Orientation;
  vtkDataArray* sizes = input && scaleName ? input->GetPointData()->GetArray(scaleName) : nullptr;
  vtkDataArray* axes =
    input && orientationName ? input->GetPointData()->GetArray(orientationName) : nullptr;
  if (!sizes || !axes || !ReadableAsVTKReadsIt(sizes, 3, input->GetNumberOfPoints()) ||
    !ReadableAsVTKReadsIt(axes, 3, input->GetNumberOfPoints()))
  {
    return;
  }
  vtkNew<vtkMatrix4x4> normalMatrix;
  normalMatrix->DeepCopy(matrix);
  normalMatrix->Invert();
  normalMatrix->Transpose();
  vtkNew<vtkCylinderSource> cylinder; // along y, height 1, radius 1
  cylinder->SetResolution(96);
  cylinder->SetRadius(1.0);
  cylinder->SetHeight(1.0);
  cylinder->CappingOn();
  vtkNew<vtkAppendPolyData> all;
  for (vtkIdType id = 0; id < input->GetNumberOfPoints(); ++id)
  {
    double p[3], o[4] = { 0, 0, 0, 0 };
    input->GetPoint(id, p);
    axes->GetTuple(id, o);
    const double length = std::abs(sizes->GetComponent(id, 0)) * vtkMath::Norm(o);
    const double radius = sizes->GetComponent(id, 1);
    double axis[4];
    normalMatrix->MultiplyPoint(o, axis);
    const glm::dvec3 centre = Project(matrix, glm::dvec3(p[0], p[1], p[2]));
    if (!(length > 0.0) || !(radius > 0.0) || !std::isfinite(length) || !std::isfinite(radius) ||
      !(vtkMath::Norm(axis) > 0.0) || !std::isfinite(centre.x + centre.y + centre.z))
    {
      continue;
    }
    vtkMath::Normalize(axis);
    const double y[3] = { 0.0, 1.0, 0.0 };
    double turnAxis[3];
    vtkMath::Cross(y, axis, turnAxis);
    const double degrees =
      vtkMath::DegreesFromRadians(std::atan2(vtkMath::Norm(turnAxis), vtkMath::Dot(y, axis)));
    vtkNew<vtkTransform> place;
    place->PostMultiply();
    place->Scale(radius, length, radius);
    if (vtkMath::Norm(turnAxis) > 1e-12)
    {
      place->RotateWXYZ(degrees, turnAxis);
    }
    else if (axis[1] < 0.0)
    {
      place->RotateX(180.0);
    }
    place->Translate(centre.x, centre.y, centre.z);
    vtkNew<vtkTransformPolyDataFilter> moved;
    moved->SetInputConnection(cylinder->GetOutputPort());
    moved->SetTransform(place);
    moved->Update();
    all->AddInputData(moved->GetOutput());
  }
  if (all->GetNumberOfInputConnections(0) == 0)
  {
    return;
  }
  all->Update();
  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  CollectDataSet(all->GetOutput(), identity, casts, opacity, meshes);
}

/// Appends the spheres a vtkOpenGLSphereMapper draws: one per input point, of the radius in its
/// scale array where the input has one, else of its Radius; the centre moved by `matrix`, the
/// radius not (the mapper's vertex shader takes it as the view-space radius).
void CollectSpheres(vtkOpenGLSphereMapper* mapper, const double matrix[16], bool casts,
  double opacity, std::vector<Mesh>& meshes)
{
  vtkPolyData* input = mapper->GetInput();
  if (!input || !input->GetPoints())
  {
    return;
  }
  const char* scaleName = mapper->*SphereArrays::Scale;
  vtkDataArray* radii = scaleName ? input->GetPointData()->GetArray(scaleName) : nullptr;
  if (radii && !ReadableAsVTKReadsIt(radii, 1, input->GetNumberOfPoints()))
  {
    return;
  }
  Mesh mesh;
  mesh.Casts = casts;
  mesh.Opacity = opacity;
  for (vtkIdType id = 0; id < input->GetNumberOfPoints(); ++id)
  {
    double p[3];
    input->GetPoint(id, p);
    const glm::dvec3 centre = Project(matrix, glm::dvec3(p[0], p[1], p[2]));
    const double radius = radii ? radii->GetComponent(id, 0) : mapper->GetRadius();
    if (radius > 0.0 && std::isfinite(radius) && std::isfinite(centre.x) &&
      std::isfinite(centre.y) && std::isfinite(centre.z))
    {
      mesh.Spheres.emplace_back(centre, radius);
    }
  }
  if (!mesh.Spheres.empty())
  {
    meshes.push_back(std::move(mesh));
  }
}

/// The input points a vtkGlyph3DMapper draws a glyph at: not hidden by `mask` (if any), and
/// with a finite orientation (VTK's matrix of a NaN orientation draws nothing).
vtkSmartPointer<vtkDataSet> DrawnGlyphPoints(
  vtkDataSet* points, vtkBitArray* mask, vtkDataArray* orientation)
{
  auto drawn = [&](vtkIdType id)
  {
    if (mask && mask->GetValue(id) == 0)
    {
      return false;
    }
    for (int c = 0; orientation && c < orientation->GetNumberOfComponents(); ++c)
    {
      if (!std::isfinite(orientation->GetComponent(id, c)))
      {
        return false;
      }
    }
    return true;
  };
  auto kept = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> positions;
  kept->GetPointData()->CopyAllocate(points->GetPointData());
  for (vtkIdType id = 0; id < points->GetNumberOfPoints(); ++id)
  {
    if (drawn(id))
    {
      kept->GetPointData()->CopyData(
        points->GetPointData(), id, positions->InsertNextPoint(points->GetPoint(id)));
    }
  }
  kept->SetPoints(positions);
  return kept;
}

/// The glyph sources of a vtkGlyph3DMapper in index order: its source connections, or the
/// children of its source table tree (a child that is not polydata draws nothing here).
std::vector<vtkPolyData*> GlyphSources(vtkGlyph3DMapper* mapper)
{
  std::vector<vtkPolyData*> sources;
  if (!mapper->GetUseSourceTableTree())
  {
    for (int i = 0; i < mapper->GetNumberOfInputConnections(1); ++i)
    {
      sources.push_back(mapper->GetSource(i));
    }
    return sources;
  }
  if (vtkDataObjectTree* table = mapper->GetSourceTableTree())
  {
    auto it = vtk::TakeSmartPointer(table->NewTreeIterator());
    it->SetTraverseSubTree(false);
    it->SetVisitOnlyLeaves(false);
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      sources.push_back(vtkPolyData::SafeDownCast(it->GetCurrentDataObject()));
    }
  }
  return sources;
}

/// The scale VTK 9.1's vtkOpenGLGlyph3DMapper gives a glyph: the scale array's magnitude or
/// components, clamped to Range and mapped onto [0, 1] when Clamping, times ScaleFactor (which
/// applies with or without scaling); 0 becomes 1e-10.
std::array<double, 3> GlyphScaleOf(vtkGlyph3DMapper* mapper, vtkDataArray* scale, vtkIdType id)
{
  std::array<double, 3> by = { 1.0, 1.0, 1.0 };
  if (scale)
  {
    const double* tuple = scale->GetTuple(id);
    if (mapper->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_COMPONENTS &&
      scale->GetNumberOfComponents() == 3)
    {
      by = { tuple[0], tuple[1], tuple[2] };
    }
    else if (mapper->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_MAGNITUDE)
    {
      by.fill(vtkMath::Norm(tuple, scale->GetNumberOfComponents()));
    }
    if (mapper->GetClamping())
    {
      const double* range = mapper->GetRange();
      const double span = range[1] - range[0] != 0.0 ? range[1] - range[0] : 1.0;
      for (double& value : by)
      {
        value = (std::min(std::max(value, range[0]), range[1]) - range[0]) / span;
      }
    }
  }
  for (double& value : by)
  {
    value *= mapper->GetScaleFactor();
    value = value == 0.0 ? 1.0e-10 : value;
  }
  return by;
}

/// The glyphs VTK draws for one dataset of a vtkGlyph3DMapper's input, as a vtkGlyph3D filter
/// (orientation by direction, or none) or a vtkTransform per glyph (rotation angles,
/// quaternions) builds them.
vtkSmartPointer<vtkPolyData> GlyphSurface(vtkGlyph3DMapper* mapper, vtkDataSet* input)
{
  auto arrayName = [mapper](int index) -> const char*
  {
    vtkInformation* info = mapper->GetInputArrayInformation(index);
    return info && info->Has(vtkDataObject::FIELD_NAME()) ? info->Get(vtkDataObject::FIELD_NAME())
                                                          : nullptr;
  };
  vtkPointData* data = input->GetPointData();
  const char* scaleName = arrayName(vtkGlyph3DMapper::SCALE);
  vtkDataArray* scale =
    mapper->GetScaling() && mapper->GetScaleMode() != vtkGlyph3DMapper::NO_DATA_SCALING
    ? (scaleName ? data->GetArray(scaleName) : data->GetScalars())
    : nullptr;
  const char* orientationName = arrayName(vtkGlyph3DMapper::ORIENTATION);
  vtkDataArray* orientation = mapper->GetOrient()
    ? (orientationName ? data->GetArray(orientationName) : data->GetVectors())
    : nullptr;
  const char* indexName = arrayName(vtkGlyph3DMapper::SOURCE_INDEX);
  vtkDataArray* index = mapper->GetSourceIndexing()
    ? (indexName ? data->GetArray(indexName) : data->GetScalars())
    : nullptr;
  const char* maskName = arrayName(vtkGlyph3DMapper::MASK);
  auto mask = mapper->GetMasking() && maskName
    ? vtkBitArray::SafeDownCast(data->GetAbstractArray(maskName))
    : nullptr;
  const std::vector<vtkPolyData*> sourceTable = GlyphSources(mapper);
  const int sources = static_cast<int>(sourceTable.size());
  vtkSmartPointer<vtkDataSet> points = DrawnGlyphPoints(input, mask, orientation);
  // The arrays again, on the points kept.
  auto same = [&points](vtkDataArray* array)
  { return array ? points->GetPointData()->GetArray(array->GetName()) : nullptr; };
  scale = same(scale);
  orientation = same(orientation);
  index = same(index);

  // vtkGlyph3D has one Range for clamping and for picking sources; the mapper clamps with it
  // and picks by the index itself. It has one scalar array, for scaling and for picking, and
  // one vector array, for orienting and for scaling by a vector's components or length; the
  // mapper may take two of each. With any of these, each glyph gets its own transform.
  const bool picks = index && sources > 1;
  const bool clampsAndPicks = mapper->GetClamping() && scale && picks;
  const bool scalesByVector = scale &&
    (mapper->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_COMPONENTS ||
      scale->GetNumberOfComponents() > 1);
  const bool twoScalarArrays = picks && scale && !scalesByVector && scale != index;
  const bool twoVectorArrays = scalesByVector && orientation && scale != orientation;
  if ((!orientation || mapper->GetOrientationMode() == vtkGlyph3DMapper::DIRECTION) &&
    !clampsAndPicks && !twoScalarArrays && !twoVectorArrays)
  {
    vtkNew<vtkGlyph3D> glyphs;
    glyphs->SetInputData(points);
    for (int i = 0; i < sources; ++i)
    {
      glyphs->SetSourceData(i, sourceTable[i]);
    }
    // The mapper applies ScaleFactor with or without a scale array; vtkGlyph3D only when
    // scaling, so it always scales (DataScalingOff without an array).
    glyphs->SetScaling(true);
    glyphs->SetScaleFactor(mapper->GetScaleFactor());
    glyphs->SetClamping(mapper->GetClamping());
    glyphs->SetRange(mapper->GetRange());
    glyphs->SetOrient(orientation != nullptr);
    glyphs->SetVectorModeToUseVector();
    if (!scale)
    {
      glyphs->SetScaleModeToDataScalingOff();
    }
    else if (mapper->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_COMPONENTS)
    {
      glyphs->SetScaleModeToScaleByVectorComponents();
      glyphs->SetInputArrayToProcess(
        1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, scale->GetName());
    }
    else if (scale->GetNumberOfComponents() == 1)
    {
      glyphs->SetScaleModeToScaleByScalar();
      glyphs->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, scale->GetName());
    }
    else
    {
      glyphs->SetScaleModeToScaleByVector();
      glyphs->SetInputArrayToProcess(
        1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, scale->GetName());
    }
    if (orientation)
    {
      glyphs->SetInputArrayToProcess(
        1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, orientation->GetName());
    }
    if (index && sources > 1)
    {
      // The mapper takes the index as the value itself; vtkGlyph3D maps Range onto the sources.
      glyphs->SetIndexModeToScalar();
      glyphs->SetRange(0.0, sources);
      glyphs->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, index->GetName());
    }
    glyphs->Update();
    return glyphs->GetOutput();
  }

  vtkNew<vtkAppendPolyData> append;
  for (vtkIdType id = 0; id < points->GetNumberOfPoints(); ++id)
  {
    const std::array<double, 3> scaleBy = GlyphScaleOf(mapper, scale, id);
    const double* o = orientation ? orientation->GetTuple(id) : nullptr;
    vtkNew<vtkTransform> transform;
    transform->Translate(points->GetPoint(id));
    if (o && mapper->GetOrientationMode() == vtkGlyph3DMapper::DIRECTION)
    {
      // A half turn about the bisector of x and the direction, as the mapper turns it.
      if (o[1] == 0.0 && o[2] == 0.0)
      {
        if (o[0] < 0.0)
        {
          transform->RotateWXYZ(180.0, 0.0, 1.0, 0.0);
        }
      }
      else
      {
        const double length = vtkMath::Norm(o);
        transform->RotateWXYZ(180.0, (o[0] + length) / 2.0, o[1] / 2.0, o[2] / 2.0);
      }
    }
    else if (o && mapper->GetOrientationMode() == vtkGlyph3DMapper::ROTATION)
    {
      transform->RotateZ(o[2]);
      transform->RotateX(o[0]);
      transform->RotateY(o[1]);
    }
    else if (o) // a quaternion (w, x, y, z)
    {
      const double length = vtkMath::Norm(o + 1);
      transform->RotateWXYZ(
        vtkMath::DegreesFromRadians(2.0 * std::atan2(length, o[0])), o[1], o[2], o[3]);
    }
    transform->Scale(scaleBy[0], scaleBy[1], scaleBy[2]);
    int source = 0;
    if (index)
    {
      source = static_cast<int>(vtkMath::Norm(index->GetTuple(id), index->GetNumberOfComponents()));
      source = std::min(std::max(source, 0), sources - 1);
    }
    if (source < 0 || !sourceTable[source])
    {
      continue;
    }
    vtkNew<vtkTransformPolyDataFilter> moved;
    moved->SetInputData(sourceTable[source]);
    moved->SetTransform(transform);
    moved->Update();
    append->AddInputData(moved->GetOutput());
  }
  append->Update();
  return append->GetOutput();
}

/// The leaves of `node` that are drawn, with their opacity: a block's visibility and opacity
/// hold for the blocks under it that set none of their own, and a block's opacity replaces the
/// actor's (`opacity` on entry), as vtkCompositePolyDataMapper2 draws them.
void VisibleLeaves(vtkDataObject* node, vtkCompositeDataDisplayAttributes* attributes, bool visible,
  double opacity, std::vector<std::pair<vtkDataObject*, double>>& leaves)
{
  if (!node)
  {
    return;
  }
  if (attributes && attributes->HasBlockVisibility(node))
  {
    visible = attributes->GetBlockVisibility(node);
  }
  if (attributes && attributes->HasBlockOpacity(node))
  {
    opacity = attributes->GetBlockOpacity(node);
  }
  if (auto blocks = vtkMultiBlockDataSet::SafeDownCast(node))
  {
    for (unsigned int i = 0; i < blocks->GetNumberOfBlocks(); ++i)
    {
      VisibleLeaves(blocks->GetBlock(i), attributes, visible, opacity, leaves);
    }
  }
  else if (auto pieces = vtkMultiPieceDataSet::SafeDownCast(node))
  {
    for (unsigned int i = 0; i < pieces->GetNumberOfPieces(); ++i)
    {
      VisibleLeaves(pieces->GetPiece(i), attributes, visible, opacity, leaves);
    }
  }
  else if (auto composite = vtkCompositeDataSet::SafeDownCast(node))
  {
    auto it = vtk::TakeSmartPointer(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      VisibleLeaves(it->GetCurrentDataObject(), attributes, visible, opacity, leaves);
    }
  }
  else if (visible && opacity > 0.0)
  {
    leaves.emplace_back(node, std::min(opacity, 1.0));
  }
}

/// Whether vtkCompositePolyDataMapper2 draws `block` (of `opacity`) in neither of VTK's passes:
/// it takes a block for opaque at opacity 1 with an opaque actor texture and, showing scalars,
/// colours its lookup table calls opaque, and draws such a block only in the opaque pass, which
/// VTK skips for an actor it takes for translucent (a property opacity below 1, say).
bool DrawnInNeitherPass(
  vtkActor* actor, vtkCompositePolyDataMapper2* mapper, vtkPolyData* block, double opacity)
{
  if (opacity < 1.0 || actor->GetForceTranslucent() || actor->HasOpaqueGeometry() ||
    (actor->GetTexture() && actor->GetTexture()->IsTranslucent()))
  {
    return false;
  }
  if (!mapper->GetScalarVisibility())
  {
    return true;
  }
  int cellFlag = 0;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(block, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  vtkScalarsToColors* colours = mapper->GetLookupTable();
  colours->Build();
  return colours->IsOpaque(scalars, mapper->GetColorMode(), mapper->GetArrayComponent()) != 0;
}

/// Whether `data` holds a polydata whose points reach an infinite coordinate.
bool ReachesInfinity(vtkDataObject* data)
{
  if (auto tree = vtkDataObjectTree::SafeDownCast(data))
  {
    vtkSmartPointer<vtkDataObjectTreeIterator> it;
    it.TakeReference(tree->NewTreeIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (ReachesInfinity(it->GetCurrentDataObject()))
      {
        return true;
      }
    }
    return false;
  }
  auto input = vtkPolyData::SafeDownCast(data);
  vtkDataArray* coordinates = input && input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
  for (int axis = 0; coordinates && axis < 3; ++axis)
  {
    const double* range = coordinates->GetRange(axis);
    if (std::isinf(range[0]) || std::isinf(range[1]))
    {
      return true;
    }
  }
  return false;
}

/// VTK 9.1's polydata mapper, with one of its automatic shift methods (the default), moves its
/// vertex buffer by the middle of its input points' range: a point at an infinite coordinate
/// makes every vertex NaN, and nothing of the data is drawn. vtkDataSetMapper hands a polydata
/// input, all its points, to such a mapper of its own; vtkCompositePolyDataMapper2 shifts one
/// buffer for all its polydata blocks.
bool ShiftedOutOfSight(vtkMapper* mapper)
{
  if (!vtkOpenGLVertexBufferObject::GetGlobalCoordShiftAndScaleEnabled())
  {
    return false;
  }
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  int method = vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE; // a vtkDataSetMapper's before it drew
  if (auto datasets = vtkDataSetMapper::SafeDownCast(mapper))
  {
    if (!vtkPolyData::SafeDownCast(input))
    {
      return false;
    }
    if (auto inner = vtkOpenGLPolyDataMapper::SafeDownCast(datasets->GetPolyDataMapper()))
    {
      method = inner->GetVBOShiftScaleMethod();
    }
  }
  else if (auto drawn = vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    method = drawn->GetVBOShiftScaleMethod();
  }
  else
  {
    return false;
  }
  switch (method)
  {
    case vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE:
    case vtkOpenGLVertexBufferObject::ALWAYS_AUTO_SHIFT_SCALE:
    case vtkOpenGLVertexBufferObject::AUTO_SHIFT:
      return ReachesInfinity(input);
    default:
      return false;
  }
}

/// The interactor of a window that draws `prop`, found through the renderers and assemblies
/// that hold it (no deeper than `levels`).
vtkRenderWindowInteractor* WindowInteractor(vtkProp* prop, int levels = 16)
{
  vtkRenderWindowInteractor* found = nullptr;
  for (int i = 0; i < prop->GetNumberOfConsumers() && !found && levels > 0; ++i)
  {
    vtkObject* holder = prop->GetConsumer(i);
    if (auto* renderer = vtkRenderer::SafeDownCast(holder))
    {
      found = renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetInteractor() : nullptr;
    }
    else if (auto* whole = vtkProp::SafeDownCast(holder))
    {
      found = WindowInteractor(whole, levels - 1);
    }
  }
  return found;
}

/// The mapper of a vtkQuadricLODActor's decimated level, where its Render drew that level:
/// an interactive frame, the actor's allotted time (as a float) at most 1.1 over the interactor's
/// desired update rate held to 1..75. The level's mapper is the one its LOD filter's output
/// feeds. Null where the full mapper was drawn.
vtkMapper* QuadricLevel(vtkQuadricLODActor* actor)
{
  vtkRenderWindowInteractor* interactor = WindowInteractor(actor);
  vtkAlgorithm* filter = actor->GetLODFilter();
  if (!interactor || !filter ||
    static_cast<float>(actor->GetAllocatedRenderTime()) >
      1.1 / vtkMath::ClampValue(interactor->GetDesiredUpdateRate(), 1.0, 75.0))
  {
    return nullptr;
  }
  vtkInformation* info = filter->GetOutputInformation(0);
  const int count = vtkExecutive::CONSUMERS()->Length(info);
  vtkExecutive** executives = vtkExecutive::CONSUMERS()->GetExecutives(info);
  for (int i = 0; i < count; ++i)
  {
    if (auto* mapper = vtkMapper::SafeDownCast(executives[i]->GetAlgorithm()))
    {
      return mapper;
    }
  }
  return nullptr;
}

/// The mapper VTK drew `actor` with last: a vtkQuadricLODActor's decimated level where it drew
/// that (QuadricLevel); a vtkLODActor's level as vtkLODActor::Render picks it (VTK 9.1): its
/// mapper when its last draw time fits the time the renderer allotted the actor; else, over its
/// levels in order and until one never drawn (time 0) is met, a faster one while none fits and
/// a slower one that still fits.
vtkMapper* LastDrawnMapper(vtkActor* actor)
{
  if (auto* quadric = vtkQuadricLODActor::SafeDownCast(actor))
  {
    vtkMapper* level = actor->GetMapper() ? QuadricLevel(quadric) : nullptr;
    return level ? level : actor->GetMapper();
  }
  auto lod = vtkLODActor::SafeDownCast(actor);
  vtkMapper* best = actor->GetMapper();
  const double allotted = lod ? lod->GetAllocatedRenderTime() : 0.0;
  if (!lod || !best || best->GetTimeToDraw() <= allotted)
  {
    return best;
  }
  vtkMapperCollection* levels = lod->GetLODMappers();
  for (int i = 0; i < levels->GetNumberOfItems() && best->GetTimeToDraw() != 0.0; ++i)
  {
    auto level = vtkMapper::SafeDownCast(levels->GetItemAsObject(i));
    const double time = level->GetTimeToDraw(), bestTime = best->GetTimeToDraw();
    const bool faster = bestTime > allotted && time < bestTime;
    const bool slowerButFits = time > bestTime && time < allotted;
    if (time == 0.0 || faster || slowerButFits)
    {
      best = level;
    }
  }
  return best;
}

/// Appends what VTK draws of one leaf prop (an actor, or an assembly's part at the path's
/// composed matrix) to `meshes`, with its opacity: its block's where one is set, else its
/// property's; 1 where VTK draws it opaque.
void CollectLeaf(vtkActor* actor, vtkMatrix4x4* pathMatrix, bool casts, std::vector<Mesh>& meshes)
{
  vtkMapper* mapper = LastDrawnMapper(actor);
  const double opacity = actor->GetProperty()->GetOpacity();
  if (!actor->GetVisibility() || !mapper || !(opacity > 0.0))
  {
    return;
  }
  mapper->Update();
  double matrix[16];
  vtkMatrix4x4::DeepCopy(matrix, pathMatrix ? pathMatrix : actor->GetMatrix());
  // Imposters: points without cells have no bounds, and VTK's culler does not draw what has
  // none. A molecule is drawn by a sphere mapper for its atoms and a stick mapper for its bonds.
  const double drawnOpacity = actor->HasOpaqueGeometry() ? 1.0 : opacity;
  auto spheres = vtkOpenGLSphereMapper::SafeDownCast(mapper);
  auto sticks = vtkOpenGLStickMapper::SafeDownCast(mapper);
  auto molecule = vtkOpenGLMoleculeMapper::SafeDownCast(mapper);
  if (spheres || sticks || molecule)
  {
    if (!vtkMath::AreBoundsInitialized(mapper->GetBounds()))
    {
      return;
    }
    if (molecule && molecule->GetRenderAtoms())
    {
      spheres = molecule->GetFastAtomMapper();
    }
    if (molecule && molecule->GetRenderBonds())
    {
      sticks = &*(molecule->*MoleculeParts::Bonds);
    }
    if (spheres)
    {
      CollectSpheres(spheres, matrix, casts, drawnOpacity, meshes);
    }
    if (sticks)
    {
      CollectSticks(sticks, matrix, casts, drawnOpacity, meshes);
    }
    return;
  }
  // Lines and points: a wireframe or points representation draws no surface; nor does data
  // VTK shifts out of sight.
  if (actor->GetProperty()->GetRepresentation() != VTK_SURFACE || ShiftedOutOfSight(mapper))
  {
    return;
  }
  // VTK's shaders clip by the first six planes, each keeping the side its normal points to.
  std::vector<glm::dvec4> clipPlanes;
  if (vtkPlaneCollection* planes = mapper->GetClippingPlanes())
  {
    for (int i = 0; i < std::min(planes->GetNumberOfItems(), 6); ++i)
    {
      const glm::dvec3 n = glm::make_vec3(planes->GetItem(i)->GetNormal());
      clipPlanes.emplace_back(n, -glm::dot(n, glm::make_vec3(planes->GetItem(i)->GetOrigin())));
    }
  }
  auto blocks = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
  std::vector<std::pair<vtkDataObject*, double>> leaves;
  VisibleLeaves(mapper->GetInputDataObject(0, 0),
    blocks ? blocks->GetCompositeDataDisplayAttributes() : nullptr, true, opacity, leaves);
  auto glyphs = vtkGlyph3DMapper::SafeDownCast(mapper);
  vtkCompositeDataDisplayAttributes* glyphBlocks = glyphs ? glyphs->GetBlockAttributes() : nullptr;
  const std::size_t first = meshes.size();
  for (const auto& leaf : leaves)
  {
    // A glyph mapper skips a leaf whose own block visibility is off, and nothing else.
    if (glyphBlocks && glyphBlocks->HasBlockVisibility(leaf.first) &&
      !glyphBlocks->GetBlockVisibility(leaf.first))
    {
      continue;
    }
    auto points = vtkDataSet::SafeDownCast(leaf.first);
    double leafOpacity = !blocks && actor->HasOpaqueGeometry() ? 1.0 : leaf.second;
    auto polyData = vtkPolyData::SafeDownCast(leaf.first);
    if (blocks && !polyData)
    {
      continue; // vtkCompositePolyDataMapper2 draws no other datasets
    }
    if (blocks && actor->GetForceOpaque())
    {
      leafOpacity = 1.0; // every block in VTK's opaque pass
    }
    else if (blocks && DrawnInNeitherPass(actor, blocks, polyData, leaf.second))
    {
      continue;
    }
    if (!glyphs)
    {
      CollectDataSet(leaf.first, matrix, casts, leafOpacity, meshes, clipPlanes);
    }
    else if (points)
    {
      CollectDataSet(GlyphSurface(glyphs, points), matrix, casts, leafOpacity, meshes, clipPlanes);
    }
  }
  for (std::size_t i = first; i < meshes.size(); ++i)
  {
    meshes[i].CullFront = actor->GetProperty()->GetFrontfaceCulling();
    meshes[i].CullBack = actor->GetProperty()->GetBackfaceCulling();
  }
}

/// Appends every leaf of a prop: itself, or each part of an assembly. `casts`: the top-level
/// prop's flag.
void CollectProp(vtkProp* prop, bool casts, std::vector<Mesh>& meshes)
{
  if (auto axes = vtkAxesActor::SafeDownCast(prop))
  {
    // Its shafts and tips are actors of its own, at the matrices VTK last drew them with.
    vtkNew<vtkPropCollection> parts;
    axes->GetActors(parts);
    for (int i = 0; i < parts->GetNumberOfItems(); ++i)
    {
      CollectProp(static_cast<vtkProp*>(parts->GetItemAsObject(i)), casts, meshes);
    }
    return;
  }
  if (auto cube = vtkAnnotatedCubeActor::SafeDownCast(prop))
  {
    CollectProp(cube->GetAssembly(), casts, meshes); // what VTK draws for it
    return;
  }
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkAssemblyNode* node = path->GetLastNode();
    vtkProp* leaf = node ? node->GetViewProp() : nullptr;
    if (vtkSkybox::SafeDownCast(leaf))
    {
      continue; // at infinity: it occludes nothing
    }
    if (auto actor = vtkActor::SafeDownCast(leaf))
    {
      CollectLeaf(actor, node->GetMatrix(), casts, meshes);
    }
    else if (auto levels = vtkLODProp3D::SafeDownCast(leaf))
    {
      // The level VTK draws (its pick level once drawn): an actor of its own at its matrix.
      vtkAbstractMapper3D* mapper = levels->GetLODMapper(levels->GetPickLODID());
      vtkNew<vtkPropCollection> actors;
      levels->GetActors(actors);
      for (int i = 0; i < actors->GetNumberOfItems(); ++i)
      {
        auto level = vtkActor::SafeDownCast(actors->GetItemAsObject(i));
        if (level && level->GetMapper() == mapper)
        {
          CollectLeaf(level, levels->GetMatrix(), casts, meshes);
        }
      }
    }
  }
}

/// Whether `light` shadows: it shines (switched on, with intensity) from somewhere else than the
/// eye (a headlight's shadows lie behind what it lights) and VTK's shadow attenuation lets it
/// darken. The twin of vtkSoftShadowPass::LightCastsShadows, kept apart so that the truth
/// shares no decision with the pass.
bool ShadowsInTheTruth(vtkLight* light)
{
  return light->GetSwitch() && light->GetLightType() != VTK_LIGHT_TYPE_HEADLIGHT &&
    light->GetIntensity() > 0.0 && light->GetShadowAttenuation() > 0.0;
}

} // namespace

void vtkRayTracedVisibility::vtkInternals::CollectMeshes(vtkRenderer* renderer)
{
  // Every visible opaque surface, in world space, found through VTK's own filters
  // (CollectProp), not through the pass's walk of the scene.
  this->Meshes.clear();
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator propIt;
  vtkProp* prop;
  for (props->InitTraversal(propIt); (prop = props->GetNextProp(propIt));)
  {
    if (prop->GetVisibility())
    {
      CollectProp(prop, vtkSoftShadowPass::GetCastsShadows(prop), this->Meshes);
    }
  }
}

bool vtkRayTracedVisibility::vtkInternals::BuildScenes(
  vtkObject* owner, vtkIdType& triangles, vtkIdType& casterTriangles)
{
  // Embree traces in float: everything is moved next to the origin in double first.
  // The box of what is traced: points no triangle uses (common in PLY, OBJ and scanner files)
  // may lie anywhere, and would move the origin and the epsilon with them.
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const Mesh& mesh : this->Meshes)
  {
    for (const glm::uvec3& triangle : mesh.Triangles)
    {
      for (int corner = 0; corner < 3; ++corner)
      {
        lo = glm::min(lo, mesh.Points[triangle[corner]]);
        hi = glm::max(hi, mesh.Points[triangle[corner]]);
      }
    }
    for (const glm::dvec4& sphere : mesh.Spheres)
    {
      lo = glm::min(lo, glm::dvec3(sphere) - sphere.w);
      hi = glm::max(hi, glm::dvec3(sphere) + sphere.w);
    }
  }
  const bool traced = lo.x <= hi.x;
  this->Origin = traced ? 0.5 * (lo + hi) : glm::dvec3(0.0);
  const double diagonal = traced ? glm::length(hi - lo) : 1.0;
  // Far above float rounding of coordinates near the origin (~6e-8 of the extent).
  this->Epsilon = 1e-5 * (diagonal > 0.0 ? diagonal : 1.0);

  this->ReleaseScenes();
  this->HasTranslucentCasters = false;
  for (RTCScene* scene : { &this->Primary, &this->Shadow, &this->Translucent })
  {
    *scene = rtcNewScene(this->Device);
    // Robust mode: rays through shared edges and vertices do not slip between triangles.
    rtcSetSceneFlags(*scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(*scene, RTC_BUILD_QUALITY_HIGH);
  }
  for (std::size_t i = 0; i < this->Meshes.size(); ++i)
  {
    Mesh& mesh = this->Meshes[i];
    for (glm::dvec3& p : mesh.Points)
    {
      p -= this->Origin;
    }
    for (glm::dvec4& sphere : mesh.Spheres)
    {
      sphere -= glm::dvec4(this->Origin, 0.0);
    }
    for (glm::dvec4& plane : mesh.ClipPlanes)
    {
      plane.w += glm::dot(glm::dvec3(plane), this->Origin);
    }
    // Ids are indices into Meshes in every scene: a hit finds its mesh's plane or opacity.
    const unsigned int id = static_cast<unsigned int>(i);
    const bool opaque = mesh.Opacity >= 1.0;
    if (opaque)
    {
      this->AddGeometry(this->Primary, id, mesh, true);
      triangles += static_cast<vtkIdType>(mesh.Triangles.size());
    }
    if (mesh.Casts)
    {
      this->AddGeometry(opaque ? this->Shadow : this->Translucent, id, mesh, false);
      casterTriangles += static_cast<vtkIdType>(mesh.Triangles.size());
      this->HasTranslucentCasters |= !opaque;
    }
  }
  for (RTCScene scene : { this->Primary, this->Shadow, this->Translucent })
  {
    rtcCommitScene(scene);
  }
  const RTCError error = rtcGetDeviceError(this->Device);
  if (error != RTC_ERROR_NONE)
  {
    vtkErrorWithObjectMacro(owner, "Embree failed to build the scene (error " << error << ").");
    this->ReleaseScenes();
    return false;
  }
  return true;
}

std::vector<ShadowLight> vtkRayTracedVisibility::vtkInternals::CollectLights(
  vtkRenderer* renderer, int width, int height, vtkObject* owner)
{
  // In collection order; those that cast no shadow get no image.
  std::vector<ShadowLight> lights;
  vtkLightCollection* lightCollection = renderer->GetLights();
  vtkCollectionSimpleIterator lightIt;
  lightCollection->InitTraversal(lightIt);
  int lightIndex = 0;
  for (vtkLight* light = lightCollection->GetNextLight(lightIt); light;
       light = lightCollection->GetNextLight(lightIt), ++lightIndex)
  {
    this->Visibility.emplace_back();
    if (!ShadowsInTheTruth(light))
    {
      continue;
    }
    ShadowLight shadowLight;
    shadowLight.Index = lightIndex;
    shadowLight.Positional = light->GetPositional() != 0;
    glm::dvec3 position, focal;
    light->GetTransformedPosition(&position.x);
    light->GetTransformedFocalPoint(&focal.x);
    const double radius = std::max(0.0, vtkSoftShadowPass::GetLightRadius(light));
    const glm::dvec3 placement = shadowLight.Positional ? position : position - focal;
    if (!std::isfinite(placement.x) || !std::isfinite(placement.y) || !std::isfinite(placement.z))
    {
      // Rays from or towards it would not be rays: it lights and shadows nothing.
      vtkWarningWithObjectMacro(owner,
        "Light " << lightIndex << " has a non-finite position or direction: it is not traced.");
      continue;
    }
    if (shadowLight.Positional)
    {
      shadowLight.Position = position - this->Origin;
      shadowLight.Radius = radius;
    }
    else
    {
      const glm::dvec3 toward = position - focal;
      if (!(glm::length(toward) > 0.0))
      {
        vtkWarningWithObjectMacro(owner,
          "Directional light " << lightIndex << " has no direction (position = focal point).");
        continue;
      }
      shadowLight.Toward = glm::normalize(toward);
      Frame(shadowLight.Toward, shadowLight.T, shadowLight.B);
      const double halfAngle = std::min(radius, 90.0) * 3.14159265358979323846 / 180.0;
      const double s = std::sin(0.5 * halfAngle);
      shadowLight.OneMinusCosMax = 2.0 * s * s;
    }
    this->Visibility.back() = NewImage(width, height, "Visibility", 1.0f);
    shadowLight.Values = static_cast<float*>(this->Visibility.back()->GetScalarPointer());
    lights.push_back(shadowLight);
  }
  return lights;
}

namespace
{
/// The primary hit redone in double against the triangle's plane (a better point to shadow
/// from), with the triangle's normal facing the viewer.
void RefineTriangleHit(const Mesh& mesh, const RTCRayHit& rayHit, const glm::dvec3& origin,
  const glm::dvec3& direction, glm::dvec3& hit, glm::dvec3& normal)
{
  const glm::uvec3& triangle = mesh.Triangles[rayHit.hit.primID];
  const glm::dvec3& a = mesh.Points[triangle.x];
  normal = glm::cross(mesh.Points[triangle.y] - a, mesh.Points[triangle.z] - a);
  const double normalLength = glm::length(normal);
  if (normalLength > 0.0)
  {
    normal /= normalLength;
  }
  else
  {
    // Flattened by the actor's matrix: Embree's float normal is all there is.
    normal = glm::normalize(glm::dvec3(rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z));
  }
  const double cosine = glm::dot(direction, normal);
  double t = rayHit.ray.tfar;
  if (std::abs(cosine) > 1e-6)
  {
    t = glm::dot(a - origin, normal) / cosine;
  }
  hit = origin + t * direction;
  if (cosine > 0.0)
  {
    normal = -normal; // face the viewer
  }
}

/// The same against a sphere (centre, radius): its nearest crossing in front of the eye, with
/// the normal facing the viewer (inward where the eye is inside).
void RefineSphereHit(const glm::dvec4& sphere, float floatT, const glm::dvec3& origin,
  const glm::dvec3& direction, glm::dvec3& hit, glm::dvec3& normal)
{
  const glm::dvec3 centre(sphere);
  const glm::dvec3 fromCentre = origin - centre;
  const double b = glm::dot(fromCentre, direction);
  const double c = glm::dot(fromCentre, fromCentre) - sphere.w * sphere.w;
  const double discriminant = b * b - c;
  double t = floatT;
  if (discriminant >= 0.0)
  {
    const double root = std::sqrt(discriminant);
    t = -b - root >= 0.0 ? -b - root : -b + root;
  }
  hit = origin + t * direction;
  normal = glm::normalize(hit - centre);
  if (glm::dot(normal, direction) > 0.0)
  {
    normal = -normal;
  }
}
} // namespace

void vtkRayTracedVisibility::vtkInternals::TracePixel(const PixelCamera& camera, int i, int j,
  const std::vector<ShadowLight>& lights, int samples, unsigned int seed, float* depth) const
{
  const std::size_t pixel = static_cast<std::size_t>(j) * camera.Width + i;
  const double x = (i + 0.5) / camera.Width * 2.0 - 1.0;
  const double y = (j + 0.5) / camera.Height * 2.0 - 1.0;
  const glm::dvec3 nearPoint = Project(camera.FromNDC, glm::dvec3(x, y, -1.0));
  const glm::dvec3 farPoint = Project(camera.FromNDC, glm::dvec3(x, y, 1.0));
  const glm::dvec3 origin = nearPoint - this->Origin;
  const double length = glm::length(farPoint - nearPoint);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return;
  }
  const glm::dvec3 direction = (farPoint - nearPoint) / length;

  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  rayHit.ray.org_x = static_cast<float>(origin.x);
  rayHit.ray.org_y = static_cast<float>(origin.y);
  rayHit.ray.org_z = static_cast<float>(origin.z);
  rayHit.ray.dir_x = static_cast<float>(direction.x);
  rayHit.ray.dir_y = static_cast<float>(direction.y);
  rayHit.ray.dir_z = static_cast<float>(direction.z);
  rayHit.ray.tnear = 0.0f;
  rayHit.ray.tfar = static_cast<float>(length);
  rayHit.ray.time = 0.0f;
  rayHit.ray.mask = ~0u;
  rayHit.ray.id = 0;
  rayHit.ray.flags = 0;
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(this->Primary, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
  {
    return; // background: depth 1, visibility 1
  }

  const Mesh& mesh = this->Meshes[rayHit.hit.geomID];
  glm::dvec3 hit, normal;
  if (mesh.Spheres.empty())
  {
    RefineTriangleHit(mesh, rayHit, origin, direction, hit, normal);
  }
  else
  {
    RefineSphereHit(
      mesh.Spheres[rayHit.hit.primID], rayHit.ray.tfar, origin, direction, hit, normal);
  }

  const glm::dvec3 ndc = Project(camera.ToNDC, hit + this->Origin);
  depth[pixel] = static_cast<float>(std::min(1.0, std::max(0.0, 0.5 * (ndc.z + 1.0))));
  for (const ShadowLight& light : lights)
  {
    Random random(StreamSeed(seed, pixel, light.Index));
    light.Values[pixel] = static_cast<float>(this->Trace(hit, normal, light, samples, random));
  }
}

namespace
{
/// World -> NDC exactly as the rasterizer sees the renderer's tiled viewport, and back.
PixelCamera MakePixelCamera(vtkRenderer* renderer, vtkCamera* camera, int width, int height)
{
  PixelCamera pixels;
  pixels.Width = width;
  pixels.Height = height;
  vtkMatrix4x4::DeepCopy(pixels.ToNDC,
    camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
  vtkMatrix4x4::Invert(pixels.ToNDC, pixels.FromNDC);
  return pixels;
}

/**
 * Runs traceRow(j) for every row j < rows on `threads` threads (this one among them), rows
 * handed out in turn so that slow rows do not leave threads idle. The caller's thread is the
 * only one that calls `progress` (with the rows done so far), about fifty times in all: VTK's
 * events must not fire from worker threads.
 */
template <typename TraceRow, typename Progress>
void TraceRowsInParallel(int rows, int threads, TraceRow traceRow, Progress progress)
{
  threads = std::max(1, std::min(threads, rows));
  std::atomic<int> nextRow{ 0 };
  std::atomic<int> rowsDone{ 0 };
  auto work = [&]()
  {
    for (int j = nextRow++; j < rows; j = nextRow++)
    {
      traceRow(j);
      ++rowsDone;
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(static_cast<std::size_t>(threads - 1));
  for (int k = 1; k < threads; ++k)
  {
    workers.emplace_back(work);
  }
  const int reportEvery = std::max(1, rows / 50);
  int lastReported = 0;
  for (int j = nextRow++; j < rows; j = nextRow++)
  {
    traceRow(j);
    const int done = ++rowsDone;
    if (done - lastReported >= reportEvery)
    {
      lastReported = done;
      progress(done);
    }
  }
  for (std::thread& worker : workers)
  {
    worker.join();
  }
}
} // namespace

bool vtkRayTracedVisibility::vtkInternals::EnsureDevice(vtkObject* owner)
{
  if (!this->Device)
  {
    this->Device = rtcNewDevice(nullptr);
    if (!this->Device)
    {
      vtkErrorWithObjectMacro(
        owner, "Embree could not create a device (error " << rtcGetDeviceError(nullptr) << ").");
      return false;
    }
  }
  return true;
}

bool vtkRayTracedVisibility::CheckRenderer(int& width, int& height)
{
  vtkRenderer* renderer = this->Renderer;
  if (!renderer || !renderer->GetRenderWindow())
  {
    vtkErrorMacro("No renderer, or a renderer without a render window, to trace.");
    return false;
  }
  int x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width <= 0 || height <= 0)
  {
    vtkErrorMacro("The renderer's viewport is empty (" << width << " x " << height << ").");
    return false;
  }
  if (!renderer->GetActiveCamera())
  {
    vtkErrorMacro("The renderer has no camera.");
    return false;
  }
  return true;
}

bool vtkRayTracedVisibility::Update()
{
  vtkInternals& internals = *this->Internals;
  internals.Visibility.clear();
  internals.Depth = nullptr;
  this->NumberOfTriangles = 0;
  this->NumberOfCasterTriangles = 0;
  this->NumberOfShadowingLights = 0;
  int width = 0, height = 0;
  if (!this->CheckRenderer(width, height) || !internals.EnsureDevice(this))
  {
    return false;
  }

  double progress = 0.0;
  this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
  vtkRenderer* renderer = this->Renderer;
  internals.CollectMeshes(renderer);
  if (!internals.BuildScenes(this, this->NumberOfTriangles, this->NumberOfCasterTriangles))
  {
    return false;
  }
  const std::vector<ShadowLight> lights = internals.CollectLights(renderer, width, height, this);
  this->NumberOfShadowingLights = static_cast<int>(lights.size());
  internals.Depth = NewImage(width, height, "Depth", 1.0f);
  float* depth = static_cast<float*>(internals.Depth->GetScalarPointer());

  const PixelCamera pixels = MakePixelCamera(renderer, renderer->GetActiveCamera(), width, height);
  const int samples = this->SamplesPerLight;
  const unsigned int seed = this->Seed;
  const int threads = this->NumberOfThreads > 0
    ? this->NumberOfThreads
    : static_cast<int>(std::thread::hardware_concurrency());
  TraceRowsInParallel(
    height, threads,
    [&](int j)
    {
      for (int i = 0; i < width; ++i)
      {
        internals.TracePixel(pixels, i, j, lights, samples, seed, depth);
      }
    },
    [&](int rowsDone)
    {
      progress = static_cast<double>(rowsDone) / height;
      this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
    });

  // The images are all that is kept: the scenes are rebuilt by the next Update anyway.
  internals.ReleaseScenes();
  internals.Meshes.clear();
  internals.Meshes.shrink_to_fit();
  progress = 1.0;
  this->InvokeEvent(vtkCommand::ProgressEvent, &progress);
  return true;
}
