//VTK::System::Dec
//VTK::Output::Dec
//PENUMBRA::Defines
// Counting at half resolution counted the pixels with even coordinates exactly
// (penumbraCountingWedgeFS.glsl). Every other pixel lies between 2 of them along a row or
// column, or 4 on the diagonals. Where their visibilities are at most `uncertain` apart, the
// pixel takes their mean: the light changes little there, whatever surfaces they lie on. The
// pixel is uncertain, and counted again at full resolution, where they differ more (a shadow's
// edge, or a crease or silhouette with a shadow ending at it), where its surface stands out in
// depth from both counted pixels of a pair (a surface narrower than two pixels, which neither
// sees), and where a pair has only one counted pixel (the other shows the background or lies
// beyond the window's border): one pixel alone bounds nothing, and beside a silhouette it often
// lies on another surface than the pixel's. Also where the light's centre is hidden from the
// pixel and seen from a counted neighbour, or the other way round (the centre's shadow-volume
// count is 0 at one of them only): the hard shadow of a thin caster, a shaft or a wire, can pass
// between two counted pixels that both see the light. Counts that differ but are both above 0
// (one shadow inside another) are left to the visibility test.
//
// With PENUMBRA_MARK_UNCERTAIN defined it writes nothing and keeps only the uncertain pixels
// (for the stencil); otherwise it writes every pixel's mean, which the full count then replaces
// at the uncertain ones.
uniform sampler2D depthTexture;
uniform sampler2D countedVisibility; // at half resolution: texel t is pixel 2t's visibility
uniform sampler2D centreCount; // every pixel's count of the light centre's shadow volumes, negated
uniform float uncertain; // the largest difference of counted neighbours taken as smooth

/// Steps of a 24-bit depth buffer within which depths are taken as equal.
const float depthSteps = 4.0 / 16777216.0;

float sum = 0.0;
float lowest = 1.0;
float highest = 0.0;
int counted = 0;
bool standsOut = false;
bool oneSided = false;
bool centreDiffers = false;
bool centreSeen = true;

/// The depth at `pixel`; 1 (the background's) off the window.
float depthAt(ivec2 pixel)
{
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, textureSize(depthTexture, 0))))
  {
    return 1.0;
  }
  return texelFetch(depthTexture, pixel, 0).r;
}

/// Adds the counted pixel at `pixel` unless it shows the background; returns its depth.
float add(ivec2 pixel)
{
  float depth = depthAt(pixel);
  if (depth < 1.0)
  {
    float visibility = texelFetch(countedVisibility, pixel / 2, 0).r;
#ifdef PENUMBRA_MARK_UNCERTAIN
    centreDiffers = centreDiffers || (texelFetch(centreCount, pixel, 0).r == 0.0) != centreSeen;
#endif
    sum += visibility;
    lowest = min(lowest, visibility);
    highest = max(highest, visibility);
    ++counted;
  }
  return depth;
}

/// Adds the counted pixels at pixel - step and pixel + step.
void addPair(ivec2 pixel, float depth, ivec2 step)
{
  float before = add(pixel - step);
  float after = add(pixel + step);
  oneSided = oneSided || (before < 1.0) != (after < 1.0);
  standsOut = standsOut || depth < min(before, after) - depthSteps ||
    depth > max(before, after) + depthSteps;
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 odd = pixel & 1;
  if (odd == ivec2(0))
  {
#ifdef PENUMBRA_MARK_UNCERTAIN
    discard; // counted
#else
    gl_FragData[0] = vec4(texelFetch(countedVisibility, pixel / 2, 0).r);
    return;
#endif
  }
  float depth = texelFetch(depthTexture, pixel, 0).r;
#ifdef PENUMBRA_MARK_UNCERTAIN
  centreSeen = texelFetch(centreCount, pixel, 0).r == 0.0;
#endif
  addPair(pixel, depth, odd);
  if (odd.x == 1 && odd.y == 1)
  {
    addPair(pixel, depth, ivec2(1, -1));
  }
#ifdef PENUMBRA_MARK_UNCERTAIN
  if (counted > 0 && !oneSided && !centreDiffers && highest - lowest <= uncertain &&
    !standsOut)
  {
    discard; // certain
  }
#else
  gl_FragData[0] = vec4(counted > 0 ? sum / float(counted) : 0.0);
#endif
}
