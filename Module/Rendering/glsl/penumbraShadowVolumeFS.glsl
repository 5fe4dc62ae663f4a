//VTK::System::Dec
//VTK::Output::Dec
// Counting shadow-volume crossings, where the light's technique says
// (ShadowTechnique::CountsInColour): in the stencil, with colour writes masked off, or as
// +-frontFaceValue per crossing added (blending, no clamping) into the float target bound (the
// light's layer, or a technique's count target), so that a point behind two casters loses twice
// the light and a side of multiplicity m is drawn once with frontFaceValue m.
uniform float frontFaceValue;

void main()
{
  gl_FragData[0] = vec4(gl_FrontFacing ? frontFaceValue : -frontFaceValue);
}
