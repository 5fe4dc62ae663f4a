#include "vtkSoftShadowPass.h"

#include "penumbraCasterDepth.h"
#include "penumbraLightIntensityBuffer.h"
#include "penumbraShadowCaches.h"
#include "penumbraShadowCamera.h"
#include "penumbraShadowTechnique.h"
#include "penumbraShadowVolumeRenderer.h"
#include "penumbraTechniqueChooser.h"

#include "penumbraPropWarnings.h"
#include "penumbraReceiverShader.h"
#include "penumbraSceneBounds.h"
#include "penumbraSceneWalk.h"
#include "penumbraShadowInputs.h"
#include "penumbraStageTimes.h"
#include "penumbraWindowReleaseCallback.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkFrameBufferObjectBase.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightsPass.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkPixelBufferObject.h"
#include "vtkPointData.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRendererSettingsPass.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include "penumbraCulling.h"
#include "penumbraMatrices.h"

#include "penumbraReceiverDec.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkSoftShadowPass);
void vtkSoftShadowPass::SetDelegatePass(vtkRenderPass* delegatePass)
{
  if (delegatePass == this)
  {
    vtkErrorMacro("A pass cannot be its own delegate: the delegate is left as it was.");
    return;
  }
  vtkSetObjectBodyMacro(DelegatePass, vtkRenderPass, delegatePass);
}

vtkInformationKeyMacro(vtkSoftShadowPass, LIGHT_RADIUS, Double);
vtkInformationKeyMacro(vtkSoftShadowPass, CASTS_SHADOWS, Integer);
vtkInformationKeyMacro(vtkSoftShadowPass, RECEIVES_SHADOWS, Integer);
vtkInformationKeyMacro(vtkSoftShadowPass, SHADOW_PLANE, Integer);

namespace
{

/// Sets a flag for as long as a call goes down the delegate chain.
class DelegateChainScope
{
public:
  explicit DelegateChainScope(bool& flag)
    : Flag(flag)
  {
    this->Flag = true;
  }
  ~DelegateChainScope() { this->Flag = false; }
  DelegateChainScope(const DelegateChainScope&) = delete;
  DelegateChainScope& operator=(const DelegateChainScope&) = delete;

private:
  bool& Flag;
};

/// `prop`'s property keys, made if it has none (which modifies the prop).
vtkInformation* PropertyKeysOf(vtkProp* prop)
{
  if (!prop->GetPropertyKeys())
  {
    vtkNew<vtkInformation> keys;
    prop->SetPropertyKeys(keys);
  }
  return prop->GetPropertyKeys();
}

/// Puts `pass` among the render passes that edit `prop`'s shaders, once: an assembly's part keeps
/// the assembly's keys after VTK drew it, so a part also added to the renderer shares them, and
/// a second entry would edit its shaders twice (declarations repeated: they fail to compile).
/// Returns the keys it went into, which VTK may take from the prop while it draws.
vtkInformation* AddRenderPassKey(vtkProp* prop, vtkOpenGLRenderPass* pass)
{
  vtkInformation* info = PropertyKeysOf(prop);
  vtkInformationObjectBaseVectorKey* passes = vtkOpenGLRenderPass::RenderPasses();
  for (int i = 0; i < info->Length(passes); ++i)
  {
    if (info->Get(passes, i) == pass)
    {
      return info;
    }
  }
  info->Append(passes, pass);
  return info;
}

} // namespace

//------------------------------------------------------------------------------
class vtkSoftShadowPass::vtkInternals
{
public:
  using ShadowLight = penumbra::ShadowLight;
  /// One object per shadow method; each light points at the one that draws its layer.
  penumbra::TechniqueChooser Techniques;

  penumbra::ShadowVolumeRenderer Volumes;

  penumbra::ShadowCaches Caches;
  penumbra::SceneWalk SceneWalk;
  penumbra::StageTimes StageTimes;
  /// The pass, for the warnings and errors the internals report.
  vtkObject* Owner = nullptr;
  penumbra::ShaderPrograms Programs;
  /// The shader edits warned about: once per live prop, mapper class and problem.
  penumbra::PropWarnings WarnedShaderEdits;
  std::vector<ShadowLight> Lights;
  /// What the kept depth and light-intensity layers were drawn from (ReuseUnchangedShadows):
  /// the scene (viewport, camera, props, settings) and each layer's light; whether this frame's
  /// could all be recorded; and what this frame keeps of the last drawn frame's.
  penumbra::ShadowInputs SceneInputs;
  std::vector<penumbra::ShadowInputs> LayerInputs;
  bool InputsRecorded = false;
  bool DepthKept = false;
  std::vector<bool> LayersKept;
  void ForgetInputs()
  {
    this->SceneInputs.Forget();
    this->LayerInputs.clear();
  }
  std::vector<penumbra::CasterCache*> Casters;
  std::vector<vtkProp*> Receivers;
  /// The receivers' assembly-path leaves, and their properties, which a vtkLODActor's or a
  /// vtkFollower's inner device actor draws with (DrawsForReceiver).
  std::set<vtkProp*> ReceiverLeaves;
  std::set<vtkProperty*> ReceiverProperties;
  /// The property keys the pass put itself into this frame (AddRenderPassKey).
  std::vector<vtkSmartPointer<vtkInformation>> ReceiverKeys;
  /// PropsCulledInView this frame: VTK does not draw them, so they cast nothing.
  std::vector<vtkProp*> CulledInView;
  /// The scene's, props' and receivers' boxes the depth range, scissors and wedges are cut to.
  penumbra::SceneBounds Bounds;
  penumbra::LightWarnings WarnedLights;
  bool WarnedWindowChange = false;
  bool WarnedNested = false;
  bool WarnedNoDelegate = false;
  bool WarnedDelegateSize = false;
  /// The receivers' draws of this frame at the shadows' size and at others (OtherSize, the last).
  vtkIdType DrawsAtShadowSize = 0;
  vtkIdType DrawsAtOtherSizes = 0;
  int OtherSize[2] = { 0, 0 };
  bool WarnedShadowMapPass = false;
  /// Set while a call goes down the delegate chain: a chain that comes back to this pass
  /// (A -> B -> A, or through a camera or sequence pass) stops there instead of recursing.
  bool InDelegateChain = false;
  /// The largest width or height the light-intensity layers (2D array textures) can take here, read
  /// once per window; 0 until read.
  int MaxLayerSize = 0;
  vtkOpenGLRenderWindow* MaxLayerSizeWindow = nullptr;
  bool WarnedLayerSize = false;

  std::string ShaderConfiguration;
  vtkTimeStamp ShaderStageTime;
  bool ApplyShadows = false;
  /// While VTK draws props into the pass's depth: surfaces drawn with their edges are then not
  /// widened (SetShaderParameters).
  bool DrawingDepth = false;

