//VTK::System::Dec
//VTK::Output::Dec
// Depth, and where the pass asks for them (writePlanes), each fragment's triangle plane: its
// unit normal in world space and its offset about ShadowFrame::SurfacePlanesOrigin
// (penumbraSurfacePlaneDec.glsl reads it back), for counting's point
// (penumbraCountingDepthFS.glsl) and own-surface test (penumbraSurfaceSideDec.glsl). The
// position's derivatives across the pixel quad lie in the triangle's plane, and any
// interpolated position lies on it up to the rounding of its coordinates, however the
// rasterized depth is off. With no colour attachment drawn to, only the depth is kept.
uniform int writePlanes;
uniform mat3 normalToWorld;     // the inverse transpose of the mesh's matrix
uniform mat4 positionToOrigin;  // the mesh's matrix, about ShadowFrame::SurfacePlanesOrigin
const float noSurfacePlane = 3.0e38; // LightIntensityBuffer::NoSurfacePlane

in vec3 positionMC;

void main()
{
  if (writePlanes != 0)
  {
    vec3 n = normalToWorld * cross(dFdx(positionMC), dFdy(positionMC));
    float size = max(max(abs(n.x), abs(n.y)), abs(n.z));
    // (A triangle too small for its derivatives: no plane.)
    if (size > 0.0)
    {
      n = normalize(n / size);
      gl_FragData[0] = vec4(n, dot(n, (positionToOrigin * vec4(positionMC, 1.0)).xyz));
    }
    else
    {
      gl_FragData[0] = vec4(noSurfacePlane, 0.0, 0.0, 0.0);
    }
  }
}
