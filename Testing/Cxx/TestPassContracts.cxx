// The pass's contracts as a VTK render pass: caching and headlights, compositing into VTK's
// shading (attenuation, exclusions, PBR), viewports, lights and resizes, render-pass chains, bad
// input and picking.
#include "penumbraTestHarness.h"

#include "vtkAssembly.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkAxesActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkConeSource.h"
#include "vtkCoordinate.h"
#include "vtkCubeSource.h"
#include "vtkCullerCollection.h"
#include "vtkDataObject.h"
#include "vtkDataSetMapper.h"
#include "vtkDepthSortPolyData.h"
#include "vtkFrustumCoverageCuller.h"
#include "vtkGlyph3DMapper.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkImageCanvasSource2D.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkLight.h"
#include "vtkLightActor.h"
#include "vtkLightsPass.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLLight.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOverlayPass.h"
#include "vtkPlane.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkPropPicker.h"
#include "vtkProperty.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderStepsPass.h"
#include "vtkRendererSettingsPass.h"
#include "vtkScalarBarActor.h"
#include "vtkScalarBarRepresentation.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSequencePass.h"
#include "vtkShaderProperty.h"
#include "vtkSphereRepresentation.h"
#include "vtkSphereSource.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTextActor.h"
#include "vtkTexture.h"
#include "vtkTimeSourceExample.h"
#include "vtkTransform.h"
#include "vtkTranslucentPass.h"
#include "vtkTrivialProducer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtk_glew.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <set>
#include <sstream>
#include <vector>

using namespace penumbra_test;

namespace
{

using Scene = PassScene;

void TestCachingAndHeadlights()
{
  Scene scene;
  scene.Ground();
  scene.Sphere(0, 1, 0, 0.6);
  scene.Camera(3, 4, 7, 0, 0.5, 0);
  scene.Window->Render();
  const vtkIdType updates = scene.Pass->GetNumberOfSilhouetteUpdates();
  for (int i = 0; i < 3; ++i)
  {
    scene.Renderer->GetActiveCamera()->Azimuth(10);
    scene.Window->Render();
  }
  Check(
    scene.Pass->GetNumberOfSilhouetteUpdates() == updates, "camera orbit does no silhouette work");
  scene.Light->SetPosition(-2, 6, 2.5);
  scene.Window->Render();
  Check(scene.Pass->GetNumberOfSilhouetteUpdates() > updates, "moving the light recomputes");

  // A caster behind the camera, lit from the front: its shadow points away from the view.
  vtkActor* behind = scene.Sphere(0, 1, 0, 0.3);
  behind->SetPosition(6, 5, 14);
  scene.Light->SetPosition(-2, 6, 2.5);
  scene.Window->Render();
  Check(scene.Pass->GetNumberOfCulledShadows() == 1,
    "a caster whose shadow cannot reach the view is skipped (" +
      std::to_string(scene.Pass->GetNumberOfCulledShadows()) + " skipped)");
  scene.Renderer->RemoveActor(behind);

  // Only a headlight: nothing to shadow, nothing drawn.
  scene.Renderer->RemoveAllLights();
  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  scene.Renderer->AddLight(headlight);
  scene.Window->Render();
  Check(scene.Pass->GetNumberOfShadowingLights() == 0 &&
      scene.Pass->GetNumberOfShadowVolumeTriangles() == 0,
    "headlight casts nothing and costs nothing");
  Check(scene.Pass->GetVisibilityImage(0) == nullptr, "no visibility image for a headlight");
}

/// Mean RGB of the pixels where `mask` says shadow (truth visibility 0), over a viewport.
double MeanInShadow(vtkRenderWindow* window, vtkImageData* truth, int width, int height)
{
  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(0, 0, width - 1, height - 1, 0, rgb);
  auto visibility = vtkFloatArray::SafeDownCast(truth->GetPointData()->GetScalars());
  double sum = 0;
  int count = 0;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(width) * height; ++i)
  {
    if (visibility->GetValue(i) < 0.5f)
    {
      sum += rgb->GetValue(3 * i) + rgb->GetValue(3 * i + 1) + rgb->GetValue(3 * i + 2);
      ++count;
    }
  }
  return count ? sum / (3.0 * count) : -1.0;
}

void TestCompositing()
{
  // Attenuation, exclusions and PBR: colours in the shadow of a sphere on a ground plane.
  Scene scene;
  vtkActor* ground = scene.Ground();
  vtkActor* sphere = scene.Sphere(0, 1, 0, 0.6);
  scene.Camera(2, 5, 5, 0, 0, 0);
  scene.Window->Render();
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(scene.Renderer);
  truth->SetSamplesPerLight(1);
  truth->Update();
  vtkNew<vtkImageData> shadowMask;
  shadowMask->DeepCopy(truth->GetVisibilityImage(0));
  // Only ground pixels: the sphere's own unlit side is not what these checks are about.
  vtkSoftShadowPass::SetCastsShadows(ground, true);

  const double shadowed = MeanInShadow(scene.Window, shadowMask, 200, 150);
  scene.Light->SetShadowAttenuation(0.5);
  scene.Window->Render();
  const double half = MeanInShadow(scene.Window, shadowMask, 200, 150);
  scene.Light->SetShadowAttenuation(1.0);
  scene.Renderer->SetPass(nullptr);
  scene.Window->Render();
  const double unshadowed = MeanInShadow(scene.Window, shadowMask, 200, 150);
  scene.Renderer->SetPass(scene.Pass);
  std::printf("     mean colour in shadow: shadowed %.1f, attenuation 0.5 %.1f, no pass %.1f\n",
    shadowed, half, unshadowed);
  Check(shadowed + 20 < unshadowed, "shadow darkens the receiver");
  Check(std::abs(half - 0.5 * (shadowed + unshadowed)) < 3.0, "ShadowAttenuation 0.5 halves it");

  vtkSoftShadowPass::SetReceivesShadows(ground, false);
  scene.Window->Render();
  Check(std::abs(MeanInShadow(scene.Window, shadowMask, 200, 150) - unshadowed) < 1.5,
    "a non-receiving actor is not shadowed");
  vtkSoftShadowPass::SetReceivesShadows(ground, true);
  vtkSoftShadowPass::SetCastsShadows(sphere, false);
  scene.Window->Render();
  Check(std::abs(MeanInShadow(scene.Window, shadowMask, 200, 150) - unshadowed) < 1.5,
    "a non-casting actor casts no shadow");
  vtkSoftShadowPass::SetCastsShadows(sphere, true);

  ground->GetProperty()->SetInterpolationToPBR();
  ground->GetProperty()->SetRoughness(0.4);
  scene.Window->Render();
  const double pbrShadowed = MeanInShadow(scene.Window, shadowMask, 200, 150);
  scene.Renderer->SetPass(nullptr);
  scene.Window->Render();
  const double pbrUnshadowed = MeanInShadow(scene.Window, shadowMask, 200, 150);
  std::printf("     PBR ground in shadow %.1f, without pass %.1f\n", pbrShadowed, pbrUnshadowed);
  Check(pbrShadowed + 20 < pbrUnshadowed, "PBR materials are shadowed");
}

/// The contracts' small scene in `renderer`: a ground of half-width 4 at y = 0 and a sphere of
/// diameter 1 at (0, 1, 0).
void AddGroundAndSphere(vtkRenderer* renderer, std::vector<vtkSmartPointer<vtkObject>>& keep)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-4, 0, -4);
  plane->SetPoint1(4, 0, -4);
  plane->SetPoint2(-4, 0, 4);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 1, 0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  AddActor(renderer, plane, 0.9, 0.9, 0.9, keep);
  AddActor(renderer, sphere, 0.9, 0.3, 0.3, keep);
}

void TestViewportsLightsAndResize()
{
  // Two renderers side by side in a non-square window, one with two coloured lights.
  vtkSmartPointer<vtkRenderWindow> window = NewRenderWindow();
  window->SetSize(320, 120);
  std::vector<vtkSmartPointer<vtkObject>> keep;
  vtkSmartPointer<vtkRenderer> renderers[2];
  vtkSmartPointer<vtkSoftShadowPass> passes[2];
  for (int i = 0; i < 2; ++i)
  {
    renderers[i] = vtkSmartPointer<vtkRenderer>::New();
    renderers[i]->SetViewport(0.5 * i, 0, 0.5 * (i + 1), 1);
    passes[i] = vtkSmartPointer<vtkSoftShadowPass>::New();
    renderers[i]->SetPass(passes[i]);
    window->AddRenderer(renderers[i]);
    AddGroundAndSphere(renderers[i], keep);
    auto light = penumbra::scene::MakeLight(true, { i ? 2.0 : -2.0, 5, 1 }, 0.0);
    light->SetDiffuseColor(1.0, 0.7, 0.7);
    renderers[i]->AddLight(light);
    vtkCamera* camera = renderers[i]->GetActiveCamera();
    camera->SetPosition(0, 5, 6);
    camera->SetFocalPoint(0, 0, 0);
  }
  auto second = penumbra::scene::MakeLight(false, { 1, 4, -2 }, 0.0);
  second->SetDiffuseColor(0.5, 0.5, 1.0);
  renderers[1]->AddLight(second);

  window->Render();
  CheckAgainstTruth("left viewport", CompareWithTruth(window, renderers[0], passes[0], 0));
  CheckAgainstTruth(
    "right viewport, light 1", CompareWithTruth(window, renderers[1], passes[1], 0));
  CheckAgainstTruth(
    "right viewport, light 2 (directional)", CompareWithTruth(window, renderers[1], passes[1], 1));
  Check(passes[1]->GetNumberOfShadowingLights() == 2, "two shadowing lights");

  window->SetSize(260, 200);
  window->Render();
  vtkImageData* resized = passes[0]->GetVisibilityImage(0);
  Check(resized && resized->GetDimensions()[0] == 130 && resized->GetDimensions()[1] == 200,
    "visibility image follows a resize");
  CheckAgainstTruth("after resize", CompareWithTruth(window, renderers[0], passes[0], 0));
}