  penumbra::LightIntensityBuffer LI;
  /// Bytes of GPU memory held: framebuffer textures (4 bytes per texel each), the techniques'
  /// own and cached buffers.
  std::size_t GraphicsMemoryBytes()
  {
    std::size_t bytes = this->LI.GraphicsMemoryBytes() + this->Caches.GraphicsBufferBytes();
    for (const penumbra::ShadowTechnique* technique : this->Techniques.All())
    {
      bytes += technique->GraphicsMemoryBytes();
    }
    return bytes;
  }
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };

  penumbra::FullScreenTriangle FullScreen;
  penumbra::FullScreenTriangle::VAO ResolveVAO;

  vtkNew<vtkOpaquePass> DepthPass;
  penumbra::CasterDepth CasterDepth;
  /// The props whose depth RenderCasterDepth draws from their caster meshes this frame.
  std::vector<vtkProp*> DepthFromMeshes;
  /// Whether the depth kept in LI has its surfaces' planes where caster meshes drew it (a
  /// counted light reads them), and the origin of their offsets; whether this frame's lights
  /// want them, as chosen before their casters are updated (the scene's inputs record that,
  /// and Automatic may then turn a counted light to averaging, which a later frame with the
  /// depth kept may undo).
  bool SurfacePlanesDrawn = false;
  glm::dvec3 SurfacePlanesOrigin{ 0.0 };
  bool SurfacePlanesForDepth = false;
  bool SurfacePlanesWanted() const
  {
    return std::any_of(this->Lights.begin(), this->Lights.end(),
      [](const ShadowLight& light) { return light.Technique->ReadsSurfacePlanes(); });
  }
  vtkNew<vtkLightsPass> LightsPass;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  /// Releases the GPU resources in Window's context when that window goes, even while the pass
  /// is off its renderer (which then does not release it).
  std::unique_ptr<penumbra::WindowReleaseCallback> WindowRelease;
  std::vector<vtkSmartPointer<vtkImageData>> VisibilityImages;

  /// Depth, volumes and wedges share one camera; the scene is drawn with the user's.
  penumbra::ShadowCamera Camera;
  glm::dmat4 WorldToClip{ 1.0 };
  std::array<glm::dvec3, 4> NearCorners;

  /// The shadows' camera, its world-to-clip matrix and near-plane corners, as VTK's mappers
  /// use them.
  void UpdateCamera(vtkRenderer* renderer, bool tightDepthRange)
  {
    vtkMatrix4x4 *worldToView, *viewToClip, *worldToClip;
    vtkMatrix3x3* normals;
    this->Camera.Update(renderer, this->Bounds.Scene(), this->Bounds.Props(), tightDepthRange)
      ->GetKeyMatrices(renderer, worldToView, normals, viewToClip, worldToClip);
    // VTK keeps its key matrices transposed for OpenGL.
    this->WorldToClip = glm::transpose(penumbra::ToGlm(worldToClip));
    const glm::dmat4 clipToWorld = glm::inverse(this->WorldToClip);
    const std::array<glm::dvec2, 4> ndc = { { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } } };
    for (int i = 0; i < 4; ++i)
    {
      const glm::dvec4 p = clipToWorld * glm::dvec4(ndc[i], -1.0, 1.0);
      this->NearCorners[i] = glm::dvec3(p) / p.w;
    }
  }

  /// Brings every opaque caster's volumes and the technique's caches for `light` up to date;
  /// returns the silhouette updates it made.
  vtkIdType UpdateLightCasters(const ShadowLight& light);
  /// The same for the translucent casters' volumes, one per sample (TranslucentSamples), once
  /// the light's technique and samples are final.
  vtkIdType UpdateTranslucentVolumes(const ShadowLight& light);
  /// Once the light's technique and samples are final (Automatic may have traded counting's for
  /// averaging's): the technique's own preparation, then UpdateTranslucentVolumes.
  vtkIdType FinishLight(const ShadowLight& light);
  /// Averaged and counted lights multiply each sample's light by what translucent casters let
  /// through; wedges and plateaus leave them out (culled for the light), with one warning.
  void SortOutTranslucentCasters(ShadowLight& light);
  bool WarnedTranslucent = false;
  /// What the techniques draw with this frame.
  penumbra::ShadowFrame MakeFrame();

  const ShadowLight* FindLight(int collectionIndex) const
  {
    for (const ShadowLight& light : this->Lights)
    {
      if (light.CollectionIndex == collectionIndex)
      {
        return &light;
      }
    }
    return nullptr;
  }
};

//------------------------------------------------------------------------------
vtkSoftShadowPass::vtkSoftShadowPass()
  : Internals(new vtkInternals)
{
  this->Internals->Owner = this;
  this->Internals->Programs.Owner = this;
  this->Internals->WindowRelease.reset(new penumbra::WindowReleaseCallback(
    [this](vtkWindow* w) { this->ReleaseGraphicsResources(w); }));
  vtkNew<vtkRendererSettingsPass> scene;
  this->SetDelegatePass(scene);
}

vtkSoftShadowPass::~vtkSoftShadowPass()
{
  // While Internals and the delegate still exist to be released.
  this->Internals->WindowRelease->Release();
  this->SetDelegatePass(nullptr);
}

void vtkSoftShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: ";
  if (this->DelegatePass && !this->Internals->InDelegateChain)
  {
    os << "\n";
    DelegateChainScope chain(this->Internals->InDelegateChain);
    this->DelegatePass->PrintSelf(os, indent.GetNextIndent());
  }
  else if (this->DelegatePass)
  {
    os << this->DelegatePass << " (back to this pass)\n";
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "ShadowsEnabled: " << this->ShadowsEnabled << "\n";
  os << indent << "Method: " << this->GetMethodAsString() << "\n";
  os << indent << "LightSamples: " << this->LightSamples << "\n";
  os << indent << "CollectStageTimes: " << this->CollectStageTimes << "\n";
  os << indent << "UseTightDepthRange: " << this->UseTightDepthRange << "\n";
  os << indent << "HalfResolutionCounting: " << this->HalfResolutionCounting << "\n";
  os << indent << "DepthFromCasterMeshes: " << this->DepthFromCasterMeshes << "\n";
  os << indent << "ReuseUnchangedShadows: " << this->ReuseUnchangedShadows << "\n";
  os << indent << "NumberOfReusedFrames: " << this->NumberOfReusedFrames << "\n";
  os << indent << "NumberOfRedrawnLights: " << this->NumberOfRedrawnLights << "\n";
  os << indent << "PlateauFalloff: "
     << (this->PlateauFalloff == PLATEAU_FALLOFF_LINEAR ? "Linear" : "Sinusoidal") << "\n";
  os << indent << "PlateauResolution: " << this->PlateauResolution << "\n";
  os << indent << "UseReceiverPlane: " << this->UseReceiverPlane << "\n";
  os << indent << "ReceiverPlaneOrigin: " << this->ReceiverPlaneOrigin[0] << " "
     << this->ReceiverPlaneOrigin[1] << " " << this->ReceiverPlaneOrigin[2] << "\n";
  os << indent << "ReceiverPlaneNormal: " << this->ReceiverPlaneNormal[0] << " "
     << this->ReceiverPlaneNormal[1] << " " << this->ReceiverPlaneNormal[2] << "\n";
  os << indent << "NumberOfPlateauTriangles: " << this->NumberOfPlateauTriangles << "\n";
  os << indent << "NumberOfCountedLights: " << this->NumberOfCountedLights << "\n";
  os << indent << "NumberOfAveragedLights: " << this->NumberOfAveragedLights << "\n";
  os << indent << "NumberOfShadowingLights: " << this->NumberOfShadowingLights << "\n";
  os << indent << "NumberOfShadowVolumeTriangles: " << this->NumberOfShadowVolumeTriangles << "\n";
  os << indent << "NumberOfZFailVolumes: " << this->NumberOfZFailVolumes << "\n";
  os << indent << "NumberOfPenumbraWedges: " << this->NumberOfPenumbraWedges << "\n";
  os << indent << "NumberOfFullViewportWedges: " << this->NumberOfFullViewportWedges << "\n";
  os << indent << "NumberOfCulledShadows: " << this->NumberOfCulledShadows << "\n";
  os << indent << "NumberOfSilhouetteUpdates: " << this->NumberOfSilhouetteUpdates << "\n";
  os << indent << "NumberOfPropsWithDepthFromMeshes: " << this->NumberOfPropsWithDepthFromMeshes
     << "\n";
  os << indent << "NumberOfPropsWithCulledDepth: " << this->NumberOfPropsWithCulledDepth << "\n";
  os << indent << "GraphicsMemoryBytes: " << this->GraphicsMemoryBytes << "\n";
}

