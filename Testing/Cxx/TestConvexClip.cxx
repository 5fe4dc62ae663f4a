// Unit tests of penumbra::ClipBox and the boxes of penumbraConvexClip.h, without a window.
//
// Random boxes cut by random half-spaces must give closed, outward, convex meshes whose points
// satisfy every half-space and whose volume matches a Monte Carlo estimate of the intersection;
// a half-space that excludes the box must leave nothing, and one that holds it must change
// nothing.
#include "penumbraCheck.h"
#include "penumbraConvexClip.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <utility>

using namespace penumbra;
using penumbra_test::Check;

namespace
{

bool InsideAll(const glm::dvec3& x, const Box& box, const std::vector<HalfSpace>& halfSpaces)
{
  if (glm::any(glm::lessThan(x, box.Min)) || glm::any(glm::greaterThan(x, box.Max)))
  {
    return false;
  }
  for (const HalfSpace& h : halfSpaces)
  {
    if (glm::dot(h.Normal, x) > h.Offset)
    {
      return false;
    }
  }
  return true;
}

/// Every directed edge has its reverse exactly once: a closed, consistently wound surface.
bool Closed(const ConvexPolyhedron& shape)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t < shape.Triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ shape.Triangles[t + k], shape.Triangles[t + (k + 1) % 3] }];
    }
  }
  for (const auto& entry : directed)
  {
    const auto reverse = directed.find({ entry.first.second, entry.first.first });
    if (entry.second != 1 || reverse == directed.end() || reverse->second != 1)
    {
      return false;
    }
  }
  return !directed.empty();
}

/// No point lies outside the plane of any triangle: convex, with outward triangles.
bool ConvexOutward(const ConvexPolyhedron& shape, double tolerance)
{
  for (std::size_t t = 0; t < shape.Triangles.size(); t += 3)
  {
    const glm::dvec3& a = shape.Points[shape.Triangles[t]];
    const glm::dvec3 n = glm::cross(
      shape.Points[shape.Triangles[t + 1]] - a, shape.Points[shape.Triangles[t + 2]] - a);
    for (const glm::dvec3& p : shape.Points)
    {
      if (glm::dot(n, p - a) > tolerance * glm::length(n))
      {
        return false;
      }
    }
  }
  return true;
}

void TestRandomCuts(std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int closed = 0, convex = 0, pointsInside = 0, volumesAgree = 0, nonEmpty = 0, empties = 0;
  const int trials = 300;
  for (int trial = 0; trial < trials; ++trial)
  {
    Box box;
    box.Valid = true;
    const glm::dvec3 centre(unit(rng), unit(rng), unit(rng));
    const glm::dvec3 half(0.2 + std::abs(unit(rng)), 0.2 + std::abs(unit(rng)), 0.05);
    box.Min = centre - half;
    box.Max = centre + half;
    std::vector<HalfSpace> halfSpaces;
    const int count = 1 + trial % 7;
    for (int k = 0; k < count; ++k)
    {
      const glm::dvec3 normal = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
      const glm::dvec3 through = centre + 0.6 * glm::dvec3(unit(rng), unit(rng), unit(rng)) * half;
      halfSpaces.push_back({ normal, glm::dot(normal, through) });
    }
    const ConvexPolyhedron shape = ClipBox(box, halfSpaces);
    // Monte Carlo volume of the intersection.
    const int samples = 20000;
    int inside = 0;
    std::uniform_real_distribution<double> zeroOne(0.0, 1.0);
    for (int s = 0; s < samples; ++s)
    {
      const glm::dvec3 x =
        box.Min + glm::dvec3(zeroOne(rng), zeroOne(rng), zeroOne(rng)) * (box.Max - box.Min);
      inside += InsideAll(x, box, halfSpaces);
    }
    const double boxVolume =
      (box.Max.x - box.Min.x) * (box.Max.y - box.Min.y) * (box.Max.z - box.Min.z);
    const double fraction = inside / static_cast<double>(samples);
    const double estimate = fraction * boxVolume;
    const double sigma = boxVolume * std::sqrt(std::max(fraction * (1 - fraction), 1e-4) / samples);
    if (shape.Empty())
    {
      ++empties;
      volumesAgree += estimate <= 4.0 * sigma;
      continue;
    }
    ++nonEmpty;
    closed += Closed(shape);
    convex += ConvexOutward(shape, 1e-9);
    bool allInside = true;
    for (const glm::dvec3& p : shape.Points)
    {
      glm::dvec3 nudged = glm::clamp(p, box.Min, box.Max);
      allInside = allInside && glm::length(nudged - p) < 1e-9;
      for (const HalfSpace& h : halfSpaces)
      {
        allInside = allInside && glm::dot(h.Normal, p) <= h.Offset + 1e-9;
      }
    }
    pointsInside += allInside;
    volumesAgree += std::abs(shape.Volume() - estimate) <= 4.0 * sigma;
  }
  std::printf("%d cuts: %d non-empty, %d empty\n", trials, nonEmpty, empties);
  Check(nonEmpty > trials / 3 && empties > 0, "the cuts cover both outcomes");
  Check(closed == nonEmpty, "every cut is closed and consistently wound");
  Check(convex == nonEmpty, "every cut is convex with outward triangles");
  Check(pointsInside == nonEmpty, "every point satisfies the box and every half-space");
  Check(volumesAgree == trials,
    "volumes match Monte Carlo within 4 sigma (" + std::to_string(volumesAgree) + " of " +
      std::to_string(trials) + ")");
}

