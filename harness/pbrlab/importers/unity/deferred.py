"""The built-in deferred path's light passes, drawn as Unity's renderer draws them.

A pass whose vertex function is ``vert_deferred`` (UnityDeferredLibrary.cginc: Unity's
Internal-DeferredShading, Internal-DeferredReflections, Internal-PrePassLighting and a user's
custom deferred shading) is a light pass: Unity draws it once per light over the light's
volume, with the light's keyword (``multi_compile_lightpass``: DIRECTIONAL, POINT, SPOT) and
its values in ``_LightPos``/``_LightColor``/``_LightDir``, each draw blended onto the light
buffer by the pass's own Blend line (the deferred shaders' ``Blend [_SrcBlend] [_DstBlend]``,
One One). The harness draws it so over the object's mesh (the object is the light volume)
once per scene light, after the first with the target's alpha (the coverage) kept, and with
``UNITY_HDR_ON``: the harness's target is a float (HDR) one, as a Unity camera with HDR on.

The passes Unity draws only with an LDR light buffer, or to composite a buffer the harness
does not keep, are skipped with a note (``skipped_reason``).

    light_draws(defines)            # [defines] of each light's draw
    light_assignments(language)     # the fragment entry's lines that fill the draw's light
"""

from __future__ import annotations

import re

LIGHT_PASS_VERTEX = "vert_deferred"
# Unity's camera keyword for a float light buffer (HDR on): the harness's target is float.
HDR_KEYWORD = "UNITY_HDR_ON"
LIGHT_KINDS = ("DIRECTIONAL", "POINT", "SPOT")


def is_light_pass(unity_pass) -> bool:
    """Whether a vertex/fragment pass is one of the deferred path's light passes."""
    return getattr(unity_pass, "kind", None) == "vertex-fragment" and \
        getattr(unity_pass, "vertex", None) == LIGHT_PASS_VERTEX


def light_draws(defines: dict) -> list[dict]:
    """The defines of each draw of a light pass: one per scene light, directional lights
    first, then point, then spot (PBRLAB_<KIND>_COUNT of the scene), each with its keyword and
    PBRLAB_UNITY_DEFERRED_<KIND> its index."""
    out = []
    for kind in LIGHT_KINDS:
        out += [{**defines, HDR_KEYWORD: 1, kind: 1, f"PBRLAB_UNITY_DEFERRED_{kind}": i}
                for i in range(defines.get(f"PBRLAB_{kind}_COUNT", 0))]
    return out


# A pass that decodes Unity's LDR light buffer (its -log2 of the exp2-encoded lights) or
# writes it (Blend DstColor Zero: the lights multiplied in as exp2(-light)): Unity draws
# these only when the camera's light buffer is LDR; the harness's is float (HDR).
_LDR_BUFFER = re.compile(r"\b_LightBuffer\b")
_REFLECTIONS_BUFFER = re.compile(r"\b_CameraReflectionsTexture\b")


def skipped_reason(unity_pass) -> str | None:
    """Why Unity would not draw this pass of a deferred shader in the harness's setting, or
    None when it draws."""
    if getattr(unity_pass, "kind", None) != "vertex-fragment":
        return None
    program = getattr(unity_pass, "program", "") or ""
    if _LDR_BUFFER.search(program):
        return ("it decodes the LDR light buffer (_LightBuffer), which Unity draws only when the "
                "camera is not HDR; the harness's target is HDR (UNITY_HDR_ON)")
    factors = tuple(f.lower() for f in (unity_pass.state.blend_factors or ()))
    if is_light_pass(unity_pass) and factors[:2] == ("dstcolor", "zero"):
        return ("a light pass into the LDR light buffer (Blend DstColor Zero: each light multiplied "
                "in as exp2(-light)), which Unity draws only when the camera is not HDR; the "
                "harness's target is HDR and takes the additive light pass")
    if _REFLECTIONS_BUFFER.search(program):
        return ("it adds the reflection buffer (_CameraReflectionsTexture) to the light buffer; "
                "the harness draws the reflection pass into its target directly")
    return None


def light_assignments(language: str) -> str:
    """The fragment entry's lines (before the pass's fragment function runs) that fill the
    draw's light from the scene's light arrays, as Unity sets _LightPos (xyz position, w
    1 / range^2), _LightColor and _LightDir (the direction the light travels); with pbrlab's
    range and spot cone beside them (UnityDeferredLibrary.cginc)."""
    text = """#if defined(PBRLAB_UNITY_DEFERRED_DIRECTIONAL)
    _LightPos = vec4(0.0, 0.0, 0.0, 0.0);
    _LightColor = vec4(u_directional_radiance[PBRLAB_UNITY_DEFERRED_DIRECTIONAL], 1.0);
    _LightDir = vec4(u_directional_direction[PBRLAB_UNITY_DEFERRED_DIRECTIONAL], 0.0);
#elif defined(PBRLAB_UNITY_DEFERRED_POINT)
    pbrlab_LightRange = u_point_range[PBRLAB_UNITY_DEFERRED_POINT];
    _LightPos = vec4(u_point_position[PBRLAB_UNITY_DEFERRED_POINT], 1.0 / (pbrlab_LightRange * pbrlab_LightRange));
    _LightColor = vec4(u_point_radiance[PBRLAB_UNITY_DEFERRED_POINT], 1.0);
    _LightDir = vec4(0.0, 0.0, 0.0, 0.0);
#elif defined(PBRLAB_UNITY_DEFERRED_SPOT)
    pbrlab_LightRange = u_spot_range[PBRLAB_UNITY_DEFERRED_SPOT];
    _LightPos = vec4(u_spot_position[PBRLAB_UNITY_DEFERRED_SPOT], 1.0 / (pbrlab_LightRange * pbrlab_LightRange));
    _LightColor = vec4(u_spot_radiance[PBRLAB_UNITY_DEFERRED_SPOT], 1.0);
    _LightDir = vec4(u_spot_direction[PBRLAB_UNITY_DEFERRED_SPOT], 0.0);
    pbrlab_LightCone = vec4(u_spot_cone[PBRLAB_UNITY_DEFERRED_SPOT], 0.0, 0.0);
#endif
"""
    return text.replace("vec4", "float4") if language == "hlsl" else text
