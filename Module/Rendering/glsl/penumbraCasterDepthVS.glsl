//VTK::System::Dec
// The depth of an opaque caster drawn from its cached mesh (penumbra::CasterDepth): the w = 1
// half of the caster's vertex buffer, positions only, so that the pass's depth costs no light
// code and no attributes but the position.
in vec4 vertexMC;

uniform mat4 MCDCMatrix;

void main()
{
  gl_Position = MCDCMatrix * vec4(vertexMC.xyz, 1.0);
}
