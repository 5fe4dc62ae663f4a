"""A movie made from a script: the camera turns, each frame is rendered and then saved through
vtkWindowToImageFilter, which renders it again (ShouldRerender, VTK's default) with a copy of the
camera. The pass draws the shadows on the first render; the screenshot's render reuses them
(ReuseUnchangedShadows) if the copy's matrix is taken as the camera's.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/screenshot_frames.py [--extent E] [--frames F]

The scene is time_varying.py's (make_scene): its isosurface (about 969,500 triangles at extent
120) on a ground plane, hard shadows. Each timed frame is an Azimuth of 2 degrees, Render and the
screenshot's Update; rows in blocks of F frames in the order none, pass, pass, none, so that a
drift of this machine's load falls on both alike. It prints each row's median and how many of
the pass's frames reused the shadows.
"""
import statistics
import time

from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

import penumbra
from time_varying import make_scene, scene_arguments


def main():
    args = scene_arguments(120, 5, "timed frames per block")
    contour, renderer, window, _ = make_scene(args.extent)
    triangles = contour.GetOutput().GetNumberOfPolys()
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToHardVolumes()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)

    def frame():
        renderer.GetActiveCamera().Azimuth(2)
        renderer.ResetCameraClippingRange()
        start = time.perf_counter()
        window.Render()
        grab.Modified()
        grab.Update()
        return (time.perf_counter() - start) * 1000.0

    def block(with_pass):
        renderer.SetPass(shadows if with_pass else None)
        frame()  # a warm-up frame after switching
        return [frame() for _ in range(args.frames)]

    times = {"none": [], "pass": []}
    reused_before = shadows.GetNumberOfReusedFrames()
    blocks = ("none", "pass", "pass", "none")
    for name in blocks:
        times[name] += block(name == "pass")
    reused = shadows.GetNumberOfReusedFrames() - reused_before
    renders = 2 * (args.frames + 1) * blocks.count("pass")  # each frame renders twice
    none, shadowed = statistics.median(times["none"]), statistics.median(times["pass"])
    print(f"{triangles} triangles, 1024x768, {len(times['pass'])} frames a row: render and "
          "screenshot")
    print(f"  no shadows    median {none:8.1f} ms")
    print(f"  hard shadows  median {shadowed:8.1f} ms ({shadowed / none:.2f}x); "
          f"{reused} of {renders} renders reused the shadows")


if __name__ == "__main__":
    main()
