#include "vtkSoftShadowPass.h"

#include "penumbraShadowCaches.h"

#include "penumbraReceiverShader.h"
#include "penumbraSceneWalk.h"
#include "penumbraStageTimes.h"

#include "vtkActor.h"
#include "vtkFloatArray.h"
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
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPixelBufferObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRendererSettingsPass.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "penumbraCulling.h"
#include "penumbraLightSamples.h"
#include "penumbraMatrices.h"
#include "penumbraPlateaus.h"
#include "penumbraSampleCounting.h"
#include "penumbraShadowVolume.h"

#include "penumbraCountingResolveFS.h"
#include "penumbraCountingWedgeFS.h"
#include "penumbraCountingWedgeVS.h"
#include "penumbraDepthPointDec.h"
#include "penumbraHorizonFS.h"
#include "penumbraPlateauFS.h"
#include "penumbraPlateauResolveFS.h"
#include "penumbraPlateauVS.h"
#include "penumbraReceiverDec.h"
#include "penumbraResolveFS.h"
#include "penumbraResolveVS.h"
#include "penumbraShadowVolumeFS.h"
#include "penumbraShadowVolumeVS.h"
#include "penumbraWedgeFS.h"
#include "penumbraWedgeVS.h"

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
vtkCxxSetObjectMacro(vtkSoftShadowPass, DelegatePass, vtkRenderPass);

vtkInformationKeyMacro(vtkSoftShadowPass, LIGHT_RADIUS, Double);
vtkInformationKeyMacro(vtkSoftShadowPass, CASTS_SHADOWS, Integer);
vtkInformationKeyMacro(vtkSoftShadowPass, RECEIVES_SHADOWS, Integer);
vtkInformationKeyMacro(vtkSoftShadowPass, SHADOW_PLANE, Integer);

namespace
{

void AddRenderPassKey(vtkProp* prop, vtkOpenGLRenderPass* pass)
{
  vtkInformation* info = prop->GetPropertyKeys();
  if (!info)
  {
    vtkNew<vtkInformation> keys;
    prop->SetPropertyKeys(keys);
    info = keys;
  }
  info->Append(vtkOpenGLRenderPass::RenderPasses(), pass);
}

vtkIdType DrawShadowVolume(vtkOpenGLState* ostate, vtkShaderProgram* program,
  penumbra::CasterCache& caster, const std::pair<vtkLight*, int>& key, const glm::dvec4& lightWorld,
  const glm::dmat4& worldToClip, const std::array<glm::dvec3, 4>& nearCorners, bool countInColor,
  vtkIdType& zFailCount);

} // namespace

//------------------------------------------------------------------------------
class vtkSoftShadowPass::vtkInternals
{
public:
  /// What a light's layer is made of.
  enum class Technique
  {
    HardSamples,    ///< hard shadows of its Samples, averaged (one: hard volumes)
    PenumbraWedges, ///< the centre's count plus centre-silhouette wedges
    Plateaus,       ///< the centre's hard shadow plus plateaus on the receiver plane
    SampleCounting  ///< the centre's count plus each sample's changes (soft shadow volumes)
  };
  struct ShadowLight
  {
    vtkLight* Light = nullptr;
    int CollectionIndex = 0; ///< index in the renderer's light collection
    int ShaderIndex = 0; ///< index among switched-on lights: the N of lightColorN in VTK's shaders
    int Layer = 0;       ///< layer of the LI buffer
    glm::dvec4 World{ 0.0 }; ///< (position, 1) or (direction towards the light, 0)
    float Attenuation = 1.0f;
    /// How this light's layer is drawn; set by ChooseMethod, and by the cost model for
    /// Automatic's soft lights (UpdateCasters).
    Technique Method = Technique::HardSamples;
    /// Points (or directions) on the light whose hard shadows are averaged (HardSamples: one for
    /// hard shadows), or the light itself for the other techniques.
    std::vector<glm::dvec4> Samples;
    /// The light's radius for wedges, plateaus and counting: world units, or radians for a
    /// directional light.
    double SoftRadius = 0.0;
    glm::dvec3 SampleTarget{ 0.0 };
    double SampleRadius = 0.0; ///< as SpreadLightSamples takes it: world units, or clamped degrees
    /// SampleCounting: the samples whose counts the potential silhouette changes.
    std::vector<glm::dvec4> CountingSamples;
    /// Automatic picked counting: it may still average the same samples where that is cheaper.
    bool CountingChosenAutomatically = false;

    bool Is(Technique technique) const { return this->Method == technique; }
    /// Wedges and counting count the centre's volumes in colour, not in the stencil.
    bool CountsCentreInColour() const
    {
      return this->Is(Technique::PenumbraWedges) || this->Is(Technique::SampleCounting);
    }
    /// Cache key of sample k's volume. The light's centre has a key of its own, so that the
    /// centre silhouette (wedges, counting) and averaged samples never evict each other.
    std::pair<vtkLight*, int> VolumeKey(std::size_t k) const
    {
      return { this->Light, this->CountsCentreInColour() ? CentreVolume : static_cast<int>(k) };
    }
  };
  static constexpr int CentreVolume = -1;

  penumbra::ShadowCaches Caches;
  penumbra::SceneWalk SceneWalk;
  penumbra::StageTimes StageTimes;
  /// The pass, for the warnings and errors the internals report.
  vtkObject* Owner = nullptr;
  /// Programs that did not build, reported once each.
  std::set<std::string> FailedPrograms;
  /// Readies one of the pass's shader programs. One that does not build is reported once, with
  /// what the pass does instead (`instead`), and nullptr returned.
  vtkShaderProgram* ReadyProgram(vtkOpenGLRenderWindow* window, const char* vertexShader,
    const char* fragmentShader, const char* name, const char* instead);
  /// Prop and problem of every shader edit warned about (once each).
  std::set<std::string> WarnedShaderEdits;
  std::vector<ShadowLight> Lights;
  std::vector<penumbra::CasterCache*> Casters;
  std::vector<vtkProp*> Receivers;
  /// Holds every receiver (penumbra::StableReceiverBox): wedges are cut to it.
  penumbra::Box ReceiverBox;
  void UpdateReceiverBox();
  std::set<vtkLight*> WarnedLights;

  std::string ShaderConfiguration;
  vtkTimeStamp ShaderStageTime;
  bool ApplyShadows = false;

  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkTextureObject> DepthStencil;
  /// The scene depth again, for the wedge shaders to read while DepthStencil is the attachment
  /// their depth test uses.
  vtkNew<vtkTextureObject> DepthCopy;
  vtkNew<vtkOpenGLFramebufferObject> DepthCopyFramebuffer;
  void CopyDepth(vtkOpenGLState* ostate);
  /// Bytes of GPU memory held: framebuffer textures (4 bytes per texel each) and cached buffers.
  std::size_t GraphicsMemoryBytes() const
  {
    const std::size_t pixels = static_cast<std::size_t>(this->Size[0]) * this->Size[1];
    const std::size_t texturePixels = this->DepthStencil->GetHandle() ? pixels * 2 : 0;
    const std::size_t plateauTexels = this->Plateau.Depth->GetHandle()
      ? static_cast<std::size_t>(this->Plateau.Depth->GetWidth()) * this->Plateau.Depth->GetHeight()
      : 0;
    const std::size_t plateauBuffer = this->Plateau.Vertices->GetHandle()
      ? this->Plateau.Triangles.size() * sizeof(penumbra::PlateauVertex)
      : 0;
    const std::size_t countingTexels =
      this->CentreCount->GetHandle() ? pixels * (1 + this->SampleCounters->GetDepth()) : 0;
    return (texturePixels + plateauTexels + pixels * this->Layers + countingTexels) * 4 +
      plateauBuffer + this->Caches.GraphicsBufferBytes();
  }
  vtkNew<vtkTextureObject> LightIntensity;

