/**
 * @file   penumbraSceneWalk.h
 * @brief  What a renderer draws, as surfaces in world space with their opacity: the casters
 *         of vtkSoftShadowPass.
 *
 * VTK draws far more than top-level actors with a polydata mapper: assembly paths with their
 * composed matrices, the leaves of composite data with their block visibility and opacity, the
 * instances of a vtkGlyph3DMapper, the spheres of a vtkOpenGLSphereMapper and the sticks of a
 * vtkOpenGLStickMapper (particles; a vtkMoleculeMapper's atoms and bonds), cast as tessellated
 * spheres and cylinders, and the parts of vtkAxesActor and vtkAnnotatedCubeActor. The walk follows
 * what VTK draws, not what a mapper's input holds: a glyph mapper's input points (a seed plane, an
 * image's bounding box) are never drawn and never cast. A surface under its mapper's clipping
 * planes casts as cut by them (ClippedSurfaces). What VTK draws but no shadow volume can be built
 * from (point-gaussian splats, volumes, image slices, wireframes and points) gets one warning per
 * prop and reason.
 *
 * The ray tracer (vtkRayTracedVisibility) walks the scene its own way, through VTK's filters,
 * so that a mistake here shows against it.
 */
#ifndef penumbraSceneWalk_h
#define penumbraSceneWalk_h

#include "penumbraClippedSurfaces.h"
#include "penumbraPropWarnings.h"

#include "vtkDataObjectTreeRange.h"
#include "vtkSmartPointer.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

class vtkActor;
class vtkCompositeDataDisplayAttributes;
class vtkCompositePolyDataMapper2;
class vtkDataObject;
class vtkGlyph3DMapper;
class vtkLODProp3D;
class vtkMapper;
class vtkObject;
class vtkOpenGLMoleculeMapper;
class vtkOpenGLSphereMapper;
class vtkOpenGLStickMapper;
class vtkPolyData;
class vtkMatrix4x4;
class vtkProp;
class vtkRenderState;
class vtkRenderer;
class vtkTexture;

