//VTK::System::Dec
//VTK::Output::Dec
// Writes the plateau shadow into the light's LI layer at the pixels that lie on the receiver
// plane; every other pixel keeps the hard shadow already resolved there.
uniform sampler2D depthTexture;   // the scene depth
uniform sampler2D plateauTexture; // plateau depth t over the plane (1 where nothing was drawn)
uniform mat4 clipToPlane;         // NDC of this viewport to world coordinates minus the plane origin
uniform vec2 viewportSize;
uniform vec3 planeNormal;
uniform vec3 planeU;
uniform vec3 planeV;
uniform vec4 planeToTexture;      // (scale u, scale v, offset u, offset v)
uniform float planeTolerance;     // distance from the plane still counted as on it, plus the
                                  // reach of one step of the depth buffer at the pixel
uniform int sinusoidal;           // falloff: 0 linear, 1 (1 - cos(pi t)) / 2

const float pi = 3.14159265358979;

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(depthTexture, pixel, 0).r;
  if (depth >= 1.0)
  {
    discard;
  }
  vec4 ndc = vec4((vec2(pixel) + 0.5) / viewportSize * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  vec4 point = clipToPlane * ndc;
  vec3 p = point.xyz / point.w;
  // How far the point may be off its true place: a few steps of a 24-bit depth buffer.
  vec4 next = clipToPlane * (ndc + vec4(0.0, 0.0, 8.0 / 16777216.0, 0.0));
  float slack = length(next.xyz / next.w - p);
  if (abs(dot(p, planeNormal)) > planeTolerance + slack)
  {
    discard;
  }
  vec2 uv = vec2(dot(p, planeU), dot(p, planeV)) * planeToTexture.xy + planeToTexture.zw;
  float t = 1.0;
  if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))))
  {
    t = clamp(texture(plateauTexture, uv).r, 0.0, 1.0);
  }
  gl_FragData[0] = vec4(sinusoidal != 0 ? 0.5 * (1.0 - cos(pi * t)) : t);
}
