/**
 * @file   penumbraWindowReleaseCallback.h
 * @brief  Releases an object's GL resources when the window whose context holds them goes.
 *
 * A render window finalized or deleted releases its renderers and their passes, but not a pass
 * taken off its renderer (SetPass(nullptr)) meanwhile: set again, it would draw with the dead
 * context's textures and buffers. VTK's own objects outside the renderer register a callback with
 * the window for this (vtkOpenGLResourceFreeCallback); this is one such callback, written here
 * because Debian's VTK 9.1 does not install that header.
 */
#ifndef penumbraWindowReleaseCallback_h
#define penumbraWindowReleaseCallback_h

#if __has_include(<vtkOpenGLResourceFreeCallback.h>)
#include <vtkOpenGLResourceFreeCallback.h>
#else
class vtkOpenGLRenderWindow;

/// VTK 9.1's interface, as declared in its uninstalled vtkOpenGLResourceFreeCallback.h:
/// vtkOpenGLRenderWindow calls these virtual functions, so the declaration must stay identical.
class vtkGenericOpenGLResourceFreeCallback
{
public:
  vtkGenericOpenGLResourceFreeCallback()
  {
    this->VTKWindow = nullptr;
    this->Releasing = false;
  }
  virtual ~vtkGenericOpenGLResourceFreeCallback() = default;
  virtual void Release() = 0;
  virtual void RegisterGraphicsResources(vtkOpenGLRenderWindow* rw) = 0;
  bool IsReleasing() { return this->Releasing; }

protected:
  vtkOpenGLRenderWindow* VTKWindow;
  bool Releasing;
};
#endif

#include <functional>

class vtkWindow;

namespace penumbra
{

/**
 * Calls `release(window)`, with the window's context current, when the window it is registered
 * with releases its graphics resources (Finalize, deletion), when it is registered with another
 * window, and when it is destroyed: the owner's GL objects always go in the context that made
 * them.
 */
class WindowReleaseCallback final : public vtkGenericOpenGLResourceFreeCallback
{
public:
  explicit WindowReleaseCallback(std::function<void(vtkWindow*)> release);
  ~WindowReleaseCallback() override;
  WindowReleaseCallback(const WindowReleaseCallback&) = delete;
  WindowReleaseCallback& operator=(const WindowReleaseCallback&) = delete;

  /// Follows `window` (nullptr: none), releasing in the window followed until now first.
  void RegisterGraphicsResources(vtkOpenGLRenderWindow* window) override;
  /// Releases now in the window followed, if any, and stops following it.
  void Release() override;

private:
  std::function<void(vtkWindow*)> ReleaseResources;
};

} // namespace penumbra

#endif
