"""pbrlab's stand-ins for the Unity include files shaders define parts of themselves with
(harness/pbrlab/importers/unity/cginc/), run through Unity's own built-in shaders (corpus/unity/
builtin-2019.4): each shows what Unity's include makes it show, computed here in numpy.

* TerrainSplatmapCommon.cginc: Nature/Terrain/Diffuse (Splats/FirstPass.shader) mixes its
  four layers by the control map: the render equals a plain Lambert surface whose albedo is
  the numpy mix sum_i w_i c_i / (W + 1e-3), weighted back by W = sum_i w_i (SplatmapFinalColor).
* UnitySprites.cginc: Sprites/Diffuse tints by _Color (the render scales channel by channel)
  and mirrors by _Flip (flip x = -1 draws the image mirrored left-right).
* UnityUI.cginc: UnityGet2DClipping with the UNITY_UI_CLIP_RECT keyword (enabled by the
  material's `keywords`, as the canvas enables it in Unity) gives alpha 0 outside _ClipRect
  and leaves it alone inside; without the keyword (Unity's default variant) nothing is clipped.
* SpeedTree*.cginc: refused at the shader's #include line, with one message.
Both languages each: HLSL (the shader as written) and GLSL (its port, the includes ported too).
"""

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.images import write_png
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene
from pbrlab.foundation.errors import PbrlabError

BUILTIN = Path(__file__).resolve().parents[3] / "corpus" / "unity" / "builtin-2019.4" / "DefaultResourcesExtra"
LANGUAGES = ("hlsl", "glsl")
SIZE = (48, 48)

# Shading is linear in the albedo in both renders compared below, which run the same
# Lambert and differ in how the albedo is formed: float32 rounding of the mix and of 8-bit
# texels decoded by the GPU (exactly k/255 for linear textures). Measured on llvmpipe, both
# languages: worst 1.2e-7 absolute (terrain, weights summing to 1), 7.5e-8 (summing to 0.4),
# 0 (sprite tint); 1e-5 absolute (1/30 of the smallest sRGB
# step at mid-grey) leaves room for another rasteriser's fused multiply-adds, not for a wrong
# weight (the smallest weight here, 0.125 of a 0.2 texel, moves a pixel by >1e-2).
ATOL = 1e-5


def _constant_png(path: Path, rgba) -> dict:
    """A 4x4 PNG of one linear colour (k/255 each, exact), bound without sRGB decoding."""
    codes = np.round(np.asarray(rgba, np.float64) * 255).astype(np.uint8)
    write_png(path, np.broadcast_to(codes, (4, 4, 4)).copy())
    return {"path": str(path), "srgb": False}


