"""Imposter spheres (vtkOpenGLSphereMapper, a lattice of N atoms above a ground plane) casting
shadows: frame times against VTK alone, hard shadows, Automatic with a light radius of 0.3, and
averaging 64 and 16 samples, all in one run at 1024x768, with the pass's counters and the
stage split of one timed Automatic frame. Medians of 5 frames (3 for the soft methods), the
camera turning 2 degrees a frame.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/imposter_spheres.py [N]
"""
import math
import sys

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLSphereMapper

import penumbra
from frame_timing import median_frame_ms


def atoms(count):
    """`count` spheres on a cubic lattice, each with verts (VTK draws nothing without cells)."""
    points, radius, verts = vtkPoints(), vtkFloatArray(), vtkCellArray()
    radius.SetName("radius")
    side = int(math.ceil(count ** (1.0 / 3.0)))
    for i in range(count):
        x, y, z = i % side, (i // side) % side, i // (side * side)
        verts.InsertNextCell(1)
        verts.InsertCellPoint(points.InsertNextPoint(
            -1.0 + 2.0 * x / side, 0.6 + 1.5 * z / side, -1.0 + 2.0 * y / side))
        radius.InsertNextValue(0.35 / side)
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetVerts(verts)
    data.GetPointData().AddArray(radius)
    return data


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 125
    mapper = vtkOpenGLSphereMapper()
    mapper.SetInputData(atoms(count))
    mapper.SetScaleArray("radius")
    molecule = vtkActor()
    molecule.SetMapper(mapper)
    plane = vtkPlaneSource()
    plane.SetOrigin(-3, 0, -3)
    plane.SetPoint1(3, 0, -3)
    plane.SetPoint2(-3, 0, 3)
    ground_mapper = vtkPolyDataMapper()
    ground_mapper.SetInputConnection(plane.GetOutputPort())
    ground = vtkActor()
    ground.SetMapper(ground_mapper)
    renderer = vtkRenderer()
    renderer.AddActor(molecule)
    renderer.AddActor(ground)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(-1, 6, 2)
    light.SetFocalPoint(0, 0, 0)
    light.SetPositional(True)
    light.SetConeAngle(80)
    renderer.AddLight(light)
    window = vtkRenderWindow()
    window.SetSize(1024, 768)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(3, 4, 7)
    camera.SetFocalPoint(0, 0.6, 0)

    def frames(n):
        return median_frame_ms(window, renderer, n, 2)

    frames(2)
    none = frames(5)
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToHardVolumes()
    renderer.SetPass(shadows)
    hard_first = frames(1)
    hard = frames(5)
    penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.3)
    shadows.SetMethodToAutomatic()
    frames(1)
    automatic = frames(3)
    shadows.CollectStageTimesOn()
    window.Render()
    counters = "counted %d, averaged %d lights; %d wedges, %d volume triangles" % (
        shadows.GetNumberOfCountedLights(), shadows.GetNumberOfAveragedLights(),
        shadows.GetNumberOfPenumbraWedges(), shadows.GetNumberOfShadowVolumeTriangles())
    stages = ", ".join("%s %.1f" % (shadows.GetStageName(s), shadows.GetStageCPUMilliseconds(s))
                       for s in range(shadows.NUMBER_OF_STAGES))
    shadows.CollectStageTimesOff()
    shadows.SetMethodToAveragedHardShadows()
    frames(1)
    averaged64 = frames(3)
    shadows.SetLightSamples(16)
    frames(1)
    averaged16 = frames(3)
    print("%d imposter spheres, 1024x768" % count)
    print("  none          %8.1f ms" % none)
    print("  hard_volumes  %8.1f ms (%.1fx; first frame %.0f ms)" % (hard, hard / none,
                                                                     hard_first))
    print("  automatic_64  %8.1f ms (%.1fx)  [%s; %s]" % (automatic, automatic / none, counters,
                                                          stages))
    print("  averaged_64   %8.1f ms (%.1fx)" % (averaged64, averaged64 / none))
    print("  averaged_16   %8.1f ms (%.1fx)" % (averaged16, averaged16 / none))


if __name__ == "__main__":
    main()