  /// The receiver plane of METHOD_PLATEAUS this frame, and the plateau texture's resources.
  struct PlateauState
  {
    bool HavePlane = false;
    penumbra::ReceiverPlane Plane;
    vtkProp* PlaneProp = nullptr; ///< the marked actor, if the plane is one
    bool Bounded = false;         ///< the plane is an actor: plane coordinates bounds
    glm::dvec2 Min{ 0.0 }, Max{ 0.0 };
    double Tolerance = 0.0; ///< distance still counted as on the plane
    /// The actor whose plane was last fitted, and when: refitted only when it, its mapper or its
    /// data change.
    vtkProp* FittedProp = nullptr;
    vtkMTimeType FittedAt = 0;
    std::set<vtkProp*> WarnedProps;
    bool WarnedNoPlane = false;
    std::vector<penumbra::PlateauVertex> Triangles;
    /// What the triangles and the texture were made from (light, plane, casters' silhouettes
    /// and matrices): while it holds, an orbiting camera redraws neither.
    std::vector<double> Signature;
    glm::dvec2 Lo{ 0.0 }, Hi{ 0.0 };
    bool TextureCurrent = false;
    vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
    vtkNew<vtkTextureObject> Depth;
    vtkNew<vtkOpenGLBufferObject> Vertices;
    vtkNew<vtkOpenGLVertexArrayObject> VAO;
    vtkShaderProgram* VAOProgram = nullptr;
  } Plateau;
  /// Renders `light`'s plateaus over the receiver plane, then writes them into its LI layer at
  /// the pixels on the plane; returns the plateau triangles drawn.
  vtkIdType DrawPlateaus(
    vtkSoftShadowPass* self, vtkOpenGLRenderWindow* window, const ShadowLight& light);
  /// Draws the current plateau triangles into the plateau texture over [lo, lo + size].
  bool RenderPlateauTexture(vtkSoftShadowPass* self, vtkOpenGLRenderWindow* window,
    const glm::dvec2& lo, const glm::dvec2& size);
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };
  int Layers = 0;

  /// A full-screen triangle at the far plane, drawn by the resolve and horizon passes.
  struct FullScreenVAO
  {
    vtkNew<vtkOpenGLVertexArrayObject> VAO;
    vtkShaderProgram* Program = nullptr;
  };
  vtkNew<vtkOpenGLBufferObject> FullScreenTriangle;
  FullScreenVAO ResolveVAO;
  FullScreenVAO HorizonVAO;
  FullScreenVAO PlateauResolveVAO;
  void DrawFullScreen(vtkShaderProgram* program, FullScreenVAO& vao);

  vtkNew<vtkOpaquePass> DepthPass;
  vtkNew<vtkLightsPass> LightsPass;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
  std::vector<vtkSmartPointer<vtkImageData>> VisibilityImages;

  glm::dmat4 WorldToClip{ 1.0 };
  std::array<glm::dvec3, 4> NearCorners;

  /// The camera's world-to-clip matrix and near-plane corners, as VTK's mappers use them.
  void UpdateCamera(vtkRenderer* renderer)
  {
    vtkMatrix4x4 *worldToView, *viewToClip, *worldToClip;
    vtkMatrix3x3* normals;
    static_cast<vtkOpenGLCamera*>(renderer->GetActiveCamera())
      ->GetKeyMatrices(renderer, worldToView, normals, viewToClip, worldToClip);
    // VTK keeps its key matrices transposed for OpenGL: element [i][j] is glm's column i, row j.
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        this->WorldToClip[i][j] = worldToClip->GetElement(i, j);
      }
    }
    const glm::dmat4 clipToWorld = glm::inverse(this->WorldToClip);
    const std::array<glm::dvec2, 4> ndc = { { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } } };
    for (int i = 0; i < 4; ++i)
    {
      const glm::dvec4 p = clipToWorld * glm::dvec4(ndc[i], -1.0, 1.0);
      this->NearCorners[i] = glm::dvec3(p) / p.w;
    }
  }

  /// Fills the light's samples (the light itself, or LightSamples points on it when the method
  /// averages) and its wedge settings, from the pass's method and the light's radius.
  void ChooseMethod(vtkSoftShadowPass* self, vtkRenderer* renderer, ShadowLight& light);
  /// Allocates the counting textures for this viewport and `samples` samples, if they are not
  /// so already: only when a light is drawn by counting, so averaging lights hold none.
  void PrepareCountingBuffers(std::size_t samples);
  /// Makes `texture` (slice `layer` of a 3D texture) the framebuffer's colour attachment 0 and
  /// its draw buffer; the framebuffer must be bound.
  void AttachColour(vtkTextureObject* texture, int layer);
  /// Soft shadow volumes' buffers: the centre's count (R32F) and the per-sample counters (R32UI,
  /// four 8-bit counts per texel, one slice per four samples).
  vtkNew<vtkTextureObject> CentreCount;
  vtkNew<vtkTextureObject> SampleCounters;
  /// Whether the context has image atomics and texture clears (checked once per window).
  int CountingSupport = -1;
  bool CountingSupported(vtkSoftShadowPass* self);
  /// Brings every caster's volumes and wedges for `light` up to date; returns the silhouette
  /// updates it made.
  vtkIdType UpdateLightCasters(const ShadowLight& light);
  /// Per caster, what the choice between counting and averaging `light`'s samples weighs.
  std::vector<penumbra::CountingCost> CountingCosts(const ShadowLight& light);
  bool WarnedCountingSamples = false;
  /// Counts `light`'s samples (its centre volume already counted into CentreCount) and writes
  /// its visibility into its LI layer; returns false when a shader failed to build.
  bool DrawSampleCounting(vtkSoftShadowPass* self, vtkOpenGLRenderWindow* window,
    const ShadowLight& light, vtkIdType& wedges, vtkIdType& fullViewport);
  FullScreenVAO CountingResolveVAO;
  /// Every full-screen pass's VAO, for releasing or re-binding them together.
  std::array<FullScreenVAO*, 4> FullScreenVAOs()
  {
    return { &this->ResolveVAO, &this->HorizonVAO, &this->PlateauResolveVAO,
      &this->CountingResolveVAO };
  }

  /// Draws one caster's wedge buffer (either kind), if it has any, with the program bound: front
  /// or back faces as the eye and near plane allow, in wedge coordinates. Adds its wedges and
  /// full-viewport ones to the counts.
  void DrawWedgeBuffer(vtkShaderProgram* program, const penumbra::CasterCache& caster,
    penumbra::WedgeBuffer& buffer, const std::vector<penumbra::VertexAttribute>& attributes,
    const ShadowLight& light, const glm::dmat4& clipToWorld, vtkIdType& wedges,
    vtkIdType& fullViewport);

  /// Adds every caster's penumbra wedges for `light` into its LI layer; returns the count of
  /// wedges and of full-viewport ones.
  void DrawWedges(vtkOpenGLRenderWindow* window, const ShadowLight& light, vtkIdType& wedges,
    vtkIdType& fullViewport);

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
  vtkNew<vtkRendererSettingsPass> scene;
  this->SetDelegatePass(scene);
}

vtkSoftShadowPass::~vtkSoftShadowPass()
{
  this->SetDelegatePass(nullptr);
}

void vtkSoftShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: ";
  if (this->DelegatePass)
  {
    os << "\n";
    this->DelegatePass->PrintSelf(os, indent.GetNextIndent());
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "ShadowsEnabled: " << this->ShadowsEnabled << "\n";
  os << indent << "Method: " << this->GetMethodAsString() << "\n";
  os << indent << "LightSamples: " << this->LightSamples << "\n";
  os << indent << "CollectStageTimes: " << this->CollectStageTimes << "\n";
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
  if (!prop->GetPropertyKeys())
  {
    vtkNew<vtkInformation> keys;
    prop->SetPropertyKeys(keys);
  }
  prop->GetPropertyKeys()->Set(key, value ? 1 : 0);
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
void vtkSoftShadowPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  vtkInternals& internals = *this->Internals;
  this->NumberOfRenderedProps = 0;
  this->NumberOfShadowingLights = 0;
  this->NumberOfShadowVolumeTriangles = 0;
  this->NumberOfZFailVolumes = 0;
  this->NumberOfPenumbraWedges = 0;
  this->NumberOfFullViewportWedges = 0;
  this->NumberOfCulledShadows = 0;
  this->NumberOfPlateauTriangles = 0;
  this->NumberOfCountedLights = 0;
  this->NumberOfAveragedLights = 0;

  using Stage = penumbra::StageTimes::Stage;
  internals.StageTimes.BeginFrame(this->CollectStageTimes);
  auto renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  auto window =
    renderer ? vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()) : nullptr;
  internals.Lights.clear();
  internals.ApplyShadows = false;
  if (this->ShadowsEnabled && window)
  {
    internals.Window = window;
    renderer->GetTiledSizeAndOrigin(
      &internals.Size[0], &internals.Size[1], &internals.Origin[0], &internals.Origin[1]);
    // Lights follow the camera only once VTK's lights pass has run: run it now, it is idempotent.
    internals.LightsPass->Render(s);
    this->CollectShadowingLights(renderer);
  }
  this->UpdateShaderConfiguration();

  if (internals.Lights.empty() || internals.Size[0] <= 0 || internals.Size[1] <= 0)
  {
    internals.Lights.clear();
    {
      penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Compositing);
      this->RenderDelegate(s);
    }
    internals.StageTimes.EndFrame();
    return;
  }

  this->AddReceiverKeys(s);
  internals.UpdateCamera(renderer);
  this->PrepareFramebuffer(window);
  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Depth);
    internals.LightIntensity->Activate();
    this->RenderDepth(s);
    internals.LightIntensity->Deactivate();
  }
  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Casters);
    this->UpdateCasters(s);
  }
  // After UpdateCasters: Automatic may have traded a light's wedges for averaged shadows, and
  // plateaus without a receiver plane fall back to hard shadows.
  if (std::any_of(internals.Lights.begin(), internals.Lights.end(),
        [](const vtkInternals::ShadowLight& light)
        { return !light.Is(vtkInternals::Technique::HardSamples); }))
  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Depth);
    internals.CopyDepth(window->GetState());
  }
  this->RenderLightIntensity(renderer, window);
  internals.LightIntensity->Activate();
  internals.ApplyShadows = true;
  this->NumberOfShadowingLights = static_cast<int>(internals.Lights.size());

  {
    penumbra::StageTimes::Scope timed(internals.StageTimes, Stage::Compositing);
    this->RenderDelegate(s);
  }
  internals.StageTimes.EndFrame();

  internals.ApplyShadows = false;
  internals.LightIntensity->Deactivate();
  this->RemoveReceiverKeys();
  internals.Caches.PurgeUnused();
  this->GraphicsMemoryBytes = static_cast<vtkIdType>(internals.GraphicsMemoryBytes());
  vtkOpenGLCheckErrorMacro("failed after Render");
}

