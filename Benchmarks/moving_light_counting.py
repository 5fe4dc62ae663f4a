"""Counting (soft shadow volumes) with the light moving every frame: the wedges are rebuilt each
frame, so the casters stage shows their CPU cost (cutting each wedge to the receivers' pieces)
and the wedge stage what the GPU draws.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/moving_light_counting.py [--extent E] [--frames F]

The scene is time_varying.py's (make_scene): its isosurface (59,796 triangles at extent 30) on a
ground plane, 16 light samples, light radius 5% of the extent, the light turning 3 degrees
before every frame. It prints the medians of the casters and wedge stages over F frames.
"""
import math
import statistics

import penumbra
from time_varying import make_scene, scene_arguments


def main():
    args = scene_arguments(30, 6, "timed frames")
    e = args.extent
    contour, renderer, window, light = make_scene(e)
    shadows = penumbra.vtkSoftShadowPass()
    shadows.SetMethodToSoftShadowVolumes()
    shadows.SetLightSamples(16)
    penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.05 * e)
    renderer.SetPass(shadows)
    shadows.CollectStageTimesOn()
    window.Render()
    casters, wedges = [], []
    for frame in range(args.frames):
        angle = math.radians(3 * (frame + 1))
        light.SetPosition(-e * math.cos(angle), 5 * e, e * math.sin(angle) + e)
        window.Render()
        casters.append(shadows.GetStageCPUMilliseconds(shadows.STAGE_CASTERS))
        wedges.append(shadows.GetStageCPUMilliseconds(shadows.STAGE_WEDGES))
    print(f"{contour.GetOutput().GetNumberOfPolys()} triangles, light moving every frame, "
          f"counting 16 samples: casters {statistics.median(casters):.1f} ms, "
          f"wedges {statistics.median(wedges):.1f} ms (medians of {args.frames} frames)")


if __name__ == "__main__":
    main()
