#include "penumbraGlyphs.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra
{
namespace
{
double ClampedToRange(const GlyphSettings& settings, double value)
{
  const double span = settings.Range[1] - settings.Range[0];
  const double clamped = std::min(std::max(value, settings.Range[0]), settings.Range[1]);
  return (clamped - settings.Range[0]) / (span == 0.0 ? 1.0 : span);
}

/// A rotation as VTK's vtkQuaterniond::ToMatrix3x3 builds it: the quaternion need not be unit.
glm::dmat3 RotationOf(const glm::dquat& q)
{
  const double norm = glm::length(q);
  return norm > 0.0 ? glm::mat3_cast(q / norm) : glm::dmat3(1.0);
}

glm::dquat OrientationQuaternion(int mode, const double* o)
{
  switch (mode)
  {
    case GlyphSettings::Rotation:
    {
      auto about = [](double degrees, const glm::dvec3& axis)
      { return glm::angleAxis(glm::radians(degrees), axis); };
      return about(o[2], { 0, 0, 1 }) * about(o[0], { 1, 0, 0 }) * about(o[1], { 0, 1, 0 });
    }
    case GlyphSettings::Quaternion:
      return glm::dquat(o[0], o[1], o[2], o[3]);
    default:
    {
      // Half-turn about the bisector of x and the direction: maps the glyph's x onto it.
      if (o[1] == 0.0 && o[2] == 0.0)
      {
        return o[0] < 0.0 ? glm::dquat(0.0, 0.0, 1.0, 0.0) : glm::dquat(1.0, 0.0, 0.0, 0.0);
      }
      const glm::dvec3 direction(o[0], o[1], o[2]);
      const glm::dvec3 bisector =
        glm::normalize(glm::dvec3(direction.x + glm::length(direction), direction.y, direction.z));
      return glm::dquat(0.0, bisector.x, bisector.y, bisector.z);
    }
  }
}
} // namespace

glm::dvec3 GlyphScale(const GlyphSettings& settings, const double* scaleTuple, int components)
{
  glm::dvec3 scale(1.0);
  if (scaleTuple && settings.Scaling)
  {
    if (settings.ScaleMode == GlyphSettings::ScaleByMagnitude)
    {
      double squared = 0.0;
      for (int i = 0; i < components; ++i)
      {
        squared += scaleTuple[i] * scaleTuple[i];
      }
      scale = glm::dvec3(std::sqrt(squared));
    }
    else if (settings.ScaleMode == GlyphSettings::ScaleByComponents && components == 3)
    {
      scale = glm::dvec3(scaleTuple[0], scaleTuple[1], scaleTuple[2]);
    }
    if (settings.Clamping && settings.ScaleMode != GlyphSettings::NoDataScaling)
    {
      for (int i = 0; i < 3; ++i)
      {
        scale[i] = ClampedToRange(settings, scale[i]);
      }
    }
  }
  scale *= settings.ScaleFactor;
  for (int i = 0; i < 3; ++i)
  {
    scale[i] = scale[i] == 0.0 ? 1.0e-10 : scale[i];
  }
  return scale;
}

bool GlyphMatrix(const GlyphSettings& settings, const glm::dvec3& position,
  const double* orientation, const glm::dvec3& scale, glm::dmat4& matrix)
{
  glm::dmat3 rotation(1.0);
  if (orientation)
  {
    const int count = settings.OrientationMode == GlyphSettings::Quaternion ? 4 : 3;
    if (!std::all_of(orientation, orientation + count, [](double v) { return std::isfinite(v); }))
    {
      return false;
    }
    rotation = RotationOf(OrientationQuaternion(settings.OrientationMode, orientation));
  }
  const glm::dvec3 size = settings.Scaling ? scale : glm::dvec3(1.0);
  matrix = glm::dmat4(1.0);
  for (int column = 0; column < 3; ++column)
  {
    matrix[column] = glm::dvec4(rotation[column] * size[column], 0.0);
  }
  matrix[3] = glm::dvec4(position, 1.0);
  return true;
}

} // namespace penumbra
