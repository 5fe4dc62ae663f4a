"""Counting on a receiver seen nearly edge-on, far from the eye.

A thin plate lies on a ground seen from low (the far ground about 7 degrees from edge-on), under a
soft light whose centre lies in the plate's top plane (a randomized sweep's seed 245). The
rasterized depth of the far ground is off by more than the few depth steps by which counting
moves its point towards the eye, and a move along a grazing view ray barely leaves the ground:
the point fell below the ground, where the samples above it counted one surface and the
own-surface test hid those below (rows of 45 pixels counted 0 where averaging and the truth give
0.56). Counting now takes its point off the ground's exact plane from the depth pass
(penumbra::CountingPointDepth), so it must equal averaging the same samples: at most 0.1% of the
shadowed pixels more than 1/N apart (57 before, 0.34%), none more than 0.5 (45 before)."""
import penumbra
from penumbra_testing import actor_of, check, counted_against_averaged, finish, light_pass_and_truth
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

renderer = vtkRenderer()
ground = vtkPlaneSource()
ground.SetOrigin(-3, 0, -3)
ground.SetPoint1(3, 0, -3)
ground.SetPoint2(-3, 0, 3)
ground.SetResolution(10, 10)
plate = vtkCubeSource()
plate.SetXLength(0.41732464662722946)
plate.SetYLength(0.026853619938699478)
plate.SetZLength(0.5482120598910276)
plate.SetCenter(-0.719459763250565, 0.013426809969349739, -0.7628261751991501)
renderer.AddActor(actor_of(ground, (0.8, 0.8, 0.75)))
renderer.AddActor(actor_of(plate, (0.9, 0.5, 0.3)))
light, window, shadows, truth = light_pass_and_truth(renderer, 320, 240)
light.SetPositional(True)
light.SetPosition(4.265363289322203, 0.026853619938699478, 0.05275263073905899)  # the plate's top
penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.22818319076878973)
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(-1.008104401516528, 0.02, -0.8596793211745734)
camera.SetPosition(-4.357334648632692, 0.3287001179442235, 0.8454153207544265)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(40.571976012591364)
renderer.ResetCameraClippingRange()
camera.SetClippingRange(1e-4, camera.GetClippingRange()[1])

shadowed, step, half = counted_against_averaged(window, shadows, 32)
print("shadowed %d px: counting and averaging 32 samples differ by more than 1/N on %.3f%%, by "
      "more than 0.5 on %.3f%%" % (shadowed, 100 * step, 100 * half))
check(shadowed > 5000, "the plate's shadow and the ground's far side are in view")
check(step <= 0.001 and half == 0.0, "counting equals averaging on the grazing ground")
finish()
