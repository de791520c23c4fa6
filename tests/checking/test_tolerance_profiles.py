"""The golden tolerance profiles: llvmpipe (bit-identical renders) and gpu (measured on a
real GPU). The gpu profile is loose enough for a GPU's filtering and transcendental
precision, and must stay tight enough to catch a real change of the scene."""

import numpy as np
import pytest

from pbrlab.checking import goldens
from pbrlab.checking.compare import TOLERANCE_PROFILES, diff, profile_for_renderer, tolerance_profile
from pbrlab.foundation.errors import PbrlabError
from pbrlab.checking.golden_scenes import lit_scene
from pbrlab.render.renderer import render_scene


@pytest.fixture(scope="module")
def lit_high():
    return render_scene(lit_scene("high"))


def _passes(profile, expected, obtained):
    return (diff(expected.linear, obtained.linear, profile.linear).passed
            and diff(expected.srgb8, obtained.srgb8, profile.srgb).passed)


def test_profile_follows_the_renderer():
    assert profile_for_renderer("llvmpipe (LLVM 15.0.6, 128 bits)").name == "llvmpipe"
    assert profile_for_renderer("NVIDIA H200/PCIe/SSE2").name == "gpu"
    assert tolerance_profile("auto", "AMD Radeon RX 7900 XTX").name == "gpu"
    with pytest.raises(ValueError, match="unknown tolerance profile"):
        tolerance_profile("gpus")


@pytest.mark.parametrize("change, amount", [("albedo", 0.9), ("intensity", 1.05), ("exposure", 0.1)])
def test_gpu_profile_rejects_a_real_change_of_the_scene(change, amount, lit_high):
    scene = lit_scene("high")
    if change == "albedo":  # a 10 % darker colour on one material
        material = next(m for m in scene.materials.values() if m.surface is None)
        material.albedo = material.albedo * amount
    elif change == "intensity":  # one light 5 % brighter
        scene.lights[0].intensity *= amount
    else:  # a tenth of a stop of exposure: the display image only
        scene.render.exposure += amount
    changed = render_scene(scene)
    assert _passes(TOLERANCE_PROFILES["gpu"], lit_high, lit_high)
    assert not _passes(TOLERANCE_PROFILES["gpu"], lit_high, changed), change


def test_gpu_profile_fails_on_flip_where_the_pixel_fraction_passes(lit_high):
    """Two changes each within 1 % of pixels over 1 code, each failed by the FLIP bound: a
    white block on 0.85 % of the image (measured FLIP 9.8e-3), and every code one brighter
    (0 % over 1 code; FLIP 2.8e-2, mostly from the black background)."""
    srgb = TOLERANCE_PROFILES["gpu"].srgb
    block = lit_high.srgb8.copy()
    side = int(np.sqrt(0.0085 * block.shape[0] * block.shape[1]))
    block[100:100 + side, 100:100 + side, :3] = 255
    brighter = lit_high.srgb8.copy()
    brighter[..., :3] = np.clip(brighter[..., :3].astype(int) + 1, 0, 255).astype(np.uint8)
    for changed in (block, brighter):
        result = diff(lit_high.srgb8, changed, srgb)
        assert result.fraction_over <= srgb.max_fraction
        assert result.flip_mean > srgb.max_flip and not result.passed


def test_golden_sidecar_records_the_profile(tmp_path, lit_high):
    info = {"GL_RENDERER": "llvmpipe (LLVM 15.0.6, 128 bits)"}
    goldens.check_golden("g", lit_high.linear, lit_high.srgb8, info=info, update=True,
                         root=tmp_path, output_dir=tmp_path / "out")
    import json
    sidecar = json.loads((tmp_path / "g.json").read_text())
    assert sidecar["tolerance_profile"] == "llvmpipe"
    assert set(sidecar["tolerance_profiles"]) == set(TOLERANCE_PROFILES)
    gpu = {"GL_RENDERER": "NVIDIA H200/PCIe/SSE2"}
    with pytest.raises(goldens.GoldenMismatch, match="tolerance profile gpu"):
        bad = lit_high.linear.copy()
        bad[..., :3] *= 1.5
        goldens.check_golden("g", bad, lit_high.srgb8, info=gpu, update=False, root=tmp_path,
                             output_dir=tmp_path / "out")
    with pytest.raises(PbrlabError, match="unknown tolerance profile"):
        goldens.check_golden("g", lit_high.linear, lit_high.srgb8, info=gpu, update=False,
                             root=tmp_path, output_dir=tmp_path / "out", profile="fast")
