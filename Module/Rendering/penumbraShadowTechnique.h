/**
 * @file    penumbraShadowTechnique.h
 * @brief   How a light's layer of the LI buffer is drawn: one class per shadow method behind one
 *          small interface, and what they draw with.
 *
 * penumbra::TechniqueChooser picks a ShadowTechnique per light, and vtkSoftShadowPass runs
 * every light the same way: the technique brings its per-caster caches up to date
 * (UpdateCaster) and prepares what it draws from (PrepareLight), the ShadowVolumeRenderer draws
 * the opaque casters' shadow volumes of the light's samples, the technique writes each sample's
 * count into the layer (ResolveSample), and finally draws what is its own (Finish): wedges,
 * counting, plateaus. Translucent casters' volumes are drawn per light sample, one a channel
 * of the target (hard and averaged shadows one sample at a time, counting four), when a
 * technique asks for them (ShadowFrame::DrawTranslucentVolumes). Everything a
 * technique draws with lives in the ShadowFrame the pass fills.
 */
#ifndef penumbraShadowTechnique_h
#define penumbraShadowTechnique_h

#include "penumbraConvexClip.h"
#include "penumbraCulling.h"
#include "penumbraOpenGLHelpers.h"
#include "penumbraShadowCaches.h"
#include "penumbraShadowVolumeRenderer.h"

#include "vtkType.h"

#include <glm/glm.hpp>

#include <array>
#include <utility>
#include <vector>

class vtkLight;
class vtkObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace penumbra
{

class LightIntensityBuffer;
class ShadowTechnique;

/// A light as the pass shadows it this frame.
struct ShadowLight
{
  vtkLight* Light = nullptr;
  int CollectionIndex = 0; ///< index in the renderer's light collection
  int ShaderIndex = 0; ///< index among switched-on lights: the N of lightColorN in VTK's shaders
  int Layer = 0;       ///< layer of the LI buffer
  glm::dvec4 World{ 0.0 }; ///< (position, 1) or (direction towards the light, 0)
  float Attenuation = 1.0f;
  /// How this light's layer is drawn: set by the pass's chooser, and by the cost model for
  /// Automatic's soft lights.
  ShadowTechnique* Technique = nullptr;
  /// Points (or directions) on the light whose hard shadows are averaged (one for hard
  /// shadows), the point counting starts from for counting (CountingReference), or the light
  /// itself for the other techniques.
  std::vector<glm::dvec4> Samples;
  /// The light's radius for wedges, plateaus and counting: world units, or radians for a
  /// directional light. Counting's is grown by CountingReferenceOffset, so that its light
  /// about the reference point holds the whole light.
  double SoftRadius = 0.0;
  glm::dvec3 SampleTarget{ 0.0 };
  double SampleRadius = 0.0; ///< as SpreadLightSamples takes it: world units, or clamped degrees
  /// Counting: the samples whose counts the potential silhouette changes.
  std::vector<glm::dvec4> CountingSamples;
  /// Automatic picked counting: it may still average the same samples where that is cheaper.
  bool CountingChosenAutomatically = false;
  /// A translucent caster's shadow may reach the view (averaged and counted lights only: wedges
  /// and plateaus leave translucent casters out).
  bool ShadowedByTranslucentCasters = false;

