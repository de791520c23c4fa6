"""s47-include: a GrabPass texture's ``_TexelSize`` declared by the program with a type of its own.

Unity sets ``<texture>_TexelSize`` = (1/width, 1/height, width, height) (Unity's manual,
"ShaderLab: built-in shader variables" / "Properties in shader programs": ``{TextureName}_TexelSize``)
into whatever the program declares: ``float2 _GrabTexture_TexelSize;`` takes the leading two
(as a Color/Vector property bound to a float2). pbrlab set the four numbers as they stand and
refused a float2 ("clashes with one of the harness's own uniforms"); it now binds them as a
property's vector (program._bind_vector), in both languages.

The shaders return ``_GrabTexture_TexelSize.xy * 16``: 16 / 64 = 0.25 for the corpus scene's
64 x 64 frame (the grab's size, read from the render), exact in float32 and half floats.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.gpu import programs
from pbrlab.importers.unity import program as unity_program

SHADERS = Path(__file__).parent / "shaders" / "s47-include"


def _expected(image) -> np.ndarray:
    """(16 / width, 16 / height, 0.75) in float64, of the frame the GrabPass copied."""
    h, w = image.shape[:2]
    return np.array([16.0 / w, 16.0 / h, 0.75], dtype=np.float64)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("kind", ["float2", "half4", "float4"])
def test_a_grab_texel_size_of_the_programs_type(language, kind):
    result = corpus.run_shader(SHADERS / f"GrabTexelSize_{kind}.shader", language)
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    assert np.array_equal(result.image[covered][:, :3].astype(np.float64),
                          np.broadcast_to(_expected(result.image), (covered.sum(), 3)))


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_the_four_numbers_as_they_stand_are_refused_by_a_float2(language, monkeypatch):
    """Control: set as the four numbers (the old binding), the float2 is refused naming the
    uniform and the clash."""
    monkeypatch.setattr(unity_program, "_bind_vector",
                        lambda program, name, what, value: programs.set_uniform(program, name, value))
    result = corpus.run_shader(SHADERS / "GrabTexelSize_float2.shader", language)
    assert result.status == "refused"
    assert "'_GrabTexture_TexelSize'" in result.message and "declares it vec2" in result.message


# A surface shader's own ``half3 _SpecColor;`` over the prelude's float4 (user_definitions'
# retyped prelude globals; the URP programs' tests are in tests/importers/urp/test_urp_s47_include.py).
SPEC_PROPERTY = np.array([0.25, 0.5, 0.75], dtype=np.float64)  # its Properties' _SpecColor, rgb


def _copied(tmp_path, name) -> Path:
    """The shader in a folder of its own (user_definitions keeps answers per text and folder)."""
    path = tmp_path / name
    path.write_text((SHADERS / name).read_text())
    return path


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_surface_shaders_own_half3_spec_color(tmp_path, language):
    """Lambert with Albedo 0 and Emission the program's own _SpecColor: the emission, exactly
    (Unity's LightingLambert adds nothing to an albedo of 0; the sky's ambient times 0 too)."""
    result = corpus.run_shader(_copied(tmp_path, "SurfaceOwnSpecColor.shader"), language)
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert np.array_equal(result.image[covered][:, :3].astype(np.float64),
                          np.broadcast_to(SPEC_PROPERTY, (covered.sum(), 3)))


def test_control_a_surface_shaders_own_spec_color_crashed_glslang(tmp_path, monkeypatch):
    """Control: without the rename glslang crashes on the redeclaration (signal 11), refused
    naming the shader, no traceback."""
    from pbrlab.importers.unity import user_definitions as ud
    monkeypatch.setattr(ud, "retyped_prelude_globals", lambda text: set())
    result = corpus.run_shader(_copied(tmp_path, "SurfaceOwnSpecColor.shader"), "hlsl")
    assert result.status == "refused" and "SurfaceOwnSpecColor.shader" in result.message
    assert "signal 11 SIGSEGV" in result.message
