"""A real client: a vedo scene (Plotter, vedo.Light, vedo meshes) with shadows from
penumbra.enable_shadows, checked against the ray-traced truth. vedo.Light is directional, so the
light's size is an angle (angular_radius, degrees).

Tolerance: hard shadows (CheckAgainstTruth's 0.2% of compared pixels wrong away from shadow
boundaries), and a soft light whose visibility MAE against the truth is below 0.03."""
import warnings

import numpy as np
import penumbra
import vedo
from penumbra_testing import check, finish
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter


vedo.settings.default_backend = "vtk"
plotter = vedo.Plotter(offscreen=True, size=(480, 320))
ground = vedo.Box(pos=(0, -0.05, 0), length=6, width=0.1, height=6).c("white")
ball = vedo.Sphere(pos=(-0.8, 1.0, 0.0), r=0.6, res=36).c("tomato")
box = vedo.Cube(pos=(1.0, 0.6, 0.3), side=0.9).c("steelblue")
sun = vedo.Light(pos=(-2, 6, 3), focal_point=(0, 0, 0), intensity=1.0)
plotter.show(ground, ball, box, sun, camera={"pos": (3, 5, 8), "focal_point": (0, 0.5, 0)},
             interactive=False)
renderer = plotter.renderer

with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    shadows = penumbra.enable_shadows(renderer, angular_radius=0.0, method="hard")
check(not caught, "no warning: the vedo light casts")
check(not sun.GetPositional(), "vedo.Light is directional")
plotter.render()
check(shadows.GetNumberOfShadowingLights() >= 1, "the pass shadows with the vedo light")


def visibility(pass_, index):
    return vtk_to_numpy(pass_.GetVisibilityImage(index).GetPointData().GetScalars())


def truth_of(samples):
    truth = penumbra.vtkRayTracedVisibility()
    truth.SetRenderer(renderer)
    truth.SetSamplesPerLight(samples)
    check(truth.Update(), "the ray tracer ran")
    return truth


# The light's index among the renderer's lights (vedo may add its own).
lights = renderer.GetLights()
index = [lights.GetItemAsObject(i) for i in range(lights.GetNumberOfItems())].index(sun)
layer = 0
ours = visibility(shadows, layer)
truth = truth_of(1)
expected = vtk_to_numpy(truth.GetVisibilityImage(index).GetPointData().GetScalars())
depth = vtk_to_numpy(truth.GetDepthImage().GetPointData().GetScalars())
seen = depth < 1.0
wrong = np.abs(ours - expected) > 0.5
shadowed = (expected < 0.5) & seen
print(f"     hard: {seen.sum()} px seen, {shadowed.sum()} shadowed, {wrong[seen].mean():.4%} differ")
check(shadowed.sum() > 0.02 * seen.sum(), "hard: the vedo scene has shadow in view")
# Differences only on shadow and object boundaries: not more than 1% of the seen pixels.
check(wrong[seen].mean() < 0.01, "hard: agrees with the ray-traced truth")

shadows = penumbra.enable_shadows(renderer, angular_radius=3.0, samples=64)
plotter.render()
soft = visibility(shadows, layer)
truth = truth_of(256)
expected = vtk_to_numpy(truth.GetVisibilityImage(index).GetPointData().GetScalars())
penumbral = seen & ((expected < 1.0) | (soft < 1.0))
mae = np.abs(soft - expected)[penumbral].mean()
print(f"     soft (3 degrees): MAE {mae:.4f} over {penumbral.sum()} px")
check(penumbral.sum() > shadowed.sum(), "soft: a penumbra wider than the hard shadow")
check(mae < 0.03, "soft: close to the ray-traced truth")

try:
    penumbra.enable_shadows(renderer, method="raytraced")
    check(False, "an unknown method is refused")
except ValueError:
    check(True, "an unknown method is refused")
# The renderer's own settings stay on: the pass's default delegate draws the scene as the
# renderer would, here with FXAA (on a single-sampled window; see limitations.md).
def frame():
    plotter.render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(plotter.window)
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).copy()


check(isinstance(shadows.GetDelegatePass(), penumbra.vtkRendererSettingsPass),
      "enable_shadows draws the scene through vtkRendererSettingsPass")
