"""Glyph mapper (each glyph a cast instance of one source) against the same glyphs merged by
vtkGlyph3D into one actor: median frame times with hard shadows, in one run.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \
        /usr/bin/python3 Benchmarks/glyph_instancing.py [--glyphs N] [--frames F]

Two cases per scene: the camera orbits (silhouettes cached, only drawing), and the light moves
(every glyph's silhouette is found again each frame).
"""
import argparse
import statistics
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkGlyph3D
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkGlyph3DMapper, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)

import penumbra


def glyph_points(side):
    points, direction = vtkPoints(), vtkDoubleArray()
    direction.SetName("direction")
    direction.SetNumberOfComponents(3)
    for i in range(side * side):
        x, z = i % side, i // side
        points.InsertNextPoint(-2 + 4.0 * x / side, 0.6 + 0.2 * ((x + z) % 3), -2 + 4.0 * z / side)
        direction.InsertNextTuple3(1.0, 0.5 + 0.1 * (i % 7), 0.3 * (i % 5) - 0.6)
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.GetPointData().AddArray(direction)
    return poly


def scene(window, instanced, points, cone):
    renderer = vtkRenderer()
    ground = vtkPlaneSource()
    ground.SetOrigin(-3, 0, -3), ground.SetPoint1(3, 0, -3), ground.SetPoint2(-3, 0, 3)
    gm = vtkPolyDataMapper()
    gm.SetInputConnection(ground.GetOutputPort())
    ga = vtkActor()
    ga.SetMapper(gm)
    renderer.AddActor(ga)
    if instanced:
        mapper = vtkGlyph3DMapper()
        mapper.SetInputData(points)
        mapper.SetSourceConnection(cone.GetOutputPort())
        mapper.SetOrientationArray("direction")
        mapper.SetScaleFactor(4.0 / int(points.GetNumberOfPoints() ** 0.5))
        mapper.SetScaleModeToNoDataScaling()
    else:
        glyphs = vtkGlyph3D()
        glyphs.SetInputData(points)
        glyphs.SetSourceConnection(cone.GetOutputPort())
        glyphs.SetInputArrayToProcess(1, 0, 0, 0, "direction")
        glyphs.SetVectorModeToUseVector()
        glyphs.SetScaleModeToDataScalingOff()
        glyphs.SetScaleFactor(4.0 / int(points.GetNumberOfPoints() ** 0.5))
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(glyphs.GetOutputPort())
        mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    light = penumbra.add_light(renderer, (-2, 6, 3))
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToHardVolumes()
    renderer.SetPass(shadows)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(4, 5, 7)
    camera.SetFocalPoint(0, 0.5, 0)
    window.AddRenderer(renderer)
    return renderer, light, shadows


def median_frame(window, renderer, light, frames, move_light):
    times = []
    for f in range(frames + 2):
        if move_light:
            light.SetPosition(-2 + 0.05 * f, 6, 3)
        else:
            renderer.GetActiveCamera().Azimuth(2)
        renderer.ResetCameraClippingRange()
        start = time.perf_counter()
        window.Render()
        times.append(time.perf_counter() - start)
    return statistics.median(times[2:]) * 1000.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--glyphs", type=int, default=1024, help="glyphs (a square number)")
    parser.add_argument("--frames", type=int, default=15)
    args = parser.parse_args()
    side = int(round(args.glyphs ** 0.5))
    cone = vtkConeSource()
    cone.SetResolution(16)
    points = glyph_points(side)
    window = vtkRenderWindow()
    window.SetSize(1024, 768)
    window.SetOffScreenRendering(1)
    print(f"{side * side} cones of {cone.GetResolution() + 1} faces, 1024x768, hard shadows")
    print(f"{'scene':<34}{'camera orbits':>16}{'light moves':>16}")
    for instanced in (True, False):
        renderer, light, shadows = scene(window, instanced, points, cone)
        orbit = median_frame(window, renderer, light, args.frames, False)
        moving = median_frame(window, renderer, light, args.frames, True)
        name = "vtkGlyph3DMapper (instanced)" if instanced else "vtkGlyph3D, one merged actor"
        print(f"{name:<34}{orbit:>13.1f} ms{moving:>13.1f} ms")
        window.RemoveRenderer(renderer)


if __name__ == "__main__":
    main()