const char* vtkSoftShadowPass::GetMethodAsString()
{
  switch (this->Method)
  {
    case METHOD_HARD_VOLUMES:
      return "HardVolumes";
    case METHOD_AVERAGED_HARD_SHADOWS:
      return "AveragedHardShadows";
    case METHOD_PENUMBRA_WEDGES:
      return "PenumbraWedges";
    case METHOD_PLATEAUS:
      return "Plateaus";
    case METHOD_SOFT_SHADOW_VOLUMES:
      return "SoftShadowVolumes";
    default:
      return "Automatic";
  }
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::SetLightRadius(vtkLight* light, double radius)
{
  if (!light)
  {
    return;
  }
  if (!(radius >= 0.0) || !std::isfinite(radius))
  {
    vtkGenericWarningMacro("vtkSoftShadowPass::SetLightRadius: radius "
      << radius << " is not a finite, non-negative "
      << "number; using 0 (hard shadows).");
    radius = 0.0;
  }
  if (!light->GetInformation())
  {
    vtkNew<vtkInformation> info;
    light->SetInformation(info);
  }
  light->GetInformation()->Set(LIGHT_RADIUS(), radius);
  light->Modified();
}

double vtkSoftShadowPass::GetLightRadius(vtkLight* light)
{
  vtkInformation* info = light ? light->GetInformation() : nullptr;
  return info && info->Has(LIGHT_RADIUS()) ? info->Get(LIGHT_RADIUS()) : 0.0;
}

namespace
{
void SetPropFlag(vtkProp* prop, vtkInformationIntegerKey* key, bool value)
{
  if (!prop)
  {
    return;
  }
  PropertyKeysOf(prop)->Set(key, value ? 1 : 0);
  prop->Modified();
}

bool GetPropFlag(vtkProp* prop, vtkInformationIntegerKey* key)
{
  vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
  return !(info && info->Has(key)) || info->Get(key) != 0;
}
} // namespace

void vtkSoftShadowPass::SetCastsShadows(vtkProp* prop, bool casts)
{
  SetPropFlag(prop, CASTS_SHADOWS(), casts);
}

bool vtkSoftShadowPass::GetCastsShadows(vtkProp* prop)
{
  return GetPropFlag(prop, CASTS_SHADOWS());
}

void vtkSoftShadowPass::SetReceivesShadows(vtkProp* prop, bool receives)
{
  SetPropFlag(prop, RECEIVES_SHADOWS(), receives);
}

void vtkSoftShadowPass::SetShadowPlane(vtkProp* prop, bool isPlane)
{
  SetPropFlag(prop, SHADOW_PLANE(), isPlane);
}

bool vtkSoftShadowPass::GetShadowPlane(vtkProp* prop)
{
  vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
  return info && info->Has(SHADOW_PLANE()) && info->Get(SHADOW_PLANE()) != 0;
}

bool vtkSoftShadowPass::GetReceivesShadows(vtkProp* prop)
{
  return GetPropFlag(prop, RECEIVES_SHADOWS());
}

bool vtkSoftShadowPass::LightCastsShadows(vtkLight* light)
{
  return light && light->GetSwitch() && !light->LightTypeIsHeadlight() &&
    light->GetIntensity() > 0.0 && light->GetShadowAttenuation() > 0.0;
}

//------------------------------------------------------------------------------
namespace
{
/// The soft shadow passes rendering on this thread, outermost first, for as long as one scope
/// lives.
class RenderingPasses
{
public:
  explicit RenderingPasses(const vtkSoftShadowPass* pass) { Active().push_back(pass); }
  ~RenderingPasses() { Active().pop_back(); }
  RenderingPasses(const RenderingPasses&) = delete;
  RenderingPasses& operator=(const RenderingPasses&) = delete;
  static std::vector<const vtkSoftShadowPass*>& Active()
  {
    static thread_local std::vector<const vtkSoftShadowPass*> active;
    return active;
  }
};
} // namespace

void vtkSoftShadowPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (this->RenderIfNested(s))
  {
    return;
  }
  RenderingPasses rendering(this);

  vtkInternals& internals = *this->Internals;
  internals.StageTimes.BeginFrame(this->CollectStageTimes);
  auto renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  auto window =
    renderer ? vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()) : nullptr;
  internals.Lights.clear();
  internals.ApplyShadows = false;
  // A selection render (picking) draws ids, not light: the delegate draws it, unshadowed. It
  // leaves the last frame's shadows, and their statistics, to the next frame.
  const bool selecting = renderer && renderer->GetSelector();
  if (this->ShadowsEnabled && window && !selecting)
  {
    this->PrepareShadowingLights(s, renderer, window);
  }
  this->UpdateShaderConfiguration();

  if (internals.Lights.empty() || internals.Size[0] <= 0 || internals.Size[1] <= 0)
  {
    this->RenderUnshadowed(s, selecting);
    return;
  }
  this->RenderShadowed(s, renderer, window);
  vtkOpenGLCheckErrorMacro("failed after Render");
}

bool vtkSoftShadowPass::RenderIfNested(const vtkRenderState* s)
{
  // One pass shadows a frame: another inside its delegate chain would edit the same shaders
  // again, and a pass inside its own chain would recurse for ever.
  const std::vector<const vtkSoftShadowPass*>& active = RenderingPasses::Active();
  if (active.empty())
  {
    return false;
  }
  vtkInternals& internals = *this->Internals;
  const bool cycle = std::find(active.begin(), active.end(), this) != active.end();
  if (!internals.WarnedNested)
  {
    vtkWarningMacro(<< (cycle ? "This pass is in its own delegate chain: it draws nothing "
                                "the second time."
                              : "This pass is in the delegate chain of another "
                                "vtkSoftShadowPass, which shadows the frame: it draws its "
                                "delegate unshadowed."));
    internals.WarnedNested = true;
  }
  if (!cycle)
  {
    RenderingPasses rendering(this);
    this->RenderDelegate(s);
  }
  return true;
}

void vtkSoftShadowPass::PrepareShadowingLights(
  const vtkRenderState* s, vtkRenderer* renderer, vtkOpenGLRenderWindow* window)
{
  vtkInternals& internals = *this->Internals;
  this->FollowWindow(window);
  this->UpdateFrameSize(s, renderer);
  // Before anything reads the props' data or bounds (the lights' samples face the casters).
  penumbra::UpdateMapperInputs(renderer);
  // Lights follow the camera only once VTK's lights pass has run: run it now, it is idempotent.
  internals.LightsPass->Render(s);
  this->CollectShadowingLights(renderer);
  if (!internals.Lights.empty() && !this->LayersFit(window))
  {
    internals.Lights.clear(); // drawn as VTK draws it, unshadowed, rather than black
  }
}

void vtkSoftShadowPass::UpdateFrameSize(const vtkRenderState* s, vtkRenderer* renderer)
{
  vtkInternals& internals = *this->Internals;
  renderer->GetTiledSizeAndOrigin(
    &internals.Size[0], &internals.Size[1], &internals.Origin[0], &internals.Origin[1]);
  // Inside a pass that draws into a framebuffer of its own (vtkSSAAPass renders into one
  // larger than the window), that framebuffer's pixels are the ones drawn: size the buffers
  // to it, as vtkSSAOPass does.
  if (vtkFrameBufferObjectBase* target = s->GetFrameBuffer())
  {
    target->GetLastSize(internals.Size[0], internals.Size[1]);
    internals.Origin[0] = internals.Origin[1] = 0;
  }
}

void vtkSoftShadowPass::RenderUnshadowed(const vtkRenderState* s, bool selecting)
{
  vtkInternals& internals = *this->Internals;
  internals.Lights.clear();
  if (!selecting)
  {
    this->ResetShadowStatistics();
    internals.ForgetInputs();
  }
  this->CompositeAndEndFrame(s);
}

void vtkSoftShadowPass::RenderShadowed(
  const vtkRenderState* s, vtkRenderer* renderer, vtkOpenGLRenderWindow* window)
{
  vtkInternals& internals = *this->Internals;
  this->AddReceiverKeys(s);
  internals.Bounds.UpdateScene(renderer);
  internals.CulledInView = penumbra::PropsCulledInView(s);
  this->WarnOfLightsReachingTheScene(renderer);
  internals.UpdateCamera(renderer, this->UseTightDepthRange);
  const bool reused = this->ShadowsUnchanged(s);
  if (!reused)
  {
    this->DrawShadows(s, window);
  }
  this->CompositeShadows(s);
  this->RemoveReceiverKeys();
  if (reused)
  {
    ++this->NumberOfReusedFrames;
  }
  else
  {
    internals.Caches.PurgeUnused(); // a reused frame used none: they are the drawn frame's
  }
  this->GraphicsMemoryBytes = static_cast<vtkIdType>(internals.GraphicsMemoryBytes());
}

void vtkSoftShadowPass::CompositeShadows(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  internals.LI.GetLayers()->Activate();
  internals.ApplyShadows = true;
  internals.DrawsAtShadowSize = internals.DrawsAtOtherSizes = 0;
  this->NumberOfShadowingLights = static_cast<int>(internals.Lights.size());
  this->CompositeAndEndFrame(s);
  this->WarnOfDelegateSize();
  internals.ApplyShadows = false;
  internals.LI.GetLayers()->Deactivate();
}

