#include "penumbraReceiverShader.h"

#include <cctype>
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

/// How often `name` occurs in `text` from `from` on as a whole identifier (lightColor1 is not
/// in lightColor10).
int IdentifierUses(const std::string& text, const std::string& name, std::size_t from)
{
  auto inIdentifier = [](char c)
  { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  int count = 0;
  for (std::size_t at = text.find(name, from); at != std::string::npos;
       at = text.find(name, at + 1))
  {
    const std::size_t end = at + name.size();
    count +=
      (at == 0 || !inIdentifier(text[at - 1])) && (end == text.size() || !inIdentifier(text[end]));
  }
  return count;
}

const char* const DeclarationsTag = "//VTK::Light::Dec";

/// Replaces the first `statement` after main's start with `gated`, which reads the uniform
/// penumbraDepthPass, and declares it; false, leaving the shader alone, where the statement is
/// missing or the shader was edited already.
bool ReplaceForDepthPass(
  std::string& shader, const std::string& statement, const std::string& gated)
{
  const std::size_t at = shader.find(statement);
  const std::size_t main = shader.find("void main()");
  if (at == std::string::npos || main == std::string::npos || main > at ||
    shader.find("penumbraDepthPass") != std::string::npos)
  {
    return false;
  }
  shader.replace(at, statement.size(), gated);
  shader.insert(main, "uniform int penumbraDepthPass; // 1 while the pass draws depth\n");
  return true;
}
} // namespace

bool InsertLightDeclarations(std::string& fragmentShader, const std::string& declarations,
  const std::vector<ReceiverLight>& lights)
{
  if (Count(fragmentShader, DeclarationsTag) != 1)
  {
    return false;
  }
  std::ostringstream dec;
  dec << declarations << "uniform float penumbraAttenuation[" << lights.size() << "];\n"
      << DeclarationsTag;
  ReplaceAll(fragmentShader, DeclarationsTag, dec.str());
  return true;
}

bool IsUnlit(const std::string& fragmentShader)
{
  // VTK 9.1's statement for unlit surfaces; the renderer's light uniforms are still declared.
  return fragmentShader.find("gl_FragData[0] = vec4(ambientColor + diffuseColor, opacity);") !=
    std::string::npos;
}

std::vector<int> ScaleLightColours(
  std::string& fragmentShader, const std::vector<ReceiverLight>& lights)
{
  std::vector<int> missing;
  if (IsUnlit(fragmentShader))
  {
    return missing; // nothing for a shadow to scale, and nothing to report
  }
  for (const ReceiverLight& light : lights)
  {
    // Every use of the light's colour after its declaration is that light's diffuse and
    // specular (Phong) or radiance (PBR) term, in VTK 9.1's statements and in a user's own: the
    // colour is redefined as itself times the light's factor. The preprocessor does not expand
    // a macro inside its own expansion, and the statements keep their text, so that a
    // vtkShaderProperty's later replacement of them still finds them.
    const std::string colour = "lightColor" + std::to_string(light.ShaderIndex);
    const std::string declaration = "uniform vec3 " + colour + ";";
    const std::size_t at = fragmentShader.find(declaration);
    if (at == std::string::npos)
    {
      continue; // not a light this shader draws with
    }
    const std::size_t after = at + declaration.size();
    if (IdentifierUses(fragmentShader, colour, after) == 0)
    {
      missing.push_back(light.ShaderIndex); // its own light code, without the light's colour
      continue;
    }
    const std::string layer = std::to_string(light.Layer);
    fragmentShader.insert(after,
      "\n#define " + colour + " (penumbraLightFactor(" + layer + ", penumbraAttenuation[" + layer +
        "]) * " + colour + ")\n");
  }
  return missing;
}

bool KeepEdgesOutOfDepthPass(std::string& geometryShader)
{
  static const std::string widen = "gl_Position.xy = gl_Position.xy + offsets[i]*gl_Position.w;";
  return ReplaceForDepthPass(
    geometryShader, widen, "if (penumbraDepthPass == 0) { " + widen + " }");
}

bool KeepOffsetOutOfDepthPass(std::string& fragmentShader)
{
  return ReplaceForDepthPass(
    fragmentShader, "1.0*cOffset/65000", "float(1 - penumbraDepthPass)*cOffset/65000");
}

} // namespace penumbra
