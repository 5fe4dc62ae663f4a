//VTK::System::Dec
// Depth only: the pass's depth framebuffer has no colour buffer to draw to.
void main()
{
}
