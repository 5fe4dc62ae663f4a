//VTK::System::Dec
//VTK::Output::Dec
// Counting shadow-volume crossings. In the stencil (hard and averaged shadows) colour writes are
// masked off and only the stencil operations count. For penumbra wedges the count goes straight
// into the float LI buffer with additive blending, so that a point behind two casters loses
// twice the light, as the wedges' per-caster corrections assume.
uniform float frontFaceValue;

void main()
{
  gl_FragData[0] = vec4(gl_FrontFacing ? frontFaceValue : -frontFaceValue);
}
