#include "penumbraReceiverShader.h"

#include <sstream>

namespace penumbra
{
namespace
{
/// Replaces every occurrence of `what`; returns how many there were.
int ReplaceAll(std::string& text, const std::string& what, const std::string& with)
{
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos;
       at = text.find(what, at + with.size()))
  {
    text.replace(at, what.size(), with);
    ++count;
  }
  return count;
}

/// How often `what` occurs in `text`.
int Count(const std::string& text, const std::string& what)
{
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
  {
    ++count;
  }
  return count;
}

const char* const DeclarationsTag = "//VTK::Light::Dec";
const char* const ImplementationTag = "//VTK::Light::Impl";
} // namespace

bool InsertLightFactors(std::string& fragmentShader, const std::string& declarations,
  const std::vector<ReceiverLight>& lights)
{
  if (Count(fragmentShader, DeclarationsTag) != 1 || Count(fragmentShader, ImplementationTag) != 1)
  {
    return false;
  }
  std::ostringstream dec;
  dec << declarations << "uniform float penumbraAttenuation[" << lights.size() << "];\n"
      << DeclarationsTag;
  ReplaceAll(fragmentShader, DeclarationsTag, dec.str());

  std::ostringstream factors;
  for (const ReceiverLight& light : lights)
  {
    factors << "  float penumbraFactor" << light.ShaderIndex << " = penumbraLightFactor("
            << light.Layer << ", penumbraAttenuation[" << light.Layer << "]);\n";
  }
  factors << ImplementationTag;
  ReplaceAll(fragmentShader, ImplementationTag, factors.str());
  return true;
}

bool IsUnlit(const std::string& fragmentShader)
{
  // VTK 9.1's statement for unlit surfaces; the renderer's light uniforms are still declared.
  return fragmentShader.find("gl_FragData[0] = vec4(ambientColor + diffuseColor, opacity);") !=
    std::string::npos;
}

std::vector<int> ScaleLightTerms(
  std::string& fragmentShader, const std::vector<ReceiverLight>& lights)
{
  std::vector<int> missing;
  if (IsUnlit(fragmentShader))
  {
    return missing; // nothing for a shadow to scale, and nothing to report
  }
  for (const ReceiverLight& light : lights)
  {
    // The exact statements VTK 9.1's vtkOpenGLPolyDataMapper writes per light (Phong and PBR,
    // directional and positional); only diffuse and specular are scaled, ambient stays.
    const std::string colour = "lightColor" + std::to_string(light.ShaderIndex);
    const std::string factor = "penumbraFactor" + std::to_string(light.ShaderIndex) + " * ";
    const int diffuse = ReplaceAll(fragmentShader, "diffuse += (df * " + colour + ");",
      "diffuse += (df * " + factor + colour + ");");
    const int specular = ReplaceAll(fragmentShader, "specular += (sf * " + colour + ");",
      "specular += (sf * " + factor + colour + ");");
    const int radiance = ReplaceAll(fragmentShader, "radiance = " + colour + ";",
                           "radiance = " + factor + colour + ";") +
      ReplaceAll(fragmentShader, "radiance = " + colour + " * attenuation;",
        "radiance = " + factor + colour + " * attenuation;");
    // VTK writes Phong's diffuse and specular statements as a pair: one without the other
    // would leave that light's highlights (or its diffuse light) unshadowed.
    const bool scaled =
      radiance > 0 ? diffuse == 0 && specular == 0 : diffuse > 0 && diffuse == specular;
    if (!scaled && fragmentShader.find("vec3 " + colour + ";") != std::string::npos)
    {
      missing.push_back(light.ShaderIndex);
    }
  }
  return missing;
}

} // namespace penumbra