void vtkSoftShadowPass::RenderDelegate(const vtkRenderState* s)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->Render(s);
    this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  }
  else
  {
    vtkWarningMacro("No delegate pass: nothing is rendered.");
  }
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::CollectShadowingLights(vtkRenderer* renderer)
{
  vtkInternals& internals = *this->Internals;
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
        if (internals.WarnedLights.insert(light).second)
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
      if (internals.WarnedLights.insert(light).second)
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
    internals.ChooseMethod(this, renderer, shadowLight);
    internals.Lights.push_back(shadowLight);
  }
}

void vtkSoftShadowPass::vtkInternals::ChooseMethod(
  vtkSoftShadowPass* self, vtkRenderer* renderer, ShadowLight& shadowLight)
{
  vtkLight* light = shadowLight.Light;
  const glm::dvec4& world = shadowLight.World;
  double radius = GetLightRadius(light);
  shadowLight.Samples = { world };
  shadowLight.Method = Technique::HardSamples;
  shadowLight.CountingChosenAutomatically = false;
  shadowLight.SoftRadius = 0.0;
  shadowLight.CountingSamples.clear();
  if (self->Method == METHOD_HARD_VOLUMES || radius <= 0.0)
  {
    return;
  }
  if (world.w == 0.0 && radius >= 90.0)
  {
    if (this->WarnedLights.insert(light).second)
    {
      vtkWarningWithObjectMacro(self,
        "Directional light " << light << " has an angular radius of " << radius
                             << " degrees; clamped to 89.");
    }
    radius = 89.0;
  }
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const glm::dvec3 target = vtkMath::AreBoundsInitialized(bounds)
    ? glm::dvec3(bounds[0] + bounds[1], bounds[2] + bounds[3], bounds[4] + bounds[5]) * 0.5
    : glm::dvec3(light->GetTransformedFocalPoint()[0], light->GetTransformedFocalPoint()[1],
        light->GetTransformedFocalPoint()[2]);
  shadowLight.SampleTarget = target;
  shadowLight.SampleRadius = radius;
  shadowLight.SoftRadius = world.w != 0.0 ? radius : glm::radians(radius);
  if (self->Method == METHOD_PLATEAUS)
  {
    shadowLight.Method = Technique::Plateaus;
    return;
  }
  if (self->Method == METHOD_PENUMBRA_WEDGES)
  {
    shadowLight.Method = Technique::PenumbraWedges;
    return;
  }
  if ((self->Method == METHOD_AUTOMATIC || self->Method == METHOD_SOFT_SHADOW_VOLUMES) &&
    this->CountingSupported(self))
  {
    constexpr int maximumSamples = 256; // the shader's uniform array
    if (self->LightSamples > maximumSamples && !this->WarnedCountingSamples)
    {
      vtkWarningWithObjectMacro(self,
        "Soft shadow volumes count at most " << maximumSamples << " light samples; LightSamples "
                                             << self->LightSamples << " is clamped for them.");
      this->WarnedCountingSamples = true;
    }
    shadowLight.Method = Technique::SampleCounting;
    shadowLight.CountingChosenAutomatically = self->Method == METHOD_AUTOMATIC;
    shadowLight.CountingSamples = penumbra::SpreadLightSamples(
      world, radius, std::min(self->LightSamples, maximumSamples), target);
    return;
  }
  shadowLight.Samples = penumbra::SpreadLightSamples(world, radius, self->LightSamples, target);
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
  internals.Receivers.clear();
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    // Any prop with opaque surfaces: an assembly hands its keys to its parts as VTK draws them,
    // composite and glyph mappers draw with their actor's. SetShaderParameters leaves
    // translucent fragments unshadowed: they lie over the LI buffer of what is behind them.
    vtkProp* prop = s->GetPropArray()[i];
    if (GetReceivesShadows(prop) && prop->HasOpaqueGeometry())
    {
      AddRenderPassKey(prop, this);
      internals.Receivers.push_back(prop);
    }
  }
}

void vtkSoftShadowPass::vtkInternals::UpdateReceiverBox()
{
  penumbra::Box current;
  for (vtkProp* prop : this->Receivers)
  {
    const double* bounds = prop->GetBounds();
    if (!bounds || !vtkMath::AreBoundsInitialized(bounds) ||
      !std::all_of(bounds, bounds + 6, [](double b) { return std::isfinite(b); }))
    {
      this->ReceiverBox = penumbra::Box(); // a receiver of unknown extent: nothing to cut to
      return;
    }
    current.Extend(
      glm::dvec3(bounds[0], bounds[2], bounds[4]), glm::dvec3(bounds[1], bounds[3], bounds[5]));
  }
  this->ReceiverBox = penumbra::StableReceiverBox(this->ReceiverBox, current);
}

void vtkSoftShadowPass::RemoveReceiverKeys()
{
  for (vtkProp* prop : this->Internals->Receivers)
  {
    prop->GetPropertyKeys()->Remove(vtkOpenGLRenderPass::RenderPasses(), this);
  }
  this->Internals->Receivers.clear();
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::PrepareFramebuffer(vtkOpenGLRenderWindow* window)
{
  vtkInternals& internals = *this->Internals;
  const int width = internals.Size[0], height = internals.Size[1];
  const int layers = static_cast<int>(internals.Lights.size());

  if (!internals.Framebuffer->GetFBOIndex())
  {
    internals.Framebuffer->SetContext(window);
    internals.DepthStencil->SetContext(window);
    internals.LightIntensity->SetContext(window);
    internals.DepthCopy->SetContext(window);
    internals.DepthCopyFramebuffer->SetContext(window);
    internals.CentreCount->SetContext(window);
    internals.SampleCounters->SetContext(window);
  }
  if (static_cast<int>(internals.DepthStencil->GetWidth()) != width ||
    static_cast<int>(internals.DepthStencil->GetHeight()) != height)
  {
    internals.DepthStencil->AllocateDepthStencil(width, height);
    internals.DepthCopy->AllocateDepthStencil(width, height);
  }
  if (static_cast<int>(internals.LightIntensity->GetWidth()) != width ||
    static_cast<int>(internals.LightIntensity->GetHeight()) != height || internals.Layers != layers)
  {
    internals.LightIntensity->SetMinificationFilter(vtkTextureObject::Nearest);
    internals.LightIntensity->SetMagnificationFilter(vtkTextureObject::Nearest);
    internals.LightIntensity->Allocate3D(width, height, layers, 1, VTK_FLOAT);
    internals.Layers = layers;
  }
  internals.VisibilityImages.clear();
}

void vtkSoftShadowPass::BindFramebuffer(int layer)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLFramebufferObject* fbo = internals.Framebuffer;
  fbo->Bind();
  // VTK 9.1 attaches depth without stencil and ignores a new slice of the same texture: attach
  // the depth-stencil texture ourselves and re-add the LI layer.
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
    internals.DepthStencil->GetHandle(), 0);
  internals.AttachColour(internals.LightIntensity, layer);
}

void vtkSoftShadowPass::vtkInternals::PrepareCountingBuffers(std::size_t samples)
{
  const int width = this->Size[0], height = this->Size[1];
  const unsigned int words = static_cast<unsigned int>((samples + 3) / 4);
  if (static_cast<int>(this->CentreCount->GetWidth()) == width &&
    static_cast<int>(this->CentreCount->GetHeight()) == height &&
    this->SampleCounters->GetDepth() == words)
  {
    return;
  }
  for (vtkTextureObject* texture : { this->CentreCount.Get(), this->SampleCounters.Get() })
  {
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  }
  this->CentreCount->Allocate2D(width, height, 1, VTK_FLOAT);
  this->SampleCounters->SetInternalFormat(GL_R32UI);
  this->SampleCounters->SetFormat(GL_RED_INTEGER);
  this->SampleCounters->SetDataType(GL_UNSIGNED_INT);
  this->SampleCounters->Allocate3D(width, height, words, 1, VTK_UNSIGNED_INT);
}

void vtkSoftShadowPass::vtkInternals::AttachColour(vtkTextureObject* texture, int layer)
{
  // VTK 9.1 ignores a new slice of the attached texture: remove, then add.
  this->Framebuffer->RemoveColorAttachment(0);
  this->Framebuffer->AddColorAttachment(0, texture, static_cast<unsigned int>(layer));
  this->Framebuffer->ActivateDrawBuffer(0);
}

