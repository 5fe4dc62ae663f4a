#include "vtkPlanarSoftShadowFilter.h"

#include "penumbraLightSamples.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <clipper.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

vtkStandardNewMacro(vtkPlanarSoftShadowFilter);

namespace
{

using Paths = ClipperLib::Paths;

// Exact predicates and exact (lazy) constructions: the vertices are Clipper's integers, and where
// rounding makes two rings cross by a unit the crossing point must be exact too, or inserting the
// next constraint can walk a corrupted triangulation (measured: a crash with inexact ones).
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<vtkIdType, Kernel>;
using InfoFace = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using ConstrainedFace = CGAL::Constrained_triangulation_face_base_2<Kernel, InfoFace>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, ConstrainedFace>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_intersections_tag>;

/// Clipper's 64-bit fast path holds for |coordinate| <= 2^30; the shadow's extent maps to 1e9.
constexpr double IntegerExtent = 1e9;
/// A positional light's sample sees casters only below this fraction of its height: a point at
/// the sample's height would project to infinity, one at 99% lands 100 times farther out.
constexpr double MaximumHeightFraction = 0.99;

/// A triangulation point in doubles (exact coordinates rounded once).
glm::dvec2 ToDouble(const CDT::Point& p)
{
  return glm::dvec2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
}

/// A caster polygon in plane coordinates: (u, v) in the plane's basis and height h above it.
using Polygon3 = std::vector<glm::dvec3>;

/// Keeps the part of `poly` where sign * (h - level) >= 0 (Sutherland-Hodgman on one plane).
Polygon3 ClipHeight(const Polygon3& poly, double level, double sign)
{
  Polygon3 out;
  const size_t n = poly.size();
  for (size_t i = 0; i < n; ++i)
  {
    const glm::dvec3& a = poly[i];
    const glm::dvec3& b = poly[(i + 1) % n];
    const double da = sign * (a.z - level), db = sign * (b.z - level);
    if (da >= 0.0)
    {
      out.push_back(a);
    }
    if ((da >= 0.0) != (db >= 0.0))
    {
      const double t = da / (da - db);
      glm::dvec3 p = a + t * (b - a);
      p.z = level; // exactly on the plane, so that the projection cannot overshoot
      out.push_back(p);
    }
  }
  return out;
}

/// Nonzero winding of all paths around p (holes wind the other way and cancel).
bool Inside(const Paths& paths, const glm::dvec2& p)
{
  int winding = 0;
  for (const auto& path : paths)
  {
    const size_t n = path.size();
    for (size_t i = 0; i < n; ++i)
    {
      const double ax = double(path[i].X), ay = double(path[i].Y);
      const double bx = double(path[(i + 1) % n].X), by = double(path[(i + 1) % n].Y);
      const double side = (bx - ax) * (p.y - ay) - (p.x - ax) * (by - ay);
      if (ay <= p.y)
      {
        winding += (by > p.y && side > 0.0);
      }
      else
      {
        winding -= (by <= p.y && side < 0.0);
      }
    }
  }
  return winding != 0;
}

Paths Boolean(ClipperLib::ClipType type, const Paths& a, const Paths& b)
{
  ClipperLib::Clipper clipper;
  clipper.AddPaths(a, ClipperLib::ptSubject, true);
  clipper.AddPaths(b, ClipperLib::ptClip, true);
  Paths out;
  clipper.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

/**
 * Samples of the light in plane coordinates (u, v, h): positions (w = 1) of a positional
 * light's disk, or unit directions towards a directional light (w = 0). Returns those above
 * the plane; `dropped` counts the others.
 */
std::vector<glm::dvec4> SampleLight(const glm::dvec3& light, bool positional, double radius,
  int count, int pattern, const glm::dvec3& target, const glm::dvec3& origin,
  const glm::dmat3& toPlane, int& dropped)
{
  const glm::dvec4 centre(light, positional ? 1.0 : 0.0);
  const std::vector<glm::dvec4> world = count <= 1 || radius <= 0.0
    ? std::vector<glm::dvec4>{ centre }
    : penumbra::PlaceOnLight(centre, radius,
        pattern == vtkPlanarSoftShadowFilter::SUNFLOWER ? penumbra::SunflowerPoints(count)
                                                        : penumbra::PolarRingPoints(count),
        target);
  std::vector<glm::dvec4> samples;
  dropped = 0;
  for (const glm::dvec4& w : world)
  {
    const glm::dvec3 p = positional ? toPlane * (glm::dvec3(w) - origin) : toPlane * glm::dvec3(w);
    // A directional sample must come down at a real angle, or its projection is unbounded.
    if (!std::isfinite(p.x + p.y + p.z) || p.z <= (positional ? 0.0 : 1e-9))
    {
      ++dropped;
      continue;
    }
    samples.emplace_back(p, w.w);
  }
  return samples;
}

/// Projects the part of a caster polygon above the plane (and, for a positional sample, below
/// MaximumHeightFraction of its height) onto the plane from `sample`. False when nothing is left.
bool Project(const Polygon3& poly, const glm::dvec4& sample, std::vector<glm::dvec2>& out)
{
  out.clear();
  Polygon3 part = ClipHeight(poly, 0.0, 1.0);
  if (part.size() < 3)
  {
    return false;
  }
  if (sample.w != 0.0)
  {
    part = ClipHeight(part, MaximumHeightFraction * sample.z, -1.0);
    if (part.size() < 3)
    {
      return false;
    }
    const glm::dvec2 s(sample);
    for (const glm::dvec3& q : part)
    {
      out.push_back(s + (glm::dvec2(q) - s) * (sample.z / (sample.z - q.z)));
    }
  }
  else
  {
    const glm::dvec2 d(sample);
    for (const glm::dvec3& q : part)
    {
      out.push_back(glm::dvec2(q) - d * (q.z / sample.z));
    }
  }
  return true;
}

/// What RequestData hands to the output: triangles in plane coordinates and their data.
struct Result
{
  std::vector<glm::dvec2> Points;
  std::vector<float> Intensity;
  std::vector<vtkIdType> Triangles;
  std::vector<unsigned char> Regions;
};

/// Points (or directions) of the light's samples in plane coordinates, and the integer frame
/// Clipper works in: the bounds of every projection (and the lit margin) map to IntegerExtent,
/// so coordinates are resolved to about 1e-9 of the shadow's extent.
struct IntegerFrame
{
  glm::dvec2 Lo{ 0.0 }, Hi{ 0.0 }; ///< plane coordinates, the lit margin included
  glm::dvec2 Centre{ 0.0 };
  double Scale = 1.0;

  ClipperLib::IntPoint ToInt(const glm::dvec2& p) const
  {
    const glm::dvec2 q = (p - this->Centre) * this->Scale;
    return ClipperLib::IntPoint(std::llround(q.x), std::llround(q.y));
  }
};

/// The plane's frame: origin, unit normal and in-plane basis, and world to (u, v, h).
struct PlaneFrame
{
  glm::dvec3 Origin{ 0.0 }, Normal{ 0.0, 0.0, 1.0 }, E1{ 1, 0, 0 }, E2{ 0, 1, 0 };
  glm::dmat3 ToPlane{ 1.0 };
};

/// The input's polygons and strip triangles strictly above the plane, in plane coordinates.
/// Cells with a non-finite or invalid point are dropped and counted; lo and hi bound the finite
/// points in world space.
std::vector<Polygon3> CasterPolygons(vtkPolyData* input, const PlaneFrame& plane, glm::dvec3& lo,
  glm::dvec3& hi, vtkIdType& droppedCells)
{
  vtkPoints* inPoints = input->GetPoints();
  const vtkIdType numPoints = inPoints->GetNumberOfPoints();
  std::vector<glm::dvec3> local(numPoints);
  std::vector<char> finite(numPoints);
  lo = glm::dvec3(VTK_DOUBLE_MAX);
  hi = glm::dvec3(-VTK_DOUBLE_MAX);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double x[3];
    inPoints->GetPoint(i, x);
    finite[i] = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
    if (finite[i])
    {
      const glm::dvec3 w(x[0], x[1], x[2]);
      local[i] = plane.ToPlane * (w - plane.Origin);
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  }
  std::vector<Polygon3> casters;
  droppedCells = 0;
  auto addCaster = [&](vtkIdType n, const vtkIdType* ids)
  {
    Polygon3 poly;
    double top = 0.0;
    for (vtkIdType j = 0; j < n; ++j)
    {
      if (ids[j] < 0 || ids[j] >= numPoints || !finite[ids[j]])
      {
        ++droppedCells;
        return;
      }
      poly.push_back(local[ids[j]]);
      top = std::max(top, poly.back().z);
    }
    // Only what lies strictly above the plane can shadow it.
    if (poly.size() >= 3 && top > 0.0)
    {
      casters.push_back(std::move(poly));
    }
  };
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = input->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    addCaster(n, ids);
  }
  vtkCellArray* strips = input->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(n, ids);)
  {
    for (vtkIdType j = 0; j + 2 < n; ++j)
    {
      addCaster(3, ids + j);
    }
  }
  return casters;
}

