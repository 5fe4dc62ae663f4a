//VTK::System::Dec
// The depth of an opaque caster drawn from its cached mesh (penumbra::CasterDepth): the w = 1
// half of the caster's vertex buffer, positions only, so that the pass's depth costs no light
// code and no attributes but the position.
in vec4 vertexMC;

uniform mat4 MCDCMatrix;

out vec3 positionMC; // relative to the mesh's origin: small, so its differences are precise

void main()
{
  positionMC = vertexMC.xyz;
  gl_Position = MCDCMatrix * vec4(vertexMC.xyz, 1.0);
}
