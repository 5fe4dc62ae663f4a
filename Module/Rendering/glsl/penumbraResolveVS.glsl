//VTK::System::Dec
// Full-screen triangle at the far plane: with depth test GREATER it covers exactly the pixels
// where the scene has geometry, so background pixels keep their cleared, fully lit value.
in vec2 ndCoordIn;

void main()
{
  gl_Position = vec4(ndCoordIn, 1.0, 1.0);
}
