// Added by vtkSoftShadowPass to the fragment shaders of receiving props: the fraction of each
// shadowing light that this pixel's surface sees, read from the light-intensity (LI) buffer.
uniform sampler2DArray penumbraLI;  // one layer per shadowing light
uniform int penumbraApply;          // 0 while the depth pre-pass renders, or for non-receivers
uniform ivec2 penumbraOrigin;       // viewport origin in window pixels
uniform ivec2 penumbraSize;         // viewport size in pixels

float penumbraLightFactor(int layer, float shadowAttenuation)
{
  if (penumbraApply == 0)
  {
    return 1.0;
  }
  ivec2 pixel = clamp(ivec2(gl_FragCoord.xy) - penumbraOrigin, ivec2(0), penumbraSize - 1);
  float visible = clamp(texelFetch(penumbraLI, ivec3(pixel, layer), 0).r, 0.0, 1.0);
  return 1.0 - shadowAttenuation * (1.0 - visible);
}
