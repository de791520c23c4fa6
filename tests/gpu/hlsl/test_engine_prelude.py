"""The HLSL ports drop into an engine that already has its own GLSL-flavoured names.

An engine header commonly defines ``mod`` (often as fmod), ``mix``, a ``vec3`` struct, ``PI``,
a ``saturate`` macro and its own ``D_GGX``. The generated ports spell HLSL in HLSL's own
words (float3, lerp, frac, rsqrt, pbr_mod) and define nothing outside ``pbr_``/``PBR_`` and
the Unity names of the unity include, so the whole library compiles after such a prelude,
and the engine's names keep their meaning. Compiled by glslang's HLSL front end to SPIR-V
(validated); DXC and FXC are not installable here (not in the reachable package registries).
"""

import re

import pytest

from pbrlab.gpu import hlsl
from pbrlab.foundation.errors import ShaderCompileError

ENGINE_PRELUDE = """
struct vec3 { float x; float y; float z; };                     // an engine's own vector type
#define PI 3.14159265
#define saturate(x) clamp((x), 0.0, 1.0)
float mod(float x, float y) { return fmod(x, y); }              // fmod semantics, on purpose
float3 mix(float3 x, float3 y, float a) { return lerp(x, y, a); }
float D_GGX(float NdotH, float roughness) {
    float a2 = roughness * roughness;
    float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
    return a2 / (PI * d * d);
}
"""

LIBRARY = '#include "pbr/pbr.hlsl"\n#include "pbr/unity/surface_standard.hlsl"\n'

ENTRY = """
float4 main(float4 p : SV_Position) : SV_Target0 {
    vec3 engine; engine.x = p.x; engine.y = mod(p.y, 2.0); engine.z = saturate(p.z);
    float3 c = mix(float3(engine.x, engine.y, engine.z), float3(1.0, 1.0, 1.0), 0.5);
    return float4(c * D_GGX(0.5, 0.5) + pbr_D_GGX(0.5, 0.25), 1.0);
}
"""


def test_the_library_compiles_after_an_engine_prelude():
    hlsl.compile_spirv(ENGINE_PRELUDE + LIBRARY + ENTRY, "<engine-prelude>")


def test_the_library_compiles_before_an_engine_prelude():
    hlsl.compile_spirv(LIBRARY + ENGINE_PRELUDE + ENTRY, "<engine-prelude-after>")


def test_a_port_that_defined_a_glsl_name_would_collide():
    """The positive control: a library defining ``mod`` (as the old shim did) fails beside
    the same prelude, so the tests above would catch a regression."""
    old_shim = "float mod(float x, float y) { return x - y * floor(x / y); }\n"
    with pytest.raises(ShaderCompileError):
        hlsl.compile_spirv(ENGINE_PRELUDE + old_shim + LIBRARY + ENTRY, "<collision>")


def test_the_ports_define_only_prefixed_or_unity_names():
    """Every function, struct and macro the ports define is pbr_/PBR_, a Unity name of the
    unity include, or the shim's fixed* (Unity's HLSLSupport.cginc names)."""
    unity_ok = {"fixed", "fixed2", "fixed3", "fixed4", "fixed2x2", "fixed3x3", "fixed4x4"}
    offenders = []
    for path in sorted((hlsl.HLSL_ROOT / "pbr").rglob("*.hlsl")):
        rel = path.relative_to(hlsl.HLSL_ROOT).as_posix()
        code = re.sub(r"//[^\n]*", "", path.read_text(encoding="utf-8"))
        names = set(re.findall(r"^\s*#\s*define\s+(\w+)", code, re.M))
        names |= set(re.findall(r"^\s*struct\s+(\w+)", code, re.M))
        names |= set(re.findall(r"^[A-Za-z_]\w*\s+(\w+)\s*\(", code, re.M))
        for name in names:
            if name.startswith(("pbr_", "PBR_")) or name in unity_ok or rel.startswith("pbr/unity/"):
                continue
            offenders.append(f"{rel}: {name}")
    assert not offenders, offenders