  /// Wedges and counting count the centre's volumes in colour, not in the stencil.
  bool CountsCentreInColour() const;
  /// Whether the opaque casters' volumes are counted in colour (ShadowTechnique::CountsInColour).
  bool CountsVolumesInColour() const;
  /// Cache key of sample k's volume. The light's centre has a key of its own, so that the
  /// centre silhouette (wedges, counting) and averaged samples never evict each other.
  std::pair<vtkLight*, int> VolumeKey(std::size_t k) const;
  static constexpr int CentreVolume = -1;
  /// The samples whose translucent casters' volumes are drawn one at a time: the counted ones
  /// for counting, the averaged ones otherwise. Sample k's volume is cached under
  /// TranslucentVolumeKey(k), the averaged sample k's key.
  const std::vector<glm::dvec4>& TranslucentSamples() const;
  std::pair<vtkLight*, int> TranslucentVolumeKey(std::size_t k) const
  {
    return { this->Light, static_cast<int>(k) };
  }
};

/// What the techniques add to the pass's statistics.
struct TechniqueCounts
{
  vtkIdType Wedges = 0;
  vtkIdType FullViewportWedges = 0;
  vtkIdType PlateauTriangles = 0;
  int CountedLights = 0;
};

/// What a technique draws with this frame. The pass owns all of it.
struct ShadowFrame
{
  vtkOpenGLRenderWindow* Window = nullptr;
  int Size[2] = { 0, 0 };
  glm::dmat4 WorldToClip{ 1.0 };
  glm::dmat4 ClipToWorld{ 1.0 };
  std::array<glm::dvec3, 4> NearCorners;
  const std::vector<CasterCache*>* Casters = nullptr;
  /// The LI buffer (its framebuffer bound while a light's layer is drawn).
  LightIntensityBuffer* Buffer = nullptr;
  /// The buffer's depth copy, for the shaders to read, and its layers.
  vtkTextureObject* DepthCopy() const;
  vtkTextureObject* Layers() const;
  /// The visible triangles' planes where caster meshes drew the depth (LightIntensityBuffer::
  /// AttachClearedSurfacePlanes), or nullptr where no light asked for them this frame.
  vtkTextureObject* SurfacePlanes = nullptr;
  /// The origin about which the surface planes' offsets are given: the near plane's centre in
  /// the frame that drew them (a kept depth keeps them from an earlier frame).
  glm::dvec3 SurfacePlanesOrigin{ 0.0 };
  ShaderPrograms* Programs = nullptr;
  FullScreenTriangle* FullScreen = nullptr;
  FullScreenTriangle::VAO* ResolveVAO = nullptr;
  TechniqueCounts Counts;
  /// Holds every visible prop (the pass's scene box): volumes are drawn only where it may be.
  Box SceneBox;
  ShadowVolumeRenderer* Volumes = nullptr;

  /// Sums log(1 - opacity) over the translucent surfaces between each pixel's point and the
  /// light's samples first .. first + count - 1 (TranslucentSamples) into channels 0 .. count - 1
  /// of `target`, a float target of `components` (1 or 4) channels allocated for the viewport
  /// as needed, by drawing the volumes of the translucent casters whose shadow from those
  /// samples may reach the view. Returns the pixels they may cover, where the target is cleared
  /// to 0 first: it is read only there, and elsewhere the transmission is 1. Empty when none was
  /// drawn. The light's layer is bound again after, and the stencil left as it was.
  PixelRect DrawTranslucentVolumes(const ShadowLight& light, std::size_t first, std::size_t count,
    vtkTextureObject* target, int components) const;

