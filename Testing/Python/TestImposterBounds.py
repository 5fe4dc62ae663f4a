"""Imposter spheres reach beyond the bounds VTK reports for them (their centres'), and the pass's
scene box must hold what is drawn: the shadow volumes' scissors, end planes and tight depth range
are cut to it. Spheres of radius 0.6 on two rows over a ground, under a low point light from the
side and a directional light, seen from the side and from above, against the ray tracer's
analytic spheres. Pixels in the spheres' terminator band (|N.L| < 0.25, where the 32-segment
stand-ins that cast differ from the true spheres by design, limitations.md) are left out; of
the rest at most 0.2% may be wrong beyond a one-pixel shift. Measured 0 in all four views; with
the spheres' radii left out of the scene box (a throw-away change), 1988, 3570, 1375 and 150."""
import numpy as np
from penumbra_testing import (actor_of, check, compare_hard_shadows, finish, ground_and_sphere, image,
                              light_pass_and_truth)
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLSphereMapper

RADIUS = 0.6
CENTRES = np.array([(-1.5, 1.2, 0), (0, 1.2, 0), (1.5, 1.2, 0), (-1.5, 0.6, 1.5), (1.5, 0.6, 1.5)])

renderer = vtkRenderer()
ground, _ = ground_and_sphere()
renderer.AddActor(actor_of(ground, (0.8, 0.8, 0.8)))
points = vtkPoints()
cells = vtkCellArray()
for i, centre in enumerate(CENTRES):
    points.InsertNextPoint(*centre)
    cells.InsertNextCell(1, [i])
centres = vtkPolyData()
centres.SetPoints(points)
centres.SetVerts(cells)
mapper = vtkOpenGLSphereMapper()
mapper.SetInputData(centres)
mapper.SetRadius(RADIUS)
spheres = vtkActor()
spheres.SetMapper(mapper)
renderer.AddActor(spheres)
light, window, shadows, truth = light_pass_and_truth(renderer, 400, 300)
truth.SetSamplesPerLight(1)
camera = renderer.GetActiveCamera()
w, h = window.GetSize()


def world_points(depth):
    """The world point of every pixel from the truth's depth image (NDC depth in [0, 1])."""
    matrix = camera.GetCompositeProjectionTransformMatrix(w / h, -1, 1)
    to_world = np.linalg.inv(np.array([[matrix.GetElement(i, j) for j in range(4)] for i in range(4)]))
    ys, xs = np.mgrid[0:h, 0:w]
    ndc = np.stack([(xs + 0.5) / w * 2 - 1, (ys + 0.5) / h * 2 - 1, depth * 2 - 1, np.ones_like(depth)], -1)
    world = ndc @ to_world.T
    return world[..., :3] / world[..., 3:]


for positional, position in ((True, (-6, 2.0, 1.0)), (False, (-1, 0.6, -0.3))):
    for eye in ((8, 2, 0), (0, 9, 0.5)):
        light.SetPositional(positional)
        light.SetPosition(*position)
        camera.SetPosition(*eye)
        camera.SetFocalPoint(0, 0.8, 0)
        camera.SetViewUp(0, 1, 0)
        renderer.ResetCameraClippingRange()
        window.Render()
        truth.Update()
        ours = image(shadows.GetVisibilityImage(0), w, h)
        world = world_points(image(truth.GetDepthImage(), w, h))
        # Distance to the nearest centre and N.L there: the terminator band is left out.
        offsets = world[:, :, None, :] - CENTRES[None, None, :, :]
        nearest = np.argmin(np.linalg.norm(offsets, axis=-1), axis=-1)
        offset = np.take_along_axis(offsets, nearest[..., None, None], axis=2)[:, :, 0, :]
        on_sphere = np.abs(np.linalg.norm(offset, axis=-1) - RADIUS) < 0.05
        towards = (np.array(position) - world) if positional else np.broadcast_to(position, world.shape)
        towards = towards / np.linalg.norm(towards, axis=-1, keepdims=True)
        facing = np.sum(offset / RADIUS * towards, axis=-1)
        band = on_sphere & (np.abs(facing) < 0.25)
        compared, shadowed, wrong = compare_hard_shadows(window, ours, truth, left_out=band)
        label = "%s light %s, eye %s" % ("point" if positional else "directional", position, eye)
        print("     %s: %d px compared (%d in the terminator band left out), %d in shadow, %d wrong"
              % (label, compared, band.sum(), shadowed, wrong))
        check(shadowed > 0.01 * compared and on_sphere.sum() > 1000 and wrong <= 0.002 * compared,
              label + ": imposter spheres shadowed as the truth says")
finish()
