"""A simulation played back: an isosurface whose value changes every frame, rendered without
shadows, with hard shadows, and the pass's stage split (casters: CPU geometry), in one run.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/time_varying.py [--extent E] [--frames F]

The contour (vtkFlyingEdges3D) runs every frame in both cases, as it would in an application;
what the pass adds on top is its per-frame CPU work (welding, topology, silhouettes, uploads) and
its GPU passes.
"""
import argparse
import statistics
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow

import penumbra


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--extent", type=int, default=60, help="the wavelet's half extent")
    parser.add_argument("--frames", type=int, default=8)
    args = parser.parse_args()
    e = args.extent
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-e, e, -e, e, -e, e)
    contour = vtkFlyingEdges3D()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 160.0)
    contour.ComputeNormalsOn()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(contour.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.SetPosition(0, e * 0.6, 0)
    ground = vtkPlaneSource()
    ground.SetOrigin(-2 * e, -e * 0.5, -2 * e), ground.SetPoint1(2 * e, -e * 0.5, -2 * e)
    ground.SetPoint2(-2 * e, -e * 0.5, 2 * e)
    gmapper = vtkPolyDataMapper()
    gmapper.SetInputConnection(ground.GetOutputPort())
    gactor = vtkActor()
    gactor.SetMapper(gmapper)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.AddActor(gactor)
    penumbra.add_light(renderer, (-e, 5 * e, e))
    window = vtkRenderWindow()
    window.SetSize(1024, 768)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(2 * e, 2.5 * e, 3 * e)
    camera.SetFocalPoint(0, 0, 0)

    contour.Update()
    triangles = contour.GetOutput().GetNumberOfPolys()
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToHardVolumes()

    def run(with_pass, depth_from_meshes=True):
        renderer.SetPass(shadows if with_pass else None)
        shadows.SetDepthFromCasterMeshes(depth_from_meshes)
        times = []
        for f in range(args.frames + 2):
            contour.SetValue(0, 150.0 + 3.0 * f)  # new data every frame
            renderer.ResetCameraClippingRange()
            start = time.perf_counter()
            window.Render()
            window.WaitForCompletion()
            times.append(time.perf_counter() - start)
        return statistics.median(times[2:]) * 1000.0

    plain = run(False)
    hard = run(True)
    vtk_depth = run(True, depth_from_meshes=False)
    shadows.SetDepthFromCasterMeshes(True)
    contour.SetValue(0, 149.0)
    shadows.CollectStageTimesOn()
    window.Render()
    shadows.CollectStageTimesOff()
    split = ", ".join("%s %.1f ms" % (shadows.GetStageName(s), shadows.GetStageCPUMilliseconds(s))
                      for s in range(shadows.NUMBER_OF_STAGES))
    print(f"time-varying isosurface: about {triangles} triangles, new every frame, 1024x768")
    print(f"  no shadows    median {plain:8.1f} ms")
    print(f"  hard shadows  median {hard:8.1f} ms  (+{100.0 * (hard - plain) / plain:.0f}%)")
    print(f"    VTK drawing the depth (DepthFromCasterMeshes off): median {vtk_depth:8.1f} ms"
          f"  (+{100.0 * (vtk_depth - plain) / plain:.0f}%)")
    print(f"    stages of one more frame: {split}")
    casters = shadows.GetStageCPUMilliseconds(shadows.STAGE_CASTERS)
    print(f"    casters: {1e6 * casters / max(triangles, 1):.0f} ns per triangle")


if __name__ == "__main__":
    main()
