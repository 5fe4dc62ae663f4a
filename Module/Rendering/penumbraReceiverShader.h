/**
 * @file   penumbraReceiverShader.h
 * @brief  The edits vtkSoftShadowPass makes to a receiving prop's fragment shader, as one unit
 *         that reports what it could not find.
 *
 * The pass scales each shadowing light's diffuse and specular terms by that light's visibility
 * from the LI buffer. It does so by rewriting the statements VTK 9.1's vtkOpenGLPolyDataMapper
 * writes per light; a different VTK, or a user's vtkShaderProperty replacing VTK's light code,
 * would leave nothing to rewrite and the prop silently unshadowed. So every edit is counted and
 * what is missing is returned for the pass to warn about.
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

/// Adds the LI lookup (`declarations`: penumbraReceiverDec.glsl) at VTK's light declarations and
/// one factor per light before its light code. Returns false, changing nothing, unless the
/// shader has VTK's //VTK::Light::Dec and //VTK::Light::Impl tags once each (a second copy, from
/// a vtkShaderProperty, would declare the lookup twice and the shader would not build).
bool InsertLightFactors(std::string& fragmentShader, const std::string& declarations,
  const std::vector<ReceiverLight>& lights);

/// Whether VTK wrote the fragment shader unlit (Lighting off, no normals, point-gaussian
/// splats): its ambient-plus-diffuse statement and no light terms.
bool IsUnlit(const std::string& fragmentShader);

/// Scales each light's diffuse and specular (Phong) or radiance (PBR) by its factor. Returns
/// the shader indices of the lights whose colour the shader declares but whose statements were
/// not all found: none of them, or Phong's diffuse without its specular (or the reverse). A shader
/// VTK wrote unlit (its ambient-plus-diffuse statement) is left alone and not reported.
std::vector<int> ScaleLightTerms(
  std::string& fragmentShader, const std::vector<ReceiverLight>& lights);

} // namespace penumbra

#endif