namespace penumbra
{

/// One surface VTK draws, opaque or translucent.
struct DrawnSurface
{
  vtkActor* Actor = nullptr;     ///< the actor whose mapper draws it (an assembly's part, say)
  vtkDataObject* Data = nullptr; ///< a dataset: the mapper's input, a block, a glyph's source
  glm::dmat4 ObjectToWorld{ 1.0 };
  /// Which block or glyph of Actor it is; with Actor, the surface's identity between frames.
  std::size_t Part = 0;
  /// What its shadow lets through: the block's opacity where one is set, else the property's
  /// (as vtkCompositePolyDataMapper2 replaces one by the other), in (0, 1]; 1 where VTK draws
  /// the surface opaque (ForceOpaque included).
  double Opacity = 1.0;
  /// VTK draws it in the translucent pass, so it is not in the depth pass and points behind it
  /// are seen through it (opacity 1 too, for colours with alpha or a texture).
  bool SeenThrough = false;
  /// The renderer's prop it belongs to: Actor, or the assembly or vtkAxesActor Actor is part of.
  vtkProp* ViewProp = nullptr;
};

/// The props VTK draws when it draws `prop`: `prop` itself, or, for props that draw through
/// actors of their own, those: a vtkAxesActor's shafts and tips (each at its own matrix, which
/// carries the axes' user transform) and a vtkAnnotatedCubeActor's assembly. Both place their
/// parts only when VTK draws them, so the parts are where VTK last drew them: the pass walks the
/// casters after its depth pass, in which VTK places them for the frame.
std::vector<vtkProp*> PropsDrawnFor(vtkProp* prop);

/// The mapper VTK draws `actor` with this frame: its own, but for a vtkLODActor the level
/// vtkLODActor::Render picks from the time the renderer allotted it and its mappers' last draw
/// times (a level never drawn, of time 0, is tried first), and for a vtkQuadricLODActor in an
/// interactive frame the mapper of its decimated level (once the actor has built it in a
/// draw). The renderer allots the times before the pass runs, and mappers time
/// themselves when VTK draws them.
vtkMapper* MapperDrawn(vtkActor* actor);

/// What to visit of composite data for its datasets: every leaf at any depth, none empty
/// (vtk::Range's default visits the first level only, composite children and empty ones too).
inline vtk::DataObjectTreeOptions EveryLeaf()
{
  return vtk::DataObjectTreeOptions::TraverseSubTree | vtk::DataObjectTreeOptions::VisitOnlyLeaves |
    vtk::DataObjectTreeOptions::SkipEmptyNodes;
}

/// Whether `object` is an instance of `className` itself, not of a subclass (which may draw
/// otherwise).
bool IsExactly(vtkObject* object, const char* className);

/// Whether vtkCompositePolyDataMapper2 takes `block`'s colours for opaque as it sorts its blocks
/// into VTK's opaque and translucent passes (BuildRenderValues): with scalars shown, its lookup
/// table decides for the block's scalars, or for its whole table where the block has none.
bool BlockColoursOpaque(vtkCompositePolyDataMapper2* mapper, vtkPolyData* block);

/// The textures VTK draws `actor` with: its own and its property's; with `colourOnly`, without
/// the PBR maps that carry no opacity (normal, material, emissive...).
std::vector<vtkTexture*> TexturesOf(vtkActor* actor, bool colourOnly = false);

/// Whether a texture of `actor` (its own or its property's) may have texels of alpha 0, whose
/// fragments VTK drops whatever the actor's opacity: texels with an alpha channel, texels
/// mapped through a lookup table, or none known yet.
bool TexturesMayOpenHoles(vtkActor* actor);

/// Whether one of the textures that colour the actor (TexturesOf, colourOnly) is known to have
/// texels of alpha 0, which VTK discards: unsigned chars with an alpha component, not mapped
/// through a lookup table.
bool TexturesCutHoles(vtkActor* actor);

/// Whether `actor`'s shader property holds shader code or replacements of the user's.
bool HasCustomShaders(vtkActor* actor);

/// Whether `prop` lies outside everything the shadows depend on: a prop that is neither a 3D prop
/// nor a prop assembly (a 2D actor, a widget's representation, a caption's 3D leader) draws
/// through actors of its own that the pass never sees, so it casts nothing and VTK draws it
/// unshadowed; a vtkLightActor, a light's marker, draws unlit lines. The pass leaves it out of
/// its depth, its scene box and its record of the scene: its pixels show it, not the LI buffer,
/// and moving it changes no shadow.
bool OutsideTheShadows(vtkProp* prop);

/// The renderer's visible props that are not OutsideTheShadows, in the renderer's order.
std::vector<vtkProp*> VisiblePropsInTheShadows(vtkRenderer* renderer);

/// How far (world units) what VTK draws for `prop` may reach beyond prop->GetBounds(): VTK's
/// imposter mappers (vtkOpenGLSphereMapper, vtkOpenGLStickMapper), alone or as parts of an
/// assembly, report the bounds of their centres only, without the spheres' radii or the sticks'
/// half lengths. 0 for anything else; infinite when a radius or size is not finite.
double ImposterReach(vtkProp* prop);

/**
 * The visible props of `s`'s renderer that its cullers left out of the frame (`s`'s prop array)
 * although their bounding sphere meets the camera's view: too small on screen for
 * vtkFrustumCoverageCuller's MinimumCoverage, or dropped by a culler of the user's. VTK does not
 * draw them, so they cast nothing either. A prop culled because its sphere lies wholly outside
 * the view (the test vtkFrustumCoverageCuller makes) is not among them: it may shadow the view.
 * Sorted by address.
 */
std::vector<vtkProp*> PropsCulledInView(const vtkRenderState* s);

/// Finds the surfaces a renderer draws, and warns once about what cannot cast.
class SceneWalk
{
public:
  /// The surfaces (opaque, or translucent with their opacity) of every visible prop of `renderer`
  /// (its view props, not the frustum culler's list: a prop outside the view may shadow inside it)
  /// but those in `culledInView` (PropsCulledInView) that casts shadows
  /// (vtkSoftShadowPass::GetCastsShadows, read on the top-level prop: VTK gives an assembly's
  /// parts the assembly's property keys), through PropsDrawnFor. Warnings go through `owner`.
  std::vector<DrawnSurface> Casters(
    vtkRenderer* renderer, const std::vector<vtkProp*>& culledInView, vtkObject* owner);

private:
  void Leaf(vtkProp* leaf, const vtkMatrix4x4* pathMatrix, vtkObject* owner,
    std::vector<DrawnSurface>& surfaces);
  /// A leaf that is no actor: warns where VTK draws it as a volume or an image slice, which
  /// neither cast nor receive.
  void WarnVolumeOrSlice(vtkProp* leaf, vtkObject* owner);
  /// Warns where `actor` casts otherwise than VTK draws it: seen through at an opacity of 1,
  /// or with texels VTK discards.
  void WarnShadowUnlikeDrawing(vtkActor* actor, vtkMapper* mapper, vtkObject* owner);
  /// Whether VTK draws `actor` with triangles a shadow can be cast from; warns where not
  /// (splats, wireframes and points, imposters under clipping planes).
  bool DrawsTriangles(vtkActor* actor, vtkMapper* mapper, vtkObject* owner);
  /// The surfaces of `mapper`'s input: the dataset, or the blocks of composite data.
  void InputSurfaces(vtkActor* actor, vtkMapper* mapper, const glm::dmat4& matrix, vtkObject* owner,
    std::vector<DrawnSurface>& surfaces);
  /// A vtkLODProp3D: the level it is picked by, at its matrix.
  void LODLevel(vtkLODProp3D* levels, vtkObject* owner, std::vector<DrawnSurface>& surfaces);
  /// `composite`: the vtkCompositePolyDataMapper2 drawing them, which decides per block, or
  /// null. `opaqueAtFull` is set where such a block is seen through at an opacity of 1 (its
  /// colours or texture have alpha, or ForceTranslucent): its shadow takes that opacity.
  void Blocks(vtkActor* actor, vtkCompositePolyDataMapper2* composite,
    vtkCompositeDataDisplayAttributes* attributes, vtkDataObject* node, const glm::dmat4& matrix,
    bool visible, double opacity, std::size_t& part, bool& opaqueAtFull,
    std::vector<DrawnSurface>& surfaces);
  /// Mappers that draw many instances of a few shapes (glyphs, imposter spheres and sticks, a
  /// molecule's both): adds their instances and returns true, or returns false for any other.
  bool Instances(vtkActor* actor, vtkMapper* mapper, const glm::dmat4& matrix, vtkObject* owner,
    std::vector<DrawnSurface>& surfaces);
  void Glyphs(vtkActor* actor, vtkGlyph3DMapper* mapper, const glm::dmat4& matrix, vtkObject* owner,
    std::vector<DrawnSurface>& surfaces);
  /// The glyph sources `mapper` picks from, in its order, null for those that cast nothing
  /// (missing, or without surface cells), of which it warns.
  std::vector<vtkDataObject*> CastingGlyphSources(
    vtkActor* actor, vtkGlyph3DMapper* mapper, vtkObject* owner);
  /// The glyphs from `firstGlyph` on, under their mapper's clipping planes: dropped where wholly
  /// clipped away, cut where a plane runs through them.
  void ClipGlyphs(vtkActor* actor, std::size_t firstGlyph, std::vector<DrawnSurface>& surfaces);
  /// One surface per sphere, each an instance of UnitSphere.
  void Spheres(vtkActor* actor, vtkOpenGLSphereMapper* mapper, const glm::dmat4& matrix,
    vtkObject* owner, std::vector<DrawnSurface>& surfaces);
  /// One surface per stick, each an instance of UnitStick.
  void Sticks(vtkActor* actor, vtkOpenGLStickMapper* mapper, const glm::dmat4& matrix,
    vtkObject* owner, std::vector<DrawnSurface>& surfaces);
  /// A molecule's atoms and bonds, through the sphere and stick mappers that draw them.
  void Molecule(vtkActor* actor, vtkOpenGLMoleculeMapper* mapper, const glm::dmat4& matrix,
    vtkObject* owner, std::vector<DrawnSurface>& surfaces);
  /// Warns once per prop and reason.
  void Warn(vtkObject* owner, vtkProp* prop, const std::string& reason);

  PropWarnings Warned;
  /// Surfaces cut by their mapper's clipping planes, as VTK draws them.
  ClippedSurfaces Clipped;
  /// The caster of every imposter sphere (penumbra::ImposterSphereMesh), built on first use:
  /// one topology, instanced by the spheres' matrices.
  vtkSmartPointer<vtkPolyData> UnitSphere;
  /// The same for sticks (penumbra::ImposterStickMesh).
  vtkSmartPointer<vtkPolyData> UnitStick;
};

} // namespace penumbra

#endif
