/**
 * @file   penumbraPropWarnings.h
 * @brief  Which (object, problem) pairs vtkSoftShadowPass has reported, so that each is reported
 *         once while its object (a prop, a light, a data object) lives.
 *
 * Warnings about props and lights are raised every frame the problem persists (the scene walk,
 * the shader edits and the lights' checks run each frame); the user should read each once. A
 * record holds its object weakly: once the object is deleted, a new one that VTK allocates at
 * the same address is a new object and is reported again, and the records of deleted objects
 * are dropped as new ones come.
 */
#ifndef penumbraPropWarnings_h
#define penumbraPropWarnings_h

#include "vtkDataObject.h"
#include "vtkLight.h"
#include "vtkProp.h"
#include "vtkWeakPointer.h"

#include <cstddef>
#include <map>
#include <string>
#include <utility>

namespace penumbra
{

template <typename T>
class WarnedOnce
{
public:
  /// True the first time `problem` is met for this live `object`, false after.
  bool First(T* object, const std::string& problem)
  {
    vtkWeakPointer<T>& reported = this->Reported[{ object, problem }];
    if (reported && reported == object)
    {
      return false;
    }
    reported = object;
    this->DropDeleted();
    return true;
  }

  /// Whether `problem` was reported for this live `object`.
  bool Said(T* object, const std::string& problem) const
  {
    auto found = this->Reported.find({ object, problem });
    return found != this->Reported.end() && found->second && found->second == object;
  }

private:
  /// Every 64 new records, the records of deleted objects go: the map stays as large as the
  /// live objects warned about, not as all that ever were (a light added every frame).
  void DropDeleted()
  {
    if (++this->Added % 64 != 0)
    {
      return;
    }
    for (auto it = this->Reported.begin(); it != this->Reported.end();)
    {
      it = it->second ? std::next(it) : this->Reported.erase(it);
    }
  }

  std::map<std::pair<T*, std::string>, vtkWeakPointer<T>> Reported;
  std::size_t Added = 0;
};

using PropWarnings = WarnedOnce<vtkProp>;
using LightWarnings = WarnedOnce<vtkLight>;
using DataWarnings = WarnedOnce<vtkDataObject>;

} // namespace penumbra

#endif
