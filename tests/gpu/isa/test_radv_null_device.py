"""pbrlab.gpu.isa: RADV's null device compiles for each AMD family and its figures respond
to what the program does (controls with known answers, not just "a number came back")."""

import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.gpu.isa import compile as gpu

_HEAD = "#version 450\nlayout(location = 0) out vec4 colour;\nuniform float u;\n"


def _chain(n: int, kind: str = "float") -> str:
    """n dependent multiply-adds on u (a loose uniform: -R gathers it into a block)."""
    lines = [f"{kind} x = {kind}(u);"] + [f"x = x * x + {kind}({i + 1}.5);" for i in range(n)]
    return "\n    ".join(lines)


@pytest.fixture(scope="module")
def compiled():
    if (why := gpu.available()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    jobs = [gpu.Job(f"chain{n}", _HEAD + f"void main() {{\n    {_chain(n)}\n    colour = vec4(x);\n}}\n")
            for n in (4, 20)]
    f16 = ("#version 450\n#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require\n"
           "layout(location = 0) out vec4 colour;\nuniform vec4 w;\n"
           "void main() {\n    f16vec2 a = f16vec2(w.xy), b = f16vec2(w.zw);\n"
           "    for (int i = 0; i < 8; ++i) a = a * b + f16vec2(1.5, 2.5);\n"
           "    colour = vec4(a, 0.0, 1.0);\n}\n")
    jobs.append(gpu.Job("packed_f16", f16))
    hlsl = ("cbuffer C { float u; };\nfloat4 main() : SV_Target {\n    float x = u;\n"
            + "".join(f"    x = x * x + {i + 1}.5;\n" for i in range(20))
            + "    return float4(x, x, x, x);\n}\n")
    jobs.append(gpu.Job("hlsl_chain20", hlsl, language="hlsl"))
    return gpu.run(jobs)


def test_every_family_names_its_null_device(compiled):
    names = {family: result["_device"]["name"] for family, result in compiled.items()}
    assert names == {"rdna3": "Null hardware (RADV GFX1100)",
                     "rdna2": "Null hardware (RADV NAVI21)",
                     "gcn5": "Null hardware (RADV VEGA10)"}


def test_instructions_grow_with_the_work(compiled):
    for family, result in compiled.items():
        small, large = result["chain4"], result["chain20"]
        # 16 more dependent FMAs: at least 16 more instructions, and a longer latency
        assert large["Instructions"] - small["Instructions"] >= 16, family
        assert large["Latency"] > small["Latency"], family
        assert large["VGPRs"] >= 1 and large["Code size"] > small["Code size"], family


def test_hlsl_reaches_the_same_compiler(compiled):
    for family, result in compiled.items():
        glsl, hlsl = result["chain20"], result["hlsl_chain20"]
        assert abs(hlsl["Instructions"] - glsl["Instructions"]) <= 4, family


def test_explicit_float16_is_packed_where_the_hardware_packs(compiled):
    # GCN5 (Vega) and RDNA have packed 16-bit maths (v_pk_fma_f16)
    for family, result in compiled.items():
        isa = result["packed_f16"]["isa"]
        assert isa["valu_packed"] >= 8, (family, isa)
        assert compiled[family]["chain20"]["isa"]["valu_f16"] == 0


def test_a_shader_error_is_reported_not_crashed():
    with pytest.raises(PbrlabError, match="glslang"):
        gpu.run([gpu.Job("broken", _HEAD + "void main() { colour = undefined_name; }\n")],
                families=("rdna3",))
