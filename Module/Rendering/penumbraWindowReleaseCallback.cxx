#include "penumbraWindowReleaseCallback.h"

#include "vtkOpenGLRenderWindow.h"

#include <utility>

namespace penumbra
{

WindowReleaseCallback::WindowReleaseCallback(std::function<void(vtkWindow*)> release)
  : ReleaseResources(std::move(release))
{
}

WindowReleaseCallback::~WindowReleaseCallback()
{
  this->Release();
}

void WindowReleaseCallback::RegisterGraphicsResources(vtkOpenGLRenderWindow* window)
{
  if (this->VTKWindow == window)
  {
    return;
  }
  this->Release();
  this->VTKWindow = window;
  if (window)
  {
    window->RegisterGraphicsResources(this);
  }
}

void WindowReleaseCallback::Release()
{
  if (!this->VTKWindow || this->Releasing)
  {
    return;
  }
  this->Releasing = true;
  vtkOpenGLRenderWindow* window = this->VTKWindow;
  window->PushContext();
  this->ReleaseResources(window);
  window->UnregisterGraphicsResources(this);
  window->PopContext();
  this->VTKWindow = nullptr;
  this->Releasing = false;
}

} // namespace penumbra
