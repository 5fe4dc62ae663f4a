"""A light dragged over a still scene: what the pass saves by keeping its depth and the layers
of the lights that did not move (ReuseUnchangedShadows), against drawing every frame.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/moving_light.py [--extent E] [--frames F]

The scene is time_varying.py's isosurface (about 969,500 triangles at extent 120, open where the
extent clips it) on a ground plane, unchanged, the camera still, hard shadows. Two cases: one
shadowing light that turns a little every frame, and two shadowing lights of which one turns.
Three renderings: VTK without the pass, the pass with ReuseUnchangedShadows (the default) and
the pass without, in blocks of F timed frames in the order A B C C B A, so that a drift of this
machine's load falls on all three alike; the light moves before every frame.
"""
import argparse
import math
import statistics
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow

import penumbra


def make_actor(algorithm):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(algorithm.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--extent", type=int, default=120, help="the wavelet's half extent")
    parser.add_argument("--frames", type=int, default=5, help="timed frames per block")
    args = parser.parse_args()
    e = args.extent
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-e, e, -e, e, -e, e)
    contour = vtkFlyingEdges3D()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 160.0)
    contour.ComputeNormalsOn()
    surface = make_actor(contour)
    surface.SetPosition(0, e * 0.6, 0)
    ground = vtkPlaneSource()
    ground.SetOrigin(-2 * e, -e * 0.5, -2 * e), ground.SetPoint1(2 * e, -e * 0.5, -2 * e)
    ground.SetPoint2(-2 * e, -e * 0.5, 2 * e)

    renderer = vtkRenderer()
    renderer.AddActor(surface)
    renderer.AddActor(make_actor(ground))
    moving = penumbra.add_light(renderer, (-e, 5 * e, e))
    window = vtkRenderWindow()
    window.SetSize(1024, 768)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(2 * e, 2.5 * e, 3 * e)
    camera.SetFocalPoint(0, 0, 0)
    contour.Update()
    renderer.ResetCameraClippingRange()
    triangles = contour.GetOutput().GetNumberOfPolys()

    passes = {}
    for name, reuse in (("kept", True), ("drawn", False)):
        shadows = penumbra.vtkSoftShadowPass()
        shadows.SetMethodToHardVolumes()
        shadows.SetReuseUnchangedShadows(reuse)
        passes[name] = shadows

    def render(shadows):
        renderer.SetPass(shadows)
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        return (time.perf_counter() - start) * 1000.0

    turns = [0]

    def turn_light():
        turns[0] += 1
        angle = math.radians(3.0 * turns[0])
        c, s = math.cos(angle), math.sin(angle)
        moving.SetPosition(-e * c - e * s, 5 * e, -e * s + e * c)

    def run_case(title):
        times = {"none": [], "kept": [], "drawn": []}
        redrawn = []
        for name in ("none", "kept", "drawn", "drawn", "kept", "none"):
            for f in range(args.frames + 2):
                turn_light()
                ms = render(passes.get(name))
                if f >= 2:  # the first frames after a change of pass rebuild shaders
                    times[name].append(ms)
                    if name == "kept":
                        redrawn.append(passes["kept"].GetNumberOfRedrawnLights())
        none, kept, drawn = (statistics.median(times[n]) for n in ("none", "kept", "drawn"))
        print(f"{title}")
        print(f"  no shadows                     median {none:8.1f} ms")
        print(f"  hard shadows, depth kept       median {kept:8.1f} ms  ({kept / none:.2f}x;"
              f" lights drawn per frame: {statistics.median(redrawn):.0f})")
        print(f"  hard shadows, all drawn        median {drawn:8.1f} ms  ({drawn / none:.2f}x)")
        print(f"  drawn / kept: {drawn / kept:.2f}")

    print(f"a still isosurface of {triangles} triangles and a ground, 1024x768, camera still,"
          f" 2 x {args.frames} timed frames each")
    run_case("one shadowing light, turning 3 degrees a frame")
    penumbra.add_light(renderer, (e, 5 * e, 2 * e))
    run_case("two shadowing lights, one of them turning")


if __name__ == "__main__":
    main()
