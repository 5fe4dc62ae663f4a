//VTK::System::Dec
// Haines' plateau primitives seen straight down the receiver plane's normal: plane coordinates
// (u, v) map onto the plateau texture and the plateau depth t (0 at the hard shadow, 1 at the
// penumbra's outer edge) becomes the depth, so that the depth test keeps the darkest primitive.
in vec3 plateauVertex; // (u, v, t)
uniform vec4 planeToClip; // (scale u, scale v, offset u, offset v)

void main()
{
  gl_Position = vec4(plateauVertex.xy * planeToClip.xy + planeToClip.zw, plateauVertex.z * 2.0 - 1.0, 1.0);
}
