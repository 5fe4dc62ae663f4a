// The scenes of the hard-case suite, numbered as in issue 5. Every scene stands on a ground plane
// (y = 0) unless the case is about something else; light radii are world units (positional) or
// degrees (directional), as vtkSoftShadowPass::SetLightRadius takes them.
#include "penumbraHardCases.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkColorTransferFunction.h"
#include "vtkConeSource.h"
#include "vtkContourFilter.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkParametricBoy.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricKlein.h"
#include "vtkParametricMobius.h"
#include "vtkParametricTorus.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTrivialProducer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/glm.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace penumbra_hard
{

const char* MethodName(int method)
{
  static const char* names[METHOD_COUNT] = { "hard", "averaged16", "wedges", "automatic",
    "counted16", "half16" };
  return method >= 0 && method < METHOD_COUNT ? names[method] : "?";
}

namespace
{

vtkSmartPointer<vtkPolyData> MakeMesh(
  const std::vector<glm::dvec3>& points, const std::vector<std::vector<vtkIdType>>& cells)
{
  vtkNew<vtkPoints> vtkpoints;
  vtkpoints->SetDataTypeToDouble();
  for (const glm::dvec3& p : points)
  {
    vtkpoints->InsertNextPoint(p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& cell : cells)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(cell.size()), cell.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(vtkpoints);
  mesh->SetPolys(polys);
  return mesh;
}

vtkActor* AddParametric(CaseScene& scene, vtkParametricFunction* function, int uResolution,
  int vResolution, double r, double g, double b)
{
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(function);
  source->SetUResolution(uResolution);
  source->SetVResolution(vResolution);
  return scene.Add(source, r, g, b);
}

/// A surface z = f(x, y) on a grid, as quads.
vtkSmartPointer<vtkPolyData> HeightField(
  int n, double half, const std::function<double(double, double)>& height)
{
  std::vector<glm::dvec3> points;
  std::vector<std::vector<vtkIdType>> quads;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double x = -half + 2 * half * i / n, z = -half + 2 * half * j / n;
      points.emplace_back(x, height(x, z), z);
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i;
      quads.push_back({ a, a + n + 1, a + n + 2, a + 1 });
    }
  }
  return MakeMesh(points, quads);
}

/// The scene of the far-coordinates cases, with every coordinate x mapped to scale * x + offset.
void TransformedScene(CaseScene& scene, double scale, double offset)
{
  auto place = [&](vtkAlgorithm* source, double r, double g, double b)
  {
    vtkNew<vtkTransform> transform;
    transform->Translate(offset, offset, offset);
    transform->Scale(scale, scale, scale);
    vtkNew<vtkTransformPolyDataFilter> filter;
    filter->SetTransform(transform);
    filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    filter->SetInputConnection(source->GetOutputPort());
    scene.Keep.push_back(source);
    return scene.Add(filter, r, g, b);
  };
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-4, 0, -4);
  ground->SetPoint1(4, 0, -4);
  ground->SetPoint2(-4, 0, 4);
  ground->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  place(ground, 0.85, 0.85, 0.8);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-0.8, 0.9, 0);
  sphere->SetRadius(0.7);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  place(sphere, 0.9, 0.35, 0.3);
  vtkNew<vtkCubeSource> box;
  box->SetCenter(1.0, 0.6, 0.3);
  box->SetXLength(0.8);
  box->SetYLength(1.2);
  box->SetZLength(0.8);
  box->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  place(box, 0.3, 0.5, 0.9);
  auto at = [&](double x) { return scale * x + offset; };
  scene.PointLight(at(-2), at(6), at(3), 0.4 * scale);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(at(3), at(4), at(7));
  camera->SetFocalPoint(at(0), at(0.5), at(0));
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(3 * scale, 20 * scale);
}

/// A classic scene: ground, sphere and box, one area light.
void ClassicScene(CaseScene& scene, double radius = 0.4)
{
  scene.Ground();
  scene.Sphere(-0.8, 0.9, 0, 0.7, 32);
  scene.Box(1.0, 0.6, 0.3, 0.8, 1.2, 0.8);
  scene.PointLight(-2, 6, 3, radius);
  scene.Camera(3, 4, 7, 0, 0.5, 0);
}

/// A roof over the camera (group 1).
void RoofScene(CaseScene& scene, double radius)
{
  scene.Ground(8);
  scene.Box(0, 3, 0, 4, 0.2, 4);
  scene.PointLight(0.5, 10, 0.2, radius);
}

/// A sphere with some triangles walked the other way round.
vtkSmartPointer<vtkPolyData> InconsistentSphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetCenter(0, 1.1, 0);
  source->SetRadius(0.7);
  source->SetThetaResolution(24);
  source->SetPhiResolution(12);
  source->Update();
  vtkPolyData* sphere = source->GetOutput();
  std::vector<glm::dvec3> points;
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    double p[3];
    sphere->GetPoint(i, p);
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::vector<vtkIdType>> cells;
  const vtkIdType* ids;
  vtkIdType count;
  auto polys = sphere->GetPolys();
  polys->InitTraversal();
  for (int c = 0; polys->GetNextCell(count, ids); ++c)
  {
    std::vector<vtkIdType> cell(ids, ids + count);
    if (c % 3 == 0)
    {
      std::reverse(cell.begin(), cell.end());
    }
    cells.push_back(cell);
  }
  return MakeMesh(points, cells);
}