void vtkSoftShadowPass::CompositeAndEndFrame(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  using Stage = penumbra::StageTimes::Stage;
  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Compositing);
    this->RenderDelegate(s);
  }
  internals.StageTimes.EndFrame();
}

void vtkSoftShadowPass::ResetShadowStatistics(bool depthKept)
{
  this->NumberOfShadowingLights = 0;
  this->NumberOfRedrawnLights = 0;
  this->NumberOfShadowVolumeTriangles = 0;
  this->NumberOfZFailVolumes = 0;
  this->NumberOfPenumbraWedges = 0;
  this->NumberOfFullViewportWedges = 0;
  this->NumberOfCulledShadows = 0;
  this->NumberOfPlateauTriangles = 0;
  this->NumberOfCountedLights = 0;
  this->NumberOfAveragedLights = 0;
  if (!depthKept)
  {
    this->NumberOfPropsWithDepthFromMeshes = 0;
    this->NumberOfPropsWithCulledDepth = 0;
  }
}

bool vtkSoftShadowPass::ShadowsUnchanged(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  internals.DepthKept = false;
  internals.LayersKept.assign(internals.Lights.size(), false);
  internals.InputsRecorded = false;
  if (!this->ReuseUnchangedShadows)
  {
    return false;
  }
  vtkRenderer* renderer = s->GetRenderer();
  penumbra::ShadowInputs& scene = internals.SceneInputs;
  scene.Begin();
  scene.Add(renderer);
  scene.Add(internals.Window.GetPointer());
  scene.Add(s->GetFrameBuffer());
  scene.Add(
    glm::dvec4(internals.Size[0], internals.Size[1], internals.Origin[0], internals.Origin[1]));
  scene.Add(static_cast<double>(internals.Lights.size())); // the layers' count
  scene.AddTime(this->GetMTime());
  // Values: vtkCamera::DeepCopy does not modify the camera.
  scene.SetWorldToClip(internals.WorldToClip);
  // Image slices follow the focal point, which SetDistance moves without changing the matrix.
  vtkCamera* camera = renderer->GetActiveCamera();
  scene.Add(glm::dvec4(glm::make_vec3(camera->GetFocalPoint()), camera->GetDistance()));
  scene.AddCoincidentTopologySettings();
  scene.Add(internals.SurfacePlanesWanted() ? 1.0 : 0.0);
  // A culler's settings (vtkFrustumCoverageCuller's MinimumCoverage) choose the casters too.
  scene.Add(static_cast<double>(internals.CulledInView.size()));
  for (vtkProp* culled : internals.CulledInView)
  {
    scene.Add(culled);
  }
  internals.InputsRecorded = scene.AddProps(renderer);
  if (!internals.InputsRecorded)
  {
    return false;
  }
  // The depth is the scene's alone: with the scene unchanged, only lights that changed are drawn.
  internals.DepthKept = scene.MatchKept();
  internals.LayerInputs.resize(internals.Lights.size());
  bool allKept = internals.DepthKept;
  for (const vtkInternals::ShadowLight& light : internals.Lights)
  {
    penumbra::ShadowInputs& layer = internals.LayerInputs[light.Layer];
    layer.Begin();
    layer.Add(light.Light);
    layer.AddTime(light.Light->GetMTime());
    layer.Add(light.World);
    layer.Add(glm::dvec4(light.SampleTarget, light.SoftRadius));
    layer.Add(glm::dvec4(light.SampleRadius, static_cast<double>(light.Samples.size()),
      static_cast<double>(light.CountingSamples.size()), light.Layer));
    layer.Add(light.Technique);
    const bool kept = internals.DepthKept && layer.MatchKept();
    internals.LayersKept[light.Layer] = kept;
    allKept = allKept && kept;
  }
  return allKept;
}

void vtkSoftShadowPass::DrawShadows(const vtkRenderState* s, vtkOpenGLRenderWindow* window)
{
  vtkInternals& internals = *this->Internals;
  using Stage = penumbra::StageTimes::Stage;
  this->ResetShadowStatistics(internals.DepthKept);
  internals.VisibilityImages.clear();
  internals.SurfacePlanesForDepth = internals.SurfacePlanesWanted();
  if (!internals.DepthKept)
  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Depth);
    internals.LI.GetLayers()->Activate();
    this->RenderDepth(s);
    internals.LI.GetLayers()->Deactivate();
  }
  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Casters);
    this->UpdateCasters(s);
  }
  if (!internals.DepthKept && !internals.DepthFromMeshes.empty())
  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Depth);
    internals.LI.GetLayers()->Activate();
    this->RenderCasterDepth(s);
    internals.LI.GetLayers()->Deactivate();
  }
  // After UpdateCasters: Automatic may have traded a light's wedges for averaged shadows, and
  // plateaus without a receiver plane fall back to hard shadows.
  if (std::any_of(internals.Lights.begin(), internals.Lights.end(),
        [&](const vtkInternals::ShadowLight& light)
        { return !internals.LayersKept[light.Layer] && light.Technique->ReadsDepthCopy(); }))
  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Depth);
    internals.LI.CopyDepth(window->GetState());
  }
  const bool drawn = this->RenderLightIntensity(window);
  if (!drawn || !internals.InputsRecorded)
  {
    internals.ForgetInputs();
    return;
  }
  internals.SceneInputs.Keep();
  for (penumbra::ShadowInputs& layer : internals.LayerInputs)
  {
    layer.Keep();
  }
}

void vtkSoftShadowPass::RenderDelegate(const vtkRenderState* s)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  }
  else if (!this->Internals->WarnedNoDelegate)
  {
    vtkWarningMacro("No delegate pass: nothing is rendered.");
    this->Internals->WarnedNoDelegate = true;
  }
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::CollectShadowingLights(vtkRenderer* renderer)
{
  vtkInternals& internals = *this->Internals;
  // Soft lights' samples face the centre of the visible props' bounds, as VTK's camera reset
  // takes them (UseBounds), or, with nothing visible, the light's focal point. Props outside
  // the shadows (widgets) are left out, so that dragging one does not turn the samples.
  penumbra::Box visible;
  for (vtkProp* prop : penumbra::VisiblePropsInTheShadows(renderer))
  {
    const double* bounds = prop->GetUseBounds() ? prop->GetBounds() : nullptr;
    if (bounds && vtkMath::AreBoundsInitialized(bounds))
    {
      visible.Extend(
        glm::dvec3(bounds[0], bounds[2], bounds[4]), glm::dvec3(bounds[1], bounds[3], bounds[5]));
    }
  }
  const bool haveBounds = visible.Valid;
  const glm::dvec3 sceneCentre = (visible.Min + visible.Max) * 0.5;
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  vtkLight* light;
  int collectionIndex = 0;
  int shaderIndex = 0;
  for (lights->InitTraversal(it); (light = lights->GetNextLight(it)); ++collectionIndex)
  {
    if (!light->GetSwitch())
    {
      continue; // VTK's shaders number switched-on lights only
    }
    const int index = shaderIndex++;
    if (!LightCastsShadows(light))
    {
      continue;
    }
    const glm::dvec3 position = glm::make_vec3(light->GetTransformedPosition());
    glm::dvec4 world(position, 1.0);
    if (!light->GetPositional())
    {
      const glm::dvec3 towards = position - glm::make_vec3(light->GetTransformedFocalPoint());
      const double length = glm::length(towards);
      if (!(length > 0.0) || !std::isfinite(length))
      {
        if (internals.WarnedLights.First(light, "no direction"))
        {
          vtkWarningMacro("Directional light " << light << " has no direction (position equals "
                                               << "focal point): it casts no shadow.");
        }
        continue;
      }
      world = glm::dvec4(towards / length, 0.0);
    }
    else if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z))
    {
      if (internals.WarnedLights.First(light, "non-finite position"))
      {
        vtkWarningMacro("Light " << light << " has a non-finite position: it casts no shadow.");
      }
      continue;
    }
    vtkInternals::ShadowLight shadowLight;
    shadowLight.Light = light;
    shadowLight.CollectionIndex = collectionIndex;
    shadowLight.ShaderIndex = index;
    shadowLight.Layer = static_cast<int>(internals.Lights.size());
    shadowLight.World = world;
    shadowLight.Attenuation = static_cast<float>(light->GetShadowAttenuation());
    internals.Techniques.Choose(this, shadowLight,
      haveBounds ? sceneCentre : glm::make_vec3(light->GetTransformedFocalPoint()),
      internals.Window);
    internals.Lights.push_back(shadowLight);
  }
}

