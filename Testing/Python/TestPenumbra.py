"""Python use of the penumbra package: API, hard shadows against the ray-traced truth, and a
regression image. Usage: TestPenumbra.py <baseline.png> <output directory>"""
import sys

import numpy as np
import penumbra
from penumbra_testing import (actor_of, check, compare_hard_shadows, finish, ground_and_sphere, image,
                              offscreen_window, same_surface)
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkConeSource
from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderer
from vtkmodules.vtkTestingRendering import vtkTesting
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401


def shaded_actor_of(data_or_source, color):
    actor = actor_of(data_or_source, color)
    actor.GetProperty().SetAmbient(0.2)
    actor.GetProperty().SetSpecular(0.3)
    return actor


# API: light radius and per-prop keys, the VTK way.
light = vtkLight()
check(penumbra.vtkSoftShadowPass.GetLightRadius(light) == 0.0, "default light radius is 0")
penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.25)
check(penumbra.vtkSoftShadowPass.GetLightRadius(light) == 0.25, "light radius round-trips")
penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.0)

renderer = vtkRenderer()
renderer.SetBackground(0.15, 0.17, 0.25)
plane, sphere = ground_and_sphere()
cone = vtkConeSource()
cone.SetCenter(1.2, 0.8, 0.5)
cone.SetDirection(0, 1, 0)
cone.SetHeight(1.6)
cone.SetResolution(24)
ground = shaded_actor_of(plane, (0.85, 0.85, 0.8))
for a in (ground, shaded_actor_of(sphere, (0.9, 0.3, 0.3)), shaded_actor_of(cone, (0.3, 0.6, 0.9))):
    renderer.AddActor(a)
check(penumbra.vtkSoftShadowPass.GetCastsShadows(ground), "actors cast by default")
penumbra.vtkSoftShadowPass.SetCastsShadows(ground, False)
check(not penumbra.vtkSoftShadowPass.GetCastsShadows(ground), "casting can be switched off")

# Bad input beside good casters: a lines-only actor gets a warning, nothing else changes.
points = vtkPoints()
points.InsertNextPoint(2, 0.2, -1)
points.InsertNextPoint(2, 1.5, -1)
lines = vtkCellArray()
lines.InsertNextCell(2, [0, 1])
wire = vtkPolyData()
wire.SetPoints(points)
wire.SetLines(lines)
renderer.AddActor(shaded_actor_of(wire, (1, 1, 0)))

light.SetLightTypeToSceneLight()
light.SetPositional(True)
light.SetConeAngle(180)
light.SetPosition(-2, 6, 3)
light.SetFocalPoint(0, 0, 0)
renderer.AddLight(light)
camera = renderer.GetActiveCamera()
camera.SetPosition(3, 4, 7)
camera.SetFocalPoint(0, 0.5, 0)

window = offscreen_window(renderer, 320, 240)
shadows = penumbra.vtkSoftShadowPass()
warnings = []
shadows.AddObserver(vtkCommand.WarningEvent, lambda obj, event: warnings.append(event))
renderer.SetPass(shadows)
window.Render()
check(shadows.GetNumberOfShadowingLights() == 1, "one shadowing light")
check(len(warnings) >= 1, "lines-only caster reported (%d warnings)" % len(warnings))

# Hard shadows against the ray-traced truth, ignoring one-pixel boundary shifts.
truth = penumbra.vtkRayTracedVisibility()
truth.SetRenderer(renderer)
truth.SetSamplesPerLight(1)
check(truth.Update(), "ray tracer ran")
w, h = window.GetSize()
ours = image(shadows.GetVisibilityImage(0), w, h)
depth = image(truth.GetDepthImage(), w, h)
compared, shadowed, wrong = compare_hard_shadows(window, ours, truth)
surface = same_surface(window, truth)
print("     compared %d px, in shadow %d, wrong %d" % (compared, shadowed, wrong))
check(shadowed > 0.02 * compared, "shadow in view")
check(wrong <= 0.002 * compared, "agrees with ray-traced truth (<= 0.2% wrong)")
check(ours[depth >= 1].min() == 1.0, "background is fully lit")

testing = vtkTesting()
for argument in ("-V", sys.argv[1], "-T", sys.argv[2]):
    testing.AddArgument(argument)
testing.SetRenderWindow(window)
check(testing.RegressionTest(10) == vtkTesting.PASSED, "matches its baseline image")

