"""What the URP front end reads beyond the first slice: custom varying semantics, the Core RP
functions and stand-in files the public corpus (corpus/urp) uses. Each with a control that
fails without it."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity import port
from pbrlab.render.renderer import render_scene

HERE = Path(__file__).resolve().parent
SHADERS = HERE / "shaders"


def _plane_scene(shader: Path, properties=None) -> dict:
    """A unit plane (XZ, UVs over [0, 1]^2) filling the view from above, one directional light."""
    return {
        "camera": {"position": [0.0, 2.0, 0.0], "target": [0.0, 0.0, 0.0], "up": [0.0, 0.0, -1.0],
                   "fov_y_deg": 20, "size": [32, 32]},
        "lights": [{"type": "directional", "direction": [-0.3, -1.0, -0.2], "color": [1, 1, 1], "intensity": 1.0}],
        "materials": {"m": {"surface": str(shader), **({"properties": properties} if properties else {})}},
        "objects": [{"mesh": {"primitive": "plane", "size": 1.0}, "material": "m"}],
    }


def _render(shader: Path, language: str, properties=None) -> np.ndarray:
    scene = parse_scene(_plane_scene(shader, properties), origin="t", base=shader.parent)
    return render_scene(scene, language=language).linear


def test_the_port_drops_a_custom_semantic_where_a_declaration_carries_it():
    code = ("struct V { float4 p : SV_POSITION; float f : FOG_FACTOR; };\n"
            "float g(float a : MY_A, float b) { return a > b ? a : b; }\n"
            "float h(int k) { switch (k) { case K : return 1.0; } return c ? x : y; }\n")
    ported = port.port_code(code)
    assert "FOG_FACTOR" not in ported and "MY_A" not in ported
    assert "a > b ? a : b;" in ported and "case K : return" in ported and "c ? x : y;" in ported


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_custom_varying_semantics_link_the_stages_by_name(language):
    got = _render(SHADERS / "urp_custom_semantic.shader", language)
    want = _render(SHADERS / "urp_uv.shader", language)
    assert (got[..., 3] > 0).all()
    np.testing.assert_allclose(got, want, atol=1e-6)


def test_without_dropping_it_the_glsl_port_fails(monkeypatch, tmp_path):
    """Control: the known-semantic rule alone leaves ``: FOG_FACTOR`` in the GLSL (a copy of
    the shader: the program caches know the original)."""
    monkeypatch.setattr(port, "_DECLARED_SEMANTIC", re.compile(r"((?!x)x)"))
    copy = tmp_path / "custom_semantic.shader"
    copy.write_text((SHADERS / "urp_custom_semantic.shader").read_text())
    with pytest.raises(PbrlabError, match="FOG_FACTOR|syntax error"):
        _render(copy, "glsl")


INCLUDE_PASS = SHADERS / "include_pass" / "urp_include_pass.shader"


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_a_fragment_function_in_an_include_reads_as_in_the_program(language):
    """The pass's functions in an include: FRONT_FACE_TYPE/FRONT_FACE_SEMANTIC read there as in
    the program (the face reaches it: front, 0.75), another include's int function read into a uint, and
    Core RP's CreateTangentToWorld (rows T, cross(N, T) * flipSign, N: the bitangent's y is -1
    for N = z, T = x, flip -1) and URP's CalculateFinalColor (GI + main + additional + vertex
    lights, times albedo 1, plus emission: 0.5)."""
    got = _render(INCLUDE_PASS, language)
    assert (got[..., 3] > 0).all()
    np.testing.assert_allclose(got[..., :3], np.broadcast_to([0.5, 0.25, 0.75], got[..., :3].shape), atol=1e-6)


def test_without_the_spellings_in_includes_the_face_parameter_has_no_value(monkeypatch, tmp_path):
    """Control: the include's FRONT_FACE_SEMANTIC parameter read as written is a semantic the
    entry generator has no value for: the parameter (FRONT_FACE_TYPE, Core RP's alias of bool:
    parse_pass._dealiased) is zero, as for any semantic without a value, so the face is read as
    the back (0.125, not the test's 0.75). (Before session 44 the alias was unresolved and the
    entry held a literal None: neither language compiled.)"""
    from pbrlab.importers.unity import parse_pass
    monkeypatch.setattr(parse_pass, "respelled", lambda text, spellings: text)
    _copy_include_pass(tmp_path)
    for language in ("glsl", "hlsl"):
        got = _render(tmp_path / "urp_include_pass.shader", language)
        covered = got[..., 3] > 0
        np.testing.assert_allclose(got[covered, 2], 0.125, atol=1e-6)


def test_without_other_includes_functions_the_glsl_port_fails(monkeypatch, tmp_path):
    """Control: without the other includes' prototypes the port's type pass does not know what
    their functions return, and the GLSL compile fails: GetAdditionalLightsCount()'s int reaches
    a uint unconverted (GLSL 330 refuses), or, since session 47's Core.hlsl brings Core RP's
    vector math (PbrlabCommonMath.hlsl, compiled before the pass), a call there first ("too many
    parameters to vec2 constructor")."""
    from pbrlab.importers.unity import program
    monkeypatch.setattr(program, "_prototypes", lambda masked: [])
    _copy_include_pass(tmp_path)
    with pytest.raises(PbrlabError, match="uint|too many parameters to `vec2. constructor"):
        _render(tmp_path / "urp_include_pass.shader", "glsl")


def _copy_include_pass(folder: Path):
    for f in INCLUDE_PASS.parent.iterdir():
        (folder / f.name).write_text(f.read_text())
