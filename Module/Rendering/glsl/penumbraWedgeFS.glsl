//VTK::System::Dec
//VTK::Output::Dec
// Adds one silhouette edge's share of the light to the LI buffer at the visible point of this
// pixel (penumbraWedge.cxx, EdgeOcclusion, is the reference implementation and its tests): seen
// from the point, the light is a disk; the edge's correction is the part of triangle
// (disk centre, projected edge) inside the disk minus the disk sector it spans. It is zero
// outside the wedge, so the wedge only bounds the pixels worth evaluating.
//PENUMBRA::DepthPoint::Dec
uniform vec4 lightWedge;      // (centre, 1) or (direction towards the light, 0), wedge coordinates
uniform float lightRadius;    // world units, or radians for a directional light

flat in vec3 edgeFromVS;
flat in vec3 edgeToVS;
flat in float edgeWeightVS;

const float pi = 3.14159265358979;

float insideCorrection(vec2 A, vec2 B, float R)
{
  vec2 AB = B - A;
  float len = length(AB);
  if (len <= 0.0)
  {
    return 0.0;
  }
  vec2 u = AB / len;
  float closest = -dot(A, u);
  vec2 nearest = A + closest * u;
  float halfChord2 = R * R - dot(nearest, nearest);
  if (halfChord2 <= 0.0)
  {
    return 0.0;
  }
  float halfChord = sqrt(halfChord2);
  float s0 = max(0.0, closest - halfChord);
  float s1 = min(len, closest + halfChord);
  if (s1 <= s0)
  {
    return 0.0;
  }
  vec2 P = A + s0 * u;
  vec2 Q = A + s1 * u;
  float crossPQ = P.x * Q.y - P.y * Q.x;
  return 0.5 * crossPQ - 0.5 * R * R * atan(crossPQ, dot(P, Q));
}

float edgeOcclusion(vec3 p, vec3 a, vec3 b)
{
  vec3 towards;
  float distance;
  float diskRadius;
  if (lightWedge.w != 0.0)
  {
    towards = lightWedge.xyz - p;
    distance = length(towards);
    if (distance <= lightRadius)
    {
      return 0.0;
    }
    towards /= distance;
    diskRadius = distance * lightRadius / sqrt(distance * distance - lightRadius * lightRadius);
  }
  else
  {
    towards = normalize(lightWedge.xyz);
    distance = 1.0;
    diskRadius = tan(lightRadius);
  }
  vec3 helper = abs(towards.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 e1 = normalize(cross(helper, towards));
  vec3 e2 = cross(towards, e1);

  vec3 from = a - p;
  vec3 to = b - p;
  float hFrom = dot(from, towards);
  float hTo = dot(to, towards);
  float hMin = 1e-6 * distance;
  if (hFrom < hMin && hTo < hMin)
  {
    return 0.0;
  }
  if (hFrom < hMin)
  {
    from += (to - from) * ((hMin - hFrom) / (hTo - hFrom));
    hFrom = hMin;
  }
  else if (hTo < hMin)
  {
    to += (from - to) * ((hMin - hTo) / (hFrom - hTo));
    hTo = hMin;
  }
  vec3 fromPlane = from * (distance / hFrom);
  vec3 toPlane = to * (distance / hTo);
  vec2 A = vec2(dot(fromPlane, e1), dot(fromPlane, e2));
  vec2 B = vec2(dot(toPlane, e1), dot(toPlane, e2));
  return insideCorrection(A, B, diskRadius) / (pi * diskRadius * diskRadius);
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = penumbraSceneDepth(pixel);
  float occlusion = edgeOcclusion(penumbraPointAt(pixel, depth, 0.0), edgeFromVS, edgeToVS);
  gl_FragData[0] = vec4(-edgeWeightVS * occlusion);
}