void TestSpecialCases()
{
  Box box;
  box.Valid = true;
  box.Min = glm::dvec3(-1.0);
  box.Max = glm::dvec3(2.0, 1.0, 1.0);
  const ConvexPolyhedron whole = ClipBox(box, {});
  Check(Closed(whole) && std::abs(whole.Volume() - 12.0) < 1e-12, "no half-space: the box");
  Check(ClipBox(box, { { { 1, 0, 0 }, -1.5 } }).Empty(), "a half-space beside the box: nothing");
  const ConvexPolyhedron held = ClipBox(box, { { { 1, 0, 0 }, 5.0 } });
  Check(std::abs(held.Volume() - 12.0) < 1e-12 && held.Points.size() == 8,
    "a half-space that holds the box changes nothing");
  const ConvexPolyhedron faceOn = ClipBox(box, { { { 1, 0, 0 }, 2.0 } });
  Check(Closed(faceOn) && faceOn.Triangles.size() == 36,
    "a plane on a face of the box leaves one face there, not two");
  const ConvexPolyhedron halfBox = ClipBox(box, { { { 2, 0, 0 }, 1.0 } });
  Check(Closed(halfBox) && std::abs(halfBox.Volume() - 6.0) < 1e-12,
    "an unnormalized normal cuts where its plane is");
  Check(ClipBox(Box{}, {}).Empty(), "no box: nothing");
  const ConvexPolyhedron ignored = ClipBox(
    box, { { { 0, 0, 0 }, 1.0 }, { { std::nan(""), 0, 0 }, 0.0 }, { { 1, 0, 0 }, INFINITY } });
  Check(
    std::abs(ignored.Volume() - 12.0) < 1e-12, "zero, NaN and infinite half-spaces are ignored");
  const ConvexPolyhedron sliver = ClipBox(box, { { { 1, 0, 0 }, -1.0 + 1e-14 } });
  Check(sliver.Empty(), "a cut thinner than 1e-12 of the box leaves nothing");
}

void TestStableReceiverBox()
{
  Box ground;
  ground.Extend(glm::dvec3(-5, -5, 0), glm::dvec3(5, 5, 0));
  const Box first = StableReceiverBox(Box{}, ground);
  Check(first.Contains(ground) && first.Min.z < -0.1 && first.Max.z > 0.1,
    "a flat receiver gets a box with thickness around it");
  Box moved = ground;
  moved.Min.x += 0.3;
  moved.Max.x += 0.3;
  const Box second = StableReceiverBox(first, moved);
  Check(second.Min == first.Min && second.Max == first.Max,
    "a receiver moving within the kept box keeps it (no rebuild)");
  Box far = ground;
  far.Min.x += 20.0;
  far.Max.x += 20.0;
  const Box third = StableReceiverBox(first, far);
  Check(third.Contains(far) && !(third.Min == first.Min), "one that leaves it gets a new box");
  Box small;
  small.Extend(glm::dvec3(-0.1), glm::dvec3(0.1));
  Check(StableReceiverBox(first, small).Diagonal() < 0.5, "a much smaller scene gets a new box");
  Check(!StableReceiverBox(first, Box{}).Valid, "no receivers' box: no box to cut to");
  Box infinite;
  infinite.Extend(glm::dvec3(-INFINITY), glm::dvec3(1.0));
  Check(!StableReceiverBox(first, infinite).Valid, "an infinite box: no box to cut to");
}