void TestDelegateChain()
{
  // The pass as the opaque step of a hand-built vtkCameraPass / vtkSequencePass chain.
  Scene scene;
  scene.Ground();
  scene.Sphere(0.5, 1, 0, 0.6);
  scene.Camera(3, 4, 7, 0, 0.5, 0);
  vtkNew<vtkOpaquePass> opaque;
  scene.Pass->SetDelegatePass(opaque);
  vtkNew<vtkLightsPass> lights;
  vtkNew<vtkTranslucentPass> translucent;
  vtkNew<vtkOverlayPass> overlay;
  vtkNew<vtkRenderPassCollection> steps;
  steps->AddItem(lights);
  steps->AddItem(scene.Pass);
  steps->AddItem(translucent);
  steps->AddItem(overlay);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(steps);
  vtkNew<vtkCameraPass> cameraPass;
  cameraPass->SetDelegatePass(sequence);
  scene.Renderer->SetPass(cameraPass);
  CheckAgainstTruth("inside a vtkCameraPass / vtkSequencePass chain", scene.Render());

  // The passes after it draw whole: a translucent sphere against the sky, drawn by the chain's
  // vtkTranslucentPass, looks the same with shadows on and off (the pass restores the scissor
  // box its volumes set).
  vtkActor* glass = scene.Sphere(-1.5, 1.8, -2.5, 0.3);
  glass->GetProperty()->SetOpacity(0.5);
  vtkSoftShadowPass::SetCastsShadows(glass, false);
  scene.Renderer->SetWorldPoint(-1.5, 1.8, -2.5, 1.0);
  scene.Renderer->WorldToDisplay();
  const int x = static_cast<int>(scene.Renderer->GetDisplayPoint()[0]);
  const int y = static_cast<int>(scene.Renderer->GetDisplayPoint()[1]);
  auto colourAt = [&]()
  {
    scene.Window->Render();
    unsigned char* rgb = scene.Window->GetPixelData(x, y, x, y, 0);
    const std::array<int, 3> colour = { rgb[0], rgb[1], rgb[2] };
    delete[] rgb;
    return colour;
  };
  scene.Pass->ShadowsEnabledOff();
  const std::array<int, 3> unshadowed = colourAt();
  scene.Pass->ShadowsEnabledOn();
  const std::array<int, 3> shadowed = colourAt();
  std::printf("     glass at (%d, %d) after the pass: %d %d %d, without shadows %d %d %d\n", x, y,
    shadowed[0], shadowed[1], shadowed[2], unshadowed[0], unshadowed[1], unshadowed[2]);
  Check(shadowed == unshadowed, "translucent geometry after the pass is drawn whole");

  // The same pass as the opaque step of a user's vtkRenderStepsPass (VTK's own sequence of
  // camera, lights, opaque, translucent, volumes and overlays).
  vtkNew<vtkRenderStepsPass> renderSteps;
  renderSteps->SetOpaquePass(scene.Pass);
  scene.Renderer->SetPass(renderSteps);
  const Comparison stepsTruth = scene.Render();
  CheckAgainstTruth("as the opaque step of a vtkRenderStepsPass", stepsTruth);
  // And its shadows reach the image VTK's steps draw: the shadowed pixels are darker than
  // with shadows off.
  scene.Pass->ShadowsEnabledOff();
  scene.Window->Render();
  const std::vector<unsigned char> lit = WindowColours(scene.Window, scene.Renderer);
  scene.Pass->ShadowsEnabledOn();
  scene.Window->Render();
  const std::vector<unsigned char> shaded = WindowColours(scene.Window, scene.Renderer);
  int darker = 0;
  for (std::size_t p = 0; p + 2 < lit.size() && lit.size() == shaded.size(); p += 3)
  {
    darker += shaded[p] + shaded[p + 1] + shaded[p + 2] + 30 < lit[p] + lit[p + 1] + lit[p + 2];
  }
  std::printf("     vtkRenderStepsPass: %d pixels darker with shadows on\n", darker);
  Check(darker >= stepsTruth.Shadowed / 2, "vtkRenderStepsPass: the shadows are in its image");
  // Lit pixels are as VTK's steps draw them without the pass.
  const std::vector<float> visibility = ImageValues(scene.Pass->GetVisibilityImage(0));
  vtkNew<vtkOpaquePass> plainOpaque;
  renderSteps->SetOpaquePass(plainOpaque);
  scene.Window->Render();
  const std::vector<unsigned char> withoutPass = WindowColours(scene.Window, scene.Renderer);
  int litPixels = 0, litDiffer = 0;
  for (std::size_t i = 0; i < visibility.size() && 3 * visibility.size() == shaded.size(); ++i)
  {
    if (visibility[i] >= 1.0f)
    {
      ++litPixels;
      const std::size_t c = 3 * i;
      litDiffer += std::abs(shaded[c] - withoutPass[c]) > 2 ||
        std::abs(shaded[c + 1] - withoutPass[c + 1]) > 2 ||
        std::abs(shaded[c + 2] - withoutPass[c + 2]) > 2;
    }
  }
  std::printf("     vtkRenderStepsPass: %d of %d lit pixels differ from VTK's without the pass\n",
    litDiffer, litPixels);
  Check(litPixels > 1000 && litDiffer <= litPixels / 500,
    "vtkRenderStepsPass: lit pixels as VTK's steps draw them without the pass");
}

/// Picking with the pass set: vtkHardwareSelector's selection renders go through the renderer's
/// selector (vtkRendererSettingsPass), with no shadow work; the shadows come back after.
void TestPicking()
{
  Scene scene;
  vtkActor* ground = scene.Ground();
  vtkActor* sphere = scene.Sphere(0, 1, 0, 0.6);
  vtkActor* box = scene.Box(1.6, 0.4, 0.8, 0.6, 0.8, 0.6);
  scene.Camera(3, 4, 7, 0, 0.5, 0);
  scene.Window->Render();
  Check(scene.Pass->GetNumberOfShadowingLights() == 1, "picking: the scene is shadowed");

  auto display = [&](double x, double y, double z)
  {
    vtkNew<vtkCoordinate> world;
    world->SetCoordinateSystemToWorld();
    world->SetValue(x, y, z);
    const double* d = world->GetComputedDoubleDisplayValue(scene.Renderer);
    return std::array<double, 2>{ { d[0], d[1] } };
  };
  vtkNew<vtkCallbackCommand> onError;
  int errors = 0;
  onError->SetClientData(&errors);
  onError->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });

  vtkNew<vtkPropPicker> picker;
  picker->AddObserver(vtkCommand::ErrorEvent, onError);
  const std::array<double, 2> atSphere = display(0, 1, 0), atGround = display(0.5, 0, 2.5);
  picker->Pick(atSphere[0], atSphere[1], 0, scene.Renderer);
  const bool sphereFound = picker->GetViewProp() == sphere;
  picker->Pick(atGround[0], atGround[1], 0, scene.Renderer);
  Check(sphereFound && picker->GetViewProp() == ground,
    "picking: vtkPropPicker finds the sphere and the ground under their pixels");

  vtkNew<vtkHardwareSelector> selector;
  selector->AddObserver(vtkCommand::ErrorEvent, onError);
  selector->SetRenderer(scene.Renderer);
  const int* size = scene.Window->GetSize();
  selector->SetArea(0, 0, size[0] - 1, size[1] - 1);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  vtkSmartPointer<vtkSelection> selection = vtkSmartPointer<vtkSelection>::Take(selector->Select());
  std::set<vtkProp*> selected;
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkInformation* properties = selection->GetNode(n)->GetProperties();
    selected.insert(vtkProp::SafeDownCast(properties->Get(vtkSelectionNode::PROP())));
  }
  Check(selected == std::set<vtkProp*>{ ground, sphere, box },
    "picking: a hardware selection over the view holds the ground, the sphere and the box");
  // Picking from a list: the sphere's pixel gives the ground behind it. (Last: VTK keeps the
  // list for later selections of the renderer.)
  vtkNew<vtkPropCollection> onlyGround;
  onlyGround->AddItem(ground);
  vtkAssemblyPath* path = scene.Renderer->PickPropFrom(atSphere[0], atSphere[1], onlyGround);
  Check(path && path->GetFirstNode()->GetViewProp() == ground,
    "picking: PickPropFrom a list of props picks among them only");

  Check(errors == 0, "picking: no errors from the picker or the selector");

  scene.Window->Render();
  Check(scene.Pass->GetNumberOfShadowingLights() == 1 &&
      scene.Pass->GetNumberOfShadowVolumeTriangles() > 0,
    "picking: the shadows come back after the selection");
}

