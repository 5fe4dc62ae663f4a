"""A simulation played back: an isosurface whose value changes every frame, rendered without
shadows, with hard shadows, and the pass's stage split (casters: CPU geometry), in one run; then
the same isosurface unchanged from frame to frame, which leaves the pass only its GPU work
(ReuseUnchangedShadows off: every frame draws its shadows), and the same again with the pass's
default, which composites the last frame's shadows when nothing they depend on changed.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/time_varying.py [--extent E] [--frames F]

With new data, the contour (vtkFlyingEdges3D) runs before each timed frame, outside its timing;
what the pass adds is its per-frame CPU work (welding, topology, silhouettes, uploads) and its
GPU passes.
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


def make_actor(algorithm):
    """An actor drawing `algorithm`'s output in one colour."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(algorithm.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def scene_arguments(extent, frames, frames_help="timed frames"):
    """The command line of the scripts built on make_scene: --extent and --frames."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--extent", type=int, default=extent, help="the wavelet's half extent")
    parser.add_argument("--frames", type=int, default=frames, help=frames_help)
    return parser.parse_args()


def make_scene(e):
    """The wavelet's isosurface (half extent `e`, open where the extent clips it) over a ground,
    one shadowing light, a 1024x768 off-screen window: (contour, renderer, window, light)."""
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-e, e, -e, e, -e, e)
    contour = vtkFlyingEdges3D()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 160.0)
    contour.ComputeNormalsOn()
    surface = make_actor(contour)
    surface.SetPosition(0, e * 0.6, 0)
    ground = vtkPlaneSource()
    ground.SetOrigin(-2 * e, -e * 0.5, -2 * e), ground.SetPoint1(2 * e, -e * 0.5, -2 * e)
    ground.SetPoint2(-2 * e, -e * 0.5, 2 * e)

    renderer = vtkRenderer()
    renderer.AddActor(surface)
    renderer.AddActor(make_actor(ground))
    light = penumbra.add_light(renderer, (-e, 5 * e, e))
    window = vtkRenderWindow()
    window.SetSize(1024, 768)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(2 * e, 2.5 * e, 3 * e)
    camera.SetFocalPoint(0, 0, 0)
    return contour, renderer, window, light


def main():
    args = scene_arguments(60, 8)
    contour, renderer, window, _ = make_scene(args.extent)

    contour.Update()
    triangles = contour.GetOutput().GetNumberOfPolys()
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToHardVolumes()

    def run(with_pass, depth_from_meshes=True, new_data=True, reuse=False):
        renderer.SetPass(shadows if with_pass else None)
        shadows.SetDepthFromCasterMeshes(depth_from_meshes)
        shadows.SetReuseUnchangedShadows(reuse)
        times = []
        for f in range(args.frames + 2):
            if new_data:
                contour.SetValue(0, 150.0 + 3.0 * f)  # new data every frame
            renderer.ResetCameraClippingRange()  # runs the contour, outside the timed frame
            start = time.perf_counter()
            window.Render()
            window.WaitForCompletion()
            times.append(time.perf_counter() - start)
        return statistics.median(times[2:]) * 1000.0

    plain = run(False)
    hard = run(True)
    vtk_depth = run(True, depth_from_meshes=False)
    plain_same = run(False, new_data=False)
    hard_same = run(True, new_data=False)
    reused_before = shadows.GetNumberOfReusedFrames()
    hard_reused = run(True, new_data=False, reuse=True)
    reused = shadows.GetNumberOfReusedFrames() - reused_before
    # The stage split: the median of each stage over three more frames with new data.
    shadows.SetDepthFromCasterMeshes(True)
    shadows.CollectStageTimesOn()
    stage_times = [[] for _ in range(shadows.NUMBER_OF_STAGES)]
    for f in range(3):
        contour.SetValue(0, 149.0 - f)
        renderer.ResetCameraClippingRange()
        window.Render()
        for s in range(shadows.NUMBER_OF_STAGES):
            stage_times[s].append(shadows.GetStageCPUMilliseconds(s))
    shadows.CollectStageTimesOff()
    stage = [statistics.median(t) for t in stage_times]
    split = ", ".join("%s %.1f ms" % (shadows.GetStageName(s), stage[s])
                      for s in range(shadows.NUMBER_OF_STAGES))
    print(f"time-varying isosurface: about {triangles} triangles, new every frame, 1024x768")
    print(f"  no shadows    median {plain:8.1f} ms")
    print(f"  hard shadows  median {hard:8.1f} ms  (+{100.0 * (hard - plain) / plain:.0f}%)")
    print(f"    VTK drawing the depth (DepthFromCasterMeshes off): median {vtk_depth:8.1f} ms"
          f"  (+{100.0 * (vtk_depth - plain) / plain:.0f}%)")
    print(f"    stages, medians of three more frames: {split}")
    casters = stage[shadows.STAGE_CASTERS]
    print(f"    casters: {1e6 * casters / max(triangles, 1):.0f} ns per triangle")
    print(f"  the same data every frame (no CPU geometry work): no shadows {plain_same:.1f} ms,"
          f" hard shadows {hard_same:.1f} ms (+{100.0 * (hard_same - plain_same) / plain_same:.0f}%)")
    print(f"    with ReuseUnchangedShadows (the default): {hard_reused:.1f} ms"
          f" (+{100.0 * (hard_reused - plain_same) / plain_same:.0f}%; {reused} of"
          f" {args.frames + 2} frames reused the shadows)")


if __name__ == "__main__":
    main()
