// The receivers' shader edits (penumbraReceiverShader) on the light code VTK 9.1's
// vtkOpenGLPolyDataMapper writes: Phong and PBR, directional and positional lights; light code of
// other shapes (another version, a vtkShaderProperty's toon shading); and what they report when
// the code does not use a light's colour.
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

/// The definition ScaleLightColours gives light `index` of LI layer `layer`.
std::string Scaled(int index, int layer)
{
  const std::string colour = "lightColor" + std::to_string(index), l = std::to_string(layer);
  return "#define " + colour + " (penumbraLightFactor(" + l + ", penumbraAttenuation[" + l +
    "]) * " + colour + ")";
}

int main()
{
  const std::vector<penumbra::ReceiverLight> lights = { { 0, 0 }, { 1, 1 } };
  for (const bool pbr : { false, true })
  {
    const std::string name = pbr ? "PBR" : "Phong";
    std::string shader = pbr ? PbrShader() : PhongShader();
    const std::string vtkShader = shader;
    Check(penumbra::InsertLightDeclarations(shader, "// LI lookup\n", lights),
      name + ": VTK's light tag found");
    Check(Count(shader, "// LI lookup") == 1 && Count(shader, "penumbraAttenuation[2]") == 1 &&
        Count(shader, "//VTK::Light::Dec") == 1 && Count(shader, "//VTK::Light::Impl") == 1,
      name + ": declarations once, tags kept for VTK");
    Check(penumbra::ScaleLightColours(shader, lights).empty(), name + ": every light scaled");
    // Each colour redefined once, right after its declaration; VTK's statements keep their text
    // (a vtkShaderProperty's later replacement of them must still find them).
    Check(Count(shader, "uniform vec3 lightColor0;\n" + Scaled(0, 0)) == 1 &&
        Count(shader, "uniform vec3 lightColor1;\n" + Scaled(1, 1)) == 1 &&
        Count(shader, "#define") == 2,
      name + ": each light's colour scaled by its own layer's factor");
    const char* statement =
      pbr ? "  radiance = lightColor1 * attenuation;\n" : "  diffuse += (df * lightColor0);\n";
    Check(Count(shader, statement) == 1 && Count(vtkShader, statement) == 1,
      name + ": VTK's statements kept as they were");
  }

  // A shader whose tags a vtkShaderProperty replaced: nothing changed, reported.
  std::string custom = "uniform vec3 lightColor0;\nvoid main() { gl_FragColor = vec4(1.0); }\n";
  const std::string before = custom;
  Check(!penumbra::InsertLightDeclarations(custom, "// LI lookup\n", lights) && custom == before,
    "no light tags: reported, shader unchanged");
  // A vtkShaderProperty that repeats a tag: the lookup would be declared twice. Reported.
  std::string repeated = PhongShader() + "//VTK::Light::Dec\n";
  const std::string repeatedBefore = repeated;
  Check(!penumbra::InsertLightDeclarations(repeated, "// LI lookup\n", lights) &&
      repeated == repeatedBefore,
    "a light tag twice: reported, shader unchanged");
  // A repeated //VTK::Light::Impl is VTK's to expand: the light code is scaled all the same.
  std::string repeatedImpl = PhongShader() + "//VTK::Light::Impl\n";
  Check(penumbra::InsertLightDeclarations(repeatedImpl, "// LI lookup\n", lights) &&
      penumbra::ScaleLightColours(repeatedImpl, lights).empty(),
    "the light code's tag twice: scaled");
  // Light code that is not VTK 9.1's, using the lights' colours (a toon diffuse term, another
  // spacing): scaled all the same.
  std::string other = PhongShader();
  other.replace(
    other.find("diffuse += (df * lightColor1);"), 30, "diffuse += step(0.5, df)*lightColor1;");
  other.replace(other.find("specular += (sf * lightColor0);"), 31, "specular+=sf*lightColor0;");
  Check(penumbra::ScaleLightColours(other, lights).empty() && Count(other, "#define") == 2,
    "light code of other shapes, with the lights' colours: scaled");
  // Light code of its own that does not use a light's colour: that light reported, and left.
  std::string own = PhongShader();
  for (const char* term : { "diffuse += (df * lightColor1);", "specular += (sf * lightColor1);" })
  {
    own.replace(own.find(term), std::string(term).size(), "/* its own */");
  }
  const std::vector<int> missing = penumbra::ScaleLightColours(own, lights);
  Check(missing.size() == 1 && missing[0] == 1 && Count(own, "#define lightColor1") == 0 &&
      Count(own, Scaled(0, 0)) == 1,
    "a light whose colour is not used: reported, the others scaled");
  // An unlit shader declares no light colour: nothing to scale, nothing to report.
  std::string unlit = "//VTK::Light::Dec\nvoid main() {\n//VTK::Light::Impl\n}\n";
  Check(penumbra::ScaleLightColours(unlit, lights).empty(), "an unlit shader is not reported");
  // VTK's own unlit shader (Lighting off, point-gaussian splats) still declares the renderer's
  // light colours: it is not reported either, and left as it is.
  std::string vtkUnlit = "uniform vec3 lightColor0;\nuniform vec3 lightColor1;\nvoid main() {\n"
                         "  gl_FragData[0] = vec4(ambientColor + diffuseColor, opacity);\n}\n";
  const std::string vtkUnlitBefore = vtkUnlit;
  Check(penumbra::ScaleLightColours(vtkUnlit, lights).empty() && vtkUnlit == vtkUnlitBefore,
    "VTK's unlit shader, light colours declared: not reported, unchanged");
  Check(
    penumbra::IsUnlit(vtkUnlit) && !penumbra::IsUnlit(unlit) && !penumbra::IsUnlit(PhongShader()),
    "VTK's unlit statement is recognised, and only it");
  // VTK's positional lights declare the next light's colour on the line of the previous one's
  // last uniform, and a user's template may go on after a declaration: each definition is a line
  // of its own, the rest moved to the next line.
  std::string sameLine = "uniform int lightPositional0;uniform vec3 lightColor1; uniform vec3 x;\n"
                         "void main() {\n  diffuse += (df * lightColor1);\n}\n";
  Check(penumbra::ScaleLightColours(sameLine, { { 1, 0 } }).empty() &&
      Count(sameLine, "uniform vec3 lightColor1;\n" + Scaled(1, 0) + "\n uniform vec3 x;\n") == 1,
    "a definition after a declaration that shares its line: a line of its own");
  // Light 1 is not a prefix match of light 10.
  std::string ten = "uniform vec3 lightColor10;\n  diffuse += (df * lightColor10);\n";
  const std::string tenBefore = ten;
  Check(penumbra::ScaleLightColours(ten, { { 1, 0 } }).empty() && ten == tenBefore,
    "light 1's edits leave light 10 alone");
  std::string unusedOne = "uniform vec3 lightColor1;\n  diffuse += (df * lightColor10);\n";
  Check(penumbra::ScaleLightColours(unusedOne, { { 1, 0 } }).size() == 1,
    "light 10's colour is not a use of light 1's");

  // VTK 9.1's geometry shader for surfaces drawn with their edges (vtkPolyDataEdgesGS): the
  // widening of each triangle is kept out of the pass's depth.
  const std::string widen = "gl_Position.xy = gl_Position.xy + offsets[i]*gl_Position.w;";
  const std::string edgesBefore = "#version 150\nuniform float lineWidth;\nvoid main()\n{\n"
                                  "  for (int i = 0; i < 3; i++)\n  {\n    gl_Position = "
                                  "gl_in[i].gl_Position;\n    " +
    widen + "\n    EmitVertex();\n  }\n}\n";
  std::string edges = edgesBefore;
  Check(penumbra::KeepEdgesOutOfDepthPass(edges), "the edges' widening is found");
  Check(edges.find("uniform int penumbraDepthPass;") < edges.find("void main()") &&
      edges.find("if (penumbraDepthPass == 0) { " + widen + " }") != std::string::npos,
    "the widening happens outside the pass's depth only, its uniform declared before main");
  const std::string edited = edges;
  Check(!penumbra::KeepEdgesOutOfDepthPass(edges) && edges == edited, "edited once only");
  std::string wideLines = "void main()\n{\n  gl_Position = gl_in[0].gl_Position;\n}\n";
  const std::string wideLinesBefore = wideLines;
  Check(!penumbra::KeepEdgesOutOfDepthPass(wideLines) && wideLines == wideLinesBefore,
    "other geometry shaders are left alone");
  const std::string offsetBefore = "uniform float cOffset;\nvoid main()\n{\n  gl_FragDepth = "
                                   "gl_FragCoord.z + 1.0*cOffset/65000;\n}\n";
  std::string offset = offsetBefore;
  Check(penumbra::KeepOffsetOutOfDepthPass(offset) &&
      offset.find("uniform int penumbraDepthPass;") < offset.find("void main()") &&
      offset.find("gl_FragCoord.z + float(1 - penumbraDepthPass)*cOffset/65000;") !=
        std::string::npos,
    "VTK's coincident offset is added outside the pass's depth only");
  const std::string offsetEdited = offset;
  Check(!penumbra::KeepOffsetOutOfDepthPass(offset) && offset == offsetEdited,
    "the offset is edited once only");
  std::string noOffset = "void main()\n{\n}\n";
  Check(!penumbra::KeepOffsetOutOfDepthPass(noOffset) && noOffset == "void main()\n{\n}\n",
    "a shader without an offset is left alone");
  return penumbra_test::Finish();
}