/// DisjointPieces of random overlapping boxes: every random point of their union lies in exactly
/// one piece (half-open), and no point outside it in any; each receiver's piece box holds it with
/// a margin and stays put while it moves a little.
void TestDisjointPieces(std::mt19937& rng)
{
  std::uniform_real_distribution<double> coordinate(-4.0, 4.0), size(0.1, 3.0), unit(0.0, 1.0);
  int trials = 0, wrongCount = 0, outsideCounted = 0, pieceTotal = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    std::vector<Box> boxes(1 + trial % 6);
    for (Box& box : boxes)
    {
      const glm::dvec3 corner(coordinate(rng), coordinate(rng), coordinate(rng));
      box.Extend(corner, corner + glm::dvec3(size(rng), size(rng), size(rng)));
    }
    const std::vector<Box> pieces = DisjointPieces(boxes);
    pieceTotal += static_cast<int>(pieces.size());
    for (int sample = 0; sample < 400; ++sample)
    {
      const glm::dvec3 p(
        coordinate(rng) + unit(rng), coordinate(rng) + unit(rng), coordinate(rng) + unit(rng));
      auto holds = [&p](const Box& box, bool halfOpen)
      {
        return glm::all(glm::lessThanEqual(box.Min, p)) &&
          (halfOpen ? glm::all(glm::lessThan(p, box.Max))
                    : glm::all(glm::lessThanEqual(p, box.Max)));
      };
      const bool inUnion =
        std::any_of(boxes.begin(), boxes.end(), [&](const Box& box) { return holds(box, true); });
      const auto count = std::count_if(
        pieces.begin(), pieces.end(), [&](const Box& piece) { return holds(piece, true); });
      wrongCount += inUnion ? count != 1 : 0;
      outsideCounted += !inUnion && count != 0;
    }
    ++trials;
  }
  std::printf("     %d unions of 1 to 6 boxes: %d pieces, %d points counted other than once, %d "
              "outside counted\n",
    trials, pieceTotal, wrongCount, outsideCounted);
  Check(wrongCount == 0, "every point of the union lies in exactly one piece");
  Check(outsideCounted == 0, "no point outside the union lies in a piece");

  Box a, b;
  a.Extend(glm::dvec3(0), glm::dvec3(2));
  b.Extend(glm::dvec3(1), glm::dvec3(3));
  Check(DisjointPieces({ a, b }, 1).size() == 1 && DisjointPieces({ a, b }, 1)[0].Max.x == 3.0,
    "more boxes than allowed: their bounds, as one piece");
  Check(DisjointPieces({ Box{} }).empty(), "no valid box: no piece");
  Check(DisjointPieces({ a }).size() == 1, "one box: itself");

  Box receivers, ground;
  receivers.Extend(glm::dvec3(-6, -2, -6), glm::dvec3(6, 4, 6));
  ground.Extend(glm::dvec3(-5, 0, -5), glm::dvec3(5, 0, 5));
  const Box piece = ReceiverPieceBox(receivers, ground);
  const double margin = 0.01 * receivers.Diagonal();
  Check(piece.Min.y <= -margin && piece.Max.y >= margin && piece.Max.y < 0.1 * receivers.Diagonal(),
    "a flat receiver's piece is a thin slab around it");
  Box nudged = ground;
  nudged.Min.y = nudged.Max.y = 1e-4;
  const Box same = ReceiverPieceBox(receivers, nudged);
  Check(
    same.Min == piece.Min && same.Max == piece.Max, "a receiver moved a little keeps its piece");
  Check(!ReceiverPieceBox(Box{}, ground).Valid, "no receivers' box: no piece");
}

