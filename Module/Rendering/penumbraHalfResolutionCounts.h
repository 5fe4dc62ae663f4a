/**
 * @file    penumbraHalfResolutionCounts.h
 * @brief   Soft shadow volumes counted at half the window's resolution in each direction
 *          (vtkSoftShadowPass::HalfResolutionCounting), then brought up to every pixel.
 *
 * Counting's cost on the GPU is its wedge fragments (Documentation/wedges.md); at half
 * resolution there are a quarter as many. Counter texel t counts the pixel 2t exactly: the
 * wedges' clip space is shifted so that t's centre falls on that pixel's centre, and their depth
 * test runs against that pixel's depth. A pixel between takes the mean of its counted
 * neighbours where they nearly agree and its depth lies between theirs
 * (penumbraHalfUpsampleFS.glsl); the rest, at shadow edges, creases, depth discontinuities and
 * beside the background, are
 * counted again at full resolution with the stencil test rejecting every other pixel, which
 * costs a fraction of starting the counting shader there.
 */
#ifndef penumbraHalfResolutionCounts_h
#define penumbraHalfResolutionCounts_h

#include "penumbraOpenGLHelpers.h"

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h" // for vtkSmartPointer<vtkOpenGLFramebufferObject>
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for vtkNew<vtkTextureObject>

#include <glm/glm.hpp>

#include <cstddef>

class vtkShaderProgram;
class vtkWindow;

namespace penumbra
{

struct ShadowFrame;

class HalfResolutionCounts
{
public:
  /// The LI framebuffer's stencil values that Upsample leaves at the geometry's pixels: certain
  /// or uncertain (ClassStencilBits); the second count marks the uncertain pixels that a wedge
  /// reached with ReachedStencil, for the resolve to read their counters only there, as the full
  /// count does.
  static constexpr int UncertainStencil = 1;
  static constexpr int CertainStencil = 2;
  static constexpr int ClassStencilBits = UncertainStencil | CertainStencil;
  static constexpr int ReachedStencil = 4;
  /// Counter texels for a viewport of `size` pixels: every other pixel, the last one included.
  static glm::ivec2 CounterSize(const int size[2]);
  /// The clip-space scale (xy) and offset (zw) that put counter texel t's centre on pixel 2t's
  /// centre for a viewport of `size` pixels drawn into CounterSize(size) texels.
  static glm::vec4 ClipToCounters(const int size[2]);

  /// Binds the half-resolution framebuffer with its own depth (each counted pixel's, from the
  /// frame's depth copy), and sets the viewport to it. False, reported once, when one of its
  /// shaders does not build: the caller counts at full resolution instead.
  bool Begin(ShadowFrame& frame);
  /// Makes the counted pixels' visibility (R32F) the colour target of the bound framebuffer.
  void AttachVisibility();
  /// Writes every geometry pixel's visibility into `layer` of the frame's LI layers: the counted
  /// pixels' own, and between them the mean of their counted neighbours. Where that mean is
  /// uncertain (neighbours more than `uncertain` apart, or across a crease or a depth
  /// discontinuity; penumbraHalfUpsampleFS.glsl) the LI framebuffer's stencil is set to
  /// UncertainStencil, for the caller to count those pixels at full resolution; also where the
  /// light's centre is hidden from the pixel and seen from a counted neighbour or the other way
  /// round (`centreCount`, every pixel's count of its shadow volumes, is 0 at one of them). The LI
  /// framebuffer and the full viewport are bound on return.
  bool Upsample(ShadowFrame& frame, int layer, float uncertain, vtkTextureObject* centreCount);

  /// Bytes held: 4 per counter texel each for the depth-stencil and the visibility.
  std::size_t GraphicsMemoryBytes() const;
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer =
    vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  vtkNew<vtkTextureObject> DepthStencil;
  vtkNew<vtkTextureObject> Visibility;
  void SetUniforms(
    ShadowFrame& frame, vtkShaderProgram* program, float uncertain, vtkTextureObject* centreCount);
  /// Readies the three shaders from the window's shader cache (which compiles each once), as
  /// every technique does before it draws; after one failed to build, never again until
  /// ReleaseGraphicsResources.
  bool ReadyPrograms(ShadowFrame& frame);
  vtkShaderProgram* DepthProgram = nullptr;
  vtkShaderProgram* UpsampleProgram = nullptr;
  vtkShaderProgram* MarkProgram = nullptr;
  bool ProgramsFailed = false;

  FullScreenTriangle::VAO DepthVAO, UpsampleVAO, MarkVAO;
  glm::ivec2 Size{ 0, 0 };
};

} // namespace penumbra

#endif
