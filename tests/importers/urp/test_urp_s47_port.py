"""URP's ``half4 frag(Varyings input) : SV_Target`` (issue 34, session 47): ``input``, ``output``,
``sample`` (a varying), ``filter`` and ``common`` are GLSL reserved words and HLSL's own names; the GLSL port
renames them, also inside the shorter overload it writes for a default argument (session 46's
refusal: the overload declared ``Varyings input`` as written). Drawn in both languages from a
minimal shader of ours (shaders/s47-port/reserved_parameters.shader), checked against float64."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.unity import cg_types, parse_pass, texture_methods
from test_urp_library_round2 import LANGUAGES, render_constant  # pytest puts this folder on sys.path

SHADER = Path(__file__).parent / "shaders" / "s47-port" / "reserved_parameters.shader"


@pytest.mark.parametrize("language", LANGUAGES)
def test_reserved_parameter_names_in_an_entry_and_a_default_argument_overload(tmp_path, language, monkeypatch):
    """Shade(input) with its defaults: the varying ``sample`` (0.25, 0.5, 0.75) (a constant, so
    interpolation keeps it) * 0.5 + 0.125 = (0.25, 0.375, 0.5); half is float on Direct3D 10+
    targets (Microsoft's HLSL reference, "Scalar Types"), every value a dyadic fraction: bound
    2^-24, one float32 rounding below 1. Control: the overload written with the names as the
    program spells them (cg_types.renamed_reserved the identity), GLSL refuses ``input``; and the
    member ``sample`` read as an interpolation modifier wherever it stands (parse_pass._leading
    counting every such word, as before), the pass carries no such varying and the colour is
    not the one above (0.125 in HLSL, the member read as zero; undefined in GLSL)."""
    pixels, _ = render_constant(tmp_path, SHADER.read_text(), language, environment=False)
    want = np.array([0.25, 0.375, 0.5])
    assert (np.abs(pixels[:, :3] - want) <= 2.0 ** -24).all(), pixels[0, :3]
    with monkeypatch.context() as patched:
        patched.setattr(parse_pass, "_leading", lambda words, qualifiers: sum(w in qualifiers for w in words))
        (tmp_path / "member").mkdir()
        pixels, _ = render_constant(tmp_path / "member", SHADER.read_text(), language, environment=False)
        assert not (np.abs(pixels[:, :3] - want) <= 2.0 ** -24).all()
    if language == "glsl":
        monkeypatch.setattr(cg_types, "renamed_reserved", lambda text: text)
        (tmp_path / "old").mkdir()
        with pytest.raises(PbrlabError, match="reserved word"):
            render_constant(tmp_path / "old", SHADER.read_text(), language, environment=False)


ARRAY_SHADER = Path(__file__).parent / "shaders" / "s47-port" / "texture_array_macro_methods.shader"


@pytest.mark.parametrize("language", LANGUAGES)
def test_methods_of_a_texture2d_array_declared_by_core_rps_macro(tmp_path, language, monkeypatch):
    """TEXTURE2D_ARRAY(_Layers) declares a Texture2DArray on Direct3D 11 (Core RP's
    API/D3D11.hlsl), whose Sample / SampleLevel at (uv, layer) (Microsoft's HLSL reference,
    "Texture2DArray") read the property's "gray" (0.5 in every channel, a float texel; every layer
    index reads the one layer, texture_arrays.py), as SAMPLE_TEXTURE2D_ARRAY does:
    (0.5 * 0.5, 0.5, 0.5 * 0.25), dyadic, bound 2^-24. Control: the macro not known to
    texture_methods as declaring an array, the GLSL port leaves the methods as written and GLSL
    refuses them ("unknown method")."""
    pixels, _ = render_constant(tmp_path, ARRAY_SHADER.read_text(), language, environment=False)
    want = np.array([0.25, 0.5, 0.125])
    assert (np.abs(pixels[:, :3] - want) <= 2.0 ** -24).all(), pixels[0, :3]
    if language == "glsl":
        monkeypatch.setattr(texture_methods, "_MACRO_KIND", {k: v for k, v in texture_methods._MACRO_KIND.items()
                                                             if k != "TEXTURE2D_ARRAY"})
        monkeypatch.setattr(texture_methods, "_MACRO_DECLARATION",
                            __import__("re").compile(r"\b(TEXTURE2D|TEXTURECUBE)(?:_PARAM)?\s*\(\s*(\w+)\s*[,)]"))
        (tmp_path / "old").mkdir()
        with pytest.raises(PbrlabError, match="unknown method"):
            render_constant(tmp_path / "old", ARRAY_SHADER.read_text(), language, environment=False)
