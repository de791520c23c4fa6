"""A fragment function whose signature #if lines choose (issue 34):

    #if defined(_MRT)
    fragOut frag(Varyings IN)
    #else
    half4 frag(Varyings IN) : SV_Target
    #endif
    { ... int2 cell = (int2)(IN.positionCS.xy / max(1.0, _Cell)); ... }

The GLSL port's type pass reads both heads (the first as a prototype) and the body under the
last, so the body's Cg (the C-style vector cast ``(int2)(expr)``) is ported; before, the pass
skipped the whole function and glslang met the cast as written. Both languages, checked per
pixel against float64: the pixel whose centre is x + 0.5 from the left lies in cell
trunc((x + 0.5) / _Cell).
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.importers.loader import parse_scene
from pbrlab.importers.unity import cg_types
from pbrlab.render.renderer import render_scene
from test_urp_library_round2 import urp_pass  # pytest puts this folder on sys.path

LANGUAGES = ("glsl", "hlsl")
SIZE = 48

# test_urp_scene_textures' URP pass, its fragment head replaced by two chosen by #if lines
HEAD = "float4 frag(Varyings IN) : SV_Target {"
BRANCHED_HEAD = """#if defined(_MRT)
            fragOut frag(Varyings IN)
            #else
            half4 frag(Varyings IN) : SV_Target
            #endif
            {"""
DECLARATIONS = """CBUFFER_START(UnityPerMaterial)
            float _Cell;
            CBUFFER_END
            struct fragOut { half4 colour : SV_Target0; };"""
BODY = """int2 cell = (int2)(IN.positionCS.xy / max(1.0, _Cell));
                float4 colour = float4(cell.x / 16.0, 0.0, 0.0, 1.0);
            #if defined(_MRT)
                fragOut o;
                o.colour = colour;
                return o;
            #else
                return colour;
            #endif"""


def shader_text(cell) -> str:
    text = urp_pass("signature branches", BODY, DECLARATIONS)
    assert HEAD in text
    text = text.replace(HEAD, BRANCHED_HEAD)
    return text.replace("SubShader {", f'Properties {{ _Cell ("cell", Float) = {cell} }}\n    SubShader {{', 1)


# The colour is a multiple of 1/16 below 1: exact in float32 and in the float target.
EXACT = 0.0


def _render(tmp_path, language, cell):
    shader = tmp_path / "t.shader"
    shader.write_text(shader_text(cell))
    data = {
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40, "size": [SIZE, SIZE]},
        "lights": [],
        "materials": {"m": {"surface": str(shader)}},
        "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}],
    }
    image = render_scene(parse_scene(data, origin="signature test scene", base=tmp_path), language=language)
    image = image.linear.astype(np.float64)
    covered = image[..., 3] > 0
    assert covered.sum() > 200
    return image, covered


def expected_red(cell: float) -> np.ndarray:
    """float64: each column's cell index / 16 (SV_Position.x is the pixel centre, x + 0.5)."""
    x = np.arange(SIZE) + 0.5
    return np.broadcast_to(np.trunc(x / max(1.0, cell)) / 16.0, (SIZE, SIZE))


@pytest.mark.parametrize("language", LANGUAGES)
def test_a_signature_chosen_by_if_lines_ports_its_body(tmp_path, language):
    image, covered = _render(tmp_path, language, 4)
    assert np.abs(image[..., 0] - expected_red(4))[covered].max() <= EXACT
    # control: another cell size is another image (the value is read, not a default)
    assert np.abs(image[..., 0] - expected_red(3))[covered].max() >= 1.0 / 16.0


def test_the_type_pass_reads_both_heads():
    """The type pass no longer skips the function (main skipped it: its cast stayed HLSL's)."""
    text = shader_text(4)
    text = text[text.index("struct fragOut"):text.index("ENDHLSL")]
    text = text.replace("TransformObjectToHClip(IN.positionOS.xyz)", "IN.positionOS")
    result = cg_types.convert_detail("float _Cell;\nstruct Attributes { float4 positionOS : POSITION; };\n"
                                     "struct Varyings { float4 positionCS : SV_POSITION; };\n" + text)
    assert result.skipped == []
    assert "int2((IN.positionCS.xy" in result.text
