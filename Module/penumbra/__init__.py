"""Soft shadows for VTK: shadow volumes, penumbra wedges and ray-traced ground truth.

    import penumbra
    shadows = penumbra.enable_shadows(renderer, radius=0.3)

or, the VTK way:

    shadows = penumbra.vtkSoftShadowPass()
    renderer.SetPass(shadows)
"""
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers VTK's OpenGL factories first)

from .vtkPenumbraRendering import *  # noqa: F401,F403
try:  # the ray-traced truth needs Embree; the pass does not
    from .vtkPenumbraRayTracing import *  # noqa: F401,F403
except ImportError:
    pass
from .vtkPenumbraFilters import *  # noqa: F401,F403
from .shadows import add_light, disable_shadows, enable_shadows  # noqa: F401
