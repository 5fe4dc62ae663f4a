//VTK::System::Dec
//VTK::Output::Dec
// Writes one light intensity to every pixel it is drawn on: those the caller's stencil test
// selects (non-zero count: inside a shadow volume), or all of them (a layer's lit background).
uniform float lightIntensity;

void main()
{
  gl_FragData[0] = vec4(lightIntensity);
}