void vtkSoftShadowPass::RenderDepth(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLState* ostate = internals.Window->GetState();
  ostate->PushFramebufferBindings();
  this->BindFramebuffer(0);
  // No colour output at all: the LI texture is bound for sampling while this pass draws.
  ostate->vtkglDrawBuffer(GL_NONE);

  vtkOpenGLState::ScopedglViewport viewport(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  ostate->vtkglViewport(0, 0, internals.Size[0], internals.Size[1]);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglStencilMask(0xFF);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  vtkRenderState depthState(s->GetRenderer());
  depthState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  depthState.SetFrameBuffer(internals.Framebuffer);
  internals.DepthPass->Render(&depthState);

  ostate->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::UpdateCasters(const vtkRenderState* s)
{
  vtkInternals& internals = *this->Internals;
  internals.Caches.BeginFrame();
  internals.Casters.clear();
  internals.UpdateReceiverBox();
  for (const penumbra::DrawnSurface& surface : internals.SceneWalk.Casters(s->GetRenderer(), this))
  {
    penumbra::MeshCache* mesh = internals.Caches.FindMesh(surface.Data, this);
    if (mesh->Topology.Empty())
    {
      continue;
    }
    penumbra::CasterCache* caster = internals.Caches.FindCaster(surface.Actor, surface.Part);
    caster->Mesh = mesh;
    caster->Culled.clear();
    const penumbra::CasterTopology& topo = mesh->Topology;
    caster->ObjectToWorld = surface.ObjectToWorld * glm::translate(glm::dmat4(1.0), topo.Origin);
    caster->WorldMin = glm::dvec3(std::numeric_limits<double>::max());
    caster->WorldMax = -caster->WorldMin;
    for (int corner = 0; corner < 8; ++corner)
    {
      const glm::dvec3 local((corner & 1) ? topo.BoundsMax.x : topo.BoundsMin.x,
        (corner & 2) ? topo.BoundsMax.y : topo.BoundsMin.y,
        (corner & 4) ? topo.BoundsMax.z : topo.BoundsMin.z);
      const glm::dvec3 world(caster->ObjectToWorld * glm::dvec4(local, 1.0));
      caster->WorldMin = glm::min(caster->WorldMin, world);
      caster->WorldMax = glm::max(caster->WorldMax, world);
    }
    internals.Casters.push_back(caster);
  }

  const bool plateaus = std::any_of(internals.Lights.begin(), internals.Lights.end(),
    [](const vtkInternals::ShadowLight& light)
    { return light.Is(vtkInternals::Technique::Plateaus); });
  if (plateaus && !this->FindReceiverPlane(s->GetRenderer()))
  {
    if (!internals.Plateau.WarnedNoPlane)
    {
      vtkWarningMacro("METHOD_PLATEAUS needs a receiver plane (SetShadowPlane on a flat actor, "
                      "or UseReceiverPlaneOn): hard shadows instead.");
      internals.Plateau.WarnedNoPlane = true;
    }
    for (auto& light : internals.Lights)
    {
      light.Method = vtkInternals::Technique::HardSamples;
    }
  }

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
    this->NumberOfSilhouetteUpdates += internals.UpdateLightCasters(light);
    if (light.Is(vtkInternals::Technique::SampleCounting) && light.CountingChosenAutomatically &&
      !penumbra::CountingIsCheaper(internals.CountingCosts(light), light.CountingSamples.size()))
    {
      // Averaging the same samples gives the same image and is expected to be cheaper here.
      light.Method = vtkInternals::Technique::HardSamples;
      light.Samples = penumbra::SpreadLightSamples(
        light.World, light.SampleRadius, this->LightSamples, light.SampleTarget);
      this->NumberOfSilhouetteUpdates += internals.UpdateLightCasters(light);
    }
    for (penumbra::CasterCache* caster : internals.Casters)
    {
      if (light.Is(vtkInternals::Technique::SampleCounting) && !caster->Culled.count(light.Light))
      {
        caster->CountingWedges[light.Light].BuildVertices(*caster->Mesh);
      }
    }
  }
}

vtkIdType vtkSoftShadowPass::vtkInternals::UpdateLightCasters(const ShadowLight& light)
{
  vtkIdType updates = 0;
  for (penumbra::CasterCache* caster : this->Casters)
  {
    if (caster->Culled.count(light.Light))
    {
      continue;
    }
    const glm::dmat4 worldToObject = glm::inverse(caster->ObjectToWorld);
    const bool mirrored = glm::determinant(caster->ObjectToWorld) < 0.0;
    for (std::size_t k = 0; k < light.Samples.size(); ++k)
    {
      penumbra::VolumeCache& volume = caster->Volumes[light.VolumeKey(k)];
      updates += volume.Update(*caster->Mesh, worldToObject * light.Samples[k], mirrored) ? 1 : 0;
    }
    if (light.Is(Technique::PenumbraWedges))
    {
      caster->Wedges[light.Light].Update(*caster->Mesh, caster->Volumes[light.VolumeKey(0)],
        caster->ObjectToWorld, light.World, light.SoftRadius, this->ReceiverBox);
    }
    if (light.Is(Technique::SampleCounting))
    {
      const bool frontFacesOnly = penumbra::ShadowVolume::FrontFacesSuffice(
        caster->Mesh->Topology, worldToObject * light.World);
      updates += caster->CountingWedges[light.Light].Update(*caster->Mesh, caster->ObjectToWorld,
                   light.World, light.SoftRadius, frontFacesOnly, this->ReceiverBox)
        ? 1
        : 0;
    }
  }
  return updates;
}

std::vector<penumbra::CountingCost> vtkSoftShadowPass::vtkInternals::CountingCosts(
  const ShadowLight& light)
{
  std::vector<penumbra::CountingCost> costs;
  for (penumbra::CasterCache* caster : this->Casters)
  {
    if (caster->Culled.count(light.Light))
    {
      continue;
    }
    penumbra::CountingCost cost;
    cost.PotentialEdges = caster->CountingWedges[light.Light].Potential.size();
    for (const penumbra::SilhouetteEdge& edge :
      caster->Volumes[light.VolumeKey(0)].Volume.Silhouette)
    {
      cost.SilhouetteEdges += edge.Multiplicity;
    }
    if (light.World.w != 0.0)
    {
      const double distance =
        glm::length(0.5 * (caster->WorldMin + caster->WorldMax) - glm::dvec3(light.World));
      cost.AngularRadius = distance > light.SoftRadius ? light.SoftRadius / distance : 1e300;
    }
    else
    {
      cost.AngularRadius = light.SoftRadius;
    }
    costs.push_back(cost);
  }
  return costs;
}

bool vtkSoftShadowPass::vtkInternals::CountingSupported(vtkSoftShadowPass* self)
{
  if (this->CountingSupport < 0)
  {
    this->CountingSupport =
      GLEW_VERSION_4_4 || (GLEW_ARB_shader_image_load_store && GLEW_ARB_clear_texture);
    if (!this->CountingSupport)
    {
      vtkWarningWithObjectMacro(self,
        "This OpenGL context has no image atomics or texture "
        "clears (OpenGL 4.4): soft shadows average "
        "LightSamples hard shadows instead of counting them.");
    }
  }
  return this->CountingSupport != 0;
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::RenderLightIntensity(vtkRenderer* renderer, vtkOpenGLRenderWindow* window)
{
  vtkInternals& internals = *this->Internals;
  vtkOpenGLState* ostate = window->GetState();

  vtkShaderProgram* volumeProgram = internals.ReadyProgram(
    window, penumbraShadowVolumeVS, penumbraShadowVolumeFS, "shadow-volume", "no shadow is drawn");
  if (!volumeProgram)
  {
    return;
  }

  ostate->PushFramebufferBindings();
  vtkOpenGLState::ScopedglViewport viewport(ostate);
  vtkOpenGLState::ScopedglEnableDisable scissor(ostate, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable depthTest(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable stencilTest(ostate, GL_STENCIL_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable cull(ostate, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable depthClamp(ostate, GL_DEPTH_CLAMP);
  vtkOpenGLState::ScopedglDepthMask depthMask(ostate);
  vtkOpenGLState::ScopedglColorMask colorMask(ostate);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(ostate);
  vtkOpenGLState::ScopedglClearColor clearColor(ostate);
  ostate->vtkglViewport(0, 0, internals.Size[0], internals.Size[1]);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglClearColor(1.0f, 1.0f, 1.0f, 1.0f);

  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(ostate);
  ostate->vtkglBlendFunc(GL_ONE, GL_ONE);
  for (const auto& light : internals.Lights)
  {
    // The layer starts fully lit. Hard and averaged shadows: each light sample whose volume
    // covers a pixel (stencil non-zero) takes 1/N away. Wedges: the centre's volume count itself
    // is subtracted (see penumbraShadowVolumeFS.glsl). Float target, additive, no clamping.
    this->BindFramebuffer(light.Layer);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    // Wedges and soft shadow volumes count the centre's volumes in colour (additive float).
    const bool countInColour = light.CountsCentreInColour();
    if (light.Is(vtkInternals::Technique::SampleCounting))
    {
      // The centre's count goes to a texture of its own, for the resolve to read.
      internals.PrepareCountingBuffers(light.CountingSamples.size());
      internals.AttachColour(internals.CentreCount, 0);
      ostate->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
      ostate->vtkglClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    }
    const float sampleWeight = 1.0f / static_cast<float>(light.Samples.size());
    internals.StageTimes.Begin(penumbra::StageTimes::Volumes);
    for (std::size_t k = 0; k < light.Samples.size(); ++k)
    {
      ostate->vtkglStencilMask(0xFF);
      ostate->vtkglClear(GL_STENCIL_BUFFER_BIT);
      if (countInColour)
      {
        ostate->vtkglEnable(GL_BLEND);
        ostate->vtkglDisable(GL_STENCIL_TEST);
      }
      else
      {
        ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        ostate->vtkglDisable(GL_BLEND);
        ostate->vtkglEnable(GL_STENCIL_TEST);
        ostate->vtkglStencilFunc(GL_ALWAYS, 0, 0xFF);
      }
      window->GetShaderCache()->ReadyShaderProgram(volumeProgram);
      for (penumbra::CasterCache* caster : internals.Casters)
      {
        if (caster->Culled.count(light.Light))
        {
          continue;
        }
        this->NumberOfShadowVolumeTriangles += DrawShadowVolume(ostate, volumeProgram, *caster,
          light.VolumeKey(k), light.Samples[k], internals.WorldToClip, internals.NearCorners,
          countInColour, this->NumberOfZFailVolumes);
      }

      ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      ostate->vtkglEnable(GL_DEPTH_CLAMP); // the full-screen triangle lies on the far plane
      if (light.Is(vtkInternals::Technique::PenumbraWedges))
      {
        // Volumes also counted over the background: put it back to fully lit.
        ostate->vtkglDisable(GL_BLEND);
        ostate->vtkglDepthFunc(GL_LEQUAL);
        this->DrawResolve(window, 1.0f);
      }
      else if (!light.Is(vtkInternals::Technique::SampleCounting))
      {
        // Resolve: every geometry pixel with a non-zero count is in this sample's shadow.
        ostate->vtkglEnable(GL_BLEND);
        ostate->vtkglStencilFunc(GL_NOTEQUAL, 0, 0xFF);
        ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        ostate->vtkglDepthFunc(GL_GREATER);
        this->DrawResolve(window, -sampleWeight);
      }
      ostate->vtkglDisable(GL_DEPTH_CLAMP);
    }
    internals.StageTimes.End(penumbra::StageTimes::Volumes);
    penumbra::StageTimes::Scope timedWedges(internals.StageTimes, penumbra::StageTimes::Wedges);
    if (light.Is(vtkInternals::Technique::PenumbraWedges))
    {
      internals.DrawWedges(
        window, light, this->NumberOfPenumbraWedges, this->NumberOfFullViewportWedges);
    }
    if (light.Is(vtkInternals::Technique::Plateaus))
    {
      this->NumberOfPlateauTriangles += internals.DrawPlateaus(this, window, light);
    }
    if (light.Is(vtkInternals::Technique::SampleCounting))
    {
      internals.DrawSampleCounting(
        this, window, light, this->NumberOfPenumbraWedges, this->NumberOfFullViewportWedges);
      ++this->NumberOfCountedLights;
    }
    this->NumberOfAveragedLights += light.Samples.size() > 1 ? 1 : 0;
  }
  ostate->vtkglStencilFunc(GL_ALWAYS, 0, 0xFF);
  ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  ostate->PopFramebufferBindings();
}

namespace
{
/// NDC depth by which light caps are pushed back: well above float rounding of the two
/// vertex transforms (VTK's mapper and ours), which differ by about 1e-6 relative.
constexpr float CapDepthBias = 5e-5f;
/// NDC depth by which soft shadow volumes move a pixel's point towards the eye, so that it lies
/// on the side of its own surface that it is seen from: four steps of a 24-bit depth buffer.
/// Much more moves it measurably off the surface where the depth range is wide (a near plane at
/// 1/1000 of the far one makes 5e-5 a tenth of the scene's unit).
constexpr float CountingEyeDepthBias = 8.0f / 16777216.0f;

/// Draws one caster's volume for one light into the stencil; returns the triangles drawn.
vtkIdType DrawShadowVolume(vtkOpenGLState* ostate, vtkShaderProgram* program,
  penumbra::CasterCache& caster, const std::pair<vtkLight*, int>& key, const glm::dvec4& lightWorld,
  const glm::dmat4& worldToClip, const std::array<glm::dvec3, 4>& nearCorners, bool countInColor,
  vtkIdType& zFailCount)
{
  penumbra::VolumeCache& volume = caster.Volumes[key];
  if (volume.Volume.CastingTriangles == 0)
  {
    return 0;
  }
  const bool zFail =
    penumbra::VolumeMayReachNearPlane(caster.WorldMin, caster.WorldMax, lightWorld, nearCorners);
  if (zFail)
  {
    volume.EnsureCaps(*caster.Mesh);
  }
  const std::size_t sides = volume.SideCount(), darkCap = volume.DarkCapCount(),
                    lightCap = volume.CapCount();
  const glm::mat4 objectToClip(worldToClip * caster.ObjectToWorld);
  const glm::vec4 lightObject(volume.Light);
  program->SetUniformMatrix4x4("MCDCMatrix", const_cast<float*>(glm::value_ptr(objectToClip)));
  program->SetUniform4f("lightMC", glm::value_ptr(lightObject));
  caster.Mesh->Bind(program);
  volume.Upload();
  volume.Indices->Bind();

  vtkIdType drawn = 0;
  if (!zFail)
  {
    // z-pass: count volume faces in front of the visible surface; caps are not needed.
    ostate->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    ostate->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    ostate->vtkglDepthFunc(GL_LESS);
    program->SetUniformf("frontFaceValue", -1.0f); // entering a volume takes the light away
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(sides), GL_UNSIGNED_INT, nullptr);
    drawn = static_cast<vtkIdType>(sides / 3);
  }
  else
  {
    // z-fail: count faces behind it, caps included; depth clamping keeps the far end at
    // infinity from being clipped. Counting in colour, "behind" is a depth test that passes.
    ostate->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    ostate->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    ostate->vtkglDepthFunc(countInColor ? GL_GEQUAL : GL_LESS);
    program->SetUniformf("frontFaceValue", 1.0f); // leaving it behind the point does
    ostate->vtkglEnable(GL_DEPTH_CLAMP);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(sides + darkCap), GL_UNSIGNED_INT, nullptr);
    // The light cap lies on the caster's own surface: pushed away from the eye, a visible point
    // on it counts as outside its own triangle's volume, i.e. lit from the side it is seen from.
    // The cap only covers pixels where its opaque caster is the nearest surface, so a generous
    // push cannot move it behind any other visible point.
    program->SetUniformf("capDepthBias", CapDepthBias);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(lightCap), GL_UNSIGNED_INT,
      reinterpret_cast<const void*>((sides + darkCap) * sizeof(std::uint32_t)));
    program->SetUniformf("capDepthBias", 0.0f);
    ostate->vtkglDisable(GL_DEPTH_CLAMP);
    drawn = static_cast<vtkIdType>((sides + darkCap + lightCap) / 3);
    ++zFailCount;
  }
  volume.Indices->Release();
  caster.Mesh->VAO->Release();
  return drawn;
}
} // namespace

vtkShaderProgram* vtkSoftShadowPass::vtkInternals::ReadyProgram(vtkOpenGLRenderWindow* window,
  const char* vertexShader, const char* fragmentShader, const char* name, const char* instead)
{
  // The pass's fragment shaders share one reconstruction of a pixel's point from depth.
  std::string fragment = fragmentShader;
  vtkShaderProgram::Substitute(fragment, "//PENUMBRA::DepthPoint::Dec", penumbraDepthPointDec);
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vertexShader, fragment.c_str(), "");
  if (!program && this->FailedPrograms.insert(name).second)
  {
    vtkErrorWithObjectMacro(
      this->Owner, "Could not compile the " << name << " shader: " << instead << ".");
  }
  return program;
}

void vtkSoftShadowPass::vtkInternals::CopyDepth(vtkOpenGLState* ostate)
{
  ostate->PushFramebufferBindings();
  this->Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  this->DepthCopyFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
    this->DepthCopy->GetHandle(), 0);
  ostate->vtkglBlitFramebuffer(0, 0, this->Size[0], this->Size[1], 0, 0, this->Size[0],
    this->Size[1], GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  ostate->PopFramebufferBindings();
}

void vtkSoftShadowPass::vtkInternals::DrawWedgeBuffer(vtkShaderProgram* program,
  const penumbra::CasterCache& caster, penumbra::WedgeBuffer& buffer,
  const std::vector<penumbra::VertexAttribute>& attributes, const ShadowLight& light,
  const glm::dmat4& clipToWorld, vtkIdType& wedges, vtkIdType& fullViewport)
{
  if (buffer.IndexCount() == 0)
  {
    return;
  }
  vtkOpenGLState* ostate = this->Window->GetState();
  // A point inside a wedge lies behind its front faces and in front of its back faces. When
  // neither the eye nor the near plane can be inside this caster's wedges (its bounds grown by
  // the light's radius miss the near plane's hull with the light, as for z-pass), front faces
  // tested against the scene depth skip every point in front of the wedge. Otherwise back
  // faces, which every ray meeting the wedge crosses once, skip points behind it.
  const glm::dvec3 grow(light.World.w != 0.0 ? light.SoftRadius : 0.0);
  const bool frontFaces = light.World.w != 0.0 && buffer.Fallbacks == 0 &&
    !penumbra::VolumeMayReachNearPlane(
      caster.WorldMin - grow, caster.WorldMax + grow, light.World, this->NearCorners);
  ostate->vtkglCullFace(frontFaces ? GL_BACK : GL_FRONT);
  ostate->vtkglDepthFunc(frontFaces ? GL_LEQUAL : GL_GEQUAL);
  const glm::mat4 toClip(this->WorldToClip * glm::translate(glm::dmat4(1.0), buffer.Origin));
  const glm::mat4 fromClip(glm::translate(glm::dmat4(1.0), -buffer.Origin) * clipToWorld);
  const glm::vec4 lightWedge(buffer.LightInWedgeSpace());
  program->SetUniformMatrix4x4("MCDCMatrix", const_cast<float*>(glm::value_ptr(toClip)));
  program->SetUniformMatrix4x4("clipToWedge", const_cast<float*>(glm::value_ptr(fromClip)));
  program->SetUniform4f("lightWedge", glm::value_ptr(lightWedge));
  buffer.Bind(program, attributes);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(buffer.IndexCount()), GL_UNSIGNED_INT, nullptr);
  buffer.IndexBuffer->Release();
  buffer.VAO->Release();
  wedges += static_cast<vtkIdType>(buffer.Wedges + buffer.Fallbacks);
  fullViewport += static_cast<vtkIdType>(buffer.FullViewport);
}

void vtkSoftShadowPass::vtkInternals::DrawWedges(vtkOpenGLRenderWindow* window,
  const ShadowLight& light, vtkIdType& wedges, vtkIdType& fullViewport)
{
  vtkShaderProgram* program = this->ReadyProgram(
    window, penumbraWedgeVS, penumbraWedgeFS, "penumbra wedge", "penumbra wedges are left out");
  if (!program)
  {
    return;
  }
  vtkOpenGLState* ostate = window->GetState();
  this->DepthCopy->Activate();
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_CULL_FACE);
  ostate->vtkglEnable(GL_DEPTH_CLAMP);

  program->SetUniformi("depthTexture", this->DepthCopy->GetTextureUnit());
  const float viewport[2] = { static_cast<float>(this->Size[0]),
    static_cast<float>(this->Size[1]) };
  program->SetUniform2f("viewportSize", viewport);
  program->SetUniformf("lightRadius", static_cast<float>(light.SoftRadius));
  const glm::dmat4 clipToWorld = glm::inverse(this->WorldToClip);
  for (penumbra::CasterCache* caster : this->Casters)
  {
    if (caster->Culled.count(light.Light))
    {
      continue;
    }
    this->DrawWedgeBuffer(program, *caster, caster->Wedges[light.Light],
      penumbra::WedgeCache::Attributes(), light, clipToWorld, wedges, fullViewport);
  }
  ostate->vtkglCullFace(GL_BACK);
  ostate->vtkglDisable(GL_CULL_FACE);

  // Cap by the part of the light above each visible point's own plane (GL_MIN).
  vtkShaderProgram* horizon = this->ReadyProgram(window, penumbraResolveVS, penumbraHorizonFS,
    "horizon cap", "the wedges' horizon cap is left out");
  if (horizon)
  {
    const glm::dvec3 origin = light.World.w != 0.0 ? glm::dvec3(light.World) : glm::dvec3(0.0);
    const glm::mat4 fromClip(glm::translate(glm::dmat4(1.0), -origin) * clipToWorld);
    const glm::vec4 lightWedge(light.World.w != 0.0 ? glm::dvec4(0, 0, 0, 1) : light.World);
    horizon->SetUniformi("depthTexture", this->DepthCopy->GetTextureUnit());
    horizon->SetUniform2f("viewportSize", viewport);
    horizon->SetUniformf("lightRadius", static_cast<float>(light.SoftRadius));
    horizon->SetUniformMatrix4x4("clipToWedge", const_cast<float*>(glm::value_ptr(fromClip)));
    horizon->SetUniform4f("lightWedge", glm::value_ptr(lightWedge));
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglBlendEquation(GL_MIN);
    this->DrawFullScreen(horizon, this->HorizonVAO);
    ostate->vtkglBlendEquation(GL_FUNC_ADD);
    ostate->vtkglEnable(GL_DEPTH_TEST);
  }
  ostate->vtkglDisable(GL_DEPTH_CLAMP);
  this->DepthCopy->Deactivate();
}

