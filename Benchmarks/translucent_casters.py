"""Translucent casters under a soft light: frame times of averaging and counting the same
samples, and of Automatic's choice between them, with the casters translucent (opacity 0.5)
and opaque, against VTK alone, in one run at 1024x768, and each method's visibility error
against a 256-ray truth (mean absolute error over the pixels that either shadows). The scene is
TestTranslucentCasters' one: a ground, an opaque box, a translucent sphere, an open translucent
sheet and a small translucent sphere in the box's shadow, lit by a positional light of radius
0.4. Medians of 5 frames, the camera turning 1 degree a frame.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/translucent_casters.py
"""
import numpy
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow

import penumbra
from frame_timing import median_frame_ms

WIDTH, HEIGHT = 1024, 768


def actor(source, renderer):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    result = vtkActor()
    result.SetMapper(mapper)
    renderer.AddActor(result)
    return result


def plane(half):
    source = vtkPlaneSource()
    source.SetOrigin(-half, 0, -half)
    source.SetPoint1(half, 0, -half)
    source.SetPoint2(-half, 0, half)
    source.SetResolution(4, 4)
    return source


def sphere(centre, radius):
    source = vtkSphereSource()
    source.SetCenter(*centre)
    source.SetRadius(radius)
    source.SetThetaResolution(40)
    source.SetPhiResolution(20)
    return source


def main():
    renderer = vtkRenderer()
    actor(plane(5.0), renderer)
    box = vtkCubeSource()
    box.SetCenter(1.3, 0.6, 0.2)
    box.SetXLength(0.8)
    box.SetYLength(1.2)
    box.SetZLength(0.8)
    actor(box, renderer)
    sheet = actor(plane(0.5), renderer)
    sheet.SetPosition(0.3, 2.0, -1.4)
    glass = [actor(sphere((-1.0, 1.4, 0.0), 0.6), renderer), sheet,
             actor(sphere((2.2, 0.3, -0.4), 0.25), renderer)]
    light = penumbra.add_light(renderer, (-2, 6, 3), radius=0.4)
    window = vtkRenderWindow()
    window.SetSize(WIDTH, HEIGHT)
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(3, 5, 8)
    camera.SetFocalPoint(0, 0.5, 0)
    renderer.ResetCameraClippingRange()

    def frames(n):
        return median_frame_ms(window, renderer, n, 1, turn_back=True)

    frames(2)
    none = frames(5)
    shadows = penumbra.vtkSoftShadowPass()
    renderer.SetPass(shadows)

    def visibility():
        window.Render()
        return vtk_to_numpy(shadows.GetVisibilityImage(0).GetPointData().GetScalars()).copy()

    print("translucent casters, 1024x768, light radius 0.4; VTK alone %.1f ms" % none)
    for opacity in (0.5, 1.0):
        for caster in glass:
            caster.GetProperty().SetOpacity(opacity)
        shadows.SetMethodToHardVolumes()
        window.Render()
        truth = penumbra.vtkRayTracedVisibility()
        truth.SetRenderer(renderer)
        truth.SetSamplesPerLight(256)
        truth.Update()
        expected = vtk_to_numpy(truth.GetVisibilityImage(0).GetPointData().GetScalars())
        for samples in (16, 64):
            shadows.SetLightSamples(samples)
            row = []
            for name, method in (("averaged", shadows.SetMethodToAveragedHardShadows),
                                 ("counted", shadows.SetMethodToSoftShadowVolumes),
                                 ("automatic", shadows.SetMethodToAutomatic)):
                method()
                frames(1)
                milliseconds = frames(5)
                seen = visibility()
                shadowed = (seen < 1) | (expected < 1)
                error = float(numpy.abs(seen - expected)[shadowed].mean())
                row.append((name, milliseconds, error, shadows.GetNumberOfCountedLights()))
            print("  opacity %.1f, N = %2d: " % (opacity, samples) + "; ".join(
                "%s %.1f ms (%.1fx), MAE %.4f%s" % (
                    name, ms, ms / none, error, " [counts]" if counted else " [averages]")
                for name, ms, error, counted in row)
                + "; averaged/counted %.2f" % (row[0][1] / row[1][1]))


if __name__ == "__main__":
    main()
