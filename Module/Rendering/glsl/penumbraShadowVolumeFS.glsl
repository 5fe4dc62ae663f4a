//VTK::System::Dec
//VTK::Output::Dec
// Stencil only: colour writes are masked off while volumes are drawn.
void main()
{
  gl_FragData[0] = vec4(0.0);
}
