// The visible triangle's plane at a pixel, where the caster meshes' depth pass drew it
// (LightIntensityBuffer::AttachClearedSurfacePlanes): its world unit normal and its offset
// about ShadowFrame::SurfacePlanesOrigin. Shared through //PENUMBRA::SurfacePlane::Dec by the
// shaders that read it (ShadowFrame::SetSurfaceSideUniforms sets these).
uniform sampler2D surfacePlanes;
uniform int surfacePlanesDrawn; // 0: no plane is known anywhere
const float noSurfacePlane = 3.0e38; // LightIntensityBuffer::NoSurfacePlane

/// The pixel's plane (unit normal, offset), or one whose x is noSurfacePlane where none is known
/// (VTK drew the surface, or nothing).
vec4 penumbraSurfacePlane(ivec2 pixel)
{
  return surfacePlanesDrawn != 0 ? texelFetch(surfacePlanes, pixel, 0) : vec4(noSurfacePlane);
}
