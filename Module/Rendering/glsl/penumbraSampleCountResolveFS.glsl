//VTK::System::Dec
//VTK::Output::Dec
// One averaged light sample's share of the light, taken away where the sample's opaque casters'
// volumes cover the point (penumbraHardShadowTechnique.h). The target holds minus their count,
// added in colour: exact small integers, so any count of one or more is a shadow.
uniform sampler2D sampleCount;
uniform float sampleShare; // 1/N

void main()
{
  if (texelFetch(sampleCount, ivec2(gl_FragCoord.xy), 0).r > -0.5)
  {
    discard;
  }
  gl_FragData[0] = vec4(-sampleShare);
}
