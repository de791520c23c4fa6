"""`pbrlab render X.shader`: a lone Unity shader is drawn on the default sphere
(pbrlab.importers.shader_preview), and a file that is no scene gets a one-line message saying
what is one, not the JSON parser's "Expecting value".

The reference is computed here in float64 from the preview scene's documented set-up (camera,
light, environment), not by the renderer: per pixel, the ray through the pixel's centre, its
hit on the unit sphere, and Unity's Lambert, albedo * (max(0, n.l) * intensity + the constant
environment's irradiance / pi), the light's unit convention making a white surface facing an
intensity-1 light exactly 1 (docs/conventions.md)."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.commands import cli
from pbrlab.foundation.images import read_image
from pbrlab.importers.shader_preview import PREVIEW_SCENE

RED_LAMBERT = """Shader "Test/Red" {
    Properties { _Color ("Color", Color) = (1, 0, 0, 1) }
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert
        struct Input { float4 color : COLOR; };
        fixed4 _Color;
        void surf (Input IN, inout SurfaceOutput o) { o.Albedo = _Color.rgb; }
        ENDCG
    }
}
"""
ALBEDO = np.array([1.0, 0.0, 0.0])  # the shader's _Color default

# Per-pixel bound on |rendered - reference| radiance: the chain from a pixel's ray to its
# radiance (ray-sphere hit, normalize, n.l, the order-2 SH irradiance's 9 terms, the sum) is
# under 100 float32 roundings of values <= 1, each <= 2^-24 relative: 100 * 2^-24 = 6e-6,
# bounded here by 2^-16 = 1.5e-5 (the chain's near-silhouette sqrt doubles some errors).
# Measured (llvmpipe, Mesa 25): largest 2.7e-6 over 34528 covered pixels.
RADIANCE_BOUND = 2.0 ** -16
# Pixels allowed over the bound: none (the sphere is analytic, drawn per pixel).
FRACTION_ALLOWED = 0.0
# Coverage may differ from the float64 ray test only where the ray grazes the sphere: the
# discriminant b^2 - c below float32's resolution of c = |o|^2 - 1 = 15 (2^-20 * 16).
GRAZING_DISCRIMINANT = 2.0 ** -16


def reference(size: tuple[int, int], albedo) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(radiance HxWx3, covered HxW, grazing HxW) of the preview scene, in float64."""
    camera, light = PREVIEW_SCENE["camera"], PREVIEW_SCENE["lights"][0]
    sphere = PREVIEW_SCENE["objects"][0]["sphere"]
    width, height = size
    eye, target = np.array(camera["position"], float), np.array(camera["target"], float)
    assert np.allclose(target - eye, [0, 0, -np.linalg.norm(target - eye)]), "the reference assumes a view along -Z"
    half = np.tan(np.radians(camera["fov_y_deg"]) / 2)
    row, col = np.mgrid[0:height, 0:width]
    x = ((col + 0.5) / width * 2 - 1) * half * width / height
    y = (1 - (row + 0.5) / height * 2) * half
    rays = np.stack([x, y, -np.ones_like(x)], -1)
    rays /= np.linalg.norm(rays, axis=-1, keepdims=True)
    origin = eye - np.array(sphere["center"], float)
    b = rays @ origin
    disc = b * b - (origin @ origin - sphere["radius"] ** 2)
    covered = disc > 0
    normal = (origin + (-b - np.sqrt(np.maximum(disc, 0)))[..., None] * rays) / sphere["radius"]
    to_light = -np.array(light["direction"], float) / np.linalg.norm(light["direction"])
    ambient = np.array(PREVIEW_SCENE["environment"]["color"], float)  # a constant L lights Lambert to L
    irradiance = np.maximum(normal @ to_light, 0)[..., None] * light["intensity"] * np.array(light["color"]) + ambient
    radiance = np.where(covered[..., None], irradiance * np.asarray(albedo, float), 0.0)
    return radiance, covered, np.abs(disc) < GRAZING_DISCRIMINANT


def fraction_off(linear: np.ndarray, albedo) -> tuple[float, int]:
    """(fraction of covered pixels over RADIANCE_BOUND, pixels whose coverage differs away from
    the silhouette) of a render of the preview scene against the reference for ``albedo``."""
    height, width = linear.shape[:2]
    expected, covered, grazing = reference((width, height), albedo)
    drawn = linear[..., 3] > 0
    coverage_wrong = int((drawn != covered)[~grazing].sum())
    both = drawn & covered
    over = (np.abs(linear[..., :3] - expected) > RADIANCE_BOUND).any(axis=-1)[both]
    return float(over.mean()), coverage_wrong


@pytest.fixture(scope="module")
def red_render(tmp_path_factory):
    folder = tmp_path_factory.mktemp("lone_shader")
    (folder / "red.shader").write_text(RED_LAMBERT)
    exr, png = folder / "red.exr", folder / "red.png"
    assert cli.main(["render", str(folder / "red.shader"), "--hdr", str(exr), "-o", str(png)]) == 0
    return read_image(exr), read_image(png)


def test_a_lone_unity_shader_renders_on_the_default_sphere(red_render):
    linear, srgb = red_render
    assert linear.shape[:2] == tuple(reversed(PREVIEW_SCENE["camera"]["size"]))
    fraction, coverage_wrong = fraction_off(linear, ALBEDO)
    assert coverage_wrong == 0
    assert fraction <= FRACTION_ALLOWED, f"{fraction:.2%} of the sphere's pixels off by more than {RADIANCE_BOUND}"
    # The colour content as the PNG shows it: red only on the sphere's disc, about half the frame
    # (pi * 104.8^2 / 256^2 = 0.527, from its angular radius asin(1/4) in a 35 degree view),
    # black around it.
    covered = linear[..., 3] > 0
    assert abs(covered.mean() - 0.527) < 0.005
    assert srgb[covered][:, 1:3].max() == 0 and srgb[covered][:, 0].min() > 0
    assert srgb[~covered][:, :3].max() == 0


def test_the_reference_tells_a_wrong_colour_apart(red_render):
    """Control: the same render against a 10 % darker albedo, or a green one, fails the check."""
    linear, _ = red_render
    assert fraction_off(linear, 0.9 * ALBEDO)[0] > 0.99
    assert fraction_off(linear, [0.0, 1.0, 0.0])[0] > 0.99


@pytest.mark.parametrize("name, text", [("surface.glsl", "void surf(Input IN, inout SurfaceOutputStandard o) {}\n"),
                                        ("image.png", "\x89PNG\r\n")])
def test_a_file_that_is_no_scene_says_what_is_one(tmp_path, capsys, name, text):
    path = tmp_path / name
    path.write_text(text, encoding="latin-1")
    assert cli.main(["render", str(path), "-o", str(tmp_path / "out.png")]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert f"{path}: not a scene file" in err and ".shader" in err and '"surface"' in err
    assert "Expecting value" not in err


def test_render_help_says_a_shader_is_drawn_on_the_default_sphere(capsys):
    with pytest.raises(SystemExit):
        cli.main(["render", "--help"])
    assert "Unity .shader" in capsys.readouterr().out
