//VTK::System::Dec
//VTK::Output::Dec
// Depth, and where the pass asks for them (writeNormals), each fragment's triangle normal in
// world space, octahedral (penumbra::OctahedralEncode), for counting's own-surface test
// (penumbraSurfaceSideDec.glsl): the position's derivatives across the pixel quad lie in the
// triangle's plane. With no colour attachment drawn to, only the depth is kept.
uniform int writeNormals;
uniform mat3 normalToWorld; // the inverse transpose of the mesh's matrix

in vec3 positionMC;

vec2 octahedral(vec3 n)
{
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 folded = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return n.z >= 0.0 ? n.xy : folded;
}

void main()
{
  if (writeNormals != 0)
  {
    vec3 n = normalToWorld * cross(dFdx(positionMC), dFdy(positionMC));
    // (A triangle too small for its derivatives: no plane.)
    gl_FragData[0] = vec4(any(notEqual(n, vec3(0.0))) ? octahedral(n) : vec2(3.0e38), 0.0, 0.0);
  }
}
