"""Counter overflow on stream tubes converging on a critical point: soft shadow volumes against
averaged hard shadows of the same samples and the ray-traced truth, and, at the first pixels
where they differ by more than 1/N, how many tube walls lie between the point and the light
(vtkOBBTree, independent of the pass). Then what Automatic shows in three frames: averaged from
the first, whose count it reads back at once, finds near the counters' limit and draws again.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages:Testing/Python \\
        /usr/bin/python3 Benchmarks/stream_tube_counts.py [WIDTH HEIGHT]

Scene: vtkStreamTracer over the gradient of vtkRTAnalyticSource (extent -10..10), 60 seeds in a
sphere of radius 8, both directions, uncapped tubes of radius 0.15 with 8 sides, a ground at
z = -12, a light of radius 2 at (3, 4, 40), N = 32, 320x240 by default.
"""
import sys

import numpy as np
import penumbra
from penumbra_testing import actor_of
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkFiltersCore import vtkTubeFilter
from vtkmodules.vtkFiltersFlowPaths import vtkStreamTracer
from vtkmodules.vtkFiltersGeneral import vtkGradientFilter, vtkOBBTree
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkPointSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

SAMPLES = 32
LIGHT = (3.0, 4.0, 40.0)
LIGHT_RADIUS = 2.0


def stream_tubes():
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    gradient = vtkGradientFilter()
    gradient.SetInputConnection(source.GetOutputPort())
    gradient.SetInputScalars(0, "RTData")
    gradient.SetResultArrayName("g")
    gradient.Update()
    field = gradient.GetOutput()
    field.GetPointData().SetActiveVectors("g")
    seeds = vtkPointSource()
    seeds.SetRadius(8)
    seeds.SetNumberOfPoints(60)
    tracer = vtkStreamTracer()
    tracer.SetInputData(field)
    tracer.SetSourceConnection(seeds.GetOutputPort())
    tracer.SetIntegrationDirectionToBoth()
    tracer.SetMaximumPropagation(60)
    tubes = vtkTubeFilter()
    tubes.SetInputConnection(tracer.GetOutputPort())
    tubes.SetRadius(0.15)
    tubes.SetNumberOfSides(8)
    tubes.CappingOff()
    tubes.Update()
    return tubes



def walls_towards(locator, point, targets):
    """Tube walls crossed by the segments from `point` to each of `targets`."""
    hits = vtkPoints()
    counts = []
    for target in targets:
        hits.Reset()
        locator.IntersectWithLine(point, target, hits, None)
        counts.append(hits.GetNumberOfPoints())
    return counts


def main():
    width, height = (int(sys.argv[1]), int(sys.argv[2])) if len(sys.argv) > 2 else (320, 240)
    tubes = stream_tubes()
    ground = vtkPlaneSource()
    ground.SetOrigin(-20, -20, -12)
    ground.SetPoint1(20, -20, -12)
    ground.SetPoint2(-20, 20, -12)
    renderer = vtkRenderer()
    renderer.AddActor(actor_of(tubes, (0.4, 0.7, 0.5)))
    renderer.AddActor(actor_of(ground, (0.9, 0.9, 0.9)))
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(*LIGHT)
    light.SetFocalPoint(0, 0, 0)
    light.SetConeAngle(180)
    renderer.AddLight(light)
    penumbra.vtkSoftShadowPass.SetLightRadius(light, LIGHT_RADIUS)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(30, -40, 30)
    camera.SetFocalPoint(0, 0, -5)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetLightSamples(SAMPLES)
    renderer.SetPass(shadows)

    def visibility(method):
        shadows.SetMethod(method)
        window.Render()
        scalars = shadows.GetVisibilityImage(0).GetPointData().GetScalars()
        return vtk_to_numpy(scalars).reshape(height, width).copy()

    counted = visibility(shadows.METHOD_SOFT_SHADOW_VOLUMES)
    window.Render()  # the second counted frame reads the first one's deepest count: one warning
    averaged = visibility(shadows.METHOD_AVERAGED_HARD_SHADOWS)
    truth = penumbra.vtkRayTracedVisibility()
    truth.SetRenderer(renderer)
    truth.SetSamplesPerLight(256)
    truth.Update()
    true = vtk_to_numpy(truth.GetVisibilityImage(0).GetPointData().GetScalars())
    true = true.reshape(height, width)
    shadowed = (averaged < 1) | (counted < 1)
    differ = shadowed & (np.abs(counted - averaged) > 1.0 / SAMPLES + 1e-6)
    print("%d tube cells; %d shadowed px, %d differ from averaging by more than 1/N; "
          "MAE vs truth over shadowed px: counted %.4f, averaged %.4f"
          % (tubes.GetOutput().GetNumberOfCells(), shadowed.sum(), differ.sum(),
             np.abs(counted - true)[shadowed].mean(), np.abs(averaged - true)[shadowed].mean()))
    automatic = penumbra.vtkSoftShadowPass()
    automatic.SetLightSamples(SAMPLES)
    renderer.SetPass(automatic)
    choices = []
    for _ in range(3):
        window.Render()
        choices.append("counted" if automatic.GetNumberOfCountedLights() else "averaged")
    print("Automatic, three frames: " + ", ".join(choices))
    locator = vtkOBBTree()
    locator.SetDataSet(tubes.GetOutput())
    locator.BuildLocator()
    x0, y0, z0 = LIGHT
    r = LIGHT_RADIUS
    targets = [LIGHT, (x0 + r, y0, z0), (x0 - r, y0, z0), (x0, y0 + r, z0), (x0, y0 - r, z0)]
    for y, x in list(zip(*np.nonzero(differ)))[:5]:
        renderer.SetDisplayPoint(x, y, window.GetZbufferDataAtPoint(int(x), int(y)))
        renderer.DisplayToWorld()
        world = renderer.GetWorldPoint()
        point = [world[i] / world[3] for i in range(3)]
        print("pixel %d,%d: counted %.3f, averaged %.3f, truth %.3f; walls to the light's centre "
              "and four rim points %s" % (x, y, counted[y, x], averaged[y, x], true[y, x],
                                          walls_towards(locator, point, targets)))


if __name__ == "__main__":
    main()
