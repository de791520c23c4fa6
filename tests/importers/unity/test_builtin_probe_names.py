"""The built-in pipeline's names for a program that reads the reflection probe itself (issue 34):
BoxProjectedCubemapDirection (UnityStandardUtils.cginc) and the three-argument
Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(unity_SpecCube0), unity_SpecCube0_HDR, glossIn)
(UnityImageBasedLighting.cginc), both reached through UnityPBSLighting.cginc as in Unity.
Both languages, against float64 values of Unity's documented behaviour (the stand-ins' comments).
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.foundation.locations import locate
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")

PASS = """
Shader "t/{name}" {{
    SubShader {{ Pass {{
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        #include "UnityPBSLighting.cginc"
        struct v2f {{ float4 pos : SV_POSITION; float3 dir : TEXCOORD0; }};
        v2f vert(float4 vertex : POSITION, float3 normal : NORMAL) {{
            v2f o; o.pos = UnityObjectToClipPos(vertex); o.dir = UnityObjectToWorldNormal(normal); return o; }}
        float4 frag(v2f i) : SV_Target {{
{body}
        }}
        ENDCG
    }} }}
}}
"""


def _render(tmp_path, name, body, language, environment=True):
    shader = tmp_path / f"{name}.shader"
    shader.write_text(textwrap.dedent(PASS.format(name=name, body=body)))
    data = corpus.scene_for(shader)
    if environment:
        data["environment"] = {"path": str(locate("scenes") / "assets" / "sky.exr"), "intensity": 0.5}
    else:
        data.pop("environment", None)
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.2
    return image[covered, :3]


REFL, POS, MIN, MAX = (1.0, 0.5, 0.25), (0.1, 0.2, 0.3), (-1.0, -1.0, -1.0), (2.0, 2.0, 2.0)


def box_projected(refl, pos, centre, box_min, box_max):
    """float64 reference (UnityStandardUtils.cginc's behaviour, as its stand-in states): with
    centre.w > 0 the point where the ray from ``pos`` along unit ``refl`` leaves the box, seen
    from the probe's centre; otherwise ``refl``."""
    refl, pos = np.asarray(refl, np.float64), np.asarray(pos, np.float64)
    if centre[3] <= 0:
        return refl
    d = refl / np.linalg.norm(refl)
    exits = np.where(d > 0, (np.asarray(box_max) - pos) / d, (np.asarray(box_min) - pos) / d)
    return pos - np.asarray(centre[:3]) + d * exits.min()


def _box_body(w: float) -> str:
    return (f"            float3 r = BoxProjectedCubemapDirection(float3{REFL}, float3{POS}, "
            f"float4(0.05, 0.1, 0.15, {w}), float4{MIN + (0.0,)}, float4{MAX + (0.0,)});\n"
            "            return float4(r * 0.25, 1);")


# float32: a normalize, three divisions, a min and a multiply-add on values below 4, then * 0.25:
# about 8 roundings of 2^-24 relative of 4: 8 * 4 * 6e-8 = 2e-6.
BOX_BOUND = 2e-6


@pytest.mark.parametrize("language", LANGUAGES)
def test_box_projected_cubemap_direction_is_unitys(tmp_path, language):
    centre = (0.05, 0.1, 0.15, 1.0)
    got = _render(tmp_path, "box", _box_body(1.0), language, environment=False)
    want = box_projected(REFL, POS, centre, MIN, MAX) * 0.25
    assert np.abs(got - want).max() <= BOX_BOUND
    # control: a probe without box projection (w = 0, pbrlab's sky) returns the direction as given
    flat = _render(tmp_path, "flat", _box_body(0.0), language, environment=False)
    assert np.abs(flat - np.asarray(REFL) * 0.25).max() <= BOX_BOUND
    assert np.abs(flat - want).max() > 0.05


ROUGHNESS = 0.5
# Unity's mip for perceptual roughness r: r (1.7 - 0.7 r) * UNITY_SPECCUBE_LOD_STEPS (6), float64
MIP = ROUGHNESS * (1.7 - 0.7 * ROUGHNESS) * 6.0
GLOSSY = f"""            Unity_GlossyEnvironmentData g;
            g.roughness = {ROUGHNESS};
            g.reflUVW = normalize(i.dir);
            return float4(Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(unity_SpecCube0), unity_SpecCube0_HDR, g), 1);"""
# The shader's mip and the literal differ by float32 rounding (2^-23 relative of 4.05): times the
# largest change of a texel between two mips (below the environment's peak, < 10 here) 1e-5,
# plus the read's own rounding: 2e-5.
GLOSSY_BOUND = 2e-5


def _lod_body(mip: float) -> str:
    return f"            return float4(UNITY_SAMPLE_TEXCUBE_LOD(unity_SpecCube0, normalize(i.dir), {mip!r}).rgb, 1);"


@pytest.mark.parametrize("language", LANGUAGES)
def test_glossy_environment_on_the_probe_reads_unitys_mip(tmp_path, language):
    got = _render(tmp_path, "glossy", GLOSSY, language)
    want = _render(tmp_path, "lod", _lod_body(MIP), language)
    assert np.abs(got - want).max() <= GLOSSY_BOUND
    # control: the probe's sharpest mip (no roughness remap) is another image
    sharp = _render(tmp_path, "sharp", _lod_body(0.0), language)
    assert np.abs(sharp - want).max() > 1e-2
