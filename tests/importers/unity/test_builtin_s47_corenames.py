"""UnityCG.cginc's UNITY_SHOULD_SAMPLE_SH and the engine's LIGHTPROBE_SH keyword (issue 34,
session 47, s47-corenames): built-in passes copied from a surface shader's generated code test
``#if UNITY_SHOULD_SAMPLE_SH`` before adding the ambient probe's SH.

UnityCG.cginc (Unity 2017 to 2022) defines it as ``defined(LIGHTPROBE_SH)`` and none of
UNITY_PASS_FORWARDADD / PREPASSBASE / SHADOWCASTER / META; Unity's engine enables LIGHTPROBE_SH in
the ForwardBase variant of an object without a lightmap, where the program has that variant
(``multi_compile_fwdbase`` or its own keyword line): light_probes.py. The minimal pass
(shaders/s47-corenames/should_sample_sh.shader) returns ShadeSH9 along +y where it holds, else
magenta. Scene: a unit UV sphere under the sky environment, no lights; every covered pixel is
checked in both languages.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.locations import locate
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity import light_probes, lightmaps, dynamic_lightmaps
from pbrlab.importers.unity.parse import BUILTIN
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
SHADER = (Path(__file__).parent / "shaders" / "s47-corenames" / "should_sample_sh.shader").read_text()
MAGENTA = np.array([1.0, 0.0, 1.0])
# The SH coefficients reach the GPU as float32 and ShadeSH9 sums 9 products: 32 float32 ulps
# (2^-24 relative each) of a value below 1 bound it (the URP ambient tests' bound).
SH_BOUND = 32 * 2.0 ** -24


def _render(tmp_path, language, pragmas):
    shader = tmp_path / "s.shader"
    shader.write_text(SHADER % {"pragmas": pragmas})
    data = {
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [48, 48]},
        "lights": [],
        "environment": {"path": str(locate("scenes") / "assets" / "sky.exr"), "intensity": 0.5},
        "materials": {"m": {"surface": str(shader)}},
        "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}],
    }
    scene = parse_scene(data, origin="s47 should-sample-SH scene", base=tmp_path)
    image = render_scene(scene, language=language).linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 200
    return image[covered, :3], scene


def _sh_from_above(scene) -> np.ndarray:
    """ShadeSH9(+y): the scene environment's SH9 irradiance along +y over pi, clamped at 0
    (pbrlab's PBR_UNITY_SH_IRRADIANCE, as the URP ambient tests compute unity_AmbientSky)."""
    from pbrlab.maths.reference.lighting import sh9_irradiance
    from pbrlab.scene.environment import environment_sh
    sh = environment_sh(scene.environment)
    return np.maximum(sh9_irradiance(sh, np.array([[0.0, 1.0, 0.0]])), 0.0)[0] / np.pi


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("pragmas", ["#pragma multi_compile_fwdbase", "#pragma multi_compile _ LIGHTPROBE_SH"])
def test_a_forward_base_variant_samples_sh(tmp_path, language, pragmas):
    """A ForwardBase pass that has a LIGHTPROBE_SH variant, drawn for an object with no lightmap:
    UNITY_SHOULD_SAMPLE_SH holds and the pixel is the float64 ShadeSH9(+y) within SH_BOUND.
    Control: the same pass without such a variant (no pragma: LIGHTPROBE_SH never on in Unity)
    and one that defines UNITY_PASS_FORWARDADD draw magenta, which differs from the SH by far
    more than the bound."""
    pixels, scene = _render(tmp_path, language, pragmas)
    expected = _sh_from_above(scene)
    assert 0.01 < expected.min() and np.abs(expected - MAGENTA).max() > 100 * SH_BOUND
    assert np.abs(pixels - expected).max() <= SH_BOUND, (pixels[0], expected)
    for control in ("", f"{pragmas}\n#define UNITY_PASS_FORWARDADD"):
        off, _ = _render(tmp_path, language, control)
        assert np.abs(off - MAGENTA).max() == 0.0, (control, off[0])


def test_light_probe_sh_is_the_variant_of_an_object_without_a_lightmap():
    """LIGHTPROBE_SH is on for a vertex/fragment program that declares it and an object with no
    supplied lightmap; an object with a lightmap or a realtime GI lightmap draws the LIGHTMAP_ON /
    DYNAMICLIGHTMAP_ON variant instead (the pipelines lightmaps.lightmapped and
    dynamic_lightmaps.realtime_lit make drop it). Control: a program declaring neither the keyword
    nor multi_compile_fwdbase gets nothing."""
    class Pass:
        kind = "vertex-fragment"
        program = "#pragma multi_compile_fwdbase\n"
    assert light_probes.program_defines(Pass()) == {"LIGHTPROBE_SH": 1}
    assert light_probes.program_defines(Pass(), lightmap=object()) == {}
    assert light_probes.program_defines(Pass(), dynamic_lightmap=object()) == {}
    Pass.program = "#pragma multi_compile _ FOO\n"
    assert light_probes.program_defines(Pass()) == {}
    assert "LIGHTPROBE_SH" in BUILTIN.keywords
    lit = lightmaps.lightmapped(BUILTIN, None)
    assert "LIGHTPROBE_SH" not in lit.keywords and "LIGHTMAP_ON" in lit.keywords
    realtime = dynamic_lightmaps.realtime_lit(BUILTIN, object())
    assert "LIGHTPROBE_SH" not in realtime.keywords and "DYNAMICLIGHTMAP_ON" in realtime.keywords