/// Metaballs contoured inside a padded grid: a closed surface with folds and creases.
vtkActor* MetaballIsosurface(CaseScene& scene)
{
  const int n = 40;
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(n, n, n);
  grid->SetOrigin(-1.5, 0.1, -1.5);
  grid->SetSpacing(3.0 / (n - 1), 2.2 / (n - 1), 3.0 / (n - 1));
  vtkNew<vtkFloatArray> field;
  field->SetNumberOfValues(static_cast<vtkIdType>(n) * n * n);
  const glm::dvec3 centres[4] = { { -0.5, 1.0, 0 }, { 0.5, 1.2, 0.2 }, { 0, 1.5, -0.5 },
    { 0.1, 0.7, 0.6 } };
  for (vtkIdType i = 0; i < field->GetNumberOfValues(); ++i)
  {
    double p[3];
    grid->GetPoint(i, p);
    double value = 0;
    for (const glm::dvec3& c : centres)
    {
      const double d2 =
        glm::dot(glm::dvec3(p[0], p[1], p[2]) - c, glm::dvec3(p[0], p[1], p[2]) - c);
      value += 0.2 / (d2 + 1e-3);
    }
    field->SetValue(i, static_cast<float>(value));
  }
  grid->GetPointData()->SetScalars(field);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(grid);
  contour->SetValue(0, 1.0);
  scene.Keep.push_back(grid.GetPointer());
  return scene.Add(contour, 0.8, 0.75, 0.35);
}

