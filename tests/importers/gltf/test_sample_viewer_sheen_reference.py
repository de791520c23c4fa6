"""reference/sample_viewer_sheen.py (the Khronos Sample Renderer's sheen, gltf-viewer 1.1.0)
against the viewer's formulas as its shaders write them, and
sample_viewer_prediction.viewer_minus_pbrlab_sheen's input checks. The prediction names, beside
the as-rendered check of test_sample_viewer_agreement.py, the formula behind each pixel where
the viewer lies beyond the bound."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.maths.reference import sample_viewer_sheen as viewer_sheen
from pbrlab.maths.reference import sheen as ref_sheen
from pbrlab.checking.sample_viewer_prediction import viewer_minus_pbrlab_sheen


def test_neubelt_visibility_is_the_viewers_ashikhmin_where_its_clamp_does_not_bind():
    """brdf.glsl V_Ashikhmin = clamp(1 / (4 (n·l + n·v - n·l n·v)), 0, 1): the prediction
    integrates lut_charlie.b with pbrlab's V_Neubelt, which has no clamp."""
    l, v = np.meshgrid(np.linspace(0.01, 1.0, 60), np.linspace(0.01, 1.0, 60))
    viewer = np.clip(1.0 / (4.0 * (l + v - l * v)), 0.0, 1.0)
    ours = ref_sheen.V_Neubelt(l, v)
    unclamped = (l + v - l * v) >= 0.25
    assert unclamped.mean() > 0.9
    np.testing.assert_allclose(ours[unclamped], viewer[unclamped], rtol=1e-12)
    assert not np.allclose(ours[~unclamped], viewer[~unclamped])


def test_the_viewers_empty_sheen_table_leaves_the_base_unscaled():
    assert viewer_sheen.VIEWER_SHEEN_TABLE_ALBEDO == 0.0
    np.testing.assert_array_equal(viewer_sheen.base_scaling(np.array([[1.0, 1.0, 1.0], [0.2, 0.9, 0.1]])), [1.0, 1.0])
    # the formula with a filled table (pbr.frag's 1 - max3(c) E)
    np.testing.assert_allclose(viewer_sheen.base_scaling(np.array([0.2, 0.9, 0.1]), 0.5), 0.55)


def test_coat_weight_is_one_minus_the_coats_schlick_fresnel():
    np.testing.assert_allclose(viewer_sheen.coat_weight(1.0, np.array([1.0, 0.0])), [0.96, 0.0])
    np.testing.assert_allclose(viewer_sheen.coat_weight(0.0, 0.3), 1.0)


def test_environment_sheen_is_sky_times_colour_times_albedo():
    got = viewer_sheen.environment_sheen([0.25, 0.3, 0.35], [[1.0, 0.5, 0.0]], np.array([0.4]))
    np.testing.assert_allclose(got, [[0.1, 0.06, 0.0]])


def test_an_unknown_sheen_difference_is_named():
    with pytest.raises(ValueError, match="unknown differences \\['fresnel'\\]"):
        viewer_minus_pbrlab_sheen(None, None, ("fresnel",))
