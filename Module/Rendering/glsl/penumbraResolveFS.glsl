//VTK::System::Dec
//VTK::Output::Dec
// Writes the light intensity of pixels selected by the stencil test (non-zero count: inside a
// shadow volume).
uniform float lightIntensity;

void main()
{
  gl_FragData[0] = vec4(lightIntensity);
}
