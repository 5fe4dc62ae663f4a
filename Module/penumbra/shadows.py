"""Shadows for a renderer in one call, for scripts and for clients such as vedo.

    import penumbra
    shadows = penumbra.enable_shadows(renderer, radius=0.3)       # positional lights
    shadows = penumbra.enable_shadows(plotter.renderer, angular_radius=2.0)  # vedo.Light

The plain VTK way, which this wraps:

    shadows = penumbra.vtkSoftShadowPass()
    penumbra.vtkSoftShadowPass.SetLightRadius(light, 0.3)
    renderer.SetPass(shadows)
"""
import warnings

from vtkmodules.vtkRenderingCore import vtkActor, vtkLight

from .vtkPenumbraRendering import vtkSoftShadowPass

METHODS = {
    "automatic": vtkSoftShadowPass.METHOD_AUTOMATIC,
    "hard": vtkSoftShadowPass.METHOD_HARD_VOLUMES,
    "averaged": vtkSoftShadowPass.METHOD_AVERAGED_HARD_SHADOWS,
    "wedges": vtkSoftShadowPass.METHOD_PENUMBRA_WEDGES,
    "plateaus": vtkSoftShadowPass.METHOD_PLATEAUS,
    "soft_volumes": vtkSoftShadowPass.METHOD_SOFT_SHADOW_VOLUMES,
}


def _lights_of(renderer):
    lights = renderer.GetLights()
    return [lights.GetItemAsObject(i) for i in range(lights.GetNumberOfItems())]


def enable_shadows(renderer, radius=None, angular_radius=None, method="automatic", samples=None,
                   lights=None):
    """Sets a vtkSoftShadowPass on `renderer` and returns it.

    radius: the size of positional lights, in world units (0 gives hard shadows).
    angular_radius: the size of directional lights, in degrees (the sun is about 0.27). vedo's
        ``vedo.Light`` and a plain ``vtkLight`` are directional unless SetPositional(True).
    Either applies to `lights` (default: every light of the renderer); None leaves a light's
    radius as it is. method: "automatic" (the default), "hard", "averaged", "wedges",
    "plateaus" or "soft_volumes" (vtkSoftShadowPass.SetMethod). samples: light samples per area
    light (vtkSoftShadowPass.SetLightSamples), None for the default.

    The scene is drawn as the renderer draws it without a pass: its depth peeling, FXAA and SSAO
    settings are kept (vtkRendererSettingsPass). Headlights cast no shadow; camera lights do.
    A Python warning says so when no light of the renderer can cast, and when visible actors are
    unlit (Lighting off, as vedo's Plane is by default): no shadow shows on them.
    """
    if method not in METHODS:
        raise ValueError("method must be one of %s, not %r" % (", ".join(sorted(METHODS)), method))
    targets = list(lights) if lights is not None else _lights_of(renderer)
    # Headlights cannot cast: VTK's automatic one, directional, is in the list once the
    # renderer has drawn, and must not hide a size given for the wrong kind of light.
    casting = [light for light in targets if vtkSoftShadowPass.LightCastsShadows(light)]
    for name, value, positional, instead in (
            ("radius", radius, True, "angular_radius (degrees)"),
            ("angular_radius", angular_radius, False, "radius (world units)")):
        if value and casting and not any(bool(l.GetPositional()) == positional for l in casting):
            kind = "positional" if positional else "directional"
            warnings.warn("penumbra.enable_shadows: %s=%r is for %s lights and none of these is "
                          "one, so no light changes size; give %s" % (name, value, kind, instead),
                          stacklevel=2)
    for light in targets:
        size = radius if light.GetPositional() else angular_radius
        if size is not None:
            if not size >= 0:
                raise ValueError("a light's radius must be a number of at least 0 (%r)" % size)
            vtkSoftShadowPass.SetLightRadius(light, size)
    shadows = vtkSoftShadowPass()
    shadows.SetMethod(METHODS[method])
    if samples is not None:
        shadows.SetLightSamples(samples)
    renderer.SetPass(shadows)
    if not any(vtkSoftShadowPass.LightCastsShadows(light) for light in _lights_of(renderer)):
        warnings.warn("penumbra.enable_shadows: no light of this renderer casts shadows "
                      "(headlights do not, nor lights that are off); add a scene or camera light",
                      stacklevel=2)
    unlit = _unlit_receivers(renderer)
    if unlit:
        # The pass says so too, as a VTK warning, which vedo switches off.
        warnings.warn("penumbra.enable_shadows: %d visible actor(s) have Lighting off (%s), so "
                      "no shadow shows on them; turn it on (vedo: mesh.lighting(\"default\"))"
                      % (len(unlit), ", ".join(sorted({a.GetClassName() for a in unlit}))),
                      stacklevel=2)
    return shadows


def _unlit_receivers(renderer):
    """The visible actors drawn unlit for the renderer's receivers: top-level actors and the
    parts of assemblies, under the top-level prop's ReceivesShadows flag, as the pass reads it."""
    props = renderer.GetViewProps()
    found = []
    for i in range(props.GetNumberOfItems()):
        prop = props.GetItemAsObject(i)
        if not prop.GetVisibility() or not vtkSoftShadowPass.GetReceivesShadows(prop):
            continue
        prop.InitPathTraversal()
        path = prop.GetNextPath()
        while path is not None:
            leaf = path.GetLastNode().GetViewProp()
            if (isinstance(leaf, vtkActor) and leaf.GetVisibility()
                    and not leaf.GetProperty().GetLighting()):
                found.append(leaf)
            path = prop.GetNextPath()
    return found


def add_light(renderer, position, radius=0.0, focal_point=(0.0, 0.0, 0.0)):
    """Adds a positional scene light shining all round (headlights cast no shadows) of `radius`
    world units at `position`, and returns it."""
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetConeAngle(180)
    light.SetPosition(*position)
    light.SetFocalPoint(*focal_point)
    if not radius >= 0:
        raise ValueError("a light's radius must be a number of at least 0 (%r)" % radius)
    vtkSoftShadowPass.SetLightRadius(light, radius)
    renderer.AddLight(light)
    return light


def disable_shadows(renderer):
    """Removes the pass enable_shadows set: the renderer draws as VTK does by default."""
    renderer.SetPass(None)
