//VTK::System::Dec
//VTK::Output::Dec
// No surface sees more of an area light than the part above its own tangent plane. Near a
// caster's terminator the silhouette seen from the light's centre misses that self-occlusion,
// so this pass caps the LI buffer (GL_MIN blending) with the fraction of the light's disk above
// the visible point's geometric plane, its normal taken from the depth buffer.
//PENUMBRA::DepthPoint::Dec
uniform vec4 lightWedge;      // (centre, 1) or (direction towards the light, 0)
uniform float lightRadius;    // world units, or radians for a directional light

const float pi = 3.14159265358979;

/// The step along `step` to the neighbour on the same surface, the one closer in depth. False
/// where both neighbours lie behind the pixel by more than two pixels' width at its depth: a
/// feature one pixel thin (a line, a thin tube, a point) over a farther surface, whose plane the
/// depth cannot give (across it, the tangent would join the feature to the surface behind).
bool tangent(ivec2 pixel, float depth, ivec2 step, vec3 p, out vec3 along)
{
  ivec2 size = ivec2(viewportSize);
  ivec2 forward = clamp(pixel + step, ivec2(0), size - 1);
  ivec2 backward = clamp(pixel - step, ivec2(0), size - 1);
  float dForward = texelFetch(depthTexture, forward, 0).r;
  float dBackward = texelFetch(depthTexture, backward, 0).r;
  vec3 toForward = penumbraPointAt(forward, dForward, 0.0) - p;
  vec3 fromBackward = p - penumbraPointAt(backward, dBackward, 0.0);
  along = abs(dForward - depth) < abs(depth - dBackward) ? toForward : fromBackward;
  float reach = 2.0 * length(penumbraPointAt(forward, depth, 0.0) - p);
  return !(dForward > depth && dBackward > depth && length(toForward) > reach &&
    length(fromBackward) > reach);
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = penumbraSceneDepth(pixel);
  vec3 p = penumbraPointAt(pixel, depth, 0.0);
  // Screen x and y steps: their cross product faces the eye, the side that is seen. A thin
  // feature's plane is unknown: it is left uncapped.
  vec3 alongX, alongY;
  bool planar = tangent(pixel, depth, ivec2(1, 0), p, alongX);
  planar = tangent(pixel, depth, ivec2(0, 1), p, alongY) && planar;
  vec3 n = cross(alongX, alongY);
  if (!planar || dot(n, n) <= 0.0)
  {
    discard;
  }
  n = normalize(n);
  // Angle between the plane and the direction to the light's centre, against its angular radius.
  vec3 towards;
  float sinRadius;
  if (lightWedge.w != 0.0)
  {
    towards = lightWedge.xyz - p;
    float distance = length(towards);
    if (distance <= lightRadius)
    {
      discard;
    }
    towards /= distance;
    sinRadius = lightRadius / distance;
  }
  else
  {
    towards = normalize(lightWedge.xyz);
    sinRadius = sin(lightRadius);
  }
  // In the disk's (gnomonic) plane, the horizon is a line at signed distance t (in disk radii)
  // from the centre: t = cot(radius) * sin(elevation) / cos(elevation).
  float sinElevation = dot(n, towards);
  float cosElevation = sqrt(max(0.0, 1.0 - sinElevation * sinElevation));
  float cosRadius = sqrt(max(0.0, 1.0 - sinRadius * sinRadius));
  float t = (sinElevation * cosRadius) / max(cosElevation * sinRadius, 1e-12);
  float above = t >= 1.0 ? 1.0
    : t <= -1.0 ? 0.0
    : 1.0 - (acos(t) - t * sqrt(1.0 - t * t)) / pi;
  gl_FragData[0] = vec4(above);
}
