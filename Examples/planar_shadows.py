#!/usr/bin/env python3
"""Soft shadows on a ground plane, two planar ways, beside the ray-traced truth.

A torus, a sphere and a leaning plank stand over a ground plane under one spherical light. The
window has three viewports:
- left: vtkSoftShadowPass with Haines' plateaus (SetMethodToPlateaus, the ground marked with
  SetShadowPlane);
- middle: vtkPlanarSoftShadowFilter's soft shadow, as triangles drawn as a dark decal over the
  ground (the pass keeps hard shadows on the casters themselves);
- right: penumbra wedges, for comparison.

The script then prints each method's error on the ground against vtkRayTracedVisibility, and the
shadow areas the filter measures.

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \\
        Examples/planar_shadows.py --output planar_shadows.png
"""
import argparse

import numpy as np
import penumbra

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import (vtkCubeSource, vtkParametricFunctionSource,
                                          vtkPlaneSource, vtkSphereSource)
from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

LIGHT = (3.0, -4.0, 9.0)
RADIUS = 0.8


def casters():
    """World-space caster sources: (algorithm, colour)."""
    torus = vtkParametricTorus()
    torus.SetRingRadius(1.0)
    torus.SetCrossSectionRadius(0.3)
    torus_source = vtkParametricFunctionSource()
    torus_source.SetParametricFunction(torus)
    torus_source.SetUResolution(64)
    torus_source.SetVResolution(24)
    place_torus = vtkTransform()
    place_torus.Translate(-1.5, 1.0, 1.6)
    place_torus.RotateX(50)
    torus_world = vtkTransformPolyDataFilter()
    torus_world.SetTransform(place_torus)
    torus_world.SetInputConnection(torus_source.GetOutputPort())

    sphere = vtkSphereSource()
    sphere.SetCenter(1.6, 1.2, 1.2)
    sphere.SetRadius(0.6)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)

    plank = vtkCubeSource()
    plank.SetXLength(0.15)  # narrower than the spacing of the light samples' shadows
    plank.SetYLength(2.5)
    plank.SetZLength(0.15)
    lean = vtkTransform()
    lean.Translate(0.5, -1.2, 0.9)
    lean.RotateX(40)
    plank_world = vtkTransformPolyDataFilter()
    plank_world.SetTransform(lean)
    plank_world.SetInputConnection(plank.GetOutputPort())
    return [(torus_world, (0.85, 0.6, 0.3)), (sphere, (0.85, 0.3, 0.3)),
            (plank_world, (0.4, 0.6, 0.85))]