void vtkSoftShadowPass::UpdateShaderConfiguration()
{
  vtkInternals& internals = *this->Internals;
  std::ostringstream configuration;
  for (const auto& light : internals.Lights)
  {
    configuration << light.ShaderIndex << ":" << light.Layer << " ";
  }
  if (configuration.str() != internals.ShaderConfiguration)
  {
    internals.ShaderConfiguration = configuration.str();
    internals.ShaderStageTime.Modified();
  }
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::AddReceiverKeys(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  this->RemoveReceiverKeys(); // none are left from a frame that ended early
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    // Any prop with opaque surfaces: an assembly hands its keys to its parts as VTK draws them,
    // composite and glyph mappers draw with their actor's. SetShaderParameters leaves
    // translucent fragments unshadowed: they lie over the LI buffer of what is behind them.
    // Not volumes: vtkVolume keeps vtkProp's HasOpaqueGeometry (true), but VTK's volume
    // shaders have no light loop to scale, and volumes are drawn as VTK draws them.
    // A vtkAxesActor does not hand its keys to its parts: the keys go on what it draws. Props
    // outside the shadows (widgets) draw through actors that never see the keys.
    vtkProp* prop = s->GetPropArray()[i];
    // VTK's translucent pass makes a prop's keys the first time it draws it, which modifies the
    // prop after this frame's inputs were recorded, so the next frame would draw its shadows
    // again: made here, before the record.
    PropertyKeysOf(prop);
    if (GetReceivesShadows(prop) && prop->HasOpaqueGeometry() && !vtkVolume::SafeDownCast(prop) &&
      !penumbra::OutsideTheShadows(prop))
    {
      for (vtkProp* drawn : penumbra::PropsDrawnFor(prop))
      {
        internals.ReceiverKeys.emplace_back(AddRenderPassKey(drawn, this));
        internals.Receivers.push_back(drawn);
        this->AddReceiverLeaves(drawn);
      }
    }
  }
}

bool vtkSoftShadowPass::DrawsForReceiver(vtkActor* actor) const
{
  const vtkInternals& internals = *this->Internals;
  return internals.ReceiverLeaves.count(actor) ||
    internals.ReceiverProperties.count(actor->GetProperty());
}

void vtkSoftShadowPass::AddReceiverLeaves(vtkProp* receiver)
{
  // Here, before anything is drawn: walking an assembly's paths rebuilds them when a part was
  // modified, and VTK modifies each part (PokeMatrix) as it draws it, walking those paths.
  vtkInternals& internals = *this->Internals;
  receiver->InitPathTraversal();
  while (vtkAssemblyPath* path = receiver->GetNextPath())
  {
    vtkProp* leaf = path->GetLastNode()->GetViewProp();
    internals.ReceiverLeaves.insert(leaf);
    if (auto actor = vtkActor::SafeDownCast(leaf))
    {
      internals.ReceiverProperties.insert(actor->GetProperty());
    }
  }
}

void vtkSoftShadowPass::RemoveReceiverKeys()
{
  // From the keys the pass went into: an assembly gives its parts its own keys as VTK draws
  // them, and a part also in the renderer keeps them.
  for (vtkInformation* keys : this->Internals->ReceiverKeys)
  {
    keys->Remove(vtkOpenGLRenderPass::RenderPasses(), this);
  }
  this->Internals->ReceiverKeys.clear();
  this->Internals->Receivers.clear();
  this->Internals->ReceiverLeaves.clear();
  this->Internals->ReceiverProperties.clear();
}

//------------------------------------------------------------------------------
namespace
{
/// Binds the LI framebuffer for the depth pass: no colour output (the LI texture is bound for
/// sampling while it draws; the caster meshes' draw attaches the surface planes itself), the
/// viewport's size, depth test and writes on. The bindings and state are restored when it goes
/// out of scope.
class ScopedDepthDrawing
{
public:
  ScopedDepthDrawing(
    vtkOpenGLState* state, penumbra::LightIntensityBuffer& buffer, const int size[2])
    : Bindings(state)
    , Saved(state)
  {
    buffer.BindLayer(0);
    state->vtkglDrawBuffer(GL_NONE);
    state->vtkglViewport(0, 0, size[0], size[1]);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_TRUE);
  }
  ScopedDepthDrawing(const ScopedDepthDrawing&) = delete;
  ScopedDepthDrawing& operator=(const ScopedDepthDrawing&) = delete;

private:
  penumbra::ScopedFramebufferBindings Bindings;
  penumbra::ScopedDrawState Saved; // stencil write mask and clear depth included
};
} // namespace

void vtkSoftShadowPass::RenderDepth(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLState* ostate = internals.Window->GetState();
  ScopedDepthDrawing drawing(ostate, internals.LI, internals.Size);
  ostate->vtkglStencilMask(0xFF);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  internals.DepthFromMeshes.clear();
  internals.SurfacePlanesDrawn = false;
  std::vector<vtkProp*> drawnByVTK;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (penumbra::OutsideTheShadows(prop))
    {
      continue;
    }
    const bool fromMesh = this->DepthFromCasterMeshes && GetCastsShadows(prop) &&
      penumbra::CasterDepth::DrawnAsItsTriangles(prop);
    (fromMesh ? internals.DepthFromMeshes : drawnByVTK).push_back(prop);
  }
  this->RenderDepthWithVTK(s, drawnByVTK);
}

void vtkSoftShadowPass::RenderCasterDepth(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLState* ostate = internals.Window->GetState();
  ScopedDepthDrawing drawing(ostate, internals.LI, internals.Size);
  ostate->vtkglDepthFunc(GL_LEQUAL); // VTK's
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglDisable(GL_BLEND);
  // The planes' offsets about the near plane's centre: small where the view rays need them.
  const std::array<glm::dvec3, 4>& corners = internals.NearCorners;
  internals.SurfacePlanesOrigin = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
  const penumbra::ShadowFrame frame = internals.MakeFrame();
  // VTK first: it writes no planes, so a surface it drew later could hide a mesh's plane under
  // its own depth.
  std::vector<vtkProp*> drawnByVTK = internals.CasterDepth.Select(frame, internals.DepthFromMeshes);
  this->RenderDepthWithVTK(s, drawnByVTK);
  const bool planes = internals.SurfacePlanesForDepth && internals.CasterDepth.HasSelected();
  if (!planes)
  {
    internals.LI.ReleaseSurfacePlanes(internals.Window);
  }
  internals.SurfacePlanesDrawn =
    planes && internals.LI.AttachClearedSurfacePlanes(internals.Window);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDisable(GL_BLEND);
  std::vector<vtkProp*> left = internals.CasterDepth.Draw(frame, internals.SurfacePlanesDrawn);
  if (!left.empty())
  {
    internals.SurfacePlanesDrawn = false; // (VTK draws them without)
    ostate->vtkglDrawBuffer(GL_NONE);
    this->RenderDepthWithVTK(s, left);
  }
  this->NumberOfPropsWithDepthFromMeshes =
    static_cast<vtkIdType>(internals.DepthFromMeshes.size() - drawnByVTK.size() - left.size());
  this->NumberOfPropsWithCulledDepth = internals.CasterDepth.GetCulledProps();
}

