"""glTF files rendered by pyrender 0.1.45, which reads them itself (trimesh's glTF reader:
nodes, meshes, materials, textures), against pbrlab's importer lit with pyrender's terms
(pbrlab.checking.pyrender.gltf_check), through both backends. Through EGL pyrender resolves 4x
MSAA, which also blends the edges between overlapping objects (a sphere over the floor:
up to 87 codes), and the coverage-based silhouette mask does not see those; pyrender's own
OSMesa render (single-sampled) finds them: pixels where pyrender's EGL and OSMesa codes
differ by more than 2 (the MSAA allowance of pyrender_check) are left out of the EGL
comparison."""

import math
from pathlib import Path

import numpy as np
import pytest

from pbrlab.gpu import gl
from pbrlab.checking.pyrender import check as pc
from pbrlab.checking.pyrender.gltf_check import render_pbrlab_gltf_terms, render_pyrender_gltf_files

ASSETS = Path(__file__).resolve().parents[3] / "scenes" / "gltf"
SIZE = (384, 192)
MSAA_EDGE_CODES = 2  # pyrender_check: its 4x MSAA moves interior codes by up to 2

# Per backend and asset, the tolerance: pyrender_check's (OSMesa 0.05 code: float32
# rounding at a code boundary; EGL 2.5 codes: MSAA) unless the asset needs more, with why.
_TRANSFORM = pc.CodeTolerance(
    # pyrender samples UVs transformed on the CPU (make_assets.py), pbrlab transforms them in
    # the shader; llvmpipe's bilinear weights have 8 fractional bits, so the float32
    # difference of the two UVs can move a weight by 1/256 of a texel step: at the
    # checker's largest step (155 codes) 0.61 code. Measured: 0.36 code on 2 of 13560 pixels.
    0.65, 0.05, 0.001, "bilinear weights quantised to 1/256: 155-code texel step / 256")
# BLEND: pyrender blends into its 8-bit target, whose destination value is already rounded
# (up to 0.5 code x (1 - alpha) = 0.25) and whose blend unit works with alpha in 8 bits
# (|src - dst| x 0.5/255, up to 0.5 code): 0.75 code on the blended quad (a third of the
# compared pixels). Measured: worst 0.64, 27 % of pixels over 0.05.
_BLEND = pc.CodeTolerance(0.75, 0.05, 0.35, "8-bit blending: rounded destination, 8-bit alpha")
TOLERANCES = {
    "osmesa": {"hierarchy_lights.glb": pc.TOLERANCE["osmesa"], "textured.gltf": pc.TOLERANCE["osmesa"],
               "texture_transform.pyrender.gltf": _TRANSFORM, "alpha_modes.glb": _BLEND},
    "egl": {"hierarchy_lights.glb": pc.TOLERANCE["egl"], "textured.gltf": pc.TOLERANCE["egl"],
            "texture_transform.pyrender.gltf": pc.TOLERANCE["egl"],
            "alpha_modes.glb": pc.CodeTolerance(2.5, 0.05, 0.35, "MSAA (2.5 codes) and 8-bit blending")},
}
ASSET_NAMES = sorted(TOLERANCES["osmesa"])


_PYRENDER: dict = {}


def _pyrender(name, platform):
    """pyrender's render of an asset: all assets in one subprocess per platform, once."""
    if (name, platform) not in _PYRENDER:
        images = render_pyrender_gltf_files([ASSETS / n for n in ASSET_NAMES], platform, SIZE)
        _PYRENDER.update({(n, platform): image for n, image in zip(ASSET_NAMES, images)})
    return _PYRENDER[name, platform]


@pytest.fixture(scope="module", params=gl.BACKENDS)
def backend(request):
    return request.param


