//VTK::System::Dec
// One penumbra wedge per silhouette edge: its boundary triangles, positions relative to the
// wedge origin (w = 1), far edges as directions (w = 0). A vertex with w = 2 is a clip-space
// full-viewport triangle for an edge that has neither wedge planes nor a light pyramid, on the
// far plane so that the back-face test (GL_GEQUAL) passes at every pixel.
in vec4 vertexMC;
in vec3 edgeFrom;
in vec3 edgeTo;
in float edgeWeight;

uniform mat4 MCDCMatrix;

flat out vec3 edgeFromVS;
flat out vec3 edgeToVS;
flat out float edgeWeightVS;

void main()
{
  edgeFromVS = edgeFrom;
  edgeToVS = edgeTo;
  edgeWeightVS = edgeWeight;
  gl_Position = vertexMC.w > 1.5 ? vec4(vertexMC.xy, 1.0, 1.0) : MCDCMatrix * vertexMC;
}
