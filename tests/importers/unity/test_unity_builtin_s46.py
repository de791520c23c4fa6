"""Session 46's differences between pbrlab and Unity in the built-in pipeline (and URP), each with
a minimal shader of tests/importers/unity/shaders/, rendered in both languages, its pixels
checked against a float64 value from Unity's documented formula, and a control:

1. Normal maps as Unity reads them on desktop: UnpackNormal / UnpackScaleNormal are UnityCG's
   desktop branch (UnpackNormalmapRGorAG: x = r * a, y = g, z rebuilt), and a file given for a
   ``[Normal]`` property is stored in DXT5nm's layout (1, y, 1, x) (importers/unity/normal_maps.py),
   so UnpackNormalDXT5nm (.wy) reads it. Control: the old RGB reading (xyz = rgb * 2 - 1).
2. A geometry stage's ``nointerpolation`` output links (flat on both sides of each stage pair)
   and is flat. Control: the same shader without ``nointerpolation`` interpolates.
3. A SubShader with only a Deferred pass draws its Fallback in the forward path; Fallback
   "Diffuse" is pbrlab's stand-in of Unity's legacy Lambert shader (importers/unity/shipped_shaders/).
   Control: a Fallback Unity ships that pbrlab has no stand-in for is still refused by name.
4. An unlit fixed-function pass in a URP SubShader draws (Unity converts it to a program; URP
   draws an untagged pass as SRPDefaultUnlit). Control: a Lighting On one is refused by name.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from pbrlab import scene
from pbrlab.foundation.errors import PbrlabError
from pbrlab.foundation.images import write_png
from pbrlab.maths.reference import unity_cg
from pbrlab.render import renderer as render

LANGUAGES = ("glsl", "hlsl")
SHADERS = Path(__file__).parent / "shaders"
SIZE = 32
# The sphere (radius 1 at 3.2, 40 degrees) covers the central 8 x 8 pixels whole: no edge, no
# multisample blend with the background there.
CENTRE = (slice(12, 20), slice(12, 20))
# Float32 evaluation of the unpack (a texel k / 255 or 0.5, a product, * 2 - 1, a dot, sqrt, * 0.5
# + 0.5: about 8 roundings of 2^-24 relative on values <= 1) into a 32-bit float target:
# 8 * 6e-8 = 5e-7, written 1e-6.
UNPACK_BOUND = 1e-6


def _render(shader: Path, language: str, properties: dict | None = None, lights=(), base=None):
    material = {"surface": str(shader), **({"properties": properties} if properties else {})}
    data = {"camera": {"position": [0, 0, 3.2], "target": [0, 0, 0], "fov_y_deg": 40, "size": [SIZE, SIZE]},
            "lights": list(lights), "materials": {"m": material},
            "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}]}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        image = render.render_scene(scene.parse_scene(data, "<test>", base or shader.parent), language=language).linear
    return np.asarray(image, np.float64)[..., :3]


def _fraction_within(image, expected, bound) -> float:
    """The fraction of the central pixels whose every channel lies within ``bound`` of ``expected``."""
    centre = image[CENTRE]
    return float(np.all(np.abs(centre - np.asarray(expected, np.float64)) <= bound, axis=-1).mean())


# --- 1. normal maps ---------------------------------------------------------------------------

GRAY = (0.5, 0.5, 0.5, 0.5)  # Unity's "gray" default texture (Properties block reference)


@pytest.mark.parametrize("language", LANGUAGES)
def test_unpack_scale_normal_is_unity_s_desktop_branch(language):
    """UnpackScaleNormal(gray, 0.5) = Unity's desktop (x = r * a = 0.25 -> -0.5, y = 0) * 0.5, z
    rebuilt; control: the RGB branch's (0, 0, 0) * 0.5 + 0.5 = 0.5 is not what renders."""
    image = _render(SHADERS / "normal_map_unpack.shader", language)
    expected = unity_cg.unpack_normal_with_scale(GRAY, 0.5) * 0.5 + 0.5
    assert _fraction_within(image, expected, UNPACK_BOUND) == 1.0
    rgb_branch = (np.asarray(GRAY[:3]) * 2 - 1) * np.array([0.5, 0.5, 1.0]) * 0.5 + 0.5
    assert _fraction_within(image, rgb_branch, 0.05) == 0.0


