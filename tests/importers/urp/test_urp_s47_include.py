"""s47-include: include search for a project that embeds URP's packages, and the pipeline of a
shader whose passes are tagged for URP's forward renderer.

1. A project's embedded copy of ``Packages/com.unity.render-pipelines.universal`` (beside its
   ``Assets/``: ChillyHub's Unity_URP_NPR_Sample embeds URP 14's) is read as pbrlab's stand-ins,
   in both languages: ``Packages/...`` names resolve to the stand-in before the project's root
   (source_text.resolve_included; program_pass's glslang folders), and a guarded copy glslang
   reaches from the project's root anyway (a shader beside ``Packages/``: glslang searches the
   folders of the files on the include stack before its -I folders) is replaced by an include
   that names only the stand-in (vendored_library.own_include). The replacement used to be the
   copy's own package path, which resolved back to the copy: glslang followed the loop until its
   60 s limit.
2. A pass tagged ``"LightMode" = "UniversalForward"`` / ``"UniversalForwardOnly"`` in a shader
   with no RenderPipeline tag (here a CGPROGRAM including UnityCG.cginc) is a URP shader (URP's
   manual, "ShaderLab Pass tags in URP"; the built-in pipeline draws neither LightMode).

Colours are short binary fractions, exact in float32 and in the half-float target: covered
pixels must equal the float64 expectation exactly.
"""

from __future__ import annotations

import shutil
import time
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.gpu import hlsl
from pbrlab.importers.unity import vendored_library
from pbrlab.importers.urp import material as urp_material

SHADERS = Path(__file__).parent / "shaders" / "s47-include"
PROJECT = SHADERS / "vendored_project"
# Core RP's Max3 / Min3 (Common.hlsl: max(max(a, b), c), min(min(a, b), c)) of (0.25, 0.5, 0.125),
# and the shader's 0.75
MAX_MIN = np.array([max(0.25, 0.5, 0.125), min(0.25, 0.5, 0.125), 0.75], dtype=np.float64)
TINT = np.array([0.25, 0.5, 0.75], dtype=np.float64)  # the light_mode shaders' _Tint default


def _assert_exactly(result, expected):
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    assert np.array_equal(result.image[covered][:, :3].astype(np.float64),
                          np.broadcast_to(expected, (covered.sum(), 3)))


def _copy_project(tmp_path) -> Path:
    """The project copied (a path of its own: no compile cached for another test's)."""
    shutil.copytree(PROJECT, tmp_path / "project")
    return tmp_path / "project"


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("shader", ["BesideTheProjectsPackages.shader", "Assets/Shaders/InTheProjectsAssets.shader"])
def test_an_embedded_urp_core_is_read_as_the_stand_in_in_seconds(tmp_path, language, shader):
    """The embedded Core.hlsl (Unity's guard, an #error in it) is the stand-in's: Core RP's Max3 /
    Min3 answer exactly, within seconds (the loop ran to glslang's 60 s limit), from a shader
    beside the project's Packages/ (the include stack's case) and one under Assets/."""
    start = time.monotonic()
    _assert_exactly(corpus.run_shader(_copy_project(tmp_path) / shader, language), MAX_MIN)
    assert time.monotonic() - start < 30  # a compile of seconds; the loop took 60 s and failed


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_an_embedded_package_file_without_a_guard_entry_is_the_stand_in(tmp_path, language):
    """Embedded BRDF.hlsl (a guard of the project's own, an #error): named by its package path it
    is the stand-in's BRDF.hlsl in both languages (the stand-ins come before the project's root);
    the render is Max3 / Min3's. Before, glslang read the project's copy and stopped at its #error."""
    _assert_exactly(corpus.run_shader(_copy_project(tmp_path) / "Assets/Shaders/EmbeddedBrdf.shader", language),
                    MAX_MIN)


def test_the_replacement_names_only_the_stand_in():
    """The include a copy is replaced by resolves, from the project's root (where the copy's
    package path is the copy itself), to nothing: only from the stand-ins' parent, to the stand-in."""
    copy = PROJECT / "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
    stand_ins = Path(vendored_library.__file__).parent / "package_stand_ins"
    stand_in = vendored_library.stand_in_for(copy, stand_ins)
    assert stand_in == stand_ins / "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"
    name = vendored_library.own_include(stand_in, stand_ins)
    assert not (PROJECT / name).exists() and not (copy.parent / name).exists()
    assert (stand_ins.parent / name).resolve() == stand_in.resolve()


def test_control_the_package_path_as_replacement_loops(tmp_path, monkeypatch):
    """Control: replaced by its own package path (the old replacement), the copy reached from the
    project's root includes itself; glslang follows the loop until the compile time limit (cut to
    5 s here) and the shader is refused naming that limit."""
    monkeypatch.setattr(vendored_library, "own_include",
                        lambda stand_in, stand_ins: Path(stand_in).relative_to(stand_ins).as_posix())
    monkeypatch.setattr(hlsl, "_TIMEOUT_S", 5)
    result = corpus.run_shader(_copy_project(tmp_path) / "BesideTheProjectsPackages.shader", "hlsl")
    assert result.status == "refused" and "compile time limit" in result.message, result.message


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("mode", ["UniversalForward", "UniversalForwardOnly"])
def test_a_urp_forward_pass_without_a_pipeline_tag_is_drawn_by_urp(language, mode):
    """The shader is read as URP's and its pass draws the material's _Tint, exactly."""
    path = SHADERS / "light_mode" / f"{mode}.shader"
    assert urp_material.reads(path)
    _assert_exactly(corpus.run_shader(path, language), TINT)


