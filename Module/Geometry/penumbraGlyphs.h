/**
 * @file penumbraGlyphs.h
 * @brief The matrix VTK 9.1 gives one glyph of a vtkGlyph3DMapper, so that the pass casts each
 * glyph where VTK draws it (vtkOpenGLGlyph3DMapper::RebuildStructures is the reference).
 */
#ifndef penumbraGlyphs_h
#define penumbraGlyphs_h

#include "vtkPenumbraGeometryModule.h" // for export macro

#include <glm/glm.hpp>

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
/// Returns false, leaving `matrix` unset, when the orientation is not finite.
VTKPENUMBRAGEOMETRY_EXPORT bool GlyphMatrix(const GlyphSettings& settings,
  const glm::dvec3& position, const double* orientation, const glm::dvec3& scale,
  glm::dmat4& matrix);

} // namespace penumbra

#endif
