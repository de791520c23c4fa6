"""glTF files rendered by pyrender 0.1.45, which reads them itself (trimesh's glTF reader:
nodes, meshes, materials, textures), against pbrlab's importer lit with pyrender's terms
(pbrlab.pyrender_gltf_check). Compared through OSMesa, where pyrender renders single-
sampled: through EGL its 4x MSAA also blends the edges between overlapping objects
(a sphere over the floor), which the coverage-based silhouette mask does not remove
(measured: worst 87 codes on those edges, 0 inside)."""

import math
from pathlib import Path

import numpy as np
import pytest

from pbrlab import gl
from pbrlab import pyrender_check as pc
from pbrlab.pyrender_gltf_check import render_pbrlab_gltf_terms, render_pyrender_gltf

ASSETS = Path(__file__).resolve().parents[2] / "scenes" / "gltf"
SIZE = (384, 192)
BACKEND = "osmesa"

# Per asset, the tolerance: pyrender_check's single-sample one (0.05 code: float32 rounding
# at a code boundary) unless the asset needs more, with the reason.
TOLERANCES = {
    "hierarchy_lights.glb": pc.TOLERANCE[BACKEND],
    "textured.gltf": pc.TOLERANCE[BACKEND],
    # pyrender samples UVs transformed on the CPU (make_assets.py), pbrlab transforms them in
    # the shader; llvmpipe's bilinear weights have 8 fractional bits, so the float32
    # difference of the two UVs can move a weight by 1/256 of a texel step: at the
    # checker's largest step (155 codes) 0.61 code. Measured: 0.36 code on 2 of 13560 pixels.
    "texture_transform.pyrender.gltf": pc.CodeTolerance(
        0.65, 0.05, 0.001, "bilinear weights quantised to 1/256: 155-code texel step / 256"),
    # BLEND: pyrender blends into its 8-bit target, whose destination value is already
    # rounded (up to 0.5 code x (1 - alpha) = 0.25) and whose blend unit works with alpha in
    # 8 bits (|src - dst| x 0.5/255, up to 0.5 code): bound 0.75 code on the blended quad
    # (a third of the image). Measured: worst 0.64, 27 % of pixels over 0.05.
    "alpha_modes.glb": pc.CodeTolerance(
        0.75, 0.05, 0.35, "8-bit blending: rounded destination and 8-bit alpha in the blend unit"),
}


@pytest.fixture(scope="module")
def ctx():
    if BACKEND not in gl.BACKENDS:
        pytest.fail(f"the {BACKEND} backend is missing: the glTF cross-check needs pyrender's single-sample path")
    return gl.shared_context(BACKEND)


@pytest.fixture(scope="module")
def renders(ctx):
    out = {}
    for name in TOLERANCES:
        pyr = render_pyrender_gltf(ASSETS / name, BACKEND, SIZE)
        ours = render_pbrlab_gltf_terms(ASSETS / name, ctx, SIZE)
        out[name] = (pyr, ours, pc.comparison_mask(pyr, ours))
    return out


@pytest.mark.parametrize("name", sorted(TOLERANCES))
def test_gltf_asset_matches_pyrender_8bit_output(name, renders):
    pyr, ours, mask = renders[name]
    assert mask.sum() > 0.6 * (ours[..., 3] > 0).sum()  # most covered pixels are compared
    ok, message = TOLERANCES[name].check(pyr, ours, mask)
    print(name, pc.agreement(pyr, ours, mask).summary())
    assert ok, message


@pytest.mark.parametrize("name", ["hierarchy_lights.glb", "textured.gltf"])
def test_gltf_nodes_and_camera_cover_the_same_pixels_as_pyrender(name, renders):
    # Node transforms (TRS and matrix), primitives and camera placed by two readers: the
    # coverages are equal pixel for pixel (single-sampled, same rasteriser).
    pyr, ours, _ = renders[name]
    assert np.array_equal(pyr.coverage, ours[..., 3] > 0)


def test_mask_discards_what_pyrender_draws_translucent(renders):
    # pyrender has no alphaCutoff (it blends MASK materials): where the disc texture's
    # alpha is 0.2 pyrender draws, pbrlab discards; inside the disc both draw.
    pyr, ours, _ = renders["alpha_modes.glb"]
    pbrlab_only = (ours[..., 3] > 0) & ~pyr.coverage
    pyrender_only = pyr.coverage & ~(ours[..., 3] > 0)
    assert pbrlab_only.sum() == 0 and pyrender_only.sum() > 1000


def test_light_units_must_be_converted_from_gltf(ctx, renders, monkeypatch):
    # pbrlab's importer divides glTF intensities by pi (pbrlab.gltf.lights); without it the
    # image is pi times too bright and the comparison fails.
    from pbrlab.gltf import lights

    monkeypatch.setattr(lights, "GLTF_TO_PBRLAB_INTENSITY", 1.0)
    pyr, _, mask = renders["hierarchy_lights.glb"]
    wrong = render_pbrlab_gltf_terms(ASSETS / "hierarchy_lights.glb", ctx, SIZE)
    ok, _ = pc.TOLERANCE[BACKEND].check(pyr, wrong, mask)
    assert not ok


def test_gltf_roughness_must_be_perceptual(ctx, renders, monkeypatch):
    # glTF's roughness is perceptual (alpha = roughness^2): mapping it to smoothness as if
    # it were alpha (smoothness = 1 - sqrt(roughness)) must break the match.
    from pbrlab.gltf import materials

    original = materials.MaterialReader.material

    def as_alpha(self, index, vertex_color):
        m = original(self, index, vertex_color)
        m.smoothness = 1.0 - math.sqrt(1.0 - m.smoothness)
        return m

    monkeypatch.setattr(materials.MaterialReader, "material", as_alpha)
    pyr, _, mask = renders["hierarchy_lights.glb"]
    wrong = render_pbrlab_gltf_terms(ASSETS / "hierarchy_lights.glb", ctx, SIZE)
    ok, _ = pc.TOLERANCE[BACKEND].check(pyr, wrong, mask)
    assert not ok