std::vector<HardCase> BuildCases()
{
  std::vector<HardCase> cases;
  auto add = [&](const std::string& name, int group, const std::string& expected,
               std::function<void(CaseScene&)> build) -> HardCase&
  {
    HardCase c;
    c.Name = name;
    c.Group = group;
    c.Expected = expected;
    c.Build = std::move(build);
    cases.push_back(c);
    return cases.back();
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  // 1. The eye in a shadow.
  add("camera_in_shadow_volume", 1,
    "the eye under a roof, inside its volume: z-fail, the ground beyond lit",
    [](CaseScene& s)
    {
      RoofScene(s, 0.5);
      s.Camera(0, 1.0, 0, 4, 0.2, 4);
      s.Renderer->GetActiveCamera()->SetClippingRange(0.05, 50);
    });
  add("camera_in_penumbra_wedge", 1,
    "the eye inside the wedge of the roof's edge: penumbra unchanged",
    [](CaseScene& s)
    {
      RoofScene(s, 0.8);
      s.Camera(2.3, 1.5, 0, 3.5, 0, 3);
      s.Renderer->GetActiveCamera()->SetClippingRange(0.05, 50);
    });
  add("near_plane_cuts_volume_and_wedge", 1,
    "the near plane straddles the shadow boundary and its penumbra",
    [](CaseScene& s)
    {
      RoofScene(s, 0.8);
      s.Camera(1.95, 0.8, 0, 1.95, 0.0, 3);
      s.Renderer->GetActiveCamera()->SetClippingRange(0.3, 50);
    });

  // 2. Lights inside bounds and close to surfaces.
  add("light_inside_caster_bounds", 2,
    "a light inside an open tube: lit disk inside, shadow outside",
    [](CaseScene& s)
    {
      s.Ground(6);
      vtkNew<vtkCylinderSource> tube;
      tube->SetCenter(0, 1.5, 0);
      tube->SetRadius(1.2);
      tube->SetHeight(1.6);
      tube->SetResolution(32);
      tube->CappingOff();
      s.Add(tube, 0.6, 0.7, 0.8);
      s.PointLight(0.2, 2.0, 0.1, 0.15);
      s.Camera(0, 7, 6, 0, 0.5, 0);
    });
  add("light_close_to_surface", 2,
    "a light 0.05 above the ground: long grazing shadow, no acne around the light",
    [](CaseScene& s)
    {
      s.Ground();
      s.Box(0.8, 0.15, 0, 0.3, 0.3, 0.3);
      s.Sphere(-0.6, 0.2, 0.5, 0.2, 32);
      s.PointLight(0, 0.05, 0, 0.02);
      s.Camera(0.5, 4, 4, 0.5, 0, 0);
    });

  // 3. Silhouette edges along light rays; faces edge-on to the light.
  add("edges_along_light_rays", 3, "a frustum whose side edges point 1 degree away from the light",
    [](CaseScene& s)
    {
      s.Ground();
      // Lateral edges 1 degree off the rays from the light at (0, 6, 0): the side faces are
      // lit at grazing incidence.
      const double b = 0.6, t = b * (6.0 - 2.0) / (6.0 - 1.0) + std::tan(3.14159265358979 / 180.0);
      std::vector<glm::dvec3> p = { { -b, 1, -b }, { b, 1, -b }, { b, 1, b }, { -b, 1, b },
        { -t, 2, -t }, { t, 2, -t }, { t, 2, t }, { -t, 2, t } };
      std::vector<std::vector<vtkIdType>> q = { { 0, 1, 2, 3 }, { 4, 7, 6, 5 }, { 0, 4, 5, 1 },
        { 1, 5, 6, 2 }, { 2, 6, 7, 3 }, { 3, 7, 4, 0 } };
      s.AddData(MakeMesh(p, q), 0.4, 0.7, 0.4);
      s.PointLight(0, 6, 0, 0.3);
      s.Camera(2, 5, 5, 0, 0.5, 0);
    });
  add("edges_parallel_directional", 3, "a directional light 2 degrees off a vertical box's edges",
    [](CaseScene& s)
    {
      s.Ground();
      s.Box(0, 1, 0, 0.6, 2, 0.6);
      const double tilt = 2.0 * 3.14159265358979 / 180.0;
      s.DirectionalLight(std::sin(tilt), std::cos(tilt), 0.5 * std::sin(tilt), 3);
      s.Camera(-1.2, 2.5, -2.2, 0, 0.3, 0);
    });
  add("light_in_face_plane", 3, "the light in the plane of a box's side face (edge-on)",
    [](CaseScene& s)
    {
      s.Ground();
      s.Box(0, 0.6, 0, 0.6, 1.2, 0.6);
      s.PointLight(0.3, 4, 2, 0.3);
      s.Camera(3, 4, 4, 0, 0.3, 0);
    });

  // 4. Vertices shared by many silhouette edges, acute corners.
  add("boxes_touching_at_corner", 4, "two welded boxes sharing one vertex",
    [](CaseScene& s)
    {
      s.Ground();
      std::vector<glm::dvec3> p;
      std::vector<std::vector<vtkIdType>> q;
      for (const glm::dvec3& lo : { glm::dvec3(-0.8, 0.5, -0.8), glm::dvec3(0, 1.3, 0) })
      {
        const vtkIdType o = static_cast<vtkIdType>(p.size());
        for (int k = 0; k < 8; ++k)
        {
          p.push_back(lo + 0.8 * glm::dvec3(k & 1, (k >> 1) & 1, (k >> 2) & 1));
        }
        for (const auto& f : std::vector<std::vector<vtkIdType>>{ { 0, 2, 3, 1 }, { 4, 5, 7, 6 },
               { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } })
        {
          q.push_back({ o + f[0], o + f[1], o + f[2], o + f[3] });
        }
      }
      // Weld the shared corner (0, 1.3, 0): index 7 of the first box and 0 of the second.
      for (auto& cell : q)
      {
        for (auto& id : cell)
        {
          id = id == 8 ? 7 : id;
        }
      }
      s.AddData(MakeMesh(p, q), 0.5, 0.6, 0.9);
      s.PointLight(-1.5, 6, 2, 0.4);
      s.Camera(3, 4.5, 6, 0, 0.8, 0);
    });
  add("saddle", 4, "an open saddle surface: silhouette through a saddle point",
    [](CaseScene& s)
    {
      s.Ground();
      auto saddle =
        HeightField(24, 1.2, [](double x, double z) { return 1.3 + 0.5 * (x * x - z * z); });
      s.AddData(saddle, 0.8, 0.6, 0.3);
      s.PointLight(-1, 6, 2, 0.4);
      s.Camera(3, 5, 5, 0, 0.8, 0);
    });
  add("bow_tie", 4, "two triangles touching at one vertex (non-manifold vertex)",
    [](CaseScene& s)
    {
      s.Ground();
      std::vector<glm::dvec3> p = { { 0, 1.2, 0 }, { -1, 1.1, -0.5 }, { -1, 1.3, 0.5 },
        { 1, 1.1, 0.5 }, { 1, 1.3, -0.5 } };
      s.AddData(MakeMesh(p, { { 0, 1, 2 }, { 0, 3, 4 } }), 0.9, 0.5, 0.3);
      s.PointLight(-0.5, 6, 1.5, 0.4);
      s.Camera(2, 5, 5, 0, 0.5, 0);
    });
  add("acute_corner", 4, "a prism with a 10 degree corner",
    [](CaseScene& s)
    {
      s.Ground();
      const double tan10 = std::tan(10.0 * 3.14159265358979 / 180.0);
      std::vector<glm::dvec3> p;
      for (double y : { 0.8, 1.2 })
      {
        p.push_back({ -1.2, y, 0 });
        p.push_back({ 1.0, y, -1.1 * tan10 });
        p.push_back({ 1.0, y, 1.1 * tan10 });
      }
      s.AddData(
        MakeMesh(p, { { 0, 2, 1 }, { 3, 4, 5 }, { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 2, 0, 3, 5 } }),
        0.4, 0.8, 0.6);
      s.PointLight(-0.5, 6, 1.5, 0.4);
      s.Camera(1, 5, 4, 0.3, 0, 0);
    });

  // 5. Open, non-manifold and non-orientable casters.
  add("open_sheet_both_sides", 5, "a tilted open sheet seen from its unlit side",
    [](CaseScene& s)
    {
      s.Ground();
      vtkNew<vtkPlaneSource> sheet;
      sheet->SetOrigin(-1, 0.8, -1);
      sheet->SetPoint1(1, 1.6, -1);
      sheet->SetPoint2(-1, 0.8, 1);
      sheet->SetResolution(3, 3);
      s.Add(sheet, 0.6, 0.6, 0.9);
      s.PointLight(-3, 5, 1, 0.4);
      s.Camera(4, 1.5, 3, 0, 0.8, 0);
    });
  add("clipped_isosurface", 5, "an isosurface clipped open by its extent (walls share outlines)",
    [](CaseScene& s)
    {
      s.Ground(6);
      vtkNew<vtkRTAnalyticSource> wavelet;
      wavelet->SetWholeExtent(-8, 8, -8, 8, -8, 8);
      vtkNew<vtkContourFilter> contour;
      contour->SetInputConnection(wavelet->GetOutputPort());
      contour->SetValue(0, 150);
      s.Keep.push_back(wavelet.GetPointer());
      vtkActor* iso = s.Add(contour, 0.8, 0.8, 0.4);
      iso->SetScale(0.1);
      iso->SetPosition(0, 1.2, 0);
      s.PointLight(-2, 6, 3, 0.4);
      s.Camera(3, 4, 7, 0, 0.6, 0);
    });
  add("mesh_with_holes", 5, "a sphere with every seventh triangle removed: light through the holes",
    [](CaseScene& s)
    {
      s.Ground();
      vtkNew<vtkSphereSource> source;
      source->SetCenter(0, 1.2, 0);
      source->SetRadius(0.8);
      source->SetThetaResolution(16);
      source->SetPhiResolution(10);
      source->Update();
      vtkNew<vtkPoints> points;
      points->DeepCopy(source->GetOutput()->GetPoints());
      vtkNew<vtkCellArray> polys;
      const vtkIdType* ids;
      vtkIdType count;
      auto in = source->GetOutput()->GetPolys();
      in->InitTraversal();
      for (int c = 0; in->GetNextCell(count, ids); ++c)
      {
        if (c % 7 != 3)
        {
          polys->InsertNextCell(count, ids);
        }
      }
      vtkNew<vtkPolyData> holed;
      holed->SetPoints(points);
      holed->SetPolys(polys);
      s.AddData(holed, 0.9, 0.4, 0.3);
      s.PointLight(-1, 6, 2, 0.3);
      s.Camera(2, 5, 5, 0, 0.5, 0);
    });
  add("non_manifold_fins", 5, "three quads sharing one edge",
    [](CaseScene& s)
    {
      s.Ground();
      std::vector<glm::dvec3> p = { { -1, 1.2, 0 }, { 1, 1.2, 0 }, { -1, 1.2, 0.8 },
        { 1, 1.2, 0.8 }, { -1, 1.8, -0.4 }, { 1, 1.8, -0.4 }, { -1, 0.7, -0.5 }, { 1, 0.7, -0.5 } };
      s.AddData(MakeMesh(p, { { 0, 1, 3, 2 }, { 0, 4, 5, 1 }, { 1, 7, 6, 0 } }), 0.7, 0.4, 0.8);
      s.PointLight(-0.5, 6, 2, 0.4);
      s.Camera(2.5, 4.5, 5, 0, 0.6, 0);
    });
  add("inconsistent_winding", 5, "a closed sphere with a third of its triangles flipped",
    [](CaseScene& s)
    {
      s.Ground();
      s.AddData(InconsistentSphere(), 0.9, 0.5, 0.2);
      s.PointLight(-1, 6, 2, 0.4);
      s.Camera(2, 4, 5, 0, 0.6, 0);
    });
  add("mobius_strip", 5, "a Mobius strip (one-sided)",
    [](CaseScene& s)
    {
      s.Ground();
      vtkNew<vtkParametricMobius> mobius;
      vtkActor* a = AddParametric(s, mobius, 48, 8, 0.3, 0.8, 0.4);
      a->SetPosition(0, 1.3, 0);
      a->RotateX(20);
      s.PointLight(-1, 6, 2, 0.4);
      s.Camera(2, 5, 5, 0, 0.6, 0);
    });
  add("klein_bottle", 5, "a self-intersecting Klein bottle",
    [](CaseScene& s)
    {
      s.Ground();
      vtkNew<vtkParametricKlein> klein;
      vtkActor* a = AddParametric(s, klein, 36, 36, 0.8, 0.7, 0.2);
      a->SetPosition(0, 1.6, 0);
      a->SetScale(0.25);
      s.PointLight(-1, 6, 2, 0.4);
      s.Camera(2, 5, 5, 0, 0.8, 0);
    });
  add("boy_surface", 5, "Boy's surface (non-orientable, closed, self-intersecting)",
    [](CaseScene& s)
    {
      s.Ground();
      vtkNew<vtkParametricBoy> boy;
      vtkActor* a = AddParametric(s, boy, 40, 40, 0.6, 0.5, 0.9);
      a->SetPosition(0, 1.5, 0);
      a->SetScale(0.8);
      s.PointLight(-1, 6, 2, 0.4);
      s.Camera(2, 5, 5, 0, 0.8, 0);
    });
  add("split_normals", 5, "a faceted sphere whose points are duplicated along feature edges",
    [](CaseScene& s)
    {
      s.Ground();
      vtkNew<vtkSphereSource> sphere;
      sphere->SetCenter(0, 1.1, 0);
      sphere->SetRadius(0.7);
      sphere->SetThetaResolution(10);
      sphere->SetPhiResolution(6);
      vtkNew<vtkPolyDataNormals> normals;
      normals->SetInputConnection(sphere->GetOutputPort());
      normals->SetFeatureAngle(10);
      normals->SplittingOn();
      s.Keep.push_back(sphere.GetPointer());
      s.Add(normals, 0.9, 0.6, 0.3);
      s.PointLight(-1, 6, 2, 0.4);
      s.Camera(2, 4, 5, 0, 0.6, 0);
    });

  // 6. Degenerate input beside a good caster.
  HardCase& degenerate = add("degenerate_input", 6,
    "warnings for empty, lines/verts-only, NaN/Inf, zero-area, duplicate, strips and polygons; the "
    "good shadows right",
    [nan, inf](CaseScene& s)
    {
      s.Ground();
      s.Sphere(-1, 1, 0, 0.5, 32);
      // One polydata with everything mixed: a box as strips and a pentagon, zero-area and
      // duplicated triangles, collinear points, lines and vertices.
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      const double p[][3] = { { 0.6, 0.6, -0.4 }, { 1.4, 0.6, -0.4 }, { 0.6, 1.4, -0.4 },
        { 1.4, 1.4, -0.4 }, { 0.6, 0.6, 0.4 }, { 1.4, 0.6, 0.4 }, { 0.6, 1.4, 0.4 },
        { 1.4, 1.4, 0.4 }, { 1.0, 1.4, 0.4 }, { 1.0, 1.8, 0.0 } };
      for (const auto& q : p)
      {
        points->InsertNextPoint(q);
      }
      vtkNew<vtkCellArray> strips, polys, lines, verts;
      const vtkIdType s1[] = { 4, 5, 6, 7 }, s2[] = { 1, 0, 3, 2 },
                      s3[] = { 0, 4, 2, 6, 3, 7, 1, 5, 0, 4 };
      strips->InsertNextCell(4, s1);
      strips->InsertNextCell(4, s2);
      strips->InsertNextCell(10, s3);
      const vtkIdType pentagon[] = { 2, 6, 8, 7, 3 }, cap[] = { 2, 3, 9 }, flat[] = { 6, 8, 7 },
                      zero[] = { 0, 0, 1 }, dup[] = { 2, 3, 9 };
      polys->InsertNextCell(5, pentagon);
      polys->InsertNextCell(3, cap);
      polys->InsertNextCell(3, flat);
      polys->InsertNextCell(3, zero);
      polys->InsertNextCell(3, dup);
      const vtkIdType line[] = { 0, 9 }, vert[] = { 9 };
      lines->InsertNextCell(2, line);
      verts->InsertNextCell(1, vert);
      vtkNew<vtkPolyData> mixed;
      mixed->SetPoints(points);
      mixed->SetStrips(strips);
      mixed->SetPolys(polys);
      mixed->SetLines(lines);
      mixed->SetVerts(verts);
      s.AddData(mixed, 0.3, 0.6, 0.9);

      vtkNew<vtkPolyData> empty;
      s.AddData(empty, 1, 1, 1);
      vtkNew<vtkPoints> bad;
      bad->InsertNextPoint(2, 0.5, 1);
      bad->InsertNextPoint(2.5, 1.5, 1);
      bad->InsertNextPoint(nan, 1, 1);
      bad->InsertNextPoint(3, 0.5, inf);
      bad->InsertNextPoint(2.2, 1.0, 1.2);
      vtkNew<vtkCellArray> badPolys, badLines;
      const vtkIdType t1[] = { 0, 2, 1 }, t2[] = { 0, 1, 3 }, l1[] = { 0, 4 };
      badPolys->InsertNextCell(3, t1);
      badPolys->InsertNextCell(3, t2);
      badLines->InsertNextCell(2, l1);
      vtkNew<vtkPolyData> nonFinite, linesOnly;
      nonFinite->SetPoints(bad);
      nonFinite->SetPolys(badPolys);
      linesOnly->SetPoints(bad);
      linesOnly->SetLines(badLines);
      s.AddData(nonFinite, 0.9, 0.9, 0.2);
      s.AddData(linesOnly, 0.9, 0.9, 0.2);
      s.PointLight(-1.5, 6, 2, 0.4);
      s.Camera(3, 4, 6, 0.3, 0.6, 0);
    });
  degenerate.ExpectWarnings = true;

  // 7. Far from the origin: the same scene at 1e6, 1e7, and scaled by 1e-6 and 1e6.
  add("origin", 7, "the reference of the far-coordinate cases",
    [](CaseScene& s) { TransformedScene(s, 1.0, 0.0); });
  for (const auto& variant : std::vector<std::pair<std::string, std::pair<double, double>>>{
         { "offset_1e6", { 1.0, 1e6 } }, { "offset_1e7", { 1.0, 1e7 } },
         { "scaled_1e-6", { 1e-6, 0.0 } }, { "scaled_1e6", { 1e6, 0.0 } } })
  {
    const double scale = variant.second.first, offset = variant.second.second;
    HardCase& c = add(variant.first, 7, "the same image as at the origin",
      [scale, offset](CaseScene& s) { TransformedScene(s, scale, offset); });
    c.Reference = "origin";
  }

  // 8. Actor matrices.
  add("non_uniform_scale", 8, "a sphere scaled (2, 0.5, 1) by its actor",
    [](CaseScene& s)
    {
      s.Ground();
      vtkActor* a = s.Sphere(0, 0, 0, 0.6, 32);
      a->SetScale(2, 0.5, 1);
      a->SetPosition(0, 1.2, 0);
      a->RotateY(30);
      s.PointLight(-1, 6, 2, 0.4);
      s.Camera(2, 5, 5, 0, 0.5, 0);
    });
  add("negative_scale", 8, "mirrored actors (scale -1 on one axis, and on all three)",
    [](CaseScene& s)
    {
      s.Ground();
      vtkNew<vtkConeSource> cone;
      cone->SetResolution(16);
      cone->SetHeight(1.2);
      cone->SetRadius(0.4);
      cone->SetDirection(1, 0.3, 0);
      vtkActor* mirrored = s.Add(cone, 0.9, 0.6, 0.2);
      mirrored->SetScale(-1, 1, 1);
      mirrored->SetPosition(-0.8, 1.0, 0);
      vtkActor* inverted = s.Box(0, 0, 0, 0.6, 0.9, 0.4);
      inverted->SetScale(-1, -1, -1);
      inverted->SetPosition(0.9, 0.9, 0.2);
      inverted->RotateY(25);
      s.PointLight(-1.5, 6, 2, 0.4);
      s.Camera(2, 5, 5, 0, 0.5, 0);
    });

  // 9. Light sizes and grazing incidence.
  add("light_larger_than_caster", 9, "a light of radius 1.5 over a sphere of radius 0.3: no umbra",
    [](CaseScene& s)
    {
      s.Ground();
      s.Sphere(0, 1.0, 0, 0.3, 32);
      s.PointLight(0, 4, 0, 1.5);
      s.Camera(2, 4, 4, 0, 0.3, 0);
    });
  add("tiny_light", 9, "radius 1e-4: the hard shadow", [](CaseScene& s) { ClassicScene(s, 1e-4); });
  add("grazing_directional", 9, "a directional light 4 degrees above the ground, 1 degree wide",
    [](CaseScene& s)
    {
      s.Ground(8);
      s.Box(-2, 0.3, 0, 0.4, 0.6, 0.4);
      s.Sphere(-1, 0.3, 1, 0.3, 32);
      s.DirectionalLight(-1, std::tan(4.0 * 3.14159265358979 / 180.0), 0.2, 1.0);
      s.Camera(2, 4, 6, 1, 0, 0);
    });

  // 10. Contact and self-shadowing.
  add("casters_touching_receiver", 10,
    "a box resting on the ground and a sphere touching it: no leak at the contact",
    [](CaseScene& s)
    {
      s.Ground();
      s.Box(0.6, 0.5, 0, 1.0, 1.0, 1.0);
      s.Sphere(-0.9, 0.6, 0.3, 0.6, 32);
      s.PointLight(-2, 5, 2.5, 0.3);
      s.Camera(3, 3, 5, 0, 0.3, 0);
    });
  add("torus_self_shadow", 10, "a tilted torus shadowing itself",
    [](CaseScene& s)
    {
      s.Ground();
      vtkNew<vtkParametricTorus> torus;
      torus->SetRingRadius(0.8);
      torus->SetCrossSectionRadius(0.3);
      vtkActor* a = AddParametric(s, torus, 48, 24, 0.8, 0.6, 0.3);
      a->SetPosition(0, 1.1, 0);
      a->RotateX(60);
      s.PointLight(-1, 5, 1, 0.4);
      s.Camera(1.5, 4, 4, 0, 0.8, 0);
    });
  add("crumpled_sheet", 10, "an open sheet with random folds shadowing itself",
    [](CaseScene& s)
    {
      s.Ground();
      std::mt19937 random(7);
      std::uniform_real_distribution<double> jitter(-0.25, 0.25);
      std::vector<double> bumps(64);
      for (double& b : bumps)
      {
        b = jitter(random);
      }
      auto sheet = HeightField(32, 1.5,
        [&](double x, double z)
        {
          double h = 1.2;
          for (int k = 0; k < 8; ++k)
          {
            h += bumps[8 * k] * std::sin((1 + k) * x + bumps[8 * k + 1] * 10) *
              std::cos((1 + k / 2) * z + bumps[8 * k + 2] * 10);
          }
          return h;
        });
      s.AddData(sheet, 0.7, 0.7, 0.9);
      s.PointLight(-2, 5, 1, 0.4);
      s.Camera(2, 5, 5, 0, 0.8, 0);
    });
  add("isosurface_folds", 10, "closed metaballs with creases and folds",
    [](CaseScene& s)
    {
      s.Ground();
      MetaballIsosurface(s);
      s.PointLight(-2, 6, 1, 0.4);
      s.Camera(2.5, 4, 4.5, 0, 0.8, 0);
    });

  // 11. Overlaps.
  add("overlapping_casters", 11, "three casters whose shadows overlap",
    [](CaseScene& s)
    {
      s.Ground();
      s.Sphere(-0.4, 1.6, 0, 0.45, 32);
      s.Sphere(0.3, 1.0, 0.2, 0.4, 32);
      s.Box(0.1, 2.2, -0.3, 0.8, 0.15, 0.8);
      s.PointLight(-0.5, 6, 0.5, 0.5);
      s.Camera(2.5, 4.5, 5, 0, 0.5, 0);
    });
  add("two_lights", 11, "two area lights over the same casters",
    [](CaseScene& s)
    {
      ClassicScene(s, 0.4);
      s.PointLight(3, 5, 1, 0.3);
    });
  add("coloured_lights", 11, "red, green and blue lights: coloured shadows",
    [](CaseScene& s)
    {
      ClassicScene(s, 0.3);
      s.PointLight(2, 5, -2, 0.3);
      s.PointLight(0, 6, 4, 0.3);
      auto lights = s.Renderer->GetLights();
      const double colours[3][3] = { { 1, 0.2, 0.2 }, { 0.2, 1, 0.2 }, { 0.3, 0.3, 1 } };
      lights->InitTraversal();
      for (int i = 0; i < 3; ++i)
      {
        lights->GetNextItem()->SetColor(colours[i][0], colours[i][1], colours[i][2]);
      }
    });

  // 12. Window situations.
  HardCase& nonSquare = add(
    "non_square_window", 12, "a wide window (240 x 100)", [](CaseScene& s) { ClassicScene(s); });
  nonSquare.Width = 240;
  nonSquare.Height = 100;
  HardCase& resized =
    add("resized_window", 12, "resized between frames", [](CaseScene& s) { ClassicScene(s); });
  resized.Frames = 2;
  resized.Frame = [](CaseScene& s, int frame)
  {
    if (frame == 1)
    {
      s.Window->SetSize(260, 170);
    }
  };
  add("two_viewports", 12, "two viewports, their own cameras and lights",
    [](CaseScene& s)
    {
      s.Renderer->SetViewport(0, 0, 0.5, 1);
      ClassicScene(s);
      vtkRenderer* right = s.AddRenderer(0.5, 0, 1, 1);
      s.Add(s.Renderer->GetActors()->GetLastActor()->GetMapper()->GetInputAlgorithm(), 0.3, 0.8,
        0.5, right);
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(-3, 0, -3);
      plane->SetPoint1(3, 0, -3);
      plane->SetPoint2(-3, 0, 3);
      s.Add(plane, 0.8, 0.8, 0.8, right);
      s.PointLight(2, 5, 2, 0.5, right);
      s.Camera(-2, 3, 4, 0.5, 0.4, 0, right);
    });
  add("onscreen_window", 12, "an on-screen window (Xvfb) instead of off-screen",
    [](CaseScene& s)
    {
      s.Window->SetOffScreenRendering(0);
      ClassicScene(s);
    });
  add("multisampling", 12, "an 8-sample multisampled window",
    [](CaseScene& s)
    {
      s.Window->SetMultiSamples(8);
      ClassicScene(s);
    });
  add("large_image_tiles", 12, "vtkRenderLargeImage, 2 x 2 tiles: the same image as one frame",
    [](CaseScene& s) { ClassicScene(s); })
    .LargeImageTiles = true;

  // 13. Everything else VTK draws.
  add("translucent_volume_overlay", 13,
    "a translucent sphere, a volume and a text overlay drawn as VTK draws them; a non-caster and a "
    "non-receiver",
    [](CaseScene& s)
    {
      ClassicScene(s);
      vtkActor* glass = s.Sphere(1.6, 1.2, -1.2, 0.5, 32);
      glass->GetProperty()->SetOpacity(0.4);
      vtkActor* ghost = s.Box(-1.5, 0.5, 1.5, 0.6, 1.0, 0.6);
      vtkSoftShadowPass::SetCastsShadows(ghost, false);
      vtkActor* proud = s.Box(0.2, 0.2, 1.6, 0.5, 0.4, 0.5);
      vtkSoftShadowPass::SetReceivesShadows(proud, false);

      vtkNew<vtkImageData> image;
      image->SetDimensions(16, 16, 16);
      image->SetOrigin(-3.0, 0.1, -1.2);
      image->SetSpacing(0.08, 0.08, 0.08);
      image->AllocateScalars(VTK_FLOAT, 1);
      auto values = static_cast<float*>(image->GetScalarPointer());
      for (int k = 0, i = 0; k < 16; ++k)
        for (int j = 0; j < 16; ++j)
          for (int l = 0; l < 16; ++l, ++i)
            values[i] = static_cast<float>(
              std::sqrt((l - 7.5) * (l - 7.5) + (j - 7.5) * (j - 7.5) + (k - 7.5) * (k - 7.5)));
      vtkNew<vtkSmartVolumeMapper> volumeMapper;
      volumeMapper->SetInputData(image);
      vtkNew<vtkPiecewiseFunction> opacity;
      opacity->AddPoint(0, 0.8);
      opacity->AddPoint(8, 0.0);
      vtkNew<vtkColorTransferFunction> colour;
      colour->AddRGBPoint(0, 1, 0.8, 0.2);
      colour->AddRGBPoint(8, 0.2, 0.3, 1);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(volumeMapper);
      volume->GetProperty()->SetScalarOpacity(opacity);
      volume->GetProperty()->SetColor(colour);
      volume->GetProperty()->SetScalarOpacityUnitDistance(0.05);
      s.Renderer->AddVolume(volume);
      vtkNew<vtkTextActor> text;
      text->SetInput("overlay");
      text->GetTextProperty()->SetFontSize(14);
      text->SetPosition(4, 4);
      s.Renderer->AddActor2D(text);
      s.Keep.push_back(image.GetPointer());
    });

  // 14. Temporal stability.
  HardCase& sweep = add("light_through_face_planes", 14,
    "a light stepping through the planes of two box faces: changes follow the truth's",
    [](CaseScene& s)
    {
      s.Ground();
      s.Box(0, 0.6, 0, 0.6, 1.2, 0.6);
      s.PointLight(0.3, 4, 0.3, 0.3);
      s.Camera(2, 4, 4, 0, 0.3, 0);
    });
  sweep.Frames = 9;
  sweep.Temporal = true;
  sweep.Frame = [](CaseScene& s, int frame)
  {
    const double x = 0.35 - 0.0125 * frame; // crosses x = z = 0.3 at frame 4
    vtkLight* light = vtkLight::SafeDownCast(s.Renderer->GetLights()->GetItemAsObject(0));
    light->SetPosition(x, 4, x);
  };
  HardCase& orbit =
    add("light_orbit_small_steps", 14, "a light orbiting in 1 degree steps over a torus and a box",
      [](CaseScene& s)
      {
        s.Ground();
        vtkNew<vtkParametricTorus> torus;
        torus->SetRingRadius(0.6);
        torus->SetCrossSectionRadius(0.25);
        vtkActor* a = AddParametric(s, torus, 32, 16, 0.8, 0.6, 0.3);
        a->SetPosition(-0.6, 1.0, 0);
        a->RotateX(70);
        s.Box(1.0, 0.5, 0.3, 0.6, 1.0, 0.6);
        s.PointLight(2, 5, 0, 0.4);
        s.Camera(2, 5, 5, 0, 0.5, 0);
      });
  orbit.Frames = 6;
  orbit.Temporal = true;
  orbit.Frame = [](CaseScene& s, int frame)
  {
    const double angle = (30.0 + frame) * 3.14159265358979 / 180.0;
    vtkLight* light = vtkLight::SafeDownCast(s.Renderer->GetLights()->GetItemAsObject(0));
    light->SetPosition(3 * std::cos(angle), 5, 3 * std::sin(angle));
  };

  // Known limitations, measured; Documentation/robustness.md explains each. MAE -1 keeps the
  // default limit.
  const std::string layered = "forced wedges count outlines that layers of an open or "
                              "self-intersecting caster share (silhouette edges of multiplicity "
                              "> 1) twice; Automatic's soft shadow volumes count each light sample "
                              "exactly here instead";
  const std::string speck = "single-pixel numerical specks that move or vanish when the camera "
                            "moves by 0.001 to 0.01 (--camera-offset)";
  const std::string faces = "wedges use one silhouette, from the light's centre; while the light "
                            "is near the planes of the side faces, the penumbra around the base is "
                            "too wide (Documentation/wedges.md)";
  auto known = [&](const std::string& name, const Allowance& allowance)
  {
    for (HardCase& c : cases)
    {
      if (c.Name == name)
      {
        c.Known.push_back(allowance);
      }
    }
  };
  // What Automatic is allowed, the methods it may pick that count are allowed too.
  auto knownWhenCounted = [&](const std::string& name, Allowance allowance)
  {
    for (const int method : { AUTOMATIC, COUNTED, HALF_RESOLUTION })
    {
      allowance.Method = method;
      known(name, allowance);
    }
  };
  known("saddle", { HARD, 1, -1, 0, speck });
  // Averaging draws a hard volume per sample: since the depth range takes only what is in view
  // (2026-12-06), one of the saddle's sixteen shows the speck.
  known("saddle", { AVERAGED, 1, -1, 0, speck });
  // Soft shadow volumes start from the centre's hard volume and inherit its speck.
  knownWhenCounted("saddle", { AUTOMATIC, 1, -1, 0, speck });
  knownWhenCounted("klein_bottle",
    { AUTOMATIC, 1, -1, 0,
      "one pixel where soft shadow volumes and averaging disagree by more than 0.5; not yet "
      "explained (Documentation/wedges.md)" });
  known("crumpled_sheet", { HARD, 1, -1, 0, speck });
  known("crumpled_sheet", { WEDGES, 2, -1, 0, speck });
  known("clipped_isosurface", { WEDGES, 1, 0.07, 0, layered });
  known("mesh_with_holes", { WEDGES, 1, 0.07, 0, layered });
  known("inconsistent_winding", { WEDGES, 0, 0.09, 0, layered });
  known("mobius_strip", { WEDGES, 76, 0.05, 0, layered });
  known("klein_bottle", { WEDGES, 0, 0.21, 0, layered });
  known("boy_surface", { WEDGES, 0, 0.11, 0, layered });
  known("degenerate_input", { WEDGES, 9, 0.08, 0, layered + " (the duplicated triangle)" });
  known("light_through_face_planes", { WEDGES, 0, 0.05, 0.006, faces });
  known("translucent_volume_overlay",
    { WEDGES, 300, 0.13, 0,
      "penumbra wedges leave translucent casters out, with one warning; the truth and the other "
      "methods shadow by their opacity" });
  knownWhenCounted("light_through_face_planes", { AUTOMATIC, 0, 0.05, 0.006, faces });
  return cases;
}

} // namespace

const std::vector<HardCase>& AllCases()
{
  static const std::vector<HardCase> cases = BuildCases();
  return cases;
}

} // namespace penumbra_hard
