/**
 * @class   vtkSoftShadowPass
 * @brief   Render pass that gives a VTK scene hard and soft shadows (shadow volumes, penumbra
 *          wedges, averaged hard shadows).
 *
 * Drop it into any renderer (`renderer->SetPass(pass)`) and the scene renders as VTK would
 * (opaque, translucent, volumes, overlays) with the opaque geometry shadowed by every
 * switched-on light that can cast shadows: positional (point and spot) and directional scene or
 * camera lights. Headlights are skipped at no cost: a positional one casts no visible shadow,
 * and a directional one (VTK's automatic light) only thin slivers beside objects in a
 * perspective view, which stay lit as VTK draws them.
 *
 * Per frame the pass
 * 1. updates, on the CPU and only when a light, an actor's matrix or its data changed, the
 *    silhouette of every caster for every shadowing light (in the caster's object space);
 * 2. renders the opaque geometry's depth into its own framebuffer, which has the stencil that
 *    VTK 9.1's window lacks;
 * 3. for each light, draws the opaque casters' shadow volumes (swept to infinity in the vertex
 * shader, depth-clamped, z-pass where the volume cannot reach the near plane and z-fail with caps
 *    otherwise) into the stencil, or additively in colour (each side drawn once, weighted by its
 *    multiplicity), and resolves it into that light's layer of the light-intensity (LI) buffer,
 *    a float texture array (1 lit, 0 shadowed);
 *    For a light with a radius (SetLightRadius) the layer becomes soft: by default
 *    (METHOD_AUTOMATIC, which counts with METHOD_SOFT_SHADOW_VOLUMES where that is cheaper)
 *    the depth complexity of LightSamples points on the light is counted exactly from the
 *    centre's volume count and one wedge per potential silhouette edge, which equals averaging
 *    those samples' hard shadows (METHOD_AVERAGED_HARD_SHADOWS) for any mesh at the cost of
 *    one wedge pass (translucent casters' volumes are drawn per sample, in both); penumbra wedges
 * of the centre silhouette (METHOD_PENUMBRA_WEDGES) and plateaus (METHOD_PLATEAUS) are cheaper
 * approximations;
 * 4. renders the scene through its delegate (by default VTK's own render steps) with the
 *    mappers' fragment shaders edited so that each light's diffuse and specular terms are scaled
 *    by 1 - ShadowAttenuation * (1 - LI), ambient untouched (Phong and PBR).
 *
 * Actors are excluded from casting or receiving with SetCastsShadows / SetReceivesShadows, which
 * store keys in the prop's property keys. A light's size is a key in its information
 * (SetLightRadius): world units for positional lights, angular radius in degrees for directional
 * ones. Translucent actors cast by their opacity: each of their surfaces between a point and a
 * light sample lets 1 - opacity of it through (hard, averaged and counted shadows; wedges and
 * plateaus leave them out, with a warning).
 * They receive nothing: their fragments are drawn unshadowed over the shadowed surface behind.
 * Actors with Lighting off cast but show no shadow (VTK draws them without light terms; one
 * warning each).
 *
 * It also works as a delegate inside a vtkCameraPass / vtkSequencePass chain: set its delegate
 * to the pass that draws the opaque geometry.
 *
 * @sa vtkShadowMapPass vtkRayTracedVisibility
 */
#ifndef vtkSoftShadowPass_h
#define vtkSoftShadowPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkPenumbraRenderingModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkActor;
class vtkImageData;
class vtkInformationDoubleKey;
class vtkInformationIntegerKey;
class vtkLight;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderPass;
class vtkRenderer;

class VTKPENUMBRARENDERING_EXPORT vtkSoftShadowPass : public vtkOpenGLRenderPass
{
public:
  static vtkSoftShadowPass* New();
  vtkTypeMacro(vtkSoftShadowPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The pass that renders the scene once the light-intensity buffer is ready. Defaults to a
   * vtkRendererSettingsPass: the whole scene as the renderer draws it without a pass, its depth
   * peeling, FXAA and SSAO settings included.
   */
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);

