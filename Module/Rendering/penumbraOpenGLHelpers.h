/**
 * @file    penumbraOpenGLHelpers.h
 * @brief   The GL plumbing every stage of vtkSoftShadowPass shares, written once: readying and
 *          reporting its shader programs, binding a vertex array to a program, writing a
 *          buffer in place, the full-screen triangle, the scoped saver of the state it changes,
 *          scissor boxes and texture sizes.
 */
#ifndef penumbraOpenGLHelpers_h
#define penumbraOpenGLHelpers_h

#include "penumbraCulling.h" // for PixelRect

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLState.h" // for the scoped savers
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkSmartPointer.h"

#include <cstddef>
#include <functional>
#include <set>
#include <string>
#include <vector>

class vtkObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace penumbra
{

/// Bytes a texture of 32-bit components holds on the GPU (0 before it is allocated).
std::size_t TextureBytes(vtkTextureObject* texture);

/// Points `texture` at `window` and says whether the caller must allocate it (again) for
/// `width` x `height` x `depth` texels of `components`: true when it has no storage yet, the
/// window changed (which releases it) or its shape differs; the filters are then set to
/// `filter` (a vtkTextureObject filter) for the new storage.
bool TextureNeedsAllocation(vtkTextureObject* texture, vtkOpenGLRenderWindow* window, int width,
  int height, int depth, int components, int filter);

/**
 * Releases `framebuffer` in `window` and puts a new one in its place. VTK 9.1's framebuffer keeps
 * a plain pointer to its window (SetContext(nullptr) leaves it): a released one would go on
 * claiming a window that is gone, or one made later at its address, and skip taking the new
 * window's context.
 */
void ReleaseFramebuffer(
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, vtkWindow* window);

/// Readies the pass's shader programs. One that does not build is reported once, with what the
/// pass does instead, and nullptr returned.
class ShaderPrograms
{
public:
  vtkObject* Owner = nullptr; ///< the pass, for the errors
  vtkShaderProgram* Ready(vtkOpenGLRenderWindow* window, const char* vertexShader,
    const char* fragmentShader, const char* name, const char* instead);
  /// Binds a program Ready returned before, after other programs were drawn with; false (and
  /// reported once under `name`) when the shader cache cannot bind it.
  bool Bind(vtkOpenGLRenderWindow* window, vtkShaderProgram* program, const char* name);

private:
  std::set<std::string> Failed;
};

/// A vertex attribute in a buffer of floats: its name in the shader, offset and size in floats.
struct VertexAttribute
{
  const char* Name;
  int Offset;
  int Components;
};

/// Binds `vao` for `program`. When the program is not `boundProgram` (VTK's VAOs hold one
/// program's attribute locations), the VAO is first released and pointed at `attributes` of
/// `buffer`, floats packed up to the last attribute's end; `boundProgram` then remembers it.
void BindVertexArray(vtkOpenGLVertexArrayObject* vao, vtkShaderProgram* program,
  vtkShaderProgram*& boundProgram, vtkOpenGLBufferObject* buffer,
  const std::vector<VertexAttribute>& attributes);

/// Gives `buffer` storage for `bytes` and has `write` fill it in the memory the driver maps
/// for it, so that large buffers are written once instead of built in a copy of the caller's
/// that the upload then copies again (a caster's doubled points: 64 MB at 4M triangles, no
/// longer written twice nor kept for data that changes). Where the buffer cannot be mapped, or
/// its contents were lost while mapped (the unmap says so), `write` fills a copy that is
/// uploaded. False when the buffer cannot be given storage of that type.
bool WriteBuffer(vtkOpenGLBufferObject* buffer, vtkOpenGLBufferObject::ObjectType type,
  std::size_t bytes, const std::function<void(void*)>& write);

/// A full-screen triangle at the far plane, drawn by the resolve, horizon and plateau passes.
class FullScreenTriangle
{
public:
  /// One program's vertex array for the triangle; rebound when the triangle was uploaded again.
  struct VAO
  {
    vtkNew<vtkOpenGLVertexArrayObject> Array;
    vtkShaderProgram* Program = nullptr;
    std::size_t Generation = 0;
    void ReleaseGraphicsResources();
  };
  void Draw(vtkShaderProgram* program, VAO& vao);
  void ReleaseGraphicsResources();

private:
  vtkNew<vtkOpenGLBufferObject> Buffer;
  std::size_t Generation = 1;
};

/// Saves the GL state the pass's drawing changes and restores it when it goes out of scope,
/// through vtkOpenGLState: VTK's scoped savers for what they cover (enables, the scissor test
/// and box, masks, depth function, blend functions, clear colour, viewport), and the stencil
/// functions, operations and write masks of both faces, the culled face, the blend equations and
/// the clear depth beside them, which VTK 9.1 has none for.
class ScopedDrawState
{
public:
  explicit ScopedDrawState(vtkOpenGLState* state);
  ~ScopedDrawState();
  ScopedDrawState(const ScopedDrawState&) = delete;
  ScopedDrawState& operator=(const ScopedDrawState&) = delete;

private:
  vtkOpenGLState* State;
  vtkOpenGLState::ScopedglEnableDisable Blend, StencilTest, DepthTest, CullFace, DepthClamp,
    ScissorTest;
  vtkOpenGLState::ScopedglScissor ScissorBox;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
  vtkOpenGLState::ScopedglColorMask ColorMask;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglDepthFunc DepthFunc;
  vtkOpenGLState::ScopedglClearColor ClearColor;
  vtkOpenGLState::ScopedglViewport Viewport;
  /// Front and back: function, reference, value mask, then fail, depth fail, depth pass, then
  /// the write mask.
  int Stencil[2][7];
  int CullFaceMode = 0, BlendEquationRGB = 0, BlendEquationAlpha = 0;
  double ClearDepth = 1.0;
};

/// Pushes the framebuffer bindings (draw and read) and pops them when it goes out of scope.
class ScopedFramebufferBindings
{
public:
  explicit ScopedFramebufferBindings(vtkOpenGLState* state)
    : State(state)
  {
    state->PushFramebufferBindings();
  }
  ~ScopedFramebufferBindings() { this->State->PopFramebufferBindings(); }
  ScopedFramebufferBindings(const ScopedFramebufferBindings&) = delete;
  ScopedFramebufferBindings& operator=(const ScopedFramebufferBindings&) = delete;

private:
  vtkOpenGLState* State;
};

/// Sets the scissor box to `rect` (the scissor test is the caller's).
void SetScissor(vtkOpenGLState* state, const PixelRect& rect);

} // namespace penumbra

#endif
