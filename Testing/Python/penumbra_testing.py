"""What the Python tests share: their checks, actors, and the hard-shadow comparison with the
ray-traced truth that ignores one-pixel boundary shifts."""
import sys

import numpy as np
import penumbra
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderWindow

failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def finish():
    """Prints the verdict and exits with it."""
    print("%s: %d failure(s)" % ("FAILED" if failures else "passed", len(failures)))
    sys.exit(1 if failures else 0)


def actor_of(data_or_source, color):
    mapper = vtkPolyDataMapper()
    if hasattr(data_or_source, "GetOutputPort"):
        mapper.SetInputConnection(data_or_source.GetOutputPort())
    else:
        mapper.SetInputData(data_or_source)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    return actor


def ground_and_sphere():
    """The sources of the tests' common scene: an 8 x 8 ground at y = 0 and a sphere above it."""
    plane = vtkPlaneSource()
    plane.SetOrigin(-4, 0, -4)
    plane.SetPoint1(4, 0, -4)
    plane.SetPoint2(-4, 0, 4)
    sphere = vtkSphereSource()
    sphere.SetCenter(-0.8, 1.0, 0)
    sphere.SetRadius(0.7)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    return plane, sphere


def offscreen_window(renderer, width, height):
    """An off-screen window without multisampling holding `renderer`."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    return window


def light_pass_and_truth(renderer, width, height):
    """(light, window, pass, truth) for `renderer`: a scene light shining all round, aimed at the
    origin (place it), an off-screen window, a vtkSoftShadowPass set on the renderer and the ray
    tracer reading it."""
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetConeAngle(180)
    light.SetFocalPoint(0, 0, 0)
    renderer.AddLight(light)
    window = offscreen_window(renderer, width, height)
    shadows = penumbra.vtkSoftShadowPass()
    renderer.SetPass(shadows)
    truth = penumbra.vtkRayTracedVisibility()
    truth.SetRenderer(renderer)
    return light, window, shadows, truth


def image(vtk_image, width, height):
    """A vtkImageData's scalars as a (height, width) array."""
    return vtk_to_numpy(vtk_image.GetPointData().GetScalars()).reshape(height, width)


def counted_against_averaged(window, shadows, samples):
    """(shadowed, step, half) for light 0 of `shadows`, rendered in `window` with `samples` light
    samples by averaged hard shadows and by soft shadow volumes: the pixels either method
    shadows, and the shares of them where the two differ by more than 1/N and by more than 0.5.
    Leaves the pass counting."""
    width, height = window.GetSize()
    shadows.SetLightSamples(samples)
    shadows.SetMethodToAveragedHardShadows()
    window.Render()
    averaged = image(shadows.GetVisibilityImage(0), width, height).copy()
    shadows.SetMethodToSoftShadowVolumes()
    window.Render()
    counted = image(shadows.GetVisibilityImage(0), width, height)
    shadowed = (averaged < 1) | (counted < 1)
    difference = np.abs(averaged - counted)[shadowed]
    return (int(shadowed.sum()), float((difference > 1.0 / samples + 1e-6).mean()),
            float((difference > 0.5).mean()))


def same_surface(window, truth):
    """Where the window's depth and an updated vtkRayTracedVisibility's agree: the pixels where
    both see the same surface, and so the visibilities compare."""
    width, height = window.GetSize()
    depth = image(truth.GetDepthImage(), width, height)
    zbuffer = vtkFloatArray()
    window.GetZbufferData(0, 0, width - 1, height - 1, zbuffer)
    zbuffer = vtk_to_numpy(zbuffer).reshape(height, width)
    return (depth < 1) & (np.abs(depth - zbuffer) < 1e-3)


def compare_hard_shadows(window, ours, truth, left_out=None):
    """(compared, shadowed, wrong) pixels of the visibility `ours` against an updated
    vtkRayTracedVisibility: compared on the same surface, inside a one-pixel border, except where
    the boolean image `left_out` is set; wrong where no truth pixel of the 3x3 neighbourhood is
    within 0.5."""
    width, height = window.GetSize()
    true = image(truth.GetVisibilityImage(0), width, height)
    inner = (slice(1, -1), slice(1, -1))
    compared = same_surface(window, truth)
    if left_out is not None:
        compared = compared & ~left_out
    compared = compared[inner]
    neighbourhood = [np.roll(np.roll(true, dy, 0), dx, 1) for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
    explained = np.any([np.abs(n - ours) <= 0.5 for n in neighbourhood], axis=0)[inner]
    shadowed = (compared & (true[inner] < 0.5)).sum()
    return compared.sum(), shadowed, (compared & ~explained).sum()
