//VTK::System::Dec
// One potential-silhouette wedge per (edge, up to two of its faces), as penumbraWedgeVS.glsl:
// positions relative to the wedge origin (w = 1), far edges as directions (w = 0), and w = 2 for
// a clip-space full-viewport triangle on the far plane (see penumbraWedgeVS.glsl). The edge, its
// faces and the receivers' piece the polyhedron was cut to pass through unchanged.
in vec4 vertexMC;
in vec3 edgeFrom;
in vec3 edgeTo;
in vec3 faceNormal0;
in vec3 faceNormal1;
in vec2 faceSigns;
in vec3 centreNormal;
in vec3 pieceMin;
in vec3 pieceMax;

uniform mat4 MCDCMatrix;
// Clip-space scale (xy) and offset (zw) that put the counter texel centres on the pixel centres
// they count (penumbra::HalfResolutionCounts::ClipToCounters); (1, 1, 0, 0) at full resolution.
uniform vec4 clipToCounters;

flat out vec3 edgeFromVS;
flat out vec3 edgeToVS;
flat out vec3 faceNormal0VS;
flat out vec3 faceNormal1VS;
flat out vec2 faceSignsVS;
flat out vec3 centreNormalVS;
flat out vec3 pieceMinVS;
flat out vec3 pieceMaxVS;

void main()
{
  edgeFromVS = edgeFrom;
  edgeToVS = edgeTo;
  faceNormal0VS = faceNormal0;
  faceNormal1VS = faceNormal1;
  faceSignsVS = faceSigns;
  centreNormalVS = centreNormal;
  pieceMinVS = pieceMin;
  pieceMaxVS = pieceMax;
  if (vertexMC.w > 1.5)
  {
    gl_Position = vec4(vertexMC.xy, 1.0, 1.0); // covers every counter texel at any scale
    return;
  }
  gl_Position = MCDCMatrix * vertexMC;
  gl_Position.xy = gl_Position.xy * clipToCounters.xy + clipToCounters.zw * gl_Position.w;
}