void vtkSoftShadowPass::RenderDepthWithVTK(const vtkRenderState* s, std::vector<vtkProp*>& props)
{
  if (props.empty())
  {
    return;
  }
  vtkInternals& internals = *this->Internals;
  vtkRenderState depthState(s->GetRenderer());
  depthState.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  depthState.SetFrameBuffer(internals.LI.GetFramebuffer());
  penumbra::ScopedActiveCamera shadowCamera(s->GetRenderer(), internals.Camera.Get());
  internals.DrawingDepth = true;
  internals.DepthPass->Render(&depthState);
  internals.DrawingDepth = false;
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::UpdateCasters(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  internals.Caches.BeginFrame();
  internals.Casters.clear();
  internals.Bounds.UpdateReceivers(internals.Receivers);
  for (const penumbra::DrawnSurface& surface :
    internals.SceneWalk.Casters(s->GetRenderer(), internals.CulledInView, this))
  {
    penumbra::MeshCache* mesh =
      internals.Caches.FindMesh(surface.Data, surface.Actor, surface.ViewProp, this);
    if (mesh->Topology.Empty())
    {
      continue;
    }
    penumbra::CasterCache* caster = internals.Caches.FindCaster(surface.Actor, surface.Part);
    caster->Mesh = mesh;
    caster->Opacity = surface.Opacity;
    caster->SeenThrough = surface.SeenThrough;
    vtkProperty* property = surface.Actor->GetProperty();
    const bool front = property->GetFrontfaceCulling(), back = property->GetBackfaceCulling();
    caster->CulledFaces = front && back ? GL_FRONT_AND_BACK : front ? GL_FRONT : back ? GL_BACK : 0;
    caster->Culled.clear();
    const penumbra::CasterTopology& topo = mesh->Topology;
    caster->ObjectToWorld = surface.ObjectToWorld * glm::translate(glm::dmat4(1.0), topo.Origin);
    const penumbra::Box world = penumbra::TransformedBox(
      penumbra::Box{ true, topo.BoundsMin, topo.BoundsMax }, caster->ObjectToWorld);
    caster->WorldMin = world.Min;
    caster->WorldMax = world.Max;
    internals.Casters.push_back(caster);
  }

  penumbra::PlateauSettings& settings = internals.Techniques.Plateaus.Settings;
  settings.Resolution = this->PlateauResolution;
  settings.Falloff = this->PlateauFalloff == PLATEAU_FALLOFF_SINUSOIDAL
    ? penumbra::PlateauFalloff::Sinusoidal
    : penumbra::PlateauFalloff::Linear;
  settings.UseGivenPlane = this->UseReceiverPlane;
  settings.Origin = glm::make_vec3(this->ReceiverPlaneOrigin);
  settings.Normal = glm::make_vec3(this->ReceiverPlaneNormal);
  internals.Techniques.FindPlateauPlane(s->GetRenderer(), this, internals.Lights);

  for (auto& light : internals.Lights)
  {
    const double lightRadius = GetLightRadius(light.Light);
    for (penumbra::CasterCache* caster : internals.Casters)
    {
      const double radius = light.World.w != 0.0 ? lightRadius : glm::radians(lightRadius);
      if (!penumbra::ShadowMayReachView(
            caster->WorldMin, caster->WorldMax, light.World, radius, internals.WorldToClip))
      {
        caster->Culled.insert(light.Light);
        ++this->NumberOfCulledShadows;
      }
    }
    internals.SortOutTranslucentCasters(light);
    this->NumberOfSilhouetteUpdates += internals.UpdateLightCasters(light);
    if (internals.Techniques.Reconsider(
          light, internals.Casters, this->LightSamples, internals.Window, internals.Size, this))
    {
      this->NumberOfSilhouetteUpdates += internals.UpdateLightCasters(light);
    }
    this->NumberOfSilhouetteUpdates += internals.FinishLight(light);
  }
}

vtkIdType vtkSoftShadowPass::vtkInternals::FinishLight(const ShadowLight& light)
{
  light.Technique->PrepareLight(light, this->Casters);
  return this->UpdateTranslucentVolumes(light);
}

void vtkSoftShadowPass::vtkInternals::SortOutTranslucentCasters(ShadowLight& light)
{
  light.ShadowedByTranslucentCasters = false;
  for (penumbra::CasterCache* caster : this->Casters)
  {
    if (!caster->Translucent() || caster->Culled.count(light.Light))
    {
      continue;
    }
    if (light.Technique->ShadowsTranslucentCasters())
    {
      light.ShadowedByTranslucentCasters = true;
      continue;
    }
    if (!this->WarnedTranslucent)
    {
      vtkWarningWithObjectMacro(this->Owner,
        "Penumbra wedges and plateaus leave translucent casters out: they cast no shadow. "
        "Hard shadows, averaged hard shadows and soft shadow volumes shadow them by their "
        "opacity.");
      this->WarnedTranslucent = true;
    }
    caster->Culled.insert(light.Light);
  }
}

vtkIdType vtkSoftShadowPass::vtkInternals::UpdateLightCasters(const ShadowLight& light)
{
  vtkIdType updates = 0;
  for (penumbra::CasterCache* caster : this->Casters)
  {
    if (caster->Culled.count(light.Light) || caster->Translucent())
    {
      continue; // translucent casters: UpdateTranslucentVolumes
    }
    updates += penumbra::ShadowVolumeRenderer::UpdateOpaque(light, *caster);
    updates += light.Technique->UpdateCaster(light, *caster, this->Bounds.Receivers());
  }
  return updates;
}

vtkIdType vtkSoftShadowPass::vtkInternals::UpdateTranslucentVolumes(const ShadowLight& light)
{
  vtkIdType updates = 0;
  for (penumbra::CasterCache* caster : this->Casters)
  {
    if (!caster->Translucent() || caster->Culled.count(light.Light))
    {
      continue;
    }
    updates += penumbra::ShadowVolumeRenderer::UpdateTranslucent(light, *caster);
  }
  return updates;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::RenderLightIntensity(vtkOpenGLRenderWindow* window)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLState* ostate = window->GetState();
  penumbra::ShadowFrame frame = internals.MakeFrame();
  if (!internals.Volumes.Begin(frame))
  {
    return false;
  }

  penumbra::ScopedFramebufferBindings bindings(ostate);
  penumbra::ScopedDrawState saved(ostate);
  ostate->vtkglViewport(0, 0, internals.Size[0], internals.Size[1]);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglDisable(GL_STENCIL_TEST); // each draw that reads the counts turns it on
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  ostate->vtkglBlendFunc(GL_ONE, GL_ONE);
  auto drawLayer = [&](const vtkInternals::ShadowLight& light)
  {
    // Each light's volumes and technique leave the state as they found it.
    penumbra::ScopedDrawState savedForLight(ostate);
    // The layer starts fully lit; the technique takes away what each sample's volume count
    // shadows (from the stencil, or from the colour count of CountsInColour), then adds what
    // is its own. Float target, additive, no clamping.
    internals.LI.BindLayer(light.Layer);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    internals.StageTimes.Begin(penumbra::StageTimes::Volumes); // counting's depth included
    light.Technique->BeginVolumes(frame, light);
    for (std::size_t k = 0; k < light.Samples.size(); ++k)
    {
      internals.Volumes.DrawOpaqueSample(frame, light, k);
      vtkOpenGLState::ScopedglEnableDisable depthClamp(ostate, GL_DEPTH_CLAMP);
      ostate->vtkglEnable(GL_DEPTH_CLAMP); // the full-screen triangle lies on the far plane
      light.Technique->ResolveSample(frame, light, k);
    }
    internals.StageTimes.End(penumbra::StageTimes::Volumes);
    penumbra::StageTimes::Scope timedWedges(internals.StageTimes, penumbra::StageTimes::Wedges);
    light.Technique->Finish(frame, light);
  };
  for (auto& light : internals.Lights)
  {
    if (internals.LayersKept[light.Layer])
    {
      continue; // drawn by the last frame from the same light and scene
    }
    ++this->NumberOfRedrawnLights;
    const penumbra::TechniqueCounts before = frame.Counts;
    drawLayer(light);
    if (internals.Techniques.AverageIfFirstCountWentDeep(light, this->LightSamples, window))
    {
      frame.Counts = before; // the count drawn is replaced, not shown
      this->NumberOfSilhouetteUpdates += internals.UpdateLightCasters(light);
      this->NumberOfSilhouetteUpdates += internals.FinishLight(light);
      drawLayer(light);
    }
    this->NumberOfAveragedLights += light.Samples.size() > 1 ? 1 : 0;
  }
  this->NumberOfShadowVolumeTriangles = internals.Volumes.GetTriangles();
  this->NumberOfZFailVolumes = internals.Volumes.GetZFailVolumes();
  this->NumberOfPenumbraWedges = frame.Counts.Wedges;
  this->NumberOfFullViewportWedges = frame.Counts.FullViewportWedges;
  this->NumberOfPlateauTriangles = frame.Counts.PlateauTriangles;
  this->NumberOfCountedLights = frame.Counts.CountedLights;
  return true;
}

penumbra::ShadowFrame vtkSoftShadowPass::vtkInternals::MakeFrame()
{
  penumbra::ShadowFrame frame;
  frame.Window = this->Window;
  frame.Size[0] = this->Size[0];
  frame.Size[1] = this->Size[1];
  frame.WorldToClip = this->WorldToClip;
  frame.ClipToWorld = glm::inverse(this->WorldToClip);
  frame.NearCorners = this->NearCorners;
  frame.Casters = &this->Casters;
  frame.Buffer = &this->LI;
  frame.SurfacePlanes = this->SurfacePlanesDrawn ? this->LI.GetSurfacePlanes() : nullptr;
  frame.SurfacePlanesOrigin = this->SurfacePlanesOrigin;
  frame.Programs = &this->Programs;
  frame.FullScreen = &this->FullScreen;
  frame.ResolveVAO = &this->ResolveVAO;
  frame.SceneBox = this->Bounds.Scene();
  frame.Volumes = &this->Volumes;
  return frame;
}

//------------------------------------------------------------------------------
vtkImageData* vtkSoftShadowPass::GetVisibilityImage(int lightIndex)
{
  if (lightIndex < 0)
  {
    vtkErrorMacro("GetVisibilityImage(" << lightIndex
                                        << "): lights are numbered from 0, in the order of the "
                                           "renderer's light collection.");
    return nullptr;
  }
  vtkInternals& internals = *this->Internals;
  const vtkInternals::ShadowLight* light = internals.FindLight(lightIndex);
  vtkOpenGLRenderWindow* window = internals.Window;
  if (!light || !window || internals.LI.GetLayerCount() == 0)
  {
    return nullptr;
  }
  if (internals.VisibilityImages.size() < internals.Lights.size())
  {
    internals.VisibilityImages.resize(internals.Lights.size());
  }
  vtkSmartPointer<vtkImageData>& image = internals.VisibilityImages[light->Layer];
  if (image)
  {
    return image;
  }
  window->MakeCurrent();
  vtkPixelBufferObject* download = internals.LI.GetLayers()->Download();
  if (!download)
  {
    vtkErrorMacro("Could not read the light-intensity buffer back.");
    return nullptr;
  }
  const int width = internals.Size[0], height = internals.Size[1];
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  const float* data = static_cast<const float*>(download->MapPackedBuffer());
  vtkNew<vtkFloatArray> values;
  values->SetName("Visibility");
  values->SetNumberOfValues(pixels);
  // Overlapping penumbrae add up: the buffer is clamped where it is used, and here. A value
  // that is not finite is a bug to expose, not to clamp away: it is returned as NaN.
  std::transform(data + light->Layer * pixels, data + (light->Layer + 1) * pixels,
    values->GetPointer(0),
    [](float v)
    {
      return std::isfinite(v) ? std::min(1.0f, std::max(0.0f, v))
                              : std::numeric_limits<float>::quiet_NaN();
    });
  download->UnmapPackedBuffer();
  download->Delete();

  image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->GetPointData()->SetScalars(values);
  return image;
}

//------------------------------------------------------------------------------
namespace
{
/// The shadowing lights as the receivers' shaders number them.
template <typename ShadowLights>
std::vector<penumbra::ReceiverLight> ReceiverLights(const ShadowLights& lights)
{
  std::vector<penumbra::ReceiverLight> receiverLights;
  for (const auto& light : lights)
  {
    receiverLights.push_back({ light.ShaderIndex, light.Layer });
  }
  return receiverLights;
}
} // namespace

bool vtkSoftShadowPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  const auto& lights = this->Internals->Lights;
  if (!lights.empty() &&
    !penumbra::InsertLightDeclarations(fragmentShader, penumbraReceiverDec, ReceiverLights(lights)))
  {
    this->WarnShaderEdit(mapper, prop,
      "does not have VTK's //VTK::Light::Dec tag exactly once (a vtkShaderProperty replacing "
      "or repeating it?)");
  }
  return true;
}

