//VTK::System::Dec
#extension GL_ARB_shader_image_load_store : require
//VTK::Output::Dec
//PENUMBRA::SampleCount
// Turns the per-sample counters into the light's visibility: sample i is visible where its depth
// complexity, the centre's count plus the edges' changes (penumbraCountingWedgeFS.glsl), is 0,
// and it lies in front of the point's own surface (penumbraSurfaceSideDec.glsl). Pixels that no
// wedge reached (useCounters 0) see every sample in front of their surface as the centre sees it.
//
// A depth complexity cannot be negative. Where one is, the rasterized centre count missed a
// crossing that the edge terms, taken at the pixel's centre, assume (by one or two surfaces):
// the counts are shifted up until the smallest is 0. The fields are decoded with `bias` added to
// each beside the centre count (mod 256: the centre itself may be deeper): a field whose sum is
// negative borrows from the next one in the packed word, and the bias keeps every sum in
// [0, 255], where none borrows, for counts from -bias to 255 - bias. A count above that (252 or
// more surfaces between a point and a sample) overflows: it reads as any count, and as the
// lowest where it reads negative. Averaging's 8-bit stencil wraps at 256. The bias is small
// because a wrapped count reads negative with odds bias/256: 32 turned stream tubes converging
// on a critical point, hundreds of surfaces deep, into dark blobs; 128, earlier, did so from
// 132 surfaces on.
//
// Where the deepest count decoded, or the centre's, reaches reportedCount, it goes into the
// light's texel of deepCounts (penumbra::DeepCounts): the pass learns that the light's counts
// approach the limit, where a deeper point overflows unseen.
//
// With PENUMBRA_COUNT_OFFSET defined it writes, instead of the visibility, the offset that
// makes a sample's 8-bit field 0 (mod 256) exactly where that sample is visible: what the
// translucent casters' resolve (penumbraCountingTransmissionFS.glsl) reads for the samples it
// resolves (four at a time).
//
// Counter texel t holds the counts of pixel counterStride * t (see the wedges' shader).
uniform sampler2D centreCount; // minus the centre's shadow-volume count
uniform usampler2DArray counters;
uniform int useCounters;
uniform int counterStride; // pixels between counter texels: 1, or 2 at half resolution
#ifdef PENUMBRA_SAMPLES_FILL_CAPACITY
const int sampleCount = PENUMBRA_SAMPLE_CAPACITY;
#else
uniform int sampleCount; // counted samples, fewer than PENUMBRA_SAMPLE_CAPACITY
#endif
const int bias = 4;
layout(r32ui) uniform uimage2D deepCounts;
uniform int deepCountSlot; // this light's texel of deepCounts; -1: not reported
uniform int reportedCount;
//PENUMBRA::DepthPoint::Dec
//PENUMBRA::SurfaceSide::Dec

/// Field `field` of a counters' word with the centre's offset added: that sample's count.
int fieldCount(uint counts, int field)
{
  return int((counts >> uint(8 * field)) & 0xFFu) - bias;
}

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int centre =
    int(round(-texelFetch(centreCount, texel * counterStride, 0).r));
  // The surface's plane is found only where some sample's count is 0 (below): most pixels of
  // a view are wholly lit or wholly in an umbra.
  if (useCounters == 0)
  {
#ifdef PENUMBRA_COUNT_OFFSET
    gl_FragData[0] = vec4(float(centre)); // the counters hold 0: visible where the centre is 0
#else
    int seen = 0;
    if (centre == 0)
    {
      penumbraFindSurface(texel * counterStride);
      seen = penumbraSurfaceCut > 0 ? sampleCount : 0;
      for (int i = 0; penumbraSurfaceCut == 0 && i < sampleCount; ++i)
      {
        seen += penumbraSampleInFront(i) ? 1 : 0;
      }
    }
    gl_FragData[0] = vec4(float(seen) / float(sampleCount));
#endif
    return;
  }
  uint offset = (uint(centre + bias) & 0xFFu) * 0x01010101u;
  int lowest = 0;  // min(0, smallest count)
  int visible = 0; // samples whose count equals it
  int deepest = centre;
  for (int word = 0; word * 4 < sampleCount; ++word)
  {
    uint counts = texelFetch(counters, ivec3(texel, word), 0).r + offset;
    for (int field = 0; field < 4 && word * 4 + field < sampleCount; ++field)
    {
      int count = fieldCount(counts, field);
      if (count < lowest)
      {
        lowest = count;
        visible = 0;
      }
      visible += count == lowest ? 1 : 0;
      deepest = max(deepest, count);
    }
  }
  if (deepest >= reportedCount && deepCountSlot >= 0)
  {
    imageAtomicMax(deepCounts, ivec2(deepCountSlot, 0), uint(deepest));
  }
#ifdef PENUMBRA_COUNT_OFFSET
  gl_FragData[0] = vec4(float(centre - lowest));
#else
  if (visible > 0)
  {
    penumbraFindSurface(texel * counterStride);
    if (penumbraSurfaceCut < 0)
    {
      visible = 0;
    }
    else if (penumbraSurfaceCut == 0)
    {
      // Again, those of the samples at the lowest count that lie in front.
      visible = 0;
      for (int word = 0; word * 4 < sampleCount; ++word)
      {
        uint counts = texelFetch(counters, ivec3(texel, word), 0).r + offset;
        for (int field = 0; field < 4 && word * 4 + field < sampleCount; ++field)
        {
          visible +=
            fieldCount(counts, field) == lowest && penumbraSampleInFront(word * 4 + field) ? 1 : 0;
        }
      }
    }
  }
  gl_FragData[0] = vec4(float(visible) / float(sampleCount));
#endif
}
