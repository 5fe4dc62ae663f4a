// Translucent casters: each of their surfaces between a point and a light sample lets
// 1 - opacity of that sample through, in the pass (hard, averaged and counted shadows) as in
// the ray tracer's transmission. A closed sphere of opacity a lets (1 - a)^2 through, a single
// sheet 1 - a; a translucent caster in an opaque one's shadow changes nothing there.
// Translucent surfaces receive nothing: they are drawn lit over the shadowed surface behind.
//
// Tolerances: with a point light (hard shadows) at most 0.2% of the compared pixels differ from
// the truth by more than 0.02 away from shadow boundaries (the truth's own 1-pixel boundary
// band is left out, as in CompareWithTruth); with a soft light averaging 16 samples the MAE
// against a 256-ray truth is at most 0.03 and at most that of the same scene's opaque shadow
// plus 0.01. Counting the same samples differs from averaging them on at most 0.3% of the
// shadowed pixels (by more than 1e-3; measured 0.00%), with 16 and 10 samples and with a
// directional light.
#include "penumbraTestHarness.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkTexture.h"

#include <glm/glm.hpp>

#include <algorithm>

using namespace penumbra_test;

namespace
{
constexpr int Width = 320, Height = 240;

/// Ground, an opaque box, a translucent sphere and a translucent open sheet above the ground,
/// and a small translucent sphere in the box's shadow.
struct GlassScene : PassScene
{
  vtkActor* Glass = nullptr;
  vtkActor* Sheet = nullptr;

  explicit GlassScene(double opacity)
    : PassScene(Width, Height)
  {
    this->Ground();
    this->Box(1.3, 0.6, 0.2, 0.8, 1.2, 0.8)->GetProperty()->SetOpacity(1.0);
    this->Glass = this->Sphere(-1.0, 1.4, 0.0, 0.6);
    this->Glass->GetProperty()->SetOpacity(opacity);
    this->Sheet = this->Add(GroundSource(0.5), 0.4, 0.8, 0.4);
    this->Sheet->SetPosition(0.3, 2.0, -1.4);
    this->Sheet->GetProperty()->SetOpacity(opacity);
    this->Sphere(2.2, 0.3, -0.4, 0.25)->GetProperty()->SetOpacity(opacity);
    this->Camera(3.0, 5.0, 8.0, 0.0, 0.5, 0.0);
  }
};

struct Agreement
{
  int Compared = 0;
  int Off = 0; ///< off by more than the tolerance from every truth value next to it (3x3)
  double MAE = 0.0;
  int Partial = 0; ///< compared pixels the truth sees partly lit (translucent shadow)
};

/// The pass's visibility against a fresh truth of `rays` rays, where both see the same surface
/// and no object silhouette is next to it (penumbra::metrics::ComparablePixels).
Agreement CompareTruth(PassScene& scene, int rays, float tolerance)
{
  scene.Window->Render();
  const std::vector<float> pass = ImageValues(scene.Pass->GetVisibilityImage(0));
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(scene.Renderer);
  truth->SetSamplesPerLight(rays);
  Agreement result;
  if (!truth->Update())
  {
    Check(false, "ray tracer ran");
    return result;
  }
  const std::vector<float> expected = ImageValues(truth->GetVisibilityImage(0));
  const std::vector<float> zbuffer = WindowDepth(scene.Window, scene.Renderer);
  const std::vector<char> comparable = penumbra::metrics::ComparablePixels(
    ImageValues(truth->GetDepthImage()), zbuffer, Width, Height);
  for (std::size_t p = 0; p < comparable.size(); ++p)
  {
    if (!comparable[p])
    {
      continue;
    }
    ++result.Compared;
    result.Partial += expected[p] > 0.05f && expected[p] < 0.95f;
    result.Off += std::abs(pass[p] - expected[p]) > tolerance &&
      !penumbra::metrics::NearTruthValue(expected, Width, p, pass[p], tolerance);
  }
  result.MAE = VisibilityError(pass, truth, 0, zbuffer).MAE;
  return result;
}

/// The visibility the pass gives at the pixel where `point` projects.
float VisibilityAt(GlassScene& scene, double x, double y, double z)
{
  scene.Renderer->SetWorldPoint(x, y, z, 1.0);
  scene.Renderer->WorldToDisplay();
  const double* display = scene.Renderer->GetDisplayPoint();
  const std::vector<float> pass = ImageValues(scene.Pass->GetVisibilityImage(0));
  const int px = static_cast<int>(display[0]), py = static_cast<int>(display[1]);
  return pass[static_cast<std::size_t>(py) * Width + px];
}

/// Adds an actor drawing a sphere (centre, radius) as the one block of a multiblock under a
/// vtkCompositePolyDataMapper2, the block's opacity set and the actor's property given another.
vtkActor* AddSphereBlock(
  PassScene& scene, const glm::dvec4& sphere, double blockOpacity, double actorOpacity)
{
  auto source = SphereSource(sphere.x, sphere.y, sphere.z, sphere.w, 32, 16);
  source->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, source->GetOutputDataObject(0));
  vtkNew<vtkCompositePolyDataMapper2> mapper;
  mapper->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  attributes->SetBlockOpacity(source->GetOutputDataObject(0), blockOpacity);
  mapper->SetCompositeDataDisplayAttributes(attributes);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetOpacity(actorOpacity);
  scene.Renderer->AddActor(actor);
  return actor;
}