  ///@{
  /**
   * Master switch: when off the pass only renders its delegate.
   */
  vtkSetMacro(ShadowsEnabled, bool);
  vtkGetMacro(ShadowsEnabled, bool);
  vtkBooleanMacro(ShadowsEnabled, bool);
  ///@}

  /// How shadows are computed for each shadowing light.
  enum Methods
  {
    /// Hard volumes for a light of radius 0. For an area light, soft shadow volumes or averaged
    /// hard shadows of the same LightSamples, which give the same image, whichever a cost model
    /// fitted to the benchmark expects to be faster (penumbra::CountingIsCheaper: counting for
    /// small lights and coarse casters, averaging for large lights over finely tessellated
    /// ones); averaging where the OpenGL context lacks image atomics, LightSamples is above
    /// the 256 that counting holds, or the light's counts came near what the counters hold
    /// (200 surfaces deep: found in the frame of its first count, else from the next frame on).
    METHOD_AUTOMATIC = 0,
    /// One shadow volume from the light's centre: hard shadows whatever the light's radius.
    METHOD_HARD_VOLUMES = 1,
    /// Heckbert and Herf: the average of LightSamples hard shadows from points spread evenly
    /// over the light (a disk facing the casters, or a cone of directions). Converges to the
    /// true soft shadow as LightSamples grows, at one volume pass per sample.
    METHOD_AVERAGED_HARD_SHADOWS = 2,
    /// Akenine-Moller and Assarsson: the hard shadow of the light's centre plus one penumbra
    /// wedge per silhouette edge, each adding that edge's exact share of the light seen from
    /// the pixel. One volume pass and one wedge pass per light.
    METHOD_PENUMBRA_WEDGES = 3,
    /// Haines' plateaus, for a planar receiver (an actor marked with SetShadowPlane, or the
    /// plane set with SetReceiverPlaneOrigin/Normal and UseReceiverPlaneOn): the hard drop shadow
    /// plus cones and sheets around its outline, rendered straight down the plane's normal into a
    /// texture where the darkest primitive wins. Fast and smooth, with an umbra too large (no inner
    /// penumbra). Pixels off the plane get the hard shadow of the light's centre.
    METHOD_PLATEAUS = 4,
    /// Per-light-sample counting (Laine et al. 2005, Forest et al. 2008): the shadow-volume count
    /// of the light's centre plus, in one wedge per potential silhouette edge, each edge's change
    /// of the count of every one of LightSamples points on the light, as seen from the pixel.
    /// The same answer as averaging those samples' hard shadows, for any mesh, in one volume
    /// pass and one wedge pass for the opaque casters; translucent casters' volumes are drawn
    /// for every sample, as averaging draws them. Needs OpenGL 4.4 (or image load/store and
    /// clear_texture); at most 256 samples (more are clamped, with a warning); a sample's count
    /// is kept in 8 bits, read from -4 to 251 (252 layers overflow; counts of 200 and more are
    /// warned about a frame later).
    METHOD_SOFT_SHADOW_VOLUMES = 5
  };

  ///@{
  /**
   * The method (default METHOD_AUTOMATIC).
   */
  vtkSetClampMacro(Method, int, METHOD_AUTOMATIC, METHOD_SOFT_SHADOW_VOLUMES);
  vtkGetMacro(Method, int);
  void SetMethodToAutomatic() { this->SetMethod(METHOD_AUTOMATIC); }
  void SetMethodToHardVolumes() { this->SetMethod(METHOD_HARD_VOLUMES); }
  void SetMethodToAveragedHardShadows() { this->SetMethod(METHOD_AVERAGED_HARD_SHADOWS); }
  void SetMethodToPenumbraWedges() { this->SetMethod(METHOD_PENUMBRA_WEDGES); }
  void SetMethodToPlateaus() { this->SetMethod(METHOD_PLATEAUS); }
  void SetMethodToSoftShadowVolumes() { this->SetMethod(METHOD_SOFT_SHADOW_VOLUMES); }
  const char* GetMethodAsString();
  ///@}

