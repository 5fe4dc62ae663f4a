#include "penumbraDeepCounts.h"

#include "penumbraOpenGLHelpers.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <algorithm>

namespace penumbra
{

void DeepCounts::Bind(
  vtkOpenGLRenderWindow* window, vtkShaderProgram* program, int unit, vtkLight* light)
{
  if (TextureNeedsAllocation(this->Report, window, Slots, 1, 1, 1, vtkTextureObject::Nearest))
  {
    this->Report->SetInternalFormat(GL_R32UI);
    this->Report->SetFormat(GL_RED_INTEGER);
    this->Report->SetDataType(GL_UNSIGNED_INT);
    std::vector<GLuint> zeros(Slots, 0);
    this->Pending.clear();
    if (!this->Report->Create2DFromRaw(Slots, 1, 1, VTK_UNSIGNED_INT, zeros.data()))
    {
      program->SetUniformi("deepCountSlot", -1);
      return;
    }
  }
  auto slot = std::find(this->Pending.begin(), this->Pending.end(), light);
  if (slot == this->Pending.end() && this->Pending.size() < Slots)
  {
    slot = this->Pending.insert(this->Pending.end(), light);
  }
  const int index =
    slot == this->Pending.end() ? -1 : static_cast<int>(slot - this->Pending.begin());
  glBindImageTexture(unit, this->Report->GetHandle(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  program->SetUniformi("deepCounts", unit);
  program->SetUniformi("deepCountSlot", index);
  program->SetUniformi("reportedCount", ReportedCount);
}

void DeepCounts::Unbind(int unit)
{
  glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

void DeepCounts::ReadBack(vtkOpenGLRenderWindow* window)
{
  this->Deepest.clear();
  if (this->Report->GetContext() != window || !this->Report->GetHandle())
  {
    this->Pending.clear();
    return;
  }
  std::vector<GLuint> deepest(Slots, 0);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  this->Report->Activate();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, deepest.data());
  this->Report->Deactivate();
  const GLuint zero = 0;
  glClearTexImage(this->Report->GetHandle(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  for (std::size_t slot = 0; slot < this->Pending.size(); ++slot)
  {
    if (deepest[slot] > 0)
    {
      this->Deepest[this->Pending[slot]] = static_cast<int>(deepest[slot]);
    }
  }
  this->Pending.clear();
}

int DeepCounts::Take(vtkOpenGLRenderWindow* window, vtkLight* light)
{
  if (!this->Pending.empty())
  {
    this->ReadBack(window);
  }
  const auto found = this->Deepest.find(light);
  if (found == this->Deepest.end())
  {
    return 0;
  }
  const int deepest = found->second;
  this->Deepest.erase(found);
  return deepest;
}

std::size_t DeepCounts::GraphicsMemoryBytes() const
{
  return TextureBytes(this->Report);
}

void DeepCounts::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Report->ReleaseGraphicsResources(window);
  this->Pending.clear();
  this->Deepest.clear();
}

} // namespace penumbra