void TestBadInput()
{
  Scene scene;
  scene.Ground();
  scene.Sphere(0, 1, 0, 0.6);
  const WarningLog warnings(scene.Pass);

  auto addData = [&](vtkPolyData* data)
  {
    vtkNew<vtkTrivialProducer> producer;
    producer->SetOutput(data);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(producer->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    scene.Renderer->AddActor(actor);
    scene.Keep.push_back(producer.GetPointer());
    return actor.GetPointer();
  };
  vtkNew<vtkPolyData> empty;
  addData(empty);
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(2, 0.5, 0);
  points->InsertNextPoint(2.5, 1.5, 0);
  points->InsertNextPoint(std::numeric_limits<double>::quiet_NaN(), 1, 0);
  points->InsertNextPoint(3, 0.5, 0);
  vtkNew<vtkCellArray> lines, verts, polys;
  const vtkIdType line[2] = { 0, 1 }, vert[1] = { 1 }, nanTriangle[3] = { 0, 2, 3 },
                  flat[3] = { 0, 0, 1 };
  lines->InsertNextCell(2, line);
  verts->InsertNextCell(1, vert);
  polys->InsertNextCell(3, nanTriangle);
  polys->InsertNextCell(3, flat);
  vtkNew<vtkPolyData> linesOnly, vertsOnly, broken;
  linesOnly->SetPoints(points);
  linesOnly->SetLines(lines);
  vertsOnly->SetPoints(points);
  vertsOnly->SetVerts(verts);
  broken->SetPoints(points);
  broken->SetPolys(polys);
  vtkActor* linesActor = addData(linesOnly);
  addData(vertsOnly);
  addData(broken);

  scene.Camera(3, 4, 7, 0, 0.5, 0);
  const Comparison comparison = scene.Render();
  for (const std::string& message : warnings.Messages)
  {
    std::printf("     warning: %s\n", message.c_str());
  }
  // Empty data, lines only, vertices only, and triangles that are all NaN or degenerate: one
  // warning each, naming the actor and saying what the data had instead of triangles. The
  // lines and vertices, without normals, are drawn unlit too: one more warning each.
  Check(warnings.Messages.size() == 6 && warnings.Count("active point normals") == 2,
    "each bad caster is reported with one warning, and each unlit one with another");
  Check(warnings.Count("Actor (") == 6 && warnings.Count("), its vtkPolyData (") == 4 &&
      warnings.Count("has no surface triangles, so it casts no shadow") == 4,
    "each names its actor and its data, and says it casts no shadow");
  Check(warnings.Count("and 1 line cells") == 1 && warnings.Count("ignored 1 vertex") == 1 &&
      warnings.Count("NaN or infinite coordinates") == 3 &&
      warnings.Count("degenerate (zero-area) triangles") == 1,
    "each says what its data had instead: lines, vertices, non-finite points, degenerate "
    "triangles");
  CheckAgainstTruth("good caster beside bad input", comparison);
  const std::size_t before = warnings.Messages.size();
  scene.Window->Render();
  Check(warnings.Messages.size() == before, "warnings are not repeated every frame");
  // A frame without it frees its mesh; the warning stays said.
  linesActor->VisibilityOff();
  scene.Window->Render();
  linesActor->VisibilityOn();
  scene.Window->Render();
  Check(warnings.Messages.size() == before, "nor when the actor is hidden and shown again");

  // A zero scale flattens a sphere into a disc, which VTK draws: with no inverse to take the
  // light into its mesh's coordinates it casts nothing, said once; the others still cast.
  vtkActor* flattened = scene.Sphere(1.5, 1, 0, 0.4);
  flattened->SetScale(0, 1, 1);
  scene.Window->Render();
  scene.Window->Render();
  Check(warnings.Count("singular matrix") == 1 && warnings.Messages.size() == before + 1 &&
      scene.Pass->GetNumberOfShadowVolumeTriangles() > 0,
    "a flattening matrix: one warning, the other casters still cast");
}

/// One pass drawn into two windows in turn (found crashing llvmpipe once the second window drew
/// with buffers made in the first one's context): it warns once, and each window's shadows are
/// those of a pass of its own.
void TestTwoWindows()
{
  std::vector<vtkSmartPointer<vtkObject>> keep;
  auto scene = [&](vtkRenderer* renderer, double lightX, double radius)
  {
    AddGroundAndSphere(renderer, keep);
    renderer->AddLight(penumbra::scene::MakeLight(true, { lightX, 5, 1 }, radius));
    PlaceCamera(renderer, 0, 5, 6, 0, 0, 0);
  };
  PassScene first(200, 150, PassScene::StartLight::None),
    second(160, 120, PassScene::StartLight::None), alone(160, 120, PassScene::StartLight::None);
  scene(first.Renderer, -2.0, 0.3);
  scene(second.Renderer, 2.0, 0.0);
  scene(alone.Renderer, 2.0, 0.0);
  first.Window->Render();
  second.Window->Render();
  const WarningLog log(first.Pass);
  second.Renderer->SetPass(first.Pass);
  std::vector<float> shared;
  for (int frame = 0; frame < 3; ++frame)
  {
    first.Window->Render();
    second.Window->Render();
    shared = ImageValues(first.Pass->GetVisibilityImage(0));
  }
  alone.Window->Render();
  const std::vector<float> own = ImageValues(alone.Pass->GetVisibilityImage(0));
  const int apart = PixelsApart(shared, own);
  std::printf("     one pass, two windows: %d px apart from a pass of its own; %zu warnings\n",
    apart, log.Messages.size());
  Check(!own.empty() && apart == 0, "a pass shared by two windows shadows as a pass of its own");
  Check(log.Count("second render window") == 1 && log.Messages.size() == 1,
    "one warning that the pass changes window");
}

/// A positional light whose sphere reaches a visible prop: one warning, naming the distance;
/// none for a radius just below it, nor for the room it hangs in, a widget round it or its
/// vtkLightActor. A negative
/// light index: an error.
void TestLightReachingScene()
{
  std::vector<vtkSmartPointer<vtkObject>> keep;
  PassScene view(160, 120, PassScene::StartLight::None);
  AddGroundAndSphere(view.Renderer, keep);
  // A room round it all, its walls 9 or more from the light: the light inside the room's box
  // is no reason to warn.
  vtkNew<vtkCubeSource> room;
  room->SetXLength(30);
  room->SetYLength(30);
  room->SetZLength(30);
  vtkActor* walls = AddActor(view.Renderer, room, 0.8, 0.8, 0.8, keep);
  auto light = penumbra::scene::MakeLight(true, { 0.5, 6, 0.5 }, 4.3);
  view.Renderer->AddLight(light);
  // A widget's handles round the light (what vtkSphereWidget2 adds): they cast and receive
  // nothing, so they are not the scene the light reaches.
  vtkNew<vtkSphereRepresentation> handles;
  handles->SetRenderer(view.Renderer);
  double aroundLight[6] = { 0.0, 1.0, 5.5, 6.5, 0.0, 1.0 };
  handles->PlaceWidget(aroundLight);
  view.Renderer->AddViewProp(handles);
  // And the light's own marker, which draws unlit lines from it: a spot light's cone.
  light->SetConeAngle(70.0);
  vtkNew<vtkLightActor> marker;
  marker->SetLight(light);
  view.Renderer->AddViewProp(marker);
  PlaceCamera(view.Renderer, 0, 5, 6, 0, 0, 0);
  const WarningLog log(view.Pass);
  view.Window->Render();
  const std::ptrdiff_t below = log.Count("distance to the nearest visible prop's box");
  vtkSoftShadowPass::SetLightRadius(light, 4.7); // the sphere's top is 4.5 below the light
  view.Window->Render();
  view.Window->Render();
  std::printf("     light reaching the scene: %d warnings below, %d after\n",
    static_cast<int>(below),
    static_cast<int>(log.Count("distance to the nearest visible prop's box")));
  for (const std::string& w : log.Messages)
  {
    std::printf("     warning: %s", w.c_str());
  }
  Check(below == 0, "a light short of the scene: no warning");
  Check(log.Count("distance to the nearest visible prop's box (4.5") == 1,
    "a light reaching the scene: one warning, with the distance");

  // Nor are the widget and the marker props the light's samples face: the soft shadows are
  // those drawn without them (out of the room, whose box would hide a shift).
  view.Renderer->RemoveActor(walls);
  view.Window->Render();
  const std::vector<float> withMarkers = ImageValues(view.Pass->GetVisibilityImage(0));
  view.Renderer->RemoveViewProp(marker);
  view.Renderer->RemoveViewProp(handles);
  view.Window->Render();
  const std::vector<float> without = ImageValues(view.Pass->GetVisibilityImage(0));
  int changed = withMarkers.size() == without.size() ? 0 : -1;
  for (std::size_t i = 0; changed >= 0 && i < without.size(); ++i)
  {
    changed += withMarkers[i] != without[i];
  }
  std::printf(
    "     %d px of the soft shadows change with the light's widget and marker\n", changed);
  Check(changed == 0, "a widget and a vtkLightActor at the light change no shadow");

  // A negative light index is a mistake, not a light without shadows: an error says so.
  const WarningLog errors(view.Pass, vtkCommand::ErrorEvent);
  Check(view.Pass->GetVisibilityImage(-1) == nullptr && errors.Messages.size() == 1,
    "a negative light index: no image, one error");
}

/// Pixels of the first renderer's viewport that differ from the frame a fresh pass with the same
/// method and samples draws of the scene: what a pass that cached something stale gets wrong.
int PixelsOffFreshPass(PassScene& view)
{
  const std::vector<unsigned char> shown = WindowColours(view.Window, view.Renderer);
  vtkNew<vtkSoftShadowPass> fresh;
  fresh->SetLightSamples(view.Pass->GetLightSamples());
  fresh->SetMethod(view.Pass->GetMethod());
  view.Renderer->SetPass(fresh);
  view.Window->Render();
  const std::vector<unsigned char> drawn = WindowColours(view.Window, view.Renderer);
  view.Renderer->SetPass(view.Pass);
  fresh->ReleaseGraphicsResources(view.Window);
  if (shown.size() != drawn.size())
  {
    return -1;
  }
  int off = 0;
  for (std::size_t i = 0; i < shown.size(); i += 3)
  {
    off += shown[i] != drawn[i] || shown[i + 1] != drawn[i + 1] || shown[i + 2] != drawn[i + 2];
  }
  return off;
}

/// A frame whose shadows cannot have changed reuses the last drawn frame's layers
/// (ReuseUnchangedShadows), and every change that moves a shadow or a visible point draws them
/// again. After each change the frame must equal a fresh pass's frame of the same scene.
class ReuseScene
{
public:
  PassScene View{ 200, 150 };
  vtkNew<vtkSphereSource> SphereShape;
  vtkNew<vtkPlane> ClipPlane;
  vtkNew<vtkTransform> UserTransform;
  vtkNew<vtkTextActor> Text;
  vtkNew<vtkScalarBarRepresentation> ScalarBar; // what vtkScalarBarWidget adds to the renderer
  vtkNew<vtkSphereRepresentation> SphereWidget; // and vtkSphereWidget2, over the red sphere
  vtkNew<vtkAxesActor> Axes;                    // draws through shaft and tip actors of its own
  vtkNew<vtkPolyData> BlockBox;
  vtkNew<vtkTexture> PartTexture;
  vtkNew<vtkTexture> SphereTexture;
  vtkSmartPointer<vtkImageData> SphereImage; // RGBA, opaque until a change edits it in place
  vtkNew<vtkAssembly> Assembly;
  vtkNew<vtkTimeSourceExample> Column; // grows with time, which a change requests
  vtkNew<vtkDataSetMapper> ColumnMapper;
  vtkNew<vtkPolyData> TintedBall; // coloured by height through Tints
  vtkNew<vtkLookupTable> Tints;
  vtkCompositePolyDataMapper2* Blocks = nullptr;
  vtkActor* Tinted = nullptr;
  vtkSmartPointer<vtkImageData> SheetImage; // a property texture's, RGBA, edited in place
  vtkNew<vtkTexture> SheetTexture;
  vtkNew<vtkPlane> SheetClip; // cuts nothing: VTK draws the sheets' depth, holes included
  vtkNew<vtkImageCanvasSource2D> Canvas;         // another sheet's property texture, from a source
  vtkNew<vtkSelection> CellsSelected;            // the first cells of a mapper's data
  vtkNew<vtkCompositePolyDataMapper2> RootBlock; // over one polydata, not a tree
  vtkNew<vtkCompositePolyDataMapper2> TintedBlocks; // two spheres coloured by height
  vtkNew<vtkGlyph3DMapper> Glyphs;                  // cones coloured by a scalar "size"
  vtkNew<vtkLookupTable> GlyphTints;
  vtkNew<vtkLookupTable> BlockTints;
  vtkNew<vtkTexture> CanvasTexture;
  vtkActor* Sphere = nullptr;
  vtkActor* Box = nullptr;
  vtkActor* Part = nullptr;

  ReuseScene()
  {
    this->View.Ground();
    this->SphereShape->SetCenter(0, 1, 0);
    this->SphereShape->SetRadius(0.6);
    this->SphereShape->SetThetaResolution(32);
    this->SphereShape->SetPhiResolution(16);
    this->Sphere = this->View.Add(this->SphereShape, 0.9, 0.3, 0.3);
    this->Box = this->View.Box(1.6, 0.5, 0.8, 0.5, 1.0, 0.5);
    this->Box->SetUserTransform(this->UserTransform);
    this->ClipPlane->SetOrigin(0, 0, 5); // cuts nothing until moved
    this->ClipPlane->SetNormal(0, 0, -1);
    this->Sphere->GetMapper()->AddClippingPlane(this->ClipPlane);
    this->SphereImage = TextureImage(255);
    this->SphereTexture->SetInputData(this->SphereImage);
    this->Sphere->SetTexture(this->SphereTexture);

    // A multiblock leaf and an assembly part: changes below the top-level prop.
    vtkSmartPointer<vtkCubeSource> blockSource = BoxSource(-1.6, 0.4, 0.6, 0.5, 0.8, 0.5);
    blockSource->Update();
    this->BlockBox->DeepCopy(blockSource->GetOutput());
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(1);
    blocks->SetBlock(0, this->BlockBox);
    vtkNew<vtkCompositePolyDataMapper2> compositeMapper;
    this->Blocks = compositeMapper;
    vtkNew<vtkCompositeDataDisplayAttributes> blockAttributes; // the mapper has none of its own
    compositeMapper->SetCompositeDataDisplayAttributes(blockAttributes);
    compositeMapper->SetInputDataObject(blocks);
    vtkNew<vtkActor> composite;
    composite->SetMapper(compositeMapper);
    this->View.Renderer->AddActor(composite);
    this->Part = AddActor(this->View.Renderer, SphereSource(-0.6, 0.35, 1.6, 0.35, 24, 12), 0.3,
      0.8, 0.4, this->View.Keep);
    this->View.Keep.push_back(this->Part); // the renderer lets go of it
    this->View.Renderer->RemoveActor(this->Part);
    this->PartTexture->SetInputData(TextureImage()); // the part's once a change gives it
    this->Assembly->AddPart(this->Part);
    this->View.Renderer->AddActor(this->Assembly);
    this->View.Keep.push_back(blocks.GetPointer());
    this->View.Keep.push_back(composite.GetPointer());
    this->Column->GrowingOn();
    this->ColumnMapper->SetInputConnection(this->Column->GetOutputPort());
    this->ColumnMapper->ScalarVisibilityOff();
    vtkNew<vtkActor> column;
    column->SetMapper(this->ColumnMapper);
    column->SetPosition(-2.2, 0.0, -1.8);
    column->SetScale(0.4);
    this->View.Renderer->AddActor(column);

    vtkSmartPointer<vtkSphereSource> ball = SphereSource(-1.4, 0.3, -1.3, 0.3, 16, 8);
    ball->Update();
    this->TintedBall->DeepCopy(ball->GetOutput());
    vtkNew<vtkFloatArray> heights;
    for (vtkIdType i = 0; i < this->TintedBall->GetNumberOfPoints(); ++i)
    {
      heights->InsertNextValue(static_cast<float>(this->TintedBall->GetPoint(i)[1]));
    }
    this->TintedBall->GetPointData()->SetScalars(heights);
    this->Tinted = this->View.AddData(this->TintedBall, 0.8, 0.8, 0.8);
    this->Tinted->GetMapper()->SetLookupTable(this->Tints);
    this->Tinted->GetMapper()->SetScalarRange(0.0, 0.6);
    this->Tinted->GetMapper()->ScalarVisibilityOn();

    this->SheetClip->SetOrigin(0, 0, 5);
    this->SheetClip->SetNormal(0, 0, -1);
    const auto addSheet = [this](double x, double z, vtkTexture* texture)
    {
      vtkNew<vtkPlaneSource> shape;
      shape->SetOrigin(x, 0.9, z);
      shape->SetPoint1(x + 1.0, 0.9, z);
      shape->SetPoint2(x, 0.9, z + 1.0);
      vtkActor* sheet = this->View.Add(shape, 0.7, 0.7, 0.9);
      sheet->GetProperty()->SetTexture("colorTex", texture);
      sheet->GetMapper()->AddClippingPlane(this->SheetClip);
    };
    this->SheetImage = TextureImage(255);
    this->SheetTexture->SetInputData(this->SheetImage);
    addSheet(0.9, -1.6, this->SheetTexture);
    this->Canvas->SetScalarTypeToUnsignedChar();
    this->Canvas->SetNumberOfScalarComponents(4);
    this->Canvas->SetExtent(0, 7, 0, 7, 0, 0);
    this->Canvas->SetDrawColor(230, 230, 230, 255);
    this->Canvas->FillBox(0, 7, 0, 7);
    this->CanvasTexture->SetInputConnection(this->Canvas->GetOutputPort());
    addSheet(-0.4, -2.4, this->CanvasTexture);

    vtkNew<vtkSelectionNode> firstCells;
    firstCells->SetFieldType(vtkSelectionNode::CELL);
    firstCells->SetContentType(vtkSelectionNode::INDICES);
    vtkNew<vtkIdTypeArray> cellIds;
    for (vtkIdType i = 0; i < 40; ++i)
    {
      cellIds->InsertNextValue(i);
    }
    firstCells->SetSelectionList(cellIds);
    this->CellsSelected->AddNode(firstCells);
    vtkSmartPointer<vtkCubeSource> rootBox = BoxSource(2.0, 0.3, 1.4, 0.4, 0.6, 0.4);
    this->View.Keep.push_back(rootBox);
    this->RootBlock->SetInputConnection(rootBox->GetOutputPort());
    vtkNew<vtkCompositeDataDisplayAttributes> rootAttributes;
    this->RootBlock->SetCompositeDataDisplayAttributes(rootAttributes);
    vtkNew<vtkActor> rootActor;
    rootActor->SetMapper(this->RootBlock);
    this->View.Renderer->AddActor(rootActor);

    // The first block translucent, the second opaque until its colours take alpha.
    vtkNew<vtkMultiBlockDataSet> tinted;
    for (unsigned int block = 0; block < 2; ++block)
    {
      vtkNew<vtkPolyData> ball;
      ball->DeepCopy(this->TintedBall);
      vtkPoints* points = ball->GetPoints();
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        double p[3];
        points->GetPoint(i, p);
        points->SetPoint(i, p[0] + 0.8 * block, p[1], p[2] + 2.4);
      }
      tinted->SetBlock(block, ball);
    }
    this->View.Keep.push_back(tinted.GetPointer());
    this->TintedBlocks->SetInputDataObject(tinted);
    vtkNew<vtkCompositeDataDisplayAttributes> tintedAttributes;
    this->TintedBlocks->SetCompositeDataDisplayAttributes(tintedAttributes);
    this->TintedBlocks->SetBlockOpacity(1, 0.5);
    this->TintedBlocks->SetLookupTable(this->BlockTints);
    this->TintedBlocks->SetScalarRange(0.0, 0.6);
    vtkNew<vtkActor> tintedActor;
    tintedActor->SetMapper(this->TintedBlocks);
    this->View.Renderer->AddActor(tintedActor);

    vtkNew<vtkPolyData> glyphPoints;
    vtkNew<vtkPoints> glyphPlaces;
    vtkNew<vtkFloatArray> sizes;
    sizes->SetName("size");
    for (int i = 0; i < 3; ++i)
    {
      glyphPlaces->InsertNextPoint(1.6 + 0.4 * i, 0.3, 2.2);
      sizes->InsertNextValue(1.0f + 0.5f * static_cast<float>(i));
    }
    glyphPoints->SetPoints(glyphPlaces);
    glyphPoints->GetPointData()->SetScalars(sizes);
    vtkNew<vtkConeSource> cone;
    cone->SetResolution(16);
    this->Glyphs->SetSourceConnection(cone->GetOutputPort());
    this->Glyphs->SetInputData(glyphPoints);
    this->Glyphs->SetScaleFactor(0.3);
    this->Glyphs->SetScaleModeToNoDataScaling();
    this->Glyphs->SetLookupTable(this->GlyphTints);
    this->Glyphs->SetScalarRange(1.0, 2.0);
    vtkNew<vtkActor> glyphActor;
    glyphActor->SetMapper(this->Glyphs);
    this->View.Renderer->AddActor(glyphActor);
    this->View.Keep.push_back(glyphPoints.GetPointer());
    this->View.Keep.push_back(cone.GetPointer());

    this->Text->SetInput("frame 0");
    this->View.Renderer->AddActor2D(this->Text);
    vtkNew<vtkLookupTable> colours;
    this->ScalarBar->GetScalarBarActor()->SetLookupTable(colours);
    this->ScalarBar->GetScalarBarActor()->SetTitle("frame 0");
    this->View.Renderer->AddViewProp(this->ScalarBar);
    double widgetBounds[6] = { -0.7, 0.7, 0.3, 1.7, -0.7, 0.7 };
    this->SphereWidget->SetRenderer(this->View.Renderer);
    this->SphereWidget->PlaceWidget(widgetBounds);
    this->View.Renderer->AddViewProp(this->SphereWidget);
    this->Axes->SetShaftTypeToCylinder();
    this->Axes->SetCylinderRadius(0.08);
    this->Axes->SetTotalLength(0.9, 0.9, 0.9);
    this->Axes->SetPosition(0.6, 0.1, 1.4);
    this->Axes->AxisLabelsOff(); // added to the renderer by the test, after the changes
    vtkSoftShadowPass::SetLightRadius(this->View.Light, 0.3);
    this->View.Pass->SetLightSamples(16);
    this->View.Camera(3, 4, 7, 0, 0.5, 0);
  }

  /// A 2x2 texture of one light grey: RGB (opaque), or RGBA with the given alpha.
  static vtkSmartPointer<vtkImageData> TextureImage(int alpha = -1)
  {
    const int components = alpha < 0 ? 3 : 4;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(2, 2, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, components);
    auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
    for (int i = 0; i < 4 * components; ++i)
    {
      texels[i] = (i % components == 3) ? static_cast<unsigned char>(alpha) : 230;
    }
    return image;
  }

  /// Rewrites the alpha of the sphere's texture in place, as a user editing its array would: the
  /// image is modified, the texture and the actor are not.
  void SetSphereTextureAlpha(unsigned char alpha)
  {
    auto* texels = static_cast<unsigned char*>(this->SphereImage->GetScalarPointer());
    for (int i = 3; i < 16; i += 4)
    {
      texels[i] = alpha;
    }
    this->SphereImage->Modified();
  }

  /// Renders; true when the frame reused the last drawn frame's shadows.
  bool Render()
  {
    const vtkIdType before = this->View.Pass->GetNumberOfReusedFrames();
    this->View.Window->Render();
    return this->View.Pass->GetNumberOfReusedFrames() > before;
  }

  /// Pixels of the renderer's viewport that differ from a fresh pass's frame of the scene.
  int PixelsOffFresh() { return PixelsOffFreshPass(this->View); }
};

