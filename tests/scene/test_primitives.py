"""The built-in meshes made in numpy (pbrlab.scene.primitives): the same triangles as
trimesh's (so untextured images do not change), UVs that follow the documented mappings,
tangents from them, and a scene of primitives that renders without importing trimesh."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from pbrlab.scene import meshes, primitives

# Parameters of every primitive a shipped scene or golden uses, plus the defaults.
SHAPES = {
    "uv_sphere": [{"radius": 1.0}, {"radius": 0.8}],
    "torus": [{"major_radius": 1.0, "minor_radius": 0.25}, {"major_radius": 0.6, "minor_radius": 0.2},
              {"major_radius": 0.45, "minor_radius": 0.1}],
    "icosphere": [{"radius": 1.0, "subdivisions": s} for s in (0, 1, 3, 5)] + [{"radius": 0.7, "subdivisions": 1}],
    "cylinder": [{"radius": 0.5, "height": 1.0}],
    "box": [{"size": 1.0}, {"size": 0.5}],
    "plane": [{"size": 1.0}, {"size": 12.0}],
}
CASES = [(kind, params) for kind, many in SHAPES.items() for params in many]


def _trimesh_of(kind, params):
    import trimesh

    if kind == "plane":  # made by hand before too: trimesh only held it
        s = params["size"] / 2
        vertices = np.array([[-s, 0, -s], [s, 0, -s], [s, 0, s], [-s, 0, s]], float)
        return trimesh.Trimesh(vertices, [[0, 2, 1], [0, 3, 2]], process=False)
    if kind == "box":
        return trimesh.creation.box(extents=[params["size"]] * 3)
    if kind == "icosphere":
        return trimesh.creation.icosphere(subdivisions=params["subdivisions"], radius=params["radius"])
    return getattr(trimesh.creation, kind)(**params)


@pytest.mark.parametrize("kind,params", CASES, ids=[f"{k}-{'-'.join(map(str, p.values()))}" for k, p in CASES])
def test_triangles_are_trimeshs_corner_for_corner(kind, params):
    """Every triangle's corners at the same float64 positions, in the same order and
    winding, as trimesh.creation's (vertices are split at seams, so compared per corner):
    exact equality, as untextured goldens stay bit-identical only then. Smooth normals
    equal trimesh's too (same operations in the same order); the box and the cylinder
    have hard edges instead: their normals are the face's (box), radial on the side and
    +-Z on the caps (cylinder)."""
    made = primitives.make(kind, dict(params))
    reference = _trimesh_of(kind, params)
    corners = made.positions[made.faces]
    assert np.array_equal(corners, np.asarray(reference.vertices)[reference.faces])
    normals = made.normals[made.faces]
    if kind in ("box", "cylinder"):
        edges = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        face = edges / np.linalg.norm(edges, axis=1, keepdims=True)
        cap = np.abs(face[:, 2]) > 0.999 if kind == "cylinder" else np.ones(len(face), bool)
        np.testing.assert_allclose(normals[cap], np.repeat(face[cap, None], 3, axis=1), atol=1e-12)
        radial = corners[~cap] * [1, 1, 0]
        np.testing.assert_allclose(normals[~cap], radial / np.linalg.norm(radial, axis=-1, keepdims=True), atol=1e-12)
    else:
        assert np.array_equal(normals, np.asarray(reference.vertex_normals)[reference.faces])


def _sphere_uv(points):
    """The documented spherical mapping: u = longitude / 2 pi in [0, 1), v = polar angle
    from -Z / pi."""
    u = (np.arctan2(points[..., 1], points[..., 0]) / (2 * np.pi)) % 1.0
    v = np.arccos(np.clip(-points[..., 2] / np.linalg.norm(points, axis=-1), -1, 1)) / np.pi
    return u, v


def _torus_uv(points, major):
    u = (np.arctan2(points[..., 1], points[..., 0]) / (2 * np.pi)) % 1.0
    ring = np.hypot(points[..., 0], points[..., 1]) - major
    v = (np.arctan2(points[..., 2], ring) / (2 * np.pi)) % 1.0
    return u, v


# float64 atan2/arccos of float64 positions: errors near 1e-15; 1e-9 leaves room for the
# positions' own rounding (1 ulp of the radius) through arccos near the poles (slope
# 1 / sqrt(1 - x^2) at v = 1/31: about 10), and is far below one grid step (1/64).
UV_EXACTNESS = 1e-9


@pytest.mark.parametrize("kind,params", [("uv_sphere", {"radius": 0.8}), ("icosphere", {"radius": 1.0, "subdivisions": 3}),
                                         ("torus", {"major_radius": 0.6, "minor_radius": 0.2})])
def test_uvs_follow_the_documented_mapping_with_the_seam_duplicated(kind, params):
    """Each vertex's UV is the mapping of its position up to a whole turn (the seam:
    u = 1 on the uv_sphere's and torus's duplicated column; on the icosphere, whose seam
    cuts through triangles, a seam-crossing triangle's low corners take u + 1, read with
    the repeat wrap), except at the sphere's poles (u is undefined); no triangle's u or v
    spans more than half the texture (a seam left unsplit makes a triangle run back across
    the whole texture: the control)."""
    made = primitives.make(kind, dict(params))
    if kind == "torus":
        u, v = _torus_uv(made.positions, params["major_radius"])
        v_seam = np.abs(made.uv[:, 1] - 1.0) < UV_EXACTNESS
        v = np.where(v_seam & (v < 0.5), v + 1.0, v)
    else:
        u, v = _sphere_uv(made.positions)
    pole = np.hypot(made.positions[:, 0], made.positions[:, 1]) < 1e-9 * np.linalg.norm(made.positions, axis=1)
    turns = made.uv[:, 0] - u
    assert np.abs(turns - np.round(turns))[~pole].max() < UV_EXACTNESS
    assert set(np.round(turns[~pole])) <= {0.0, 1.0}
    if kind != "icosphere":  # a whole turn only on the duplicated column
        assert np.all(made.uv[~pole & (np.round(turns) == 1), 0] == 1.0)
    assert np.abs(made.uv[:, 1] - v).max() < UV_EXACTNESS
    corner_uv = made.uv[made.faces]
    spans = corner_uv.max(axis=1) - corner_uv.min(axis=1)
    assert spans.max() < 0.5
    assert made.uv.min() >= 0 and made.uv[:, 1].max() <= 1
    assert made.uv[:, 0].max() <= (1 + spans[:, 0].max() if kind == "icosphere" else 1)
    naive_u = _sphere_uv(made.positions)[0] if kind != "torus" else _torus_uv(made.positions, params["major_radius"])[0]
    assert np.ptp(naive_u[made.faces], axis=1).max() > 0.9  # control: unsplit, the seam's triangles span it all


@pytest.mark.parametrize("size", [1.0, 0.5])
def test_each_box_face_spans_the_whole_texture(size):
    """Box: 6 faces x 4 corners, each face's UVs the four corners of [0, 1]^2."""
    made = primitives.box(size)
    assert len(made.positions) == 24
    for axis in range(3):
        for sign in (-1, 1):
            on_face = np.isclose(made.normals[:, axis], sign)
            assert sorted(map(tuple, made.uv[on_face])) == [(0, 0), (0, 1), (1, 0), (1, 1)]


