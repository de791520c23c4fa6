"""Generated tangents follow the UVs the normal map is read with (KHR_texture_transform's
rotation and scale) and split where a mirror seam shares its vertices (mikktspace.c's split
by UV orientation). The references are the same quad with its UVs transformed beforehand
(no extension), and the two sides of a mirrored pair of triangles (a tangent each)."""

import math

import numpy as np
import pytest

from pbrlab.importers.gltf import load_gltf
from pbrlab.render.renderer import render_scene

from gltf_helpers import blob, quad_document, set_blob, write

OFFSET, ROTATION, SCALE = (0.25, -0.1), 0.7, (2.0, 0.5)
UV = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.float64)  # quad_document's TEXCOORD_0


def _transformed(uv):
    """The extension's uv' = T(offset) R(rotation) S(scale) uv (its README, "Overview")."""
    c, s = math.cos(ROTATION), math.sin(ROTATION)
    scaled = uv * SCALE
    return np.stack([c * scaled[:, 0] + s * scaled[:, 1], -s * scaled[:, 0] + c * scaled[:, 1]], 1) + OFFSET


def _normal_map(tmp_path):
    """A 16x16 normal map whose normals lean along +X in one half and +Y in the other: a
    tangent frame turned the wrong way lights it differently."""
    from pbrlab.foundation import images
    texels = np.zeros((16, 16, 4), np.uint8)
    texels[..., 3] = 255
    lean = np.array([[0.5, 0.0, 0.866], [0.0, 0.5, 0.866]])
    for half in range(2):
        texels[:, half * 8:(half + 1) * 8, :3] = np.round((lean[half] * 0.5 + 0.5) * 255)
    images.write_png(tmp_path / "normal.png", texels)
    return "normal.png"


def _quad(tmp_path, name, transformed_beforehand):
    doc = quad_document()
    info = {"index": 0}
    if transformed_beforehand:
        data = bytearray(blob(doc))
        data[96:128] = _transformed(UV).astype(np.float32).tobytes()
        set_blob(doc, bytes(data))
    else:
        info["extensions"] = {"KHR_texture_transform": {"offset": list(OFFSET), "rotation": ROTATION,
                                                        "scale": list(SCALE)}}
        doc["extensionsUsed"] = ["KHR_texture_transform"]
    doc["images"] = [{"uri": _normal_map(tmp_path)}]
    doc["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]  # nearest: no filtering differences
    doc["textures"] = [{"source": 0, "sampler": 0}]
    doc["materials"][0]["normalTexture"] = info
    doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 10}}]
    doc["nodes"].append({"camera": 0, "translation": [0, 0, 3]})
    doc["scenes"][0]["nodes"] = [0, 1]
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}}
    doc["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}},
                         "rotation": [0.3826834, 0.0, 0.0, 0.9238795]})  # 45 degrees about +X
    doc["scenes"][0]["nodes"].append(2)
    doc.setdefault("extensionsUsed", []).append("KHR_lights_punctual")
    return write(tmp_path, doc, name)


def test_a_transformed_normal_map_has_the_tangents_of_its_transformed_uvs(tmp_path):
    with_extension = load_gltf(_quad(tmp_path, "a.gltf", False), emit_warnings=False).scene
    baked = load_gltf(_quad(tmp_path, "b.gltf", True), emit_warnings=False).scene
    ta, tb = (s.objects[0].geometry.tangents for s in (with_extension, baked))
    # the same float64 computation on UVs that differ by float32 rounding of the baked file
    assert np.allclose(ta, tb, atol=1e-6), (ta, tb)
    # and not the untransformed UVs' tangent (+X), which the importer generated before
    assert not np.allclose(ta[:, :3], [1.0, 0.0, 0.0], atol=0.1)


def test_the_rotated_tile_renders_as_its_baked_twin(tmp_path):
    a = render_scene(load_gltf(_quad(tmp_path, "a.gltf", False), size=(48, 48), emit_warnings=False).scene).linear
    b = render_scene(load_gltf(_quad(tmp_path, "b.gltf", True), size=(48, 48), emit_warnings=False).scene).linear
    covered = (a[..., 3] > 0) & (b[..., 3] > 0)
    assert covered.sum() > 500
    # the same shading of the same texel at each pixel; the sampled texel's UV differs by float32
    # rounding of the UV (shader transform vs. baked), which can change the nearest texel only
    # where a pixel's UV lies within ~1e-6 of a texel edge: a handful of pixels at most
    differs = np.abs(a[..., :3] - b[..., :3]).max(axis=2) > 1e-5 * np.abs(b[..., :3]).max()
    assert (differs & covered).sum() <= 0.01 * covered.sum()


def _mirrored_pair(tmp_path):
    """Two triangles sharing the edge x = 0 with u = |x| (a mirror seam that shares its two
    vertices), v = (y + 1) / 2; a normal map."""
    doc = quad_document()
    positions = np.array([[-1, 0, 0], [0, -1, 0], [0, 1, 0], [1, 0, 0]], np.float32)
    uv = np.array([[1, 0.5], [0, 0], [0, 1], [1, 0.5]], np.float32)
    indices = np.array([0, 1, 2, 1, 3, 2], np.uint16)
    normals = np.tile(np.array([0, 0, 1], np.float32), (4, 1))
    set_blob(doc, positions.tobytes() + normals.tobytes() + uv.tobytes() + indices.tobytes())
    doc["images"] = [{"uri": _normal_map(tmp_path)}]
    doc["textures"] = [{"source": 0}]
    doc["materials"][0]["normalTexture"] = {"index": 0}
    return write(tmp_path, doc, "pair.gltf")


def test_a_mirror_seam_splits_its_shared_vertices(tmp_path):
    geometry = load_gltf(_mirrored_pair(tmp_path), emit_warnings=False).scene.objects[0].geometry
    assert len(geometry.positions) == 6  # the seam's two vertices copied for one side
    tangents, triangles = geometry.tangents, geometry.indices.reshape(-1, 3)
    for triangle in triangles:
        side = np.sign(geometry.positions[triangle, 0].sum())  # -1 left, +1 right
        for vertex in triangle:
            # u grows away from the seam on both sides: dP/du points along side * x
            assert tangents[vertex, :3] == pytest.approx([side, 0, 0], abs=1e-6), (triangle, vertex)
    signs = {np.sign(geometry.positions[t, 0].sum()): set(tangents[t, 3]) for t in triangles}
    assert len(signs[-1]) == len(signs[1]) == 1 and signs[-1] != signs[1]  # one mirrored side
