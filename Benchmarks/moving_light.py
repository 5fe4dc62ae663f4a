"""A light dragged over a still scene: what the pass saves by keeping its depth and the layers
of the lights that did not move (ReuseUnchangedShadows), against drawing every frame.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/moving_light.py [--extent E] [--frames F]

The scene is time_varying.py's (make_scene): its isosurface (about 969,500 triangles at extent
120, open where the extent clips it) on a ground plane, unchanged, the camera still, hard
shadows. Two cases: one shadowing light that turns a little every frame, and two shadowing
lights of which one turns.
Three renderings: VTK without the pass, the pass with ReuseUnchangedShadows (the default) and
the pass without, in blocks of F timed frames in the order A B C C B A, so that a drift of this
machine's load falls on all three alike; the light moves before every frame.
"""
import math
import statistics
import time

import penumbra
from time_varying import make_scene, scene_arguments


def main():
    args = scene_arguments(120, 5, "timed frames per block")
    e = args.extent
    contour, renderer, window, moving = make_scene(e)
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
