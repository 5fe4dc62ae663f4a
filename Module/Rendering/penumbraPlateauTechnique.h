/**
 * @file    penumbraPlateauTechnique.h
 * @brief   Plateaus (METHOD_PLATEAUS): the centre's hard shadow, plus Haines' plateaus rendered
 *          over one receiver plane into a texture and written into the layer at the pixels on
 *          that plane (Documentation/plateaus.md).
 */
#ifndef penumbraPlateauTechnique_h
#define penumbraPlateauTechnique_h

#include "penumbraHardShadowTechnique.h"
#include "penumbraPlateaus.h"
#include "penumbraPropWarnings.h"
#include "penumbraShadowTechnique.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h" // for vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for vtkNew

#include <vector>

class vtkProp;
class vtkRenderer;

namespace penumbra
{

/// The pass's plateau settings, as it holds them.
struct PlateauSettings
{
  int Resolution = 1024;
  PlateauFalloff Falloff = PlateauFalloff::Sinusoidal;
  bool UseGivenPlane = false; ///< the plane below, not a marked actor's
  glm::dvec3 Origin{ 0.0 };
  glm::dvec3 Normal{ 0.0, 0.0, 1.0 };
};

class PlateauTechnique : public HardShadowTechnique
{
public:
  PlateauSettings Settings;

  /// Finds this frame's receiver plane: the given one, or the first visible actor marked
  /// vtkSoftShadowPass::SetShadowPlane, fitted once per change of it, its mapper or its data.
  /// Warns once per actor that cannot serve.
  bool FindReceiverPlane(vtkRenderer* renderer, vtkObject* owner);
  /// Warns (once) that plateaus have no receiver plane and the pass draws hard shadows.
  void WarnNoPlane(vtkObject* owner);

  /// Pixels are placed on the receiver plane from the depth copy.
  bool ReadsDepthCopy() const override { return true; }
  /// Plateaus are drawn from the opaque casters' silhouettes only.
  bool ShadowsTranslucentCasters() const override { return false; }

  void Finish(ShadowFrame& frame, const ShadowLight& light) override;
  /// The plateau texture and triangles.
  std::size_t GraphicsMemoryBytes() const override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

private:
  /// Renders the light's plateaus over the receiver plane, then writes them into its LI layer
  /// at the pixels on the plane; returns the plateau triangles drawn.
  vtkIdType Draw(ShadowFrame& frame, const ShadowLight& light);
  /// Makes the plateau triangles of `casters`' silhouettes for the light over `plane`.
  void BuildTriangles(
    const ShadowLight& light, const ReceiverPlane& plane, const std::vector<CasterCache*>& casters);
  /// Fits the texture's extent (Lo, Hi) to the triangles, within the plane's bounds if it has any.
  void FitTextureExtent();
  /// Puts the framebuffer in `window`'s context, and allocates the plateau texture where it is
  /// not one of the resolution's there (a texture allocated anew is not current).
  void ReadyTexture(vtkOpenGLRenderWindow* window);
  /// Draws the current plateau triangles into the plateau texture over [lo, lo + size].
  bool RenderTexture(ShadowFrame& frame, const glm::dvec2& lo, const glm::dvec2& size);
  /// Writes the plateau texture over [lo, lo + size] into the light's LI layer at the pixels on
  /// `plane`; false when its shader did not build.
  bool ResolveIntoLayer(
    ShadowFrame& frame, const ReceiverPlane& plane, const glm::dvec2& lo, const glm::dvec2& size);

  bool HavePlane = false;
  ReceiverPlane Plane;
  vtkProp* PlaneProp = nullptr; ///< the marked actor, if the plane is one
  bool Bounded = false;         ///< the plane is an actor: plane coordinates bounds
  glm::dvec2 Min{ 0.0 }, Max{ 0.0 };
  double Tolerance = 0.0; ///< distance still counted as on the plane
  /// The actor whose plane was last fitted, and when: refitted only when it, its mapper or its
  /// data change.
  vtkProp* FittedProp = nullptr;
  vtkMTimeType FittedAt = 0;
  PropWarnings WarnedProps;
  bool WarnedNoPlane = false;
  std::vector<PlateauVertex> Triangles;
  /// What the triangles and the texture were made from (light, plane, casters' silhouettes and
  /// matrices): while it holds, an orbiting camera redraws neither.
  std::vector<double> Signature;
  glm::dvec2 Lo{ 0.0 }, Hi{ 0.0 };
  bool TextureCurrent = false;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer =
    vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  vtkNew<vtkTextureObject> Depth;
  vtkNew<vtkOpenGLBufferObject> Vertices;
  vtkNew<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* VAOProgram = nullptr;
  FullScreenTriangle::VAO ResolveVAO;
};

} // namespace penumbra

#endif
