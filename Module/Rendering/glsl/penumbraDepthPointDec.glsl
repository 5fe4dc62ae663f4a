// The visible point of a pixel, from the scene depth, in wedge coordinates (world space relative
// to the light, or to the caster for a directional light). Shared by the wedge, horizon and
// counting shaders through //PENUMBRA::DepthPoint::Dec.
uniform sampler2D depthTexture;
uniform mat4 clipToWedge; // NDC of this viewport to wedge coordinates
uniform vec2 viewportSize;

/// `eyeDepthBias`: NDC depth by which the point moves towards the eye (0 for the point itself).
vec3 penumbraPointAt(ivec2 pixel, float depth, float eyeDepthBias)
{
  vec4 ndc = vec4((vec2(pixel) + 0.5) / viewportSize * 2.0 - 1.0,
    depth * 2.0 - 1.0 - eyeDepthBias, 1.0);
  vec4 point = clipToWedge * ndc;
  return point.xyz / point.w;
}
