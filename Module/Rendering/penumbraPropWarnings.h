/**
 * @file   penumbraPropWarnings.h
 * @brief  Which (prop, problem) pairs vtkSoftShadowPass has reported, so that each is reported
 *         once while its prop lives.
 *
 * Warnings about props are raised every frame the problem persists (the scene walk and the
 * shader edits run each frame); the user should read each once. A record holds its prop weakly:
 * once the prop is deleted, a new prop that VTK allocates at the same address is a new prop and
 * is reported again.
 */
#ifndef penumbraPropWarnings_h
#define penumbraPropWarnings_h

#include "vtkProp.h"
#include "vtkWeakPointer.h"

#include <map>
#include <string>
#include <utility>

namespace penumbra
{

class PropWarnings
{
public:
  /// True the first time `problem` is met for this live `prop`, false after.
  bool First(vtkProp* prop, const std::string& problem)
  {
    vtkWeakPointer<vtkProp>& reported = this->Reported[{ prop, problem }];
    if (reported && reported == prop)
    {
      return false;
    }
    reported = prop;
    return true;
  }

private:
  std::map<std::pair<vtkProp*, std::string>, vtkWeakPointer<vtkProp>> Reported;
};

} // namespace penumbra

#endif