/// A light that always lives at the same address: a light the allocator places where a deleted
/// light was, every time.
class SameAddressLight : public vtkOpenGLLight
{
public:
  static SameAddressLight* New()
  {
    auto* light = new SameAddressLight;
    light->InitializeObjectBase();
    return light;
  }
  static void* operator new(std::size_t size)
  {
    alignas(std::max_align_t) static unsigned char storage[sizeof(vtkOpenGLLight)];
    return size <= sizeof(storage) ? storage : nullptr;
  }
  static void operator delete(void*) {}
};

/// What the pass remembers of a light (its one warning, Automatic's last choice) goes with the
/// light: a new light at a deleted light's address is warned again.
void TestLightRecordsFollowLights()
{
  std::vector<vtkSmartPointer<vtkObject>> keep;
  PassScene view(160, 120, PassScene::StartLight::None);
  AddGroundAndSphere(view.Renderer, keep);
  PlaceCamera(view.Renderer, 0, 5, 6, 0, 0, 0);
  const WarningLog log(view.Pass);
  const auto wideSun = []
  {
    vtkSmartPointer<vtkLight> light = vtkSmartPointer<SameAddressLight>::New();
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    light->SetPosition(0.3, 1.0, 0.2);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    vtkSoftShadowPass::SetLightRadius(light, 95.0);
    return light;
  };
  vtkSmartPointer<vtkLight> light = wideSun();
  const vtkLight* first = light.Get();
  view.Renderer->AddLight(light);
  view.Window->Render();
  view.Window->Render();
  Check(log.Count("clamped to 89") == 1, "a directional light of 95 degrees: one warning");

  view.Renderer->RemoveLight(light);
  light = nullptr;
  light = wideSun();
  view.Renderer->AddLight(light);
  view.Window->Render();
  Check(light.Get() == first && log.Count("clamped to 89") == 2,
    "a new light of 95 degrees at the deleted one's address: warned again");

  // The same for a positional light whose radius reaches the scene.
  const auto nearLamp = []
  {
    vtkSmartPointer<vtkLight> lamp = vtkSmartPointer<SameAddressLight>::New();
    lamp->SetLightTypeToSceneLight();
    lamp->SetPositional(true);
    lamp->SetConeAngle(180);
    lamp->SetPosition(2.5, 1.0, 2.5);
    lamp->SetFocalPoint(0.0, 0.0, 0.0);
    vtkSoftShadowPass::SetLightRadius(lamp, 1.5);
    return lamp;
  };
  view.Renderer->RemoveLight(light);
  light = nullptr;
  for (int lamp = 0; lamp < 2; ++lamp)
  {
    light = nearLamp();
    view.Renderer->AddLight(light);
    view.Window->Render();
    view.Window->Render();
    view.Renderer->RemoveLight(light);
    light = nullptr;
  }
  std::printf("     radius reaching the scene: %ld warnings for two lights at one address\n",
    static_cast<long>(log.Count("more than its distance")));
  Check(log.Count("more than its distance") == 2,
    "a new light reaching the scene at the deleted one's address: warned again");
}

