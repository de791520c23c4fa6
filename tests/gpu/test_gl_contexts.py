"""The context factory: both backends work, render identically, and fail clearly."""

import hashlib
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from pbrlab.gpu import gl
from pbrlab.foundation.errors import PbrlabError

# Renders a pattern with transcendental maths (pow, exp2, sin: the functions whose
# llvmpipe code depends on CPU features) into an RGBA32F target and prints its hash.
# Each backend runs in its own process so the two Mesa front ends never share one.
_RENDER_HASH = textwrap.dedent("""
    import hashlib, sys
    import numpy as np
    sys.path.insert(0, {tests_dir!r})
    from gl_helpers import fullscreen_program
    from pbrlab.gpu import gl, targets
    ctx = gl.create_context(sys.argv[1])
    program, vao = fullscreen_program(ctx, '''#version 330 core
    out vec4 o;
    void main() {{
        vec2 p = gl_FragCoord.xy / 64.0 + 0.01;
        o = vec4(pow(p.x, 2.4), exp2(p.y * 3.7), sin(p.x * 7.0), inversesqrt(p.x + p.y));
    }}''')
    with targets.Target(ctx, (64, 64), "f32", depth=False) as t:
        t.use(); vao.render(vertices=3)
        print(ctx.info["GL_RENDERER"], hashlib.sha256(t.read().tobytes()).hexdigest())
""")


def _render_hash(backend, tmp_path):
    import os
    script = tmp_path / "render_hash.py"
    script.write_text(_RENDER_HASH.format(tests_dir=os.path.dirname(__file__)))
    out = subprocess.run([sys.executable, str(script), backend], capture_output=True, text=True,
                         check=True, env=dict(os.environ, PBRLAB_LLVMPIPE_CPU_CAPS="sse4.1",
                                              GALLIUM_OVERRIDE_CPU_CAPS="sse4.1"))
    return out.stdout.strip().splitlines()[-1]


def test_egl_and_osmesa_render_bit_identical(tmp_path):
    egl = _render_hash("egl", tmp_path)
    osmesa = _render_hash("osmesa", tmp_path)
    assert "llvmpipe" in egl and "llvmpipe" in osmesa
    assert egl.split()[-1] == osmesa.split()[-1]


@pytest.mark.parametrize("backend", gl.BACKENDS)
def test_backend_gives_core_profile_33_or_later(backend):
    ctx = gl.shared_context(backend)
    assert ctx.version_code >= 330
    assert "Core Profile" in ctx.info["GL_VERSION"]
    assert gl.context_info(ctx)["backend"] == backend


def test_unknown_backend_is_a_clear_error():
    with pytest.raises(PbrlabError, match="unknown GL backend 'vulkan'"):
        gl.create_context("vulkan")


def test_bad_backend_environment_variable_is_a_clear_error(monkeypatch):
    monkeypatch.setenv(gl.BACKEND_ENV, "d3d")
    with pytest.raises(PbrlabError, match="PBRLAB_GL_BACKEND='d3d'"):
        gl.default_backend()


def test_missing_gl_libraries_give_one_paragraph_naming_packages(tmp_path):
    # Point every GL library at a file that does not exist, as on a machine without Mesa.
    code = ("from pbrlab.commands import cli; import sys; "
            "sys.exit(cli.main(['eval', 'x', '--var', 'x=0:1:2']))")
    missing = str(tmp_path / "missing.so")
    env = {"PATH": "/usr/bin:/bin", "GLCONTEXT_LINUX_LIBEGL": missing,
           "GLCONTEXT_LINUX_LIBGL": missing, "PBRLAB_OSMESA_LIBRARY": missing}
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert out.returncode == 2, out.stderr
    assert "Traceback" not in out.stderr
    assert "apt-get install" in out.stderr and "libosmesa6" in out.stderr




_EGL_AFTER_OSMESA = textwrap.dedent("""
    import sys
    from pathlib import Path
    import numpy as np
    from pbrlab.gpu import gl
    from pbrlab.importers.gltf import load_gltf
    from pbrlab.render.renderer import render_scene
    root = Path(sys.argv[1])
    model = load_gltf(root / "corpus/gltf/khronos/ClearCoatCarPaint/ClearCoatCarPaint.glb", size=(128, 128),
                      emit_warnings=False).scene
    before = render_scene(model, gl.shared_context("egl")).linear
    other = load_gltf(root / "scenes/gltf/textured.gltf", size=(64, 64), emit_warnings=False).scene
    render_scene(other, gl.shared_context("osmesa"))  # the other front end, in this process
    after = render_scene(model, gl.shared_context("egl")).linear
    print(float(np.abs(before - after).max()))
""")


def test_an_egl_render_after_an_osmesa_render_is_the_same(tmp_path):
    """OSMesaMakeCurrent sets Mesa's shared dispatch behind EGL's back: an EGL context that
    EGL still recorded as current was not bound again, and its calls went to the OSMesa
    context (measured here: max difference 1.0; the Sample Renderer tests failed after the
    OSMesa pyrender tests in one pytest worker). In its own process, so the suite's order
    cannot hide it."""
    script = tmp_path / "egl_after_osmesa.py"
    script.write_text(_EGL_AFTER_OSMESA)
    out = subprocess.run([sys.executable, str(script), str(Path(__file__).resolve().parents[2])],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert float(out.stdout.strip().splitlines()[-1]) == 0.0