@pytest.fixture(scope="module")
def renders(backend):
    ctx = gl.shared_context(backend)
    out = {}
    for name in ASSET_NAMES:
        pyr = _pyrender(name, backend)
        ours = render_pbrlab_gltf_terms(ASSETS / name, ctx, SIZE)
        mask = pc.comparison_mask(pyr, ours)
        if backend == "egl":
            single = _pyrender(name, "osmesa")
            mask &= np.abs(pyr.rgb8.astype(int) - single.rgb8.astype(int)).max(axis=-1) <= MSAA_EDGE_CODES
        out[name] = (pyr, ours, mask)
    return out


@pytest.fixture(scope="module")
def ctx(backend):
    return gl.shared_context(backend)


@pytest.mark.parametrize("name", ASSET_NAMES)
def test_gltf_asset_matches_pyrender_8bit_output(name, renders, backend):
    pyr, ours, mask = renders[name]
    assert mask.sum() > 0.6 * (ours[..., 3] > 0).sum()  # most covered pixels are compared
    ok, message = TOLERANCES[backend][name].check(pyr, ours, mask)
    print(name, pc.agreement(pyr, ours, mask).summary())
    assert ok, message


@pytest.mark.parametrize("name", ["hierarchy_lights.glb", "textured.gltf"])
def test_gltf_nodes_and_camera_cover_the_same_pixels_as_pyrender(name, renders, backend):
    # Node transforms (TRS and matrix), primitives and camera placed by two readers: the
    # coverages are equal pixel for pixel single-sampled (same rasteriser), and differ only
    # on silhouette pixels under MSAA.
    pyr, ours, _ = renders[name]
    covered = ours[..., 3] > 0
    if backend == "osmesa":
        assert np.array_equal(pyr.coverage, covered)
    else:
        silhouette = (pyr.coverage | covered) & ~(pc.erode(pyr.coverage, 1) & pc.erode(covered, 1))
        assert not np.any((pyr.coverage ^ covered) & ~silhouette)


def test_mask_discards_what_pyrender_draws_translucent(renders):
    # pyrender has no alphaCutoff (it blends MASK materials): where the disc texture's
    # alpha is 0.2 pyrender draws, pbrlab discards; inside the disc both draw.
    pyr, ours, _ = renders["alpha_modes.glb"]
    pbrlab_only = (ours[..., 3] > 0) & ~pyr.coverage
    pyrender_only = pyr.coverage & ~(ours[..., 3] > 0)
    assert pbrlab_only.sum() == 0 and pyrender_only.sum() > 1000


def test_light_units_must_be_converted_from_gltf(ctx, renders, backend, monkeypatch):
    # pbrlab's importer divides glTF intensities by pi (pbrlab.importers.gltf.lights); without it the
    # image is pi times too bright and the comparison fails.
    from pbrlab.importers.gltf import lights

    monkeypatch.setattr(lights, "GLTF_TO_PBRLAB_INTENSITY", 1.0)
    pyr, _, mask = renders["hierarchy_lights.glb"]
    wrong = render_pbrlab_gltf_terms(ASSETS / "hierarchy_lights.glb", ctx, SIZE)
    ok, _ = TOLERANCES[backend]["hierarchy_lights.glb"].check(pyr, wrong, mask)
    assert not ok


def test_gltf_roughness_must_be_perceptual(ctx, renders, backend, monkeypatch):
    # glTF's roughness is perceptual (alpha = roughness^2): mapping it to smoothness as if
    # it were alpha (smoothness = 1 - sqrt(roughness)) must break the match.
    from pbrlab.importers.gltf import materials

    original = materials.MaterialReader.material

    def as_alpha(self, index, vertex_color):
        m = original(self, index, vertex_color)
        m.smoothness = 1.0 - math.sqrt(1.0 - m.smoothness)
        return m

    monkeypatch.setattr(materials.MaterialReader, "material", as_alpha)
    pyr, _, mask = renders["hierarchy_lights.glb"]
    wrong = render_pbrlab_gltf_terms(ASSETS / "hierarchy_lights.glb", ctx, SIZE)
    ok, _ = TOLERANCES[backend]["hierarchy_lights.glb"].check(pyr, wrong, mask)
    assert not ok