namespace
{
/// A shader source with its sample count compiled in (the loops' bounds and the samples' array).
std::string WithSampleCount(const char* source, std::size_t samples)
{
  std::string text = source;
  vtkShaderProgram::Substitute(text, "//PENUMBRA::SampleCount",
    "#define PENUMBRA_SAMPLE_COUNT " + std::to_string(samples) + "\n", false);
  return text;
}
} // namespace

bool vtkSoftShadowPass::vtkInternals::DrawSampleCounting(vtkSoftShadowPass* self,
  vtkOpenGLRenderWindow* window, const ShadowLight& light, vtkIdType& wedges,
  vtkIdType& fullViewport)
{
  const std::size_t sampleCount = light.CountingSamples.size();
  const std::string wedgeFS = WithSampleCount(penumbraCountingWedgeFS, sampleCount);
  const std::string resolveFS = WithSampleCount(penumbraCountingResolveFS, sampleCount);
  // From the next frame on such lights average the same samples.
  vtkShaderProgram* program = this->ReadyProgram(window, penumbraCountingWedgeVS, wedgeFS.c_str(),
    "soft shadow volume wedge", "soft shadows average hard shadows instead");
  if (!program)
  {
    this->CountingSupport = 0;
    return false;
  }
  vtkOpenGLState* ostate = window->GetState();
  const GLuint zero = 0;
  glClearTexImage(this->SampleCounters->GetHandle(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);

  // Wedge fragments that pass the depth test mark their pixel in the stencil, so that the
  // resolve reads counters only there; counts go to the image, not to colour.
  ostate->vtkglStencilMask(0xFF);
  ostate->vtkglClear(GL_STENCIL_BUFFER_BIT);
  ostate->vtkglEnable(GL_STENCIL_TEST);
  ostate->vtkglStencilFunc(GL_ALWAYS, 1, 0xFF);
  ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglEnable(GL_CULL_FACE);
  ostate->vtkglEnable(GL_DEPTH_CLAMP);
  glBindImageTexture(0, this->SampleCounters->GetHandle(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  this->DepthCopy->Activate();

  const glm::dmat4 clipToWorld = glm::inverse(this->WorldToClip);
  const float viewport[2] = { static_cast<float>(this->Size[0]),
    static_cast<float>(this->Size[1]) };
  program->SetUniformi("depthTexture", this->DepthCopy->GetTextureUnit());
  program->SetUniformi("counters", 0);
  program->SetUniform2f("viewportSize", viewport);
  program->SetUniformf("eyeDepthBias", CountingEyeDepthBias);
  // Samples in wedge coordinates: relative to the light's centre, which is every caster's wedge
  // origin for a positional light, or directions, which no origin moves.
  std::vector<float> samples;
  samples.reserve(4 * sampleCount);
  for (const glm::dvec4& sample : light.CountingSamples)
  {
    const glm::dvec3 position = glm::dvec3(sample) - sample.w * glm::dvec3(light.World);
    samples.insert(samples.end(),
      { static_cast<float>(position.x), static_cast<float>(position.y),
        static_cast<float>(position.z), static_cast<float>(sample.w) });
  }
  program->SetUniform4fv("lightSamples", static_cast<int>(sampleCount), samples.data());
  for (penumbra::CasterCache* caster : this->Casters)
  {
    if (caster->Culled.count(light.Light))
    {
      continue;
    }
    penumbra::CountingWedgeCache& cache = caster->CountingWedges[light.Light];
    program->SetUniformi("frontFacesOnly", cache.FrontFacesOnly ? 1 : 0);
    this->DrawWedgeBuffer(program, *caster, cache, penumbra::CountingWedgeCache::Attributes(),
      light, clipToWorld, wedges, fullViewport);
  }
  ostate->vtkglCullFace(GL_BACK);
  ostate->vtkglDisable(GL_CULL_FACE);
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  this->DepthCopy->Deactivate();

  // Resolve into the light's layer at every geometry pixel (the far-plane triangle passes
  // GL_GREATER exactly there): counters where a wedge reached, the centre's count elsewhere.
  vtkShaderProgram* resolve = this->ReadyProgram(window, penumbraResolveVS, resolveFS.c_str(),
    "soft shadow volume resolve", "soft shadows average hard shadows instead");
  if (!resolve)
  {
    this->CountingSupport = 0;
    return false;
  }
  this->AttachColour(this->LightIntensity, light.Layer);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDepthFunc(GL_GREATER);
  ostate->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  this->CentreCount->Activate();
  this->SampleCounters->Activate();
  resolve->SetUniformi("centreCount", this->CentreCount->GetTextureUnit());
  resolve->SetUniformi("counters", this->SampleCounters->GetTextureUnit());
  for (int reached : { 1, 0 })
  {
    ostate->vtkglStencilFunc(GL_EQUAL, reached, 0xFF);
    resolve->SetUniformi("useCounters", reached);
    this->DrawFullScreen(resolve, this->CountingResolveVAO);
  }
  this->SampleCounters->Deactivate();
  this->CentreCount->Deactivate();
  ostate->vtkglDisable(GL_DEPTH_CLAMP);
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglEnable(GL_BLEND);
  return true;
}

void vtkSoftShadowPass::DrawResolve(vtkOpenGLRenderWindow* window, float lightIntensity)
{
  vtkShaderProgram* program = this->Internals->ReadyProgram(window, penumbraResolveVS,
    penumbraResolveFS, "LI resolve", "shadows are not written into the LI buffer");
  if (!program)
  {
    return;
  }
  program->SetUniformf("lightIntensity", lightIntensity);
  this->Internals->DrawFullScreen(program, this->Internals->ResolveVAO);
}

void vtkSoftShadowPass::vtkInternals::DrawFullScreen(vtkShaderProgram* program, FullScreenVAO& vao)
{
  if (this->FullScreenTriangle->GetHandle() == 0)
  {
    const std::vector<float> triangle = { -1.f, -1.f, 3.f, -1.f, -1.f, 3.f };
    this->FullScreenTriangle->Upload(triangle, vtkOpenGLBufferObject::ArrayBuffer);
    for (FullScreenVAO* vao : this->FullScreenVAOs())
    {
      vao->Program = nullptr;
    }
  }
  penumbra::BindVertexArray(
    vao.VAO, program, vao.Program, this->FullScreenTriangle, { { "ndCoordIn", 0, 2 } });
  glDrawArrays(GL_TRIANGLES, 0, 3);
  vao.VAO->Release();
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::FindReceiverPlane(vtkRenderer* renderer)
{
  vtkInternals::PlateauState& plateau = this->Internals->Plateau;
  plateau.HavePlane = plateau.Bounded = false;
  plateau.PlaneProp = nullptr;
  if (this->UseReceiverPlane)
  {
    plateau.HavePlane = penumbra::ReceiverPlane::Make(glm::make_vec3(this->ReceiverPlaneOrigin),
      glm::make_vec3(this->ReceiverPlaneNormal), plateau.Plane);
    if (!plateau.HavePlane && !plateau.WarnedNoPlane)
    {
      vtkWarningMacro("The receiver plane's normal is zero or not finite.");
    }
    plateau.Tolerance = 0.0; // set from the plateaus' extent when they are drawn
    return plateau.HavePlane;
  }
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  vtkProp* prop;
  for (props->InitTraversal(it); (prop = props->GetNextProp(it));)
  {
    auto actor = vtkActor::SafeDownCast(prop);
    if (!actor || !actor->GetVisibility() || !GetShadowPlane(actor) || !actor->GetMapper())
    {
      continue;
    }
    auto data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
    // The actor (matrix), its mapper (a new input) or the data itself.
    const vtkMTimeType changed =
      std::max({ actor->GetMTime(), actor->GetMapper()->GetMTime(), data ? data->GetMTime() : 0 });
    if (actor == plateau.FittedProp && changed <= plateau.FittedAt)
    {
      plateau.HavePlane = plateau.Bounded = true; // the fit below, kept from an earlier frame
      plateau.PlaneProp = actor;
      return true;
    }
    vtkPoints* points = data ? data->GetPoints() : nullptr;
    std::vector<glm::dvec3> world;
    const glm::dmat4 toWorld = penumbra::ToGlm(actor->GetMatrix());
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
    {
      world.emplace_back(toWorld * glm::dvec4(glm::make_vec3(points->GetPoint(i)), 1.0));
    }
    penumbra::PlaneFit fit;
    if (!penumbra::FitReceiverPlane(world, fit))
    {
      if (plateau.WarnedProps.insert(actor).second)
      {
        vtkWarningMacro("Shadow plane " << actor << " has no flat surface: it is not used.");
      }
      continue;
    }
    if (fit.Thickness > 1e-6 * fit.Extent && plateau.WarnedProps.insert(actor).second)
    {
      vtkWarningMacro("Shadow plane " << actor << " is not flat (points up to " << fit.Thickness
                                      << " off its plane): plateaus use its best plane.");
    }
    plateau.HavePlane = plateau.Bounded = true;
    plateau.Plane = fit.Plane;
    plateau.PlaneProp = plateau.FittedProp = actor;
    plateau.FittedAt = changed;
    plateau.Min = fit.Min;
    plateau.Max = fit.Max;
    plateau.Tolerance = std::max(1e-5 * fit.Extent, 2.0 * fit.Thickness);
    return true;
  }
  return false;
}

bool vtkSoftShadowPass::vtkInternals::RenderPlateauTexture(vtkSoftShadowPass* self,
  vtkOpenGLRenderWindow* window, const glm::dvec2& lo, const glm::dvec2& size)
{
  PlateauState& plateau = this->Plateau;
  vtkShaderProgram* program = this->ReadyProgram(
    window, penumbraPlateauVS, penumbraPlateauFS, "plateau", "plateaus are left out");
  if (!program)
  {
    return false;
  }
  const int resolution = self->GetPlateauResolution();
  vtkOpenGLState* ostate = window->GetState();
  // The plateau texture: seen down the normal, the smallest depth (darkest) wins.
  ostate->PushFramebufferBindings();
  plateau.Framebuffer->Bind();
  plateau.Framebuffer->AddDepthAttachment(plateau.Depth);
  ostate->vtkglDrawBuffer(GL_NONE);
  ostate->vtkglViewport(0, 0, resolution, resolution);
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglDisable(GL_DEPTH_CLAMP);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_LESS);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglClear(GL_DEPTH_BUFFER_BIT);
  const float planeToClip[4] = { static_cast<float>(2.0 / size.x), static_cast<float>(2.0 / size.y),
    static_cast<float>(-1.0 - 2.0 * lo.x / size.x),
    static_cast<float>(-1.0 - 2.0 * lo.y / size.y) };
  program->SetUniform4f("planeToClip", planeToClip);
  plateau.Vertices->Upload(plateau.Triangles, vtkOpenGLBufferObject::ArrayBuffer);
  static_assert(sizeof(penumbra::PlateauVertex) == 3 * sizeof(float), "packed plateau vertices");
  penumbra::BindVertexArray(
    plateau.VAO, program, plateau.VAOProgram, plateau.Vertices, { { "plateauVertex", 0, 3 } });
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(plateau.Triangles.size()));
  plateau.VAO->Release();
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->PopFramebufferBindings();

  plateau.TextureCurrent = true;
  return true;
}

vtkIdType vtkSoftShadowPass::vtkInternals::DrawPlateaus(
  vtkSoftShadowPass* self, vtkOpenGLRenderWindow* window, const ShadowLight& light)
{
  PlateauState& plateau = this->Plateau;
  // The plane faces the light, whichever way its polygons wind.
  penumbra::ReceiverPlane plane = plateau.Plane;
  const double lightSide = light.World.w != 0.0 ? plane.Height(glm::dvec3(light.World))
                                                : glm::dot(plane.Normal, glm::dvec3(light.World));
  if (lightSide < 0.0)
  {
    penumbra::ReceiverPlane::Make(plane.Origin, -plane.Normal, plane);
  }
  const int resolution = self->GetPlateauResolution();
  std::vector<double> signature = { light.World.x, light.World.y, light.World.z, light.World.w,
    light.SoftRadius, plane.Origin.x, plane.Origin.y, plane.Origin.z, plane.Normal.x,
    plane.Normal.y, plane.Normal.z, static_cast<double>(resolution) };
  std::vector<penumbra::CasterCache*> casters;
  for (penumbra::CasterCache* caster : this->Casters)
  {
    if (caster->Culled.count(light.Light) || caster->Actor == plateau.PlaneProp)
    {
      continue;
    }
    casters.push_back(caster);
    signature.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(caster)));
    signature.push_back(static_cast<double>(caster->Volumes[light.VolumeKey(0)].Generation));
    const double* m = glm::value_ptr(caster->ObjectToWorld);
    signature.insert(signature.end(), m, m + 16);
  }
  if (signature != plateau.Signature)
  {
    plateau.Signature = signature;
    plateau.TextureCurrent = false;
    plateau.Triangles.clear();
    for (penumbra::CasterCache* caster : casters)
    {
      penumbra::VolumeCache& volume = caster->Volumes[light.VolumeKey(0)];
      volume.EnsureCaps(*caster->Mesh);
      penumbra::BuildPlateaus(caster->Mesh->Topology, volume.Volume, caster->ObjectToWorld,
        light.World, light.SoftRadius, plane, plateau.Triangles);
    }
    // The texture covers the plateaus, within the receiver's extent when it has one.
    plateau.Lo = glm::dvec2(std::numeric_limits<double>::max());
    plateau.Hi = -plateau.Lo;
    for (const penumbra::PlateauVertex& v : plateau.Triangles)
    {
      plateau.Lo = glm::min(plateau.Lo, glm::dvec2(v.U, v.V));
      plateau.Hi = glm::max(plateau.Hi, glm::dvec2(v.U, v.V));
    }
    if (plateau.Bounded)
    {
      plateau.Lo = glm::max(plateau.Lo, plateau.Min);
      plateau.Hi = glm::min(plateau.Hi, plateau.Max);
    }
  }
  const glm::dvec2 lo = plateau.Lo, size = plateau.Hi - plateau.Lo;
  if (plateau.Triangles.empty() || !(size.x > 0.0) || !(size.y > 0.0))
  {
    return 0;
  }
  const double tolerance = plateau.Bounded ? plateau.Tolerance : 1e-5 * glm::length(size);

  vtkOpenGLState* ostate = window->GetState();
  if (!plateau.Framebuffer->GetFBOIndex())
  {
    plateau.Framebuffer->SetContext(window);
    plateau.Depth->SetContext(window);
  }
  if (static_cast<int>(plateau.Depth->GetWidth()) != resolution)
  {
    // Filtered lookups smooth the texels' steps; the depth is t itself, not compared.
    plateau.Depth->SetMinificationFilter(vtkTextureObject::Linear);
    plateau.Depth->SetMagnificationFilter(vtkTextureObject::Linear);
    plateau.Depth->SetWrapS(vtkTextureObject::ClampToEdge);
    plateau.Depth->SetWrapT(vtkTextureObject::ClampToEdge);
    plateau.Depth->AllocateDepth(resolution, resolution, vtkTextureObject::Float32);
    plateau.TextureCurrent = false;
  }
  if (!plateau.TextureCurrent && !this->RenderPlateauTexture(self, window, lo, size))
  {
    return 0;
  }

  // Into the LI layer, at the pixels on the plane (the hard shadow stays elsewhere).
  vtkShaderProgram* resolve = this->ReadyProgram(window, penumbraResolveVS,
    penumbraPlateauResolveFS, "plateau resolve", "plateaus are left out");
  if (!resolve)
  {
    return 0;
  }
  ostate->vtkglViewport(0, 0, this->Size[0], this->Size[1]);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  this->DepthCopy->Activate();
  plateau.Depth->Activate();
  const glm::mat4 clipToPlane(
    glm::translate(glm::dmat4(1.0), -plane.Origin) * glm::inverse(this->WorldToClip));
  const float viewport[2] = { static_cast<float>(this->Size[0]),
    static_cast<float>(this->Size[1]) };
  const float planeToTexture[4] = { static_cast<float>(1.0 / size.x),
    static_cast<float>(1.0 / size.y), static_cast<float>(-lo.x / size.x),
    static_cast<float>(-lo.y / size.y) };
  const glm::vec3 normal(plane.Normal), u(plane.U), v(plane.V);
  resolve->SetUniformi("depthTexture", this->DepthCopy->GetTextureUnit());
  resolve->SetUniformi("plateauTexture", plateau.Depth->GetTextureUnit());
  resolve->SetUniformMatrix4x4("clipToPlane", const_cast<float*>(glm::value_ptr(clipToPlane)));
  resolve->SetUniform2f("viewportSize", viewport);
  resolve->SetUniform3f("planeNormal", glm::value_ptr(normal));
  resolve->SetUniform3f("planeU", glm::value_ptr(u));
  resolve->SetUniform3f("planeV", glm::value_ptr(v));
  resolve->SetUniform4f("planeToTexture", planeToTexture);
  resolve->SetUniformf("planeTolerance", static_cast<float>(tolerance));
  resolve->SetUniformi("sinusoidal", self->GetPlateauFalloff() == PLATEAU_FALLOFF_SINUSOIDAL);
  this->DrawFullScreen(resolve, this->PlateauResolveVAO);
  plateau.Depth->Deactivate();
  this->DepthCopy->Deactivate();
  ostate->vtkglEnable(GL_DEPTH_TEST);
  return static_cast<vtkIdType>(plateau.Triangles.size() / 3);
}

