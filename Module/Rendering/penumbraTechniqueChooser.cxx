#include "penumbraTechniqueChooser.h"

#include "penumbraLightSamples.h"

#include "vtkLight.h"
#include "vtkSoftShadowPass.h"

namespace penumbra
{

TechniqueChooser::LightRecord& TechniqueChooser::Record(vtkLight* light)
{
  auto found = this->Records.find(light);
  if (found != this->Records.end() && found->second.Light == light)
  {
    return found->second;
  }
  for (auto it = this->Records.begin(); it != this->Records.end();)
  {
    it = it->second.Light ? std::next(it) : this->Records.erase(it);
  }
  LightRecord& record = this->Records[light];
  record = LightRecord();
  record.Light = light;
  return record;
}

bool TechniqueChooser::CountsCameNearLimit(
  vtkSoftShadowPass* pass, const ShadowLight& light, vtkOpenGLRenderWindow* window)
{
  LightRecord& record = this->Record(light.Light);
  const int deepest = this->Counting.TakeDeepestCount(window, light.Light);
  if (deepest > 0 && !record.DeepCounts)
  {
    record.DeepCounts = true;
    if (pass->GetMethod() == vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES)
    {
      vtkWarningWithObjectMacro(pass,
        "Soft shadow volumes of light "
          << light.Light << " met a point " << deepest
          << " casting surfaces deep (seen from the light's centre or a sample): their 8-bit "
             "counters hold 251, so deeper points may be shadowed wrongly. METHOD_AUTOMATIC "
             "averages such a light's samples instead; averaging's stencil holds 255.");
    }
  }
  return record.DeepCounts;
}

void TechniqueChooser::Choose(vtkSoftShadowPass* pass, ShadowLight& light, const glm::dvec3& target,
  vtkOpenGLRenderWindow* window)
{
  const glm::dvec4& world = light.World;
  double radius = vtkSoftShadowPass::GetLightRadius(light.Light);
  light.Samples = { world };
  light.Technique = &this->Hard;
  light.CountingChosenAutomatically = false;
  light.SoftRadius = 0.0;
  light.CountingSamples.clear();
  const int method = pass->GetMethod();
  if (method == vtkSoftShadowPass::METHOD_HARD_VOLUMES || radius <= 0.0)
  {
    return;
  }
  if (world.w == 0.0 && radius >= 90.0)
  {
    bool& warned = this->Record(light.Light).WarnedRadius;
    if (!warned)
    {
      warned = true;
      vtkWarningWithObjectMacro(pass,
        "Directional light " << light.Light << " has an angular radius of " << radius
                             << " degrees; clamped to 89.");
    }
    radius = 89.0;
  }
  light.SampleTarget = target;
  light.SampleRadius = radius;
  light.SoftRadius = world.w != 0.0 ? radius : glm::radians(radius);
  if (method == vtkSoftShadowPass::METHOD_PLATEAUS)
  {
    light.Technique = &this->Plateaus;
    return;
  }
  if (method == vtkSoftShadowPass::METHOD_PENUMBRA_WEDGES)
  {
    light.Technique = &this->Wedges;
    return;
  }
  // Automatic averages more samples than counting holds, as asked, and a light whose counts
  // came near what the counters hold; the forced method clamps the samples and warns.
  const bool automatic = method == vtkSoftShadowPass::METHOD_AUTOMATIC;
  const bool forced = method == vtkSoftShadowPass::METHOD_SOFT_SHADOW_VOLUMES;
  const bool nearLimit = (automatic || forced) && this->CountsCameNearLimit(pass, light, window);
  const bool countable = forced ||
    (automatic && pass->GetLightSamples() <= CountingTechnique::MaximumSamples && !nearLimit);
  if (countable && this->Counting.Supported(pass))
  {
    light.Technique = &this->Counting;
    this->Counting.SetHalfResolution(pass->GetHalfResolutionCounting());
    light.CountingChosenAutomatically = automatic;
    light.CountingSamples =
      this->Counting.ChooseSamples(pass, world, radius, pass->GetLightSamples(), target);
    // Counting starts from a point off the centre, on a light grown to hold the whole light
    // around it.
    light.Samples = { CountingReference(world, light.SoftRadius) };
    light.SoftRadius *= 1.0 + CountingReferenceOffset;
    return;
  }
  light.Samples = SpreadLightSamples(world, radius, pass->GetLightSamples(), target);
}

void TechniqueChooser::FindPlateauPlane(
  vtkRenderer* renderer, vtkObject* owner, std::vector<ShadowLight>& lights)
{
  bool plateaus = false;
  for (const ShadowLight& light : lights)
  {
    plateaus = plateaus || light.Technique == &this->Plateaus;
  }
  if (!plateaus || this->Plateaus.FindReceiverPlane(renderer, owner))
  {
    return;
  }
  this->Plateaus.WarnNoPlane(owner);
  for (ShadowLight& light : lights)
  {
    light.Technique = &this->Hard;
  }
}

bool TechniqueChooser::Reconsider(ShadowLight& light, const std::vector<CasterCache*>& casters,
  int lightSamples, vtkOpenGLRenderWindow* window, const int size[2], vtkObject* owner)
{
  if (light.Technique != &this->Counting)
  {
    return false;
  }
  bool count = true;
  if (light.CountingChosenAutomatically)
  {
    LastChoice& last = this->Record(light.Light).Last;
    count = this->Counting.IsCheaper(light, casters, last);
    last = count ? LastChoice::Counted : LastChoice::Averaged;
  }
  if (count && this->Counting.ReadyCounters(window, size, light.CountingSamples.size(), owner))
  {
    return false;
  }
  AverageSamples(light, lightSamples);
  return true;
}

bool TechniqueChooser::AverageIfFirstCountWentDeep(
  ShadowLight& light, int lightSamples, vtkOpenGLRenderWindow* window)
{
  if (light.Technique != &this->Counting || !light.CountingChosenAutomatically)
  {
    return false;
  }
  LightRecord& record = this->Record(light.Light);
  if (record.FirstCountChecked)
  {
    return false;
  }
  record.FirstCountChecked = true;
  if (this->Counting.TakeDeepestCount(window, light.Light) == 0)
  {
    return false;
  }
  record.DeepCounts = true;
  AverageSamples(light, lightSamples);
  return true;
}

void TechniqueChooser::AverageSamples(ShadowLight& light, int lightSamples)
{
  light.Technique = &this->Hard;
  light.Samples =
    SpreadLightSamples(light.World, light.SampleRadius, lightSamples, light.SampleTarget);
}

} // namespace penumbra
