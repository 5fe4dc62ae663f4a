//VTK::System::Dec
//VTK::Output::Dec
//PENUMBRA::SampleCount
// Four counted light samples' shares of the light that translucent casters take away, where no
// opaque caster hides the sample (penumbraCountingTechnique.h). Samples 4 * word + c, c below
// groupSize, are visible where field c of the counters' word plus the pixel's offset
// (penumbraCountingResolveFS.glsl with PENUMBRA_COUNT_OFFSET) in every field is 0; channel c of
// the log-transmission target holds the sum of log(1 - opacity) over the translucent surfaces
// between the point and that sample. The offset is added to the whole word, as the counting's
// resolve adds the centre: the fields borrow from each other where an edge change was
// negative, and only the word's sum is exact. A sample behind the point's own surface
// (penumbraSurfaceSideDec.glsl) is hidden too.
uniform sampler2D countOffset;
uniform usampler2DArray counters;
uniform sampler2D logTransmission;
uniform int word;
uniform int groupSize;
uniform float sampleShare; // 1/N
//PENUMBRA::DepthPoint::Dec
//PENUMBRA::SurfaceSide::Dec

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  // Sums of a few exact terms; min() keeps rounding from adding light.
  vec4 logT = min(texelFetch(logTransmission, pixel, 0), vec4(0.0));
  if (logT == vec4(0.0))
  {
    discard; // no translucent surface in the way: most pixels of the rectangle
  }
  penumbraFindSurface(pixel);
  int offset = int(round(texelFetch(countOffset, pixel, 0).r));
  uint counts =
    texelFetch(counters, ivec3(pixel, word), 0).r + (uint(offset) & 0xFFu) * 0x01010101u;
  float taken = 0.0;
  for (int c = 0; c < groupSize; ++c)
  {
    // A sample an opaque caster hides has lost its share already.
    bool visible =
      ((counts >> uint(8 * c)) & 0xFFu) == 0u && penumbraSampleInFront(4 * word + c);
    taken += visible ? exp(logT[c]) - 1.0 : 0.0;
  }
  gl_FragData[0] = vec4(taken * sampleShare);
}
