"""vtkPlanarSoftShadowFilter from Python: the package exposes it, the output has its arrays and
ranges, measures add up, and lines-only input warns and gives an empty output."""
import sys

import penumbra
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource

failures = 0


def check(ok, what):
    global failures
    print(("ok  " if ok else "FAIL") + ": " + what)
    failures += 0 if ok else 1


sphere = vtkSphereSource()
sphere.SetCenter(0, 0, 1)
sphere.SetRadius(0.5)
f = penumbra.vtkPlanarSoftShadowFilter()
f.SetInputConnection(sphere.GetOutputPort())
f.SetLightPosition(0.5, 0.2, 5)
f.SetLightRadius(0.6)
f.SetLightSamples(24)
f.SetOffset(0.001)
f.Update()
out = f.GetOutput()
intensity = out.GetPointData().GetArray("LightIntensity")
region = out.GetCellData().GetArray("ShadowRegion")
check(out.GetNumberOfCells() > 0, "soft shadow has triangles (%d)" % out.GetNumberOfCells())
check(intensity is not None and intensity.GetDataTypeAsString() == "float", "LightIntensity float array")
check(region is not None and region.GetNumberOfTuples() == out.GetNumberOfCells(), "ShadowRegion per cell")
lo, hi = intensity.GetRange()
check(lo == 0.0 and 0.5 < hi <= 1.0, "intensity range [%g, %g] within [0, 1], umbra at 0" % (lo, hi))
check(set(int(region.GetValue(i)) for i in range(region.GetNumberOfTuples())) == {0, 1},
      "umbra and penumbra, no lit cells by default")
check(abs(out.GetBounds()[4] - 0.001) < 1e-12 and abs(out.GetBounds()[5] - 0.001) < 1e-12,
      "output lies on the plane lifted by Offset")
check(f.GetUmbraArea() > 0 and f.GetPenumbraArea() > 0
      and f.GetUmbraArea() < f.GetShadowIntegral() < f.GetUmbraArea() + f.GetPenumbraArea(),
      "umbra %.3f <= shadow integral %.3f <= umbra + penumbra %.3f"
      % (f.GetUmbraArea(), f.GetShadowIntegral(), f.GetUmbraArea() + f.GetPenumbraArea()))
check("LightSamples: 24" in str(f), "PrintSelf lists the settings")
f.OutputLitRegionOn()
f.SetSamplePatternToPolarGrid()
f.Update()
region = f.GetOutput().GetCellData().GetArray("ShadowRegion")
check(region.GetRange() == (0.0, 2.0), "lit cells with OutputLitRegion, polar grid")

lines = vtkPolyData()
points = vtkPoints()
points.InsertNextPoint(0, 0, 1)
points.InsertNextPoint(1, 0, 1)
cells = vtkCellArray()
cells.InsertNextCell(2, [0, 1])
lines.SetPoints(points)
lines.SetLines(cells)
warnings = []
g = penumbra.vtkPlanarSoftShadowFilter()
g.AddObserver(vtkCommand.WarningEvent, lambda obj, event: warnings.append(event))
g.SetInputData(lines)
g.SetLightPosition(0, 0, 5)
g.Update()
check(len(warnings) == 1 and g.GetOutput().GetNumberOfCells() == 0, "lines only: one warning, empty output")
sys.exit(1 if failures else 0)
