// No point of an opaque surface sees a light sample behind its own plane
// (penumbra::SeesAboveSurface). Counting needs this beside its counts: it takes the point a
// little off the surface, towards the eye, for float rounding, and from there the segment to a
// sample just behind the plane can pass the surface's next edge. The plane comes from the caster
// meshes' depth pass (LightIntensityBuffer::AttachClearedSurfacePlanes); where VTK drew the
// visible surface every sample is in front. For counting's shaders: it needs
// //PENUMBRA::DepthPoint::Dec with clipToLocal's origin at counting's reference, and
// PENUMBRA_SAMPLE_CAPACITY (CountingShader).
//PENUMBRA::SurfacePlane::Dec
// As the wedges' shader has them: the reference point (0, 0, 0, 1) or direction (x, y, z, 0),
// the samples' offsets from it or their directions, and their largest distance from it.
uniform vec4 lightWedge;
uniform vec4 lightSamples[PENUMBRA_SAMPLE_CAPACITY];
uniform float sampleSpread;

/// The world normal of the pixel's visible triangle, on the side seen from `towardsEye`; zero
/// where it is not known.
vec3 penumbraSeenSurfaceNormal(ivec2 pixel, vec3 towardsEye)
{
  vec3 n = penumbraSurfacePlane(pixel).xyz;
  if (n.x >= noSurfacePlane)
  {
    return vec3(0.0);
  }
  return dot(n, towardsEye) < 0.0 ? -n : n;
}

/// Whether the samples, within `spread` of the light point or direction `towardsReference` (from
/// the surface point), lie in front of the plane of unit normal n: 1 all, -1 none, 0 some (each
/// sample then tested alone). penumbra::SurfaceCutsLight.
int penumbraSurfaceCutsLight(vec3 n, vec3 towardsReference, float spread)
{
  float side = dot(n, towardsReference);
  float reach = 1.0001 * spread;
  return side > reach ? 1 : (side < -reach ? -1 : 0);
}

vec3 penumbraSurfaceNormal; // of the pixel's point, zero where unknown
vec3 penumbraSurfacePoint;  // the point, in clipToLocal's frame
int penumbraSurfaceCut;     // penumbraSurfaceCutsLight, or 1 where no normal is known

/// Finds the pixel's point and plane, for penumbraSampleInFront.
void penumbraFindSurface(ivec2 pixel)
{
  float depth = texelFetch(depthTexture, pixel, 0).r;
  penumbraSurfacePoint = penumbraPointAt(pixel, depth, 0.0);
  penumbraSurfaceNormal =
    penumbraSeenSurfaceNormal(pixel, penumbraPointAt(pixel, 0.0, 0.0) - penumbraSurfacePoint);
  penumbraSurfaceCut = penumbraSurfaceNormal == vec3(0.0) ? 1
    : penumbraSurfaceCutsLight(penumbraSurfaceNormal,
        lightWedge.xyz - lightWedge.w * penumbraSurfacePoint, sampleSpread);
}

/// Whether light sample i lies in front of the surface penumbraFindSurface found.
bool penumbraSampleInFront(int i)
{
  return penumbraSurfaceCut > 0 ||
    (penumbraSurfaceCut == 0 &&
      dot(penumbraSurfaceNormal, lightSamples[i].xyz - lightWedge.w * penumbraSurfacePoint) >
        0.0);
}
