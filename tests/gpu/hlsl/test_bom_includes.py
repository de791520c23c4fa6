"""glslang reads HLSL includes itself and stops at a UTF-8 byte-order mark; compile_spirv hands
it BOM-free copies (hlsl._bom_free_search), which must resolve exactly as the originals do,
including an include that climbs out of its search directory (Unity projects write
``#include "../Include/ToonFunction.hlsl"`` from the shader's folder: ChiliMilk's URP toon)."""

from __future__ import annotations

import pytest

from pbrlab.foundation.errors import ShaderCompileError
from pbrlab.gpu import hlsl

BOM = b"\xef\xbb\xbf"
ENTRY = "float4 main(float4 p : SV_Position) : SV_Target0 { return float4(tint(p.xyz), 1.0); }\n"


def _project(tmp_path, bom: bool):
    """Shader/ is the search directory; Include/tint.hlsl (beside it) opens with the mark and
    includes its sibling value.hlsl (also with the mark) by the including file's folder."""
    (tmp_path / "Shader").mkdir()
    (tmp_path / "Include").mkdir()
    mark = BOM if bom else b""
    (tmp_path / "Include" / "tint.hlsl").write_bytes(
        mark + b'#include "value.hlsl"\nfloat3 tint(float3 c) { return c * TINT; }\n')
    (tmp_path / "Include" / "value.hlsl").write_bytes(mark + b"#define TINT 0.75\n")
    return tmp_path / "Shader"


@pytest.mark.parametrize("bom", [False, True])
def test_an_include_outside_its_search_dir_compiles_with_or_without_a_bom(tmp_path, bom):
    shader_dir = _project(tmp_path, bom)
    spirv = hlsl.compile_spirv('#include "../Include/tint.hlsl"\n' + ENTRY, "<bom>", [shader_dir])
    assert spirv[:4] == b"\x03\x02\x23\x07"  # SPIR-V magic, little-endian


def test_the_mark_is_what_glslang_refuses(tmp_path, monkeypatch):
    """Control: handing glslang the original directories fails on the mark."""
    shader_dir = _project(tmp_path, bom=True)
    monkeypatch.setattr(hlsl, "_bom_free_search", lambda text, dirs, tmp, replaced=None: [shader_dir])
    with pytest.raises(ShaderCompileError):
        hlsl.compile_spirv('#include "../Include/tint.hlsl"\n' + ENTRY, "<bom>", [shader_dir])


def test_an_error_in_a_bom_file_names_the_original_file(tmp_path):
    shader_dir = _project(tmp_path, bom=True)
    (tmp_path / "Include" / "value.hlsl").write_bytes(BOM + b"#define TINT nope\n")
    with pytest.raises(ShaderCompileError) as err:
        hlsl.compile_spirv('#include "../Include/tint.hlsl"\n' + ENTRY, "<bom>", [shader_dir])
    assert "bom-free" not in str(err.value)
    assert str(tmp_path / "Include" / "tint.hlsl") in str(err.value) or "tint.hlsl" in str(err.value)