//------------------------------------------------------------------------------
vtkImageData* vtkSoftShadowPass::GetVisibilityImage(int lightIndex)
{
  vtkInternals& internals = *this->Internals;
  const vtkInternals::ShadowLight* light = internals.FindLight(lightIndex);
  vtkOpenGLRenderWindow* window = internals.Window;
  if (!light || !window || internals.Layers == 0)
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
  vtkPixelBufferObject* download = internals.LightIntensity->Download();
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
    !penumbra::InsertLightFactors(fragmentShader, penumbraReceiverDec, ReceiverLights(lights)))
  {
    this->WarnShaderEdit(mapper, prop,
      "has no //VTK::Light::Dec and //VTK::Light::Impl tags (a vtkShaderProperty replacing "
      "them?)");
  }
  return true;
}

bool vtkSoftShadowPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop)
{
  const auto& lights = this->Internals->Lights;
  if (lights.empty() || fragmentShader.find("penumbraLightFactor") == std::string::npos)
  {
    return true; // nothing inserted, already reported
  }
  const std::vector<int> missing =
    penumbra::ScaleLightTerms(fragmentShader, ReceiverLights(lights));
  if (!missing.empty())
  {
    this->WarnShaderEdit(mapper, prop,
      "does not contain VTK 9.1's diffuse and specular statements for light " +
        std::to_string(missing.front()) + " (another VTK version, or custom light code?)");
  }
  return true;
}