/// VTK's translucent pass makes a prop's property keys the first time it draws it, which
/// modifies the prop: the pass makes them before it records the first frame.
void TestSecondFrameReused()
{
  PassScene view;
  view.Ground();
  view.Sphere(0, 1, 0, 0.5, 24);
  view.Box(1.2, 0.5, 0, 0.5, 1, 0.5)->GetProperty()->SetOpacity(0.5);
  view.Camera(3, 4, 7, 0, 0.5, 0);
  view.Window->Render();
  const vtkIdType before = view.Pass->GetNumberOfReusedFrames();
  view.Window->Render();
  Check(view.Pass->GetNumberOfReusedFrames() == before + 1,
    "with a translucent actor in view, the second frame reuses the first's shadows");
}

void TestReuseUnchangedShadows()
{
  ReuseScene scene;
  vtkSoftShadowPass* pass = scene.View.Pass;
  vtkRenderer* renderer = scene.View.Renderer;
  vtkNew<vtkCamera> elsewhere;
  elsewhere->DeepCopy(renderer->GetActiveCamera());
  elsewhere->Azimuth(25);
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetArea(0, 0, 199, 149);

  double offsetFactor, offsetUnits;
  vtkMapper::GetResolveCoincidentTopologyPolygonOffsetParameters(offsetFactor, offsetUnits);
  auto* coverage =
    vtkFrustumCoverageCuller::SafeDownCast(renderer->GetCullers()->GetItemAsObject(0));

  struct Change
  {
    const char* What;
    bool Reuses;
    std::function<void()> Apply;
  };
  const std::vector<Change> changes = {
    { "nothing", true, [] {} },
    { "a 2D text actor's text", true, [&] { scene.Text->SetInput("frame 1"); } },
    { "a scalar bar widget's title and place", true,
      [&]
      {
        scene.ScalarBar->GetScalarBarActor()->SetTitle("frame 1");
        scene.ScalarBar->SetPosition(0.1, 0.2);
      } },
    { "a 3D widget moved past the ground (it neither casts nor receives)", true,
      [&] { scene.SphereWidget->SetCenter(5.5, 1.1, 0.1); } },
    { "a pick between frames (selection render)", true,
      [&]
      {
        vtkSmartPointer<vtkSelection> picked;
        picked.TakeReference(selector->Select());
      } },
    // Colours change no shadow: VTK's own draw shades the receivers every frame.
    { "an actor's colours and lighting coefficients", true,
      [&]
      {
        scene.Box->GetProperty()->SetColor(0.2, 0.5, 0.9);
        scene.Box->GetProperty()->SetSpecular(0.4);
        scene.Box->GetProperty()->SetInterpolationToFlat();
      } },
    // Texels without alpha open no holes: an RGB texture keeps colours out of the shadows. (VTK
    // 9.1 rebuilds an actor's shader for a texture newer than it only.)
    { "an RGB texture given to an actor", false,
      [&]
      {
        scene.PartTexture->Modified();
        scene.Box->SetTexture(scene.PartTexture);
      } },
    { "that actor's colour", true, [&] { scene.Box->GetProperty()->SetColor(0.9, 0.5, 0.2); } },
    { "an assembly part's colour", true,
      [&] { scene.Part->GetProperty()->SetDiffuseColor(0.9, 0.8, 0.1); } },
    { "a block's colour", true,
      [&]
      {
        const double yellow[3] = { 0.9, 0.9, 0.2 };
        scene.Blocks->SetBlockColor(1, yellow);
      } },
    { "a scalar range and a lookup table's colours", true,
      [&]
      {
        scene.Tinted->GetMapper()->SetScalarRange(0.1, 0.5);
        scene.Tints->SetHueRange(0.6, 0.0);
        scene.Tints->ForceBuild();
      } },
    { "a glyph mapper's scalar range and lookup table", true,
      [&]
      {
        scene.Glyphs->SetScalarRange(1.2, 1.8);
        scene.GlyphTints->SetHueRange(0.6, 0.0);
        scene.GlyphTints->ForceBuild();
      } },
    { "the glyphs' scale factor", false, [&] { scene.Glyphs->SetScaleFactor(0.45); } },
    { "the glyphs scaled by an array chosen", false,
      [&]
      {
        scene.Glyphs->SetScaleArray("size");
        scene.Glyphs->SetScaleModeToScaleByMagnitude();
      } },
    { "a lookup table's alpha (the actor drawn translucent)", false,
      [&]
      {
        scene.Tints->SetAlphaRange(0.4, 0.4);
        scene.Tints->ForceBuild();
      } },
    { "the lookup table opaque again", false,
      [&]
      {
        scene.Tints->SetAlphaRange(1.0, 1.0);
        scene.Tints->ForceBuild();
      } },
    { "a block's opacity", false, [&] { scene.Blocks->SetBlockOpacity(1, 0.5); } },
    { "a block hidden", false, [&] { scene.Blocks->SetBlockVisibility(1, false); } },
    { "the block shown and opaque", false,
      [&]
      {
        scene.Blocks->RemoveBlockVisibilities();
        scene.Blocks->RemoveBlockOpacities();
      } },
    { "an actor drawn as a wireframe", false,
      [&] { scene.Sphere->GetProperty()->SetRepresentationToWireframe(); } },
    { "the actor's surface again, front faces culled", false,
      [&]
      {
        scene.Sphere->GetProperty()->SetRepresentationToSurface();
        scene.Sphere->GetProperty()->FrontfaceCullingOn();
      } },
    { "no faces culled", false, [&] { scene.Sphere->GetProperty()->FrontfaceCullingOff(); } },
    { "a mapper's own polygon offset", false,
      [&]
      { scene.Box->GetMapper()->SetRelativeCoincidentTopologyPolygonOffsetParameters(2, 20); } },
    // A mapper's selection is drawn with its surface, into the depth.
    { "a selection of the mapper's cells", false,
      [&] { scene.Tinted->GetMapper()->SetSelection(scene.CellsSelected); } },
    // A composite mapper sorts its blocks into VTK's opaque and translucent passes by their
    // colours: the actor, translucent already, does not show it.
    { "a lookup table making a second block translucent", false,
      [&]
      {
        scene.BlockTints->SetAlphaRange(0.4, 0.4);
        scene.BlockTints->ForceBuild();
      } },
    // vtkCompositePolyDataMapper2 keys attributes by its input itself, tree or not.
    { "a composite mapper's one polydata hidden as its root block", false,
      [&] { scene.RootBlock->SetBlockVisibility(0, false); } },
    // VTK drops fragments of alpha 0 whatever the actor's opacity, and custom shader code may
    // read colours: such colour changes can move the depth the shadows are drawn against.
    { "a property texture's image given holes in place", false,
      [&]
      {
        auto* texels = static_cast<unsigned char*>(scene.SheetImage->GetScalarPointer());
        texels[3] = texels[15] = 0;
        scene.SheetImage->Modified();
      } },
    // The source runs as VTK loads the texture, after the record: it must run before.
    { "a property texture's source redrawn with holes", false,
      [&]
      {
        scene.Canvas->SetDrawColor(230, 230, 230, 0);
        scene.Canvas->FillBox(0, 3, 0, 7);
      } },
    { "an actor forced opaque", false, [&] { scene.Tinted->ForceOpaqueOn(); } },
    { "a lookup table entry of that actor made transparent", false,
      [&]
      {
        scene.Tints->SetTableValue(0, 1.0, 0.0, 0.0, 0.0);
        scene.Tints->SetTableValue(1, 1.0, 0.0, 0.0, 0.0);
      } },
    { "shader code that reads the colour", false,
      [&]
      {
        scene.Box->GetShaderProperty()->AddFragmentShaderReplacement("//VTK::Color::Impl", true,
          "//VTK::Color::Impl\n  if (diffuseColorUniform.g > 0.5) { discard; }\n", false);
      } },
    { "the colour that code reads", false,
      [&] { scene.Box->GetProperty()->SetColor(0.2, 0.9, 0.2); } },
    { "the camera deep-copied, not modified", false,
      [&] { renderer->GetActiveCamera()->DeepCopy(elsewhere); } },
    { "the camera rolled through DeepCopy (its time and depth range unchanged)", false,
      [&]
      {
        elsewhere->Roll(15);
        renderer->GetActiveCamera()->DeepCopy(elsewhere);
      } },
    { "the light moved", false, [&] { scene.View.Light->SetPosition(-1.5, 6, 2.5); } },
    { "the light's radius", false,
      [&] { vtkSoftShadowPass::SetLightRadius(scene.View.Light, 0.6); } },
    { "an actor moved", false, [&] { scene.Sphere->SetPosition(0.3, 0, 0); } },
    { "a user transform changed in place", false,
      [&] { scene.UserTransform->Translate(0, 0, -0.5); } },
    { "a source's parameter (pipeline not yet updated)", false,
      [&] { scene.SphereShape->SetRadius(0.45); } },
    // As a time-aware viewer asks for a step; only the source's own Update honours it, and it
    // must run before the shadows read the column's bounds.
    { "a time step requested through a mapper's input information", false,
      [&]
      {
        scene.ColumnMapper->GetInputInformation()->Set(
          vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), 0.4);
      } },
    { "a clipping plane moved", false, [&] { scene.ClipPlane->SetOrigin(0, 1.2, 0); } },
    { "a multiblock leaf's points", false,
      [&]
      {
        vtkPoints* points = scene.BlockBox->GetPoints();
        for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
        {
          double p[3];
          points->GetPoint(i, p);
          points->SetPoint(i, p[0] + 0.4, p[1], p[2]);
        }
        points->Modified();
      } },
    { "an assembly part moved", false, [&] { scene.Part->SetPosition(0.2, 0, -0.3); } },
    { "an assembly part given a translucent texture", false,
      [&]
      {
        scene.PartTexture->SetInputData(ReuseScene::TextureImage(100));
        scene.Part->SetTexture(scene.PartTexture);
      } },
    { "a texture's image made translucent in place", false,
      [&] { scene.SetSphereTextureAlpha(60); } },
    { "the image made opaque again in place", false, [&] { scene.SetSphereTextureAlpha(255); } },
    { "an assembly's shadow keys", false,
      [&] { vtkSoftShadowPass::SetCastsShadows(scene.Assembly, false); } },
    { "an assembly's shadow keys set in place (the assembly not modified)", false,
      [&] { scene.Assembly->GetPropertyKeys()->Set(vtkSoftShadowPass::CASTS_SHADOWS(), 1); } },
    { "the coincident-topology offsets (static)", false,
      [] { vtkMapper::SetResolveCoincidentTopologyPolygonOffsetParameters(4, 400); } },
    { "the coincident-topology offsets back", false,
      [&] {
        vtkMapper::SetResolveCoincidentTopologyPolygonOffsetParameters(offsetFactor, offsetUnits);
      } },
    // The new data's mesh is as new as the box's was (built once): only its identity differs.
    { "an actor's mapper given another data object", false,
      [&]
      {
        vtkSmartPointer<vtkSphereSource> ball = SphereSource(1.6, 0.5, 0.8, 0.5, 24, 12);
        scene.View.Keep.push_back(ball);
        vtkMapper* mapper = scene.Box->GetMapper();
        mapper->SetInputConnection(ball->GetOutputPort());
      } },
    { "an actor's opacity", false, [&] { scene.Box->GetProperty()->SetOpacity(0.5); } },
    { "an actor hidden", false, [&] { scene.Box->VisibilityOff(); } },
    { "an actor removed", false, [&] { renderer->RemoveActor(scene.Box); } },
    { "the window resized", false, [&] { scene.View.Window->SetSize(180, 140); } },
    { "the pass's samples", false, [&] { pass->SetLightSamples(24); } },
    // Culls a prop covering less than 5% of the view: nothing else about the scene changes.
    { "the coverage culler's minimum coverage", false,
      [&] { coverage->SetMinimumCoverage(0.05); } },
    { "the minimum coverage back", false, [&] { coverage->SetMinimumCoverage(0.0); } },
  };
  // The pass gives each prop its property keys before the first frame's record: VTK's
  // translucent pass would make them while drawing it and so modify the prop.
  scene.Render();
  Check(scene.Render(), "the second frame reuses the first's shadows");
  for (const Change& change : changes)
  {
    const bool settled = scene.Render();
    change.Apply();
    const bool reused = scene.Render();
    const int off = scene.PixelsOffFresh();
    std::printf("     %s: %s, %d px off a fresh pass's frame\n", change.What,
      reused ? "reused" : "drawn", off);
    Check(settled, "an unchanged frame reuses the shadows before: " + std::string(change.What));
    Check(reused == change.Reuses,
      std::string(change.What) + (change.Reuses ? ": shadows reused" : ": shadows drawn"));
    Check(off == 0, std::string(change.What) + ": the frame equals a fresh pass's");
  }

  // A screenshot renders with a copy of the camera whose view angle vtkWindowToImageFilter
  // recomputes a double's last bit off, then puts the user's camera back: the same matrix as GL
  // takes it, so both the screenshot's frame and the next reuse the shadows.
  scene.Render();
  const vtkIdType reusedBeforeGrab = pass->GetNumberOfReusedFrames();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(scene.View.Window);
  grab->Update();
  const bool reusedAfterGrab = scene.Render();
  const vtkIdType grabReused = pass->GetNumberOfReusedFrames() - reusedBeforeGrab;
  std::printf("     a screenshot: %lld of its frame and the next reused\n",
    static_cast<long long>(grabReused));
  Check(grabReused == 2 && reusedAfterGrab && scene.PixelsOffFresh() == 0,
    "a screenshot's frame and the next reuse the shadows, the frame a fresh pass's");

  // A vtkAxesActor draws through shaft and tip actors of its own: a part's property, and the
  // axes' own settings (which its parts follow only as VTK draws them), draw the shadows again.
  // The translucent frame is not compared with a fresh pass: VTK draws a translucent shaft
  // differently from frame to frame (40 pixels alternate with no pass at all).
  renderer->AddActor(scene.Axes);
  scene.Render();
  Check(scene.Render(), "the axes' second frame reuses the shadows");
  scene.Axes->GetYAxisShaftProperty()->SetOpacity(0.3);
  Check(!scene.Render(), "an axes shaft made translucent (a part's property): shadows drawn");
  Check(scene.Render(), "the frame after it reuses the shadows");
  scene.Axes->GetYAxisShaftProperty()->SetOpacity(1.0);
  Check(!scene.Render() && scene.PixelsOffFresh() == 0,
    "the shaft opaque again: shadows drawn, the frame a fresh pass's");
  scene.Render();
  scene.Axes->SetPosition(0.9, 0.1, 1.2);
  Check(!scene.Render() && scene.PixelsOffFresh() == 0,
    "the axes moved: shadows drawn, the frame a fresh pass's");

  // Two lights: moving one draws its shadows alone, against the depth kept from the last frame.
  vtkLight* second = scene.View.PointLight(2.5, 5, -1, 0.2);
  scene.View.Sphere(1.2, 0.3, -1.2, 0.3, 16); // a plain caster: depth from its mesh
  scene.Render();
  scene.Render();
  const vtkIdType depthFromMeshes = pass->GetNumberOfPropsWithDepthFromMeshes();
  second->SetPosition(2.0, 5, -1.6);
  const bool allReused = scene.Render();
  const int oneMoved = pass->GetNumberOfRedrawnLights();
  std::printf("     depth from meshes %lld, then %lld\n", static_cast<long long>(depthFromMeshes),
    static_cast<long long>(pass->GetNumberOfPropsWithDepthFromMeshes()));
  Check(depthFromMeshes > 0 && pass->GetNumberOfPropsWithDepthFromMeshes() == depthFromMeshes,
    "a kept depth keeps its statistics (props with depth from their meshes)");
  const int oneMovedOff = scene.PixelsOffFresh();
  std::printf("     one of two lights moved: %d drawn, %d px off a fresh pass's frame\n", oneMoved,
    oneMovedOff);
  Check(!allReused && oneMoved == 1 && oneMovedOff == 0,
    "one of two lights moved: its shadows alone drawn, the frame a fresh pass's");
  renderer->GetActiveCamera()->Azimuth(5);
  scene.Render();
  const int cameraMoved = pass->GetNumberOfRedrawnLights();
  Check(cameraMoved == 2 && scene.PixelsOffFresh() == 0,
    "the camera moved: both lights' shadows drawn, the frame a fresh pass's");
  scene.Render();
  scene.Sphere->SetPosition(-0.3, 0, 0.2);
  scene.Render();
  Check(pass->GetNumberOfRedrawnLights() == 2 && scene.PixelsOffFresh() == 0,
    "an actor moved: both lights' shadows drawn, the frame a fresh pass's");

  // Whatever an UpdateShaderEvent observer does to the vertices, no pass can see it: drawn.
  vtkNew<vtkCallbackCommand> uniforms;
  scene.Sphere->GetMapper()->AddObserver(vtkCommand::UpdateShaderEvent, uniforms);
  scene.Render();
  Check(!scene.Render(), "a mapper with an UpdateShaderEvent observer: shadows drawn every frame");
  scene.Sphere->GetMapper()->RemoveObservers(vtkCommand::UpdateShaderEvent);

  pass->ReuseUnchangedShadowsOff();
  scene.Render();
  Check(!scene.Render(), "ReuseUnchangedShadows off: shadows drawn every frame");
}

