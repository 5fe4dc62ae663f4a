//VTK::System::Dec
//VTK::Output::Dec
// Depth only: the plateau texture is the depth buffer of this pass.
void main()
{
  gl_FragData[0] = vec4(0.0);
}