  ///@{
  /**
   * Light samples per area light for METHOD_SOFT_SHADOW_VOLUMES (at most 256 there) and
   * METHOD_AVERAGED_HARD_SHADOWS: the same N gives the same points, and the same answer, in
   * both. Default 64, so that soft shadows by default are as accurate as averaging 64 hard
   * shadows (Documentation/results.md).
   */
  vtkSetClampMacro(LightSamples, int, 1, 4096);
  vtkGetMacro(LightSamples, int);
  ///@}

  /// How a plateau's depth t (0 at the hard shadow, 1 at the penumbra's edge) becomes light.
  enum PlateauFalloffType
  {
    PLATEAU_FALLOFF_LINEAR = 0,    ///< intensity t
    PLATEAU_FALLOFF_SINUSOIDAL = 1 ///< (1 - cos(pi t)) / 2: no crease at either end
  };
  ///@{
  /**
   * Falloff of METHOD_PLATEAUS (default sinusoidal, Haines' Figure 5).
   */
  vtkSetClampMacro(PlateauFalloff, int, PLATEAU_FALLOFF_LINEAR, PLATEAU_FALLOFF_SINUSOIDAL);
  vtkGetMacro(PlateauFalloff, int);
  void SetPlateauFalloffToLinear() { this->SetPlateauFalloff(PLATEAU_FALLOFF_LINEAR); }
  void SetPlateauFalloffToSinusoidal() { this->SetPlateauFalloff(PLATEAU_FALLOFF_SINUSOIDAL); }
  ///@}
  ///@{
  /**
   * Width and height in texels of the plateau texture, which covers the shadows on the plane
   * (default 1024).
   */
  vtkSetClampMacro(PlateauResolution, int, 16, 8192);
  vtkGetMacro(PlateauResolution, int);
  ///@}
  ///@{
  /**
   * The receiver plane of METHOD_PLATEAUS, when UseReceiverPlane is on; otherwise the plane of
   * the first visible actor marked with SetShadowPlane (its polydata must be flat).
   */
  vtkSetVector3Macro(ReceiverPlaneOrigin, double);
  vtkGetVector3Macro(ReceiverPlaneOrigin, double);
  vtkSetVector3Macro(ReceiverPlaneNormal, double);
  vtkGetVector3Macro(ReceiverPlaneNormal, double);
  vtkSetMacro(UseReceiverPlane, bool);
  vtkGetMacro(UseReceiverPlane, bool);
  vtkBooleanMacro(UseReceiverPlane, bool);
  ///@}
  ///@{
  /**
   * Marks a flat actor (a ground plane, a slice) as the receiver plane of METHOD_PLATEAUS,
   * through its property keys; default false.
   */
  static void SetShadowPlane(vtkProp* prop, bool isPlane);
  static bool GetShadowPlane(vtkProp* prop);
  static vtkInformationIntegerKey* SHADOW_PLANE();
  ///@}

  ///@{
  /**
   * Light size, stored in the light's vtkInformation: radius in world units for positional
   * lights, angular radius in degrees for directional lights. 0 (the default) gives hard shadows.
   */
  static void SetLightRadius(vtkLight* light, double radius);
  static double GetLightRadius(vtkLight* light);
  static vtkInformationDoubleKey* LIGHT_RADIUS();
  ///@}

  ///@{
  /**
   * Per-prop control through the prop's property keys; both default to true.
   */
  static void SetCastsShadows(vtkProp* prop, bool casts);
  static bool GetCastsShadows(vtkProp* prop);
  static void SetReceivesShadows(vtkProp* prop, bool receives);
  static bool GetReceivesShadows(vtkProp* prop);
  static vtkInformationIntegerKey* CASTS_SHADOWS();
  static vtkInformationIntegerKey* RECEIVES_SHADOWS();
  ///@}

  /**
   * True when this pass would shadow with `light`: switched on, not a headlight, with some
   * intensity and shadow attenuation.
   */
  static bool LightCastsShadows(vtkLight* light);

  /**
   * The last frame's light intensity for the i-th light of the renderer's light collection, as a
   * one-component float image of the viewport's size (1 lit, 0 in shadow; background 1), or
   * nullptr for a light that cast no shadow. Reads the GPU buffer back: not for every frame.
   * A pass set on several renderers holds the last renderer's frame. Pixels of props that do
   * not receive shadows (SetReceivesShadows off) hold no defined value: counted lights cut their
   * wedges to the receivers, so there such a pixel holds the centre's hard shadow.
   */
  vtkImageData* GetVisibilityImage(int lightIndex);