void vtkSoftShadowPass::WarnShaderEdit(
  vtkAbstractMapper* mapper, vtkProp* prop, const std::string& problem)
{
  std::ostringstream what;
  what << (prop ? prop->GetClassName() : "a prop") << " (" << prop << ", drawn by "
       << (mapper ? mapper->GetClassName() : "a mapper") << ")";
  if (this->Internals->WarnedShaderEdits.insert(what.str() + problem).second)
  {
    vtkWarningMacro(
      "The fragment shader of " << what.str() << " " << problem << ": it is drawn unshadowed.");
  }
}

bool vtkSoftShadowPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  vtkInternals& internals = *this->Internals;
  if (internals.Lights.empty() || !program->IsUniformUsed("penumbraApply"))
  {
    return true;
  }
  const bool apply = internals.ApplyShadows && GetReceivesShadows(prop) &&
    !prop->IsRenderingTranslucentPolygonalGeometry();
  program->SetUniformi("penumbraApply", apply ? 1 : 0);
  program->SetUniformi("penumbraLI", internals.LightIntensity->GetTextureUnit());
  // The LI buffer covers the viewport. A pass drawing into a framebuffer of its own (SSAO, depth
  // peeling, tone mapping) puts the viewport at that framebuffer's origin, not the window's:
  // take the origin of the viewport being drawn.
  GLint viewport[4] = { internals.Origin[0], internals.Origin[1], 0, 0 };
  if (internals.Window)
  {
    internals.Window->GetState()->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  }
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
    : 0.0;
}

