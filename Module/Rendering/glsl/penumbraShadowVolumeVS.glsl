//VTK::System::Dec
// Shadow volume of one caster for one light. Each caster point is uploaded twice: w = 1 as
// itself, w = 0 for its copy swept away from the light, which reaches infinity exactly
// (homogeneous w = 0), stops on the end plane or goes a set length; the mesh is uploaded once
// per data change.
in vec4 vertexMC;

uniform mat4 MCDCMatrix;
// Object space, relative to the caster's origin: (position, 1) or (direction to light, 0).
uniform vec4 lightMC;
// z-pass only: (n, -d) of a plane beyond every visible point (penumbra::VolumeEndPlane), object
// space; the swept copies stop on it, which spares the fill of the volume beyond the scene.
// (0, 0, 0, 0): they go to infinity.
uniform vec4 endPlaneMC;
// z-fail under a parallel projection, which draws infinity nowhere: the object-space length the
// swept directions are scaled to (penumbra::ParallelSweepLength); 0 otherwise.
uniform float sweepLength;
// Pushes the volume's faces at the caster away from the eye (NDC depth units): the light cap's,
// and for soft shadow volumes the sides' (ShadowTechnique::VolumeDepthBias); see
// ShadowVolumeRenderer::DrawVolume.
uniform float depthBias;

void main()
{
  if (vertexMC.w > 0.5)
  {
    gl_Position = MCDCMatrix * vec4(vertexMC.xyz, 1.0);
    gl_Position.z += depthBias * gl_Position.w;
  }
  else
  {
    vec3 away = vertexMC.xyz * lightMC.w - lightMC.xyz;
    if (sweepLength > 0.0)
    {
      gl_Position = MCDCMatrix * vec4(vertexMC.xyz + away * (sweepLength / length(away)), 1.0);
    }
    else if (endPlaneMC == vec4(0.0))
    {
      gl_Position = MCDCMatrix * vec4(away, 0.0);
    }
    else
    {
      float reach = -dot(endPlaneMC, vec4(vertexMC.xyz, 1.0)) / dot(endPlaneMC.xyz, away);
      gl_Position = MCDCMatrix * vec4(vertexMC.xyz + reach * away, 1.0);
    }
  }
}