/// The integer frame over every sample's projection of every caster, grown by `litMargin` of
/// its size; false when nothing projects or the extent is degenerate.
bool FrameProjections(const std::vector<Polygon3>& casters, const std::vector<glm::dvec4>& samples,
  double litMargin, IntegerFrame& frame)
{
  std::vector<glm::dvec2> projected;
  glm::dvec2 plo(VTK_DOUBLE_MAX), phi(-VTK_DOUBLE_MAX);
  for (const glm::dvec4& sample : samples)
  {
    for (const Polygon3& poly : casters)
    {
      if (Project(poly, sample, projected))
      {
        for (const glm::dvec2& p : projected)
        {
          plo = glm::min(plo, p);
          phi = glm::max(phi, p);
        }
      }
    }
  }
  if (!(plo.x <= phi.x) || !(plo.y <= phi.y))
  {
    return false;
  }
  const double margin = litMargin * std::max(phi.x - plo.x, phi.y - plo.y);
  plo -= margin;
  phi += margin;
  const double extent = std::max(phi.x - plo.x, phi.y - plo.y);
  if (!(extent > 0.0) || !std::isfinite(extent))
  {
    return false;
  }
  frame.Lo = plo;
  frame.Hi = phi;
  frame.Centre = 0.5 * (plo + phi);
  frame.Scale = IntegerExtent / extent;
  return true;
}