def test_cylinder_side_and_caps_cover_the_texture():
    made = primitives.cylinder(0.5, 2.0)
    side = np.abs(made.normals[:, 2]) < 0.5
    np.testing.assert_allclose(made.uv[side, 1], (made.positions[side, 2] + 1.0) / 2.0)
    assert made.uv[side, 0].min() == 0 and made.uv[side, 0].max() == 1
    cap = ~side
    np.testing.assert_allclose(np.hypot(made.uv[cap, 0] - 0.5, made.uv[cap, 1] - 0.5),
                               np.hypot(made.positions[cap, 0], made.positions[cap, 1]), atol=1e-12)


# Degrees between a vertex's tangent and the direction its u grows along the surface:
# the per-vertex tangent averages the gradients of the triangles around it (Lengyel
# 2001), whose directions turn by at most one step of longitude across a vertex: 360/64 =
# 5.6 degrees on the uv_sphere, 360/32 = 11.25 on the torus and the cylinder's side, 0 on
# the box's flat faces (0.5 allowed there: far above float32 rounding, far below a wrong axis); on the icosphere an edge spans 63.4 / 2^s degrees of arc
# (the icosahedron's edge, halved per subdivision), that is (63.4 / 2^s) / sin(polar
# angle) of longitude (checked where that is under 30 degrees: sin > 0.3 at s = 3;
# measured 1.7 .. 10.7 there).
def _longitude_step_deg(kind, params, positions):
    if kind == "icosphere":
        return (63.43 / 2 ** params["subdivisions"]) / np.maximum(np.hypot(positions[:, 0], positions[:, 1]) / params["radius"], 1e-12)
    return np.full(len(positions), {"uv_sphere": 360 / 64, "box": 0.5}.get(kind, 360 / 32))


