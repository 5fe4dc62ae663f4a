//VTK::System::Dec
//VTK::Output::Dec
// Counting's point for each pixel, as a window depth (penumbra::CountingPointDepth is the
// reference and its tests): written into the depth attachment that the centre's volume is
// counted against, and read by the wedges, so that the centre's count and the edges' terms
// judge one point. In front of the scene depth by depthBias, or where the caster meshes' depth
// pass left the surface's plane, in front of the plane's own depth on the view ray and at least
// a float margin off it.
//PENUMBRA::DepthPoint::Dec
//PENUMBRA::SurfacePlane::Dec
uniform float depthBias; // window depth
uniform float planeBias; // share of the ray's ends' distances from clipToLocal's origin

/// Window depth - 1 at the share u of the way from the ray's far end back to its near one.
float depthMinusOne(float u, float farOverNearW)
{
  return -u / (u + (1.0 - u) * farOverNearW);
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float sceneDepth = texelFetch(depthTexture, pixel, 0).r;
  if (sceneDepth >= 1.0)
  {
    gl_FragDepth = 1.0;
    return;
  }
  gl_FragDepth = sceneDepth - min(depthBias, sceneDepth);
  vec4 plane = penumbraSurfacePlane(pixel); // about clipToLocal's origin
  if (plane.x >= noSurfacePlane)
  {
    return;
  }
  vec4 nearPoint = penumbraHomogeneousAt(pixel, 0.0, 0.0);
  vec4 farPoint = penumbraHomogeneousAt(pixel, 1.0, 0.0);
  vec3 nearEnd = nearPoint.xyz / nearPoint.w;
  vec3 farEnd = farPoint.xyz / farPoint.w;
  // Heights above the plane, the near end's on the seen side.
  float nearHeight = dot(plane.xyz, nearEnd) - plane.w;
  float farHeight = dot(plane.xyz, farEnd) - plane.w;
  if (nearHeight < 0.0)
  {
    nearHeight = -nearHeight;
    farHeight = -farHeight;
  }
  if (!(farHeight < 0.0 && nearHeight > 0.0))
  {
    return;
  }
  float farOverNearW = nearPoint.w / farPoint.w; // the homogeneous w is 1 / clip w, scaled
  float span = nearHeight - farHeight;
  float onPlane = depthMinusOne(-farHeight / span, farOverNearW);
  if (!(abs(1.0 + onPlane - sceneDepth) <= max(16.0 * depthBias, 0.01 * (1.0 - sceneDepth))))
  {
    return; // not this pixel's surface
  }
  float clearance = planeBias * (length(nearEnd) + length(farEnd));
  float offPlane = depthMinusOne(min((clearance - farHeight) / span, 1.0), farOverNearW);
  gl_FragDepth = max(1.0 + min(onPlane - depthBias, offPlane), 0.0);
}