/// An actor whose mapper is given another data object casts the new data's shadow, with every
/// method: what was cached for the old mesh must not pass for the new one's, although the new
/// mesh has been built as often as the old one had (once) and lies about the same centre.
void TestDataObjectSwapped()
{
  const std::vector<std::pair<const char*, int>> methods = {
    { "hard volumes", vtkSoftShadowPass::METHOD_HARD_VOLUMES },
    { "averaged hard shadows", vtkSoftShadowPass::METHOD_AVERAGED_HARD_SHADOWS },
    { "penumbra wedges", vtkSoftShadowPass::METHOD_PENUMBRA_WEDGES },
    { "soft shadow volumes", vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES },
  };
  for (const auto& method : methods)
  {
    PassScene view(200, 150);
    view.Ground();
    vtkActor* caster = view.Sphere(0, 1.2, 0, 0.6, 32);
    view.Camera(3, 4, 7, 0, 0.5, 0);
    const bool hard = method.second == vtkSoftShadowPass::METHOD_HARD_VOLUMES;
    vtkSoftShadowPass::SetLightRadius(view.Light, hard ? 0.0 : 0.3);
    view.Pass->SetMethod(method.second);
    view.Pass->SetLightSamples(16);
    view.Window->Render();
    // Centred where the sphere is, so that the light is where it was relative to the mesh.
    vtkSmartPointer<vtkCubeSource> slab = BoxSource(0, 1.2, 0, 1.8, 0.3, 1.2);
    view.Keep.push_back(slab);
    caster->GetMapper()->SetInputConnection(slab->GetOutputPort());
    view.Window->Render();
    const int off = PixelsOffFreshPass(view);
    std::printf("     %s: %d px off a fresh pass's frame\n", method.first, off);
    Check(
      off == 0, std::string(method.first) + ": the new data's shadow, as a fresh pass draws it");
  }
}