  /**
   * Number of lights shadowed in the last frame, and the shadow-volume triangles drawn for them.
   * Counts of lights are int, as VTK's; counts of casters, triangles and wedges are vtkIdType.
   */
  vtkGetMacro(NumberOfShadowingLights, int);
  vtkGetMacro(NumberOfShadowVolumeTriangles, vtkIdType);
  /// Wedges drawn in the last frame (centre-silhouette penumbra wedges and soft shadow volumes'
  /// potential-silhouette wedges), and those drawn over the whole viewport (or the receivers'
  /// box) because their edge points at the light and has no bound: no wedge planes exist, and
  /// its light pyramid (penumbra::LightPyramid) would be wider than 60 degrees or the edge
  /// reaches into a positional light.
  vtkGetMacro(NumberOfPenumbraWedges, vtkIdType);
  vtkGetMacro(NumberOfFullViewportWedges, vtkIdType);
  /// (caster, light) pairs skipped in the last frame because that shadow cannot reach the view.
  vtkGetMacro(NumberOfCulledShadows, vtkIdType);
  /// Shadow volumes drawn with z-fail (caps) in the last frame; the rest used z-pass.
  vtkGetMacro(NumberOfZFailVolumes, vtkIdType);
  /// Plateau triangles (drop shadows, cones, sheets) drawn in the last frame.
  vtkGetMacro(NumberOfPlateauTriangles, vtkIdType);
  /// Lights whose soft shadows were counted (soft shadow volumes) in the last frame, and those
  /// averaged from more than one light sample: Automatic's choices, for one.
  vtkGetMacro(NumberOfCountedLights, int);
  vtkGetMacro(NumberOfAveragedLights, int);
  /// Silhouette updates done so far (a static scene under an orbiting camera adds none).
  vtkGetMacro(NumberOfSilhouetteUpdates, vtkIdType);
  /// Bytes of GPU memory the pass held after the last frame: its framebuffer textures (depth
  /// and stencil, depth copy, one light-intensity layer per light, for soft shadow volumes the
  /// counting depth and centre count, one byte per pixel and light sample, the visible
  /// triangles' planes (16 bytes per pixel, with depth from caster meshes), the count offsets, the
  /// half-resolution targets once used and the deep-count report, the averaged samples' count
  /// target once open casters were averaged, the plateaus' depth texture and buffer once drawn, and
  /// the translucent casters' transmission targets once one was drawn) and the casters' vertex,
  /// index and wedge buffers.
  vtkGetMacro(GraphicsMemoryBytes, vtkIdType);

  /// The stages of a frame, for GetStageCPUMilliseconds and GetStageGPUMilliseconds.
  enum Stages
  {
    STAGE_DEPTH = 0,   ///< the depth pass and its copy for the wedge shaders
    STAGE_CASTERS = 1, ///< the scene walk, topology, silhouettes and wedge buffers (CPU)
    STAGE_VOLUMES = 2, ///< shadow volumes and their resolves into the LI buffer
    /// wedges, per-sample counting (with a counted light's translucent casters) and plateaus
    STAGE_WEDGES = 3,
    STAGE_COMPOSITING = 4, ///< the delegate: the scene drawn with the LI buffer applied
    NUMBER_OF_STAGES = 5
  };
  static const char* GetStageName(int stage);

  ///@{
  /**
   * Per-stage times of the last frame: off by default. When on, GL timestamp queries bracket
   * each stage, and the pipeline is drained (glFinish) at every stage boundary so that no
   * stage is billed for work the driver deferred: a timed frame is slower than an untimed one
   * and the split, not the sum, is the figure. CPU times are the wall-clock time from a stage's
   * start to the end of its GL work.
   */
  vtkSetMacro(CollectStageTimes, bool);
  vtkGetMacro(CollectStageTimes, bool);
  vtkBooleanMacro(CollectStageTimes, bool);
  ///@}
  /// Milliseconds of the last frame in `stage` on the CPU, and on the GPU: -1 for both when the
  /// frame was not timed or `stage` is not one, and on the GPU where timestamps are not supported.
  double GetStageCPUMilliseconds(int stage);
  double GetStageGPUMilliseconds(int stage);

