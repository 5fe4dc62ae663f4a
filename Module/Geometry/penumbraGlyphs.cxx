#include "penumbraGlyphs.h"

#include <glm/gtc/constants.hpp>
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

/// A size an imposter can have: NaN, infinities, zero and negatives are refused.
bool IsPositiveAndFinite(double value)
{
  return value > 0.0 && std::isfinite(value);
}

/// An imposter's centre moved by the actor's matrix; false when the result is not finite.
bool WorldPosition(const glm::dmat4& actorMatrix, const glm::dvec3& centre, glm::dvec3& position)
{
  const glm::dvec4 world = actorMatrix * glm::dvec4(centre, 1.0);
  position = glm::dvec3(world) / world.w;
  return std::isfinite(position.x) && std::isfinite(position.y) && std::isfinite(position.z);
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
  // A direction whose squares underflow (1e-236) has no length to normalize by, in VTK 9.1's
  // vtkOpenGLGlyph3DMapper too, which draws no such glyph (found by the fuzzer).
  if (!std::isfinite(rotation[0][0] + rotation[0][1] + rotation[0][2] + rotation[1][0] +
        rotation[1][1] + rotation[1][2] + rotation[2][0] + rotation[2][1] + rotation[2][2]))
  {
    return false;
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

TriangleMesh ImposterSphereMesh(int segments)
{
  const int around = std::max(8, segments + segments % 2);
  const int rings = around / 2;
  const double pi = glm::pi<double>();
  TriangleMesh mesh;
  mesh.Points.push_back({ 0.0, 0.0, 1.0 }); // north pole
  for (int ring = 1; ring < rings; ++ring)
  {
    const double polar = pi * ring / rings;
    for (int k = 0; k < around; ++k)
    {
      const double azimuth = 2.0 * pi * k / around;
      mesh.Points.push_back({ std::sin(polar) * std::cos(azimuth),
        std::sin(polar) * std::sin(azimuth), std::cos(polar) });
    }
  }
  mesh.Points.push_back({ 0.0, 0.0, -1.0 }); // south pole
  const std::uint32_t south = static_cast<std::uint32_t>(mesh.Points.size() - 1);
  auto at = [around](int ring, int k)
  { return static_cast<std::uint32_t>(1 + (ring - 1) * around + (k % around)); };
  for (int k = 0; k < around; ++k)
  {
    mesh.Triangles.emplace_back(0u, at(1, k), at(1, k + 1));
    for (int ring = 1; ring + 1 < rings; ++ring)
    {
      mesh.Triangles.emplace_back(at(ring, k), at(ring + 1, k), at(ring + 1, k + 1));
      mesh.Triangles.emplace_back(at(ring, k), at(ring + 1, k + 1), at(ring, k + 1));
    }
    mesh.Triangles.emplace_back(at(rings - 1, k), south, at(rings - 1, k + 1));
  }
  return mesh;
}

bool ImposterSphereMatrix(
  const glm::dmat4& actorMatrix, const glm::dvec3& centre, double radius, glm::dmat4& matrix)
{
  glm::dvec3 position;
  if (!IsPositiveAndFinite(radius) || !WorldPosition(actorMatrix, centre, position))
  {
    return false;
  }
  matrix = glm::dmat4(radius);
  matrix[3] = glm::dvec4(position, 1.0);
  return true;
}

TriangleMesh ImposterStickMesh(int segments)
{
  const int around = std::max(8, segments);
  const double pi = glm::pi<double>();
  TriangleMesh mesh;
  for (const double z : { -0.5, 0.5 })
  {
    mesh.Points.push_back({ 0.0, 0.0, z }); // the cap's centre
    for (int k = 0; k < around; ++k)
    {
      const double azimuth = 2.0 * pi * k / around;
      mesh.Points.push_back({ std::cos(azimuth), std::sin(azimuth), z });
    }
  }
  const std::uint32_t bottom = 0, top = static_cast<std::uint32_t>(around + 1);
  auto rim = [around](std::uint32_t cap, int k)
  { return cap + 1 + static_cast<std::uint32_t>(k % around); };
  for (int k = 0; k < around; ++k)
  {
    mesh.Triangles.emplace_back(bottom, rim(bottom, k + 1), rim(bottom, k));
    mesh.Triangles.emplace_back(top, rim(top, k), rim(top, k + 1));
    mesh.Triangles.emplace_back(rim(bottom, k), rim(bottom, k + 1), rim(top, k + 1));
    mesh.Triangles.emplace_back(rim(bottom, k), rim(top, k + 1), rim(top, k));
  }
  return mesh;
}

bool ImposterStickMatrix(const glm::dmat4& actorMatrix, const glm::dvec3& centre,
  const glm::dvec3& orientation, double length, double radius, glm::dmat4& matrix)
{
  const glm::dvec3 axis = glm::transpose(glm::inverse(glm::dmat3(actorMatrix))) * orientation;
  const double axisLength = glm::length(axis);
  glm::dvec3 position;
  if (!IsPositiveAndFinite(length) || !IsPositiveAndFinite(radius) ||
    !IsPositiveAndFinite(axisLength) || !WorldPosition(actorMatrix, centre, position))
  {
    return false;
  }
  const glm::dvec3 along = axis / axisLength;
  // Any two unit vectors across the axis: the stick is round.
  const glm::dvec3 helper = std::abs(along.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  const glm::dvec3 across = glm::normalize(glm::cross(along, helper));
  matrix[0] = glm::dvec4(radius * across, 0.0);
  matrix[1] = glm::dvec4(radius * glm::cross(along, across), 0.0);
  matrix[2] = glm::dvec4(length * along, 0.0);
  matrix[3] = glm::dvec4(position, 1.0);
  return true;
}

} // namespace penumbra
