"""Figures of Documentation/planar_filter.md that the ctest suite does not print: timings (median
of 5 updates), the share of the penumbra area covered by flat-intensity triangles, and the largest
per-step change of intensity at fixed ground points as the sphere moves, for several N (probed
everywhere, also where the sphere hides the ground from above, which the ctest leaves out).

    PYTHONPATH=build-filter/lib/python3/dist-packages /usr/bin/python3 Testing/Filters/planar_filter_figures.py
"""
import statistics
import time

import numpy as np
import penumbra
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkProbeFilter
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource


def scene(shift=0.0, sphere_only=False):
    """The scene of TestPlanarSoftShadowFilter: sphere, box crossing the ground, thin plank."""
    app = vtkAppendPolyData()
    s = vtkSphereSource()
    s.SetCenter(-1 + shift, 0.4, 1.1)
    s.SetRadius(0.5)
    s.SetThetaResolution(48)
    s.SetPhiResolution(24)
    app.AddInputConnection(s.GetOutputPort())
    if not sphere_only:
        b = vtkCubeSource()
        b.SetCenter(1.1, -0.9, 0.15)
        b.SetXLength(0.9)
        b.SetYLength(0.6)
        b.SetZLength(0.7)
        p = vtkCubeSource()
        p.SetCenter(0.4, 1.5, 1.6)
        p.SetXLength(2.2)
        p.SetYLength(0.04)
        p.SetZLength(0.04)
        app.AddInputConnection(b.GetOutputPort())
        app.AddInputConnection(p.GetOutputPort())
    app.Update()
    return app


def make_filter(source, samples, refine=True):
    f = penumbra.vtkPlanarSoftShadowFilter()
    f.SetInputConnection(source.GetOutputPort())
    f.SetLightPosition(0.6, 0.4, 4)
    f.SetLightRadius(0.6)
    f.SetLightSamples(samples)
    f.SetRefine(refine)
    return f


def flat_share(out):
    """Share of penumbra area in triangles whose three intensities are equal."""
    intensity = out.GetPointData().GetArray("LightIntensity")
    region = out.GetCellData().GetArray("ShadowRegion")
    total = flat = 0.0
    for c in range(out.GetNumberOfCells()):
        if region.GetValue(c) != 1:
            continue
        ids = out.GetCell(c).GetPointIds()
        p = [out.GetPoint(ids.GetId(i)) for i in range(3)]
        area = abs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1])) / 2
        v = [intensity.GetValue(ids.GetId(i)) for i in range(3)]
        total += area
        flat += area if max(v) - min(v) < 1e-6 else 0.0
    return flat / total if total else 0.0


def largest_step(samples):
    grid = vtkImageData()
    grid.SetDimensions(96, 96, 1)
    grid.SetSpacing(3 / 96, 3 / 96, 1)
    grid.SetOrigin(-1.4 - 1.5 + 3 / 192, 0.35 - 1.5 + 3 / 192, 0)
    previous, worst = None, 0.0
    for step in range(13):
        shadow = make_filter(scene(0.01 * step, True), samples)  # kept: ports do not own producers
        probe = vtkProbeFilter()
        probe.SetInputData(grid)
        probe.SetSourceConnection(shadow.GetOutputPort())
        probe.Update()
        values = vtk_to_numpy(probe.GetOutput().GetPointData().GetArray("LightIntensity")).copy()
        valid = vtk_to_numpy(probe.GetOutput().GetPointData().GetArray("vtkValidPointMask"))
        values[valid == 0] = 1.0
        if previous is not None:
            worst = max(worst, float(np.abs(values - previous).max()))
        previous = values
    return worst


casters = scene()
print("caster polygons:", casters.GetOutput().GetNumberOfCells())
for n in (1, 8, 16, 32, 64):
    for refine in (True, False):
        f = make_filter(casters, n, refine)
        times = []
        for _ in range(5):
            f.Modified()
            t = time.perf_counter()
            f.Update()
            times.append(time.perf_counter() - t)
        print("N=%3d refine=%-5s median %.3f s, %6d triangles, flat penumbra share %.4f"
              % (n, refine, statistics.median(times), f.GetOutput().GetNumberOfCells(), flat_share(f.GetOutput())))
sphere_and_box = vtkAppendPolyData()
for part in range(2):  # the same scene without the plank, whose disjoint strips are flat
    sphere_and_box.AddInputConnection(casters.GetInputConnection(0, part))
sphere_and_box.Update()
for n in (8, 32, 64):
    shares = []
    for refine in (True, False):
        f = make_filter(sphere_and_box, n, refine)
        f.Update()
        shares.append(flat_share(f.GetOutput()))
    print("N=%3d sphere and box only: flat penumbra share refined %.4f, unrefined %.4f" % (n, *shares))
for n in (32, 64, 128):
    print("N=%3d largest per-step change, sphere moving 0.01 per step: %.3f" % (n, largest_step(n)))