  ///@{
  /**
   * Whether the pass draws its depth, shadow volumes and wedges with the camera's clipping range
   * narrowed to the depths of everything visible (every visible prop's bounds, UseBounds or
   * not); the scene is drawn with the camera's own range. On by default: VTK's own range is
   * expanded by half its length and its near plane clamped to 1/1000 of the far one, so that a
   * 24-bit depth buffer's steps span far more than the scene, and the shadows' tests against
   * the depth of each pixel (counting's point above all) lose precision with them
   * (Documentation/wedges.md). The user's camera is not modified: the pass draws with a copy,
   * made the renderer's active camera while VTK draws props into the shadows' depth (which
   * modifies the renderer on those frames, as vtkShadowMapBakerPass's light cameras do).
   */
  vtkSetMacro(UseTightDepthRange, bool);
  vtkGetMacro(UseTightDepthRange, bool);
  vtkBooleanMacro(UseTightDepthRange, bool);
  ///@}

  ///@{
  /**
   * Whether soft shadow volumes (METHOD_SOFT_SHADOW_VOLUMES, and Automatic where it counts) are
   * counted at half the viewport's resolution in each direction. Every other pixel in each
   * direction is counted exactly; a pixel between takes the mean of its counted neighbours where
   * they are at most two samples' shares apart (with fewer than 8 samples: fewer shares, so that
   * no hard step is blended) and its depth does not stand out from theirs, and is counted again
   * at full resolution elsewhere (shadow edges, silhouettes, the background's edge, thin
   * surfaces, thin hard shadows of the light's centre). A penumbra narrower than two pixels
   * between counted pixels that agree, where the light's centre is seen, is lost. A light whose
   * translucent casters' shadows reach the view is counted at full resolution. Automatic's choice
   * between counting and averaging does not take it into account. Off by default; up to 1.7 times
   * faster on large lights and big casters, slower on small scenes (Documentation/wedges.md,
   * "Counting at half resolution").
   */
  vtkSetMacro(HalfResolutionCounting, bool);
  vtkGetMacro(HalfResolutionCounting, bool);
  vtkBooleanMacro(HalfResolutionCounting, bool);
  ///@}

  ///@{
  /**
   * Whether the pass draws the depth it counts shadows against from its casters' cached meshes,
   * for the props VTK draws as nothing but their polydata's triangles (a plain actor with a
   * polydata mapper, a surface with no edges, clipping planes or custom shaders; see
   * penumbraCasterDepth.h): one position-only draw each instead of VTK's full shaders, and a
   * closed caster seen from outside only with its hidden faces culled. The depth is the same; on
   * by default. For soft shadow volumes the same draw also keeps each visible triangle's plane,
   * from which counting takes its point on the seen side of the surface, even seen nearly
   * edge-on, and which keeps the light samples behind a surface's own facet off it (wedges.md,
   * "Facets at the terminator"). Off, VTK draws every prop's depth, and near terminators or on
   * far grazing receivers counting may see samples a facet hides or lose ones it does not.
   */
  vtkSetMacro(DepthFromCasterMeshes, bool);
  vtkGetMacro(DepthFromCasterMeshes, bool);
  vtkBooleanMacro(DepthFromCasterMeshes, bool);
  ///@}
  /// Props whose depth the last frame drew from their caster meshes (DepthFromCasterMeshes),
  /// and those of them drawn with their hidden faces culled (closed casters seen from outside).
  vtkGetMacro(NumberOfPropsWithDepthFromMeshes, vtkIdType);
  vtkGetMacro(NumberOfPropsWithCulledDepth, vtkIdType);