# Soft shadows: soft shadow volumes (per-sample counting) against the truth.
penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.5)
shadows.SetMethodToSoftShadowVolumes()
window.Render()
check(shadows.GetNumberOfPenumbraWedges() > 0, "an area light is counted with wedges")
truth.SetSamplesPerLight(256)
truth.Update()
ours = image(shadows.GetVisibilityImage(0), w, h)
true = image(truth.GetVisibilityImage(0), w, h)
region = surface & ((true < 0.999) | (ours < 0.999))
error = np.abs(ours - true)[region]
print("     soft: %d px, MAE %.4f, >0.1: %.2f%%" % (region.sum(), error.mean(), 100 * (error > 0.1).mean()))
check(np.isfinite(ours).all() and ours.min() >= 0 and ours.max() <= 1, "soft visibility in [0, 1]")
# Measured MAE 0.0062 and 0.17% above 0.1 at 64 samples (2026-12-06; 0.0149 and 3.2% before the
# tight depth range). What is left is the sphere's and cone's terminators, where counting takes the
# point from the depth buffer (Documentation/wedges.md, "Where it is not exact").
check(error.mean() < 0.016 and (error > 0.1).mean() < 0.04, "soft shadows agree with the truth")
soft = vtkTesting()
for argument in ("-V", sys.argv[1].replace(".png", "_soft.png"), "-T", sys.argv[2]):
    soft.AddArgument(argument)
soft.SetRenderWindow(window)
check(soft.RegressionTest(10) == vtkTesting.PASSED, "soft shadows match their baseline image")

# Counting at half resolution: every other pixel counted, the rest the mean of their counted
# neighbours or counted again; within 0.005 of the full count's MAE (C++ TestSoftShadowVolumes
# holds it to the full count pixel by pixel).
soft_mae = error.mean()
full_bytes = shadows.GetGraphicsMemoryBytes()
shadows.HalfResolutionCountingOn()
check(shadows.GetHalfResolutionCounting(), "half-resolution counting is on")
window.Render()
# Its depth-stencil and visibility, 4 bytes each per counter texel: it did count at half size.
check(shadows.GetGraphicsMemoryBytes() == full_bytes + ((w + 1) // 2) * ((h + 1) // 2) * 8,
      "half-resolution targets in use")
half = image(shadows.GetVisibilityImage(0), w, h)
half_mae = np.abs(half - true)[region].mean()
print("     soft at half resolution: MAE %.4f (full %.4f)" % (half_mae, soft_mae))
check(np.isfinite(half).all() and half.min() >= 0 and half.max() <= 1, "half-resolution visibility in [0, 1]")
check(half_mae < soft_mae + 0.005, "half-resolution counting near the full count")
shadows.HalfResolutionCountingOff()
window.Render()
check(shadows.GetGraphicsMemoryBytes() == full_bytes, "half-resolution targets freed once off")

# Plateaus on the ground plane, marked through the actor's keys.
penumbra.vtkSoftShadowPass.SetShadowPlane(ground, True)
check(penumbra.vtkSoftShadowPass.GetShadowPlane(ground), "shadow plane key round-trips")
shadows.SetMethodToPlateaus()
check(shadows.GetMethodAsString() == "Plateaus", "plateaus selected")
window.Render()
ours = image(shadows.GetVisibilityImage(0), w, h)
error = np.abs(ours - true)[region]
print("     plateaus: MAE %.4f, %d plateau triangles" % (error.mean(), shadows.GetNumberOfPlateauTriangles()))
check(shadows.GetNumberOfPlateauTriangles() > 0, "plateau triangles drawn")
# Measured MAE 0.1106: the umbra is too large by design and off the plane shadows are hard.
check(np.isfinite(ours).all() and error.mean() < 0.13, "plateaus near the truth")

# A frame that changes nothing composites the last frame's shadows; a moved light draws them.
check(shadows.GetReuseUnchangedShadows(), "ReuseUnchangedShadows is on by default")
window.Render()
reused = shadows.GetNumberOfReusedFrames()
window.Render()
check(shadows.GetNumberOfReusedFrames() == reused + 1, "an unchanged frame reuses the shadows")
check(np.array_equal(image(shadows.GetVisibilityImage(0), w, h), ours), "reused shadows are the drawn ones")
position = light.GetPosition()
light.SetPosition(position[0] + 0.5, position[1], position[2])
window.Render()
check(shadows.GetNumberOfReusedFrames() == reused + 1, "a moved light draws the shadows again")
check(not np.array_equal(image(shadows.GetVisibilityImage(0), w, h), ours), "and they moved")
light.SetPosition(position)

finish()
