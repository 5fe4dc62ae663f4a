//VTK::System::Dec
//VTK::Output::Dec
// One light sample's share of the light that translucent casters take away, where no opaque
// caster hides the sample (penumbraHardShadowTechnique.h): the target holds the sum of
// log(1 - opacity) over the translucent surfaces between the point and the sample.
uniform sampler2D logTransmission;
uniform float sampleShare; // 1/N

void main()
{
  // Counts are exact sums of a few terms; min() keeps rounding from adding light.
  float logT = min(texelFetch(logTransmission, ivec2(gl_FragCoord.xy), 0).r, 0.0);
  gl_FragData[0] = vec4((exp(logT) - 1.0) * sampleShare);
}