/// A point light: the sphere's shadow lets (1 - a)^2 through, the sheet's 1 - a, and both
/// agree with the truth; a change of opacity shows in the next frame.
void TestHardShadows()
{
  GlassScene scene(0.5);
  scene.Pass->SetMethodToHardVolumes();
  for (const double opacity : { 0.5, 0.8 })
  {
    scene.Glass->GetProperty()->SetOpacity(opacity);
    scene.Sheet->GetProperty()->SetOpacity(opacity);
    const Agreement agreement = CompareTruth(scene, 1, 0.02f);
    std::printf("hard, opacity %.1f: compared %d px (%d partly lit), %d off by > 0.02, MAE %.4f\n",
      opacity, agreement.Compared, agreement.Partial, agreement.Off, agreement.MAE);
    Check(agreement.Partial > agreement.Compared / 100, "translucent shadows in view");
    Check(agreement.Off <= agreement.Compared / 500, "hard translucent shadows match the truth");
    // Where the ray from the light through the sphere's centre meets the ground: two surfaces
    // in the way.
    const glm::dvec3 light(-2, 6, 3), centre(-1.0, 1.4, 0.0);
    const glm::dvec3 onGround = light + (centre - light) * (6.0 / (6.0 - 1.4));
    const float below = VisibilityAt(scene, onGround.x, 0.0, onGround.z);
    const double expected = (1.0 - opacity) * (1.0 - opacity);
    std::printf("  under the sphere: %.4f, expected %.4f\n", below, expected);
    Check(std::abs(below - expected) < 0.01, "a closed translucent sphere lets (1 - a)^2 through");
  }
}

/// A translucent sheet lying in an opaque box's top face, triangulated otherwise (a
/// segmentation's translucent label on an opaque one): the face is not behind the sheet, as
/// the truth starts its rays off the surface, and reads lit evenly; its sides, under the
/// sheet's overhang, let 1 - a through. Before, the sheet's caps z-fought with the face.
void TestSheetOnOpaqueFace()
{
  PassScene scene(Width, Height);
  scene.Pass->SetMethodToHardVolumes();
  scene.Ground();
  scene.Box(0.0, 0.5, 0.0, 1.6, 1.0, 1.2)->GetProperty()->SetOpacity(1.0);
  vtkNew<vtkPlaneSource> sheet;
  sheet->SetOrigin(-1.3, 1.0, -1.1);
  sheet->SetPoint1(1.1, 1.0, -1.1);
  sheet->SetPoint2(-1.3, 1.0, 0.9);
  sheet->SetResolution(7, 7);
  scene.Add(sheet, 0.3, 0.5, 0.9)->GetProperty()->SetOpacity(0.3);
  scene.Camera(1.0, 4.0, 4.0, 0.0, 0.6, 0.0);
  const Agreement agreement = CompareTruth(scene, 1, 0.02f);
  std::printf("sheet on a face: compared %d px (%d partly lit), %d off by > 0.02\n",
    agreement.Compared, agreement.Partial, agreement.Off);
  Check(agreement.Partial > agreement.Compared / 20, "the sheet's shadow in view");
  Check(
    agreement.Off <= agreement.Compared / 500, "a sheet on an opaque face shadows as the truth");
}

