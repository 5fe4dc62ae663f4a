#include "penumbraWedgeBound.h"

#include "penumbraSampleCounting.h"
#include "penumbraWedge.h"

#include <array>

namespace penumbra
{
namespace
{
/// How far the silhouette sector's planes are pushed out, as a share of the receivers' box.
constexpr double SectorMargin = 2e-4;

/// Where an edge's fragments can be: its Wedge, or else its LightPyramid, as half-spaces.
WedgeShape EdgeBound(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec4& light,
  double radius, Wedge& wedge, LightPyramid& pyramid, std::vector<HalfSpace>& halfSpaces)
{
  wedge = Wedge::Build(from, to, light, radius);
  if (wedge.Valid)
  {
    halfSpaces = wedge.HalfSpaces();
    return WedgeShape::Planes;
  }
  pyramid = LightPyramid::Build(from, to, light, radius);
  if (pyramid.Valid)
  {
    halfSpaces = pyramid.HalfSpaces();
    return WedgeShape::Pyramid;
  }
  halfSpaces.clear();
  return WedgeShape::FullViewport;
}

/// `shape`, or Enlarged for a wedge whose cut left a plane out (it may then reach beyond the
/// wedge, and drawn by front faces would miss the points of an eye inside it).
WedgeShape Loosened(WedgeShape shape, const ConvexPolyhedron& cut)
{
  return shape == WedgeShape::Planes && cut.CutsLeftOut > 0 ? WedgeShape::Enlarged : shape;
}

/// Appends `cut`'s points (w = 1), each followed by `attributes` and then `extra`, and its
/// triangles.
void AppendPolyhedron(const ConvexPolyhedron& cut, const float* attributes, int attributeCount,
  const float* extra, int extraCount, std::vector<float>& vertices,
  std::vector<std::uint32_t>& indices)
{
  const auto first =
    static_cast<std::uint32_t>(vertices.size() / (4 + attributeCount + extraCount));
  for (const glm::dvec3& point : cut.Points)
  {
    const float xyzw[4] = { static_cast<float>(point.x), static_cast<float>(point.y),
      static_cast<float>(point.z), 1.0f };
    vertices.insert(vertices.end(), xyzw, xyzw + 4);
    vertices.insert(vertices.end(), attributes, attributes + attributeCount);
    vertices.insert(vertices.end(), extra, extra + extraCount);
  }
  for (unsigned int index : cut.Triangles)
  {
    indices.push_back(first + index);
  }
}

/// EdgeBound's half-spaces for an edge cut to receivers, with, given the edge's two `faces`, its
/// silhouette sector's, pushed out by a fraction of the receivers' box (well beyond the depth
/// buffer's error) so that points on the caster's faces next to the edge stay inside.
WedgeShape CutBound(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec4& light,
  double radius, const Box& receivers, const EdgeFace* faces, bool frontFacesOnly,
  std::vector<HalfSpace>& halfSpaces)
{
  Wedge wedge;
  LightPyramid pyramid;
  const WedgeShape shape = EdgeBound(from, to, light, radius, wedge, pyramid, halfSpaces);
  if (faces && wedge.Valid)
  {
    const std::vector<HalfSpace> sector = SilhouetteSector(
      wedge, from, to, faces, 2, frontFacesOnly, SectorMargin * receivers.Diagonal());
    halfSpaces.insert(halfSpaces.end(), sector.begin(), sector.end());
  }
  return shape;
}
} // namespace

WedgeShape AppendWedgeBound(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec4& light,
  double radius, const Box& receivers, const EdgeFace* faces, bool frontFacesOnly,
  const float* attributes, int attributeCount, std::vector<float>& vertices,
  std::vector<std::uint32_t>& indices)
{
  const int floatsPerVertex = 4 + attributeCount;
  const auto first = static_cast<std::uint32_t>(vertices.size() / floatsPerVertex);
  auto emit = [&](const glm::dvec4& position)
  {
    const float xyzw[4] = { static_cast<float>(position.x), static_cast<float>(position.y),
      static_cast<float>(position.z), static_cast<float>(position.w) };
    vertices.insert(vertices.end(), xyzw, xyzw + 4);
    vertices.insert(vertices.end(), attributes, attributes + attributeCount);
  };
  auto emitShape = [&](const auto& corners, const auto& triangles)
  {
    for (const auto& corner : corners)
    {
      emit(glm::dvec4(corner));
    }
    for (unsigned int index : triangles)
    {
      indices.push_back(first + index);
    }
  };
  std::vector<HalfSpace> halfSpaces;
  if (receivers.Valid)
  {
    const WedgeShape shape =
      CutBound(from, to, light, radius, receivers, faces, frontFacesOnly, halfSpaces);
    const ConvexPolyhedron cut = ClipBox(receivers, halfSpaces);
    if (cut.Empty())
    {
      return WedgeShape::Nothing;
    }
    AppendPolyhedron(cut, attributes, attributeCount, nullptr, 0, vertices, indices);
    return Loosened(shape, cut);
  }
  Wedge wedge;
  LightPyramid pyramid;
  const WedgeShape shape = EdgeBound(from, to, light, radius, wedge, pyramid, halfSpaces);
  if (shape == WedgeShape::Planes)
  {
    emitShape(wedge.Vertices, Wedge::Triangles());
  }
  else if (shape == WedgeShape::Pyramid)
  {
    emitShape(pyramid.Vertices, LightPyramid::Triangles());
  }
  else
  {
    const std::array<glm::dvec4, 3> viewport = { glm::dvec4(-1, -1, 0, 2), glm::dvec4(-1, 3, 0, 2),
      glm::dvec4(3, -1, 0, 2) };
    emitShape(viewport, std::array<unsigned int, 3>{ 0, 1, 2 });
  }
  return shape;
}

WedgeShape AppendWedgeBoundInPieces(const glm::dvec3& from, const glm::dvec3& to,
  const glm::dvec4& light, double radius, const Box& receivers, const std::vector<Box>& pieces,
  const EdgeFace* faces, bool frontFacesOnly, const float* attributes, int attributeCount,
  std::vector<float>& vertices, std::vector<std::uint32_t>& indices)
{
  std::vector<HalfSpace> halfSpaces;
  const WedgeShape shape =
    CutBound(from, to, light, radius, receivers, faces, frontFacesOnly, halfSpaces);
  bool drawn = false;
  WedgeShape drawnShape = shape;
  for (const Box& piece : pieces)
  {
    const ConvexPolyhedron cut = ClipBox(piece, halfSpaces);
    if (cut.Empty())
    {
      continue;
    }
    if (Loosened(shape, cut) == WedgeShape::Enlarged)
    {
      drawnShape = WedgeShape::Enlarged;
    }
    const float bounds[6] = { static_cast<float>(piece.Min.x), static_cast<float>(piece.Min.y),
      static_cast<float>(piece.Min.z), static_cast<float>(piece.Max.x),
      static_cast<float>(piece.Max.y), static_cast<float>(piece.Max.z) };
    AppendPolyhedron(cut, attributes, attributeCount, bounds, 6, vertices, indices);
    drawn = true;
  }
  return drawn ? drawnShape : WedgeShape::Nothing;
}

} // namespace penumbra
