//VTK::System::Dec
//VTK::Output::Dec
// Writes the plateau shadow into the light's LI layer at the pixels that lie on the receiver
// plane; every other pixel keeps the hard shadow already resolved there.
//PENUMBRA::DepthPoint::Dec
uniform sampler2D plateauTexture; // plateau depth t over the plane (1 where nothing was drawn)
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
  float depth = penumbraSceneDepth(pixel);
  vec3 p = penumbraPointAt(pixel, depth, 0.0);
  // How far the point may be off its true place: a few steps of a 24-bit depth buffer.
  float slack = length(penumbraPointAt(pixel, depth, -8.0 / 16777216.0) - p);
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
