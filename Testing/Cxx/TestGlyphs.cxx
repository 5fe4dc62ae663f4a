// The glyph matrices of penumbraGlyphs against VTK's own constructions: vtkGlyph3D's output for
// orientation by direction and scaling by magnitude or components (clamped too), and vtkTransform
// for rotation angles and quaternions. Random points, orientations and scales; every source
// point must land within 1e-6 of VTK's (its points are float; a wrong rotation is off by 0.1).
#include "penumbraCasterTopology.h"
#include "penumbraCheck.h"
#include "penumbraGlyphs.h"

#include "vtkConeSource.h"
#include "vtkDoubleArray.h"
#include "vtkGlyph3D.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTransform.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

namespace
{
using penumbra::GlyphSettings;
using penumbra_test::Check;

/// Largest distance between `source` moved by `matrix` and the points VTK produced.
double WorstDistance(
  vtkPolyData* source, const glm::dmat4& matrix, vtkPoints* expected, vtkIdType offset = 0)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < source->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    source->GetPoint(i, p);
    expected->GetPoint(offset + i, q);
    const glm::dvec3 moved(matrix * glm::dvec4(p[0], p[1], p[2], 1.0));
    worst = penumbra_test::Worse(worst, glm::length(moved - glm::dvec3(q[0], q[1], q[2])));
  }
  return worst;
}

vtkSmartPointer<vtkPolyData> Cone()
{
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(7);
  cone->SetCenter(0.2, -0.1, 0.05); // off-centre, so translation and rotation both show
  cone->Update();
  return cone->GetOutput();
}

/// Direction and scale by vtkGlyph3D, one glyph per point, in each scale mode.
void TestAgainstGlyph3D(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  vtkSmartPointer<vtkPolyData> cone = Cone();
  struct Mode
  {
    const char* Name;
    int Ours;
    bool Clamping;
  };
  for (const Mode& mode : { Mode{ "magnitude", GlyphSettings::ScaleByMagnitude, false },
         Mode{ "components", GlyphSettings::ScaleByComponents, false },
         Mode{ "magnitude, clamped", GlyphSettings::ScaleByMagnitude, true },
         Mode{ "no data scaling", GlyphSettings::NoDataScaling, false } })
  {
    vtkNew<vtkPolyData> input;
    vtkNew<vtkPoints> points;
    vtkNew<vtkDoubleArray> vectors;
    vectors->SetNumberOfComponents(3);
    vectors->SetName("v");
    for (int i = 0; i < 40; ++i)
    {
      points->InsertNextPoint(u(rng), u(rng), u(rng));
      // A few along x, both ways: VTK's special case for them.
      if (i < 2)
      {
        vectors->InsertNextTuple3(i == 0 ? 1.5 : -0.7, 0.0, 0.0);
      }
      else
      {
        vectors->InsertNextTuple3(u(rng), u(rng), u(rng));
      }
    }
    input->SetPoints(points);
    input->GetPointData()->SetVectors(vectors);

    GlyphSettings settings;
    settings.ScaleMode = mode.Ours;
    settings.ScaleFactor = 0.7;
    settings.Clamping = mode.Clamping;
    settings.Range[0] = 0.5;
    settings.Range[1] = 2.0;
    vtkNew<vtkGlyph3D> glyphs;
    glyphs->SetInputData(input);
    glyphs->SetSourceData(cone);
    glyphs->SetVectorModeToUseVector();
    glyphs->SetScaleFactor(settings.ScaleFactor);
    glyphs->SetClamping(settings.Clamping);
    glyphs->SetRange(settings.Range);
    if (mode.Ours == GlyphSettings::ScaleByComponents)
    {
      glyphs->SetScaleModeToScaleByVectorComponents();
    }
    else if (mode.Ours == GlyphSettings::ScaleByMagnitude)
    {
      glyphs->SetScaleModeToScaleByVector();
    }
    else
    {
      glyphs->SetScaleModeToDataScalingOff();
    }
    glyphs->Update();
    vtkPoints* expected = glyphs->GetOutput()->GetPoints();

    double worst = 0.0;
    bool allFinite = true;
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double position[3], v[3];
      points->GetPoint(i, position);
      vectors->GetTuple(i, v);
      const glm::dvec3 scale = penumbra::GlyphScale(settings, v, 3);
      glm::dmat4 matrix;
      allFinite &= penumbra::GlyphMatrix(settings, glm::make_vec3(position), v, scale, matrix);
      worst = penumbra_test::Worse(
        worst, WorstDistance(cone, matrix, expected, i * cone->GetNumberOfPoints()));
    }
    std::printf("     direction, scale by %s: worst distance %.2e\n", mode.Name, worst);
    Check(allFinite, "finite directions give matrices");
    Check(worst < 1e-6, std::string("direction, scale by ") + mode.Name + ": as vtkGlyph3D");
  }
}