double vtkSoftShadowPass::GetStageGPUMilliseconds(int stage)
{
  return stage >= 0 && stage < NUMBER_OF_STAGES
    ? this->Internals->StageTimes.GpuMilliseconds(static_cast<penumbra::StageTimes::Stage>(stage))
    : -1.0;
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkInternals& internals = *this->Internals;
  internals.StageTimes.ReleaseGraphicsResources();
  internals.Caches.ReleaseGraphicsResources();
  internals.Framebuffer->ReleaseGraphicsResources(w);
  internals.DepthStencil->ReleaseGraphicsResources(w);
  internals.DepthCopy->ReleaseGraphicsResources(w);
  internals.DepthCopyFramebuffer->ReleaseGraphicsResources(w);
  internals.Plateau.Framebuffer->ReleaseGraphicsResources(w);
  internals.Plateau.Depth->ReleaseGraphicsResources(w);
  internals.Plateau.Vertices->ReleaseGraphicsResources();
  internals.Plateau.VAO->ReleaseGraphicsResources();
  internals.Plateau.VAOProgram = nullptr;
  internals.Plateau.TextureCurrent = false;
  internals.Plateau.Signature.clear();
  internals.Plateau.FittedProp = nullptr;
  internals.LightIntensity->ReleaseGraphicsResources(w);
  internals.CentreCount->ReleaseGraphicsResources(w);
  internals.SampleCounters->ReleaseGraphicsResources(w);
  internals.CountingSupport = -1;
  internals.FullScreenTriangle->ReleaseGraphicsResources();
  for (vtkInternals::FullScreenVAO* vao : internals.FullScreenVAOs())
  {
    vao->VAO->ReleaseGraphicsResources();
    vao->Program = nullptr;
  }
  internals.DepthPass->ReleaseGraphicsResources(w);
  internals.Layers = 0;
  internals.VisibilityImages.clear();
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  this->Superclass::ReleaseGraphicsResources(w);
}
