/**
 * @file penumbraGlyphs.h
 * @brief The matrix VTK 9.1 gives one glyph of a vtkGlyph3DMapper, so that the pass casts each
 * glyph where VTK draws it (vtkOpenGLGlyph3DMapper::RebuildStructures is the reference), and the
 * triangles and matrices that stand in for the spheres of a vtkOpenGLSphereMapper and the
 * sticks of a vtkOpenGLStickMapper.
 */
#ifndef penumbraGlyphs_h
#define penumbraGlyphs_h

#include "vtkPenumbraGeometryModule.h" // for export macro

#include <glm/glm.hpp>

#include <vector>

namespace penumbra
{

/// vtkGlyph3DMapper's settings that place and size a glyph, with its enums' values.
struct GlyphSettings
{
  enum ScaleModes
  {
    NoDataScaling = 0,
    ScaleByMagnitude = 1,
    ScaleByComponents = 2
  };
  enum OrientationModes
  {
    Direction = 0,
    Rotation = 1,  ///< degrees about x, y and z, applied as VTK does (z, then x, then y)
    Quaternion = 2 ///< (w, x, y, z)
  };
  bool Scaling = true;
  int ScaleMode = ScaleByMagnitude;
  double ScaleFactor = 1.0;
  bool Clamping = false;
  double Range[2] = { 0.0, 1.0 };
  int OrientationMode = Direction;
};

/// The glyph's scale along its x, y and z: data scale (a tuple of `components` values, or none),
/// clamped and normalized to Range when Clamping, times ScaleFactor; zero becomes 1e-10 as in VTK.
VTKPENUMBRAGEOMETRY_EXPORT glm::dvec3 GlyphScale(
  const GlyphSettings& settings, const double* scaleTuple, int components);

/// The glyph's object-to-data matrix: translated to `position`, rotated by `orientation` (3 or 4
/// values as the mode wants, or null for none), scaled by `scale` when settings.Scaling.
/// Returns false, leaving `matrix` unset, when the orientation is not finite or gives no finite
/// rotation (a direction too small to normalize: VTK draws no such glyph).
VTKPENUMBRAGEOMETRY_EXPORT bool GlyphMatrix(const GlyphSettings& settings,
  const glm::dvec3& position, const double* orientation, const glm::dvec3& scale,
  glm::dmat4& matrix);

/// A closed triangle mesh, outward wound.
struct TriangleMesh
{
  std::vector<glm::dvec3> Points;
  std::vector<glm::uvec3> Triangles;
};

/**
 * A UV sphere of `segments` around (at least 8, even) and segments / 2 rings, its points on the
 * unit sphere: the caster of one imposter sphere. Inscribed on purpose: every point of the true
 * sphere lies outside it, so the sphere VTK draws is never shadowed by its own stand-in (a
 * larger one would put the lit surface just inside its own shadow volume). Its outline lies
 * inside the true one by at most about 1 - cos^2(pi / segments) of the radius (the middle of a
 * quad's diagonal; 1% at 32, 0.5% along the rings).
 */
VTKPENUMBRAGEOMETRY_EXPORT TriangleMesh ImposterSphereMesh(int segments);

/// The object-to-world matrix of one sphere of a vtkOpenGLSphereMapper: VTK moves the centre by
/// the actor's matrix but draws the radius in world units, unscaled (vtkPointGaussianVS.glsl
/// passes radiusMC on as the view-space radius). Returns false, leaving `matrix` unset, when the
/// centre or the radius is not finite or the radius is not positive.
VTKPENUMBRAGEOMETRY_EXPORT bool ImposterSphereMatrix(
  const glm::dmat4& actorMatrix, const glm::dvec3& centre, double radius, glm::dmat4& matrix);

/**
 * A capped cylinder of `segments` around (at least 8) along z from -0.5 to 0.5, its rim points on
 * the unit circle: the caster of one stick of a vtkOpenGLStickMapper (a molecule's bond),
 * inscribed for the reason ImposterSphereMesh is.
 */
VTKPENUMBRAGEOMETRY_EXPORT TriangleMesh ImposterStickMesh(int segments);

/// The object-to-world matrix of one stick of a vtkOpenGLStickMapper, as its shaders place it:
/// centred on the actor-moved `centre`, its axis along the actor's normal matrix times
/// `orientation`, `length` long (VTK's length times the orientation's norm) and `radius` wide,
/// neither scaled by the actor. Returns false, leaving `matrix` unset, when any of them is not
/// finite, or the length or the radius is not positive.
VTKPENUMBRAGEOMETRY_EXPORT bool ImposterStickMatrix(const glm::dmat4& actorMatrix,
  const glm::dvec3& centre, const glm::dvec3& orientation, double length, double radius,
  glm::dmat4& matrix);

} // namespace penumbra

#endif