/// Hard shadow of each sample, merged at once into the nested levels: after adding shadow P,
/// levels[k] (covered by at least k + 1 shadows) grows by levels[k - 1] intersected with P.
std::vector<Paths> CoverageLevels(const std::vector<Polygon3>& casters,
  const std::vector<glm::dvec4>& samples, const IntegerFrame& frame)
{
  const int count = static_cast<int>(samples.size());
  std::vector<glm::dvec2> projected;
  std::vector<Paths> levels(count);
  for (int s = 0; s < count; ++s)
  {
    Paths pieces;
    for (const Polygon3& poly : casters)
    {
      if (!Project(poly, samples[s], projected))
      {
        continue;
      }
      ClipperLib::Path path;
      for (const glm::dvec2& p : projected)
      {
        const ClipperLib::IntPoint q = frame.ToInt(p);
        if (path.empty() || !(path.back() == q))
        {
          path.push_back(q);
        }
      }
      while (path.size() > 1 && path.front() == path.back())
      {
        path.pop_back();
      }
      const double area = path.size() >= 3 ? ClipperLib::Area(path) : 0.0;
      if (area == 0.0)
      {
        continue; // edge-on or degenerate: covers nothing
      }
      if (area < 0.0)
      {
        std::reverse(path.begin(), path.end()); // one orientation, so nonzero fill is a union
      }
      pieces.push_back(std::move(path));
    }
    Paths shadow = Boolean(ClipperLib::ctUnion, pieces, Paths());
    ClipperLib::CleanPolygons(shadow);
    for (int k = std::min(s, count - 1); k >= 1; --k)
    {
      if (!levels[k - 1].empty())
      {
        levels[k] = Boolean(ClipperLib::ctUnion, levels[k],
          Boolean(ClipperLib::ctIntersection, levels[k - 1], shadow));
      }
    }
    levels[0] = Boolean(ClipperLib::ctUnion, levels[0], shadow);
  }
  return levels;
}

