"""The stencil state ``stencil_state.apply`` keeps per context (to skip GL calls when it does
not change) stays the context's true state: it is recorded only once every GL call is made (a
call that raised once left it recorded, and the next apply of that state made no call), and a
render whose draw raises (a refused program after a pass with a Stencil block) turns the test
off before the error leaves the renderer (before, the test stayed on for the context's next
user: the pyrender cross-check draws into a depth-stencil target without resetting it)."""

from __future__ import annotations

import ctypes
import textwrap

import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.gpu import gl, stencil_state
from pbrlab.gpu.stencil_state import StencilFace, StencilState
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

# glGet names (OpenGL 3.3 core, table 6.21): the test's enable and the front face's pass op
_GL_STENCIL_TEST, _GL_STENCIL_PASS_DEPTH_PASS = 0x0B90, 0x0B96
_GL_REPLACE, _GL_KEEP = 0x1E01, 0x1E00
WRITES = StencilState(ref=3, front=StencilFace("always", pass_op="replace"))


def _get(ctx, name: int) -> int:
    value = ctypes.c_int(-1)
    gl.gl_function(ctx, "glGetIntegerv")(name, ctypes.byref(value))
    return value.value


def test_a_call_that_raised_leaves_the_state_unknown():
    """The pass op's call raises once; the next apply of the same state sets it. Control: a
    state recorded as set whose calls were not made (the old order) is skipped: GL keeps KEEP."""
    ctx = gl.shared_context()
    stencil_state.apply(ctx, None)
    kept = stencil_state._of(ctx)

    def fails(*args):
        raise PbrlabError("the GL driver does not provide glStencilOpSeparate")
    real = kept.glStencilOpSeparate
    kept.functions["glStencilOpSeparate"] = fails
    try:
        with pytest.raises(PbrlabError):
            stencil_state.apply(ctx, WRITES)
    finally:
        kept.functions["glStencilOpSeparate"] = real
    assert _get(ctx, _GL_STENCIL_PASS_DEPTH_PASS) == _GL_KEEP  # (the raise left it unset)
    stencil_state.apply(ctx, WRITES)
    assert _get(ctx, _GL_STENCIL_PASS_DEPTH_PASS) == _GL_REPLACE and _get(ctx, _GL_STENCIL_TEST) == 1
    # control: recorded without its calls, the apply is skipped and GL keeps what it had
    stencil_state.apply(ctx, None)
    kept.state = WRITES
    stencil_state.apply(ctx, WRITES)
    assert _get(ctx, _GL_STENCIL_PASS_DEPTH_PASS) == _GL_KEEP
    stencil_state.forget(ctx)  # what code that changes the state behind apply calls
    stencil_state.apply(ctx, WRITES)
    assert _get(ctx, _GL_STENCIL_PASS_DEPTH_PASS) == _GL_REPLACE
    stencil_state.apply(ctx, None)


SHADER = textwrap.dedent("""\
    Shader "Test/StencilThenRefused"
    {
        SubShader
        {
            Stencil { Ref 1 Comp Always Pass Replace }
            Pass
            {
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "UnityCG.cginc"
                float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
                fixed4 frag() : SV_Target { return fixed4(0.5, 0.5, 0.5, 1); }
                ENDCG
            }
            Pass
            {
                CGPROGRAM
                #pragma vertex vert
                #pragma fragment frag
                #include "UnityCG.cginc"
                float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
                fixed4 frag() : SV_Target { return fixed4(SECOND, 1); }
                ENDCG
            }
        }
    }
    """)


def _render(tmp_path, second: str):
    path = tmp_path / "stencil_then_refused.shader"
    path.write_text(SHADER.replace("SECOND", second))
    scene = parse_scene({"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40, "size": [16, 16]},
                         "lights": [], "environment": None, "materials": {"m": {"surface": path.name}},
                         "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}]},
                        origin="test scene", base=tmp_path)
    return render_scene(scene, language="glsl")


def test_a_render_that_raises_after_a_stencil_pass_leaves_the_test_off(tmp_path):
    """The SubShader's Stencil block applies to both passes; the second's program does not
    compile (a name nothing declares), so the render raises with the test on; the context's
    test is off afterwards, as after a render that finished (the same shader with the name
    fixed). Before: the test stayed on."""
    ctx = gl.shared_context()
    with pytest.raises(PbrlabError):
        _render(tmp_path, "undeclared_name")
    assert _get(ctx, _GL_STENCIL_TEST) == 0
    assert stencil_state._of(ctx).state is None
    _render(tmp_path, "0.25, 0.25, 0.25")
    assert _get(ctx, _GL_STENCIL_TEST) == 0
