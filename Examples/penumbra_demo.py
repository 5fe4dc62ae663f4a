#!/usr/bin/env python3
"""Penumbra demo in Python: shadows for an ordinary VTK scene with one render pass.

An isosurface of the analytic "wavelet" field floats over a ground plane with a field of cone
glyphs, lit by one positional key light. A small glowing sphere marks the light: it is
decorative, so it is told not to cast shadows (it would otherwise enclose the light and shadow
the whole scene).

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Examples/penumbra_demo.py --output penumbra_demo.png

Writes the shadowed image and prints the frame time with and without shadows.
"""
import argparse
import statistics
import sys
import time

import penumbra  # vtkSoftShadowPass, vtkRayTracedVisibility

from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkGlyph3D
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkLight,
    vtkPolyDataMapper,
    vtkRenderWindow,
    vtkRenderer,
    vtkWindowToImageFilter,
)

LIGHT_POSITION = (5.0, -8.7, 8.5)


def actor_for(algorithm, color, specular=0.0):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(algorithm.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetColor(color)
    prop.SetAmbient(0.15)  # shadows keep some ambient light: not pure black
    prop.SetDiffuse(0.85)
    prop.SetSpecular(specular)
    prop.SetSpecularPower(30.0)
    return actor


def build_scene(renderer):
    # Isosurface of vtkRTAnalyticSource: blobby, open where the extent clips it.
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-20, 20, -20, 20, -20, 20)
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 172.0)
    contour.ComputeScalarsOff()
    isosurface = actor_for(contour, (0.90, 0.55, 0.25), specular=0.3)
    isosurface.SetScale(0.09)
    isosurface.SetPosition(0.0, 0.0, 2.6)
    isosurface.RotateZ(20.0)

    plane = vtkPlaneSource()
    plane.SetOrigin(-8.0, -8.0, 0.0)
    plane.SetPoint1(8.0, -8.0, 0.0)
    plane.SetPoint2(-8.0, 8.0, 0.0)
    ground = actor_for(plane, (0.85, 0.85, 0.82))

    # A 7x7 grid of cones standing on the plane, glyphed into one polydata.
    sites = vtkPoints()
    for i in range(7):
        for j in range(7):
            sites.InsertNextPoint(-5.4 + 1.8 * i, -5.4 + 1.8 * j, 0.35)
    site_data = vtkPolyData()
    site_data.SetPoints(sites)
    cone = vtkConeSource()
    cone.SetHeight(0.7)
    cone.SetRadius(0.22)
    cone.SetResolution(24)
    cone.SetDirection(0.0, 0.0, 1.0)
    glyph = vtkGlyph3D()
    glyph.SetInputData(site_data)
    glyph.SetSourceConnection(cone.GetOutputPort())
    glyph.OrientOff()
    glyph.SetScaleModeToDataScalingOff()
    glyphs = actor_for(glyph, (0.30, 0.50, 0.85), specular=0.2)

    # The key light: a positional scene light from above, to the side.
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetConeAngle(180.0)
    light.SetPosition(LIGHT_POSITION)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.0)  # hard shadows

    # A glowing marker around the light: decorative, so it neither casts nor receives shadows.
    bulb_source = vtkSphereSource()
    bulb_source.SetCenter(LIGHT_POSITION)
    bulb_source.SetRadius(0.35)
    bulb = actor_for(bulb_source, (1.0, 0.9, 0.5))
    bulb.GetProperty().SetAmbient(1.0)
    bulb.GetProperty().SetDiffuse(0.0)
    penumbra.vtkSoftShadowPass.SetCastsShadows(bulb, False)
    penumbra.vtkSoftShadowPass.SetReceivesShadows(bulb, False)

    for actor in (ground, isosurface, glyphs, bulb):
        renderer.AddActor(actor)
    renderer.AddLight(light)
    renderer.SetBackground(0.12, 0.14, 0.18)
    renderer.SetBackground2(0.35, 0.40, 0.48)
    renderer.GradientBackgroundOn()

    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(2.0, -3.0, 3.5)
    camera.SetPosition(-8.0, -20.0, 9.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetViewAngle(40.0)
    renderer.ResetCameraClippingRange()


def median_frame_ms(window, camera, frames):
    """Median time of `frames` orbiting renders, after 3 warm-up frames."""
    for _ in range(3):
        camera.Azimuth(1.0)
        window.Render()
    window.WaitForCompletion()
    times = []
    for _ in range(frames):
        camera.Azimuth(1.0)
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(1000.0 * (time.perf_counter() - start))
    for _ in range(3 + frames):
        camera.Azimuth(-1.0)  # back to where it started
    return statistics.median(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", default="penumbra_demo.png", help="PNG to write")
    parser.add_argument("--width", type=int, default=1024)
    parser.add_argument("--height", type=int, default=768)
    parser.add_argument("--frames", type=int, default=20, help="timed frames per mode")
    parser.add_argument("--offscreen", action=argparse.BooleanOptionalAction, default=True,
                        help="render without showing a window (default on)")
    args = parser.parse_args()

    renderer = vtkRenderer()
    build_scene(renderer)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1 if args.offscreen else 0)
    window.SetSize(args.width, args.height)
    window.AddRenderer(renderer)
    window.SetWindowName("Penumbra demo")

    # The whole change needed for shadows: one pass on the renderer.
    shadows = penumbra.vtkSoftShadowPass()

    camera = renderer.GetActiveCamera()
    window.Render()
    plain_ms = median_frame_ms(window, camera, args.frames)
    renderer.SetPass(shadows)
    window.Render()
    shadow_ms = median_frame_ms(window, camera, args.frames)
    if shadows.GetNumberOfShadowingLights() < 1:
        print("error: the shadow pass shadowed no light", file=sys.stderr)
        return 1

    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    if writer.GetErrorCode():
        print(f"error: could not write {args.output}", file=sys.stderr)
        return 1

    print(f"Penumbra demo (Python): {args.width}x{args.height}, "
          f"{shadows.GetNumberOfShadowingLights()} shadowing light")
    print(f"  no shadows    median {plain_ms:6.1f} ms")
    print(f"  hard shadows  median {shadow_ms:6.1f} ms  (x{shadow_ms / plain_ms:.2f})")
    print(f"wrote: {args.output}")
    renderer.SetPass(None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
