#include "penumbraPlateauTechnique.h"

#include "penumbraMatrices.h"
#include "vtkSoftShadowPass.h"

#include "vtkActor.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include "penumbraPlateauFS.h"
#include "penumbraPlateauResolveFS.h"
#include "penumbraPlateauVS.h"
#include "penumbraResolveVS.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

namespace penumbra
{

namespace
{
/// `plane`, or the same plane turned over, so that it faces the light whichever way its polygons
/// wind.
ReceiverPlane FacingLight(ReceiverPlane plane, const glm::dvec4& light)
{
  const double lightSide =
    light.w != 0.0 ? plane.Height(glm::dvec3(light)) : glm::dot(plane.Normal, glm::dvec3(light));
  if (lightSide < 0.0)
  {
    ReceiverPlane::Make(plane.Origin, -plane.Normal, plane);
  }
  return plane;
}

/// The casters whose plateaus fall on the plane: those not culled for the light, the plane's own
/// actor left out.
std::vector<CasterCache*> PlateauCasters(
  const ShadowFrame& frame, const ShadowLight& light, const vtkProp* planeProp)
{
  std::vector<CasterCache*> casters;
  for (CasterCache* caster : *frame.Casters)
  {
    if (!caster->Culled.count(light.Light) && caster->Actor != planeProp)
    {
      casters.push_back(caster);
    }
  }
  return casters;
}

/// What the plateau triangles and texture are made from (PlateauTechnique::Signature): the
/// light, the plane, the texture's resolution and each caster's silhouette and matrix.
std::vector<double> PlateauSignature(const ShadowLight& light, const ReceiverPlane& plane,
  int resolution, const std::vector<CasterCache*>& casters)
{
  std::vector<double> signature = { light.World.x, light.World.y, light.World.z, light.World.w,
    light.SoftRadius, plane.Origin.x, plane.Origin.y, plane.Origin.z, plane.Normal.x,
    plane.Normal.y, plane.Normal.z, static_cast<double>(resolution) };
  for (CasterCache* caster : casters)
  {
    signature.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(caster)));
    signature.push_back(static_cast<double>(caster->Volumes[light.VolumeKey(0)].Generation));
    const double* m = glm::value_ptr(caster->ObjectToWorld);
    signature.insert(signature.end(), m, m + 16);
  }
  return signature;
}
} // namespace

bool PlateauTechnique::FindReceiverPlane(vtkRenderer* renderer, vtkObject* owner)
{
  this->HavePlane = this->Bounded = false;
  this->PlaneProp = nullptr;
  if (this->Settings.UseGivenPlane)
  {
    // Plateau coordinates are floats on the plane: take its origin next to the scene.
    double bounds[6];
    renderer->ComputeVisiblePropBounds(bounds);
    const glm::dvec3 centre = vtkMath::AreBoundsInitialized(bounds)
      ? glm::dvec3(bounds[0] + bounds[1], bounds[2] + bounds[3], bounds[4] + bounds[5]) * 0.5
      : this->Settings.Origin;
    this->HavePlane =
      ReceiverPlane::MakeNear(this->Settings.Origin, this->Settings.Normal, centre, this->Plane);
    if (!this->HavePlane && !this->WarnedNoPlane)
    {
      vtkWarningWithObjectMacro(
        owner, "The receiver plane's normal is zero, or its normal or origin is not finite.");
    }
    this->Tolerance = 0.0; // set from the plateaus' extent when they are drawn
    return this->HavePlane;
  }
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  vtkProp* prop;
  for (props->InitTraversal(it); (prop = props->GetNextProp(it));)
  {
    auto actor = vtkActor::SafeDownCast(prop);
    if (!actor || !actor->GetVisibility() || !vtkSoftShadowPass::GetShadowPlane(actor) ||
      !actor->GetMapper())
    {
      continue;
    }
    auto data = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0));
    // The actor (matrix), its mapper (a new input) or the data itself.
    const vtkMTimeType changed =
      std::max({ actor->GetMTime(), actor->GetMapper()->GetMTime(), data ? data->GetMTime() : 0 });
    if (actor == this->FittedProp && changed <= this->FittedAt)
    {
      this->HavePlane = this->Bounded = true; // the fit below, kept from an earlier frame
      this->PlaneProp = actor;
      return true;
    }
    vtkPoints* points = data ? data->GetPoints() : nullptr;
    std::vector<glm::dvec3> world;
    const glm::dmat4 toWorld = ToGlm(actor->GetMatrix());
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
    {
      world.emplace_back(toWorld * glm::dvec4(glm::make_vec3(points->GetPoint(i)), 1.0));
    }
    PlaneFit fit;
    if (!FitReceiverPlane(world, fit))
    {
      if (this->WarnedProps.First(actor, "plane"))
      {
        vtkWarningWithObjectMacro(
          owner, "Shadow plane " << actor << " has no flat surface: it is not used.");
      }
      continue;
    }
    if (fit.Thickness > 1e-6 * fit.Extent && this->WarnedProps.First(actor, "plane"))
    {
      vtkWarningWithObjectMacro(owner,
        "Shadow plane " << actor << " is not flat (points up to " << fit.Thickness
                        << " off its plane): plateaus use its best plane.");
    }
    this->HavePlane = this->Bounded = true;
    this->Plane = fit.Plane;
    this->PlaneProp = this->FittedProp = actor;
    this->FittedAt = changed;
    this->Min = fit.Min;
    this->Max = fit.Max;
    this->Tolerance = std::max(1e-5 * fit.Extent, 2.0 * fit.Thickness);
    return true;
  }
  return false;
}

