"""How a frame's cost grows with the window, the light's radius and the casters' triangles, for
hard shadows, 16 averaged hard shadows and soft shadow volumes of the same 16 samples, beside
the unshadowed frame and the number of pixels in a penumbra (0 < visibility < 1), in one run.

    xvfb-run -a env PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Benchmarks/cost_scaling.py [--frames F] [--output DIR]

Writes DIR/cost_scaling.csv and DIR/cost_scaling.png (default build/cost_scaling). The scene is
a tessellated sphere and a cone over a ground plane, lit by one positional light; one sweep
changes one of window size, light radius and sphere tessellation, the others at their defaults
(1024x768, radius 0.5, about 16k triangles).
"""
import argparse
import csv
import os
import statistics
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow

import penumbra

METHODS = ("none", "hard_volumes", "averaged_16", "soft_volumes_16")
COLOURS = dict(zip(METHODS, ("tab:blue", "tab:orange", "tab:green", "tab:red")))
DEFAULT_SIZE = (1024, 768)
DEFAULT_RADIUS = 0.5
DEFAULT_RESOLUTION = 90  # theta and phi: about 16k triangles


def actor_of(source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


class Scene:
    def __init__(self):
        self.sphere = vtkSphereSource()
        self.sphere.SetCenter(0, 0, 1.5)
        self.sphere.SetRadius(1.0)
        cone = vtkConeSource()
        cone.SetCenter(2.2, 0.5, 1.0)
        cone.SetDirection(0, 0, 1)
        cone.SetHeight(2.0)
        cone.SetRadius(0.7)
        cone.SetResolution(48)
        ground = vtkPlaneSource()
        ground.SetOrigin(-6, -6, 0), ground.SetPoint1(6, -6, 0), ground.SetPoint2(-6, 6, 0)
        self.renderer = vtkRenderer()
        self.sources = (self.sphere, cone, ground)
        for source in self.sources:
            self.renderer.AddActor(actor_of(source))
        self.light = penumbra.add_light(self.renderer, (-3.0, -2.0, 9.0))
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.AddRenderer(self.renderer)
        camera = self.renderer.GetActiveCamera()
        camera.SetPosition(4.0, -9.0, 7.0)
        camera.SetFocalPoint(0.5, 0.0, 0.5)
        camera.SetViewUp(0, 0, 1)
        self.shadows = penumbra.vtkSoftShadowPass()
        self.shadows.SetLightSamples(16)
        # The same frame is timed again and again: every one must draw its shadows.
        self.shadows.ReuseUnchangedShadowsOff()

    def configure(self, size, radius, resolution):
        self.window.SetSize(*size)
        self.sphere.SetThetaResolution(resolution)
        self.sphere.SetPhiResolution(resolution)
        self.sphere.Update()
        penumbra.vtkSoftShadowPass.SetLightRadius(self.light, radius)
        self.renderer.ResetCameraClippingRange()

    def triangles(self):
        """Triangles the casters and the ground draw (polygons fanned into triangles)."""
        count = 0
        for source in self.sources:
            source.Update()
            polys = source.GetOutput().GetPolys()
            for c in range(polys.GetNumberOfCells()):
                count += max(0, polys.GetCellSize(c) - 2)
        return count

    def time(self, method, frames):
        if method == "none":
            self.renderer.SetPass(None)
        else:
            {"hard_volumes": self.shadows.SetMethodToHardVolumes,
             "averaged_16": self.shadows.SetMethodToAveragedHardShadows,
             "soft_volumes_16": self.shadows.SetMethodToSoftShadowVolumes}[method]()
            self.renderer.SetPass(self.shadows)
        times = []
        for _ in range(frames + 1):  # the first frame builds the caches
            start = time.perf_counter()
            self.window.Render()
            self.window.WaitForCompletion()
            times.append(time.perf_counter() - start)
        return statistics.median(times[1:]) * 1000.0

    def penumbra_pixels(self):
        """Pixels of the last shadowed frame with a visibility strictly between 0 and 1."""
        image = self.shadows.GetVisibilityImage(0)
        if image is None:
            return 0
        values = image.GetPointData().GetScalars()
        return sum(1 for i in range(values.GetNumberOfValues())
                   if 0.0 < values.GetValue(i) < 1.0)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=3)
    parser.add_argument("--output", default="build/cost_scaling")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    scene = Scene()
    sweeps = [("pixels", size, {"size": size}) for size in
              ((320, 240), (640, 480), (1024, 768), (1600, 1200))]
    sweeps += [("radius", radius, {"radius": radius}) for radius in (0.1, 0.25, 0.5, 1.0, 2.0)]
    sweeps += [("triangles", res, {"resolution": res}) for res in (24, 45, 90, 180, 360)]
    rows = []
    for sweep, value, change in sweeps:
        size = change.get("size", DEFAULT_SIZE)
        radius = change.get("radius", DEFAULT_RADIUS)
        resolution = change.get("resolution", DEFAULT_RESOLUTION)
        scene.configure(size, radius, resolution)
        triangles = scene.triangles()
        row = {"sweep": sweep, "width": size[0], "height": size[1], "radius": radius,
               "triangles": triangles}
        for method in METHODS:
            row[method] = round(scene.time(method, args.frames), 1)
        row["penumbra_pixels"] = scene.penumbra_pixels()  # of the soft_volumes_16 frame
        rows.append(row)
        print(", ".join(f"{k} {v}" for k, v in row.items()), flush=True)
    path = os.path.join(args.output, "cost_scaling.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    plot(rows, os.path.join(args.output, "cost_scaling.png"))
    print("wrote", path)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = [("pixels", lambda r: r["width"] * r["height"] / 1e6, "window (megapixels)"),
              ("radius", lambda r: r["radius"], "light radius (world units)"),
              ("triangles", lambda r: r["triangles"] / 1e3, "triangles (thousands)")]
    figure, axes = plt.subplots(1, 4, figsize=(18, 4.2))
    for axis, (sweep, x, label) in zip(axes, panels):
        chosen = [r for r in rows if r["sweep"] == sweep]
        for method in METHODS:
            axis.plot([x(r) for r in chosen], [r[method] for r in chosen], "o-", label=method,
                      color=COLOURS[method])
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel(label)
        axis.set_ylabel("ms per frame (median)")
        axis.grid(True, which="both", alpha=0.3)
    axis = axes[3]
    for method in METHODS[1:]:
        axis.plot([r["penumbra_pixels"] / 1e3 for r in rows],
                  [max(r[method] - r["none"], 0.1) for r in rows], "o", label=method,
                  color=COLOURS[method])
    axis.set_xscale("log")
    axis.set_yscale("log")
    axis.set_xlabel("pixels in a penumbra (thousands), every sweep")
    axis.set_ylabel("ms added to the unshadowed frame")
    axis.grid(True, which="both", alpha=0.3)
    axes[0].legend()
    figure.suptitle("Frame cost against window, light radius and triangles (llvmpipe, 2 cores)")
    figure.tight_layout()
    figure.savefig(path, dpi=90)


if __name__ == "__main__":
    main()
