/**
 * @file   penumbraMatrices.h
 * @brief  VTK's matrices as GLM's: vtkMatrix4x4 is row-major, glm::dmat4 column-major.
 */
#ifndef penumbraMatrices_h
#define penumbraMatrices_h

#include "vtkMatrix4x4.h"

#include <glm/glm.hpp>

namespace penumbra
{

inline glm::dmat4 ToGlm(const vtkMatrix4x4* m)
{
  glm::dmat4 result;
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      result[column][row] = m->GetElement(row, column);
    }
  }
  return result;
}

} // namespace penumbra

#endif
