#include "penumbraCasterDepth.h"

#include "penumbraCulling.h"
#include "penumbraSceneWalk.h"
#include "penumbraShadowCaches.h"
#include "penumbraShadowTechnique.h"

#include "penumbraCasterDepthFS.h"
#include "penumbraCasterDepthVS.h"

#include "vtkActor.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <unordered_map>

namespace penumbra
{
namespace
{
/// Whether VTK draws nothing of `data` but its polygons' and strips' triangles.
bool OnlySurfaceCells(vtkPolyData* data)
{
  return data && data->GetNumberOfVerts() == 0 && data->GetNumberOfLines() == 0 &&
    !data->GetCellGhostArray();
}

/// The same for a composite mapper's input: every leaf at any depth, drawn or hidden, a polydata
/// of surface cells only (empty blocks draw nothing).
bool OnlySurfaceLeaves(vtkDataObject* input)
{
  auto tree = vtkDataObjectTree::SafeDownCast(input);
  if (!tree)
  {
    return OnlySurfaceCells(vtkPolyData::SafeDownCast(input));
  }
  for (vtkDataObject* leaf : vtk::Range(tree, EveryLeaf()))
  {
    if (!OnlySurfaceCells(vtkPolyData::SafeDownCast(leaf)))
    {
      return false;
    }
  }
  return true;
}
} // namespace

unsigned int HiddenFace(const ShadowFrame& frame, CasterCache& caster)
{
  const int winding = caster.Mesh->OutwardWinding();
  if (winding == 0)
  {
    return 0;
  }
  if (!BoxBeyondNearPlane(caster.WorldMin, caster.WorldMax, frame.WorldToClip))
  {
    return 0; // the near plane cuts it, or the eye is inside its box
  }
  // A camera's projection has a negative determinant: with it, counter-clockwise outward faces
  // stay counter-clockwise in the window (GL's front faces, which VTK never changes). A mirrored
  // actor or an inward winding turns them.
  const double determinant = glm::determinant(frame.WorldToClip * caster.ObjectToWorld);
  if (!std::isfinite(determinant) || determinant == 0.0)
  {
    return 0;
  }
  const bool turned = (determinant > 0.0) != (winding < 0);
  return turned ? GL_FRONT : GL_BACK;
}

bool CasterDepth::DrawnAsItsTriangles(vtkProp* prop)
{
  auto actor = vtkActor::SafeDownCast(prop);
  if (!IsExactly(actor, "vtkOpenGLActor"))
  {
    return false;
  }
  // A composite mapper draws its blocks from one vertex buffer shifted to the data's centre,
  // so that blocks far from it get coarse depth; each block's caster mesh keeps its own origin.
  vtkMapper* mapper = actor->GetMapper();
  const bool composite = IsExactly(mapper, "vtkCompositePolyDataMapper2");
  if (!composite && !IsExactly(mapper, "vtkOpenGLPolyDataMapper"))
  {
    return false;
  }
  vtkProperty* property = actor->GetProperty();
  // VTK drops fragments of alpha 0 even from an actor forced opaque, or through a texture it
  // does not count as translucent (alpha 0 and 255 only, or a property texture): holes its mesh
  // lacks.
  if (actor->GetForceOpaque() || TexturesMayOpenHoles(actor) || !actor->HasOpaqueGeometry() ||
    actor->HasTranslucentPolygonalGeometry() || property->GetRepresentation() != VTK_SURFACE ||
    property->GetVertexVisibility() || property->GetBackfaceCulling() ||
    property->GetFrontfaceCulling() || mapper->GetNumberOfClippingPlanes() > 0 ||
    HasCustomShaders(actor))
  {
    return false;
  }
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  return composite ? OnlySurfaceLeaves(input) : OnlySurfaceCells(vtkPolyData::SafeDownCast(input));
}

std::vector<vtkProp*> CasterDepth::Select(
  const ShadowFrame& frame, const std::vector<vtkProp*>& props)
{
  this->Selected.clear();
  std::vector<vtkProp*> left;
  // Each prop's surfaces: a plain actor's one, a composite mapper's drawn blocks. A prop is
  // ours to draw only if every one of them is opaque and cut as VTK cuts it.
  struct PropCasters
  {
    std::vector<CasterCache*> Casters;
    bool Usable = true;
  };
  std::unordered_map<vtkProp*, PropCasters> casters;
  for (CasterCache* caster : *frame.Casters)
  {
    PropCasters& prop = casters[caster->Actor.GetPointer()];
    prop.Casters.push_back(caster);
    prop.Usable = prop.Usable && !caster->Translucent() && !caster->SeenThrough &&
      caster->Mesh->Topology.Report.PolygonsCutUnlikeVTK == 0;
  }
  for (vtkProp* prop : props)
  {
    auto found = casters.find(prop);
    if (found == casters.end() || !found->second.Usable)
    {
      left.push_back(prop);
    }
    else
    {
      this->Selected.push_back({ prop, std::move(found->second.Casters) });
    }
  }
  return left;
}

std::vector<vtkProp*> CasterDepth::Draw(const ShadowFrame& frame, bool writePlanes)
{
  this->CulledProps = 0;
  std::vector<vtkProp*> left;
  if (this->Selected.empty())
  {
    return left;
  }
  this->Program = frame.Programs->Ready(frame.Window, penumbraCasterDepthVS, penumbraCasterDepthFS,
    "caster-depth", "VTK draws the casters' depth");
  if (!this->Program)
  {
    for (const SelectedProp& selected : this->Selected)
    {
      left.push_back(selected.Prop);
    }
    return left;
  }
  this->Program->SetUniformi("writePlanes", writePlanes ? 1 : 0);
  for (const SelectedProp& selected : this->Selected)
  {
    bool culled = false;
    for (CasterCache* caster : selected.Casters)
    {
      culled = this->DrawCaster(frame, *caster) || culled;
    }
    this->CulledProps += culled ? 1 : 0;
  }
  return left;
}

bool CasterDepth::DrawCaster(const ShadowFrame& frame, CasterCache& caster)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  const unsigned int hidden = HiddenFace(frame, caster);
  if (hidden)
  {
    ostate->vtkglEnable(GL_CULL_FACE);
    ostate->vtkglCullFace(hidden);
  }
  else
  {
    ostate->vtkglDisable(GL_CULL_FACE);
  }
  const glm::mat4 objectToClip(frame.WorldToClip * caster.ObjectToWorld);
  this->Program->SetUniformMatrix4x4(
    "MCDCMatrix", const_cast<float*>(glm::value_ptr(objectToClip)));
  const glm::mat3 normalToWorld(glm::transpose(glm::inverse(glm::dmat3(caster.ObjectToWorld))));
  this->Program->SetUniformMatrix3x3(
    "normalToWorld", const_cast<float*>(glm::value_ptr(normalToWorld)));
  // The planes' offsets about an origin near the eye, summed in double: small where the
  // counting point's view rays need them precise.
  const glm::mat4 positionToOrigin(
    glm::translate(glm::dmat4(1.0), -frame.SurfacePlanesOrigin) * caster.ObjectToWorld);
  this->Program->SetUniformMatrix4x4(
    "positionToOrigin", const_cast<float*>(glm::value_ptr(positionToOrigin)));
  caster.Mesh->Bind(this->Program);
  caster.Mesh->BindTriangles();
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(3 * caster.Mesh->Topology.Triangles.size()),
    GL_UNSIGNED_INT, nullptr);
  caster.Mesh->TriangleIndices->Release();
  caster.Mesh->VAO->Release();
  return hidden != 0;
}

} // namespace penumbra
