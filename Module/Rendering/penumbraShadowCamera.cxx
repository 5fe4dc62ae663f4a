#include "penumbraShadowCamera.h"

#include "penumbraCulling.h"
#include "penumbraMatrices.h"

#include "vtkRenderer.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstring>

namespace penumbra
{

vtkOpenGLCamera* ShadowCamera::Update(
  vtkRenderer* renderer, const Box& scene, const std::vector<Box>& props, bool tight)
{
  auto* active = static_cast<vtkOpenGLCamera*>(renderer->GetActiveCamera());
  this->Current = active;
  // An explicit projection sets its own depth range, and VTK 9.1's DeepCopy drops it.
  if (!tight || !scene.Valid || active->GetUseExplicitProjectionTransformMatrix())
  {
    return active;
  }
  const glm::dvec2 own = glm::make_vec2(active->GetClippingRange());
  const glm::dvec2 range = TightClippingRange(props, ToGlm(active->GetViewTransformMatrix()),
    ToGlm(active->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1)),
    own);
  if (range == own)
  {
    return active;
  }
  // Of the active camera's own class: a subclass may compute its matrices its own way.
  if (!this->Copy || std::strcmp(this->Copy->GetClassName(), active->GetClassName()) != 0)
  {
    this->Copy.TakeReference(active->NewInstance());
    this->CopiedWorldToClip = glm::dmat4(0.0);
  }
  // Copied every frame and compared by value: vtkCamera::DeepCopy into the user's camera
  // changes its view without changing its time.
  this->Copy->DeepCopy(active);
  this->Copy->SetClippingRange(range.x, range.y);
  const glm::dmat4 worldToClip = ToGlm(
    this->Copy->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
  if (worldToClip != this->CopiedWorldToClip)
  {
    this->Copy->Modified(); // DeepCopy does not, and its key matrices are cached by time
    this->CopiedWorldToClip = worldToClip;
  }
  this->Current = this->Copy;
  return this->Current;
}

ScopedActiveCamera::ScopedActiveCamera(vtkRenderer* renderer, vtkCamera* camera)
  : Renderer(renderer)
  , Saved(renderer->GetActiveCamera())
{
  if (this->Saved == camera)
  {
    this->Saved = nullptr;
    return;
  }
  this->Renderer->SetActiveCamera(camera);
}

ScopedActiveCamera::~ScopedActiveCamera()
{
  if (this->Saved)
  {
    this->Renderer->SetActiveCamera(this->Saved);
  }
}

} // namespace penumbra
