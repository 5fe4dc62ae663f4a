"""A vedo user's scene: a plane, an opaque box, a translucent sphere (alpha 0.5) and a
translucent cone (alpha 0.7) standing on the plane, shadows turned on with penumbra's helper
(light radius 0.4, 32 samples), 800x450. Prints each method's frame time and which one
Automatic picked, and the counted visibility's error against a 256-ray truth (mean absolute
error over the pixels either shadows, and pixels off by more than 0.5). `--lift D` raises the
cone by D, so that its base cap no longer lies in the plane (limitations.md, "Unlit props").

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/vedo_translucent.py [--lift 0.05]
"""
import argparse
import time

import numpy
import vedo
from vtkmodules.util.numpy_support import vtk_to_numpy

import penumbra


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lift", type=float, default=0.0, help="raise the cone off the plane")
    args = parser.parse_args()
    vedo.settings.default_backend = "vtk"
    sphere = vedo.Sphere(pos=(0, 1.2, 0), r=0.6).c("tomato").alpha(0.5)
    box = vedo.Box(pos=(1.4, 0.5, 0), length=0.6, width=1.0, height=0.6).c("steelblue")
    plane = vedo.Plane(pos=(0, 0, 0), normal=(0, 1, 0), s=(8, 8)).c("white")
    cone = vedo.Cone(pos=(-1.5, 0.6 + args.lift, 0.6), r=0.4, height=1.2, axis=(0, 1, 0))
    cone.c("gold").alpha(0.7)
    plotter = vedo.Plotter(offscreen=True, size=(800, 450))
    plotter.show(sphere, box, plane, cone, camera=dict(pos=(3, 5, 8), focal_point=(0, 0.5, 0)),
                 interactive=False)
    renderer, window = plotter.renderer, plotter.window
    light = penumbra.add_light(renderer, (-2, 6, 3), radius=0.4)
    shadows = penumbra.enable_shadows(renderer, samples=32)
    lights = renderer.GetLights()
    index = [i for i in range(lights.GetNumberOfItems()) if lights.GetItemAsObject(i) is light][0]

    def visibility():
        image = shadows.GetVisibilityImage(index)
        return vtk_to_numpy(image.GetPointData().GetScalars()).copy()

    for name in ("automatic", "averaged", "soft_volumes"):
        shadows.SetMethod(penumbra.shadows.METHODS[name])
        window.Render()
        start = time.perf_counter()
        window.Render()
        milliseconds = 1e3 * (time.perf_counter() - start)
        print("%-12s %7.0f ms  counted %d, averaged %d lights" % (
            name, milliseconds, shadows.GetNumberOfCountedLights(),
            shadows.GetNumberOfAveragedLights()))
    counted = visibility()
    truth = penumbra.vtkRayTracedVisibility()
    truth.SetRenderer(renderer)
    truth.SetSamplesPerLight(256)
    truth.Update()
    expected = vtk_to_numpy(truth.GetVisibilityImage(index).GetPointData().GetScalars())
    shadowed = (counted < 1) | (expected < 1)
    print("counted against the truth: MAE %.4f, %d px off by more than 0.5 (cone lifted by %g)" % (
        numpy.abs(counted - expected)[shadowed].mean(),
        int((numpy.abs(counted - expected) > 0.5).sum()), args.lift))


if __name__ == "__main__":
    main()
