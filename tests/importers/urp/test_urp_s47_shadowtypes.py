"""Shadow textures typed per texture in both languages (issue 34, session 47): a program that
compares one depth texture and reads another plainly, and one that reads the same texture both
through a comparison sampler and plainly (Direct3D allows it: one Texture2D, two samplers;
Microsoft's HLSL reference, "Texture2D"). Both languages type each texture by one decision,
importers/unity/compared_textures.py's texture_reads: compared only, a sampler2DShadow; plain
only, a sampler2D; both, a sampler2D under the texture's name and a sampler2DShadow view
``<name>_pbrlab_compared`` that its comparisons read, bound to the property's depths.

What main did (before session 47): the GLSL port typed every TEXTURE2D_SHADOW a comparison
sampler when the program compared ANY texture, and a Texture2D by its own direct SampleCmp
only: shadow_split.shader, shadow_both_core.shader, shadow_both_objects.shader and
shadow_both_passed.shader failed to compile in GLSL (``tex2D(sampler2DShadow, vec2)``,
``CompareIn(sampler2D, ...)``). The HLSL path: spirv-cross splits a global read both ways into
``_Depths`` and ``_Depths_1``, which no property binds, so shadow_both_core's and
shadow_both_objects' plain read read the white stand-in, 1.0 on every pixel; and
shadow_both_passed failed to compile (the global retyped sampler2DShadow, its plain read
``texture(sampler2DShadow, vec2)``).

Scene: test_urp_shadow_compare_s46.py's (a plane filling a 64 x 64 view seen straight down; each
pixel's screen uv its centre, u = (x + 0.5) / 64); every texture property is a 2 x 1 PNG whose
red codes 64 and 192 are the stored depths d = (64/255, 192/255), linear (srgb false).

Float64 references:
* a comparison (Microsoft's HLSL reference, "SampleCmp"; OpenGL 3.3 core 3.8.16): the bilinear,
  clamp-to-edge interpolation of [z <= d_k] at u (shadow_maps.py binds the depths clamped);
* a plain read: the bilinear interpolation of d_k at u with the texture property's wrap, Repeat
  (Unity's default wrap mode for an imported texture, which pbrlab's texture properties take).
Bound 2^-8 for both: Direct3D 11's 8 bits of subtexel weight precision (the s46 test's
derivation); an 8-bit texel's code / 255 is exact in the filter's input, float32 rounding
(2^-24) below it, and every reference is >= 0.03 from every stored depth (no comparison flips).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.images import write_png
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
SHADERS = Path(__file__).resolve().parent / "shaders" / "s47-shadowtypes"
SIZE = 64
CODES = (64, 192)
BOUND = 2.0 ** -8
REFERENCE = 0.5
_DISTANCE, _FOV_DEG = 3.0, 40.0


def _render(tmp_path, shader: str, language: str, names=("_Depths",)) -> np.ndarray:
    write_png(tmp_path / "depths.png", np.array([[[CODES[0], 0, 0, 255], [CODES[1], 0, 0, 255]]], np.uint8))
    depths = {"path": str(tmp_path / "depths.png"), "srgb": False}
    side = 2 * _DISTANCE * np.tan(np.radians(_FOV_DEG / 2))
    data = {
        "camera": {"position": [0.0, 2.0, 0.0], "target": [0.0, -1.0, 0.0], "up": [0.0, 0.0, -1.0],
                   "fov_y_deg": _FOV_DEG, "size": [SIZE, SIZE]},
        "lights": [{"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0}],
        "materials": {"m": {"surface": str(SHADERS / shader),
                            "properties": {**{n: depths for n in names}, "_Reference": REFERENCE}}},
        "objects": [{"mesh": {"primitive": "plane", "size": float(side)},
                     "transform": {"translate": [0.0, -1.0, 0.0]}, "material": "m"}],
    }
    scene = parse_scene(data, origin="s47 shadow types test scene", base=tmp_path)
    return render_scene(scene, language=language).linear.astype(np.float64)


def _bilinear(per_texel: np.ndarray, wrap: bool) -> np.ndarray:
    """GL's linear filter across the 2 texels at each pixel column's u: (SIZE, SIZE)."""
    u = (np.arange(SIZE) + 0.5) / SIZE
    s = u * len(per_texel) - 0.5
    i0 = np.floor(s).astype(int)
    a = s - i0
    index = (lambda i: i % len(per_texel)) if wrap else (lambda i: np.clip(i, 0, len(per_texel) - 1))
    row = (1 - a) * per_texel[index(i0)] + a * per_texel[index(i0 + 1)]
    return np.broadcast_to(row, (SIZE, SIZE))


STORED = np.array(CODES, np.float64) / 255.0
COMPARED = _bilinear((REFERENCE <= STORED).astype(np.float64), wrap=False)
PLAIN = _bilinear(STORED, wrap=True)


def _within(channel: np.ndarray, expected: np.ndarray) -> None:
    err = np.abs(channel - expected)
    assert (err <= BOUND).all(), err.max()


@pytest.mark.parametrize("language", LANGUAGES)
def test_one_texture_compared_another_read_plainly(tmp_path, language):
    """shadow_split.shader: red, _Depths compared (SAMPLE_TEXTURE2D_SHADOW); green, _Plain
    (declared TEXTURE2D_SHADOW) read by SAMPLE_TEXTURE2D; blue, a Texture2D compared only
    inside a function it is passed to. Each against its float64 reference within BOUND.
    Control: on main the GLSL port declared _Plain a sampler2DShadow (the program compares
    _Depths) and _Passed a sampler2D, and the program did not compile; the plain read is not a
    comparison's 0/1 ramp (it differs from COMPARED by more than BOUND on most pixels)."""
    image = _render(tmp_path, "shadow_split.shader", language, ("_Depths", "_Plain", "_Passed"))
    _within(image[..., 0], COMPARED)
    _within(image[..., 1], PLAIN)
    _within(image[..., 2], COMPARED)
    assert (np.abs(image[..., 1] - COMPARED) > BOUND).mean() > 0.9
    assert (image[..., 0] == 0).any() and (image[..., 0] == 1).any()  # shadowed and lit texels


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("shader", ["shadow_both_core.shader", "shadow_both_objects.shader"])
def test_one_texture_compared_and_read_plainly(tmp_path, language, shader):
    """One texture read both ways (Core RP's macros; Direct3D 11's objects): red, its direct
    comparison; green, its plain read, the stored depth; blue, its comparison through a function
    it is passed to. Controls: on main the GLSL port failed to compile both shaders
    (``tex2D(sampler2DShadow, vec2)``), and the HLSL path's plain read read the unbound
    ``_Depths_1`` (the white stand-in), 1.0 on every pixel, which fails the green check here:
    every expected depth is at least 0.25 from 1. The comparisons are not of URP's empty shadow
    map either (its reads are 1 everywhere; here half the texels read 0)."""
    image = _render(tmp_path, shader, language)
    _within(image[..., 0], COMPARED)
    _within(image[..., 1], PLAIN)
    _within(image[..., 2], COMPARED)
    assert (np.abs(image[..., 1] - 1.0) > BOUND).all()
    assert (image[..., 0] == 0).any() and (image[..., 2] == 0).any()


