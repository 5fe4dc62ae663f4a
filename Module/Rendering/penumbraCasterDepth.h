/**
 * @file    penumbraCasterDepth.h
 * @brief   The pass's depth of opaque casters, drawn from their cached meshes where that is the
 *          depth VTK would draw.
 *
 * Shadows are counted against the depth of everything VTK draws opaque, so the pass draws that
 * depth before anything else. Drawn by VTK, each prop runs its full shaders (normals, colours,
 * the light loop) and VTK's per-prop set-up, although only the depth is kept. A prop that VTK
 * draws as nothing but its polydata's triangles has the same triangles in its caster's cached
 * mesh (penumbra::CasterTopology: welded, degenerate ones dropped, polygons cut as VTK's fan
 * cuts them): drawn from there, its depth needs a position-only shader and one draw call (which
 * also writes each visible triangle's plane while a light is counted). A
 * composite mapper's blocks are drawn the same way, one mesh each: VTK draws them from one vertex
 * buffer shifted to the data's centre, so that a block far from it gets coarse depth.
 * Everything else (other mappers, clipping planes, lines and points, custom shaders, a
 * concave polygon) is left to VTK's opaque pass. A polygon offset or z-shift is not drawn
 * (nor by VTK in the pass's depth pass, for receivers: KeepOffsetOutOfDepthPass): it moves a
 * surface's depth, not its points, and the shadows are counted at the points. A closed caster
 * seen from outside only is drawn with the faces turned away from the eye culled: they are
 * hidden behind its own.
 */
#ifndef penumbraCasterDepth_h
#define penumbraCasterDepth_h

#include "vtkType.h"

#include <vector>

class vtkProp;
class vtkShaderProgram;

namespace penumbra
{

struct CasterCache;
struct ShadowFrame;

/// The faces of `caster` hidden behind its own from the eye, which its depth may cull: GL_BACK
/// (or GL_FRONT where a mirroring matrix or an inward winding turns them) for a closed mesh whose
/// pieces all wind one way (CasterTopology::OutwardWinding) and whose box lies wholly beyond the
/// near plane; 0 otherwise (the near plane cuts it, or the eye is inside its box).
unsigned int HiddenFace(const ShadowFrame& frame, CasterCache& caster);

class CasterDepth
{
public:
  /// Whether VTK's opaque pass draws `prop` as the triangles of its mapper's vtkPolyData, or of
  /// its composite data's polydata blocks, and nothing else: a vtkOpenGLActor (not a subclass:
  /// LOD actors and followers draw otherwise) with a vtkOpenGLPolyDataMapper or a
  /// vtkCompositePolyDataMapper2, opaque (every drawn block), neither forced so nor textured with
  /// alpha (VTK drops fragments of alpha 0 then too), a surface (edges drawn on it included:
  /// VTK widens its triangles for them, a band the pass's depth leaves out,
  /// KeepEdgesOutOfDepthPass) without vertices or culled faces, no clipping plane, no custom
  /// shader code (a polygon offset or z-shift is left out of the pass's depth), and
  /// data with no vertex or line cells and no ghost cells. Read before VTK draws the frame's
  /// other props.
  static bool DrawnAsItsTriangles(vtkProp* prop);

  /// Chooses which of `props` (all DrawnAsItsTriangles) Draw draws: each whose caster among
  /// frame.Casters is opaque and cut as VTK draws it. Returns the others (a prop that casts no
  /// shadow, say), for VTK to draw before Draw: VTK writes no planes, so a surface it drew
  /// later could hide a mesh's plane under its own depth.
  std::vector<vtkProp*> Select(const ShadowFrame& frame, const std::vector<vtkProp*>& props);
  /// Whether Select chose any prop.
  bool HasSelected() const { return !this->Selected.empty(); }
  /// Draws into the bound depth buffer the depth of the props Select chose, with the caller's
  /// depth state, and with `writePlanes` each fragment's triangle plane into colour
  /// attachment 0 (LightIntensityBuffer::AttachClearedSurfacePlanes). Returns the props it could
  /// not draw (all of them where its shader does not build), for VTK to draw.
  std::vector<vtkProp*> Draw(const ShadowFrame& frame, bool writePlanes);
  /// Props the last Draw drew with the hidden faces of their mesh, or of some of their blocks,
  /// culled: closed casters whose pieces all wind one way (CasterTopology::OutwardWinding),
  /// wholly beyond the near plane.
  vtkIdType GetCulledProps() const { return this->CulledProps; }

private:
  /// Draws one caster's mesh; returns whether its hidden faces were culled.
  bool DrawCaster(const ShadowFrame& frame, CasterCache& caster);

  struct SelectedProp
  {
    vtkProp* Prop;
    std::vector<CasterCache*> Casters; ///< its surfaces: one, or a composite mapper's blocks
  };
  std::vector<SelectedProp> Selected;
  vtkShaderProgram* Program = nullptr;
  vtkIdType CulledProps = 0;
};

} // namespace penumbra

#endif