bool PlateauTechnique::RenderTexture(
  ShadowFrame& frame, const glm::dvec2& lo, const glm::dvec2& size)
{
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkShaderProgram* program = frame.Programs->Ready(
    window, penumbraPlateauVS, penumbraPlateauFS, "plateau", "plateaus are left out");
  if (!program)
  {
    return false;
  }
  const int resolution = this->Settings.Resolution;
  vtkOpenGLState* ostate = window->GetState();
  ScopedDrawState saved(ostate);
  // The plateau texture: seen down the normal, the smallest depth (darkest) wins.
  ScopedFramebufferBindings bindings(ostate);
  this->Framebuffer->Bind();
  this->Framebuffer->AddDepthAttachment(this->Depth);
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
  this->Vertices->Upload(this->Triangles, vtkOpenGLBufferObject::ArrayBuffer);
  static_assert(sizeof(PlateauVertex) == 3 * sizeof(float), "packed plateau vertices");
  BindVertexArray(
    this->VAO, program, this->VAOProgram, this->Vertices, { { "plateauVertex", 0, 3 } });
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(this->Triangles.size()));
  this->VAO->Release();

  this->TextureCurrent = true;
  return true;
}

vtkIdType PlateauTechnique::Draw(ShadowFrame& frame, const ShadowLight& light)
{
  const ReceiverPlane plane = FacingLight(this->Plane, light.World);
  const std::vector<CasterCache*> casters = PlateauCasters(frame, light, this->PlaneProp);
  const std::vector<double> signature =
    PlateauSignature(light, plane, this->Settings.Resolution, casters);
  if (signature != this->Signature)
  {
    this->Signature = signature;
    this->TextureCurrent = false;
    this->BuildTriangles(light, plane, casters);
    this->FitTextureExtent();
  }
  const glm::dvec2 lo = this->Lo, size = this->Hi - this->Lo;
  if (this->Triangles.empty() || !(size.x > 0.0) || !(size.y > 0.0))
  {
    return 0;
  }
  this->ReadyTexture(frame.Window);
  if (!this->TextureCurrent && !this->RenderTexture(frame, lo, size))
  {
    return 0;
  }
  if (!this->ResolveIntoLayer(frame, plane, lo, size))
  {
    return 0;
  }
  return static_cast<vtkIdType>(this->Triangles.size() / 3);
}

void PlateauTechnique::BuildTriangles(
  const ShadowLight& light, const ReceiverPlane& plane, const std::vector<CasterCache*>& casters)
{
  this->Triangles.clear();
  for (CasterCache* caster : casters)
  {
    VolumeCache& volume = caster->Volumes[light.VolumeKey(0)];
    volume.EnsureCaps(*caster->Mesh);
    BuildPlateaus(caster->Mesh->Topology, volume.Volume, caster->ObjectToWorld, light.World,
      light.SoftRadius, plane, this->Triangles);
  }
}

void PlateauTechnique::FitTextureExtent()
{
  // The texture covers the plateaus, within the receiver's extent when it has one.
  this->Lo = glm::dvec2(std::numeric_limits<double>::max());
  this->Hi = -this->Lo;
  for (const PlateauVertex& v : this->Triangles)
  {
    this->Lo = glm::min(this->Lo, glm::dvec2(v.U, v.V));
    this->Hi = glm::max(this->Hi, glm::dvec2(v.U, v.V));
  }
  if (this->Bounded)
  {
    this->Lo = glm::max(this->Lo, this->Min);
    this->Hi = glm::min(this->Hi, this->Max);
  }
}