/// Every ring of every level as a constraint of one triangulation; false when it is flat.
bool TriangulateLevels(const std::vector<Paths>& levels, CDT& cdt)
{
  for (const Paths& level : levels)
  {
    for (const ClipperLib::Path& path : level)
    {
      if (path.size() < 3)
      {
        continue;
      }
      std::vector<CDT::Vertex_handle> handles;
      CDT::Face_handle hint;
      for (const ClipperLib::IntPoint& p : path)
      {
        handles.push_back(cdt.insert(CDT::Point(double(p.X), double(p.Y)), hint));
        hint = handles.back()->face();
      }
      for (size_t i = 0; i < handles.size(); ++i)
      {
        const auto a = handles[i], b = handles[(i + 1) % handles.size()];
        if (a != b)
        {
          cdt.insert_constraint(a, b);
        }
      }
    }
  }
  return cdt.dimension() >= 2;
}

/// Coverage of each face: faces joined by unconstrained edges share it, so one point-in-rings
/// test per component, at the centroid of its largest face (well inside, whatever slivers the
/// component has). Levels are nested, so a binary search finds the highest one containing it.
std::vector<int> Classify(CDT& cdt, const std::vector<Paths>& levels)
{
  const int count = static_cast<int>(levels.size());
  std::vector<int> coverage;
  for (auto f : cdt.all_face_handles())
  {
    f->info() = -1;
  }
  std::vector<CDT::Face_handle> stack;
  for (auto seed : cdt.all_face_handles())
  {
    if (seed->info() >= 0)
    {
      continue;
    }
    const int component = static_cast<int>(coverage.size());
    bool unbounded = false;
    double bestArea = -1.0;
    glm::dvec2 probe(0.0);
    seed->info() = component;
    stack.push_back(seed);
    while (!stack.empty())
    {
      const CDT::Face_handle f = stack.back();
      stack.pop_back();
      if (cdt.is_infinite(f))
      {
        unbounded = true;
      }
      else
      {
        const glm::dvec2 a = ToDouble(f->vertex(0)->point());
        const glm::dvec2 b = ToDouble(f->vertex(1)->point());
        const glm::dvec2 c = ToDouble(f->vertex(2)->point());
        const double area = std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
        if (area > bestArea)
        {
          bestArea = area;
          probe = (a + b + c) / 3.0;
        }
      }
      for (int i = 0; i < 3; ++i)
      {
        const CDT::Face_handle g = f->neighbor(i);
        if (!f->is_constrained(i) && g->info() < 0)
        {
          g->info() = component;
          stack.push_back(g);
        }
      }
    }
    int covered = 0;
    if (!unbounded)
    {
      int below = 0, above = count; // levels[below - 1] contains probe, levels[above] does not
      while (below < above)
      {
        const int mid = (below + above + 1) / 2;
        if (Inside(levels[mid - 1], probe))
        {
          below = mid;
        }
        else
        {
          above = mid - 1;
        }
      }
      covered = below;
    }
    coverage.push_back(covered);
  }
  return coverage;
}

