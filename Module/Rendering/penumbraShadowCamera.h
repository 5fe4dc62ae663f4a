/**
 * @file   penumbraShadowCamera.h
 * @brief  The camera vtkSoftShadowPass draws its depth, volumes and wedges with.
 *
 * With the tight depth range, that is a copy of the renderer's active camera whose clipping
 * range is narrowed to the depths of the visible props' parts in view
 * (penumbra::TightClippingRange); without it, for an explicit projection matrix, or where
 * narrowing changes nothing, the active camera itself. The user's
 * camera is never modified: camera observers and pipelines that depend on the camera's time
 * (vtkDepthSortPolyData) see nothing of the shadows, and a still scene stays still. The copy is
 * modified only when its view or projection changed.
 *
 * The props VTK draws into the shadows' depth read the renderer's active camera, so the copy is
 * made the active camera while they draw (ScopedActiveCamera), as vtkShadowMapBakerPass does
 * with its light cameras: that modifies the renderer, on frames whose depth VTK draws, and
 * fires its ActiveCameraEvent.
 */
#ifndef penumbraShadowCamera_h
#define penumbraShadowCamera_h

#include "vtkOpenGLCamera.h"
#include "vtkSmartPointer.h"

#include "penumbraConvexClip.h"

#include <glm/glm.hpp>

#include <vector>

class vtkRenderer;

namespace penumbra
{

class ShadowCamera
{
public:
  /// Follows `renderer`'s active camera; with `tight` and a valid `scene` (the box of every
  /// visible prop), narrows its copy's range to what the view holds of the props' boxes.
  vtkOpenGLCamera* Update(
    vtkRenderer* renderer, const Box& scene, const std::vector<Box>& props, bool tight);
  /// The camera of the last Update.
  vtkOpenGLCamera* Get() const { return this->Current; }

private:
  vtkSmartPointer<vtkOpenGLCamera> Copy;
  vtkOpenGLCamera* Current = nullptr;
  // The copy's last world-to-clip matrix: it is modified only when that changed, so that
  // pipelines reading the active camera during the depth pass do not run again on every drawn
  // frame.
  glm::dmat4 CopiedWorldToClip{ 0.0 };
};

/// Makes `camera` the renderer's active camera while it lives (VTK's props read the active
/// camera), and the camera that was active again after; nothing when it already is.
class ScopedActiveCamera
{
public:
  ScopedActiveCamera(vtkRenderer* renderer, vtkCamera* camera);
  ~ScopedActiveCamera();
  ScopedActiveCamera(const ScopedActiveCamera&) = delete;
  ScopedActiveCamera& operator=(const ScopedActiveCamera&) = delete;

private:
  vtkRenderer* Renderer;
  vtkSmartPointer<vtkCamera> Saved;
};

} // namespace penumbra

#endif
