//VTK::System::Dec
//VTK::Output::Dec
// The half-resolution depth that counting's wedges are tested against: texel t takes the depth of
// the pixel 2t it counts (penumbraCountingWedgeFS.glsl), not a blend of its four, so that the
// depth test and the counted point agree.
uniform sampler2D depthTexture;

void main()
{
  gl_FragDepth = texelFetch(depthTexture, 2 * ivec2(gl_FragCoord.xy), 0).r;
}
