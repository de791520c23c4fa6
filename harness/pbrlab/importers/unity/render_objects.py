"""Passes of a custom LightMode tag in URP, drawn as a Render Objects renderer feature draws them.

URP's default renderer draws only its own LightMode tags (UniversalForward, UniversalForwardOnly,
SRPDefaultUnlit and an untagged pass; parse.URP.drawn) and its own special passes (ShadowCaster,
DepthOnly, DepthNormals, Meta, UniversalGBuffer, MotionVectors, the editor's Picking ...:
parse.URP.skipped). A pass tagged anything else (``"LightMode" = "MobileSSPR"``) is drawn by a
Render Objects renderer feature the user adds to the renderer with that tag in its LightMode
Tags list (URP's manual, "Render Objects Renderer Feature"): at its event, AfterRenderingOpaques
by default, each such pass of the objects its filters select, in the shader's pass order.

Where no pass of a SubShader would draw otherwise, the reader draws those custom-tag passes so
(``drawing``), with a warning naming each tag and the feature (``warning``); where another pass
draws, they stay skipped, as without the feature. The legacy built-in pipeline's tags
(ForwardBase, Always, Vertex, ...) are not custom: URP does not draw them (its editor shows
them with its error shader), so they stay skipped too.

    tags = custom_tags(sub, URP)                   # ("MobileSSPR",): the SubShader's custom tags
    pipeline = drawing(URP, tags)                  # URP drawing those tags too
"""

from __future__ import annotations

from dataclasses import replace

# The built-in pipeline's LightMode tags (Unity's manual, "Pass tags in the built-in render
# pipeline"): URP draws none of them, feature or not.
BUILTIN_LIGHT_MODES = frozenset((
    "always", "forwardbase", "forwardadd", "deferred", "shadowcaster", "shadowcollector", "meta",
    "prepassbase", "prepassfinal", "vertex", "vertexlm", "vertexlmrgbm", "motionvectors"))


def custom_tags(sub, pipeline) -> tuple:
    """The LightMode tags of ``sub``'s passes that ``pipeline`` (a Scriptable Render Pipeline's)
    neither draws nor skips as its own, as written, in pass order; () for the built-in pipeline."""
    if not pipeline.srp:
        return ()
    own = set(pipeline.drawn) | set(pipeline.skipped) | BUILTIN_LIGHT_MODES
    modes = (item[1].light_mode for item in sub.items if item[0] == "pass")
    return tuple(dict.fromkeys(m for m in modes if m.lower() not in own))


def skip_reason(mode: str, pipeline) -> str:
    """Why a pass of LightMode ``mode`` that ``pipeline`` does not draw is skipped."""
    if mode.lower() in BUILTIN_LIGHT_MODES:
        return "not a forward pass"
    if pipeline.srp:
        return ("not a forward pass (a custom LightMode: URP draws it only through a Render Objects renderer "
                "feature, which the harness models where no other pass draws)")
    return ("not a LightMode the built-in pipeline draws: a tag of a Scriptable Render Pipeline's or of a "
            "script's own, drawn only where a renderer or script asks for it by name (a CommandBuffer's draw of "
            "the pass, or in URP a Render Objects renderer feature with that tag); to have pbrlab draw it as "
            "such a URP feature would, tag the SubShader \"RenderPipeline\" = \"UniversalPipeline\"")


def drawing(pipeline, tags: tuple):
    """``pipeline`` drawing the passes of ``tags`` too (in pass order, as the feature does)."""
    return replace(pipeline, drawn=pipeline.drawn + tuple(t.lower() for t in tags))


def warning(path, sub, tags: tuple) -> str:
    named = ", ".join(f'"{t}"' for t in tags)
    return (f"{path}:{sub.line}: no pass draws in URP's default renderer: the passes of LightMode {named} "
            "are drawn as a Render Objects renderer feature with that tag in its LightMode Tags would draw "
            "them (URP draws a custom tag only through such a feature, which you add to the URP renderer), "
            "in pass order; the feature's event (AfterRenderingOpaques by default) is not modelled: "
            "objects draw in the scene's order here")