@pytest.mark.parametrize("kind,params", [("uv_sphere", {"radius": 1.0}), ("torus", {"major_radius": 1.0, "minor_radius": 0.25}),
                                         ("cylinder", {"radius": 0.5, "height": 1.0}), ("box", {"size": 1.0}),
                                         ("icosphere", {"radius": 1.0, "subdivisions": 3})])
def test_tangents_follow_u_and_are_right_handed(kind, params):
    """Tangents (meshes.vertex_arrays) point where u grows: on the revolved shapes along
    +longitude (-sin phi, cos phi, 0), on the box along each face's right; w = +1 (no UV
    mirrored). Control: the same mesh with all UVs zero (as trimesh gave) has tangents
    of no relation to u (its fallback)."""
    made = primitives.make(kind, dict(params))
    positions, normals, uv, tangents, _ = meshes.vertex_arrays(made)
    tangents = tangents.astype(np.float64)
    if kind == "box":
        expected = np.cross(np.where(np.abs(normals[:, 1:2]) > 0.5, [[0.0, 0, 1]] * -normals[:, 1:2], [[0.0, 1, 0]]), normals)
        keep = np.ones(len(positions), bool)
    else:
        phi = np.arctan2(positions[:, 1], positions[:, 0])
        expected = np.stack([-np.sin(phi), np.cos(phi), 0 * phi], axis=1)
        keep = np.hypot(positions[:, 0], positions[:, 1]) > 1e-6  # not at a pole / a cap's centre
        if kind == "cylinder":
            keep &= np.abs(normals[:, 2]) < 0.5  # the side; caps are planar maps
    step = _longitude_step_deg(kind, params, positions.astype(np.float64))
    keep &= step < 30
    cosine = np.sum(tangents[keep, :3] * expected[keep], axis=1)
    assert keep.sum() > (0.45 if kind == "cylinder" else 0.8) * len(keep)  # the cylinder: its side
    assert np.all(cosine > np.cos(np.radians(step[keep])))
    assert set(tangents[:, 3]) == {1.0}
    flat = meshes.tangents(positions.astype(np.float64), normals.astype(np.float64), np.zeros_like(uv, np.float64),
                           _.reshape(-1, 3).astype(np.int64))
    assert np.sum(flat[keep, :3] * expected[keep], axis=1).min() < 0.5  # control


ROOT = Path(__file__).resolve().parents[2]


def _modules_after_render(scene: Path, tmp_path: Path) -> set[str]:
    """Top-level modules loaded by a fresh ``pbrlab render`` of ``scene`` (size 32x20) on
    an empty disk cache: every mesh is made, none read back from an earlier run."""
    probe = (f"from pbrlab.commands import cli\n"
             f"assert cli.main(['render', {str(scene)!r}, '-o', {str(tmp_path / 'out.png')!r}, '--size', '32x20', '-q']) == 0\n"
             f"import sys, json\nprint(json.dumps(sorted({{m.split('.')[0] for m in sys.modules}})))")
    cache = tmp_path / f"cache-{scene.stem}"
    env = dict(os.environ, PBRLAB_CACHE_DIR=str(cache),
               PYTHONPATH=os.pathsep.join([str(Path(meshes.__file__).parents[2]), os.environ.get("PYTHONPATH", "")]))
    result = subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True, cwd=ROOT)
    assert result.returncode == 0, result.stderr[-2000:]
    assert any(cache.rglob("*")), "the render kept nothing in its disk cache: the meshes were not made"
    return set(json.loads(result.stdout.strip().splitlines()[-1]))


def test_a_first_render_of_primitives_never_imports_trimesh(tmp_path):
    """scenes/example.json (a torus and a plane, analytic spheres) on an empty disk cache:
    the primitives are made in numpy, so trimesh (and scipy under it) stays unloaded
    (main imported it: 0.7 s, about 43 % of the render's CPU). Control: the same scene
    with the torus read from an OBJ file does import trimesh, so the probe sees it."""
    loaded = _modules_after_render(ROOT / "scenes" / "example.json", tmp_path)
    assert "trimesh" not in loaded and "scipy" not in loaded
    scene = json.loads((ROOT / "scenes" / "example.json").read_text())
    obj = tmp_path / "tri.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    scene["objects"][2]["mesh"] = str(obj)
    control = tmp_path / "with_obj.json"
    control.write_text(json.dumps(scene))
    assert "trimesh" in _modules_after_render(control, tmp_path)