/// An actor that is a part of an assembly and also in the renderer (VTK's own assembly.py test
/// does it) shares the assembly's keys once VTK has drawn it as a part: its shaders are edited
/// once, not once per entry (repeated declarations failed to compile, and VTK crashed).
void TestActorInAssemblyAndRenderer()
{
  PassScene view(200, 150);
  view.Ground();
  vtkActor* shared = view.Sphere(0.0, 1.0, 0.0, 0.5, 24);
  vtkNew<vtkAssembly> assembly;
  assembly->AddPart(shared);
  assembly->SetPosition(1.2, 0.0, 0.0);
  view.Renderer->AddActor(assembly);
  view.Camera(3, 4, 7, 0, 0.5, 0);
  const WarningLog warnings(view.Pass);
  vtkNew<vtkInformation> ownKeys; // the actor's keys before VTK gives it the assembly's
  shared->SetPropertyKeys(ownKeys);
  view.Window->Render(); // the first frame's objects take references of their own
  const int references = view.Pass->GetReferenceCount();
  view.Window->Render(); // a segmentation fault here before the fix
  view.Window->Render();
  const Comparison comparison = view.Render();
  std::printf("     %zu warnings\n", warnings.Messages.size());
  Check(warnings.Messages.empty(), "a part also in the renderer: its shaders edited once");
  const auto keepsPass = [&](vtkInformation* keys)
  {
    vtkInformationObjectBaseVectorKey* passes = vtkOpenGLRenderPass::RenderPasses();
    for (int i = 0; keys && i < keys->Length(passes); ++i)
    {
      if (keys->Get(passes, i) == view.Pass)
      {
        return true;
      }
    }
    return false;
  };
  std::printf("     pass in the actor's own keys %d, its keys now %d, the assembly's %d; "
              "references %d, after the first frame %d\n",
    keepsPass(ownKeys), keepsPass(shared->GetPropertyKeys()),
    keepsPass(assembly->GetPropertyKeys()), view.Pass->GetReferenceCount(), references);
  Check(!keepsPass(ownKeys) && !keepsPass(shared->GetPropertyKeys()) &&
      !keepsPass(assembly->GetPropertyKeys()) && view.Pass->GetReferenceCount() == references,
    "after the frame no keys hold the pass, and it is held no more than after the first");
  CheckAgainstTruth("a part also in the renderer", comparison);

  // A clipping plane in world coordinates cuts each place of it where it stands: the part at
  // x = 1.2 loses its half beyond x = 1.2, the actor at the origin nothing.
  vtkNew<vtkPlane> keepLeft;
  keepLeft->SetOrigin(1.2, 0.0, 0.0);
  keepLeft->SetNormal(-1.0, 0.0, 0.0);
  shared->GetMapper()->AddClippingPlane(keepLeft);
  view.Window->Render();
  CheckAgainstTruth("a clipped part also in the renderer", view.Render());
}

/// A soft shadow pass inside another's delegate chain draws its delegate unshadowed (the outer
/// one shadows the frame) and a pass inside its own chain draws nothing the second time: one
/// warning each, no receiver shader edited twice, no endless recursion.
void TestNestedPasses()
{
  PassScene view(200, 150);
  view.Ground();
  view.Sphere(0, 1, 0, 0.6);
  view.Camera(3, 4, 7, 0, 0.5, 0);
  view.Window->Render();
  const std::vector<unsigned char> alone = WindowColours(view.Window, view.Renderer);
  vtkNew<vtkSoftShadowPass> inner;
  const WarningLog innerLog(inner);
  view.Pass->SetDelegatePass(inner);
  view.Window->Render();
  view.Window->Render();
  const std::vector<unsigned char> nested = WindowColours(view.Window, view.Renderer);
  std::printf("     nested: %lld warnings, frame %s the pass's alone\n",
    static_cast<long long>(innerLog.Count("delegate chain of another")),
    nested == alone ? "equal to" : "unlike");
  Check(nested == alone && view.Pass->GetNumberOfShadowingLights() == 1,
    "a pass inside another's chain: the outer one's shadows, drawn once");
  Check(innerLog.Count("delegate chain of another") == 1, "one warning for the inner pass");

  vtkNew<vtkSoftShadowPass> cyclic;
  const WarningLog cyclicLog(cyclic);
  vtkNew<vtkSequencePass> loop;
  vtkNew<vtkRenderPassCollection> steps;
  steps->AddItem(cyclic);
  loop->SetPasses(steps);
  cyclic->SetDelegatePass(loop);
  view.Renderer->SetPass(cyclic);
  view.Window->Render();
  view.Window->Render();
  Check(cyclicLog.Count("its own delegate chain") == 1,
    "a pass inside its own chain: one warning, no endless recursion");
  // Calls that go down the chain stop where it comes back (a user's trial: a segmentation fault,
  // the stack overflowing in ReleaseGraphicsResources).
  std::ostringstream printed;
  cyclic->Print(printed);
  cyclic->ReleaseGraphicsResources(view.Window);
  view.Window->Render();
  // Two passes delegating to each other: printing stops where the chain comes back.
  vtkNew<vtkSoftShadowPass> partner;
  partner->SetDelegatePass(cyclic);
  cyclic->SetDelegatePass(partner);
  cyclic->Print(printed);
  cyclic->ReleaseGraphicsResources(view.Window);
  Check(printed.str().find("(back to this pass)") != std::string::npos,
    "a pass inside its own chain: printed, released and drawn again without endless recursion");
  cyclic->SetDelegatePass(nullptr); // the cycles hold themselves
  partner->SetDelegatePass(nullptr);
  view.Renderer->SetPass(view.Pass);

  // A pass as its own delegate is refused, with one error.
  const WarningLog errors(view.Pass, vtkCommand::ErrorEvent);
  vtkRenderPass* delegate = view.Pass->GetDelegatePass();
  view.Pass->SetDelegatePass(view.Pass);
  view.Window->Render();
  Check(view.Pass->GetDelegatePass() == delegate && errors.Count("its own delegate") == 1 &&
      view.Pass->GetNumberOfShadowingLights() == 1,
    "a pass set as its own delegate: refused with one error, the frame drawn as before");
}

/// A pass taken off its renderer while its window's context goes (Finalize, or the window
/// deleted), then set again or set in another window: the window released the pass's GPU
/// objects in their own context, so it draws as a fresh pass does. Before, it drew with the
/// dead context's objects: a segmentation fault in Mesa, or lost shadows.
void TestContextGoneWhileDetached()
{
  for (const double radius : { 0.0, 0.3 })
  {
    auto setUp = [radius](PassScene& view)
    {
      view.Ground();
      view.Sphere(0, 1, 0, 0.6);
      view.Camera(3, 4, 7, 0, 0.5, 0);
      vtkSoftShadowPass::SetLightRadius(view.Light, radius);
    };
    PassScene view(200, 150);
    setUp(view);
    view.Window->Render();
    view.Renderer->SetPass(nullptr);
    view.Window->Finalize();
    view.Window->Render();
    view.Renderer->SetPass(view.Pass);
    view.Window->Render();
    const int finalized = PixelsOffFreshPass(view);

    // The pass outlives the window it drew into, then draws into a new one.
    vtkSmartPointer<vtkSoftShadowPass> moved = view.Pass;
    {
      PassScene first(200, 150);
      setUp(first);
      first.Renderer->SetPass(moved);
      first.Window->Render();
      first.Renderer->SetPass(nullptr);
    }
    PassScene second(200, 150);
    setUp(second);
    second.Renderer->SetPass(moved);
    second.Window->Render();
    second.Window->Render();
    const std::vector<unsigned char> shown = WindowColours(second.Window, second.Renderer);
    second.Renderer->SetPass(second.Pass);
    second.Window->Render();
    const bool sameAsFresh = shown == WindowColours(second.Window, second.Renderer);
    std::printf("     radius %.1f: %d px off a fresh pass after Finalize; moved pass %s\n", radius,
      finalized, sameAsFresh ? "equal to a fresh pass" : "unlike a fresh pass");
    Check(finalized == 0 && view.Pass->GetNumberOfShadowingLights() == 1,
      "a pass set again after its window was finalized draws as a fresh pass");
    Check(sameAsFresh, "a pass whose window was deleted draws in a new window as a fresh pass");
  }

  // The default delegate on its own, with FXAA (GPU resources of its own): the same contract.
  PassScene view(200, 150);
  view.Ground();
  view.Sphere(0, 1, 0, 0.6);
  view.Camera(3, 4, 7, 0, 0.5, 0);
  view.Renderer->SetUseFXAA(true);
  vtkNew<vtkRendererSettingsPass> settings;
  view.Renderer->SetPass(settings);
  view.Window->Render();
  view.Renderer->SetPass(nullptr);
  view.Window->Finalize();
  view.Window->Render();
  view.Renderer->SetPass(settings);
  view.Window->Render();
  const std::vector<unsigned char> again = WindowColours(view.Window, view.Renderer);
  vtkNew<vtkRendererSettingsPass> freshSettings;
  view.Renderer->SetPass(freshSettings);
  view.Window->Render();
  Check(again == WindowColours(view.Window, view.Renderer),
    "vtkRendererSettingsPass set again after its window was finalized draws as a fresh one");
}

/// VTK's coverage culler leaves out props too small on screen (MinimumCoverage): such a prop
/// casts nothing, as if it were not there, where before it cast a shadow VTK did not draw it
/// for. A prop culled because it lies outside the view still casts into it.
void TestCulledProps()
{
  for (const double radius : { 0.0, 0.3 })
  {
    PassScene view(200, 150);
    view.Ground();
    view.Box(1.2, 0.6, 0, 1.2, 1.2, 1.2);
    vtkActor* small = view.Sphere(-0.8, 0.6, 0.4, 0.2);
    view.Camera(3, 4, 7, 0, 0.5, 0);
    vtkSoftShadowPass::SetLightRadius(view.Light, radius);
    auto* coverage =
      vtkFrustumCoverageCuller::SafeDownCast(view.Renderer->GetCullers()->GetItemAsObject(0));
    coverage->SetMinimumCoverage(0.05);
    view.Window->Render();
    const bool culled = small->GetRenderTimeMultiplier() == 0.0;
    const std::vector<unsigned char> shown = WindowColours(view.Window, view.Renderer);
    view.Renderer->RemoveActor(small);
    const int offFresh = PixelsOffFreshPass(view);
    const std::vector<unsigned char> without = WindowColours(view.Window, view.Renderer);
    std::printf("     radius %.1f: sphere %s; frame %s the frame without it\n", radius,
      culled ? "culled" : "drawn", shown == without ? "equal to" : "unlike");
    Check(culled && offFresh == 0 && shown == without,
      "a prop the coverage culler leaves out casts nothing: the frame equals one without it");
  }

  // Above the view, between the light and the ground the camera sees.
  PassScene view(200, 150);
  view.Ground();
  vtkActor* high = view.Sphere(-1.5, 4.5, 2.25, 0.4);
  view.Camera(0, 1.5, 6, 0, 0, 0);
  view.Window->Render();
  const bool outside = high->GetRenderTimeMultiplier() == 0.0;
  const std::vector<float> culledView = ImageValues(view.Pass->GetVisibilityImage(0));
  view.Renderer->GetCullers()->RemoveAllItems();
  view.Window->Render();
  const std::vector<float> unculled = ImageValues(view.Pass->GetVisibilityImage(0));
  const auto shadowed = std::count_if(
    culledView.begin(), culledView.end(), [](float visibility) { return visibility < 0.5f; });
  std::printf("     sphere above the view: %s, %lld shadowed px, %d px apart without cullers\n",
    outside ? "culled" : "drawn", static_cast<long long>(shadowed),
    PixelsApart(culledView, unculled));
  Check(outside && shadowed > 50 && PixelsApart(culledView, unculled) == 0,
    "a prop culled outside the view still casts into it");
}