def _normal_png(folder: Path, rgb) -> Path:
    path = folder / "normal.png"
    write_png(path, np.tile(np.array((*rgb, 255), np.uint8), (4, 4, 1)))
    return path


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_normal_map_file_is_stored_as_dxt5nm(tmp_path, language):
    """A [Normal] property's file (x, y, z) = (200, 100, 230) / 255 reads through UnpackNormalDXT5nm
    (.wy) as x = 200/255 * 2 - 1, y = 100/255 * 2 - 1, and its raw texel is (1, y, 1), DXT5nm's
    layout. Control: the plain RGB upload (alpha 1) gives UnpackNormalDXT5nm x = 1."""
    shader = tmp_path / "normal_map_dxt5nm.shader"
    shader.write_text((SHADERS / "normal_map_dxt5nm.shader").read_text())
    png = _normal_png(tmp_path, (200, 100, 230))
    stored = np.array([1.0, 100 / 255, 1.0, 200 / 255])  # (1, y, 1, x)
    image = _render(shader, language, {"_NormalMap": {"path": png.name}})
    expected = unity_cg.unpack_normal_dxt5nm(stored) * 0.5 + 0.5
    assert _fraction_within(image, expected, UNPACK_BOUND) == 1.0
    plain = np.array([200 / 255, 100 / 255, 230 / 255, 1.0])
    assert _fraction_within(image, unity_cg.unpack_normal_dxt5nm(plain) * 0.5 + 0.5, 0.05) == 0.0
    raw = _render(shader, language, {"_NormalMap": {"path": png.name}, "_Raw": 1.0})
    assert _fraction_within(raw, stored[:3], UNPACK_BOUND) == 1.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_texture_the_shader_unpacks_is_a_normal_map(tmp_path, language):
    """Without [Normal] and with a "white" default, a texture the shader's file hands to
    UnpackNormalDXT5nm(tex2D(...)) is a normal map too: its file is stored as DXT5nm. Control:
    read through a variable first (no unpack of a tex2D in the file), it stays plain RGBA."""
    text = (SHADERS / "normal_map_dxt5nm.shader").read_text().replace(
        '[Normal] _NormalMap ("Normal map", 2D) = "bump" {}', '_NormalMap ("Normal map", 2D) = "white" {}')
    png = _normal_png(tmp_path, (200, 100, 230))
    unpacked = tmp_path / "unpacked.shader"
    unpacked.write_text(text.replace("UnpackNormalDXT5nm(packed)", "UnpackNormalDXT5nm(tex2D(_NormalMap, i.uv))"))
    image = _render(unpacked, language, {"_NormalMap": {"path": png.name}})
    stored = np.array([1.0, 100 / 255, 1.0, 200 / 255])
    assert _fraction_within(image, unity_cg.unpack_normal_dxt5nm(stored) * 0.5 + 0.5, UNPACK_BOUND) == 1.0
    plain = tmp_path / "plain.shader"
    plain.write_text(text)
    image = _render(plain, language, {"_NormalMap": {"path": png.name, "srgb": False}})
    rgba = np.array([200 / 255, 100 / 255, 230 / 255, 1.0])
    assert _fraction_within(image, unity_cg.unpack_normal_dxt5nm(rgba) * 0.5 + 0.5, UNPACK_BOUND) == 1.0


@pytest.mark.parametrize("language", LANGUAGES)
def test_the_default_bump_binds_as_its_rgba(language):
    """The default "bump" (0.5, 0.5, 1, 1) binds as its RGBA (a global texture, not an imported
    normal map): UnpackNormalDXT5nm reads its alpha 1 as x = 1, as Unity's .wy does."""
    image = _render(SHADERS / "normal_map_dxt5nm.shader", language)
    expected = unity_cg.unpack_normal_dxt5nm((0.5, 0.5, 1.0, 1.0)) * 0.5 + 0.5
    assert _fraction_within(image, expected, UNPACK_BOUND) == 1.0


# --- 2. a geometry stage's nointerpolation output ---------------------------------------------

