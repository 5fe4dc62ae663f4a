"""A translucent isosurface (a vtkRTAnalyticSource contour, opacity 0.4) and an opaque sphere
over a ground, with depth peeling, in a non-square 900x500 window, a light of radius 0.5 and
32 samples. Prints each method's frame time and Automatic's choice, each method's visibility
error against a 256-ray truth (mean absolute error over the pixels either shadows; pixels off by
more than 0.5) and how many shadowed pixels counting and averaging disagree on.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/translucent_isosurface.py
"""
import time

import numpy
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkContourFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow

import penumbra

WIDTH, HEIGHT = 900, 500


def actor(source, renderer, colour, opacity=1.0):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.ScalarVisibilityOff()
    result = vtkActor()
    result.SetMapper(mapper)
    result.GetProperty().SetColor(*colour)
    result.GetProperty().SetOpacity(opacity)
    renderer.AddActor(result)
    return result


def main():
    renderer = vtkRenderer()
    renderer.SetBackground(0.2, 0.2, 0.25)
    renderer.SetUseDepthPeeling(1)
    renderer.SetMaximumNumberOfPeels(6)
    renderer.SetOcclusionRatio(0)
    window = vtkRenderWindow()
    window.SetSize(WIDTH, HEIGHT)
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-15, 15, -15, 15, -15, 15)
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 170)
    isosurface = actor(contour, renderer, (0.3, 0.6, 0.9), 0.4)
    isosurface.SetScale(0.1)
    isosurface.SetPosition(-1.2, 1.8, 0)
    sphere = vtkSphereSource()
    sphere.SetCenter(1.3, 1.0, 0.3)
    sphere.SetRadius(0.7)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    actor(sphere, renderer, (0.9, 0.4, 0.3))
    ground = vtkPlaneSource()
    ground.SetOrigin(-5, 0, -5)
    ground.SetPoint1(5, 0, -5)
    ground.SetPoint2(-5, 0, 5)
    actor(ground, renderer, (1.0, 1.0, 1.0))
    penumbra.add_light(renderer, (-3, 7, 2), radius=0.5)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(2, 5, 9)
    camera.SetFocalPoint(0, 0.8, 0)
    renderer.ResetCameraClippingRange()
    shadows = penumbra.enable_shadows(renderer, samples=32)

    images = {}
    for name in ("automatic", "averaged", "soft_volumes"):
        shadows.SetMethod(penumbra.shadows.METHODS[name])
        window.Render()
        start = time.perf_counter()
        window.Render()
        milliseconds = 1e3 * (time.perf_counter() - start)
        images[name] = vtk_to_numpy(shadows.GetVisibilityImage(0).GetPointData().GetScalars()).copy()
        print("%-12s %7.0f ms  counted %d, averaged %d lights" % (
            name, milliseconds, shadows.GetNumberOfCountedLights(),
            shadows.GetNumberOfAveragedLights()))
    truth = penumbra.vtkRayTracedVisibility()
    truth.SetRenderer(renderer)
    truth.SetSamplesPerLight(256)
    truth.Update()
    expected = vtk_to_numpy(truth.GetVisibilityImage(0).GetPointData().GetScalars())
    for name, seen in images.items():
        shadowed = (seen < 1) | (expected < 1)
        print("%-12s MAE %.4f against the truth, %d px off by more than 0.5" % (
            name, numpy.abs(seen - expected)[shadowed].mean(),
            int((numpy.abs(seen - expected) > 0.5).sum())))
    counted, averaged = images["soft_volumes"], images["averaged"]
    either = (counted < 1) | (averaged < 1)
    print("counted and averaged differ by more than 1e-3 on %d of %d shadowed px (at most %.3f)" % (
        int((numpy.abs(counted - averaged) > 1e-3).sum()), int(either.sum()),
        float(numpy.abs(counted - averaged).max())))


if __name__ == "__main__":
    main()
