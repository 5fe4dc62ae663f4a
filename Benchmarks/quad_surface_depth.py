"""A surface of quads (a height field, as structured data and plane sources give it): the pass's
depth drawn from the caster mesh against VTK drawing it.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/quad_surface_depth.py [--resolution R] [--rounds N]

An R x R grid of quads warped into hills (vtkPlaneSource, vtkWarpScalar), one point light, hard
shadows, 1024x768. Its quads are convex, so the casters cut them as the fan VTK draws them and
the pass may draw the surface's depth itself. Each round times the unshadowed frame, then the
pass with DepthFromCasterMeshes on and off (medians of frames with the camera turning,
frame_timing.py), and prints the depth stage of one more frame (CollectStageTimes) for each.
"""
import argparse
import math

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkFiltersGeneral import vtkWarpScalar
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

import penumbra
from frame_timing import depth_source_rounds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--resolution", type=int, default=700)
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--frames", type=int, default=8)
    args = parser.parse_args()

    plane = vtkPlaneSource()
    plane.SetOrigin(-10, -10, 0), plane.SetPoint1(10, -10, 0), plane.SetPoint2(-10, 10, 0)
    plane.SetResolution(args.resolution, args.resolution)
    plane.Update()
    flat = plane.GetOutput()
    heights = vtkFloatArray()
    heights.SetName("height")
    for i in range(flat.GetNumberOfPoints()):
        x, y, _ = flat.GetPoint(i)
        hills = math.sin(0.6 * x) * math.cos(0.5 * y)
        heights.InsertNextValue(hills + 0.3 * math.sin(1.7 * x + y))
    flat.GetPointData().SetScalars(heights)
    warp = vtkWarpScalar()
    warp.SetInputData(flat)
    warp.SetScaleFactor(1.5)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(warp.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    penumbra.add_light(renderer, (-6, -4, 12))

    print(f"{args.resolution ** 2} warped quads, hard shadows, 1024x768")
    depth_source_rounds(renderer, (0, -22, 16), args.rounds, args.frames)


if __name__ == "__main__":
    main()