@pytest.mark.parametrize("language", LANGUAGES)
def test_a_geometry_stage_s_nointerpolation_output_links_and_is_flat(tmp_path, language):
    """Every central pixel is the flat 0.75 (exact: no interpolation); control: without
    nointerpolation, the same shader's pixels are interpolated below 0.75."""
    text = (SHADERS / "geometry_nointerpolation.shader").read_text()
    image = _render(SHADERS / "geometry_nointerpolation.shader", language)
    assert _fraction_within(image, (0.75, 0.5, 0.125), 0.0) == 1.0
    plain = tmp_path / "geometry_interpolated.shader"
    plain.write_text(text.replace("nointerpolation float value", "float value"))
    smooth = _render(plain, language)
    assert _fraction_within(smooth, (0.75, 0.5, 0.125), 1e-3) < 0.5


# --- 3. a Deferred-only SubShader draws its Fallback -------------------------------------------

# The scene's one light: white, directional; Lambert is linear in the albedo
_SUN = {"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0}
# Float32 shading (the albedo product, N.L, the SH ambient, a sum: about 6 roundings of 2^-24
# relative) in each of two renders, then a float64 ratio: 2 * 6 * 6e-8 = 7e-7, written 1e-6.
RATIO_BOUND = 1e-6


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_deferred_only_subshader_draws_its_diffuse_fallback(tmp_path, language):
    """Fallback "Diffuse" (Unity's legacy Lambert: texture x Main Color) draws: each channel of a
    render with _Color (0.25, 0.5, 1) over one with white is that channel of _Color (Lambert's
    diffuse and ambient terms are the albedo times light), and the pixels are lit (> 0)."""
    shader = SHADERS / "deferred_only_diffuse.shader"
    white = _render(shader, language, lights=[_SUN])
    tinted = _render(shader, language, {"_Color": [0.25, 0.5, 1.0, 1.0]}, lights=[_SUN])
    centre_white, centre_tinted = white[CENTRE], tinted[CENTRE]
    assert (centre_white > 1e-3).all()
    ratio = centre_tinted / centre_white
    assert float(np.all(np.abs(ratio - [0.25, 0.5, 1.0]) <= RATIO_BOUND, axis=-1).mean()) == 1.0
    # control: a shipped Fallback without a stand-in is still refused, naming it
    other = tmp_path / "deferred_only_specular.shader"
    other.write_text(shader.read_text().replace('Fallback "Diffuse"', 'Fallback "Specular"'))
    with pytest.raises(PbrlabError) as refused:
        _render(other, language)
    assert 'its Fallback "Specular" is one of the shaders Unity ships with the editor' in str(refused.value)
    # and the stand-in hides no mistake: a SubShader pbrlab cannot read keeps its own refusal
    broken = tmp_path / "broken_diffuse.shader"
    broken.write_text(shader.read_text().replace('Tags { "LightMode" = "Deferred" }', "").replace(
        "float4 frag() : SV_Target { return float4(1.0, 0.0, 0.0, 1.0); }",
        "float4 frag() : SV_Target { return undeclared_name; }"))
    with pytest.raises(PbrlabError) as refused:
        _render(broken, language)
    assert "undeclared_name" in str(refused.value)


# --- 4. an unlit fixed-function pass in URP ----------------------------------------------------

@pytest.mark.parametrize("language", LANGUAGES)
def test_an_unlit_fixed_function_pass_draws_in_urp(tmp_path, language):
    """Color [_Color] then SetTexture [_MainTex] { combine texture * primary DOUBLE } over the gray
    default: 2 * 0.5 * _Color = _Color (0.25, 0.5, 0.75), exact. Control: the same pass with
    Lighting On is refused naming the command's line and the vertex lights URP does not give it."""
    shader = SHADERS / "fixed_function_urp.shader"
    image = _render(shader, language)
    expected = np.minimum(2.0 * 0.5 * np.array([0.25, 0.5, 0.75]), 1.0)
    assert _fraction_within(image, expected, 0.0) == 1.0
    lit = tmp_path / "fixed_function_urp_lit.shader"
    text = shader.read_text().replace("Color [_Color]", "Material { Diffuse [_Color] }\n            Lighting On")
    lit.write_text(text)
    line = text.split("\n").index("            Lighting On") + 1
    with pytest.raises(PbrlabError) as refused:
        _render(lit, language)
    assert f"{lit}:{line}: a fixed-function Pass with Lighting On" in str(refused.value)
