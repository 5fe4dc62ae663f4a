"""Random triangle soups through vtkPlanarSoftShadowFilter: 5 to 300 triangles of sizes 1e-7 to 2,
some below the plane or above the light, a third of them far from the origin (x + 1e6), positional
and directional lights of several radii, 1 to 32 samples, both patterns, lit region on or off.
Checks that every update finishes with intensities in [0, 1]; prints times and measures.

    PYTHONPATH=build-filter/lib/python3/dist-packages /usr/bin/python3 Testing/Filters/planar_filter_soups.py [SEED ...]
"""
import random
import sys
import time

import penumbra
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

worst = 0.0
for seed in [int(a) for a in sys.argv[1:]] or range(150):
    rnd = random.Random(seed)
    points, cells = vtkPoints(), vtkCellArray()
    offset = rnd.choice([0, 0, 1e6])
    for _ in range(rnd.choice([5, 50, 300])):
        centre = [rnd.uniform(-2, 2), rnd.uniform(-2, 2), rnd.uniform(-0.5, 5)]
        size = rnd.choice([1e-7, 0.05, 0.5, 2])
        ids = [points.InsertNextPoint(centre[0] + rnd.uniform(-size, size) + offset,
                                      centre[1] + rnd.uniform(-size, size),
                                      centre[2] + rnd.uniform(-size, size)) for _ in range(3)]
        if rnd.random() < 0.05:
            ids[2] = ids[1]  # degenerate
        cells.InsertNextCell(3, ids)
    soup = vtkPolyData()
    soup.SetPoints(points)
    soup.SetPolys(cells)
    f = penumbra.vtkPlanarSoftShadowFilter()
    f.SetInputData(soup)
    f.SetLightPosition(offset + rnd.uniform(-1, 1), rnd.uniform(-1, 1), 4)
    f.SetLightRadius(rnd.choice([0, 0.3, 1.5]))
    f.SetLightSamples(rnd.choice([1, 7, 16, 32]))
    f.SetSamplePattern(rnd.choice([0, 1]))
    f.SetOutputLitRegion(rnd.random() < 0.3)
    f.SetPositional(rnd.random() < 0.8)
    if not f.GetPositional():
        f.SetLightPosition(rnd.uniform(-1, 1), rnd.uniform(-1, 1), 1)
        f.SetLightRadius(rnd.choice([0, 2, 10]))
    start = time.perf_counter()
    f.Update()
    seconds = time.perf_counter() - start
    worst = max(worst, seconds)
    out = f.GetOutput()
    low, high = out.GetPointData().GetArray("LightIntensity").GetRange() if out.GetNumberOfPoints() else (0, 0)
    assert 0 <= low <= high <= 1, (seed, low, high)
    print("seed %3d: %6.2f s, %7d triangles, umbra %.3g, penumbra %.3g, integral %.3g"
          % (seed, seconds, out.GetNumberOfCells(), f.GetUmbraArea(), f.GetPenumbraArea(), f.GetShadowIntegral()))
print("worst %.2f s" % worst)
