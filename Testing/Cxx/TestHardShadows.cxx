// Hard shadows of vtkSoftShadowPass against an independent ray tracer (vtkRayTracedVisibility,
// Embree): the classic scene, the camera inside a shadow, z-fail for visible casters, open,
// non-manifold and non-orientable meshes, a light inside a closed caster, a shadow running off
// the ground over the background, a camera with an explicit projection matrix. Tolerance: see
// penumbraTestHarness.h.
#include "penumbraTestHarness.h"

#include "vtkCamera.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataSetMapper.h"
#include "vtkGlyph3DMapper.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkParametricFunctionSource.h"
#include "vtkParametricKlein.h"
#include "vtkParametricMobius.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

using namespace penumbra_test;

namespace
{

using Scene = PassScene;

/// A sphere and a box on the ground, seen from above and in front.
void AddClassicScene(Scene& scene)
{
  scene.Ground();
  scene.Sphere(-0.8, 0.9, 0, 0.7);
  scene.Box(1.0, 0.6, 0.3, 0.8, 1.2, 0.8);
  scene.Camera(3, 4, 7, 0, 0.5, 0);
}

void TestClassic()
{
  Scene scene;
  AddClassicScene(scene);
  CheckAgainstTruth("classic scene, point light", scene.Render());
  Check(scene.Pass->GetNumberOfShadowingLights() == 1, "classic: one shadowing light");
  Check(scene.Pass->GetNumberOfZFailVolumes() == 0, "classic: eye outside all volumes, z-pass");

  // A directional light from the same side.
  scene.Light->SetPositional(false);
  scene.Light->SetPosition(-1, 3, 1.5);
  CheckAgainstTruth("classic scene, directional light", scene.Render());
}

/// A camera with an explicit projection matrix, which VTK 9.1's vtkCamera::DeepCopy drops: the
/// shadows follow it, and a change made to it in place once the camera is marked modified.
void TestExplicitProjection()
{
  Scene scene;
  AddClassicScene(scene);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  vtkNew<vtkMatrix4x4> projection;
  projection->DeepCopy(
    camera->GetProjectionTransformMatrix(scene.Renderer->GetTiledAspectRatio(), -1, 1));
  projection->SetElement(0, 0, 1.6 * projection->GetElement(0, 0));
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->UseExplicitProjectionTransformMatrixOn();
  CheckAgainstTruth("an explicit projection", scene.Render());
  projection->SetElement(1, 1, 0.7 * projection->GetElement(1, 1));
  camera->Modified();
  CheckAgainstTruth("the explicit projection changed in place", scene.Render());
}

void TestCameraInsideShadow()
{
  // A roof over the camera: the eye is inside the roof's shadow volume (z-fail), looking out at
  // ground that is partly lit beyond the roof's shadow.
  Scene scene;
  scene.Ground(8);
  scene.Box(0, 3, 0, 4, 0.2, 4);
  scene.Light->SetPosition(0.5, 10, 0.2);
  scene.Camera(0, 1.0, 0, 4, 0.2, 4);
  scene.Renderer->GetActiveCamera()->SetClippingRange(0.05, 50);
  CheckAgainstTruth("camera inside a shadow volume", scene.Render(), 0.05);
  Check(scene.Pass->GetNumberOfZFailVolumes() >= 1, "camera inside: z-fail used");

  // Near plane straddling the roof's shadow boundary, looking across it.
  scene.Camera(1.95, 0.8, 0, 1.95, 0.0, 3);
  scene.Renderer->GetActiveCamera()->SetClippingRange(0.3, 50);
  CheckAgainstTruth("near plane cutting a shadow volume", scene.Render(), 0.05);
  Check(scene.Pass->GetNumberOfZFailVolumes() >= 1, "near plane cut: z-fail used");
}

void TestVisibleCastersOnZFail()
{
  // A low camera under a roof: the ground (itself a caster) and the roof take the z-fail path, so
  // their light caps lie on visible surfaces; those must stay lit, not z-fight.
  Scene scene;
  scene.Ground(5);
  vtkNew<vtkPlaneSource> roof;
  roof->SetOrigin(-1, 3.5, 1.5);
  roof->SetPoint1(3, 3.5, 1.5);
  roof->SetPoint2(-1, 3.5, 6);
  scene.Add(roof, 0.7, 0.7, 0.75);
  scene.Sphere(0, 1.2, 0, 0.8);
  scene.Light->SetPosition(0.5, 8, 2.5);
  scene.Camera(0.8, 1.0, 3.5, 0, 0.8, 0);
  scene.Renderer->GetActiveCamera()->SetClippingRange(0.1, 30);
  CheckAgainstTruth("visible casters on the z-fail path", scene.Render());
  Check(scene.Pass->GetNumberOfZFailVolumes() >= 2, "ground and roof use z-fail");
}

void TestAwkwardMeshes()
{
  // Open, non-orientable, inconsistently wound and mirrored casters over a ground plane.
  Scene scene(240, 180);
  scene.Ground(6);
  vtkNew<vtkParametricMobius> mobius;
  vtkNew<vtkParametricFunctionSource> mobiusSource;
  mobiusSource->SetParametricFunction(mobius);
  mobiusSource->SetUResolution(40);
  mobiusSource->SetVResolution(10);
  vtkActor* strip = scene.Add(mobiusSource, 0.3, 0.8, 0.4);
  strip->SetPosition(-1.8, 1.5, 0);
  strip->SetScale(0.8);

  vtkNew<vtkParametricKlein> klein;
  vtkNew<vtkParametricFunctionSource> kleinSource;
  kleinSource->SetParametricFunction(klein);
  kleinSource->SetUResolution(30);
  kleinSource->SetVResolution(30);
  vtkActor* bottle = scene.Add(kleinSource, 0.8, 0.7, 0.2);
  bottle->SetPosition(1.5, 1.8, -0.5);
  bottle->SetScale(0.25);

  // An open sheet tilted towards the light, and a mirrored (negative-scale) sphere.
  vtkNew<vtkPlaneSource> sheet;
  sheet->SetResolution(3, 3);
  vtkActor* sheetActor = scene.Add(sheet, 0.6, 0.6, 0.9);
  sheetActor->SetPosition(0.2, 1.2, 1.8);
  sheetActor->RotateX(60);
  vtkActor* mirrored = scene.Sphere(0, 0, 0, 0.4);
  mirrored->SetPosition(-0.3, 0.8, -1.5);
  mirrored->SetScale(-1.0, 1.3, 1.0);

  scene.Camera(2, 6, 8, 0, 0.5, 0);
  CheckAgainstTruth("open, non-orientable and mirrored casters", scene.Render());
}

void TestLightInsideClosedCaster()
{
  // A bulb sphere that casts, around its own light: nothing outside it sees the light.
  Scene scene;
  scene.Ground();
  scene.Sphere(0, 1, 0, 0.6);
  scene.Sphere(-2, 6, 3, 0.3);
  scene.Camera(3, 4, 7, 0, 0.5, 0);
  const Comparison c = scene.Render();
  CheckAgainstTruth("light inside a closed caster", c, 0.9);
}

void TestBackgroundStaysLit()
{
  // A small ground under a sphere lit from low at the side: the sphere's volume runs off the
  // ground across the background, where the visibility image must read 1 (hard shadows add
  // their count straight into the light's layer).
  Scene scene;
  scene.Ground(1.5);
  scene.Sphere(0, 1, 0, 0.6);
  scene.Light->SetPosition(-6, 2.5, 1);
  scene.Camera(3, 4, 7, 0, 0.5, 0);
  CheckAgainstTruth("a shadow running off the ground", scene.Render());
  const std::vector<float> visibility = ImageValues(scene.Pass->GetVisibilityImage(0));
  const std::vector<float> depth = WindowDepth(scene.Window, scene.Renderer);
  std::size_t background = 0, dark = 0;
  for (std::size_t p = 0; p < depth.size() && p < visibility.size(); ++p)
  {
    if (depth[p] >= 1.0f)
    {
      ++background;
      dark += visibility[p] != 1.0f ? 1 : 0;
    }
  }
  std::printf("    background pixels: %zu, not 1 in the visibility image: %zu\n", background, dark);
  Check(background > 0 && dark == 0, "the background stays lit in the visibility image");
}

/// Renders `scene` with the casters' depth from their meshes, then drawn by VTK: both must agree
/// with the truth and with each other; `fromMeshes` props take the mesh depth, `culled` of them
/// with their hidden faces culled.
void CompareDepthSources(Scene& scene, const std::string& what, int fromMeshes, int culled)
{
  scene.Pass->DepthFromCasterMeshesOn();
  CheckAgainstTruth(what + ", depth from the caster meshes", scene.Render());
  Check(scene.Pass->GetNumberOfPropsWithDepthFromMeshes() == fromMeshes,
    what + ": the plain spheres' depth comes from their meshes, the other props' from VTK");
  Check(scene.Pass->GetNumberOfPropsWithCulledDepth() == culled,
    what + ": the spheres seen from outside only are drawn with their hidden faces culled");
  const std::vector<float> meshes = ImageValues(scene.Pass->GetVisibilityImage(0));

  scene.Pass->DepthFromCasterMeshesOff();
  CheckAgainstTruth(what + ", depth drawn by VTK", scene.Render());
  Check(
    scene.Pass->GetNumberOfPropsWithDepthFromMeshes() == 0, what + ": off, VTK draws every depth");
  const std::vector<float> vtk = ImageValues(scene.Pass->GetVisibilityImage(0));

  // The same triangles through another vertex shader: at most a pixel's rounding on a terminator.
  const std::size_t differing = static_cast<std::size_t>(PixelsApart(meshes, vtk));
  std::printf("    %s: pixels whose visibility differs by more than 0.5: %zu of %zu\n",
    what.c_str(), differing, vtk.size());
  Check(!vtk.empty() && differing <= vtk.size() / 1000,
    what + ": the depth from the meshes shadows as VTK's depth does (at most 0.1% of pixels)");
}

void TestDepthFromCasterMeshes()
{
  // Spheres (triangles, plain actors and a composite mapper's block: their depth comes from
  // their caster meshes, closed and seen from outside, so with their hidden faces culled), one
  // placed by a position, orientation, mirroring scale and user matrix; the ground and a box
  // (convex quads, cut as VTK's fan: their depth comes from their meshes too, the box's with its
  // hidden faces culled); a sphere with its edges shown (from its mesh too: VTK's widened
  // triangles are not its surface) and one that casts no shadow (VTK draws it). The depth, and
  // so the shadows, must be the same as VTK's.
  Scene scene(320, 240);
  scene.Ground();
  scene.Sphere(-1.2, 0.9, 0.4, 0.6);
  // A small sphere between the light and the first, shadowing its lit side: were the first's
  // depth its far side (the wrong faces culled), that shadow would move.
  scene.Sphere(-1.48, 2.69, 1.31, 0.2, 24);
  vtkActor* placed = scene.Sphere(0, 0, 0, 0.5, 24);
  placed->SetPosition(0.4, 1.6, -0.6);
  placed->SetOrientation(20, 35, 10);
  placed->SetScale(-1.4, 0.8, 1.0); // mirrored: its front faces turn
  vtkNew<vtkTransform> user;
  user->Translate(0.2, 0.0, 0.3);
  user->RotateY(15);
  placed->SetUserTransform(user);
  scene.Box(1.4, 0.5, 0.6, 0.7, 1.0, 0.7);
  scene.Sphere(-0.3, 0.4, 1.6, 0.4)->GetProperty()->EdgeVisibilityOn();
  vtkSoftShadowPass::SetCastsShadows(scene.Sphere(1.0, 0.3, -1.4, 0.3), false);
  // Composite data: a sphere block drawn, nested one level down, an empty block and a sphere
  // block hidden, whose depth VTK does not draw either.
  vtkNew<vtkMultiBlockDataSet> blocks;
  vtkNew<vtkMultiBlockDataSet> nested;
  vtkSmartPointer<vtkSphereSource> drawn = SphereSource(-1.7, 0.35, -1.3, 0.35, 32, 16);
  vtkSmartPointer<vtkSphereSource> hidden = SphereSource(0, 0.5, 2.4, 0.4, 32, 16);
  drawn->Update();
  hidden->Update();
  nested->SetBlock(0, drawn->GetOutput());
  blocks->SetBlock(0, nested);
  blocks->SetBlock(1, nullptr);
  blocks->SetBlock(2, hidden->GetOutput());
  vtkNew<vtkCompositePolyDataMapper2> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  attributes->SetBlockVisibility(blocks->GetBlock(2), false);
  compositeMapper->SetCompositeDataDisplayAttributes(attributes);
  vtkNew<vtkActor> composite;
  composite->SetMapper(compositeMapper);
  scene.Renderer->AddActor(composite);
  scene.Camera(3, 4, 7, 0, 0.5, 0);

  CompareDepthSources(scene, "spheres seen from outside", 7, 6);
  scene.Pass->DepthFromCasterMeshesOn();

  // The camera inside a closed caster (a sphere around the scene, the light inside it too): its
  // box holds the eye, so none of its faces may be culled, or the walls would lose their depth.
  // (The visibility does not show it in this view: with the walls culled, as many pixels
  // differed from VTK's depth as without, 23, the shadows in view lying on the small sphere.
  // The culled-props count does.)
  Scene room(320, 240);
  room.Sphere(0, 0, 0, 8, 60);
  room.Sphere(0, 1, 0, 0.8);
  room.Light->SetPosition(-2, 5, 1);
  room.Camera(3, 2, 3, 0, 1, 0);
  CompareDepthSources(room, "the camera inside a closed caster", 2, 1);
}

/// Of the pixels where something is drawn, a pixel in from the background, the share where the
/// light's visibility is below one half.
double ShadowedShareOfDrawnPixels(Scene& scene)
{
  const std::vector<float> depth = WindowDepth(scene.Window, scene.Renderer);
  const std::vector<float> visibility = ImageValues(scene.Pass->GetVisibilityImage(0));
  const int* size = scene.Window->GetSize();
  const int width = size[0], height = size[1];
  std::size_t drawn = 0, shadowed = 0;
  for (int y = 1; y + 1 < height; ++y)
  {
    for (int x = 1; x + 1 < width; ++x)
    {
      const std::size_t p = static_cast<std::size_t>(y) * width + x;
      if (depth[p] < 1.0f && depth[p - 1] < 1.0f && depth[p + 1] < 1.0f &&
        depth[p - width] < 1.0f && depth[p + width] < 1.0f)
      {
        ++drawn;
        shadowed += visibility[p] < 0.5f ? 1 : 0;
      }
    }
  }
  return drawn > 100 && visibility.size() == depth.size() ? double(shadowed) / drawn : 0.0;
}

/// Face culling hides faces from the eye, not from the light. Seen through its culled front
/// faces, the inside of a closed sphere lit from outside lies in the sphere's own shadow; seen
/// from above through a ground whose culled back faces are its upper side (GroundSource's normal
/// points down), a box under the ground lies in the ground's shadow. Each is all that is drawn.
/// z-pass counting relies on a caster's lit faces hiding what lies behind them, and left 77% of
/// the sphere's inside and 97% of the box lit, with every method.
void TestFaceCulledCasters()
{
  const std::vector<std::pair<std::string, std::function<void(vtkSoftShadowPass*)>>> methods = {
    { "hard", [](vtkSoftShadowPass* pass) { pass->SetMethodToHardVolumes(); } },
    { "averaged", [](vtkSoftShadowPass* pass) { pass->SetMethodToAveragedHardShadows(); } },
    { "counted", [](vtkSoftShadowPass* pass) { pass->SetMethodToSoftShadowVolumes(); } },
  };
  for (const auto& method : methods)
  {
    Scene sphere(320, 240);
    sphere.Sphere(0, 1, 0, 0.8)->GetProperty()->FrontfaceCullingOn();
    sphere.Camera(3, 4, 7, 0, 1, 0);
    Scene box(320, 240);
    box.Ground(5.0)->GetProperty()->BackfaceCullingOn();
    box.Box(0, -1, 0, 2, 0.5, 2);
    box.Camera(2, 5, 6, 0, -1, 0);
    for (Scene* scene : { &sphere, &box })
    {
      vtkSoftShadowPass::SetLightRadius(scene->Light, method.first == "hard" ? 0.0 : 0.3);
      method.second(scene->Pass);
      scene->Window->Render();
    }
    const double inside = ShadowedShareOfDrawnPixels(sphere);
    const double under = ShadowedShareOfDrawnPixels(box);
    std::printf("    %s: shadowed inside the front-culled sphere %.1f%%, on the box under the "
                "back-culled ground %.1f%%\n",
      method.first.c_str(), 100.0 * inside, 100.0 * under);
    Check(inside >= 0.99, method.first + ": the inside of a front-culled sphere is in its shadow");
    Check(under >= 0.99, method.first + ": a box seen through a culled ground is in its shadow");
    if (method.first == "hard")
    {
      // Back faces of a closed mesh seen from outside are hidden behind its own: culling them
      // shows nothing through, and its volume stays z-pass.
      Scene closed(320, 240);
      closed.Ground();
      closed.Sphere(0, 1, 0, 0.8)->GetProperty()->BackfaceCullingOn();
      closed.Camera(3, 4, 7, 0, 1, 0);
      CheckAgainstTruth("a back-culled closed sphere", closed.Render());
      Check(closed.Pass->GetNumberOfZFailVolumes() == 0,
        "a back-culled closed sphere seen from outside keeps z-pass");
      // The truth's eye rays pass culled faces too, its shadow rays do not.
      CheckAgainstTruth("the inside of a front-culled sphere",
        CompareWithTruth(sphere.Window, sphere.Renderer, sphere.Pass, 0), 0.9);
      CheckAgainstTruth("a box under a back-culled ground",
        CompareWithTruth(box.Window, box.Renderer, box.Pass, 0), 0.9);
    }
  }
}

/// The eye inside the box of 60 sphere glyphs placed at points without cells. The depth range
/// takes where a dataset's cells lie when the eye is inside its box (penumbra::OccupancyGrid), but
/// a glyph mapper draws its glyphs at its input's points, not those cells: taken for the glyphs,
/// the cells (none here) left them out of the range, and 32.7% of the compared pixels were wrong.
void TestGlyphsAroundTheEye()
{
  Scene scene(320, 240);
  scene.Ground(5.0);
  vtkNew<vtkPoints> centres;
  for (int i = 0; i < 60; ++i)
  {
    // A fixed scatter over [-4, 4] x [0.3, 3] x [-4, 4].
    const double u = std::fmod(0.618034 * i, 1.0), v = std::fmod(0.414214 * i, 1.0),
                 w = std::fmod(0.732051 * i, 1.0);
    centres->InsertNextPoint(-4.0 + 8.0 * u, 0.3 + 2.7 * v, -4.0 + 8.0 * w);
  }
  vtkNew<vtkPolyData> points;
  points->SetPoints(centres);
  vtkNew<vtkGlyph3DMapper> glyphs;
  glyphs->SetInputData(points);
  glyphs->SetSourceConnection(SphereSource(0, 0, 0, 0.25, 16, 8)->GetOutputPort());
  vtkNew<vtkActor> cloud;
  cloud->SetMapper(glyphs);
  scene.Renderer->AddActor(cloud);
  scene.Light->SetPosition(-1, 6, 1);
  scene.Camera(0.5, 1.5, 0.5, 3, 0.5, 3);
  CheckAgainstTruth("the eye among glyphs", scene.Render());
}

/// vtkCompositePolyDataMapper2 draws the polydata blocks of its data only: an image block beside
/// a sphere block shows nothing, so it casts nothing either (a user's trial: floating shadows of
/// blocks VTK did not draw, 1,121 pixels wrong against the truth).
void TestCompositeBlocksVTKDraws()
{
  std::vector<float> visibility[2];
  for (int withImage = 0; withImage < 2; ++withImage)
  {
    Scene scene(320, 240);
    scene.Ground();
    vtkSmartPointer<vtkSphereSource> sphere = SphereSource(0, 1, 0, 0.6, 32, 16);
    sphere->Update();
    vtkNew<vtkImageData> image; // a 1.2 x 0.2 x 1.2 slab of voxels above the ground
    image->SetDimensions(7, 2, 7);
    image->SetSpacing(0.2, 0.2, 0.2);
    image->SetOrigin(1.0, 1.2, -0.6);
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetBlock(0, sphere->GetOutput());
    if (withImage)
    {
      blocks->SetBlock(1, image);
    }
    vtkNew<vtkCompositePolyDataMapper2> mapper;
    mapper->SetInputDataObject(blocks);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    scene.Renderer->AddActor(actor);
    scene.Camera(3, 4, 7, 0, 0.5, 0);
    CheckAgainstTruth(
      withImage ? "composite data with an image block" : "composite data", scene.Render());
    visibility[withImage] = ImageValues(scene.Pass->GetVisibilityImage(0));
  }
  Check(!visibility[0].empty() && visibility[0] == visibility[1],
    "an image block VTK does not draw casts no shadow");
}

/// A sphere whose data holds one point, used by no cell, at an infinite coordinate (as files
/// do): VTK 9.1 shifts the vertex buffer by the points' range and draws none of it, so it casts
/// nothing, with one warning, and the truth agrees. The pass cast the whole sphere and drew its
/// depth: a shadow and a self-shadow crescent where VTK showed the ground (a user trial).
void TestInfinitePointsVTKDraws()
{
  // Through a polydata mapper, a vtkDataSetMapper (PyVista's) and, as a block beside a clean
  // sphere, a vtkCompositePolyDataMapper2, which shifts one buffer for both blocks.
  for (const char* kind :
    { "vtkPolyDataMapper", "vtkDataSetMapper", "vtkCompositePolyDataMapper2" })
  {
    Scene scene(320, 240);
    scene.Ground();
    vtkSmartPointer<vtkSphereSource> sphere = SphereSource(0, 1, 0, 0.6, 32, 16);
    sphere->Update();
    vtkNew<vtkPolyData> data;
    data->DeepCopy(sphere->GetOutput());
    data->GetPoints()->InsertNextPoint(std::numeric_limits<double>::infinity(), 0.0, 0.0);
    data->GetPoints()->Modified();
    vtkSmartPointer<vtkSphereSource> clean = SphereSource(-1.5, 1, 0, 0.4, 32, 16);
    clean->Update();
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetBlock(0, data);
    blocks->SetBlock(1, clean->GetOutput());
    vtkSmartPointer<vtkMapper> mapper;
    if (std::string(kind) == "vtkPolyDataMapper")
    {
      mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
      mapper->SetInputDataObject(data);
    }
    else if (std::string(kind) == "vtkDataSetMapper")
    {
      mapper = vtkSmartPointer<vtkDataSetMapper>::New();
      mapper->SetInputDataObject(data);
    }
    else
    {
      mapper = vtkSmartPointer<vtkCompositePolyDataMapper2>::New();
      mapper->SetInputDataObject(blocks);
    }
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    scene.Renderer->AddActor(actor);
    scene.Camera(3, 4, 7, 0, 0.5, 0);
    const WarningLog log(scene.Pass);
    const Comparison truth = scene.Render();
    std::printf("     %s: truth %d px compared, %d shadowed, %d wrong\n", kind, truth.Compared,
      truth.Shadowed, truth.Mismatched);
    const std::string what = std::string(" (") + kind + ")";
    Check(truth.Compared > 1000 && truth.Shadowed == 0 && truth.Mismatched == 0,
      "the truth casts nothing of it either" + what);
    const std::vector<float> visibility = ImageValues(scene.Pass->GetVisibilityImage(0));
    Check(!visibility.empty() &&
        std::all_of(visibility.begin(), visibility.end(), [](float v) { return v == 1.0f; }),
      "data VTK does not draw (a point at infinity) casts no shadow" + what);
    Check(log.Count("draws none of it") == 1 && log.Count("infinite") == 1,
      "one warning says why" + what);
  }
}

} // namespace

int main(int argc, char* argv[])
{
  static const Features features = {
    { "Classic", TestClassic },
    { "CameraInsideShadow", TestCameraInsideShadow },
    { "VisibleCastersOnZFail", TestVisibleCastersOnZFail },
    { "AwkwardMeshes", TestAwkwardMeshes },
    { "LightInsideClosedCaster", TestLightInsideClosedCaster },
    { "BackgroundStaysLit", TestBackgroundStaysLit },
    { "DepthFromCasterMeshes", TestDepthFromCasterMeshes },
    { "FaceCulledCasters", TestFaceCulledCasters },
    { "GlyphsAroundTheEye", TestGlyphsAroundTheEye },
    { "CompositeBlocksVTKDraws", TestCompositeBlocksVTKDraws },
    { "ExplicitProjection", TestExplicitProjection },
    { "InfinitePointsVTKDraws", TestInfinitePointsVTKDraws },
  };
  return RunFeatures(argc, argv, features);
}