/// Looking through the glass sphere at its own shadow (the eye behind the light): z-pass must
/// count the sphere's own surface, which lies between the eye and the shadowed ground.
void TestSeenThroughCaster()
{
  GlassScene scene(0.5);
  scene.Pass->SetMethodToHardVolumes();
  const glm::dvec3 light(-2, 6, 3), centre(-1.0, 1.4, 0.0);
  const glm::dvec3 eye = light + 0.6 * (light - centre);
  scene.Camera(eye.x, eye.y, eye.z, centre.x, centre.y, centre.z);
  const Agreement agreement = CompareTruth(scene, 1, 0.02f);
  std::printf("through the glass: compared %d px (%d partly lit), %d off by > 0.02\n",
    agreement.Compared, agreement.Partial, agreement.Off);
  Check(scene.Pass->GetNumberOfZFailVolumes() == 0, "the view through the glass is z-pass");
  Check(agreement.Partial > agreement.Compared / 20, "the shadow is seen through the glass");
  Check(agreement.Off <= agreement.Compared / 500, "a shadow seen through its caster is right");
}

/// Translucent surfaces receive nothing: a translucent sheet above the box's shadow on the
/// ground is drawn lit, blended over the shadowed ground. The sheet is a translucent block of a
/// composite actor whose other block is opaque (a small cube away from it), so that the actor
/// is a receiver and its translucent fragments are drawn with the shadows switched off. The
/// sheet's colour over the shadow is what it adds alone over a black background plus (1 - a)
/// times the ground without it, within 3 of 255 in each channel on 99% of its inner pixels
/// there; a sheet that read the ground's visibility would be darker by a times its own colour
/// times the shadow's depth.
void TestTranslucentReceivesNothing()
{
  PassScene scene(Width, Height);
  scene.Renderer->SetBackground(0.0, 0.0, 0.0);
  scene.Pass->SetMethodToHardVolumes();
  vtkActor* ground = scene.Ground();
  vtkActor* box = scene.Box(1.3, 0.6, 0.2, 0.8, 1.2, 0.8);
  auto sheetSource = GroundSource(1.0);
  sheetSource->SetCenter(2.6, 2.5, 3.6);
  auto cubeSource = BoxSource(-3.0, 0.1, -3.0, 0.2, 0.2, 0.2);
  vtkNew<vtkMultiBlockDataSet> blocks;
  for (vtkPolyDataAlgorithm* source : { static_cast<vtkPolyDataAlgorithm*>(sheetSource),
         static_cast<vtkPolyDataAlgorithm*>(cubeSource) })
  {
    source->Update();
    blocks->SetBlock(blocks->GetNumberOfBlocks(), source->GetOutputDataObject(0));
  }
  vtkNew<vtkCompositePolyDataMapper2> mapper;
  mapper->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  attributes->SetBlockOpacity(blocks->GetBlock(0), 0.5);
  mapper->SetCompositeDataDisplayAttributes(attributes);
  vtkNew<vtkActor> sheet;
  sheet->SetMapper(mapper);
  sheet->GetProperty()->SetColor(0.9, 0.9, 0.3);
  scene.Renderer->AddActor(sheet);
  vtkSoftShadowPass::SetCastsShadows(sheet, false);
  scene.Camera(3.0, 5.0, 8.0, 0.0, 0.5, 0.0);

  scene.Window->Render();
  const std::vector<unsigned char> blended = WindowColours(scene.Window, scene.Renderer);
  sheet->VisibilityOff();
  scene.Window->Render();
  const std::vector<unsigned char> behind = WindowColours(scene.Window, scene.Renderer);
  const std::vector<float> visibility = ImageValues(scene.Pass->GetVisibilityImage(0));
  sheet->VisibilityOn();
  ground->VisibilityOff();
  box->VisibilityOff();
  scene.Window->Render();
  const std::vector<unsigned char> alone = WindowColours(scene.Window, scene.Renderer);

  int compared = 0, off = 0;
  double darkest = 1.0;
  for (int y = 1; y + 1 < Height; ++y)
  {
    for (int x = 1; x + 1 < Width; ++x)
    {
      const int i = y * Width + x;
      bool inner = visibility[i] < 0.5f;
      for (int dy = -1; dy <= 1; ++dy)
      {
        for (int dx = -1; dx <= 1; ++dx)
        {
          inner = inner && alone[3 * (i + dy * Width + dx)] > 0; // the sheet covers it
        }
      }
      if (!inner)
      {
        continue;
      }
      ++compared;
      darkest = std::min(darkest, double(visibility[i]));
      bool differs = false;
      for (int c = 0; c < 3; ++c)
      {
        const double expected = alone[3 * i + c] + 0.5 * behind[3 * i + c];
        differs = differs || std::abs(blended[3 * i + c] - expected) > 3.0;
      }
      off += differs;
    }
  }
  std::printf("translucent sheet over the shadow: %d px (visibility down to %.2f), %d differ "
              "from the sheet alone blended over the ground\n",
    compared, darkest, off);
  Check(compared > 500, "the sheet is seen over the box's shadow");
  Check(off <= compared / 100, "a translucent surface is drawn unshadowed over the shadow");
}