/// A frame wider than 3D textures may be (2048 pixels on llvmpipe and many integrated GPUs) has
/// its shadows, hard and counted, right against the truth: the light-intensity layers and the
/// counters are 2D array textures, as wide as 2D textures. Until 2026-12-06 they were 3D textures
/// and such a frame was drawn unshadowed.
void TestWideFrame()
{
  PassScene view(200, 150);
  view.Window->SetOffScreenRendering(1); // larger than the screen
  view.Ground(8.0);
  for (int i = -3; i <= 3; ++i)
  {
    view.Sphere(2.0 * i, 1.0, 0.0, 0.6, 24);
  }
  view.Window->Render();
  view.Window->MakeCurrent();
  GLint max3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  const int width = std::min(max3D + 64, 4160);
  view.Window->SetSize(width, 120);
  // A long, flat view along the row of spheres, the light above it.
  view.Light->SetPosition(0, 9, 3);
  view.Camera(0, 3.5, 11, 0, 0.5, 0);
  view.Renderer->GetActiveCamera()->SetViewAngle(12);
  const WarningLog log(view.Pass);
  for (const double radius : { 0.0, 0.3 })
  {
    vtkSoftShadowPass::SetLightRadius(view.Light, radius);
    view.Pass->SetMethod(radius > 0.0 ? vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES
                                      : vtkSoftShadowPass::METHOD_HARD_VOLUMES);
    const Comparison comparison = view.Render();
    std::printf("     %dx120 (3D textures reach %d), radius %.1f: %d shadowing lights\n", width,
      max3D, radius, view.Pass->GetNumberOfShadowingLights());
    Check(view.Pass->GetNumberOfShadowingLights() == 1, "a frame wider than 3D textures shadows");
    CheckAgainstTruth(
      std::string("wide frame, ") + (radius > 0.0 ? "counted" : "hard"), comparison, 0.005);
  }
  Check(log.Messages.empty(), "no warning for a frame that fits 2D textures");
}

/// Buffers OpenGL refuses for memory (GL_OUT_OF_MEMORY; llvmpipe refuses a texture of about
/// 1.7 GB): a counted light whose counters do not fit averages the same samples, and a frame
/// whose light-intensity layers do not fit is drawn unshadowed, each with one warning. Before,
/// the first silently drew the centre's hard shadow and the second a black frame. Where the GPU
/// allocates them, the test says so and checks that they were used.
void TestRefusedAllocations()
{
  PassScene view(200, 150, PassScene::StartLight::None);
  view.Window->SetOffScreenRendering(1); // larger than the screen
  view.Ground(4.0);
  view.Sphere(0, 1, 0, 0.6, 32);
  view.Camera(3, 5, 8, 0, 0.5, 0);
  vtkLight* key = view.PointLight(-2, 6, 3, 0.4);
  const WarningLog log(view.Pass);

  // 4K with 256 samples: 64 counter words a pixel, 2 GB.
  view.Window->SetSize(3840, 2160);
  view.Pass->SetMethod(vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES);
  view.Pass->SetLightSamples(256);
  view.Window->Render();
  const std::vector<float> soft = ImageValues(view.Pass->GetVisibilityImage(0));
  const auto penumbra =
    std::count_if(soft.begin(), soft.end(), [](float v) { return v > 0.001f && v < 0.999f; });
  const bool counted = view.Pass->GetNumberOfCountedLights() == 1;
  std::printf("     3840x2160, 256 samples: %s, %lld penumbra px, %lld warnings\n",
    counted ? "counted" : "averaged", static_cast<long long>(penumbra),
    static_cast<long long>(log.Count("refused")));
  Check(penumbra > static_cast<long long>(soft.size() / 400),
    "counters too large for OpenGL: soft shadows all the same (averaged), not the hard one");
  Check(counted ? log.Messages.empty() : log.Count("sample counters for 256 light samples") == 1,
    "refused counters: one warning saying so");
  view.Window->Render();
  Check(log.Messages.size() == (counted ? 0u : 1u), "the warning is not repeated every frame");

  // 8K with 14 hard lights: 14 float layers, 1.8 GB.
  key->SetIntensity(1.0 / 14);
  vtkSoftShadowPass::SetLightRadius(key, 0.0);
  for (int i = 1; i < 14; ++i)
  {
    const double angle = 2.0 * vtkMath::Pi() * i / 14;
    view.PointLight(4 * std::cos(angle), 6, 4 * std::sin(angle), 0.0)->SetIntensity(1.0 / 14);
  }
  view.Pass->SetMethod(vtkSoftShadowPass::METHOD_HARD_VOLUMES);
  view.Window->SetSize(7680, 4320);
  view.Window->Render();
  const int lights = view.Pass->GetNumberOfShadowingLights();
  const std::vector<unsigned char> shown = WindowColours(view.Window, view.Renderer);
  const bool lit = std::count(shown.begin(), shown.end(), 0) < static_cast<long>(shown.size() / 2);
  // Where the layers were drawn, the first light's shadow is a small part of the view.
  const std::vector<float> first =
    lights ? ImageValues(view.Pass->GetVisibilityImage(0)) : std::vector<float>();
  const auto dark = std::count_if(first.begin(), first.end(), [](float v) { return v < 0.5f; });
  std::printf("     7680x4320, 14 lights: %d shadowing, frame %s, %lld px of light 0 shadowed\n",
    lights, lit ? "lit" : "black", static_cast<long long>(dark));
  Check(lit && dark <= static_cast<long long>(first.size() / 10),
    "layers too large for OpenGL: neither a black frame nor a light shadowing everything");
  Check(lights == 14 || (lights == 0 && log.Count("light intensity for 14 lights") == 1),
    "refused layers: drawn unshadowed with one warning");
  view.Window->SetSize(200, 150);
  view.Window->Render();
  Check(view.Pass->GetNumberOfShadowingLights() == 14, "a frame that fits has its shadows again");
}

/// The tight depth range draws the shadows with a copy of the camera: the user's camera is not
/// modified, so a pipeline that depends on it (vtkDepthSortPolyData) does not run again and a
/// still scene reuses its shadows. The copy is made active only while VTK draws props into the
/// shadows' depth (the ground, which casts nothing, is such a prop).
void TestCameraLeftAlone()
{
  PassScene view;
  vtkActor* ground = view.Ground();
  vtkSoftShadowPass::SetCastsShadows(ground, false);
  vtkNew<vtkDepthSortPolyData> sorted;
  sorted->SetInputConnection(SphereSource(0, 1, 0, 0.6, 32, 16)->GetOutputPort());
  view.Camera(3, 4, 7, 0, 0.5, 0);
  vtkCamera* camera = view.Renderer->GetActiveCamera();
  sorted->SetCamera(camera);
  view.Add(sorted, 0.9, 0.3, 0.3);

  int cameraModified = 0;
  int activeCameraSwaps = 0;
  const auto count = [](vtkObject*, unsigned long, void* counter, void*)
  { ++*static_cast<int*>(counter); };
  vtkNew<vtkCallbackCommand> countModified;
  countModified->SetClientData(&cameraModified);
  countModified->SetCallback(count);
  camera->AddObserver(vtkCommand::ModifiedEvent, countModified);
  vtkNew<vtkCallbackCommand> countSwaps;
  countSwaps->SetClientData(&activeCameraSwaps);
  countSwaps->SetCallback(count);
  view.Renderer->AddObserver(vtkCommand::ActiveCameraEvent, countSwaps);

  view.Window->Render(); // the first frame gives the props their keys, which modifies them
  const int firstSwaps = activeCameraSwaps;
  view.Window->Render();
  const vtkMTimeType sortedTime = sorted->GetOutput()->GetMTime();
  const vtkIdType reusedBefore = view.Pass->GetNumberOfReusedFrames();
  for (int frame = 0; frame < 3; ++frame)
  {
    view.Window->Render();
  }
  const vtkIdType reused = view.Pass->GetNumberOfReusedFrames() - reusedBefore;
  std::printf("     camera modified %d times, active camera swapped %d times (first frame %d), "
              "%lld of 3 still frames reused\n",
    cameraModified, activeCameraSwaps, firstSwaps, static_cast<long long>(reused));
  Check(firstSwaps == 2, "the first frame draws the ground's depth with the shadows' camera");
  Check(cameraModified == 0, "the shadows leave the user's camera unmodified");
  Check(view.Renderer->GetActiveCamera() == camera, "the user's camera is active after a frame");
  Check(sorted->GetOutput()->GetMTime() == sortedTime,
    "a pipeline that depends on the camera does not run again in a still scene");
  Check(reused == 3, "a still scene with a camera-dependent pipeline reuses its shadows");

  camera->Azimuth(10);
  cameraModified = 0;
  view.Window->Render();
  Check(cameraModified == 0, "a moved camera is not modified by the frame that follows");
}
} // namespace

int main(int argc, char* argv[])
{
  static const Features features = {
    { "CachingAndHeadlights", TestCachingAndHeadlights },
    { "Compositing", TestCompositing },
    { "ViewportsLightsAndResize", TestViewportsLightsAndResize },
    { "DelegateChain", TestDelegateChain },
    { "BadInput", TestBadInput },
    { "Picking", TestPicking },
    { "TwoWindows", TestTwoWindows },
    { "LightReachingScene", TestLightReachingScene },
    { "LightRecordsFollowLights", TestLightRecordsFollowLights },
    { "ReuseUnchangedShadows", TestReuseUnchangedShadows },
    { "SecondFrameReused", TestSecondFrameReused },
    { "CameraLeftAlone", TestCameraLeftAlone },
    { "DataObjectSwapped", TestDataObjectSwapped },
    { "ActorInAssemblyAndRenderer", TestActorInAssemblyAndRenderer },
    { "WideFrame", TestWideFrame },
    { "NestedPasses", TestNestedPasses },
    { "ContextGoneWhileDetached", TestContextGoneWhileDetached },
    { "CulledProps", TestCulledProps },
    { "RefusedAllocations", TestRefusedAllocations },
  };
  return RunFeatures(argc, argv, features);
}
