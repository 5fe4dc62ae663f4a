//VTK::System::Dec
#extension GL_ARB_shader_image_load_store : require
//VTK::Output::Dec
//PENUMBRA::SampleCount
// Per-light-sample counting (penumbraSampleCounting.cxx is the reference implementation and its
// tests): at the visible point p of this pixel, the edge changes the depth complexity of light
// sample i by -m(p) when the path on the light from its centre to the sample crosses the edge's
// projection from p, with the sign of the side the sample lies on. The changes of four samples
// are packed into one 32-bit word, 8 bits each, and added with one atomic; modular arithmetic
// keeps every field exact while the final count stays in [0, 255].
//
// The depth test must run before this shader: a fragment it rejects must not count.
//
// Counter texel t counts the pixel counterStride * t: every pixel, or at half
// resolution every other pixel in each direction, whose texel centre the wedges' vertex shader
// puts on that pixel's centre, so that the depth test (against the scene depth) and the point
// (from counting's depth at that pixel) are the same pixel's.
layout(early_fragment_tests) in;

//PENUMBRA::DepthPoint::Dec
uniform vec4 lightWedge;    // (centre, 1) or (direction towards the light, 0), wedge coordinates
// Positional: each sample's offset from the centre; directional: directions towards the light.
uniform vec4 lightSamples[PENUMBRA_SAMPLE_CAPACITY];
#ifdef PENUMBRA_SAMPLES_FILL_CAPACITY
const int sampleCount = PENUMBRA_SAMPLE_CAPACITY; // a constant bound unrolls the loops
#else
uniform int sampleCount; // samples set in lightSamples
#endif
uniform float sampleSpread; // the largest |sample - centre|, wedge coordinates
uniform int frontFacesOnly; // the counting rule of this caster's centre volume
// The share of its frame's coordinates' size by which p moves further towards the eye.
uniform float eyeFloatBias;
uniform int counterStride;  // pixels between counter texels: 1, or 2 at half resolution
layout(r32ui) uniform uimage2DArray counters;

flat in vec3 edgeFromVS;
flat in vec3 edgeToVS;
flat in vec3 faceNormal0VS;
flat in vec3 faceNormal1VS;
flat in vec2 faceSignsVS;
flat in vec3 centreNormalVS;
flat in vec3 pieceMinVS;
flat in vec3 pieceMaxVS;

float faceWeight(vec3 normal, vec3 fromEdge)
{
  float side = dot(normal, fromEdge);
  return frontFacesOnly != 0 ? (side > 0.0 ? 1.0 : 0.0) : sign(side);
}

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 pixel = texel * counterStride;
  float depth = penumbraSceneDepth(pixel);
  // The point as seen, on the eye's side of its own surface: depthTexture holds counting's
  // depth (penumbraCountingDepthFS.glsl), which the centre's volume was counted against.
  vec3 p = penumbraPointAt(pixel, depth, 0.0);
  vec3 towardsEye = penumbraPointAt(pixel, 0.0, 0.0) - p;
  p += towardsEye *
    (eyeFloatBias * (length(p) + length(p + towardsEye)) / max(length(towardsEye), 1e-30));
  // The view ray may cross the wedge's polyhedra in several receivers' pieces: only the piece
  // that holds p counts it (penumbra::AppendWedgeBoundInPieces; pieces are half-open).
  if (any(lessThan(p, pieceMinVS)) || any(greaterThanEqual(p, pieceMaxVS)))
  {
    discard;
  }

  vec3 fromP = edgeFromVS - p;
  int multiplicity = int(faceSignsVS.x * faceWeight(faceNormal0VS, -fromP) +
    faceSignsVS.y * faceWeight(faceNormal1VS, -fromP));
  if (multiplicity == 0)
  {
    discard; // not a silhouette seen from p
  }
  // No sample can cross where the plane (p, edge) passes farther from the centre than the
  // samples spread (penumbra::EdgePlaneMissesSamples, with the same margin).
  vec3 edge = edgeToVS - edgeFromVS;
  vec3 sampleSide = cross(fromP, edge);
  vec3 edgeToCentre = lightWedge.xyz - lightWedge.w * edgeFromVS;
  float centreSide = dot(edgeToCentre, sampleSide);
  if (abs(centreSide) >
    (sampleSpread + 1e-5 * length(edgeToCentre)) * length(sampleSide))
  {
    discard;
  }

  // Sides of the plane (p, edge) as p's side of the planes through the edge and each light point
  // (penumbraSampleCounting.cxx, SampleCrossing): the centre's plane, from the CPU in double, is
  // its shadow volume's side, so the sign agrees with the rasterized centre count.
  float dc = dot(fromP, centreNormalVS);
  vec3 towardsCentre = lightWedge.xyz - lightWedge.w * p;
  // The "in front and beyond the edge" test is homogeneous of degree 4 in lengths: scaled by
  // 1/|a - p| it stays inside float range for scenes of size 1e-6 or 1e6.
  float scale = 1.0 / max(length(fromP), 1e-30);
  float lightScale = lightWedge.w != 0.0 ? scale : 1.0;
  vec3 u = fromP * scale;
  vec3 e = edge * scale;
  vec3 n = cross(u, e);
  vec3 alongAxis = cross(e, n) * lightScale;
  float alongCentre = dot(towardsCentre, alongAxis);
  float beyond = lightWedge.w != 0.0 ? dot(n, n) : 0.0;

  // Each of SampleCrossing's four tests is linear in the sample s, so one matrix takes s to all
  // four (triple products rearranged): the side of the plane through the edge and s, the sides
  // of the edge's ends from the plane through p and the path to s, and the path's end along the
  // edge's normal. The ends' expressions depend on p, the end and the path alone, so edges that
  // share an end still decide it alike. For a positional light s is the centre plus an offset,
  // and the tests are the centre's (the paths' planes hold the centre) plus the offset's: no
  // float cancels the centre's distance, however far the light.
  vec3 pathFrom = cross(fromP, towardsCentre);
  vec3 pathTo = cross(edgeToVS - p, towardsCentre);
  mat4x3 toTests = mat4x3(sampleSide, pathFrom, pathTo, alongAxis);
  vec4 atCentre = lightWedge.w * vec4(centreSide, 0.0, 0.0, alongCentre);

  for (int word = 0; word * 4 < sampleCount; ++word)
  {
    uint changes = 0u;
    for (int field = 0; field < 4; ++field)
    {
      int i = word * 4 + field;
      if (i >= sampleCount)
      {
        break;
      }
      vec4 tests = lightSamples[i].xyz * toTests + atCentre; // (ds, sa, sb, along the normal)
      float ds = tests.x;
      bool crossesEdgePlane = dc != 0.0 && ds != 0.0 && (dc < 0.0) != (ds < 0.0);
      bool crossesPath = tests.y != 0.0 && tests.z != 0.0 && (tests.y < 0.0) != (tests.z < 0.0);
      float along = alongCentre + dc / (dc - ds) * (tests.w - alongCentre);
      bool nearer = lightWedge.w != 0.0 ? along >= beyond : along > 0.0;
      if (crossesEdgePlane && crossesPath && nearer)
      {
        int change = ds > 0.0 ? -multiplicity : multiplicity;
        changes += uint(change) << uint(8 * field);
      }
    }
    if (changes != 0u)
    {
      imageAtomicAdd(counters, ivec3(texel, word), changes);
    }
  }
}
