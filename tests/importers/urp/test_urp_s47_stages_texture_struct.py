"""A program's own struct with texture and sampler members (s47-stages, issue 34):
``struct TextureInfo { TEXTURE2D(tex); SAMPLER(sampler_tex); float4 st; };`` filled in a local
from the globals and passed to a function that samples it (shaders/s47-stages/
urp_texture_struct.shader). GLSL allows no sampler in a struct and spirv-cross no struct of
separate samplers, so texture_structs.py spells the members out as FXC resolves them (its
docstring). Before the change the GLSL port failed to compile ("syntax error, unexpected '='")
and spirv-cross refused the HLSL ("structs of separate samplers"): the render test then fails.

The shader places the plane's corners (x, z) / 0.3 at NDC (x / 0.3, -z / 0.3), so a pixel centre
(X, Y) has uv ((X + 1) / 2, (Y + 1) / 2); the fragment snaps it to c = (floor(8 uv) + 0.5) / 8 and
the function reads the texture at c * st.xy + st.zw with st = _MainTex_ST, tiling (2, 2) and
offset (0.25, 0.5): (k + 0.5) / 4 + (0.25, 0.5) for k = floor(8 uv), the centre of texel
(k_u + 1, k_v + 2) mod 4 (the sampler repeats), read exactly by bilinear filtering. The 4 x 4
texture holds 17 (x + 4 y) / 255 (linear, y up as Unity's v): a texel's float32 value is k / 255
rounded at most twice (the unorm conversion k * (1 / 255): the reciprocal and the product), so the
bound is 2 * 2^-24 (values < 1; measured 1.2 ulp on llvmpipe). Control: without the tiling (the struct's float
member) the texels read differ.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.texture_structs import spelled_out
from pbrlab.render.renderer import render_scene

SHADER = Path(__file__).parent / "shaders/s47-stages/urp_texture_struct.shader"


def _grid(path: Path) -> np.ndarray:
    values = np.array([[17 * (x + 4 * y) for x in range(4)] for y in range(4)], np.uint8)
    Image.fromarray(np.repeat(values[::-1, :, None], 3, axis=2)).save(path)
    return values / 255.0


def _render(tmp_path, language, offset=(0.25, 0.5)):
    shader = tmp_path / SHADER.name
    shader.write_text(SHADER.read_text())
    data = corpus.scene_for(shader)
    data["materials"]["m"]["properties"] = {"_MainTex": {"path": str(tmp_path / "grid.png"), "srgb": False,
                                                         "tiling": [2, 2], "offset": list(offset)}}
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


def _expected(grid, shape, offset):
    h, w = shape
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    ku, kv = np.floor((X + 1) / 2 * 8).astype(int), np.floor((Y + 1) / 2 * 8).astype(int)
    return grid[(kv + int(offset[1] * 4)) % 4, (ku + int(offset[0] * 4)) % 4]


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_struct_s_texture_is_the_global_assigned_to_it(tmp_path, language):
    grid = _grid(tmp_path / "grid.png")
    image = _render(tmp_path, language)
    want = _expected(grid, image.shape[:2], (0.25, 0.5))
    assert (image[..., 3] > 0).all()
    for c in range(3):
        assert (np.abs(image[..., c] - want) <= 2 * 2.0 ** -24).all()
    assert np.abs(image[..., 0] - _expected(grid, image.shape[:2], (0.0, 0.0))).max() > 0.1  # control


def test_the_spelling_keeps_lines_and_leaves_other_structs():
    text = SHADER.read_text()
    spelled = spelled_out(text)
    assert spelled.count("\n") == text.count("\n")
    assert "TEXTURE2D(info_tex), SAMPLER(info_sampler_tex)" in spelled
    assert "SampleInfo(info, _MainTex, sampler_MainTex, uv)" in spelled
    assert "info.tex" not in spelled and "info.st.xy" in spelled
    plain = "struct A { float4 x; };\nfloat4 f(A a) { return a.x; }\n"
    assert spelled_out(plain) == plain


def test_hlsl_typed_members_and_a_parameter_handed_on():
    text = ("struct T { Texture2D<float4> map; SamplerState ss; float k; };\n"
            "float4 F(T t, float2 uv) { return t.map.Sample(t.ss, uv) * t.k; }\n"
            "float4 G(T t) { return F(t, 0.5); }\n"
            "float4 H() { T t; t.map = _A; t.ss = sampler_A; t.k = 2; return G(t); }\n")
    spelled = spelled_out(text)
    assert spelled.count("\n") == text.count("\n")
    assert "struct T {" in spelled and "Texture2D" not in spelled.split("\n")[0]
    assert "float4 F(T t, Texture2D<float4> t_map, SamplerState t_ss, float2 uv)" in spelled
    assert "return t_map.Sample(t_ss, uv) * t.k;" in spelled
    assert "return F(t, t_map, t_ss, 0.5);" in spelled          # a parameter handed on
    assert "return G(t, _A, sampler_A);" in spelled and "t.k = 2;" in spelled