@pytest.mark.parametrize("language", LANGUAGES)
def test_one_texture_read_plainly_and_compared_in_a_function(tmp_path, language):
    """shadow_both_passed.shader: a Texture2D read by Sample and compared only inside a function
    it is passed to. Red: the comparison; green: the plain read. Control: on main both languages
    refused to compile it (GLSL: ``CompareIn(sampler2D, ...)``; HLSL: spirv-cross's global
    retyped sampler2DShadow, its plain read ``texture(sampler2DShadow, vec2)``)."""
    image = _render(tmp_path, "shadow_both_passed.shader", language)
    _within(image[..., 0], COMPARED)
    _within(image[..., 1], PLAIN)
    assert (np.abs(image[..., 1] - COMPARED) > BOUND).mean() > 0.9


_FLOW = """
#define SAMPLE_TEXTURE2D_SHADOW(t, s, coord3) t.SampleCmpLevelZero(s, (coord3).xy, (coord3).z)
TEXTURE2D_SHADOW(_A); TEXTURE2D_SHADOW(_B); TEXTURE2D_SHADOW(_C); Texture2D _D; Texture2D t;
float Inner(TEXTURE2D_SHADOW_PARAM(map, sampler_map), float3 c) { return SAMPLE_TEXTURE2D_SHADOW(map, sampler_map, c); }
float Outer(TEXTURE2D_SHADOW_PARAM(m2, s2), float3 c) { return Inner(TEXTURE2D_SHADOW_ARGS(m2, s2), c); }
float Plain(Texture2D tex, SamplerState s, float2 uv) { return tex.Sample(s, uv).r; }
float4 frag(float4 p : SV_Position) : SV_Target {
    return float4(Outer(TEXTURE2D_SHADOW_ARGS(_A, sA), p.xyz), SAMPLE_TEXTURE2D(_B, sB, p.xy).r,
                  Plain(_C, sC, p.xy) + Outer(_C, sC, p.xyz), _D.Load(int3(0, 0, 0)).r);
}
"""


