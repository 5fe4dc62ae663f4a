"""A simulation played back: an isosurface whose value changes every frame, rendered without
shadows, with hard shadows, and the pass's stage split (casters: CPU geometry), in one run; then
the same isosurface unchanged from frame to frame, which leaves the pass only its GPU work
(ReuseUnchangedShadows off: every frame draws its shadows), and the same again with the pass's
default, which composites the last frame's shadows when nothing they depend on changed.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/time_varying.py [--extent E] [--frames F]

With new data, the contour (vtkFlyingEdges3D) runs before each timed frame, outside its timing;
what the pass adds is its per-frame CPU work (welding, topology, silhouettes, uploads) and its
GPU passes. The rows' frames are interleaved (one frame of each in turn, every frame with data
no frame drew before) and the ratios are medians of each round's ratio, as this machine's load
drifts by tens of percent over the seconds one row's frames take.
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
    one shadowing light, a 1024x768 off-screen window, the contour run and the camera's range
    set to it: (contour, renderer, window, light)."""
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
    contour.Update()
    renderer.ResetCameraClippingRange()
    return contour, renderer, window, light


def main():
    args = scene_arguments(60, 8, "timed frames of each configuration")
    contour, renderer, window, _ = make_scene(args.extent)
    triangles = contour.GetOutput().GetNumberOfPolys()
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToHardVolumes()
    # Each frame a little lower a value than the last: the surface grows, as a front spreading
    # through a simulation does (from 969,500 triangles at 160 to about 985,000 at 152).
    values = iter(160.0 - 0.25 * v for v in range(100000))

    def frame(configuration, new_data):
        """Renders one frame of `configuration` (None: no pass; else (depth from meshes, reuse))
        and returns its time in ms; the contour runs before the timing."""
        renderer.SetPass(shadows if configuration else None)
        if configuration:
            shadows.SetDepthFromCasterMeshes(configuration[0])
            shadows.SetReuseUnchangedShadows(configuration[1])
        if new_data:
            contour.SetValue(0, next(values))  # data no frame has drawn before
        renderer.ResetCameraClippingRange()  # runs the contour, outside the timed frame
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        return (time.perf_counter() - start) * 1000.0

    def interleaved(configurations, new_data):
        """Frames of every configuration in turn, so that this machine's load, which drifts
        over seconds, weighs on all of them alike: each one's median, and the median over the
        rounds of each one's time over the first's in the same round."""
        times = [[] for _ in configurations]
        for _ in range(args.frames + 2):
            for c, configuration in enumerate(configurations):
                times[c].append(frame(configuration, new_data))
        rounds = [[t[r] for t in times] for r in range(2, args.frames + 2)]  # 2 warm-up rounds
        medians = [statistics.median(t[2:]) for t in times]
        ratios = [statistics.median(r[c] / r[0] for r in rounds) for c in range(len(times))]
        return medians, ratios

    def extra(ratio):
        return f"{100.0 * (ratio - 1.0):+.0f}%"  # signed: a reused frame can cost less

    plain, hard, vtk_depth = None, (True, False), (False, False)
    (new_ms, new_ratio) = interleaved([plain, hard, vtk_depth], new_data=True)
    (same_ms, same_ratio) = interleaved([plain, hard], new_data=False)
    # Reuse in a pair of its own: a setter called between frames modifies the pass, which
    # draws the shadows again.
    reused_before = shadows.GetNumberOfReusedFrames()
    (reuse_ms, reuse_ratio) = interleaved([plain, (True, True)], new_data=False)
    reused = shadows.GetNumberOfReusedFrames() - reused_before
    # The stage split: the median of each stage over three more frames with new data.
    renderer.SetPass(shadows)
    shadows.SetDepthFromCasterMeshes(True)
    shadows.CollectStageTimesOn()
    stage_times = [[] for _ in range(shadows.NUMBER_OF_STAGES)]
    for f in range(3):
        contour.SetValue(0, next(values))
        renderer.ResetCameraClippingRange()
        window.Render()
        for s in range(shadows.NUMBER_OF_STAGES):
            stage_times[s].append(shadows.GetStageCPUMilliseconds(s))
    shadows.CollectStageTimesOff()
    stage = [statistics.median(t) for t in stage_times]
    split = ", ".join("%s %.1f ms" % (shadows.GetStageName(s), stage[s])
                      for s in range(shadows.NUMBER_OF_STAGES))
    print(f"time-varying isosurface: about {triangles} triangles, 1024x768, {args.frames}"
          " frames of each row, interleaved; the % is the median of each round's ratio")
    print("  new data every frame:")
    print(f"    no shadows    median {new_ms[0]:8.1f} ms")
    print(f"    hard shadows  median {new_ms[1]:8.1f} ms  ({extra(new_ratio[1])})")
    print(f"    VTK drawing the depth (DepthFromCasterMeshes off): median {new_ms[2]:8.1f} ms"
          f"  ({extra(new_ratio[2])})")
    print(f"    stages, medians of three more frames: {split}")
    casters = stage[shadows.STAGE_CASTERS]
    print(f"    casters: {1e6 * casters / max(triangles, 1):.0f} ns per triangle")
    print("  the same data every frame (no CPU geometry work):")
    print(f"    no shadows    median {same_ms[0]:8.1f} ms")
    print(f"    hard shadows, ReuseUnchangedShadows off: median {same_ms[1]:8.1f} ms"
          f"  ({extra(same_ratio[1])})")
    print(f"    with ReuseUnchangedShadows (the default): median {reuse_ms[1]:8.1f} ms"
          f"  ({extra(reuse_ratio[1])}; {reused} of {args.frames + 2} frames reused the shadows;"
          f" no shadows {reuse_ms[0]:.1f} ms in this pair)")


if __name__ == "__main__":
    main()