  ///@{
  /**
   * Whether a frame whose shadows cannot have changed composites the light-intensity layers of
   * the last frame the pass drew instead of drawing them again: the same renderer, viewport and
   * camera matrices, the same shadowing lights, unmodified (a light's colour, which changes no
   * shadow, redraws that light's too), the same settings,
   * and no prop, mapper, clipping plane, shader property or input data object (each block of
   * composite data) modified since (penumbraShadowInputs.h). Props that are neither a
   * vtkProp3D nor a vtkPropAssembly (text, scalar bars, 2D and 3D widgets' representations,
   * captions), which neither cast nor receive, may change freely, and so may the colours of
   * VTK's own actors and mappers (not those that can open holes or have shader code of their
   * own). On by default. A frame is always drawn while a visible prop is a vtkLODActor or
   * vtkLODProp3D (they pick their level by render time) or has a mapper with an
   * UpdateShaderEvent observer. Geometry that
   * changes without any VTK object being modified (data arrays edited in place without
   * Modified(), which VTK's mappers do not redraw either) keeps its old shadows: call Modified()
   * on the data, or on this pass to redraw.
   */
  vtkSetMacro(ReuseUnchangedShadows, bool);
  vtkGetMacro(ReuseUnchangedShadows, bool);
  vtkBooleanMacro(ReuseUnchangedShadows, bool);
  ///@}
  /// Frames so far that reused every light's shadows from the last drawn frame
  /// (ReuseUnchangedShadows). The other statistics then describe that drawn frame.
  vtkGetMacro(NumberOfReusedFrames, vtkIdType);
  /// Lights whose shadows the last drawn frame drew: with ReuseUnchangedShadows, a frame in which
  /// only some lights changed draws those alone, against the depth it kept. The statistics of
  /// what is drawn per light (volume triangles, wedges, z-fail volumes, plateau triangles,
  /// counted and averaged lights) then count those lights alone; NumberOfShadowingLights counts
  /// them all.
  vtkGetMacro(NumberOfRedrawnLights, int);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /// Shader edits applied to the mappers of receiving props (vtkOpenGLRenderPass API).
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;
  ///@}

protected:
  vtkSoftShadowPass();
  ~vtkSoftShadowPass() override;

  vtkRenderPass* DelegatePass = nullptr;
  bool ShadowsEnabled = true;
  int Method = METHOD_AUTOMATIC;
  int LightSamples = 64;
  int PlateauFalloff = PLATEAU_FALLOFF_SINUSOIDAL;
  int PlateauResolution = 1024;
  double ReceiverPlaneOrigin[3] = { 0.0, 0.0, 0.0 };
  double ReceiverPlaneNormal[3] = { 0.0, 0.0, 1.0 };
  bool UseReceiverPlane = false;
  bool CollectStageTimes = false;
  bool UseTightDepthRange = true;
  bool HalfResolutionCounting = false;
  bool DepthFromCasterMeshes = true;
  bool ReuseUnchangedShadows = true;
  vtkIdType NumberOfReusedFrames = 0;
  int NumberOfRedrawnLights = 0;
  vtkIdType NumberOfPropsWithDepthFromMeshes = 0;
  vtkIdType NumberOfPropsWithCulledDepth = 0;
  vtkIdType NumberOfPlateauTriangles = 0;
  int NumberOfCountedLights = 0;
  int NumberOfAveragedLights = 0;
  int NumberOfShadowingLights = 0;
  vtkIdType NumberOfShadowVolumeTriangles = 0;
  vtkIdType NumberOfZFailVolumes = 0;
  vtkIdType NumberOfCulledShadows = 0;
  vtkIdType NumberOfPenumbraWedges = 0;
  vtkIdType NumberOfFullViewportWedges = 0;
  vtkIdType NumberOfSilhouetteUpdates = 0;
  vtkIdType GraphicsMemoryBytes = 0;

private:
  vtkSoftShadowPass(const vtkSoftShadowPass&) = delete;
  void operator=(const vtkSoftShadowPass&) = delete;