/// Refinement against long, thin triangles (Mach bands), in the penumbra only, in rounds and
/// bounded in points. As in Ruppert's algorithm, a ring edge that a neighbouring vertex sees at
/// more than 90 degrees (it encroaches) is split at its midpoint; a triangle whose smallest angle
/// is under 20 degrees and has no such edge gets its centroid. Either point stays in its band.
/// Midpoints of the integer ring vertices are exact in doubles down to tiny edges, so no
/// construction nests. (CGAL's Delaunay_mesher_2 nests midpoints: with exact constructions it
/// stalled in GMP, with inexact ones a later constraint insertion crashed.)
void RefinePenumbra(CDT& cdt, const std::vector<Paths>& levels, int maximumPoints)
{
  const double sinMin = std::sin(glm::radians(20.0));
  // Nothing shorter than 1e-5 of the extent is split: that would only make more slivers.
  const double minLength = 1e-5 * IntegerExtent;
  const int count = static_cast<int>(levels.size());
  int budget = maximumPoints;
  for (int round = 0; round < 8 && budget > 0; ++round)
  {
    const std::vector<int> coverage = Classify(cdt, levels);
    std::vector<CDT::Point> steiner;
    auto penumbra = [&](CDT::Face_handle f)
    { return !cdt.is_infinite(f) && coverage[f->info()] > 0 && coverage[f->info()] < count; };
    for (auto f : cdt.finite_face_handles())
    {
      if (!penumbra(f) || static_cast<int>(steiner.size()) >= budget)
      {
        continue;
      }
      glm::dvec2 p[3];
      for (int i = 0; i < 3; ++i)
      {
        p[i] = ToDouble(f->vertex(i)->point());
      }
      bool split = false;
      for (int i = 0; i < 3; ++i)
      {
        // Edge i is opposite vertex i; each constrained edge is looked at from both sides, and
        // split once: from the side whose face handle sorts first.
        const glm::dvec2 a = p[CDT::ccw(i)], b = p[CDT::cw(i)];
        if (!f->is_constrained(i) || glm::length(b - a) < minLength ||
          glm::dot(a - p[i], b - p[i]) >= 0.0)
        {
          continue;
        }
        split = true;
        const CDT::Face_handle g = f->neighbor(i);
        const int j = g->index(f);
        const bool encroachedFromThere = !cdt.is_infinite(g) && penumbra(g) &&
          glm::dot(a - ToDouble(g->vertex(j)->point()), b - ToDouble(g->vertex(j)->point())) < 0.0;
        if (!encroachedFromThere || &*f < &*g)
        {
          const glm::dvec2 m = 0.5 * (a + b);
          steiner.emplace_back(m.x, m.y);
        }
      }
      const double ab = glm::length(p[1] - p[0]), bd = glm::length(p[2] - p[1]),
                   da = glm::length(p[0] - p[2]);
      const double shortest = std::min({ ab, bd, da });
      // sin of the smallest angle (opposite the shortest edge) = 2 area / (the other two edges)
      const double others = shortest == ab ? bd * da : shortest == bd ? ab * da : ab * bd;
      const double twiceArea =
        std::abs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y));
      if (!split && shortest > minLength && twiceArea < sinMin * others)
      {
        const glm::dvec2 centroid = (p[0] + p[1] + p[2]) / 3.0;
        steiner.emplace_back(centroid.x, centroid.y);
      }
    }
    if (steiner.empty())
    {
      break;
    }
    budget -= static_cast<int>(steiner.size());
    cdt.insert(steiner.begin(), steiner.end());
  }
}

/// The frame's rectangle as constraints, so that the lit region around the shadow is output.
void AddLitRegion(CDT& cdt, const IntegerFrame& frame)
{
  const ClipperLib::IntPoint a = frame.ToInt(frame.Lo), b = frame.ToInt(frame.Hi);
  const CDT::Point corners[4] = { { double(a.X), double(a.Y) }, { double(b.X), double(a.Y) },
    { double(b.X), double(b.Y) }, { double(a.X), double(b.Y) } };
  for (int i = 0; i < 4; ++i)
  {
    cdt.insert_constraint(corners[i], corners[(i + 1) % 4]);
  }
}

