"""A texture shows on the built-in meshes: a two-colour checker on uv_sphere, box, cylinder
and torus renders with both colours on the object. Main's primitives had no UVs (every
vertex at (0, 0)), so the whole object took one texel's colour: the control."""

import numpy as np
import pytest

from pbrlab.foundation import images
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene
from pbrlab.scene import meshes, primitives

RED, BLUE = (200, 30, 30), (30, 30, 200)   # sRGB codes of the checker's two squares
CHECKS, TEXELS_PER_CHECK = 8, 8            # an 8 x 8 checker of 8 x 8 texel squares
# The primitives stand along +Z; each camera sees a large part of the UV square.
VIEWS = {
    "uv_sphere": ({"primitive": "uv_sphere", "radius": 1.0}, [3.2, 0.8, 0.6]),
    "box": ({"primitive": "box", "size": 1.2}, [2.0, 1.4, 1.7]),
    "cylinder": ({"primitive": "cylinder", "radius": 0.6, "height": 1.4}, [2.6, 0.9, 1.6]),
    "torus": ({"primitive": "torus", "major_radius": 0.8, "minor_radius": 0.3}, [1.2, 1.0, 3.0]),
}
# A pixel counts as one colour when that channel is over twice the other (linear): a
# rough dielectric under a white uniform sky shows albedo (R/B = 38 for RED in linear)
# plus a grey specular of at most F(90 deg) = 1 at grazing silhouettes, so a pure square
# stays far over 2 and a filtered border between squares (R = B) counts as neither.
DOMINANCE = 2.0
# Each colour covers half of the UV area the camera sees, less the filtered borders
# between squares (neither colour); foreshortening weights squares by the cosine of the
# view, which moves a share only where a square is seen edge-on. Measured (96 x 96, llvmpipe):
# uv_sphere 0.446 / 0.449, box 0.396 / 0.399, cylinder 0.417 / 0.413, torus 0.443 / 0.445
# (red / blue); the UV-less control 0.000 / 0.000 (every pixel's r / (r + b) = 0.500).
# 20 % is under half the expected share (50 % less the borders), and a one-colour object
# has one share at 0 %.
SHARE = 0.20


def _checker(path):
    index = (np.arange(CHECKS * TEXELS_PER_CHECK) // TEXELS_PER_CHECK)
    odd = (index[:, None] + index[None, :]) % 2 == 1
    rgba = np.where(odd[..., None], np.array([*RED, 255], np.uint8), np.array([*BLUE, 255], np.uint8))
    images.write_png(path, rgba.astype(np.uint8))
    return path


def _shares(gl_context, tmp_path, mesh, eye):
    scene = {"camera": {"position": eye, "target": [0, 0, 0], "up": [0, 0, 1], "fov_y_deg": 40, "size": [96, 96]},
             "environment": {"color": [1.0, 1.0, 1.0]},
             "materials": {"m": {"workflow": "metallic", "albedo": [1, 1, 1], "metallic": 0.0, "smoothness": 0.0,
                                 "textures": {"albedo": str(_checker(tmp_path / "checker.png"))}}},
             "objects": [{"mesh": mesh, "material": "m"}]}
    linear = render_scene(parse_scene(scene, base=str(tmp_path)), gl_context).linear
    covered = linear[..., 3] > 0.99
    r, b = linear[..., 0][covered], linear[..., 2][covered]
    assert covered.sum() > 1000  # the object fills a good part of the frame
    return float(np.mean(r > DOMINANCE * b)), float(np.mean(b > DOMINANCE * r)), r / (r + b)


@pytest.fixture
def fresh_meshes(tmp_path, monkeypatch):
    """Meshes made anew (no disk or memory cache from another test or run)."""
    monkeypatch.setenv("PBRLAB_CACHE_DIR", str(tmp_path / "cache"))
    meshes._MESH_DATA.clear()
    yield
    meshes._MESH_DATA.clear()


@pytest.mark.parametrize("kind", list(VIEWS))
def test_a_checker_shows_both_colours_on_the_primitive(gl_context, tmp_path, fresh_meshes, kind):
    red, blue, _ = _shares(gl_context, tmp_path, *VIEWS[kind])
    assert red > SHARE and blue > SHARE, f"{kind}: red {red:.3f}, blue {blue:.3f} of the covered pixels"


def test_control_the_uv_less_sphere_shows_one_colour(gl_context, tmp_path, fresh_meshes, monkeypatch):
    """As main made it: trimesh's uv_sphere had no UVs, read as (0, 0) everywhere: the
    corner of four texels, filtered to one purple (neither colour dominant) over the
    whole sphere: the red share r / (r + b) of every covered pixel within 0.02 of the
    others (the checker's two colours differ by 0.95 in it)."""
    made = meshes._primitive

    def without_uvs(spec):
        mesh = made(spec)
        return primitives.Primitive(mesh.positions, mesh.normals, np.zeros_like(mesh.uv), mesh.faces)

    monkeypatch.setattr(meshes, "_primitive", without_uvs)
    red, blue, red_share = _shares(gl_context, tmp_path, *VIEWS["uv_sphere"])
    assert not (red > SHARE and blue > SHARE), f"red {red:.3f}, blue {blue:.3f}"
    assert np.ptp(red_share) < 0.02, f"red share {red_share.min():.3f} .. {red_share.max():.3f}"