/// Opacity as VTK draws it: a block's opacity replaces its actor's (vtkCompositePolyDataMapper2:
/// a block of 0.5 under an actor of 0.5 is drawn at 0.5, not 0.25), and ForceOpaque draws a
/// translucent actor opaque, with a full shadow.
void TestOpacityAsVTKDrawsIt()
{
  GlassScene scene(0.5);
  scene.Pass->SetMethodToHardVolumes();
  scene.Glass->ForceOpaqueOn(); // opacity 0.5, drawn opaque
  // The actor's 0.5 is replaced by the block's 0.5, not multiplied.
  AddSphereBlock(scene, glm::dvec4(1.3, 1.4, -1.8, 0.4), 0.5, 0.5);
  const Agreement agreement = CompareTruth(scene, 1, 0.02f);
  const glm::dvec3 light(-2, 6, 3);
  auto under = [&](const glm::dvec3& centre)
  {
    const glm::dvec3 onGround = light + (centre - light) * (light.y / (light.y - centre.y));
    return VisibilityAt(scene, onGround.x, 0.0, onGround.z);
  };
  const float forced = under({ -1.0, 1.4, 0.0 }), block = under({ 1.3, 1.4, -1.8 });
  std::printf("as VTK draws it: under the ForceOpaque sphere %.3f, under the block %.3f; "
              "%d of %d px off the truth\n",
    forced, block, agreement.Off, agreement.Compared);
  Check(forced < 0.01f, "a ForceOpaque actor casts a full shadow");
  Check(std::abs(block - 0.25f) < 0.01f, "a block's opacity replaces its actor's");
  Check(agreement.Off <= agreement.Compared / 500, "and the truth agrees");
}