  /// Makes `texture` (layer `layer` of a vtkPenumbraLayeredTexture, or a 2D texture) the LI
  /// framebuffer's colour attachment 0 and its draw buffer; the framebuffer must be bound.
  void AttachColour(vtkTextureObject* texture, int layer) const;
  /// Makes `depth` the LI framebuffer's depth attachment in place of its depth-stencil, or with
  /// nullptr the depth-stencil again (LightIntensityBuffer::AttachDepth).
  void AttachDepth(vtkTextureObject* depth) const;
  /// Makes `texture` a float target of `components` channels (R32F, RGBA32F) and the
  /// viewport's size in this window, allocating it when it is not one yet, attaches it as
  /// AttachColour does and clears it to 0 (within the scissor box, when the scissor test is on)
  /// with colour writes on: where a technique adds counts with additive blending.
  void AttachClearedFloatTarget(vtkTextureObject* texture, int components = 1) const;
  /// Sets the uniforms every shader that reads the scene depth declares: the texture unit of
  /// `depth` (activated by the caller; nullptr: the depth copy) and the viewport size.
  void SetDepthUniforms(vtkShaderProgram* program, vtkTextureObject* depth = nullptr) const;
  /// Sets `clipToLocal`, which penumbraPointAt reads: NDC to world space relative to `origin`,
  /// with the NDC depth's column added into the constant one, so that the shader multiplies by
  /// the NDC depth minus 1. Near the far plane, where a perspective depth buffer holds most of
  /// the scene, the depth then takes no float cancellation: depth - 1 is exact, and the columns'
  /// sum, which cancels, is taken here in double.
  void SetClipToLocal(vtkShaderProgram* program, const glm::dvec3& origin) const;
  /// SetClipToLocal about a light point (x, y, z, 1), and `lightWedge` (0, 0, 0, 1) there; or,
  /// for a direction (x, y, z, 0), about the world's origin, with `lightWedge` the direction.
  void SetClipToLight(vtkShaderProgram* program, const glm::dvec4& light) const;
  /// Sets the uniforms of //PENUMBRA::SurfacePlane::Dec: the surface planes' texture unit, or
  /// that there are none. The caller activates SurfacePlanes (where it is not nullptr) and the
  /// depth copy.
  void SetSurfaceSideUniforms(vtkShaderProgram* program) const;
  /// Adds `lightIntensity` into the bound layer at every pixel the current depth and stencil
  /// tests pass for the full-screen triangle at the far plane.
  void DrawResolve(float lightIntensity);
  /// Writes 1 into the bound layer where no surface is (the depth buffer at the far plane):
  /// volumes counted straight into the layer also cross the background, which must stay lit.
  void LightBackground();
  /// Draws one caster's wedge buffer (either kind), if it has any, with the program bound: front
  /// or back faces as the eye and near plane allow, in wedge coordinates. It sets the culled face
  /// and the depth function: its callers hold a ScopedDrawState, not it, as it runs per caster.
  void DrawWedgeBuffer(vtkShaderProgram* program, const CasterCache& caster, WedgeBuffer& buffer,
    const std::vector<VertexAttribute>& attributes, const ShadowLight& light);
};

/// How one light's layer is drawn.
class ShadowTechnique
{
public:
  virtual ~ShadowTechnique() = default;
  /// Whether the pass counts the centre's volume into the layer in colour (+-1 per crossing)
  /// instead of each sample's in the stencil.
  virtual bool CountsCentreInColour() const { return false; }
  /// Whether the light's opaque casters' volumes are counted in colour, with additive blending
  /// into a float target, rather than in the stencil. Colour weights each side by its
  /// multiplicity and so draws it once (penumbra::ShadowVolume), where the stencil draws it
  /// |m| times: the general counting rule gives an open mesh's silhouette edges m = 2.
  virtual bool CountsInColour(const ShadowLight&) const { return this->CountsCentreInColour(); }
  /// Whether it reads the scene's depth copy (LightIntensityBuffer::CopyDepth) while drawing.
  virtual bool ReadsDepthCopy() const { return true; }
  /// NDC depth by which its opaque volumes' sides are pushed away from the eye at the caster,
  /// where they start on a surface and their rasterized depth is off by more than the point's
  /// margin in front of it.
  virtual float VolumeDepthBias() const { return 0.0f; }
  /// Whether it reads the surface planes (LightIntensityBuffer::AttachClearedSurfacePlanes).
  virtual bool ReadsSurfacePlanes() const { return false; }
  /// Whether translucent casters shadow by their opacity (otherwise they are left out).
  virtual bool ShadowsTranslucentCasters() const { return false; }
  /// Brings this technique's caches of one caster for the light, beyond the samples' volumes,
  /// up to date; returns the silhouette updates it made.
  virtual vtkIdType UpdateCaster(const ShadowLight&, CasterCache&, const ReceiverBounds&)
  {
    return 0;
  }
  /// Once the light's technique and casters are final for the frame, before anything is drawn.
  virtual void PrepareLight(const ShadowLight&, const std::vector<CasterCache*>&) {}
  /// Prepares the light's targets before its volumes are drawn (its layer bound and cleared).
  virtual void BeginVolumes(ShadowFrame&, const ShadowLight&) {}
  /// Writes the opaque casters' volume count just drawn for light.Samples[k] into the layer.
  virtual void ResolveSample(ShadowFrame& frame, const ShadowLight& light, std::size_t k) = 0;
  /// Draws the rest of the light's layer after its volumes.
  virtual void Finish(ShadowFrame&, const ShadowLight&) {}
  virtual std::size_t GraphicsMemoryBytes() const { return 0; }
  virtual void ReleaseGraphicsResources(vtkWindow*) {}
};

} // namespace penumbra

#endif
