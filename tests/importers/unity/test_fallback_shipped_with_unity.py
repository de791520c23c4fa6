"""A Fallback pbrlab does not find (issue 34, session 45's long tail): when it names one of the
shaders Unity ships with the editor ("Specular", "VertexLit", "Legacy Shaders/...") or Unity's error
shader, the refusal says so instead of asking for the shader's file in the project (no project
holds it); a project's own Fallback keeps that hint, and a project that does hold a shader of a
shipped name gets it drawn. Both languages; the refusals name the shader's file and the Fallback's
line, the drawn Fallback's pixel is its exact constant.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from pbrlab import scene
from pbrlab.foundation.errors import PbrlabError
from pbrlab.render import renderer as render

LANGUAGES = ("hlsl", "glsl")

# one SubShader whose only pass is the deferred path's (pbrlab draws the forward path), so the
# Fallback is what Unity would draw
_DEFERRED_ONLY = """Shader "t/deferred_only" {
    SubShader {
        Pass {
            Tags { "LightMode" = "Deferred" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            float4 frag() : SV_Target { return float4(1.0, 0.0, 0.0, 1.0); }
            ENDCG
        }
    }
    Fallback "%s"
}
"""
FALLBACK_LINE = _DEFERRED_ONLY.split("\n").index("    Fallback \"%s\"") + 1

# a project's own shader of a shipped name, found before anything else
_PROJECT_DIFFUSE = """Shader "Diffuse" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            float4 frag() : SV_Target { return float4(0.25, 0.5, 0.125, 1.0); }
            ENDCG
        }
    }
}
"""


def _render(shader, language):
    data = {"camera": {"position": [0, 0, 3.2], "target": [0, 0, 0], "fov_y_deg": 40, "size": [32, 32]},
            "lights": [], "materials": {"m": {"surface": str(shader)}},
            "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}]}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        image = render.render_scene(scene.parse_scene(data, "<test>", shader.parent), language=language).linear
    return np.asarray(image, np.float64)


def _refusal(tmp_path, language, fallback) -> str:
    shader = tmp_path / "deferred_only.shader"
    shader.write_text(_DEFERRED_ONLY % fallback)
    with pytest.raises(PbrlabError) as refused:
        _render(shader, language)
    message = str(refused.value)
    assert f"{shader}:2: nothing here draws" in message  # the SubShader's own reason first
    return message


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("fallback", ["Specular", "VertexLit", "Legacy Shaders/Bumped Specular", "Mobile/Diffuse"])
def test_a_fallback_unity_ships_is_named_as_such(tmp_path, language, fallback):
    """The Fallback named, its line, and that Unity ships it; no advice to put its file in the project.
    Control: a project's own missing Fallback keeps that advice, also under a first name Unity's
    shaders use ("Unlit/NewUnlitShader", the name Unity's own new-shader template gives)."""
    message = _refusal(tmp_path, language, fallback)
    assert (f'its Fallback "{fallback}" is one of the shaders Unity ships with the editor (no file of the '
            f"project) (line {FALLBACK_LINE}): pbrlab has no stand-in for it") in message
    assert "put its .shader file" not in message
    for own in ("Game/Plain", "Unlit/NewUnlitShader"):
        control = _refusal(tmp_path, language, own)
        assert (f'its Fallback "{own}" is a shader pbrlab does not have (line {FALLBACK_LINE}): put its .shader '
                "file") in control


@pytest.mark.parametrize("language", LANGUAGES)
def test_unity_s_error_shader_as_fallback_is_named(tmp_path, language):
    """Fallback "Hidden/InternalErrorShader": Unity's magenta error shader, said so."""
    message = _refusal(tmp_path, language, "Hidden/InternalErrorShader")
    assert (f'its Fallback "Hidden/InternalErrorShader" is Unity\'s error shader (line {FALLBACK_LINE}): Unity draws '
            "the object in its flat magenta") in message


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_project_shader_of_a_shipped_name_is_drawn(tmp_path, language):
    """A project holding its own "Diffuse" gets it drawn as the Fallback: its exact constant on every
    covered pixel (the deferred pass's red is not drawn)."""
    (tmp_path / "diffuse.shader").write_text(_PROJECT_DIFFUSE)
    shader = tmp_path / "deferred_only.shader"
    shader.write_text(_DEFERRED_ONLY % "Diffuse")
    image = _render(shader, language)
    covered = image[..., 3] > 0
    assert covered.sum() > 100
    assert np.all(image[covered][:, :3] == np.array([0.25, 0.5, 0.125], np.float32))