/// Coverage at every finite vertex (numbered in its info), in samples.
/// A penumbra vertex takes the mean coverage of a small disk around it: the angle-weighted mean
/// of its faces' coverages (outside the hull counts 0). On a straight ring between k - 1 and k
/// that is k - 1/2; where rings cross, their average; inside a band, the band's own coverage.
std::vector<double> VertexCoverage(CDT& cdt, const std::vector<int>& coverage, int count)
{
  std::vector<double> sumCoverage;
  vtkIdType vertexCount = 0;
  for (auto v : cdt.finite_vertex_handles())
  {
    v->info() = vertexCount++;
  }
  sumCoverage.assign(vertexCount, 0.0);
  for (auto f : cdt.finite_face_handles())
  {
    const int c = coverage[f->info()];
    if (c == 0)
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      const glm::dvec2 a = ToDouble(f->vertex(i)->point());
      const glm::dvec2 ab = ToDouble(f->vertex(CDT::ccw(i))->point()) - a;
      const glm::dvec2 ad = ToDouble(f->vertex(CDT::cw(i))->point()) - a;
      const double angle = std::atan2(std::abs(ab.x * ad.y - ab.y * ad.x), glm::dot(ab, ad));
      sumCoverage[f->vertex(i)->info()] += angle * c;
    }
  }

  // Refinement points inside a band take the band's coverage as a start; a Steiner point with
  // that constant would make flat terraces (the staircase, Mach bands), so the free points are
  // relaxed to the discrete harmonic interpolation between the rings (Gauss-Seidel, bounded).
  std::vector<double> value(vertexCount);
  std::vector<std::vector<vtkIdType>> neighbours;
  std::vector<vtkIdType> freeVertices;
  for (auto v : cdt.finite_vertex_handles())
  {
    const vtkIdType i = v->info();
    value[i] = sumCoverage[i] / (2.0 * 3.14159265358979323846);
    if (cdt.are_there_incident_constraints(v))
    {
      continue;
    }
    int band = -1;
    bool interior = true;
    std::vector<vtkIdType> around;
    auto f = cdt.incident_faces(v), done = f;
    do
    {
      const int c = cdt.is_infinite(f) ? 0 : coverage[f->info()];
      interior &= band < 0 || c == band;
      band = c;
    } while (++f != done);
    if (!interior || band <= 0 || band >= count)
    {
      continue;
    }
    auto w = cdt.incident_vertices(v), first = w;
    do
    {
      if (!cdt.is_infinite(w))
      {
        around.push_back(w->info());
      }
    } while (++w != first);
    value[i] = band;
    freeVertices.push_back(i);
    neighbours.push_back(std::move(around));
  }
  for (int iteration = 0; iteration < 64 && !freeVertices.empty(); ++iteration)
  {
    for (size_t j = 0; j < freeVertices.size(); ++j)
    {
      double sum = 0.0;
      for (vtkIdType k : neighbours[j])
      {
        sum += value[k];
      }
      value[freeVertices[j]] = sum / neighbours[j].size();
    }
  }
  return value;
}

/// Areas in plane units, and the integral of the shadow (1 - intensity) over the plane.
struct ShadowAreas
{
  double Umbra = 0.0, Penumbra = 0.0, Integral = 0.0;
};

/// The output triangles (integer frame coordinates): faces covered by no sample are left out
/// unless `outputLitRegion`.
/// Umbra, penumbra and lit triangles have their own points, so that the umbra is flat 0 and the
/// lit region flat 1 whatever their neighbours.
void EmitTriangles(CDT& cdt, const std::vector<int>& coverage, const std::vector<double>& value,
  int count, bool outputLitRegion, double scale, Result& result, ShadowAreas& areas)
{
  const vtkIdType vertexCount = static_cast<vtkIdType>(value.size());
  std::vector<vtkIdType> pointOf[3];
  for (auto& ids_ : pointOf)
  {
    ids_.assign(vertexCount, -1);
  }
  for (auto f : cdt.finite_face_handles())
  {
    const int c = coverage[f->info()];
    if (c == 0 && !outputLitRegion)
    {
      continue;
    }
    const unsigned char region = c >= count ? 0 : (c > 0 ? 1 : 2);
    double mean = 0.0;
    glm::dvec2 corner[3];
    for (int i = 0; i < 3; ++i)
    {
      const CDT::Vertex_handle v = f->vertex(i);
      // A penumbra face between rings c - 1/2 and c + 1/2 (in samples) keeps its corners in that
      // band. Where many rings meet in one vertex (a caster standing on the plane: every sample's
      // outline passes through its contact corners) the vertex's mean coverage belongs to none
      // of the faces around it, and long faces would carry it far along their ring (measured
      // 0.34 off the truth across a tall box's shadow). Such a corner gets a point of its own.
      const double shared = value[v->info()];
      const double banded = region == 1 ? std::min(c + 0.5, std::max(c - 0.5, shared)) : shared;
      const bool own = std::abs(banded - shared) > 1e-9;
      vtkIdType ownId = -1;
      vtkIdType& id = own ? ownId : pointOf[region][v->info()];
      if (id < 0)
      {
        id = static_cast<vtkIdType>(result.Points.size());
        result.Points.push_back(ToDouble(v->point()));
        const double lit = region == 0 ? 0.0 : region == 2 ? 1.0 : 1.0 - banded / count;
        result.Intensity.push_back(static_cast<float>(std::min(1.0, std::max(0.0, lit))));
      }
      result.Triangles.push_back(id);
      corner[i] = result.Points[id];
      mean += result.Intensity[id] / 3.0;
    }
    result.Regions.push_back(region);
    const double area = 0.5 *
      ((corner[1].x - corner[0].x) * (corner[2].y - corner[0].y) -
        (corner[2].x - corner[0].x) * (corner[1].y - corner[0].y)) /
      (scale * scale);
    if (region == 0)
    {
      areas.Umbra += area;
    }
    else if (region == 1)
    {
      areas.Penumbra += area;
    }
    areas.Integral += area * (1.0 - mean);
  }
}