bool vtkSoftShadowPass::PostReplaceShaderValues(std::string&, std::string& geometryShader,
  std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  const auto& lights = this->Internals->Lights;
  if (lights.empty() || fragmentShader.find("penumbraLightFactor") == std::string::npos)
  {
    return true; // nothing inserted, already reported
  }
  penumbra::KeepEdgesOutOfDepthPass(geometryShader);
  penumbra::KeepOffsetOutOfDepthPass(fragmentShader);
  auto actor = vtkActor::SafeDownCast(prop);
  // Actors that a prop such as vtkCubeAxesActor draws through, unseen by the renderer, are its
  // annotation: VTK draws their lines unlit by design, so they say nothing.
  if (penumbra::IsUnlit(fragmentShader) && actor && this->DrawsForReceiver(actor))
  {
    // Worth saying: vedo's Plane, for one, is unlit by default, and VTK draws streamlines
    // (whose normals vtkStreamTracer does not make active) unlit. Splats are unlit by nature
    // and say nothing.
    if (!actor->GetProperty()->GetLighting())
    {
      this->WarnShaderEdit(
        mapper, prop, "is written without lighting (its vtkProperty has Lighting off)");
    }
    else if (penumbra::IsExactly(mapper, "vtkOpenGLPolyDataMapper") ||
      penumbra::IsExactly(mapper, "vtkCompositeMapperHelper2"))
    {
      this->WarnShaderEdit(mapper, prop,
        "for points, lines or vertices is written without lighting (VTK 9.1 lights them only "
        "where the data has active point normals, vtkPointData::SetActiveNormals, and the "
        "interpolation is not flat)");
    }
    return true;
  }
  // VTK's vtkShadowMapPass, later in the delegate chain, declares its shadow maps before and
  // scales VTK's light statements after this pass, which leaves them as they are: each light
  // is darkened by both passes' shadows.
  if (fragmentShader.find("uniform sampler2D shadowMap") != std::string::npos &&
    !this->Internals->WarnedShadowMapPass)
  {
    vtkWarningMacro("VTK's vtkShadowMapPass draws inside this pass: both scale the same light "
                    "terms, so each light is darkened by both passes' shadows. Use one or the "
                    "other.");
    this->Internals->WarnedShadowMapPass = true;
  }
  const std::vector<int> missing =
    penumbra::ScaleLightColours(fragmentShader, ReceiverLights(lights));
  if (!missing.empty())
  {
    std::string which = missing.size() == 1 ? "light " : "lights ";
    for (std::size_t k = 0; k < missing.size(); ++k)
    {
      which += (k ? ", " : "") + std::to_string(missing[k]);
    }
    this->WarnShaderEdit(
      mapper, prop, "does not use the colour of " + which + " (light code of its own?)");
  }
  return true;
}

void vtkSoftShadowPass::WarnShaderEdit(
  vtkAbstractMapper* mapper, vtkProp* prop, const std::string& problem)
{
  const std::string key = std::string(mapper ? mapper->GetClassName() : "") + ": " + problem;
  if (!this->Internals->WarnedShaderEdits.First(prop, key))
  {
    return;
  }
  std::ostringstream what;
  what << (prop ? prop->GetClassName() : "a prop") << " (" << prop << ", drawn by "
       << (mapper ? mapper->GetClassName() : "a mapper") << ")";
  vtkWarningMacro(
    "The fragment shader of " << what.str() << " " << problem << ": it is drawn unshadowed.");
}

bool vtkSoftShadowPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  vtkInternals& internals = *this->Internals;
  if (program->IsUniformUsed("penumbraDepthPass"))
  {
    program->SetUniformi("penumbraDepthPass", internals.DrawingDepth ? 1 : 0);
  }
  if (internals.Lights.empty() || !program->IsUniformUsed("penumbraApply"))
  {
    return true;
  }
  // The LI buffer covers the viewport. A pass drawing into a framebuffer of its own (SSAO, depth
  // peeling, tone mapping) puts the viewport at that framebuffer's origin, not the window's:
  // take the origin of the viewport being drawn.
  GLint viewport[4] = { internals.Origin[0], internals.Origin[1], internals.Size[0],
    internals.Size[1] };
  if (internals.Window)
  {
    internals.Window->GetState()->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  }
  const bool placed = this->ViewportMatchesShadows(viewport);
  const bool apply = placed && internals.ApplyShadows && GetReceivesShadows(prop) &&
    !prop->IsRenderingTranslucentPolygonalGeometry();
  program->SetUniformi("penumbraApply", apply ? 1 : 0);
  // The window's renderers share programs, and VTK uploads a program's light uniforms only when
  // the renderer's lights or camera are newer than its last upload, which may have been another
  // renderer's (vtkOpenGLRenderer::UpdateLightingUniforms): with the user's camera unmodified,
  // one viewport's receivers drew with the other's lights. Ask for the upload on every draw.
  program->SetUniformGroupUpdateTime(vtkShaderProgram::LightingGroup, 0);
  program->SetUniformi("penumbraLI", internals.LI.GetLayers()->GetTextureUnit());
  const int origin[2] = { viewport[0], viewport[1] };
  program->SetUniform2i("penumbraOrigin", origin);
  program->SetUniform2i("penumbraSize", internals.Size);
  std::vector<float> attenuation;
  for (const auto& light : internals.Lights)
  {
    attenuation.push_back(light.Attenuation);
  }
  program->SetUniform1fv(
    "penumbraAttenuation", static_cast<int>(attenuation.size()), attenuation.data());
  return true;
}