plotter.window.SetMultiSamples(0)
renderer.SetUseFXAA(True)
penumbra.disable_shadows(renderer)
vtk_fxaa = frame()
shadows = penumbra.enable_shadows(renderer)
shadows.ShadowsEnabledOff()
pass_fxaa = frame()
renderer.SetUseFXAA(False)
pass_plain = frame()
shadows.ShadowsEnabledOn()
fxaa_kept = np.abs(pass_fxaa.astype(int) - vtk_fxaa).max(axis=1) > 2
fxaa_changes = np.abs(pass_plain.astype(int) - vtk_fxaa).max(axis=1) > 2
print(f"     FXAA: {fxaa_kept.mean():.4%} of pixels differ from VTK's, {fxaa_changes.mean():.4%} "
      "without it")
check(fxaa_kept.mean() < 0.001 and fxaa_changes.mean() > 0.002,
      "enable_shadows keeps the renderer's FXAA (the image is VTK's with FXAA)")

# vedo's light is directional: a radius in world units is for positional lights, and is said
# to change nothing rather than silently giving hard shadows.
import warnings as python_warnings
with python_warnings.catch_warnings(record=True) as caught:
    python_warnings.simplefilter("always")
    before = penumbra.vtkSoftShadowPass.GetLightRadius(sun)
    penumbra.enable_shadows(renderer, radius=0.3, lights=[sun])
said = [str(w.message) for w in caught if "radius=0.3 is for positional lights" in str(w.message)]
check(len(said) == 1 and penumbra.vtkSoftShadowPass.GetLightRadius(sun) == before,
      "a radius for directional lights only: one warning, the light unchanged")
# A headlight cannot cast: beside a positional light (VTK's automatic headlight is in the list
# once the renderer has drawn), an angle given for directional lights still changes nothing.
from vtkmodules.vtkRenderingCore import vtkLight
headlight = vtkLight()
headlight.SetLightTypeToHeadlight()
lamp = vtkLight()
lamp.SetPositional(True)
lamp.SetPosition(2, 6, 3)
with python_warnings.catch_warnings(record=True) as caught:
    python_warnings.simplefilter("always")
    penumbra.enable_shadows(renderer, angular_radius=2, lights=[lamp, headlight])
said = [str(w.message) for w in caught if "angular_radius=2 is for directional" in str(w.message)]
check(len(said) == 1, "an angle beside a positional light and a headlight: one warning")

# vedo's Plane is unlit by default, so no shadow shows on it, and vedo switches VTK's warnings
# (the pass's among them) off: enable_shadows says so in Python.
plane = vedo.Plane(pos=(0, 0.01, 2.5), s=(1, 1), normal=(0, 1, 0))
plotter.add(plane)


def unlit_warnings():
    with python_warnings.catch_warnings(record=True) as caught:
        python_warnings.simplefilter("always")
        penumbra.enable_shadows(renderer)
    return [str(w.message) for w in caught if "Lighting off" in str(w.message)]


check(len(unlit_warnings()) == 1, "an unlit vedo Plane: one Python warning")
plane.lighting("default")
check(not unlit_warnings(), "the plane lit: no warning")
plotter.remove(plane)

for bad in (-1.0, float("nan")):
    refused = []
    for call in (lambda: penumbra.add_light(renderer, (0, 5, 0), radius=bad),
                 lambda: penumbra.enable_shadows(renderer, angular_radius=bad, lights=[sun])):
        try:
            call()
            refused.append(False)
        except ValueError:
            refused.append(True)
    check(all(refused), "a radius of %r: both helpers refuse it" % bad)
penumbra.disable_shadows(renderer)
check(renderer.GetPass() is None, "disable_shadows takes the pass off")
light = penumbra.add_light(renderer, (1, 4, 2), radius=0.3)
check(light.GetPositional() and penumbra.vtkSoftShadowPass.GetLightRadius(light) == 0.3 and
      penumbra.vtkSoftShadowPass.LightCastsShadows(light), "add_light: a positional scene light that casts")
renderer.RemoveLight(light)
plotter.close()
finish()
