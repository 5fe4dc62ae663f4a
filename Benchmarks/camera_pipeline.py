"""A still scene with a pipeline that depends on the camera: a translucent sphere sorted back to
front by vtkDepthSortPolyData (the usual way to draw translucency without depth peeling), beside
time_varying.py's isosurface (make_scene) on its ground, hard shadows, camera and light still.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/camera_pipeline.py [--extent E] [--frames F]

The pass draws its shadows with a copy of the camera and leaves the user's alone, so the sort
does not run again and a still frame reuses the last frame's shadows (ReuseUnchangedShadows).
Three renderings in blocks of F timed frames, A B C C B A: VTK without the pass, the pass as it
is, and the pass with the camera modified before every frame, which is what the pass did to
such a scene before 2026-12-05 (its tight depth range set and restored the camera's clipping
range every frame: the sort ran again and the shadows were drawn every frame).
"""
import statistics
import time

from vtkmodules.vtkFiltersHybrid import vtkDepthSortPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource

import penumbra
from time_varying import make_actor, make_scene, scene_arguments


def main():
    args = scene_arguments(60, 5, "timed frames per block")
    e = args.extent
    contour, renderer, window, _ = make_scene(e)
    camera = renderer.GetActiveCamera()
    sphere = vtkSphereSource()
    sphere.SetCenter(1.2 * e, 0.4 * e, 0.6 * e)
    sphere.SetRadius(0.5 * e)
    sphere.SetThetaResolution(400)
    sphere.SetPhiResolution(200)
    sorted_sphere = vtkDepthSortPolyData()
    sorted_sphere.SetInputConnection(sphere.GetOutputPort())
    sorted_sphere.SetCamera(camera)
    sorted_sphere.SetDirectionToBackToFront()
    glass = make_actor(sorted_sphere)
    glass.GetProperty().SetOpacity(0.4)
    renderer.AddActor(glass)
    renderer.ResetCameraClippingRange()
    triangles = contour.GetOutput().GetNumberOfPolys()

    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToHardVolumes()
    sorts = [0]
    sorted_sphere.AddObserver("EndEvent", lambda *_: sorts.__setitem__(0, sorts[0] + 1))

    def render(name):
        renderer.SetPass(None if name == "none" else shadows)
        if name == "camera modified":
            camera.Modified()
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        return (time.perf_counter() - start) * 1000.0

    names = ("none", "still", "camera modified")
    times = {name: [] for name in names}
    reused = {name: 0 for name in names}
    sort_runs = {name: 0 for name in names}
    for name in names + tuple(reversed(names)):
        for f in range(args.frames + 2):
            reused_before, sorts_before = shadows.GetNumberOfReusedFrames(), sorts[0]
            ms = render(name)
            if f >= 2:  # the first frames after a change of pass rebuild shaders
                times[name].append(ms)
                reused[name] += shadows.GetNumberOfReusedFrames() - reused_before
                sort_runs[name] += sorts[0] - sorts_before
    none = statistics.median(times["none"])
    print(f"isosurface of {triangles} triangles, a depth-sorted translucent sphere of"
          f" {sorted_sphere.GetOutput().GetNumberOfPolys()} triangles, a ground; 1024x768,"
          f" camera and light still; hard shadows; 2 x {args.frames} timed frames each")
    for name in names:
        ms = statistics.median(times[name])
        print(f"  {name:16s} median {ms:8.1f} ms ({ms / none:.2f}x); shadows reused in"
              f" {reused[name]} and the sort run in {sort_runs[name]} of {2 * args.frames}"
              f" frames")


if __name__ == "__main__":
    main()