/// TransformedBox against Arvo's closed form for an affine matrix (the centre moved, the half
/// size through the absolute linear part), for random rotations, scales (mirrors among them)
/// and translations; random points of the box must land inside the result.
void TestTransformedBox(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  double worstFace = 0.0;
  int outside = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    Box box;
    const glm::dvec3 corner(5.0 * u(rng), 5.0 * u(rng), 5.0 * u(rng));
    box.Extend(corner, corner + glm::dvec3(unit(rng), unit(rng), trial % 10 ? unit(rng) : 0.0));
    glm::dmat4 matrix(1.0);
    for (int column = 0; column < 4; ++column)
    {
      for (int row = 0; row < 3; ++row)
      {
        matrix[column][row] = 3.0 * u(rng);
      }
    }
    const Box moved = TransformedBox(box, matrix);
    const glm::dvec3 centre(matrix * glm::dvec4(0.5 * (box.Min + box.Max), 1.0));
    const glm::dvec3 half = 0.5 * (box.Max - box.Min);
    glm::dvec3 reach(0.0);
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int k = 0; k < 3; ++k)
      {
        reach[axis] += std::abs(matrix[k][axis]) * half[k];
      }
    }
    const glm::dvec3 faceError =
      glm::max(glm::abs(moved.Min - (centre - reach)), glm::abs(moved.Max - (centre + reach)));
    worstFace =
      penumbra_test::Worse(worstFace, std::max({ faceError.x, faceError.y, faceError.z }));
    for (int k = 0; k < 20; ++k)
    {
      const glm::dvec3 t(unit(rng), unit(rng), unit(rng));
      const glm::dvec3 p(matrix * glm::dvec4(box.Min + t * (box.Max - box.Min), 1.0));
      outside += glm::any(glm::lessThan(p, moved.Min - 1e-9)) ||
        glm::any(glm::greaterThan(p, moved.Max + 1e-9));
    }
  }
  std::printf("     transformed boxes: faces off the closed form by %.2e at most, %d points "
              "outside\n",
    worstFace, outside);
  Check(worstFace < 1e-9, "a transformed box is the tight box of the moved box (Arvo)");
  Check(outside == 0, "points of a box land inside its transformed box");
  Check(!TransformedBox(Box{}, glm::dmat4(1.0)).Valid, "an invalid box stays invalid");
}

} // namespace

/// Nearly parallel planes, as a small light's wedge has (its front and back planes about 2r/d
/// apart), crossing inside boxes near and far from the origin: the cut is closed, and ClipBox
/// need not leave a plane out. The two faces sharing a side computed its crossing from opposite
/// ends, and points differing in the last bits opened 2.7% of such cuts at 1e-5 radians (a
/// review); 0.2% at 1e-3.
void TestNearlyParallelCuts(std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int cuts = 0, open = 0, leftOut = 0;
  for (const double offset : { 0.0, 1e3, 1e6 })
  {
    for (const double angle : { 1e-3, 1e-4, 1e-5 })
    {
      for (int k = 0; k < 500; ++k)
      {
        const glm::dvec3 origin(offset, 0.7 * offset, -0.3 * offset);
        const Box box{ true, origin - glm::dvec3(5.0), origin + glm::dvec3(5.0, 40.0, 5.0) };
        const glm::dvec3 n = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        const glm::dvec3 through = origin + glm::dvec3(unit(rng), 10.0 * unit(rng), unit(rng));
        const glm::dvec3 tilt = glm::normalize(glm::cross(n, glm::dvec3(unit(rng), 1.0, 0.3)));
        const glm::dvec3 m = glm::normalize(n + angle * tilt);
        const ConvexPolyhedron shape = ClipBox(
          box, { { n, glm::dot(n, through) }, { -m, -glm::dot(m, through) + 1e-3 * unit(rng) } });
        ++cuts;
        open += !shape.Empty() && !Closed(shape);
        leftOut += shape.CutsLeftOut > 0;
      }
    }
  }
  std::printf(
    "     nearly parallel cuts: %d, %d open, %d with a cut left out\n", cuts, open, leftOut);
  Check(open == 0, "nearly parallel cuts are closed");
  Check(leftOut <= cuts / 500, "nearly parallel cuts seldom leave a plane out");
}

int main()
{
  std::mt19937 rng(11);
  TestNearlyParallelCuts(rng);
  TestSpecialCases();
  TestStableReceiverBox();
  TestRandomCuts(rng);
  TestDisjointPieces(rng);
  TestTransformedBox(rng);
  return penumbra_test::Finish();
}
