"""A struct-typed member inside the vertex stage's output struct (s47-stages, issue 34):
``struct Inner { float2 uv; float tint; }; struct v2f { ...; Inner inner : TEXCOORD0; }`` (built-in)
and ``struct Inner { float2 uv : TEXCOORD3; float tint : TEXCOORD5; }; struct Varyings { ...;
Inner inner; }`` (URP). Each leaf passes as a varying of its own (parse_pass._leaves). Before
the change both were refused ("Inner cannot pass between the stages here"); the render tests then
fail.

The shaders place the plane's corners (x, z) / 0.3 at NDC (x / 0.3, -z / 0.3): the plane fills
the 64 x 64 image and its uv is the linear function u = (X + 1) / 2, v = (Y + 1) / 2 of a pixel
centre's NDC (X, Y) (scene/primitives.plane: uv (0, 1) at (x, z) = (-0.3, -0.3)). The fragment
writes (inner.uv, inner.tint). Tolerance: the interpolation of values <= 1 in float32, a few ulp
(2^-22 each): 1e-6.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity.parse_pass import _structs
from pbrlab.render.renderer import render_scene

HERE = Path(__file__).parent
SHADERS = {"builtin": HERE / "shaders/s47-stages/struct_varying.shader",
           "urp": HERE.parent / "urp/shaders/s47-stages/urp_struct_varying.shader"}


def _render(tmp_path, language, which):
    shader = tmp_path / f"{which}.shader"
    shader.write_text(SHADERS[which].read_text())
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    return render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)


@pytest.mark.parametrize("which", ["builtin", "urp"])
@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_struct_member_passes_between_the_stages(tmp_path, language, which):
    image = _render(tmp_path, language, which)
    h, w = image.shape[:2]
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    expected = np.stack([(X + 1) / 2, (Y + 1) / 2, np.full_like(X, 0.25)], axis=-1)
    assert (image[..., 3] > 0).all()
    assert np.abs(image[..., :3] - expected).max() <= 1e-6
    # control: the uv is not constant (a member left 0 or unlinked would be)
    assert image[..., 0].max() - image[..., 0].min() > 0.9


def test_the_leaves_take_the_members_semantic_or_their_own():
    structs = _structs("struct In { float2 uv : TEXCOORD7; nointerpolation int k : TEXCOORD6; };\n"
                       "struct Deep { In a; float3 n : NORMAL; };\n"
                       "struct V { float4 p : SV_POSITION; In i : TEXCOORD2; Deep d; };\n")
    assert structs["V"].members == [("float4", "p", "SV_POSITION"), ("float2", "i.uv", "TEXCOORD2"),
                                    ("int", "i.k", "TEXCOORD3"), ("float2", "d.a.uv", "TEXCOORD7"),
                                    ("int", "d.a.k", "TEXCOORD6"), ("float3", "d.n", "NORMAL")]
    assert structs["V"].flat == {"i.k", "d.a.k"}


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_struct_member_reaches_a_geometry_stage(tmp_path, language):
    """shaders/s47-stages/struct_varying_geometry.shader: the point-input billboard of
    test_s47_stages_point_geometry.py with its uv in ``v2g.inner`` (a struct member at TEXCOORD0):
    the one square, around corner 0 at NDC (-0.6, 0.6), is coloured (corner 0's uv, 0.5) =
    (0, 1, 0.5) exactly. In HLSL spirv-cross names the leaf ``IN_inner_uv`` (before it was not
    linked: "cannot link the geometry stage's IN_inner_uv"); control: the pixels beside the
    square stay empty."""
    shader = tmp_path / "geometry.shader"
    shader.write_text((HERE / "shaders/s47-stages/struct_varying_geometry.shader").read_text())
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    h, w = image.shape[:2]
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    d = 0.02 * 2 / w  # (pixel centres this close to the square's edge may fall either way)
    inner = (np.abs(X + 0.6) <= 0.1 - d) & (np.abs(Y - 0.6) <= 0.1 - d)
    outer = (np.abs(X + 0.6) <= 0.1 + d) & (np.abs(Y - 0.6) <= 0.1 + d)
    assert inner.sum() > 20 and not (image[..., 3] > 0)[~outer].any()
    assert np.array_equal(image[inner][:, :3], np.tile([0.0, 1.0, 0.5], (int(inner.sum()), 1)))


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_struct_member_passes_through_tessellation(tmp_path, language):
    """shaders/s47-stages/struct_varying_tessellation.shader: the control points and the domain
    output carry ``In inner : TEXCOORD0``; the flat patches (BULGE 0) cover |X|, |Y| <= 0.6 and
    the interpolated uv is linear there: x = X / 2, z = -Y / 2 (clip = 0.6 (x, -z) / 0.3), so
    u = (X / 2 + 0.3) / 0.6, v = (Y / 2 + 0.3) / 0.6. In HLSL glslang wrote the leaf of the
    hull's output at a constant index (GLSL refused it: "outputs can only be indexed by
    gl_InvocationID"; tessellation_stage.hlsl_renamed). Tolerance: float32 interpolation, 1e-6.
    Control: the uv varies across the square (a leaf left 0 would not)."""
    shader = tmp_path / "tessellated.shader"
    shader.write_text((HERE / "shaders/s47-stages/struct_varying_tessellation.shader").read_text())
    data = corpus.scene_for(shader)
    data["objects"] = [{"mesh": {"primitive": "plane", "size": 0.6}, "material": "m"}]
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    h, w = image.shape[:2]
    X, Y = np.meshgrid((np.arange(w) + 0.5) / w * 2 - 1, 1 - (np.arange(h) + 0.5) / h * 2)
    inside = (np.abs(X) <= 0.6 - 0.02 * 2 / w) & (np.abs(Y) <= 0.6 - 0.02 * 2 / w)
    want = np.stack([(X / 2 + 0.3) / 0.6, (Y / 2 + 0.3) / 0.6], axis=-1)
    assert inside.sum() > 1000 and (image[..., 3] > 0)[inside].all()
    assert np.abs(image[inside][:, :2] - want[inside]).max() <= 1e-6
    assert np.ptp(image[inside][:, 0]) > 0.9