/// The result's triangles on the plane, lifted by `offset` along its normal, with their
/// "LightIntensity" point and "ShadowRegion" cell arrays (empty arrays when there is none).
void WriteOutput(const Result& result, const PlaneFrame& plane, double offset,
  const IntegerFrame& frame, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(result.Points.size()));
  const glm::dvec3 lift = plane.Origin + offset * plane.Normal;
  for (size_t i = 0; i < result.Points.size(); ++i)
  {
    const glm::dvec2 uv = result.Points[i] / frame.Scale + frame.Centre;
    const glm::dvec3 x = lift + uv.x * plane.E1 + uv.y * plane.E2;
    points->SetPoint(static_cast<vtkIdType>(i), x.x, x.y, x.z);
  }
  vtkNew<vtkFloatArray> intensity;
  intensity->SetName("LightIntensity");
  intensity->SetNumberOfValues(static_cast<vtkIdType>(result.Intensity.size()));
  std::copy(result.Intensity.begin(), result.Intensity.end(), intensity->GetPointer(0));
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkUnsignedCharArray> regions;
  regions->SetName("ShadowRegion");
  regions->SetNumberOfValues(static_cast<vtkIdType>(result.Regions.size()));
  for (size_t t = 0; t < result.Regions.size(); ++t)
  {
    triangles->InsertNextCell(3, &result.Triangles[3 * t]);
    regions->SetValue(static_cast<vtkIdType>(t), result.Regions[t]);
  }
  output->Initialize();
  output->SetPoints(points);
  output->SetPolys(triangles);
  output->GetPointData()->SetScalars(intensity);
  output->GetCellData()->SetScalars(regions);
}

} // namespace

//------------------------------------------------------------------------------
vtkPlanarSoftShadowFilter::vtkPlanarSoftShadowFilter() = default;
vtkPlanarSoftShadowFilter::~vtkPlanarSoftShadowFilter() = default;