def actor_for(algorithm, colour):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(algorithm.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(colour)
    actor.GetProperty().SetAmbient(0.15)
    actor.GetProperty().SetDiffuse(0.85)
    return actor


def scene(window, viewport):
    """A renderer over `viewport` with the ground, the casters and the light; returns it, its
    pass and the ground actor."""
    renderer = vtkRenderer()
    renderer.SetViewport(*viewport)
    renderer.SetBackground(0.15, 0.16, 0.22)
    window.AddRenderer(renderer)
    ground_source = vtkPlaneSource()
    ground_source.SetOrigin(-5, -5, 0)
    ground_source.SetPoint1(5, -5, 0)
    ground_source.SetPoint2(-5, 5, 0)
    ground = actor_for(ground_source, (0.85, 0.85, 0.8))
    renderer.AddActor(ground)
    for algorithm, colour in casters():
        renderer.AddActor(actor_for(algorithm, colour))
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetConeAngle(180)
    light.SetPosition(*LIGHT)
    light.SetFocalPoint(0, 0, 0)
    penumbra.vtkSoftShadowPass.SetLightRadius(light, RADIUS)
    renderer.AddLight(light)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(6, -9, 7)
    camera.SetFocalPoint(0, 0.3, 0.5)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    shadows = penumbra.vtkSoftShadowPass()
    renderer.SetPass(shadows)
    return renderer, shadows, ground


def shadow_decal(samples):
    """vtkPlanarSoftShadowFilter on the casters, and an actor drawing it as a dark decal."""
    append = vtkAppendPolyData()
    for algorithm, _ in casters():
        append.AddInputConnection(algorithm.GetOutputPort())
    planar = penumbra.vtkPlanarSoftShadowFilter()
    planar.SetInputConnection(append.GetOutputPort())
    planar.SetLightPosition(*LIGHT)
    planar.SetLightRadius(RADIUS)
    planar.SetLightSamples(samples)
    planar.SetPlaneOrigin(0, 0, 0)
    planar.SetPlaneNormal(0, 0, 1)
    planar.SetOffset(1e-3)  # above the ground: no z-fighting
    planar.Update()
    shade = vtkLookupTable()  # black, as opaque as the light is hidden
    shade.SetTableRange(0, 1)
    shade.SetValueRange(0, 0)
    shade.SetSaturationRange(0, 0)
    shade.SetAlphaRange(0.8, 0.0)
    shade.Build()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(planar.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("LightIntensity")
    mapper.SetLookupTable(shade)
    mapper.SetScalarRange(0, 1)
    decal = vtkActor()
    decal.SetMapper(mapper)
    decal.GetProperty().SetLighting(False)
    decal.ForceTranslucentOn()
    penumbra.vtkSoftShadowPass.SetCastsShadows(decal, False)
    return planar, decal


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", default="planar_shadows.png")
    parser.add_argument("--width", type=int, default=1200)
    parser.add_argument("--height", type=int, default=400)
    parser.add_argument("--samples", type=int, default=32, help="light samples of the filter")
    args = parser.parse_args()

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(args.width, args.height)
    plateaus, plateau_pass, plateau_ground = scene(window, (0, 0, 1 / 3, 1))
    penumbra.vtkSoftShadowPass.SetShadowPlane(plateau_ground, True)
    plateau_pass.SetMethodToPlateaus()
    filtered, filter_pass, filter_ground = scene(window, (1 / 3, 0, 2 / 3, 1))
    filter_pass.SetMethodToHardVolumes()  # the casters' own shadows; the ground takes the decal
    penumbra.vtkSoftShadowPass.SetReceivesShadows(filter_ground, False)
    planar, decal = shadow_decal(args.samples)
    filtered.AddActor(decal)
    wedges, wedge_pass, _ = scene(window, (2 / 3, 0, 1, 1))
    wedge_pass.SetMethodToPenumbraWedges()
    window.Render()

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    writer = vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print("wrote %s" % args.output)

    # Error on the ground against the truth (256 rays per pixel), for the pass's methods.
    for name, renderer, shadows in (("plateaus", plateaus, plateau_pass),
                                    ("wedges", wedges, wedge_pass)):
        truth = penumbra.vtkRayTracedVisibility()
        truth.SetRenderer(renderer)
        truth.SetSamplesPerLight(256)
        truth.Update()
        ours = vtk_to_numpy(shadows.GetVisibilityImage(0).GetPointData().GetScalars())
        true = vtk_to_numpy(truth.GetVisibilityImage(0).GetPointData().GetScalars())
        depth = vtk_to_numpy(truth.GetDepthImage().GetPointData().GetScalars())
        region = (depth < 1) & ((ours < 0.999) | (true < 0.999))
        error = np.abs(ours - true)[region]
        print("%-9s MAE %.4f over %d shadowed pixels, %.1f%% off by more than 0.1"
              % (name, error.mean(), region.sum(), 100 * (error > 0.1).mean()))
    print("filter: %d triangles, umbra %.3f, penumbra %.3f square units, shadow integral %.3f"
          % (planar.GetOutput().GetNumberOfCells(), planar.GetUmbraArea(),
             planar.GetPenumbraArea(), planar.GetShadowIntegral()))


if __name__ == "__main__":
    main()
