"""Frame timing shared by the benchmark scripts: medians of frames with the camera turning, so
that every frame redraws what a user's interaction would."""
import statistics
import time


def median_frame_ms(window, renderer, frames, degrees, turn_back=False):
    """Median of `frames` renders in milliseconds, the camera turning `degrees` about the focal
    point before each (the clipping range reset as VTK's interactor does); with `turn_back` the
    camera returns to where it started, so that images taken after match."""
    camera = renderer.GetActiveCamera()
    times = []
    for _ in range(frames):
        camera.Azimuth(degrees)
        renderer.ResetCameraClippingRange()
        start = time.perf_counter()
        window.Render()
        times.append(1e3 * (time.perf_counter() - start))
    if turn_back:
        camera.Azimuth(-degrees * frames)
        renderer.ResetCameraClippingRange()
    return statistics.median(times)


def depth_source_rounds(renderer, eye, rounds, frames):
    """Prints `rounds` rounds of `renderer`'s unshadowed frame against hard shadows with their
    depth drawn from the caster meshes and by VTK (DepthFromCasterMeshes on and off), at
    1024x768 with the camera at `eye` looking at the origin: medians of `frames` frames with the
    camera turning, and the depth stage of one more frame (CollectStageTimes)."""
    import penumbra
    from vtkmodules.vtkRenderingCore import vtkRenderWindow

    window = vtkRenderWindow()
    window.SetSize(1024, 768)
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(eye)
    camera.SetFocalPoint(0, 0, 0)
    renderer.ResetCameraClippingRange()
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToHardVolumes()

    def run(with_pass, depth_from_meshes=True):
        renderer.SetPass(shadows if with_pass else None)
        shadows.SetDepthFromCasterMeshes(depth_from_meshes)
        window.Render()  # warm-up: shader builds, topology, uploads
        median = median_frame_ms(window, renderer, frames, 0.5)
        if not with_pass:
            return median, None, 0
        shadows.CollectStageTimesOn()
        window.Render()
        shadows.CollectStageTimesOff()
        return (median, shadows.GetStageCPUMilliseconds(shadows.STAGE_DEPTH),
                shadows.GetNumberOfPropsWithDepthFromMeshes())

    for round_index in range(rounds):
        plain, _, _ = run(False)
        meshes, meshes_depth, count = run(True, True)
        vtk, vtk_depth, _ = run(True, False)
        print(f"  round {round_index + 1}: none {plain:.1f} ms; depth from meshes {meshes:.1f} ms"
              f" ({meshes / plain:.2f}x, depth stage {meshes_depth:.1f} ms, {count} props);"
              f" VTK's depth {vtk:.1f} ms ({vtk / plain:.2f}x, depth stage {vtk_depth:.1f} ms)")