/// A block VTK draws translucent for its colours' alpha (a lookup table), at an opacity of 1,
/// casts as a plain actor drawn so does: opaque, with one warning, onto the ground seen through
/// it too. The volumes take a caster missing from the depth as seen through; taken for opaque,
/// it left the ground behind the block lit (8,678 px shadowed as an actor, 25 as a block, in a
/// user trial). The table is left for VTK to build, and the actor has an opaque texture with
/// an alpha channel (so that its look is recorded by its times, not read first through VTK's
/// own translucency check): the pass must not ask the table before it is built, which left VTK
/// itself drawing the block opaque.
void TestBlocksSeenThroughByColours()
{
  const auto shadowOf = [](bool asBlock, std::ptrdiff_t& warnings, bool& drawnTranslucent)
  {
    PassScene scene(Width, Height);
    scene.Ground();
    vtkSmartPointer<vtkPlaneSource> shape = GroundSource(0.8, 0.8);
    shape->Update();
    vtkNew<vtkPolyData> sheet;
    sheet->DeepCopy(shape->GetOutput());
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfValues(sheet->GetNumberOfPoints());
    values->Fill(0.5);
    sheet->GetPointData()->SetScalars(values);
    vtkNew<vtkLookupTable> tints;
    tints->SetAlphaRange(0.4, 0.4);
    vtkSmartPointer<vtkMapper> mapper;
    if (asBlock)
    {
      vtkNew<vtkMultiBlockDataSet> blocks;
      blocks->SetBlock(0, sheet);
      auto composite = vtkSmartPointer<vtkCompositePolyDataMapper2>::New();
      composite->SetInputDataObject(blocks);
      mapper = composite;
    }
    else
    {
      auto plain = vtkSmartPointer<vtkPolyDataMapper>::New();
      plain->SetInputData(sheet);
      mapper = plain;
    }
    mapper->SetLookupTable(tints);
    mapper->SetScalarRange(0.0, 1.0);
    vtkNew<vtkImageData> white; // an opaque RGBA texture: an alpha channel, all of it 255
    white->SetDimensions(2, 2, 1);
    white->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
    std::fill_n(static_cast<unsigned char*>(white->GetScalarPointer()), 16, 255);
    vtkNew<vtkTexture> texture;
    texture->SetInputData(white);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(texture);
    scene.Renderer->AddActor(actor);
    scene.Pass->SetMethodToHardVolumes();
    scene.Camera(1.0, 4.0, 3.0, 0.0, 0.0, 0.0);
    const WarningLog log(scene.Pass);
    scene.Window->Render();
    warnings = log.Count("translucent with an opacity of 1");
    drawnTranslucent = actor->HasTranslucentPolygonalGeometry();
    return ImageValues(scene.Pass->GetVisibilityImage(0));
  };
  std::ptrdiff_t actorWarnings = 0, blockWarnings = 0;
  bool actorTranslucent = false, blockTranslucent = false;
  const std::vector<float> asActor = shadowOf(false, actorWarnings, actorTranslucent);
  const std::vector<float> asBlock = shadowOf(true, blockWarnings, blockTranslucent);
  Check(actorTranslucent && blockTranslucent, "VTK draws both translucent, as asked");
  const auto shadowed = [](const std::vector<float>& v)
  { return std::count_if(v.begin(), v.end(), [](float x) { return x < 0.5f; }); };
  const int apart = PixelsApart(asActor, asBlock);
  std::printf("a sheet translucent by its colours: %ld px shadowed as an actor, %ld as a block, "
              "%d px apart; warnings %ld and %ld\n",
    static_cast<long>(shadowed(asActor)), static_cast<long>(shadowed(asBlock)), apart,
    static_cast<long>(actorWarnings), static_cast<long>(blockWarnings));
  Check(shadowed(asActor) > Width * Height / 20 && apart <= Width * Height / 500,
    "a block translucent by its colours casts as such an actor does, behind itself too");
  Check(actorWarnings == 1 && blockWarnings == 1,
    "each is warned of once: its shadow takes the opacity, 1");
}

