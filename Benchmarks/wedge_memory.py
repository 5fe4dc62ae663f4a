"""Bytes of counting wedge buffer per wedge drawn: GetGraphicsMemoryBytes under soft shadow
volumes, minus that under averaged hard shadows and minus the counters (4 + N bytes a pixel),
over GetNumberOfPenumbraWedges, for a sphere and for an isosurface over a ground.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages:Testing/Python \\
        /usr/bin/python3 Benchmarks/wedge_memory.py

Approximate: averaging's own targets are subtracted with it.
"""
import penumbra
from penumbra_testing import actor_of
from vtkmodules.vtkFiltersCore import vtkContourFilter
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

WIDTH, HEIGHT, SAMPLES = 400, 300, 16



def sphere():
    source = vtkSphereSource()
    source.SetThetaResolution(48)
    source.SetPhiResolution(24)
    source.SetCenter(0, 1, 0)
    source.SetRadius(0.7)
    return source, (-2, 6, 3), 0.5, -1


def isosurface():
    field = vtkRTAnalyticSource()
    field.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    source = vtkContourFilter()
    source.SetInputConnection(field.GetOutputPort())
    source.SetValue(0, 150)
    return source, (-2, 30, 3), 2.0, -12


def main():
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(WIDTH, HEIGHT)
    for name, make in (("sphere 48x24", sphere), ("isosurface", isosurface)):
        source, position, radius, ground_height = make()
        ground = vtkPlaneSource()
        ground.SetOrigin(-30, ground_height, -30)
        ground.SetPoint1(30, ground_height, -30)
        ground.SetPoint2(-30, ground_height, 30)
        renderer = vtkRenderer()
        window.AddRenderer(renderer)
        renderer.AddActor(actor_of(source, (0.9, 0.3, 0.3)))
        renderer.AddActor(actor_of(ground, (0.9, 0.9, 0.9)))
        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPosition(*position)
        light.SetConeAngle(180)
        renderer.AddLight(light)
        penumbra.vtkSoftShadowPass.SetLightRadius(light, radius)
        renderer.ResetCamera()
        shadows = penumbra.vtkSoftShadowPass()
        shadows.SetLightSamples(SAMPLES)
        renderer.SetPass(shadows)
        shadows.SetMethodToAveragedHardShadows()
        window.Render()
        averaged = shadows.GetGraphicsMemoryBytes()
        shadows.SetMethodToSoftShadowVolumes()
        window.Render()
        wedge_bytes = (shadows.GetGraphicsMemoryBytes() - averaged
                       - WIDTH * HEIGHT * (4 + SAMPLES))
        wedges = shadows.GetNumberOfPenumbraWedges()
        print("%s: %d bytes of wedges for %d wedges drawn, %.0f bytes a wedge"
              % (name, wedge_bytes, wedges, wedge_bytes / max(wedges, 1)))
        window.RemoveRenderer(renderer)


if __name__ == "__main__":
    main()