  /// Inside a soft shadow pass already rendering (another one, or this one through its own
  /// delegate chain): warns once and draws the delegate unshadowed, or nothing in a cycle, and
  /// returns true. False otherwise, having drawn nothing.
  bool RenderIfNested(const vtkRenderState* s);
  /// Sizes the frame and collects the lights that shadow it, none where their layers do not fit.
  void PrepareShadowingLights(
    const vtkRenderState* s, vtkRenderer* renderer, vtkOpenGLRenderWindow* window);
  /// The viewport's size and origin, or those of the framebuffer the frame is drawn into.
  void UpdateFrameSize(const vtkRenderState* s, vtkRenderer* renderer);
  /// The frame without shadows: the delegate alone. Outside a selection render (which leaves
  /// them to the next frame) the shadows' statistics are zeroed and their kept inputs forgotten.
  void RenderUnshadowed(const vtkRenderState* s, bool selecting);
  /// Draws the shadows, or keeps the last drawn frame's, then the delegate with them applied.
  void RenderShadowed(
    const vtkRenderState* s, vtkRenderer* renderer, vtkOpenGLRenderWindow* window);
  /// The delegate drawn with the LI layers applied to the receivers.
  void CompositeShadows(const vtkRenderState* s);
  /// The delegate, timed as the compositing stage; then the frame's stage times end.
  void CompositeAndEndFrame(const vtkRenderState* s);
  void RenderDelegate(const vtkRenderState* s);
  /// Zeroes the statistics of the shadows drawn (a reused frame keeps the drawn frame's); with
  /// `depthKept`, the depth's statistics stay: the kept depth is the last drawn frame's.
  void ResetShadowStatistics(bool depthKept = false);
  /// Records this frame's shadow inputs and finds what it keeps of the last drawn frame's
  /// (ReuseUnchangedShadows): the depth when the scene is unchanged, and the layers of the lights
  /// that are unchanged too. True when every layer is kept.
  bool ShadowsUnchanged(const vtkRenderState* s);
  /// Depth, casters and the light layers not kept, then keeps the inputs they were drawn from.
  void DrawShadows(const vtkRenderState* s, vtkOpenGLRenderWindow* window);
  /// Warns once per positional light whose sphere reaches a visible prop's box.
  void WarnOfLightsReachingTheScene(vtkRenderer* renderer);
  /// Whether the frame's light-intensity layers fit: its size within GL_MAX_TEXTURE_SIZE, and the
  /// layers allocated (OpenGL may refuse them for memory); warns once while they do not.
  bool LayersFit(vtkOpenGLRenderWindow* window);
  /// Before drawing into `window`: releases the GPU resources made in another window's context
  /// and registers for the release of this one's.
  void FollowWindow(vtkOpenGLRenderWindow* window);
  /// Whether the viewport being drawn (x, y, width, height) has the shadows' size, so that the
  /// LI buffer lines up with it; counts the frame's draws at either.
  bool ViewportMatchesShadows(const int viewport[4]);
  /// Warns once where the frame's delegate drew receivers only at another size than the shadows'.
  void WarnOfDelegateSize();
  /// Warns once per prop and problem that a receiver's shader could not be edited.
  void WarnShaderEdit(vtkAbstractMapper* mapper, vtkProp* prop, const std::string& problem);
  void CollectShadowingLights(vtkRenderer* renderer);
  void UpdateShaderConfiguration();
  void AddReceiverKeys(const vtkRenderState* s);
  void RemoveReceiverKeys();
  /// Records `receiver`'s assembly-path leaves and their properties for DrawsForReceiver.
  void AddReceiverLeaves(vtkProp* receiver);
  /// Whether `actor` is one of this frame's receivers or a leaf of one's assembly paths, or
  /// draws with one's property (a vtkLODActor's or vtkFollower's device actor).
  bool DrawsForReceiver(vtkActor* actor) const;
  /// Clears the depth and draws, through VTK, that of the props not left to RenderCasterDepth.
  void RenderDepth(const vtkRenderState* s);
  /// After UpdateCasters: the depth of the props left to it, from their caster meshes.
  void RenderCasterDepth(const vtkRenderState* s);
  /// Draws `props`' depth through VTK's opaque pass into the LI framebuffer.
  void RenderDepthWithVTK(const vtkRenderState* s, std::vector<vtkProp*>& props);
  void UpdateCasters(const vtkRenderState* s);
  /// Draws the layers of the lights not kept; false when the volumes' shader did not build.
  bool RenderLightIntensity(vtkOpenGLRenderWindow* window);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
