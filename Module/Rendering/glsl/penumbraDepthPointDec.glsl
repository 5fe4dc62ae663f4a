// The point of a pixel at a depth (the scene's, or for the counting wedges counting's own,
// penumbraCountingDepthFS.glsl), in the shader's local frame: world space
// relative to the caster's origin for the wedge and counting shaders (WedgeBuffer::Origin),
// relative to the light (world space for a directional light) for the horizon cap, relative to
// the receiver plane's origin for the plateau resolve. Shared through //PENUMBRA::DepthPoint::Dec.
uniform sampler2D depthTexture;
// NDC of this viewport to the local frame, applied to (x, y, z - 1, 1): its last column holds
// the far plane's centre (ShadowFrame::SetClipToLocal)
uniform mat4 clipToLocal;
uniform vec2 viewportSize;

/// The pixel's point at window `depth`, moved towards the eye by `eyeDepthBias` (NDC depth; 0
/// for the point itself), in homogeneous coordinates of the local frame: w is the same multiple
/// of 1 / clip w for every point.
vec4 penumbraHomogeneousAt(ivec2 pixel, float depth, float eyeDepthBias)
{
  // depth - 1 is exact in float for depth >= 0.5, and the matrix's constant column already
  // holds its depth column (summed in double): multiplying NDC z itself, those two columns
  // cancelled in float near the far plane, where a perspective range keeps most of its steps.
  vec4 ndcFromFar = vec4((vec2(pixel) + 0.5) / viewportSize * 2.0 - 1.0,
    (depth - 1.0) * 2.0 - eyeDepthBias, 1.0);
  return clipToLocal * ndcFromFar;
}

vec3 penumbraPointAt(ivec2 pixel, float depth, float eyeDepthBias)
{
  vec4 point = penumbraHomogeneousAt(pixel, depth, eyeDepthBias);
  return point.xyz / point.w;
}

/// The scene depth at the fragment's pixel; a background fragment (depth 1: nothing there to
/// shadow) is discarded.
float penumbraSceneDepth(ivec2 pixel)
{
  float depth = texelFetch(depthTexture, pixel, 0).r;
  if (depth >= 1.0)
  {
    discard;
  }
  return depth;
}
