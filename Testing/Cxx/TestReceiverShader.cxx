// The receivers' shader edits (penumbraReceiverShader) on the light code VTK 9.1's
// vtkOpenGLPolyDataMapper writes: Phong and PBR, directional and positional lights; and what they
// report when the code is not VTK 9.1's (another version, a vtkShaderProperty's own lighting).
#include "penumbraCheck.h"
#include "penumbraReceiverShader.h"

#include <string>

using penumbra_test::Check;

namespace
{
/// A fragment shader shaped as VTK 9.1 writes it for two lights (0 directional, 1 positional).
std::string PhongShader()
{
  return "uniform vec3 lightColor0;\nuniform vec3 lightColor1;\n//VTK::Light::Dec\n"
         "void main() {\n//VTK::Light::Impl\n"
         "  df = max(0.0, dot(normalVCVSOutput, -lightDirectionVC0));\n"
         "  diffuse += (df * lightColor0);\n"
         "  specular += (sf * lightColor0);\n"
         "  df = max(0.0, attenuation*dot(normalVCVSOutput, -vertLightDirectionVC));\n"
         "  diffuse += (df * lightColor1);\n"
         "  specular += (sf * lightColor1);\n}\n";
}

std::string PbrShader()
{
  return "uniform vec3 lightColor0;\nuniform vec3 lightColor1;\n//VTK::Light::Dec\n"
         "void main() {\n//VTK::Light::Impl\n"
         "  radiance = lightColor0;\n"
         "  radiance = lightColor1 * attenuation;\n}\n";
}

int Count(const std::string& text, const std::string& what)
{
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
  {
    ++count;
  }
  return count;
}
} // namespace

int main()
{
  const std::vector<penumbra::ReceiverLight> lights = { { 0, 0 }, { 1, 1 } };
  for (const bool pbr : { false, true })
  {
    const std::string name = pbr ? "PBR" : "Phong";
    std::string shader = pbr ? PbrShader() : PhongShader();
    Check(penumbra::InsertLightFactors(shader, "// LI lookup\n", lights),
      name + ": VTK's light tags found");
    Check(Count(shader, "float penumbraFactor0 = penumbraLightFactor(0,") == 1 &&
        Count(shader, "float penumbraFactor1 = penumbraLightFactor(1,") == 1 &&
        Count(shader, "// LI lookup") == 1 && Count(shader, "//VTK::Light::Impl") == 1,
      name + ": one factor per light, declarations once, tags kept for VTK");
    Check(penumbra::ScaleLightTerms(shader, lights).empty(), name + ": every light scaled");
    const int expected = pbr ? 1 : 2; // diffuse and specular, or the radiance
    Check(Count(shader, "penumbraFactor0 * lightColor0") == expected &&
        Count(shader, "penumbraFactor1 * lightColor1") == expected,
      name + ": each light's terms scaled by its own factor");
  }

  // A shader whose tags a vtkShaderProperty replaced: nothing changed, reported.
  std::string custom = "uniform vec3 lightColor0;\nvoid main() { gl_FragColor = vec4(1.0); }\n";
  const std::string before = custom;
  Check(!penumbra::InsertLightFactors(custom, "// LI lookup\n", lights) && custom == before,
    "no light tags: reported, shader unchanged");
  // A vtkShaderProperty that repeats a tag: the lookup would be declared twice. Reported.
  std::string repeated = PhongShader() + "//VTK::Light::Dec\n";
  const std::string repeatedBefore = repeated;
  Check(
    !penumbra::InsertLightFactors(repeated, "// LI lookup\n", lights) && repeated == repeatedBefore,
    "a light tag twice: reported, shader unchanged");
  // Two lights whose statements are not VTK 9.1's: both reported.
  std::string neither = PhongShader();
  for (const char* light : { "0", "1" })
  {
    const std::string statement = std::string("specular += (sf * lightColor") + light + ");";
    neither.replace(neither.find(statement), statement.size(), "/* replaced */");
  }
  const std::vector<int> both = penumbra::ScaleLightTerms(neither, lights);
  Check(both.size() == 2 && both[0] == 0 && both[1] == 1, "two lights not found: both reported");
  // Light code that is not VTK 9.1's: the light is reported.
  std::string other = PhongShader();
  other.replace(other.find("diffuse += (df * lightColor1);"), 30, "diffuse += df*lightColor1;  ");
  other.replace(
    other.find("specular += (sf * lightColor1);"), 31, "specular += sf*lightColor1;   ");
  const std::vector<int> missing = penumbra::ScaleLightTerms(other, lights);
  Check(missing.size() == 1 && missing[0] == 1, "another VTK's statements: that light reported");
  // Only the diffuse statement is VTK 9.1's: the light's highlights would stay unshadowed.
  std::string halfScaled = PhongShader();
  halfScaled.replace(
    halfScaled.find("specular += (sf * lightColor0);"), 31, "specular += sf*lightColor0;   ");
  const std::vector<int> partial = penumbra::ScaleLightTerms(halfScaled, lights);
  Check(partial.size() == 1 && partial[0] == 0, "diffuse found without specular: reported");
  // An unlit shader declares no light colour: nothing to scale, nothing to report.
  std::string unlit = "//VTK::Light::Dec\nvoid main() {\n//VTK::Light::Impl\n}\n";
  Check(penumbra::ScaleLightTerms(unlit, lights).empty(), "an unlit shader is not reported");
  // VTK's own unlit shader (Lighting off, point-gaussian splats) still declares the renderer's
  // light colours: it is not reported either, and left as it is.
  std::string vtkUnlit = "uniform vec3 lightColor0;\nuniform vec3 lightColor1;\nvoid main() {\n"
                         "  gl_FragData[0] = vec4(ambientColor + diffuseColor, opacity);\n}\n";
  const std::string vtkUnlitBefore = vtkUnlit;
  Check(penumbra::ScaleLightTerms(vtkUnlit, lights).empty() && vtkUnlit == vtkUnlitBefore,
    "VTK's unlit shader, light colours declared: not reported, unchanged");
  Check(
    penumbra::IsUnlit(vtkUnlit) && !penumbra::IsUnlit(unlit) && !penumbra::IsUnlit(PhongShader()),
    "VTK's unlit statement is recognised, and only it");
  // Light 1 is not a prefix match of light 10.
  std::string ten = "uniform vec3 lightColor10;\n  diffuse += (df * lightColor10);\n";
  Check(
    penumbra::ScaleLightTerms(ten, { { 1, 0 } }).empty() && Count(ten, "penumbraFactor1 *") == 0,
    "light 1's edits leave light 10 alone");
  return penumbra_test::Finish();
}
