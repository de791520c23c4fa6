"""pbrlab's own renders of the glTF assets (scenes/gltf) at the high tier, as goldens; the
same renders through the HLSL library (read-only against the GLSL golden) and through the
full runtime-branching program (bit-identical). Their independent checks: pyrender
(test_gltf_pyrender.py) and, for the layered assets' untextured materials, the float64 CPU
renderer (test_layered_goldens_cpu.py)."""

import numpy as np
import pytest

from pbrlab.checking.golden_scenes import GLTF_GOLDENS, gltf_scene as _scene
from pbrlab.render.renderer import render_scene

CASES = list(GLTF_GOLDENS.values())
_GOLDEN_NAME = {case: name for name, case in GLTF_GOLDENS.items()}


def _golden_name(name, environment):
    return _GOLDEN_NAME[(name, environment)]


@pytest.mark.parametrize("name, environment", CASES)
def test_gltf_asset_matches_golden(name, environment, gl_context, golden):
    rendering = render_scene(_scene(name, environment), gl_context)
    assert np.isfinite(rendering.linear).all() and (rendering.linear >= 0).all()
    golden.check(_golden_name(name, environment), rendering.linear, rendering.srgb8)


@pytest.mark.parametrize("name, environment", CASES)
def test_gltf_asset_in_hlsl_matches_glsl_golden(name, environment, gl_context, golden):
    rendering = render_scene(_scene(name, environment), gl_context, language="hlsl")
    golden.check(_golden_name(name, environment), rendering.linear, rendering.srgb8, read_only=True)


@pytest.mark.parametrize("name, environment", CASES)
def test_gltf_asset_full_program_is_bit_identical(name, environment, gl_context):
    specialised = render_scene(_scene(name, environment), gl_context)
    full = render_scene(_scene(name, environment), gl_context, specialise=False)
    assert specialised.programs.specialised and not full.programs.specialised
    if name == "features.gltf" and environment is None:
        # An emissive material under a spot light differs by up to 1 float32 ulp between the
        # two programs (measured: 2.4e-7 at 2.7); main shows the same with a JSON scene (an
        # emissive plane under a spot light: 1900 of 2916 pixels), so it is the shared scene
        # shading's, not the glTF path's. Bound: 2^-22 relative (two ulps).
        np.testing.assert_allclose(full.linear, specialised.linear, rtol=2.0 ** -22, atol=0)
        return
    assert np.array_equal(specialised.linear, full.linear)