/// Rotation angles (z, then x, then y) and quaternions against vtkTransform.
void TestAgainstTransform(std::mt19937& rng)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  vtkSmartPointer<vtkPolyData> cone = Cone();
  double worstRotation = 0.0, worstQuaternion = 0.0;
  bool allFinite = true;
  for (int i = 0; i < 50; ++i)
  {
    const glm::dvec3 position(u(rng), u(rng), u(rng));
    const glm::dvec3 scale(0.5 + std::abs(u(rng)));
    GlyphSettings settings;

    const double angles[3] = { 180.0 * u(rng), 180.0 * u(rng), 180.0 * u(rng) };
    settings.OrientationMode = GlyphSettings::Rotation;
    glm::dmat4 matrix;
    allFinite &= penumbra::GlyphMatrix(settings, position, angles, scale, matrix);
    vtkNew<vtkTransform> rotation;
    rotation->Translate(position.x, position.y, position.z);
    rotation->RotateZ(angles[2]);
    rotation->RotateX(angles[0]);
    rotation->RotateY(angles[1]);
    rotation->Scale(scale.x, scale.y, scale.z);
    vtkNew<vtkPoints> rotated;
    rotation->TransformPoints(cone->GetPoints(), rotated);
    worstRotation = penumbra_test::Worse(worstRotation, WorstDistance(cone, matrix, rotated));

    // A quaternion that is not of unit length: VTK normalizes it.
    const double q[4] = { u(rng), u(rng), u(rng), u(rng) };
    settings.OrientationMode = GlyphSettings::Quaternion;
    allFinite &= penumbra::GlyphMatrix(settings, position, q, scale, matrix);
    const double axis = std::sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    vtkNew<vtkTransform> turn;
    turn->Translate(position.x, position.y, position.z);
    turn->RotateWXYZ(
      2.0 * std::atan2(axis, q[0]) * 180.0 / 3.14159265358979323846, q[1], q[2], q[3]);
    turn->Scale(scale.x, scale.y, scale.z);
    vtkNew<vtkPoints> turned;
    turn->TransformPoints(cone->GetPoints(), turned);
    worstQuaternion = penumbra_test::Worse(worstQuaternion, WorstDistance(cone, matrix, turned));
  }
  std::printf(
    "     rotation angles: worst %.2e; quaternions: worst %.2e\n", worstRotation, worstQuaternion);
  Check(allFinite, "finite angles and quaternions give matrices");
  Check(worstRotation < 1e-6, "rotation angles as vtkTransform's RotateZ, RotateX, RotateY");
  Check(worstQuaternion < 1e-6, "quaternions as vtkTransform's RotateWXYZ");
}

void TestBadInput()
{
  GlyphSettings settings;
  glm::dmat4 matrix(2.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double direction[3] = { nan, 0.0, 0.0 };
  Check(!penumbra::GlyphMatrix(settings, glm::dvec3(0.0), direction, glm::dvec3(1.0), matrix),
    "a NaN direction gives no matrix");
  // Its squares underflow: no length to normalize by, in VTK's mapper too (the fuzzer found a
  // NaN matrix returned as placed).
  const double tiny[3] = { 3.8e-236, 3.8e-236, 3.8e-236 };
  Check(!penumbra::GlyphMatrix(settings, glm::dvec3(0.0), tiny, glm::dvec3(1.0), matrix),
    "a direction too small to normalize gives no matrix");
  settings.OrientationMode = GlyphSettings::Quaternion;
  const double infinite[4] = { 1.0, std::numeric_limits<double>::infinity(), 0.0, 0.0 };
  Check(!penumbra::GlyphMatrix(settings, glm::dvec3(0.0), infinite, glm::dvec3(1.0), matrix),
    "an infinite quaternion gives no matrix");
  const double zero[4] = { 0.0, 0.0, 0.0, 0.0 };
  Check(penumbra::GlyphMatrix(settings, glm::dvec3(1.0), zero, glm::dvec3(1.0), matrix) &&
      matrix == glm::translate(glm::dmat4(1.0), glm::dvec3(1.0)),
    "a zero quaternion leaves the glyph unrotated");
  const double none[1] = { 0.0 };
  Check(penumbra::GlyphScale(settings, none, 1) == glm::dvec3(1e-10),
    "a zero scale becomes 1e-10, as in VTK");
}
} // namespace

