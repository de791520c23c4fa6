"""The transmission copy from a glTF file (scenes/gltf/transmission_slab.gltf, built by
make_assets.py): three glass slabs half over an emissive backdrop, no light and no
environment, so each slab shows only the backdrop through it. Where a slab covers the
backdrop, its pixels are the backdrop's own render (the file without the slabs) times the
fraction the slab transmits, computed per pixel in float64 from pbrlab.maths.reference
(cpu_render.transmitted_fraction: rho (1 - E_spec) x Beer-Lambert, at the pixel's exact
view), in GLSL and in HLSL; where it does not, it shows black (the copy is empty there and
there is no environment)."""

import numpy as np
import pytest
from scipy import ndimage

from pbrlab.maths.camera import camera_rays
from pbrlab.render.cpu_render import transmitted_fraction
from pbrlab.render.depth_range import scene_frame
from pbrlab.checking.golden_scenes import GLTF_DIR, GLTF_SIZE
from pbrlab.importers.gltf import load_gltf
from pbrlab.render.renderer import render_scene

SLABS = {"thin_ior_1": -1.5, "thin_ior_1_5": 0.0, "tinted_volume": 1.5}  # material: the slab's x
SLAB_HALF = 0.5   # the unit quads of make_assets.transmission_slab
# |through - backdrop x fraction| <= RTOL x expected. Measured worst (llvmpipe, GLSL and HLSL
# alike): 0 through the IOR-1 wall, 3.7e-8 relative at IOR 1.5, 1.7e-7 through the volume (its
# exp2/log2); 1e-5 is 60 times that and 1/100 of the CPU comparisons' 1e-3
# (test_gpu_matches_cpu_reference.py), which covers the DFG table's interpolation at grazing
# views, not met on these nearly face-on slabs.
RTOL = 1e-5


def _scene():
    return load_gltf(GLTF_DIR / "transmission_slab.gltf", size=GLTF_SIZE, emit_warnings=False).scene


def _slab_pixels(scene):
    """material -> (the pixels where the camera ray meets that slab at z = 0, eroded by 2
    pixels from its edges; the pixels' views)."""
    frame = scene_frame(scene)
    d = camera_rays(frame)
    t = -frame.position[2] / d[..., 2]
    p = frame.position + t[..., None] * d
    out = {}
    for name, x in SLABS.items():
        inside = (np.abs(p[..., 0] - x) < SLAB_HALF) & (np.abs(p[..., 1]) < SLAB_HALF)
        out[name] = (ndimage.binary_erosion(inside, iterations=2), -d)
    return out


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_each_slab_passes_the_backdrop_times_its_float64_fraction(language, gl_context):
    scene = _scene()
    through = render_scene(scene, gl_context, language=language).linear.astype(np.float64)
    backdrop_only = _scene()
    backdrop_only.objects = [o for o in backdrop_only.objects if o.material == "backdrop"]
    backdrop = render_scene(backdrop_only, gl_context, language=language).linear.astype(np.float64)
    # 3 pixels from the backdrop's edge: the copy's mip 8 x 0.045 = 0.36 blurs it over about 2
    lit = ndimage.binary_erosion(backdrop[..., 3] > 0, iterations=3)
    dark = ~ndimage.binary_dilation(backdrop[..., 3] > 0, iterations=3)
    for name, (inside, v) in _slab_pixels(scene).items():
        seen = inside & lit
        assert seen.sum() > 200, (name, seen.sum())
        fraction = transmitted_fraction(scene, scene.materials[name], np.tile([0.0, 0.0, 1.0], (seen.sum(), 1)), v[seen])
        expected = backdrop[seen][:, :3] * fraction
        err = np.abs(through[seen][:, :3] - expected)
        assert np.all(err <= RTOL * expected), (name, float((err / expected).max()))
        nothing = inside & dark  # above the backdrop: black, the copy empty there
        assert nothing.sum() > 50 and through[nothing][:, :3].max() == 0.0, name
    # the fractions are the physics': 1 through an IOR-1 wall, 1 - E_spec (0.96 face-on) at
    # IOR 1.5, and Beer-Lambert's c^(0.3 / 0.5) on top for the volume
    centre = np.array([[0.0, 0.0, 1.0]])
    assert np.allclose(transmitted_fraction(scene, scene.materials["thin_ior_1"], centre, centre), 1.0, atol=1e-12)
    thin = transmitted_fraction(scene, scene.materials["thin_ior_1_5"], centre, centre)
    volume = transmitted_fraction(scene, scene.materials["tinted_volume"], centre, centre)
    assert 0.955 < thin[0, 0] < 0.961
    np.testing.assert_allclose(volume / thin, [np.array([0.4, 0.7, 0.9]) ** 0.6], rtol=1e-12)
