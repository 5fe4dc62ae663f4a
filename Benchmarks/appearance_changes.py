"""Colours changed between frames, as a user tuning a colour map or highlighting a block does:
what the pass saves by reusing its shadows when only the look of props changed
(ReuseUnchangedShadows), against drawing them every frame, as it did for such frames before.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/appearance_changes.py [--extent E] [--frames F]

Two scenes, each with the camera and light still and hard shadows, at 1024x768:
- time_varying.py's isosurface (about 969,500 triangles at extent 120), coloured by its scalars,
  its mapper's scalar range moved before every frame;
- 5,000 spheres (8 x 8 facets each) as the blocks of one multiblock dataset under a
  vtkCompositePolyDataMapper2 over a ground, one block's colour changed before every frame.
Three renderings of each: VTK without the pass, the pass (reusing its shadows) and the pass with
ReuseUnchangedShadows off, in blocks of F timed frames in the order A B C C B A, so that a drift
of this machine's load falls on all three alike. Prints medians and the frames reused.
"""
import statistics
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCompositeDataDisplayAttributes,
                                         vtkRenderer, vtkRenderWindow)
from vtkmodules.vtkRenderingOpenGL2 import vtkCompositePolyDataMapper2

import penumbra
from time_varying import make_actor, make_scene, scene_arguments

BLOCKS = 5000


def block_scene(count, window):
    """`count` small spheres in a square grid as one multiblock over a ground, in `window`:
    (renderer, mapper, keep)."""
    blocks = vtkMultiBlockDataSet()
    side = int(count ** 0.5 + 0.999)
    for i in range(count):
        sphere = vtkSphereSource()
        sphere.SetCenter(i % side - side / 2, 1.0, i // side - side / 2)
        sphere.SetRadius(0.35)
        sphere.SetThetaResolution(8)
        sphere.SetPhiResolution(8)
        sphere.Update()
        blocks.SetBlock(i, sphere.GetOutput())
    mapper = vtkCompositePolyDataMapper2()
    mapper.SetInputDataObject(blocks)
    attributes = vtkCompositeDataDisplayAttributes()
    mapper.SetCompositeDataDisplayAttributes(attributes)
    actor = vtkActor()
    actor.SetMapper(mapper)
    ground = vtkPlaneSource()
    ground.SetOrigin(-side, 0, -side), ground.SetPoint1(side, 0, -side)
    ground.SetPoint2(-side, 0, side)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.AddActor(make_actor(ground))
    penumbra.add_light(renderer, (-side, 3 * side, side))
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.6 * side, 0.8 * side, 1.1 * side)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCameraClippingRange()
    return renderer, mapper, (blocks, attributes, actor, ground)


def run_case(title, window, renderer, change, frames):
    """Times the three renderings of `renderer` in `window`, `change` applied before every
    frame, and prints their medians."""
    passes = {}
    for name, reuse in (("reused", True), ("drawn", False)):
        shadows = penumbra.vtkSoftShadowPass()
        shadows.SetMethodToHardVolumes()
        shadows.SetReuseUnchangedShadows(reuse)
        passes[name] = shadows
    times = {"none": [], "reused": [], "drawn": []}
    reused = 0
    for name in ("none", "reused", "drawn", "drawn", "reused", "none"):
        renderer.SetPass(passes.get(name))
        for f in range(frames + 2):
            change()
            before = passes["reused"].GetNumberOfReusedFrames()
            start = time.perf_counter()
            window.Render()
            window.WaitForCompletion()
            ms = (time.perf_counter() - start) * 1000.0
            if f >= 2:  # the first frames after a change of pass draw everything
                times[name].append(ms)
                reused += passes["reused"].GetNumberOfReusedFrames() - before
    none = statistics.median(times["none"])
    print(title)
    print("  no shadows %.1f ms" % none)
    for name in ("reused", "drawn"):
        median = statistics.median(times[name])
        print("  %-6s     %.1f ms (%.2fx)" % (name, median, median / none))
    print("  frames that reused the shadows: %d of %d" % (reused, 2 * frames))
    renderer.SetPass(None)


def main():
    args = scene_arguments(120, 5, "timed frames per block")
    contour, renderer, window, _ = make_scene(args.extent)
    surface = renderer.GetActors().GetItemAsObject(0)
    surface.GetMapper().ScalarVisibilityOn()
    low = [80.0]

    def move_range():
        low[0] = 80.0 + (low[0] - 79.0) % 40.0
        surface.GetMapper().SetScalarRange(low[0], 260.0)

    run_case("isosurface of %d triangles, its scalar range moved every frame"
             % contour.GetOutput().GetNumberOfPolys(), window, renderer, move_range, args.frames)
    window.RemoveRenderer(renderer)

    blocks_renderer, mapper, keep = block_scene(BLOCKS, window)
    turn = [0]

    def recolour_block():
        turn[0] += 1
        mapper.SetBlockColor(1 + turn[0] % BLOCKS, (turn[0] % 2, 0.5, 0.2))

    run_case("%d sphere blocks, one block's colour changed every frame" % BLOCKS, window,
             blocks_renderer, recolour_block, args.frames)
    del keep


if __name__ == "__main__":
    main()