/// A block of opacity 1 in an actor of opacity 0.5: VTK draws opaque blocks in its opaque pass
/// only, which it skips for an actor it takes for translucent, so the block is drawn nowhere,
/// and casts nothing.
void TestOpaqueBlockOfTranslucentActor()
{
  PassScene scene(Width, Height);
  scene.Ground();
  scene.Camera(3.0, 5.0, 8.0, 0.0, 0.5, 0.0);
  scene.Pass->SetMethodToHardVolumes();
  vtkActor* actor = AddSphereBlock(scene, glm::dvec4(0.0, 1.2, 0.0, 0.5), 1.0, 0.5);
  scene.Window->Render();
  const std::vector<unsigned char> shown = WindowColours(scene.Window, scene.Renderer);
  const std::vector<float> visibility = ImageValues(scene.Pass->GetVisibilityImage(0));
  vtkNew<vtkRayTracedVisibility> truth;
  truth->SetRenderer(scene.Renderer);
  Check(truth->Update(), "ray tracer ran");
  const std::vector<float> expected = ImageValues(truth->GetVisibilityImage(0));
  actor->VisibilityOff();
  scene.Window->Render();
  const std::vector<unsigned char> hidden = WindowColours(scene.Window, scene.Renderer);
  const auto shadowed =
    std::count_if(visibility.begin(), visibility.end(), [](float v) { return v < 0.99f; });
  std::printf("an opaque block of a translucent actor: frame %s the frame without it, %ld px "
              "shadowed\n",
    shown == hidden ? "equals" : "differs from", static_cast<long>(shadowed));
  Check(shown == hidden, "VTK draws an opaque block of a translucent actor nowhere");
  Check(shadowed == 0 &&
      std::none_of(expected.begin(), expected.end(), [](float v) { return v < 0.99f; }),
    "and it casts nothing, in the pass and in the truth");
}

/// Counting against averaging with a partial last counter word (10 samples) and with a
/// directional light, translucent casters included: the same limits as with 16 samples.
void CheckCountingVariants(GlassScene& scene)
{
  struct Variant
  {
    const char* Name;
    int Samples;
    bool Directional;
    double Radius; ///< world units, or degrees
  };
  for (const Variant& variant :
    { Variant{ "10 samples", 10, false, 0.4 }, Variant{ "directional, 3 degrees", 16, true, 3.0 } })
  {
    scene.Light->SetPositional(!variant.Directional);
    vtkSoftShadowPass::SetLightRadius(scene.Light, variant.Radius);
    scene.Pass->SetLightSamples(variant.Samples);
    scene.Pass->SetMethodToAveragedHardShadows();
    scene.Window->Render();
    const std::vector<float> averaged = ImageValues(scene.Pass->GetVisibilityImage(0));
    scene.Pass->SetMethodToSoftShadowVolumes();
    scene.Window->Render();
    const SampleAgreement agreement = CompareSampledVisibility(
      averaged, ImageValues(scene.Pass->GetVisibilityImage(0)), variant.Samples);
    std::printf("counted, %s: of %d shadowed px %.2f%% differ from averaging by more than 1/N, "
                "%.2f%% at all\n",
      variant.Name, agreement.Shadowed, 100.0 * agreement.Step, 100.0 * agreement.Any);
    Check(scene.Pass->GetNumberOfCountedLights() == 1 && agreement.Shadowed > Width * Height / 50,
      std::string(variant.Name) + ": counted, with shadow in view");
    Check(agreement.Step <= 0.003 && agreement.Half <= 0.0005 && agreement.Any <= 0.003,
      std::string(variant.Name) + ": counting equals averaging the same samples");
  }
  scene.Light->SetPositional(true);
}