def test_texture_reads_follow_calls_and_skip_the_api_definitions():
    """texture_reads (the one decision both languages type by): _A compared through two calls
    (Outer passes it to Inner), _B read plainly, _C both (a plain function and a comparing one),
    _D plainly by Load; the stand-in's own #define of SAMPLE_TEXTURE2D_SHADOW is not a read of
    its parameter ``t`` (a Texture2D global here, never read). Control: _A is compared only
    through the calls (no direct comparison names it)."""
    from pbrlab.importers.unity.compared_textures import texture_reads
    reads = texture_reads(_FLOW)
    assert {"_A", "_C", "map", "m2"} <= reads.compared and not {"_B", "_D", "t"} & reads.compared
    assert {"_B", "_C", "_D", "tex"} <= reads.plain and not {"_A", "t"} & reads.plain
    assert reads.both == {"_C"}
    assert "SAMPLE_TEXTURE2D_SHADOW(_A" not in _FLOW and "_A.SampleCmp" not in _FLOW


_BOTH_DIRECT = """
Texture2D _M; SamplerComparisonState sampler_cmp; SamplerState sampler_point;
float4 main(float4 p : SV_Position) : SV_Target {
    return float4(_M.SampleCmpLevelZero(sampler_cmp, p.xy, p.z), _M.Sample(sampler_point, p.xy).r, 0, 1);
}
"""


def test_hlsl_path_names_the_comparison_view():
    """spirv-cross's GLSL of a global read both ways: two combined samplers, ``_M`` and ``_M_1``
    (control: spirv-cross alone); typed_shadow_globals names them ``_M`` (the plain sampler,
    which the property binds) and ``_M_pbrlab_compared`` (the comparison view), by
    texture_reads of the HLSL."""
    from pbrlab.gpu import hlsl
    from pbrlab.importers.unity.compared_textures import texture_reads
    from pbrlab.importers.unity.shadow_sampler_globals import typed_shadow_globals
    plain = hlsl.cross_to_glsl(hlsl.compile_spirv(_BOTH_DIRECT, "both_direct.hlsl"))
    assert "_M_1;" in plain  # control: spirv-cross's own second name
    glsl = typed_shadow_globals(plain, texture_reads(_BOTH_DIRECT))
    assert "uniform sampler2D _M;" in glsl and "uniform sampler2DShadow _M_pbrlab_compared;" in glsl
    assert "_M_1" not in glsl