@pytest.mark.parametrize("mode", ["UniversalForward", "UniversalForwardOnly"])
def test_control_without_the_light_mode_rule_the_builtin_pipeline_draws_nothing(mode, monkeypatch):
    """Control: without the rule (the old choice) the shader is the built-in pipeline's, whose
    every pass is skipped: refused, "nothing here draws"."""
    monkeypatch.setattr(urp_material, "_urp_forward_passes", lambda text: False)
    path = SHADERS / "light_mode" / f"{mode}.shader"
    assert not urp_material.reads(path)
    result = corpus.run_shader(path, "glsl")
    assert result.status == "refused" and "nothing here draws" in result.message


def test_a_builtin_light_mode_beside_keeps_the_builtin_pipeline(tmp_path):
    """A shader with a ForwardBase pass beside its UniversalForward one stays the built-in
    pipeline's (the rule asks that no pass be tagged for the built-in pipeline)."""
    text = (SHADERS / "light_mode" / "UniversalForward.shader").read_text()
    path = tmp_path / "b.shader"
    path.write_text(text.replace("        Pass {", '        Pass { Tags { "LightMode" = "ForwardBase" } }\n        Pass {', 1))
    assert '"ForwardBase"' in path.read_text() and not urp_material.reads(path)


# 3. A program's own declaration of a global pbrlab's prelude declares, with another type.
RETYPED = SHADERS / "retyped_global"
SPEC_PROPERTY = np.array([0.25, 0.5, 0.75], dtype=np.float64)  # the Properties' _SpecColor, .rgb
# pbrlab's _SpecColor without a property (program.DEFAULT_SPEC_COLOR, Unity's legacy shaders'
# default (0.5, 0.5, 0.5, 1)), .rgb
SPEC_DEFAULT = np.array([0.5, 0.5, 0.5], dtype=np.float64)


def _copied(tmp_path, name) -> Path:
    """A shader of RETYPED copied to a folder of its own (user_definitions keeps its answers
    per program text and folder: a control's monkeypatch must not meet a kept answer)."""
    path = tmp_path / name
    shutil.copyfile(RETYPED / name, path)
    return path


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("name, expected", [("SpecColorGlobal.shader", SPEC_PROPERTY),
                                            ("SpecColorCbuffer.shader", SPEC_PROPERTY),
                                            ("SpecColorNoProperty.shader", SPEC_DEFAULT)])
def test_a_programs_own_half3_spec_color_is_the_only_one(tmp_path, language, name, expected):
    """``half3 _SpecColor;`` (outside or inside a CBUFFER) over the prelude's float4: the program's
    declaration is the one read (``half4(_SpecColor, 1.0)`` compiles only with three components),
    given the property's (or pbrlab's default) colour's rgb, exactly."""
    _assert_exactly(corpus.run_shader(_copied(tmp_path, name), language), expected)


def test_the_retyped_global_is_told_from_a_same_typed_one():
    """Only a declaration with a type of its own renames the prelude's (a float4 / half4 one is
    the prelude's type: the prelude's declaration serves, as before)."""
    from pbrlab.importers.unity import user_definitions as ud
    assert ud.retyped_prelude_globals("half3 _SpecColor;") == {"_SpecColor"}
    assert ud.retyped_prelude_globals("CBUFFER_START(UnityPerMaterial) half3 _SpecColor; CBUFFER_END") == {"_SpecColor"}
    assert ud.retyped_prelude_globals("float4 _SpecColor;\nhalf4 _SpecColor;\nfixed4 unity_FogColor;") == set()
    assert ud.prelude_renames(ud.text_defines("half3 _SpecColor;", RETYPED)) == {"_SpecColor": "pbrlab_prelude_SpecColor"}


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_control_without_the_rename_the_redeclaration_is_refused_naming_the_shader(tmp_path, language, monkeypatch):
    """Control: without the rename (the old behaviour) both declarations reach the compiler:
    glslang crashes (signal 11), reported as a refusal naming the shader and the signal (no
    traceback); the GLSL compiler refuses the redeclaration naming the file."""
    from pbrlab.importers.unity import user_definitions as ud
    monkeypatch.setattr(ud, "retyped_prelude_globals", lambda text: set())
    result = corpus.run_shader(_copied(tmp_path, "SpecColorGlobal.shader"), language)
    assert result.status == "refused", result.message
    assert "SpecColorGlobal.shader" in result.message
    if language == "hlsl":
        assert "signal 11 SIGSEGV" in result.message
