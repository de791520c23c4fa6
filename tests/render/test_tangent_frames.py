"""pbrlab.render.tangent_frames' bound is a lower bound: over random triangles whose tangent
frames it accepts, the Gram-Schmidt tangent |T x N/|N|| (float64) at barycentric weights
down to -OUTSIDE is never below it; and it refuses the frames that do degenerate (controls:
tangents turning through the normal's direction inside the triangle, tangents along the
normal). A similarity transform scales the bound by its scale (the shortcut needs_fallback
takes for instances) and a shear is checked in world space. The sampling catches a wrong
bound: one that keeps only the cross products u_i x v_i (no i != j terms) fails it (measured:
a spread-0.05 triangle's least |t| 2.1918 under that bound's 2.1950)."""

import numpy as np
import pytest

from pbrlab.render import tangent_frames as tf


def _gs_length(tangents, normals, weights):
    """|T - n (n.T)| at each row of ``weights`` (float64): what the shader's |t| is."""
    T = weights @ tangents
    N = weights @ normals
    n = N / np.linalg.norm(N, axis=1, keepdims=True)
    return np.linalg.norm(T - n * np.sum(n * T, axis=1, keepdims=True), axis=1)


def _weights(rng, count):
    """Barycentric weights >= -OUTSIDE (the grown triangle), its corners among them."""
    w = rng.dirichlet((0.3, 0.3, 0.3), count)
    w = (1 + 3 * tf.OUTSIDE) * w - tf.OUTSIDE
    corners = (1 + 3 * tf.OUTSIDE) * np.eye(3) - tf.OUTSIDE
    return np.vstack([w, corners])


def _frames(rng, spread):
    """Three vertex frames: a common normal and tangent, each perturbed by ``spread`` and
    re-orthogonalised (valid per-vertex tangents), tangents scaled as a model matrix might."""
    n0 = rng.normal(size=3)
    n0 /= np.linalg.norm(n0)
    normals = n0 + spread * rng.normal(size=(3, 3))
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    t0 = np.cross(n0, rng.normal(size=3))
    tangents = t0 / np.linalg.norm(t0) + spread * rng.normal(size=(3, 3))
    tangents -= normals * np.sum(normals * tangents, axis=1, keepdims=True)
    tangents *= rng.uniform(0.2, 3.0, size=(3, 1)) / np.linalg.norm(tangents, axis=1, keepdims=True)
    return tangents, normals


def test_the_bound_is_never_above_the_tangent_it_bounds():
    rng = np.random.default_rng(35)
    accepted = 0
    for spread in (0.05, 0.3, 0.8):
        for _ in range(300):
            tangents, normals = _frames(rng, spread)
            margin = tf.frame_bound(tangents[None], normals[None])[0]
            if margin <= 0:
                continue
            accepted += 1
            threshold = tf.FALLBACK_TAKEN_BELOW + tf.ROUNDING_ULPS * 2.0 ** -24 * np.linalg.norm(
                tf._grown(tangents[None])[0], axis=1).max()
            lowest = _gs_length(tangents, normals, _weights(rng, 2000)).min()
            assert lowest >= margin + threshold - 1e-12, (spread, lowest, margin + threshold)
    assert accepted > 300  # measured: 719 of the 900 triangles accepted


def test_tangents_turning_through_the_normal_inside_the_triangle_are_refused():
    """+x and -x at two corners: T = 0 halfway along their edge (the control)."""
    normals = np.tile([0.0, 0.0, 1.0], (3, 1))
    tangents = np.array([[1.0, 0, 0], [-1.0, 0, 0], [0, 1.0, 0]])
    assert tf.frame_bound(tangents[None], normals[None])[0] <= 0
    assert _gs_length(tangents, normals, np.array([[0.5, 0.5, 0.0]]))[0] == 0


def test_tangents_along_the_normal_are_refused_and_a_flat_frame_accepted():
    normals = np.tile([0.0, 1.0, 0.0], (3, 1))
    assert tf.frame_bound(normals[None].copy(), normals[None])[0] == -np.inf
    tangents = np.tile([1.0, 0.0, 0.0], (3, 1))
    np.testing.assert_allclose(tf.frame_bound(tangents[None], normals[None])[0],
                               1.0 - tf.FALLBACK_TAKEN_BELOW - tf.ROUNDING_ULPS * 2.0 ** -24, rtol=1e-12)


class _Mesh:
    """What needs_fallback reads of an object: its transform and (through mesh_data) arrays."""
    def __init__(self, transform):
        self.transform = transform
        self.geometry = None
        self.sphere = None


@pytest.mark.parametrize("scale", [1.0, 1e-3, 1e-7])
def test_a_similarity_scales_the_bound(monkeypatch, scale):
    """Rotation times ``scale``: the tangents shrink by the scale, and at 1e-7 every |t| is
    under the fallback's 1e-6, so it is needed (the harness's old program took it there)."""
    from pbrlab.scene import meshes

    rng = np.random.default_rng(7)
    tangents, normals = _frames(rng, 0.05)
    arrays = (None, normals.astype(np.float32), None,
              np.hstack([tangents, np.ones((3, 1))]).astype(np.float32), np.arange(3, dtype=np.int32))
    monkeypatch.setattr(meshes, "mesh_data", lambda obj: type("M", (), {"arrays": arrays})())
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    transform = np.eye(4)
    transform[:3, :3] = scale * q
    world = tf._world_margin(arrays, "triangles", transform)
    assert tf.needs_fallback([_Mesh(transform)]) == (world <= 0)
    assert tf.needs_fallback([_Mesh(transform)]) == (scale == 1e-7)
    shear = transform.copy()
    shear[0, 1] += 0.5 * scale  # not a similarity: the world-space path
    assert tf.needs_fallback([_Mesh(shear)]) == (tf._world_margin(arrays, "triangles", shear) <= 0)