bool vtkSoftShadowPass::ViewportMatchesShadows(const int viewport[4])
{
  vtkInternals& internals = *this->Internals;
  if (!internals.ApplyShadows)
  {
    return true;
  }
  const bool matches = viewport[2] == internals.Size[0] && viewport[3] == internals.Size[1];
  ++(matches ? internals.DrawsAtShadowSize : internals.DrawsAtOtherSizes);
  if (!matches)
  {
    internals.OtherSize[0] = viewport[2];
    internals.OtherSize[1] = viewport[3];
  }
  return matches;
}

void vtkSoftShadowPass::WarnOfDelegateSize()
{
  vtkInternals& internals = *this->Internals;
  // Passes that draw the scene elsewhere too (vtkShadowMapPass's maps) also draw it at the
  // shadows' size; a delegate that never does pads or supersamples the frame.
  if (internals.DrawsAtOtherSizes == 0 || internals.DrawsAtShadowSize > 0 ||
    internals.WarnedDelegateSize)
  {
    return;
  }
  vtkWarningMacro(<< "The delegate draws the scene " << internals.OtherSize[0] << " x "
                  << internals.OtherSize[1] << " pixels large, not at the shadows' "
                  << internals.Size[0] << " x " << internals.Size[1]
                  << " (a pass that pads or supersamples its image, such as "
                     "vtkDepthOfFieldPass, vtkGaussianBlurPass or vtkSSAAPass, inside this one): "
                     "the shadows cannot be placed, and the frame is drawn unshadowed. Put such "
                     "a pass around this one.");
  internals.WarnedDelegateSize = true;
}

vtkMTimeType vtkSoftShadowPass::GetShaderStageMTime()
{
  return this->Internals->ShaderStageTime.GetMTime();
}

//------------------------------------------------------------------------------
static_assert(static_cast<int>(penumbra::StageTimes::Count) == vtkSoftShadowPass::NUMBER_OF_STAGES,
  "one stage list");

const char* vtkSoftShadowPass::GetStageName(int stage)
{
  static const char* const names[NUMBER_OF_STAGES] = { "depth", "casters", "volumes", "wedges",
    "compositing" };
  return stage >= 0 && stage < NUMBER_OF_STAGES ? names[stage] : "unknown";
}

double vtkSoftShadowPass::GetStageCPUMilliseconds(int stage)
{
  return stage >= 0 && stage < NUMBER_OF_STAGES
    ? this->Internals->StageTimes.CpuMilliseconds(static_cast<penumbra::StageTimes::Stage>(stage))
    : -1.0;
}

double vtkSoftShadowPass::GetStageGPUMilliseconds(int stage)
{
  return stage >= 0 && stage < NUMBER_OF_STAGES
    ? this->Internals->StageTimes.GpuMilliseconds(static_cast<penumbra::StageTimes::Stage>(stage))
    : -1.0;
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::WarnOfLightsReachingTheScene(vtkRenderer* renderer)
{
  vtkInternals& internals = *this->Internals;
  for (const vtkInternals::ShadowLight& light : internals.Lights)
  {
    // The light's own radius (SampleRadius: world units for a positional light), not the one
    // counting grows about its reference.
    if (light.World.w == 0.0 || !(light.SampleRadius > 0.0) ||
      internals.WarnedLights.Said(light.Light, "reaching"))
    {
      continue;
    }
    const double distance =
      penumbra::SceneBounds::NearestPropSurface(renderer, glm::dvec3(light.World));
    if (distance < light.SampleRadius)
    {
      internals.WarnedLights.First(light.Light, "reaching");
      vtkWarningMacro("Light " << light.Light << " has a radius of " << light.SampleRadius
                               << ", more than its distance to the nearest visible prop's box ("
                               << distance
                               << "): points inside its sphere see all of it, but soft shadows "
                                  "sample it as a disk facing the scene, so shadows near it "
                                  "are wrong. Give it a radius below that distance.");
    }
  }
}

bool vtkSoftShadowPass::LayersFit(vtkOpenGLRenderWindow* window)
{
  vtkInternals& internals = *this->Internals;
  if (internals.MaxLayerSizeWindow != window)
  {
    GLint size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
    internals.MaxLayerSize = size;
    internals.MaxLayerSizeWindow = window;
  }
  const int layers = static_cast<int>(internals.Lights.size());
  const int largest = std::max(internals.Size[0], internals.Size[1]);
  const bool sizeFits = largest <= internals.MaxLayerSize;
  if (sizeFits && internals.LI.Prepare(window, internals.Size[0], internals.Size[1], layers))
  {
    internals.WarnedLayerSize = false;
    return true;
  }
  if (!internals.WarnedLayerSize)
  {
    if (sizeFits)
    {
      vtkWarningMacro("The shadows' light intensity for "
        << layers << " lights at " << internals.Size[0] << "x" << internals.Size[1]
        << " pixels needs "
        << penumbra::LightIntensityBuffer::LayerBytes(
             internals.Size[0], internals.Size[1], layers) /
          (1 << 20)
        << " MiB of GPU memory in one texture, which this OpenGL refused: the scene is drawn "
           "without shadows at this size. Fewer shadowing lights or a smaller frame fit.");
    }
    else
    {
      vtkWarningMacro("The frame is " << internals.Size[0] << "x" << internals.Size[1]
                                      << " pixels, but this OpenGL's 2D textures, which hold the "
                                         "shadows' light intensity, reach "
                                      << internals.MaxLayerSize
                                      << " pixels at most: the scene is drawn without shadows "
                                         "at this size.");
    }
    internals.WarnedLayerSize = true;
  }
  return false;
}

void vtkSoftShadowPass::FollowWindow(vtkOpenGLRenderWindow* window)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLRenderWindow* previous = internals.Window;
  if (previous && previous != window && !internals.WarnedWindowChange)
  {
    vtkWarningMacro("This pass draws into a second render window ("
      << window << " after " << previous
      << "): its GPU buffers are remade each time it changes window. Give each window a "
         "vtkSoftShadowPass of its own.");
    internals.WarnedWindowChange = true;
  }
  // Textures, buffers and vertex arrays belong to the context they were made in: drawn with in
  // another context, they crash the driver. The callback releases them in the window followed
  // until now, in its context, and from now on when this window finalizes its context.
  internals.WindowRelease->RegisterGraphicsResources(window);
  internals.Window = window;
}

void vtkSoftShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& internals = *this->Internals;
  internals.ForgetInputs();
  internals.StageTimes.ReleaseGraphicsResources();
  internals.Caches.ReleaseGraphicsResources();
  internals.LI.ReleaseGraphicsResources(w);
  for (penumbra::ShadowTechnique* technique : internals.Techniques.All())
  {
    technique->ReleaseGraphicsResources(w);
  }
  internals.FullScreen.ReleaseGraphicsResources();
  internals.ResolveVAO.ReleaseGraphicsResources();
  internals.DepthPass->ReleaseGraphicsResources(w);
  internals.VisibilityImages.clear();
  // A window made later may take this one's address.
  internals.MaxLayerSizeWindow = nullptr;
  if (this->DelegatePass && !internals.InDelegateChain)
  {
    DelegateChainScope chain(internals.InDelegateChain);
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  this->Superclass::ReleaseGraphicsResources(w);
}
