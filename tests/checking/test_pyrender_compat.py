"""pyrender 0.1.45 works headless here despite its PyOpenGL pin and numpy 2 (see docs/getting-started.md)."""

import subprocess
import sys
import textwrap

import pytest

SCRIPT = textwrap.dedent("""
    import sys
    import numpy as np
    import trimesh
    from pbrlab.checking.pyrender.compat import import_pyrender
    pyrender = import_pyrender(sys.argv[1])
    import OpenGL
    assert OpenGL.__version__ == "3.1.10", OpenGL.__version__
    scene = pyrender.Scene(ambient_light=[0.0, 0.0, 0.0])
    scene.add(pyrender.Mesh.from_trimesh(trimesh.creation.icosphere(subdivisions=2)))
    pose = np.eye(4); pose[2, 3] = 4.0
    scene.add(pyrender.PerspectiveCamera(yfov=0.8), pose=pose)
    scene.add(pyrender.DirectionalLight(intensity=3.0), pose=pose)
    renderer = pyrender.OffscreenRenderer(64, 64)
    color, depth = renderer.render(scene)
    renderer.delete()
    print(int(color[32, 32].sum() > 0), int((depth > 0).sum()))
""")


@pytest.mark.parametrize("platform", ["egl", "osmesa"])
def test_pyrender_renders_a_lit_sphere_headless(platform):
    out = subprocess.run([sys.executable, "-c", SCRIPT, platform], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr[-2000:]
    lit, covered = map(int, out.stdout.split())
    assert lit == 1 and 500 < covered < 64 * 64
