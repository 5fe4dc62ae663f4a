//VTK::System::Dec
// One potential-silhouette wedge per (edge, up to two of its faces), as penumbraWedgeVS.glsl:
// positions relative to the wedge origin (w = 1), far edges as directions (w = 0), and w = 2 for
// a clip-space full-viewport triangle on the far plane (see penumbraWedgeVS.glsl). The edge and
// its faces pass through unchanged.
in vec4 vertexMC;
in vec3 edgeFrom;
in vec3 edgeTo;
in vec3 faceNormal0;
in vec3 faceNormal1;
in vec2 faceSigns;
in vec3 centreNormal;

uniform mat4 MCDCMatrix;

flat out vec3 edgeFromVS;
flat out vec3 edgeToVS;
flat out vec3 faceNormal0VS;
flat out vec3 faceNormal1VS;
flat out vec2 faceSignsVS;
flat out vec3 centreNormalVS;

void main()
{
  edgeFromVS = edgeFrom;
  edgeToVS = edgeTo;
  faceNormal0VS = faceNormal0;
  faceNormal1VS = faceNormal1;
  faceSignsVS = faceSigns;
  centreNormalVS = centreNormal;
  gl_Position = vertexMC.w > 1.5 ? vec4(vertexMC.xy, 1.0, 1.0) : MCDCMatrix * vertexMC;
}