void PlateauTechnique::ReadyTexture(vtkOpenGLRenderWindow* window)
{
  if (this->Framebuffer->GetContext() != window)
  {
    this->Framebuffer->SetContext(window);
  }
  // Filtered lookups smooth the texels' steps; the depth is t itself, not compared.
  const int resolution = this->Settings.Resolution;
  if (TextureNeedsAllocation(
        this->Depth, window, resolution, resolution, 1, 1, vtkTextureObject::Linear))
  {
    this->Depth->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Depth->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Depth->AllocateDepth(resolution, resolution, vtkTextureObject::Float32);
    this->TextureCurrent = false;
  }
}

bool PlateauTechnique::ResolveIntoLayer(
  ShadowFrame& frame, const ReceiverPlane& plane, const glm::dvec2& lo, const glm::dvec2& size)
{
  // Into the LI layer, at the pixels on the plane (the hard shadow stays elsewhere).
  vtkOpenGLRenderWindow* window = frame.Window;
  vtkShaderProgram* resolve = frame.Programs->Ready(window, penumbraResolveVS,
    penumbraPlateauResolveFS, "plateau resolve", "plateaus are left out");
  if (!resolve)
  {
    return false;
  }
  vtkOpenGLState* ostate = window->GetState();
  ScopedDrawState saved(ostate);
  ostate->vtkglViewport(0, 0, frame.Size[0], frame.Size[1]);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_STENCIL_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  frame.DepthCopy()->Activate();
  this->Depth->Activate();
  const float planeToTexture[4] = { static_cast<float>(1.0 / size.x),
    static_cast<float>(1.0 / size.y), static_cast<float>(-lo.x / size.x),
    static_cast<float>(-lo.y / size.y) };
  const glm::vec3 normal(plane.Normal), u(plane.U), v(plane.V);
  const double tolerance = this->Bounded ? this->Tolerance : 1e-5 * glm::length(size);
  frame.SetDepthUniforms(resolve);
  resolve->SetUniformi("plateauTexture", this->Depth->GetTextureUnit());
  frame.SetClipToLocal(resolve, plane.Origin);
  resolve->SetUniform3f("planeNormal", glm::value_ptr(normal));
  resolve->SetUniform3f("planeU", glm::value_ptr(u));
  resolve->SetUniform3f("planeV", glm::value_ptr(v));
  resolve->SetUniform4f("planeToTexture", planeToTexture);
  resolve->SetUniformf("planeTolerance", static_cast<float>(tolerance));
  resolve->SetUniformi("sinusoidal", this->Settings.Falloff == PlateauFalloff::Sinusoidal);
  frame.FullScreen->Draw(resolve, this->ResolveVAO);
  this->Depth->Deactivate();
  frame.DepthCopy()->Deactivate();
  return true;
}

void PlateauTechnique::WarnNoPlane(vtkObject* owner)
{
  if (!this->WarnedNoPlane)
  {
    vtkWarningWithObjectMacro(owner,
      "METHOD_PLATEAUS needs a receiver plane (SetShadowPlane on a flat actor, "
      "or UseReceiverPlaneOn): hard shadows instead.");
    this->WarnedNoPlane = true;
  }
}

void PlateauTechnique::Finish(ShadowFrame& frame, const ShadowLight& light)
{
  frame.Counts.PlateauTriangles += this->Draw(frame, light);
}

std::size_t PlateauTechnique::GraphicsMemoryBytes() const
{
  const std::size_t buffer =
    this->Vertices->GetHandle() ? this->Triangles.size() * sizeof(PlateauVertex) : 0;
  return TextureBytes(this->Depth) + buffer + this->HardShadowTechnique::GraphicsMemoryBytes();
}

void PlateauTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->HardShadowTechnique::ReleaseGraphicsResources(window);
  ReleaseFramebuffer(this->Framebuffer, window);
  this->Depth->ReleaseGraphicsResources(window);
  this->Vertices->ReleaseGraphicsResources();
  this->VAO->ReleaseGraphicsResources();
  this->VAOProgram = nullptr;
  this->ResolveVAO.ReleaseGraphicsResources();
  this->TextureCurrent = false;
  this->Signature.clear();
  this->FittedProp = nullptr;
}

} // namespace penumbra
