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
