/**
 * @file   penumbraReceiverShader.h
 * @brief  The edits vtkSoftShadowPass makes to a receiving prop's fragment shader, as one unit
 *         that reports what it could not find.
 *
 * The pass scales each shadowing light's diffuse and specular terms by that light's visibility
 * from the LI buffer. It does so by redefining the light's colour uniform, which VTK 9.1's
 * vtkOpenGLPolyDataMapper uses in those terms only (Phong's diffuse and specular, PBR's
 * radiance), as the colour times the visibility: VTK's statements keep their text, so a user's
 * vtkShaderProperty that replaces them afterwards (a toon shading of the diffuse term) still
 * finds them and is shadowed too. Light code that does not use the colour cannot be shadowed;
 * that is returned for the pass to warn about.
 */
#ifndef penumbraReceiverShader_h
#define penumbraReceiverShader_h

#include <string>
#include <vector>

namespace penumbra
{

/// A shadowing light as the shader sees it: VTK's light number and its LI buffer layer.
struct ReceiverLight
{
  int ShaderIndex = 0;
  int Layer = 0;
};

/// Adds the LI lookup (`declarations`: penumbraReceiverDec.glsl) and the lights' attenuations at
/// VTK's light declarations. Returns false, changing nothing, unless the shader has VTK's
/// //VTK::Light::Dec tag once (a second copy, from a vtkShaderProperty, would declare the lookup
/// twice and the shader would not build).
bool InsertLightDeclarations(std::string& fragmentShader, const std::string& declarations,
  const std::vector<ReceiverLight>& lights);

/// Whether VTK wrote the fragment shader unlit (Lighting off, no normals, point-gaussian
/// splats): its ambient-plus-diffuse statement and no light terms.
bool IsUnlit(const std::string& fragmentShader);

/// After VTK's light code is in place: redefines each light's colour, after its declaration, as
/// the colour times the light's factor, so that every term using it is scaled. Returns the
/// shader indices of the lights whose colour the shader declares but never uses (light code of
/// its own). A shader VTK wrote unlit (its ambient-plus-diffuse statement) is left alone and not
/// reported.
std::vector<int> ScaleLightColours(
  std::string& fragmentShader, const std::vector<ReceiverLight>& lights);

/// Makes VTK 9.1's geometry shader for surfaces drawn with their edges (vtkPolyDataEdgesGS)
/// widen each triangle by half the line width in screen space only while `penumbraDepthPass` is
/// 0. Widened, a triangle keeps its corners' depths at moved corners: its depth is no longer its
/// plane's, and the pass's depth, from which counting takes each pixel's point, put the points
/// of a face nearly edge-on to the light on the wrong side of it. Returns whether the shader
/// widens triangles.
bool KeepEdgesOutOfDepthPass(std::string& geometryShader);

/// Makes VTK 9.1's coincident-topology offset (a polygon offset's units or a z-shift, which VTK
/// adds to gl_FragDepth) apply only while `penumbraDepthPass` is 0. It moves a surface's depth
/// back, not its points, and counting takes each pixel's point from the pass's depth: behind
/// its own face, the point read the face's edges from behind (vedo sets an offset for every
/// mesh). A uniform rather than VTK's global setting turned off, which would make VTK rebuild
/// the shader for each of the two draws of every frame. Returns whether the shader offsets.
bool KeepOffsetOutOfDepthPass(std::string& fragmentShader);

} // namespace penumbra

#endif