void TestImposterSphere()
{
  // The stand-in for a vtkOpenGLSphereMapper sphere: closed, outward, and as large as a sphere.
  const penumbra::TriangleMesh sphere = penumbra::ImposterSphereMesh(32);
  const penumbra::CasterTopology topology =
    penumbra::CasterTopology::Build(sphere.Points, sphere.Triangles);
  Check(topology.ClosedAndOriented && topology.Report.DegenerateTriangles == 0,
    "imposter sphere mesh: closed, oriented, no degenerate triangle");
  double volume = 0.0, lo = 1e9, hi = 0.0;
  for (const glm::uvec3& t : sphere.Triangles)
  {
    volume +=
      glm::dot(sphere.Points[t.x], glm::cross(sphere.Points[t.y], sphere.Points[t.z])) / 6.0;
  }
  for (const glm::dvec3& p : sphere.Points)
  {
    lo = std::min(lo, glm::length(p));
    hi = std::max(hi, glm::length(p));
  }
  const double unitVolume = 4.0 / 3.0 * glm::pi<double>();
  std::printf("imposter sphere: %zu triangles, radius %.4f, volume %.4f of the unit sphere's\n",
    sphere.Triangles.size(), hi, volume / unitVolume);
  Check(volume > 0.97 * unitVolume && volume < unitVolume,
    "imposter sphere mesh: wound outward, the unit sphere's volume within 3%");
  Check(std::abs(lo - 1.0) < 1e-12 && std::abs(hi - 1.0) < 1e-12,
    "imposter sphere mesh: inscribed, every point on the unit sphere");

  glm::dmat4 actor(1.0), matrix(0.0);
  actor[0][0] = 3.0; // the actor's scale moves centres, not radii
  actor[3] = glm::dvec4(1.0, 2.0, 3.0, 1.0);
  Check(penumbra::ImposterSphereMatrix(actor, { 1.0, 0.0, 0.0 }, 0.5, matrix) &&
      glm::length(glm::dvec3(matrix * glm::dvec4(1.0, 0.0, 0.0, 1.0)) - glm::dvec3(4.5, 2.0, 3.0)) <
        1e-12,
    "imposter sphere matrix: centre moved by the actor, radius unscaled");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Check(!penumbra::ImposterSphereMatrix(actor, { nan, 0.0, 0.0 }, 0.5, matrix) &&
      !penumbra::ImposterSphereMatrix(actor, { 0.0, 0.0, 0.0 }, 0.0, matrix) &&
      !penumbra::ImposterSphereMatrix(actor, { 0.0, 0.0, 0.0 }, -1.0, matrix) &&
      !penumbra::ImposterSphereMatrix(actor, { 0.0, 0.0, 0.0 }, nan, matrix),
    "imposter sphere matrix: refused for a NaN centre and a radius not positive or not finite");
}

void TestImposterStick()
{
  const penumbra::TriangleMesh stick = penumbra::ImposterStickMesh(24);
  const penumbra::CasterTopology topology =
    penumbra::CasterTopology::Build(stick.Points, stick.Triangles);
  double volume = 0.0;
  for (const glm::uvec3& t : stick.Triangles)
  {
    volume += glm::dot(stick.Points[t.x], glm::cross(stick.Points[t.y], stick.Points[t.z])) / 6.0;
  }
  Check(
    topology.ClosedAndOriented && volume > 0.98 * glm::pi<double>() && volume < glm::pi<double>(),
    "imposter stick mesh: closed, outward, inscribed in the unit cylinder of height 1");

  // An actor rotated and scaled: the axis follows the normal matrix, the sizes do not scale.
  glm::dmat4 actor = glm::rotate(glm::dmat4(1.0), 0.7, glm::dvec3(0.3, 1.0, -0.2));
  actor = glm::scale(actor, glm::dvec3(2.0, 2.0, 2.0));
  actor[3] = glm::dvec4(1.0, -2.0, 0.5, 1.0);
  const glm::dvec3 centre(0.5, 0.25, -1.0), orientation(1.0, 2.0, 0.5);
  glm::dmat4 matrix;
  const bool placed = penumbra::ImposterStickMatrix(actor, centre, orientation, 3.0, 0.2, matrix);
  const glm::dvec3 worldCentre(actor * glm::dvec4(centre, 1.0));
  const glm::dvec3 axis = glm::normalize(glm::dmat3(actor) * orientation); // uniform scale
  const glm::dvec3 top(matrix * glm::dvec4(0.0, 0.0, 0.5, 1.0));
  const glm::dvec3 rim(matrix * glm::dvec4(1.0, 0.0, 0.0, 1.0));
  Check(placed && glm::length(top - (worldCentre + 1.5 * axis)) < 1e-12 &&
      std::abs(glm::length(rim - worldCentre) - 0.2) < 1e-12 &&
      std::abs(glm::dot(rim - worldCentre, axis)) < 1e-12,
    "imposter stick matrix: centred, along the actor's normal matrix, length and radius unscaled");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Check(!penumbra::ImposterStickMatrix(actor, centre, { 0.0, 0.0, 0.0 }, 3.0, 0.2, matrix) &&
      !penumbra::ImposterStickMatrix(actor, centre, orientation, 0.0, 0.2, matrix) &&
      !penumbra::ImposterStickMatrix(actor, centre, orientation, 3.0, nan, matrix) &&
      !penumbra::ImposterStickMatrix(actor, { nan, 0.0, 0.0 }, orientation, 3.0, 0.2, matrix),
    "imposter stick matrix: refused for a zero axis, a zero length, a NaN radius or centre");
}

int main()
{
  std::mt19937 rng(7);
  TestAgainstGlyph3D(rng);
  TestAgainstTransform(rng);
  TestBadInput();
  TestImposterSphere();
  TestImposterStick();
  return penumbra_test::Finish();
}
