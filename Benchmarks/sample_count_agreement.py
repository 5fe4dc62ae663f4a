"""Counting against averaging the same samples as N grows: the share of shadowed pixels where
they differ by more than 1/N and by more than 0.5, on the tests' ground and sphere
(penumbra_testing.ground_and_sphere), a directional light from (-2, 6, 3) of 0.4 degrees (vtkLight
is not positional unless set), 320x240.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages:Testing/Python \\
        /usr/bin/python3 Benchmarks/sample_count_agreement.py
"""
import penumbra
from penumbra_testing import (actor_of, counted_against_averaged, ground_and_sphere,
                              light_pass_and_truth)
from vtkmodules.vtkRenderingCore import vtkRenderer

WIDTH, HEIGHT = 320, 240


def main():
    renderer = vtkRenderer()
    plane, sphere = ground_and_sphere()
    renderer.AddActor(actor_of(plane, (0.9, 0.9, 0.9)))
    renderer.AddActor(actor_of(sphere, (0.9, 0.3, 0.3)))
    light, window, shadows, _ = light_pass_and_truth(renderer, WIDTH, HEIGHT)
    light.SetPosition(-2, 6, 3)
    penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.4)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(3, 5, 8)
    camera.SetFocalPoint(0, 0.5, 0)
    renderer.ResetCameraClippingRange()
    for samples in (16, 64, 255):
        shadowed, step, half = counted_against_averaged(window, shadows, samples)
        print("N %3d: %d shadowed px, differ by more than 1/N %.2f%%, by more than 0.5 %.2f%%"
              % (samples, shadowed, 100 * step, 100 * half))

if __name__ == "__main__":
    main()
