"""The HLSL ports through a second, independent compiler: Slang (the compiler library that the
PyPI package slangpy ships), besides glslang's HLSL front end (test_compile_matrix.py).

Slang parses, type-checks and links each port (every function, called or not, is checked
when its module loads), the whole library beside an engine prelude (test_engine_prelude.py),
and refuses a broken file (the positive control). It runs on slangpy's CPU device: this
machine has no Vulkan driver, so Slang's SPIR-V emission (sm_6_0 -> SPIR-V) is not run here;
the SPIR-V path stays glslang -> SPIR-V -> spirv-cross. DXC and FXC are not available here
(not in the reachable package registries).
"""

import pytest

from pbrlab.gpu import hlsl

from test_compile_matrix import HLSL_FILES
from test_engine_prelude import ENGINE_PRELUDE, LIBRARY

spy = pytest.importorskip("slangpy", reason="slangpy (requirements.txt) carries the Slang compiler")

PIXEL_ENTRY = '[shader("pixel")]\nfloat4 main(float4 p : SV_Position) : SV_Target0 {{ return float4({value}, 0.0, 0.0, 1.0); }}\n'


@pytest.fixture(scope="module")
def session():
    device = spy.Device(type=spy.DeviceType.cpu,
                        compiler_options={"include_paths": [str(hlsl.HLSL_ROOT)]})
    return device.slang_session


def _link(session, name, source):
    module = session.load_module_from_source(name, source)
    return session.link_program([module], [module.entry_point("main")])


@pytest.mark.parametrize("path", HLSL_FILES)
def test_every_hlsl_port_compiles_alone_in_slang(session, path):
    name = "port_" + path.replace("/", "_").replace(".", "_")
    _link(session, name, f'#include "{path}"\n' + PIXEL_ENTRY.format(value="p.x"))


def test_the_library_compiles_beside_an_engine_prelude_in_slang(session):
    source = ENGINE_PRELUDE + LIBRARY + PIXEL_ENTRY.format(value="pbr_D_GGX(0.5, 0.25) + D_GGX(0.5, 0.5)")
    _link(session, "engine_prelude", source)


def test_slang_refuses_a_broken_file(session):
    with pytest.raises(spy.SlangCompileError, match="undefined identifier"):
        _link(session, "broken", "float f(float x) { return x + nope; }\n" + PIXEL_ENTRY.format(value="f(p.x)"))
