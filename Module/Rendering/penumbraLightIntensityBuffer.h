/**
 * @file    penumbraLightIntensityBuffer.h
 * @brief   The light-intensity (LI) buffer: one R32F layer per shadowing light, the framebuffer
 *          they are drawn through with its depth-stencil attachment, a copy of that depth
 *          for the shaders that read the scene's depth while testing against it, and the
 *          visible triangles' planes where the pass drew the depth from caster meshes.
 *
 * VTK 9.1's window has no stencil, and vtkOpenGLFramebufferObject attaches depth without
 * stencil and ignores a new slice of an attached texture: this class attaches both itself.
 */
#ifndef penumbraLightIntensityBuffer_h
#define penumbraLightIntensityBuffer_h

#include "penumbraLayeredTexture.h" // for vtkNew<vtkPenumbraLayeredTexture>

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h" // for vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for vtkNew

#include <cstddef>

class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkWindow;

namespace penumbra
{

class LightIntensityBuffer
{
public:
  /// Sizes the buffer for a viewport of width x height and `layers` lights, reallocating only
  /// what changed. False, with nothing held, when OpenGL refuses the layers (GL_OUT_OF_MEMORY:
  /// on llvmpipe a texture of about 1.7 GB, an 8K frame's 14 lights); a size refused is not
  /// tried again until the buffer is released.
  bool Prepare(vtkOpenGLRenderWindow* window, int width, int height, int layers);
  /// Bytes the layers of Prepare's arguments take.
  static std::size_t LayerBytes(int width, int height, int layers);
  /// Binds the framebuffer with the depth-stencil attachment and `layer` as colour.
  void BindLayer(int layer);
  /// Makes `texture` (layer `layer` of a vtkPenumbraLayeredTexture, or a 2D texture) colour
  /// attachment 0 and the draw buffer; the framebuffer must be bound.
  void AttachColour(vtkTextureObject* texture, int layer);
  /// Copies the depth attachment into DepthCopy.
  void CopyDepth(vtkOpenGLState* ostate);
  /// Makes `depth` (a depth texture of the buffer's size) the framebuffer's depth attachment in
  /// place of the depth-stencil, which nullptr attaches again; the framebuffer must be bound.
  void AttachDepth(vtkTextureObject* depth);
  /// Makes the surface planes (an RGBA32F texture of the buffer's size, allocated on first use)
  /// colour attachment 0 and the draw buffer, cleared to NoSurfacePlane; the framebuffer must
  /// be bound. The caster meshes' depth shader writes there each fragment's triangle plane, its
  /// unit normal in world space and its offset about ShadowFrame::SurfacePlanesOrigin, which
  /// counting's point (penumbra::CountingPointDepth) and own-surface test
  /// (penumbra::SeesAboveSurface) read. False, with nothing attached, where OpenGL refuses it.
  bool AttachClearedSurfacePlanes(vtkOpenGLRenderWindow* window);
  /// Releases the surface planes, where no light asks for them.
  void ReleaseSurfacePlanes(vtkWindow* window);
  /// The planes' first channel where no caster mesh drew the visible surface (VTK did, or
  /// nothing): outside a unit normal's [-1, 1].
  static constexpr float NoSurfacePlane = 3.0e38f;

  vtkOpenGLFramebufferObject* GetFramebuffer() { return this->Framebuffer; }
  /// The LI layers (a 2D array texture, one layer per light), for the receivers to sample.
  vtkTextureObject* GetLayers() { return this->Layers; }
  vtkTextureObject* GetDepthCopy() { return this->DepthCopy; }
  /// The surface planes, or nullptr before AttachClearedSurfacePlanes first allocated them.
  vtkTextureObject* GetSurfacePlanes();
  int GetLayerCount() const { return this->LayerCount; }

  /// Bytes held: 4 per texel of the depth-stencil, its copy and every layer, and 16 per texel
  /// of the surface planes where they were allocated.
  std::size_t GraphicsMemoryBytes() const;
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer =
    vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  vtkNew<vtkTextureObject> DepthStencil;
  vtkNew<vtkTextureObject> DepthCopy;
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthCopyFramebuffer =
    vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  vtkNew<vtkPenumbraLayeredTexture> Layers;
  vtkNew<vtkTextureObject> SurfacePlanes;
  int Width = 0, Height = 0, LayerCount = 0;
  /// The smallest layers' size OpenGL refused (0: none).
  std::size_t RefusedBytes = 0;
};

} // namespace penumbra

#endif
