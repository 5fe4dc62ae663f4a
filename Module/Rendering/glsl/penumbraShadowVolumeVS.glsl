//VTK::System::Dec
// Shadow volume of one caster for one light. Each caster point is uploaded twice: w = 1 as
// itself, w = 0 for its copy swept to infinity away from the light, so the volume reaches
// infinity exactly (homogeneous w = 0) and the mesh is uploaded once per data change.
in vec4 vertexMC;

uniform mat4 MCDCMatrix;
// Object space, relative to the caster's origin: (position, 1) or (direction to light, 0).
uniform vec4 lightMC;
// Pushes the light cap away from the eye (NDC depth units); see ShadowVolumeRenderer::DrawVolume.
uniform float capDepthBias;

void main()
{
  if (vertexMC.w > 0.5)
  {
    gl_Position = MCDCMatrix * vec4(vertexMC.xyz, 1.0);
    gl_Position.z += capDepthBias * gl_Position.w;
  }
  else
  {
    gl_Position = MCDCMatrix * vec4(vertexMC.xyz * lightMC.w - lightMC.xyz, 0.0);
  }
}
