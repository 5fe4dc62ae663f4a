"""Shadows seen through a parallel (orthographic) camera, against the ray-traced truth.

The pass's z-pass/z-fail choice, wedge faces and the volumes' end planes all reason about the
near rectangle, which a parallel camera moves to a plane of its own instead of a point's
neighbourhood. Hard shadows from two point lights and a directional one, seen from three sides
(one a grazing view along the ground), must match the truth but for one-pixel boundary shifts
(at most 0.2% of the compared pixels); soft shadows (counting 16 samples) must stay within the
MAE of averaging the same samples, and both near the truth, and equal averaging with a clipping
range the user set far wider than the scene (the pass narrows it for its shadows). The same scenes
in perspective are checked alongside, so that a failure says which projection broke."""
import numpy as np
import penumbra
from penumbra_testing import (actor_of, check, compare_hard_shadows, counted_against_averaged, finish,
                              ground_and_sphere, image, light_pass_and_truth)
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

renderer = vtkRenderer()
plane, sphere = ground_and_sphere()
box = vtkCubeSource()
box.SetCenter(1.2, 0.8, 0.5)
box.SetXLength(0.8)
box.SetYLength(1.6)
box.SetZLength(0.6)
for source, color in ((plane, (0.85, 0.85, 0.8)), (sphere, (0.9, 0.3, 0.3)), (box, (0.3, 0.6, 0.9))):
    renderer.AddActor(actor_of(source, color))
light, window, shadows, truth = light_pass_and_truth(renderer, 400, 300)
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
            ours = image(shadows.GetVisibilityImage(0), w, h)
            compared, shadowed, wrong = compare_hard_shadows(window, ours, truth)
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
    true = image(truth.GetVisibilityImage(0), w, h)
    surface = image(truth.GetDepthImage(), w, h) < 1
    results = {}
    for method, choose in (("counted", shadows.SetMethodToSoftShadowVolumes),
                           ("averaged", shadows.SetMethodToAveragedHardShadows)):
        choose()
        window.Render()
        results[method] = image(shadows.GetVisibilityImage(0), w, h).copy()
    # The error where any of the three sees shadow: the penumbrae and umbrae, not the lit ground.
    shade = surface & ((true < 0.999) | (results["counted"] < 0.999) | (results["averaged"] < 0.999))
    errors = {m: np.abs(v - true)[shade].mean() for m, v in results.items()}
    print("     %s soft shadows: %d px in shade, MAE counted %.4f, averaged %.4f"
          % (projection, shade.sum(), errors["counted"], errors["averaged"]))
    check(shade.sum() > 0.02 * surface.sum() and errors["counted"] < 0.05 and
          errors["counted"] < errors["averaged"] + 0.01,
          projection + ": counted soft shadows as near the truth as averaged ones")

    # A clipping range the user set far wider than the scene: the pass narrows it for its own
    # drawing in either projection, so counting still equals averaging but for single pixels.
    camera.SetClippingRange(1e-4, 1e3)
    shadowed, differ, _ = counted_against_averaged(window, shadows, 16)
    print("     %s, range (1e-4, 1e3): %.2f%% of %d shadowed px differ by more than 1/N"
          % (projection, 100 * differ, shadowed))
    check(shadowed > 0.02 * surface.sum() and differ <= 0.003,
          projection + ": counting equals averaging with a wide user range")

# A point light behind the plane of a parallel eye close to a lone, open ground: the ground's
# volumes are drawn z-fail, and their far end at infinity, which lies behind every pixel here,
# is drawn nowhere by a parallel projection (every swept point at w = 0). A sweep of random
# scenes found averaged and counted shadows reading the whole lit ground as shadowed (mean
# visibility 0 against the truth's 1), while the one-sample hard shadow happened to be right.
renderer.RemoveAllViewProps()
ground = vtkPlaneSource()
ground.SetOrigin(-3, 0, -3)
ground.SetPoint1(3, 0, -3)
ground.SetPoint2(-3, 0, 3)
renderer.AddActor(actor_of(ground, (0.85, 0.85, 0.8)))
light.SetPositional(True)
light.SetPosition(-0.49, 1.93, -2.70)
penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.064)
focal = np.array([-0.089, 0.586, 0.608])
towards_eye = np.array([-0.103, 0.323, -0.221])
camera.SetFocalPoint(*focal)
camera.SetPosition(*(focal + 0.4 * towards_eye / np.linalg.norm(towards_eye)))
camera.SetViewUp(0, 1, 0)
camera.SetParallelProjection(True)
camera.SetParallelScale(0.1)
renderer.ResetCameraClippingRange()
truth.SetSamplesPerLight(64)
truth.Update()
true = image(truth.GetVisibilityImage(0), w, h)
for method, choose in (("averaged", shadows.SetMethodToAveragedHardShadows),
                       ("counted", shadows.SetMethodToSoftShadowVolumes)):
    choose()
    window.Render()
    ours = image(shadows.GetVisibilityImage(0), w, h)
    off = np.mean(np.abs(ours - true) > 1.0 / 16 + 1e-6)
    print("     parallel, light behind the eye's plane, %s: %d z-fail volumes, mean visibility "
          "%.3f (truth %.3f), %.2f%% of pixels off by more than 1/N"
          % (method, shadows.GetNumberOfZFailVolumes(), ours.mean(), true.mean(), 100 * off))
    check(shadows.GetNumberOfZFailVolumes() > 0 and off <= 0.002,
          "parallel, light behind the eye's plane: %s z-fail volumes end beyond the scene" % method)

finish()