def _scene(surface, properties=None, keywords=None, mesh=None, transform=None, environment=True):
    material = {"surface": str(surface), "properties": properties or {}}
    if keywords is not None:
        material["keywords"] = keywords
    obj = {"mesh": mesh or {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}
    if transform:
        obj["transform"] = transform
    scene = {
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": list(SIZE)},
        "lights": [{"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0}],
        "materials": {"m": material},
        "objects": [obj],
        "render": {"quality": "high", "tonemap": "none"},
    }
    if environment:
        scene["environment"] = {"color": [0.2, 0.25, 0.3]}
    return scene


def _render(scene, ctx, language, base):
    with _quiet():
        return render_scene(parse_scene(scene, origin="test scene", base=base), ctx, language=language).linear.astype(np.float64)


class _quiet:
    """Unity's notes and warnings (SubShader chosen, options with no effect) are not under test."""

    def __enter__(self):
        import warnings
        self._catch = warnings.catch_warnings()
        self._catch.__enter__()
        warnings.simplefilter("ignore")

    def __exit__(self, *exc):
        return self._catch.__exit__(*exc)


LAMBERT = """Shader "Test/PlainLambert" {
    Properties { _Color ("Albedo", Color) = (1, 1, 1, 1) }
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert
        fixed4 _Color;
        struct Input { float2 uv_MainTex; };
        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = _Color.rgb; o.Alpha = 1.0; }
        ENDCG
    }
}
"""

# Four layer colours and two control texels (weights sum to 1, and to 0.4 where the final
# colour's weighting by W shows), k/255 each.
LAYERS = np.array([[204, 51, 25], [25, 178, 51], [51, 76, 229], [229, 204, 102]]) / 255.0
CONTROLS = {"sum_one": np.array([128, 64, 32, 31]) / 255.0, "sum_0.4": np.array([51, 25, 13, 13]) / 255.0}


@pytest.mark.parametrize("control", sorted(CONTROLS))
@pytest.mark.parametrize("language", LANGUAGES)
def test_terrain_splat_mixes_layers_by_the_control_map(control, language, gl_context, tmp_path):
    w = CONTROLS[control]
    props = {"_Control": _constant_png(tmp_path / "control.png", w)}
    for i, c in enumerate(LAYERS):
        props[f"_Splat{i}"] = _constant_png(tmp_path / f"splat{i}.png", [*c, 1.0])
    terrain = _render(_scene(BUILTIN / "TerrainShaders/Splats/FirstPass.shader", props), gl_context, language, tmp_path)
    # Unity's mix: weights normalised by their sum W (+1e-3), layers summed, then the lit colour
    # times W (SplatmapFinalColor); Lambert is linear in the albedo, so that is the albedo below.
    weight = w.sum()
    albedo = (w[:, None] * LAYERS).sum(axis=0) / (weight + 1e-3) * weight
    shader = tmp_path / "lambert.shader"
    shader.write_text(LAMBERT)
    plain = _render(_scene(shader, {"_Color": [*albedo, 1.0]}), gl_context, language, tmp_path)
    covered = terrain[..., 3] > 0
    assert covered.mean() > 0.3 and np.array_equal(covered, plain[..., 3] > 0)
    err = np.abs(terrain - plain)[covered][:, :3]
    assert err.max() <= ATOL, err.max()
    assert terrain[covered][:, :3].max() > 0.1  # lit, not black


@pytest.mark.parametrize("language", LANGUAGES)
def test_sprite_color_tints_channel_by_channel(language, gl_context, tmp_path):
    sprite = BUILTIN / "Sprites-Diffuse.shader"
    tint = np.array([1.0, 0.5, 0.25])
    white = _render(_scene(sprite, {"_Color": [1, 1, 1, 1]}), gl_context, language, tmp_path)
    tinted = _render(_scene(sprite, {"_Color": [*tint, 1.0]}), gl_context, language, tmp_path)
    covered = white[..., 3] > 0
    assert covered.mean() > 0.3
    # Sprites/Diffuse: vertex colour x _Color x _RendererColor into Albedo (x alpha 1); Lambert
    err = np.abs(tinted[..., :3] - white[..., :3] * tint)[covered]
    assert err.max() <= ATOL, err.max()
    assert white[covered][:, 0].max() > 0.1


@pytest.mark.parametrize("language", LANGUAGES)
def test_sprite_flip_mirrors_the_sprite(language, gl_context, tmp_path):
    # A quad facing the camera (the plane primitive turned from +Y to +Z) with a texture dark on
    # its left, bright on its right; _Flip (-1, 1) mirrors the vertices in x (UnityFlipSprite).
    ramp = np.zeros((4, 8, 4), np.uint8)
    ramp[..., 3] = 255
    ramp[:, :, 0] = np.linspace(20, 240, 8).astype(np.uint8)[None, :]
    write_png(tmp_path / "ramp.png", ramp)
    sprite = BUILTIN / "Sprites-Diffuse.shader"
    quad = {"primitive": "plane", "size": 1.6}
    turn = {"rotate_deg": [90, 0, 0]}
    props = {"_MainTex": {"path": str(tmp_path / "ramp.png"), "srgb": False}}
    images = {flip: _render(_scene(sprite, {**props, "_Flip": [flip, 1, 1, 1]}, mesh=quad, transform=turn,
                                   environment=False), gl_context, language, tmp_path)
              for flip in (1.0, -1.0)}
    straight, flipped = images[1.0], images[-1.0]
    covered = straight[..., 3] > 0
    assert covered.mean() > 0.2 and np.array_equal(covered, covered[:, ::-1])
    # the quad's normal faces the camera either way, so the mirrored render is the image mirrored
    # (a directional light: the same shading at every pixel of the flat quad)
    mirrored = straight[:, ::-1]
    err = np.abs(flipped - mirrored)[covered][:, :3]
    assert err.max() <= 1e-3, err.max()  # texel filtering at mirrored UVs (bilinear, 8 texels)
    row = straight[SIZE[1] // 2, covered[SIZE[1] // 2], 0]
    half = len(row) // 2
    assert row[half:].mean() > 2 * row[:half].mean()  # the ramp runs left to right before the flip


UI_CLIP = """Shader "Test/UIClip" {
    Properties { _ClipRect ("Clip Rect", Vector) = (-100, -100, 100, 100) }
    SubShader {
        Tags { "Queue" = "Transparent" }
        CGPROGRAM
        #pragma surface surf Lambert alpha
        #include "UnityUI.cginc"
        #pragma multi_compile_local _ UNITY_UI_CLIP_RECT
        float4 _ClipRect;
        struct Input { float3 worldPos; };
        void surf (Input IN, inout SurfaceOutput o) {
            o.Albedo = fixed3(0.8, 0.8, 0.8);
            o.Alpha = 1.0;
            #ifdef UNITY_UI_CLIP_RECT
            o.Alpha *= UnityGet2DClipping(IN.worldPos.xy, _ClipRect);
            #endif
        }
        ENDCG
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
def test_ui_clip_rect_clips_outside_the_rect(language, gl_context, tmp_path):
    # Written as UI-Default / UI-Lit-* use UnityUI.cginc (their own vertex stages need UnityCG's
    # stereo macros, outside this file): alpha times UnityGet2DClipping under UNITY_UI_CLIP_RECT.
    shader = tmp_path / "ui_clip.shader"
    shader.write_text(UI_CLIP)
    rect = [0.0, -0.5, 10.0, 10.0]  # x >= 0 and y >= -0.5 (world units; the unit sphere at 0)
    clipped = _render(_scene(shader, {"_ClipRect": rect}, keywords=["UNITY_UI_CLIP_RECT"]), gl_context,
                      language, tmp_path)
    unclipped = _render(_scene(shader, {"_ClipRect": rect}), gl_context, language, tmp_path)
    # world x, y of each pixel's front hit on the unit sphere, in numpy (camera at z = 3.2, 40 deg)
    h, w = SIZE[1], SIZE[0]
    t = np.tan(np.radians(40) / 2)
    px = ((np.arange(w) + 0.5) / w * 2 - 1) * t * w / h
    py = (1 - (np.arange(h) + 0.5) / h * 2) * t
    d = np.stack(np.broadcast_arrays(px[None, :], py[:, None], -np.ones((h, w))), -1)
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    o = np.array([0.0, 0.0, 3.2])
    b = d @ o
    disc = b * b - (o @ o - 1.0)
    hit = disc > 0
    dist = -b - np.sqrt(np.maximum(disc, 0))
    p = o + dist[..., None] * d
    inside = (p[..., 0] >= rect[0]) & (p[..., 1] >= rect[1])
    # away from the rect's edges and the silhouette by 1.5 px (pixel footprint at the sphere)
    margin = 1.5 * 2 * t * 3.2 / h
    clear = (np.abs(p[..., 0] - rect[0]) > margin) & (np.abs(p[..., 1] - rect[1]) > margin) & (disc > 0.05)
    assert clear.sum() > 200
    assert np.all(unclipped[..., 3][hit & clear] > 0.99)           # the default variant clips nothing
    assert np.all(clipped[..., 3][hit & clear & inside] > 0.99)     # inside: alpha as it was
    assert np.all(clipped[..., 3][hit & clear & ~inside] == 0.0)    # outside: alpha 0, nothing drawn
    assert np.all(clipped[..., :3][hit & clear & ~inside] == 0.0)


def test_a_keyword_the_shader_does_not_declare_is_an_error(tmp_path):
    shader = tmp_path / "ui_clip.shader"
    shader.write_text(UI_CLIP)
    with pytest.raises(PbrlabError, match=r"'UNITY_UI_CLIPRECT' is not a keyword of .*declare: UNITY_UI_CLIP_RECT"):
        parse_scene(_scene(shader, keywords=["UNITY_UI_CLIPRECT"]), origin="test scene", base=tmp_path)


@pytest.mark.parametrize("name", ["SpeedTree.shader", "SpeedTree8.shader", "SpeedTreeBillboard.shader"])
def test_speedtree_is_refused_at_its_include_line(name, tmp_path):
    path = BUILTIN / "Nature" / name
    with pytest.raises(PbrlabError) as caught:
        with _quiet():
            parse_scene(_scene(path), origin="test scene", base=tmp_path)
    message = str(caught.value)
    lines = [i + 1 for i, line in enumerate(path.read_text().splitlines()) if '#include "SpeedTree' in line]
    assert f"{path}:{lines[0]}: #include \"SpeedTree" in message, message
    assert message.endswith("SpeedTree shaders need SpeedTree's wind and billboard data, which pbrlab does not have")
    assert message.count("SpeedTree shaders need") == 1  # one message, not one per SubShader
