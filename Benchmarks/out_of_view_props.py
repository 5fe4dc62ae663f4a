"""Counting against averaging where props reach out of view, with the pass's tight depth range:
the tests' ground and sphere (penumbra_testing.ground_and_sphere) alone, with a copy of both behind
the eye (actors of their own), with a 0.01-unit triangle 1,000 units to the side in the sphere's
polydata, and with a second sphere 1,000 units away in the same polydata. A directional light
from (-2, 6, 3) of 0.4 degrees, 320x240, 16 and 32 samples: the share of shadowed pixels where the
two methods differ by more than 1/N and by more than 0.5 (wedges.md, "Props reaching out of
view").

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages:Testing/Python \\
        /usr/bin/python3 Benchmarks/out_of_view_props.py
"""
import penumbra
from penumbra_testing import (actor_of, counted_against_averaged, ground_and_sphere,
                              offscreen_window)
from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderer
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
from vtkmodules.vtkCommonCore import vtkPoints

W, H = 320, 240


def moved(source, offset):
    """`source` translated by `offset` (keep the filter: VTK's Python wrapping frees it with its
    last reference, and its output port with it)."""
    t = vtkTransform()
    t.Translate(*offset)
    f = vtkTransformPolyDataFilter()
    f.SetTransform(t)
    f.SetInputConnection(source.GetOutputPort())
    return f


def triangle(at):
    """A right triangle of legs 0.01 at `at`."""
    pts = vtkPoints()
    for d in ((0, 0, 0), (0.01, 0, 0), (0, 0.01, 0)):
        pts.InsertNextPoint(at[0] + d[0], at[1] + d[1], at[2] + d[2])
    cells = vtkCellArray()
    cells.InsertNextCell(3, [0, 1, 2])
    poly = vtkPolyData()
    poly.SetPoints(pts)
    poly.SetPolys(cells)
    return poly


def scene_renderer(name):
    """The renderer of the scene `name`, with a vtkSoftShadowPass and a directional light of 0.4
    degrees (vtkLight is not positional unless set)."""
    renderer = vtkRenderer()
    plane, sphere = ground_and_sphere()
    keep = [plane, sphere]
    renderer.AddActor(actor_of(plane, (0.9, 0.9, 0.9)))
    if name == "stray triangle":
        caster = vtkAppendPolyData()
        caster.AddInputConnection(sphere.GetOutputPort())
        caster.AddInputData(triangle((1000, 0, 0)))
    elif name == "two copies 1000 apart":
        caster = vtkAppendPolyData()
        caster.AddInputConnection(sphere.GetOutputPort())
        keep.append(moved(sphere, (1000, 0, 0)))
        caster.AddInputConnection(keep[-1].GetOutputPort())
    else:
        caster = sphere
    renderer.AddActor(actor_of(caster, (0.9, 0.3, 0.3)))
    if name == "copy behind the eye":
        for source, colour in ((plane, (0.9, 0.9, 0.9)), (sphere, (0.9, 0.3, 0.3))):
            keep.append(moved(source, (6, 9, 16)))
            renderer.AddActor(actor_of(keep[-1], colour))
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetConeAngle(180)
    light.SetFocalPoint(0, 0, 0)
    light.SetPosition(-2, 6, 3)
    penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.4)
    renderer.AddLight(light)
    shadows = penumbra.vtkSoftShadowPass()
    renderer.SetPass(shadows)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(3, 5, 8)
    camera.SetFocalPoint(0, 0.5, 0)
    return renderer, shadows, keep


def main():
    # One window for every scene: Xvfb refuses some rapid reconnects.
    window = None
    for name in ("alone", "copy behind the eye", "stray triangle", "two copies 1000 apart"):
        renderer, shadows, _ = scene_renderer(name)
        if window is None:
            window = offscreen_window(renderer, W, H)
        else:
            window.GetRenderers().RemoveAllItems()
            window.AddRenderer(renderer)
        renderer.ResetCameraClippingRange()
        for samples in (16, 32):
            shadowed, step, half = counted_against_averaged(window, shadows, samples)
            print("%-22s N %2d: %4d shadowed px, differ > 1/N %.2f%%, > 0.5 %.2f%%"
                  % (name, samples, shadowed, 100 * step, 100 * half))


if __name__ == "__main__":
    main()
