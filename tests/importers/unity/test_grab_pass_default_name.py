"""An unnamed ``GrabPass {}`` (issue 34, the black renders of session 45): Unity binds what is
drawn so far as ``_GrabTexture`` with its ``_GrabTexture_TexelSize`` (ShaderLab manual,
"GrabPass": "GrabPass { } grabs the current screen contents into a texture ... accessed in
further passes by _GrabTexture"). The corpus scene draws no sky behind its sphere, so a shader
that shows only its grab draws black there, as Unity would over the same black background
(corpus/urp/black_by_defaults.md, "What lies behind the sphere"). This checks that the black is
the background's and not an unbound grab: with an emitting wall behind the sphere, the grab
holds the wall.

Scene: the corpus scene (unity_corpus.scene_for) with an emissive plane filling the view behind
the sphere (black albedo and specular: its radiance is its emission alone, WALL_EMISSION).
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

from corpus_sphere import covered_pixels

LANGUAGES = ("glsl", "hlsl")
WALL_EMISSION = np.array([1.0, 0.5, 0.25], np.float64)
WALL = {"workflow": "specular", "albedo": [0, 0, 0], "specular": [0, 0, 0], "smoothness": 0.0,
        "emission": WALL_EMISSION.tolist()}
BEHIND = {"mesh": {"primitive": "plane", "size": 40}, "material": "wall",
          "transform": {"translate": [0, 0, -3], "rotate_deg": [90, 0, 0]}}
HALF = 0.5

# Half of what it grabbed, times _GrabTexture_TexelSize.x * .z (1/w * w = 1 when Unity's
# texel size is set, 0 when it is not).
GRAB_SHADER = textwrap.dedent("""
    Shader "t/UnnamedGrab" { SubShader { Tags { "Queue" = "Transparent" }
    %s
    Pass { CGPROGRAM
    #pragma vertex vert
    #pragma fragment frag
    #include "UnityCG.cginc"
    sampler2D _GrabTexture;
    float4 _GrabTexture_TexelSize;
    struct v2f { float4 pos : SV_POSITION; float4 grab : TEXCOORD0; };
    v2f vert(appdata_base v) {
        v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.grab = ComputeGrabScreenPos(o.pos); return o;
    }
    float4 frag(v2f i) : SV_Target {
        float3 behind = tex2Dproj(_GrabTexture, UNITY_PROJ_COORD(i.grab)).rgb;
        return float4(behind * 0.5 * (_GrabTexture_TexelSize.x * _GrabTexture_TexelSize.z), 1);
    }
    ENDCG } } }
""")

# The expected value: WALL_EMISSION * HALF in float64. In float32 (the rgba32f target) every step
# is exact but one: 1, 0.5, 0.25 and their halves are powers of two; the grab is a float-to-float
# blit; the filtered lookup of a uniform wall interpolates equal texels (a + t (b - a) = a); the
# product 1/w * w is rounded once, at most half an ulp (2^-24 relative), and the halving is exact.
# Bound: one float32 ulp relative, 2^-23.
BOUND = 2.0 ** -23


def _render(tmp_path, language, grab_line: str, wall: bool):
    shader = tmp_path / "grab.shader"
    shader.write_text(GRAB_SHADER % grab_line, encoding="utf-8")
    data = corpus.scene_for(shader)
    if wall:
        data["materials"]["wall"] = WALL
        data["objects"] = [BEHIND] + data["objects"]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear


def _off(image, covered):
    """The fraction of the covered pixels whose colour is off WALL_EMISSION * HALF by more than BOUND."""
    expected = WALL_EMISSION * HALF
    error = np.abs(np.asarray(image[covered][:, :3], np.float64) - expected)
    return float(np.mean(np.any(error > BOUND * expected, axis=-1)))


@pytest.mark.parametrize("language", LANGUAGES)
def test_unnamed_grab_pass_binds_what_lies_behind(gl_context, tmp_path, language):
    bare = _render(tmp_path, language, "GrabPass { }", wall=False)
    covered = covered_pixels(bare)  # the sphere's pixels (alpha 1 over a background of 0)
    # the corpus scene: the grab holds its black background, so the sphere draws black
    assert bare[covered][:, :3].max() < corpus.BLACK_LEVEL
    walled = _render(tmp_path, language, "GrabPass { }", wall=True)
    assert _off(walled, covered) == 0.0  # every covered pixel: half the wall's radiance
    # control: without the GrabPass the program reads an unset _GrabTexture (no wall)
    control = _render(tmp_path, language, "", wall=True)
    assert _off(control, covered) > 0.9
