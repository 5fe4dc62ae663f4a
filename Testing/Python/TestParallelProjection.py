"""Shadows seen through a parallel (orthographic) camera, against the ray-traced truth.

The pass's z-pass/z-fail choice, wedge faces and the volumes' end planes all reason about the
near rectangle, which a parallel camera moves to a plane of its own instead of a point's
neighbourhood. Hard shadows from two point lights and a directional one, seen from three sides
(one a grazing view along the ground), must match the truth but for one-pixel boundary shifts
(at most 0.2% of the compared pixels); soft shadows (counting 16 samples) must stay within the
MAE of averaging the same samples, and both near the truth. The same scenes in perspective are
checked alongside, so that a failure says which projection broke."""
import numpy as np
import penumbra
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def actor_of(source, color):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    return actor


def image(vtk_image, h, w):
    return vtk_to_numpy(vtk_image.GetPointData().GetScalars()).reshape(h, w)


renderer = vtkRenderer()
plane = vtkPlaneSource()
plane.SetOrigin(-4, 0, -4)
plane.SetPoint1(4, 0, -4)
plane.SetPoint2(-4, 0, 4)
sphere = vtkSphereSource()
sphere.SetCenter(-0.8, 1.0, 0)
sphere.SetRadius(0.7)
sphere.SetThetaResolution(48)
sphere.SetPhiResolution(24)
box = vtkCubeSource()
box.SetCenter(1.2, 0.8, 0.5)
box.SetXLength(0.8)
box.SetYLength(1.6)
box.SetZLength(0.6)
for source, color in ((plane, (0.85, 0.85, 0.8)), (sphere, (0.9, 0.3, 0.3)), (box, (0.3, 0.6, 0.9))):
    renderer.AddActor(actor_of(source, color))
light = vtkLight()
light.SetLightTypeToSceneLight()
light.SetConeAngle(180)
light.SetFocalPoint(0, 0, 0)
renderer.AddLight(light)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(400, 300)
window.AddRenderer(renderer)
shadows = penumbra.vtkSoftShadowPass()
renderer.SetPass(shadows)
truth = penumbra.vtkRayTracedVisibility()
truth.SetRenderer(renderer)
camera = renderer.GetActiveCamera()
w, h = window.GetSize()

lights = (("point above", True, (-2, 6, 3)), ("directional", False, (-1, 3, 0.5)),
          ("low point", True, (3, 1.5, -2)))
cameras = ((3, 4, 7), (0.5, 9, 0.3), (-6, 1.2, 2))
for parallel in (True, False):
    projection = "parallel" if parallel else "perspective"
    for name, positional, position in lights:
        light.SetPositional(positional)
        light.SetPosition(*position)
        for eye in cameras:
            camera.SetPosition(*eye)
            camera.SetFocalPoint(0, 0.5, 0)
            camera.SetViewUp(0, 1, 0)
            camera.SetParallelProjection(parallel)
            camera.SetParallelScale(3.5)
            renderer.ResetCameraClippingRange()
            penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.0)
            shadows.SetMethodToHardVolumes()
            window.Render()
            truth.SetSamplesPerLight(1)
            truth.Update()
            ours = image(shadows.GetVisibilityImage(0), h, w)
            true = image(truth.GetVisibilityImage(0), h, w)
            depth = image(truth.GetDepthImage(), h, w)
            zbuffer = vtkFloatArray()
            window.GetZbufferData(0, 0, w - 1, h - 1, zbuffer)
            zbuffer = vtk_to_numpy(zbuffer).reshape(h, w)
            same = ((depth < 1) & (np.abs(depth - zbuffer) < 1e-3))[1:-1, 1:-1]
            near = [np.roll(np.roll(true, dy, 0), dx, 1) for dy in (-1, 0, 1) for dx in (-1, 0, 1)]
            explained = np.any([np.abs(n - ours) <= 0.5 for n in near], axis=0)[1:-1, 1:-1]
            compared = same.sum()
            wrong = (same & ~explained).sum()
            shadowed = (same & (true[1:-1, 1:-1] < 0.5)).sum()
            label = "%s, %s light, eye %s" % (projection, name, eye)
            print("     %s: %d px compared, %d in shadow, %d wrong, %d z-fail volumes"
                  % (label, compared, shadowed, wrong, shadows.GetNumberOfZFailVolumes()))
            check(shadowed > 0.01 * compared and wrong <= 0.002 * compared,
                  label + ": hard shadows match the truth")

    # Soft shadows from the point light above, seen from the first eye.
    light.SetPositional(True)
    light.SetPosition(*lights[0][2])
    camera.SetPosition(*cameras[0])
    camera.SetParallelProjection(parallel)
    renderer.ResetCameraClippingRange()
    penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.3)
    shadows.SetLightSamples(16)
    truth.SetSamplesPerLight(64)
    truth.Update()
    true = image(truth.GetVisibilityImage(0), h, w)
    surface = image(truth.GetDepthImage(), h, w) < 1
    results = {}
    for method, choose in (("counted", shadows.SetMethodToSoftShadowVolumes),
                           ("averaged", shadows.SetMethodToAveragedHardShadows)):
        choose()
        window.Render()
        results[method] = image(shadows.GetVisibilityImage(0), h, w).copy()
    # The error where any of the three sees shadow: the penumbrae and umbrae, not the lit ground.
    shade = surface & ((true < 0.999) | (results["counted"] < 0.999) | (results["averaged"] < 0.999))
    errors = {m: np.abs(v - true)[shade].mean() for m, v in results.items()}
    print("     %s soft shadows: %d px in shade, MAE counted %.4f, averaged %.4f"
          % (projection, shade.sum(), errors["counted"], errors["averaged"]))
    check(shade.sum() > 0.02 * surface.sum() and errors["counted"] < 0.05 and
          errors["counted"] < errors["averaged"] + 0.01,
          projection + ": counted soft shadows as near the truth as averaged ones")

if failures:
    raise SystemExit("%d check(s) failed" % len(failures))