/// A soft light averaging 16 samples against a 256-ray truth; the counting method counts the
/// opaque casters and multiplies each visible sample by the translucent casters' transmission,
/// equal to averaging within the counting's tolerance (TestSoftShadowVolumes: at most 0.3% of
/// the shadowed pixels off by more than 1/N, 0.05% by more than 0.5); wedges leave translucent
/// casters out with one warning.
void TestSoftShadows()
{
  GlassScene scene(0.5);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 0.4);
  scene.Pass->SetLightSamples(16);
  const WarningLog log(scene.Pass);
  auto count = [&](const std::string& needle) { return log.Count(needle); };

  scene.Pass->SetMethodToAveragedHardShadows();
  const Agreement averaged = CompareTruth(scene, 256, 0.1f);
  const std::vector<float> averagedImage = ImageValues(scene.Pass->GetVisibilityImage(0));
  for (vtkActor* glass : { scene.Glass, scene.Sheet })
  {
    glass->GetProperty()->SetOpacity(1.0);
  }
  const Agreement opaque = CompareTruth(scene, 256, 0.1f);
  for (vtkActor* glass : { scene.Glass, scene.Sheet })
  {
    glass->GetProperty()->SetOpacity(0.5);
  }
  std::printf("averaged 16: MAE %.4f (the same scene opaque: %.4f), %d partly lit px\n",
    averaged.MAE, opaque.MAE, averaged.Partial);
  Check(averaged.MAE <= 0.03 && averaged.MAE <= opaque.MAE + 0.01,
    "averaged translucent shadows as accurate as opaque ones");

  scene.Pass->SetMethodToSoftShadowVolumes();
  const Agreement counted = CompareTruth(scene, 256, 0.1f);
  Check(scene.Pass->GetNumberOfAveragedLights() == 0 && scene.Pass->GetNumberOfCountedLights() == 1,
    "soft shadow volumes count a light that translucent casters shadow");
  const SampleAgreement agreement =
    CompareSampledVisibility(averagedImage, ImageValues(scene.Pass->GetVisibilityImage(0)), 16);
  std::printf("counted 16: MAE %.4f; of %d shadowed px %.2f%% differ from averaging by more than "
              "1/N, %.2f%% by more than 0.5, %.2f%% at all\n",
    counted.MAE, agreement.Shadowed, 100.0 * agreement.Step, 100.0 * agreement.Half,
    100.0 * agreement.Any);
  Check(agreement.Step <= 0.003 && agreement.Half <= 0.0005 && agreement.Any <= 0.003,
    "counting with translucent casters equals averaging the same samples");
  Check(counted.MAE <= averaged.MAE + 0.01, "and is as accurate");
  const vtkIdType updates = scene.Pass->GetNumberOfSilhouetteUpdates();
  scene.Window->Render();
  Check(scene.Pass->GetNumberOfSilhouetteUpdates() == updates,
    "a steady frame rebuilds no translucent caster's volumes");

  CheckCountingVariants(scene);
  scene.Pass->SetLightSamples(16);
  vtkSoftShadowPass::SetLightRadius(scene.Light, 0.4);

  scene.Pass->SetMethodToAutomatic();
  scene.Window->Render();
  Check(CompareSampledVisibility(averagedImage, ImageValues(scene.Pass->GetVisibilityImage(0)), 16)
          .Step <= 0.003,
    "Automatic gives the same shadows");
  // More samples than counting takes: Automatic counts 256 of them here, and a steady frame
  // rebuilds no translucent caster's volumes.
  scene.Pass->SetLightSamples(300);
  scene.Window->Render();
  const vtkIdType manySamples = scene.Pass->GetNumberOfSilhouetteUpdates();
  scene.Window->Render();
  Check(scene.Pass->GetNumberOfSilhouetteUpdates() == manySamples,
    "300 samples under Automatic: a steady frame rebuilds nothing");
  Check(count("translucent") == 0, "neither warns about translucent casters");

  scene.Pass->SetMethodToPenumbraWedges();
  scene.Window->Render();
  scene.Window->Render();
  Check(count("leave translucent casters out") == 1, "one warning that wedges leave them out");
}
} // namespace

int main()
{
  TestHardShadows();
  TestSeenThroughCaster();
  TestSheetOnOpaqueFace();
  TestTranslucentReceivesNothing();
  TestOpacityAsVTKDrawsIt();
  TestBlocksSeenThroughByColours();
  TestOpaqueBlockOfTranslucentActor();
  TestSoftShadows();
  return penumbra_test::Finish();
}