//------------------------------------------------------------------------------
int vtkPlanarSoftShadowFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkPlanarSoftShadowFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->UmbraArea = this->PenumbraArea = this->ShadowIntegral = 0.0;
  this->NumberOfUsedSamples = 0;

  Result result;
  PlaneFrame plane;
  plane.Origin = glm::dvec3(this->PlaneOrigin[0], this->PlaneOrigin[1], this->PlaneOrigin[2]);
  plane.Normal = glm::dvec3(this->PlaneNormal[0], this->PlaneNormal[1], this->PlaneNormal[2]);
  IntegerFrame frame;
  // Everything that can go wrong ends here, with an empty output that still has the arrays.
  auto finish = [&]()
  {
    WriteOutput(result, plane, this->Offset, frame, output);
    return 1;
  };

  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    return finish();
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkWarningMacro("Input has no polygons or triangle strips (only vertices or lines cast no "
                    "shadow on a plane); the output is empty.");
    return finish();
  }
  if (!std::isfinite(glm::dot(plane.Normal, plane.Normal)) || glm::length(plane.Normal) <= 0.0 ||
    !std::isfinite(glm::dot(plane.Origin, plane.Origin)) || !std::isfinite(this->Offset))
  {
    vtkErrorMacro(
      "PlaneNormal must be a finite, non-zero vector, and PlaneOrigin and Offset finite.");
    return finish();
  }
  plane.Normal = glm::normalize(plane.Normal);
  penumbra::PlaneBasis(plane.Normal, plane.E1, plane.E2);
  plane.ToPlane = glm::transpose(glm::dmat3(plane.E1, plane.E2, plane.Normal));

  // Caster polygons in plane coordinates; points with non-finite coordinates drop their cells.
  glm::dvec3 lo, hi;
  vtkIdType droppedCells = 0;
  const std::vector<Polygon3> casters = CasterPolygons(input, plane, lo, hi, droppedCells);
  if (droppedCells > 0)
  {
    vtkWarningMacro(<< droppedCells << " cells with non-finite or invalid points were dropped.");
  }
  if (casters.empty())
  {
    return finish();
  }

  // The light, sampled.
  const glm::dvec3 light(this->LightPosition[0], this->LightPosition[1], this->LightPosition[2]);
  const double height = this->Positional ? glm::dot(light - plane.Origin, plane.Normal)
                                         : glm::dot(glm::normalize(light), plane.Normal);
  if (!std::isfinite(height) || height <= 0.0 || !std::isfinite(this->LightRadius))
  {
    vtkErrorMacro("The light must be strictly above the plane (on the side PlaneNormal points "
                  "to) and finite; the output is empty.");
    return finish();
  }
  int dropped = 0;
  const std::vector<glm::dvec4> samples = SampleLight(
    this->Positional ? light : glm::normalize(light), this->Positional, this->LightRadius,
    this->LightSamples, this->SamplePattern, 0.5 * (lo + hi), plane.Origin, plane.ToPlane, dropped);
  if (dropped > 0)
  {
    vtkWarningMacro(<< dropped << " light samples on or below the plane were left out.");
  }
  const int count = static_cast<int>(samples.size());
  this->NumberOfUsedSamples = count;
  if (count == 0 ||
    !FrameProjections(casters, samples, this->OutputLitRegion ? this->LitMargin : 0.0, frame))
  {
    return finish();
  }

  // Nested coverage levels, triangulated with every ring as a constraint, refined in the
  // penumbra, classified, then a coverage at every vertex and the output triangles.
  const std::vector<Paths> levels = CoverageLevels(casters, samples, frame);
  CDT cdt;
  if (levels[0].empty() || !TriangulateLevels(levels, cdt))
  {
    return finish();
  }
  if (this->Refine && this->MaximumRefinementPoints > 0)
  {
    RefinePenumbra(cdt, levels, this->MaximumRefinementPoints);
  }
  if (this->OutputLitRegion)
  {
    AddLitRegion(cdt, frame);
  }
  const std::vector<int> coverage = Classify(cdt, levels);
  const std::vector<double> value = VertexCoverage(cdt, coverage, count);
  ShadowAreas areas;
  EmitTriangles(
    cdt, coverage, value, count, this->OutputLitRegion != 0, frame.Scale, result, areas);
  this->UmbraArea = areas.Umbra;
  this->PenumbraArea = areas.Penumbra;
  this->ShadowIntegral = areas.Integral;
  return finish();
}

//------------------------------------------------------------------------------
void vtkPlanarSoftShadowFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightPosition: (" << this->LightPosition[0] << ", " << this->LightPosition[1]
     << ", " << this->LightPosition[2] << ")\n";
  os << indent << "Positional: " << this->Positional << "\n";
  os << indent << "LightRadius: " << this->LightRadius << "\n";
  os << indent << "LightSamples: " << this->LightSamples << "\n";
  os << indent
     << "SamplePattern: " << (this->SamplePattern == SUNFLOWER ? "Sunflower" : "PolarGrid") << "\n";
  os << indent << "PlaneOrigin: (" << this->PlaneOrigin[0] << ", " << this->PlaneOrigin[1] << ", "
     << this->PlaneOrigin[2] << ")\n";
  os << indent << "PlaneNormal: (" << this->PlaneNormal[0] << ", " << this->PlaneNormal[1] << ", "
     << this->PlaneNormal[2] << ")\n";
  os << indent << "Offset: " << this->Offset << "\n";
  os << indent << "OutputLitRegion: " << this->OutputLitRegion << "\n";
  os << indent << "LitMargin: " << this->LitMargin << "\n";
  os << indent << "Refine: " << this->Refine << "\n";
  os << indent << "MaximumRefinementPoints: " << this->MaximumRefinementPoints << "\n";
  os << indent << "UmbraArea: " << this->UmbraArea << "\n";
  os << indent << "PenumbraArea: " << this->PenumbraArea << "\n";
  os << indent << "ShadowIntegral: " << this->ShadowIntegral << "\n";
  os << indent << "NumberOfUsedSamples: " << this->NumberOfUsedSamples << "\n";
}
