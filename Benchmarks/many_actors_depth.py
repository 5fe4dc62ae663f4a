"""Many small actors: the pass's depth drawn from the casters' meshes against VTK drawing it.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/many_actors_depth.py [--actors N] [--rounds R] [--composite]

N spheres of 264 triangles share one polydata (each its own vtkActor, as an application placing
objects would make them) over a ground plane, one point light, hard shadows, 1024x768. With
--composite they are instead the N blocks of one vtkMultiBlockDataSet drawn by one
vtkCompositePolyDataMapper2 (each block its own translated copy). Each round
times the unshadowed frame, then the pass with DepthFromCasterMeshes on and off (medians of
frames with the camera turning, frame_timing.py), and prints the depth stage of one more frame
(CollectStageTimes) for each.
"""
import argparse
import math

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkCompositePolyDataMapper2

import penumbra
from frame_timing import depth_source_rounds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--actors", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--frames", type=int, default=8)
    parser.add_argument("--composite", action="store_true",
                        help="the spheres as blocks of one composite dataset")
    args = parser.parse_args()

    renderer = vtkRenderer()
    ground = vtkPlaneSource()
    ground.SetOrigin(-20, -20, 0), ground.SetPoint1(20, -20, 0), ground.SetPoint2(-20, 20, 0)
    ground_mapper = vtkPolyDataMapper()
    ground_mapper.SetInputConnection(ground.GetOutputPort())
    ground_actor = vtkActor()
    ground_actor.SetMapper(ground_mapper)
    renderer.AddActor(ground_actor)
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(12), sphere.SetPhiResolution(12), sphere.SetRadius(0.4)
    positions = [((i % 32) - 16, (i // 32) - 16, 1 + 0.3 * math.sin(i))
                 for i in range(args.actors)]
    if args.composite:
        blocks = vtkMultiBlockDataSet()
        for i, position in enumerate(positions):
            move = vtkTransform()
            move.Translate(position)
            placed = vtkTransformPolyDataFilter()
            placed.SetTransform(move)
            placed.SetInputConnection(sphere.GetOutputPort())
            placed.Update()
            blocks.SetBlock(i, placed.GetOutput())
        composite_mapper = vtkCompositePolyDataMapper2()
        composite_mapper.SetInputDataObject(blocks)
        actor = vtkActor()
        actor.SetMapper(composite_mapper)
        renderer.AddActor(actor)
    else:
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(sphere.GetOutputPort())
        for position in positions:
            actor = vtkActor()
            actor.SetMapper(mapper)
            actor.SetPosition(position)
            renderer.AddActor(actor)
    penumbra.add_light(renderer, (3, 3, 25))

    kind = "blocks of one composite actor" if args.composite else "actors"
    print(f"{args.actors} spheres as {kind} over a ground, hard shadows, 1024x768")
    depth_source_rounds(renderer, (0, -30, 25), args.rounds, args.frames)


if __name__ == "__main__":
    main()
