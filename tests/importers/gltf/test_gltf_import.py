"""The glTF importer's pieces against references written here from the specification:
node transforms, KHR_texture_transform, light units, cameras, MikkTSpace tangents, the
material mapping, warnings, the features report and glTF sub-scenes in JSON scenes."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

from pbrlab.commands import cli
from pbrlab.importers.gltf import GltfWarning, load_gltf
from pbrlab.importers.gltf.lights import GLTF_TO_PBRLAB_INTENSITY
from pbrlab.importers.gltf.materials import FLIP_V
from pbrlab.importers.gltf.tangents import mikktspace_tangents
from pbrlab.foundation.errors import SceneError
from pbrlab.render.renderer import render_scene
from pbrlab.importers import loader as scene_files
from pbrlab.scene import load_scene, parse_scene

from gltf_helpers import blob, quad_document, set_blob, write

ASSETS = Path(__file__).resolve().parents[3] / "scenes" / "gltf"


def _rotation(axis, angle):
    """Rodrigues' rotation matrix (independent of the importer's quaternion formula)."""
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def test_node_hierarchy_world_matrices_follow_trs_and_matrix(tmp_path):
    doc = quad_document()
    axis, angle = np.array([0.0, 1.0, 0.0]), 0.7
    q = [*(axis * math.sin(angle / 2)), math.cos(angle / 2)]
    child = np.eye(4)
    child[:3, 3] = [0.5, 0, 0]
    doc["nodes"] = [{"children": [1], "translation": [1, 2, 3], "rotation": q, "scale": [2, 2, 2]},
                    {"mesh": 0, "matrix": child.T.reshape(-1).tolist()}]
    scene = load_gltf(write(tmp_path, doc), emit_warnings=False).scene
    parent = np.eye(4)
    parent[:3, :3] = _rotation(axis, angle) * 2
    parent[:3, 3] = [1, 2, 3]
    np.testing.assert_allclose(scene.objects[0].transform, parent @ child, atol=1e-12)


def test_texture_transform_matches_the_extension_formula_in_gl_space(tmp_path):
    # The importer's matrix acts on GL UVs (v up); mapped back to glTF UVs it must equal
    # the extension's T R S (its README), evaluated here point by point.
    from pbrlab.importers.gltf.materials import MaterialReader

    offset, rotation, scale = np.array([0.25, -0.1]), 0.4, np.array([1.6, 1.3])
    reader = MaterialReader(None, ("k",), lambda m: None)
    m = reader._uv_transform({"offset": offset.tolist(), "rotation": rotation, "scale": scale.tolist()}, "x")
    gl = FLIP_V @ m @ FLIP_V
    rng = np.random.default_rng(1)
    for uv in rng.uniform(-2, 2, (20, 2)):
        s = uv * scale
        c, sn = math.cos(rotation), math.sin(rotation)
        expected = np.array([c * s[0] + sn * s[1], -sn * s[0] + c * s[1]]) + offset
        uv_gl = np.array([uv[0], 1 - uv[1], 1.0])
        out = gl @ uv_gl
        np.testing.assert_allclose([out[0], 1 - out[1]], expected, atol=1e-12)


def test_light_units_and_placement():
    result = load_gltf(ASSETS / "hierarchy_lights.glb", emit_warnings=False)
    sun, bulb, spot = result.scene.lights
    assert GLTF_TO_PBRLAB_INTENSITY == 1 / math.pi
    assert sun.type == "directional" and math.isclose(sun.intensity, 2.5 / math.pi)
    np.testing.assert_allclose(sun.direction, np.array([0.4, -0.7, -0.6]) / np.linalg.norm([0.4, -0.7, -0.6]),
                               atol=1e-12)
    assert bulb.type == "point" and math.isclose(bulb.intensity, 12 / math.pi) and bulb.range == math.inf
    np.testing.assert_allclose(bulb.position, [-1.5, 2.6, 2.2])
    assert math.isclose(spot.inner_cone_deg, math.degrees(0.15)) and math.isclose(spot.outer_cone_deg, math.degrees(0.4))


def test_white_lambert_under_a_1_lux_gltf_light_reads_1_over_pi(tmp_path, gl_context):
    # The documented convention: glTF renderers return BRDF x lux x cos = 1/pi for a white
    # Lambert surface (pbrlab's Lambert with metallic 0 keeps 1 - 0.04 of the albedo).
    doc = quad_document()
    doc["materials"][0]["pbrMetallicRoughness"] = {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0.0,
                                                   "roughnessFactor": 1.0}
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 1.0}]}}
    doc["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}}})
    doc["scenes"][0]["nodes"].append(1)
    scene = load_gltf(write(tmp_path, doc), size=(16, 16), emit_warnings=False).scene
    scene.render.energy_compensation = False
    centre = render_scene(scene, gl_context).linear[8, 8, :3]
    # diffuse 0.96 / pi plus the GGX lobe of F0 0.04 at roughness 1 seen head-on
    assert np.all(np.abs(centre - 0.96 / math.pi) < 0.02), centre


def test_gltf_camera_looks_down_minus_z_with_its_aspect():
    scene = load_gltf(ASSETS / "hierarchy_lights.glb", emit_warnings=False).scene
    cam = scene.camera
    forward = (cam.target - cam.position) / np.linalg.norm(cam.target - cam.position)
    expected = np.array([0.0, 0.8, 0.0]) - np.array([0.0, 2.6, 8.5])
    np.testing.assert_allclose(forward, expected / np.linalg.norm(expected), atol=1e-9)
    assert cam.size == (1024, 512) and math.isclose(cam.fov_y_deg, math.degrees(0.55))


def test_orthographic_camera_and_camera_option():
    ortho = load_gltf(ASSETS / "features.gltf", emit_warnings=False).scene.camera
    assert ortho.ortho_half_height == 1.7 and ortho.size == (1024, 512)
    persp = load_gltf(ASSETS / "features.gltf", camera=1, emit_warnings=False).scene.camera
    assert persp.ortho_half_height is None and math.isclose(persp.fov_y_deg, math.degrees(0.7))


def test_framing_camera_sees_every_vertex(tmp_path, gl_context):
    scene = load_gltf(write(tmp_path, quad_document()), size=(64, 64), emit_warnings=False).scene
    coverage = render_scene(scene, gl_context).linear[..., 3] > 0
    assert coverage.any() and not coverage[0].any() and not coverage[-1].any()
    assert not coverage[:, 0].any() and not coverage[:, -1].any()


def test_mikktspace_tangents_of_a_plane_follow_u_and_the_uv_handedness():
    positions = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    normals = np.tile([0.0, 0.0, 1.0], (4, 1))
    triangles = np.array([[0, 1, 2], [0, 2, 3]])
    uv = positions[:, :2] * [2.0, 3.0]  # u along +x, v along +y: right-handed
    t = mikktspace_tangents(positions, normals, uv, triangles)
    np.testing.assert_allclose(t, np.tile([1.0, 0, 0, 1.0], (4, 1)), atol=1e-12)
    mirrored = mikktspace_tangents(positions, normals, uv * [-1.0, 1.0], triangles)
    np.testing.assert_allclose(mirrored, np.tile([-1.0, 0, 0, -1.0], (4, 1)), atol=1e-12)


def test_mikktspace_tangents_of_a_curved_surface_are_unit_and_orthogonal():
    import trimesh

    mesh = trimesh.creation.cylinder(radius=1, height=2, sections=32)
    p, n = np.asarray(mesh.vertices), np.asarray(mesh.vertex_normals)
    uv = np.stack([np.arctan2(p[:, 1], p[:, 0]) / (2 * np.pi), p[:, 2]], axis=1)
    t = mikktspace_tangents(p, n, uv, mesh.faces)
    np.testing.assert_allclose(np.linalg.norm(t[:, :3], axis=1), 1.0, atol=1e-12)
    assert np.all(np.abs(np.sum(t[:, :3] * n, axis=1)) < 1e-12)


def test_material_mapping():
    scene = load_gltf(ASSETS / "features.gltf", emit_warnings=False).scene
    glass = scene.materials["glass_like"]
    f0 = ((1.8 - 1) / (1.8 + 1)) ** 2
    assert glass.workflow == "specular"
    np.testing.assert_allclose(glass.specular, f0 * 0.9 * np.array([1.0, 0.9, 0.8]))
    assert math.isclose(glass.smoothness, 0.85)
    bumps = scene.materials["occluded_bumps"]
    assert bumps.texture_uv_set == {"albedo": 0, "occlusion": 1, "normal": 0}
    assert bumps.normal_scale == 0.5 and bumps.occlusion_strength == 0.7
    glow = scene.materials["two_sided_glow"]
    np.testing.assert_allclose(glow.emission, [0.3, 0.6, 1.0])
    assert glow.double_sided and scene.materials["vertex_coloured"].vertex_color
    textured = load_gltf(ASSETS / "textured.gltf", emit_warnings=False).scene.materials["checker_mr"]
    assert textured.texture_srgb == {"albedo": True, "metallic_roughness": False}
    assert textured.metallic == 1.0 and textured.smoothness == 0.0


def test_mirrored_repeat_is_a_doubled_image_at_half_the_uvs():
    scene = load_gltf(ASSETS / "texture_transform.gltf", emit_warnings=False).scene
    mirrored = scene.materials["mirrored_repeat"]
    image = mirrored.textures["albedo"].pixels()
    assert image.shape[:2] == (128, 128)
    np.testing.assert_array_equal(image[:, 64:], image[:, :64][:, ::-1])
    np.testing.assert_array_equal(image[:64], image[64:][::-1])
    np.testing.assert_allclose(mirrored.texture_transform["albedo"], [[0.5, 0, 0], [0, 0.5, 0]])
    assert mirrored.texture_sampler["albedo"][:2] == (True, True)
    assert scene.materials["clamp_nearest"].texture_sampler["albedo"] == (False, False, 9728, 9728)


def test_every_ignored_extension_is_one_warning_in_render_and_features(capsys, tmp_path):
    with pytest.warns(GltfWarning, match='KHR_materials_dispersion ignored in material "glass_like"'):
        load_gltf(ASSETS / "features.gltf")
    assert cli.main(["render", str(ASSETS / "features.gltf"), "-o", str(tmp_path / "f.png"), "--size", "32x16"]) == 0
    err = capsys.readouterr().err
    assert err.count("warning: ") == 1 and 'KHR_materials_dispersion ignored in material "glass_like"' in err
    assert cli.main(["features", str(ASSETS / "features.gltf")]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["warnings"] == ['KHR_materials_dispersion ignored in material "glass_like"']
    assert report["scene"]["orthographic"] and report["scene"]["spot"] == 1
    assert report["materials"]["occluded_bumps"]["uv1_maps"] == ["occlusion"]


def test_unhonoured_features_are_named(tmp_path):
    doc = quad_document()
    doc["materials"][0]["extensions"] = {"KHR_materials_dispersion": {}}
    doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2
    doc["meshes"][0]["primitives"][0]["attributes"]["_CUSTOM"] = 2
    doc["animations"] = [{"channels": [], "samplers": []}]
    result = load_gltf(write(tmp_path, doc), emit_warnings=False)
    assert result.warnings == ['KHR_materials_dispersion ignored in material "paint"',
                               "attribute _CUSTOM ignored in mesh 0 primitive 0"]


def test_vertex_colour_multiplies_base_colour(tmp_path, gl_context):
    doc = quad_document()
    import base64
    colours = np.tile(np.array([0.25, 1.0, 0.5, 1.0], np.float32), (4, 1)).tobytes()
    data = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1]) + colours
    doc["buffers"][0] = {"byteLength": len(data), "uri": "data:application/octet-stream;base64,"
                         + base64.b64encode(data).decode()}
    doc["bufferViews"].append({"buffer": 0, "byteOffset": 140, "byteLength": 64})
    doc["accessors"].append({"bufferView": 4, "componentType": 5126, "count": 4, "type": "VEC4"})
    doc["materials"][0]["emissiveFactor"] = [0, 0, 0]
    env = parse_scene({"camera": {"position": [0, 0, 1], "target": [0, 0, 0]}, "materials": {"m": {}},
                       "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}],
                       "environment": {"color": [1, 1, 1]}}).environment
    plain = render_scene(load_gltf(write(tmp_path, doc), size=(16, 16), environment=env,
                                   emit_warnings=False).scene, gl_context).linear[8, 8, :3]
    doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 4
    coloured = render_scene(load_gltf(write(tmp_path, doc), size=(16, 16), environment=env,
                                      emit_warnings=False).scene, gl_context).linear[8, 8, :3]
    # a rough dielectric in a white environment: the diffuse part scales with the colour
    # (R x 0.25), the specular part does not; G (colour 1) is unchanged
    assert coloured[0] < plain[0] * 0.5 and math.isclose(coloured[1], plain[1], rel_tol=1e-6)


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_double_sided_back_face_is_lit_as_a_front_face(tmp_path, gl_context, language):
    # The quad seen from behind with a light behind the camera: a double-sided material
    # shows the same radiance as the front seen from the front; single-sided, it is culled.
    doc = quad_document()
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 2.0}]}}
    doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.5, "aspectRatio": 1.0}}]
    doc["nodes"] += [{"extensions": {"KHR_lights_punctual": {"light": 0}}, "translation": [0, 0, 5]},
                     {"camera": 0, "translation": [0, 0, 5]}]
    doc["scenes"][0]["nodes"] += [1, 2]
    front = render_scene(load_gltf(write(tmp_path, doc), size=(16, 16), emit_warnings=False).scene,
                         gl_context, language=language).linear
    turn = [0.0, 1.0, 0.0, 0.0]  # 180 degrees about y: camera and light look at the back
    doc["nodes"][1]["rotation"] = doc["nodes"][2]["rotation"] = turn
    doc["nodes"][1]["translation"] = doc["nodes"][2]["translation"] = [0, 0, -5]
    culled = render_scene(load_gltf(write(tmp_path, doc), size=(16, 16), emit_warnings=False).scene,
                          gl_context, language=language).linear
    assert not culled[..., 3].any()
    doc["materials"][0]["doubleSided"] = True
    back = render_scene(load_gltf(write(tmp_path, doc), size=(16, 16), emit_warnings=False).scene,
                        gl_context, language=language).linear
    covered = front[..., 3] > 0
    assert covered.sum() > 50
    # the back view is the front view mirrored left-right; light along the view axis makes
    # the radiance symmetric, so pixel for pixel (float32 rounding: 1e-5 relative)
    np.testing.assert_allclose(back[..., :3][covered], front[..., :3][covered], rtol=1e-5)


def test_gltf_sub_scene_in_a_json_scene(tmp_path, gl_context):
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps({
        "materials": {"white": {}},
        "objects": [{"sphere": {"center": [0, 4, 0], "radius": 0.3}, "material": "white"},
                    {"gltf": str(ASSETS / "hierarchy_lights.glb"), "transform": {"translate": [0, 0, -1]}}]}))
    scene = scene_files.load_scene(scene_file)  # the loader above the scene model hands it the glTF reader
    direct = load_gltf(ASSETS / "hierarchy_lights.glb", emit_warnings=False).scene
    assert len(scene.objects) == 1 + len(direct.objects) and len(scene.lights) == 3
    assert "hierarchy_lights.glb/gold_metal" in scene.materials
    np.testing.assert_allclose(scene.camera.position, direct.camera.position + [0, 0, -1])
    np.testing.assert_allclose(scene.lights[1].position, direct.lights[1].position + [0, 0, -1])
    moved = [o.transform[:3, 3] for o in scene.objects[1:]]
    np.testing.assert_allclose(moved, [o.transform[:3, 3] + [0, 0, -1] for o in direct.objects])
    assert render_scene(scene, gl_context, size=(32, 16)).linear[..., 3].any()


def test_zero_emissive_strength_reports_no_emission(tmp_path, capsys):
    doc = quad_document()
    doc["materials"][0]["emissiveFactor"] = [1.0, 0.5, 0.2]
    doc["materials"][0]["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": 0.0}}
    assert cli.main(["features", str(write(tmp_path, doc))]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["materials"]["paint"]["emission"] is False and report["warnings"] == []


def test_ior_on_a_partly_metallic_material_sets_its_dielectric_f0(tmp_path):
    doc = quad_document()
    doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 0.5
    doc["materials"][0]["extensions"] = {"KHR_materials_ior": {"ior": 1.33}}
    result = load_gltf(write(tmp_path, doc), emit_warnings=False)
    material = result.scene.materials["paint"]
    assert material.workflow == "metallic" and material.metallic == 0.5
    np.testing.assert_allclose(material.dielectric_specular, [(0.33 / 2.33) ** 2] * 3, rtol=1e-12)
    assert material.specular_f90 is None  # KHR_materials_ior alone: F90 from F0
    assert result.warnings == []


def test_metallic_roughness_slot_in_a_json_scene_and_one_packing_only(tmp_path):
    from pbrlab.foundation.errors import SceneError

    png = ASSETS / "textured_mr.png"
    scene = {"camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
             "materials": {"m": {"textures": {"metallic_roughness": str(png)}}},
             "objects": [{"mesh": {"primitive": "plane"}, "material": "m"}]}
    assert parse_scene(scene).materials["m"].texture_srgb == {"metallic_roughness": False}
    scene["materials"]["m"]["textures"]["metallic_smoothness"] = str(png)
    with pytest.raises(SceneError, match="give one packing"):
        parse_scene(scene)


def test_environment_from_the_command_line_or_a_side_file(tmp_path, capsys):
    from pbrlab.foundation.images import read_image

    path = write(tmp_path, quad_document())  # no light: black without an environment
    out = tmp_path / "out.exr"

    def centre(*options):
        assert cli.main(["render", str(path), "--hdr", str(out), "--size", "16x16", *options]) == 0
        return read_image(out)[8, 8, :3]

    assert not centre().any()
    (tmp_path / "model.pbrlab.json").write_text(json.dumps(
        {"environment": {"color": [1, 1, 1]}, "render": {"tonemap": "aces_fitted"}}))
    assert centre().min() > 0.1
    assert not centre("--environment", "0,0,0").any()  # the command line wins
    capsys.readouterr()
    assert cli.main(["features", str(path)]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["scene"]["environment"] and report["scene"]["tonemap"] == "aces_fitted"
    (tmp_path / "model.pbrlab.json").write_text(json.dumps({"lights": []}))
    assert cli.main(["render", str(path), "--hdr", str(out)]) == 2
    assert "expected an object with environment and/or render" in capsys.readouterr().err
    (tmp_path / "model.pbrlab.json").unlink()
    assert cli.main(["render", str(path), "--hdr", str(out), "--environment", "nowhere.exr"]) == 2
    assert "--environment: environment.path: file not found" in capsys.readouterr().err


def test_sparse_accessor_replaces_elements(tmp_path):
    from gltf_helpers import blob, set_blob

    doc = quad_document()
    data = blob(doc)  # 140 bytes: the next view starts 4-aligned
    extra = np.array([2], np.uint16).tobytes() + b"\0\0" + np.array([1.5, 1.5, 0.0], np.float32).tobytes()
    doc["bufferViews"] += [{"buffer": 0, "byteOffset": len(data), "byteLength": 2},
                           {"buffer": 0, "byteOffset": len(data) + 4, "byteLength": 12}]
    set_blob(doc, data + extra)
    doc["buffers"][0]["byteLength"] = len(data + extra)
    doc["accessors"][0]["sparse"] = {"count": 1, "indices": {"bufferView": 4, "componentType": 5123},
                                     "values": {"bufferView": 5}}
    geometry = load_gltf(write(tmp_path, doc), emit_warnings=False).scene.objects[0].geometry
    np.testing.assert_array_equal(geometry.positions[2], [1.5, 1.5, 0.0])
    np.testing.assert_array_equal(geometry.positions[1], [1.0, -1.0, 0.0])
    doc["accessors"][0]["sparse"]["count"] = 2
    doc["bufferViews"][4]["byteLength"] = 4
    from pbrlab.foundation.errors import SceneError
    with pytest.raises(SceneError, match="sparse"):
        load_gltf(write(tmp_path, doc), emit_warnings=False)


def test_extension_used_where_nothing_looks_is_named(tmp_path):
    doc = quad_document()
    doc["extensionsUsed"] = ["EXT_lights_image_based", "KHR_lights_punctual"]
    assert load_gltf(write(tmp_path, doc), emit_warnings=False).warnings == [
        "EXT_lights_image_based ignored (listed in extensionsUsed)"]


def test_orthographic_camera_maps_ymag_to_half_the_image_height(tmp_path, gl_context):
    # The 2 x 2 quad under an orthographic camera with ymag 2 (half-height 2) fills rows
    # 25 %..75 % of the image and, with xmag 4, columns 37.5 %..62.5 % (glTF 3.10.3).
    doc = quad_document()
    doc["cameras"] = [{"type": "orthographic", "orthographic": {"xmag": 4.0, "ymag": 2.0, "znear": 0.1,
                                                               "zfar": 10}}]
    doc["nodes"].append({"camera": 0, "translation": [0, 0, 3]})
    doc["scenes"][0]["nodes"].append(1)
    scene = load_gltf(write(tmp_path, doc), emit_warnings=False).scene
    assert scene.camera.size == (1024, 512)
    covered = render_scene(scene, gl_context, size=(64, 32)).linear[..., 3] > 0
    rows, cols = np.flatnonzero(covered.any(axis=1)), np.flatnonzero(covered.any(axis=0))
    assert (rows.min(), rows.max()) == (8, 23) and (cols.min(), cols.max()) == (24, 39)


def test_given_tangents_are_used_and_missing_ones_are_computed(tmp_path, gl_context):
    # A normal map tilted towards +Y of the image: with no TANGENT the computed frame is
    # (+x, w = +1) on this quad, so a TANGENT of (1, 0, 0, 1) changes nothing and
    # (1, 0, 0, -1) mirrors the bitangent.
    import base64
    import io

    from PIL import Image

    texel = np.round((np.array([0.0, 0.6, 0.8]) * 0.5 + 0.5) * 255).astype(np.uint8)
    png = io.BytesIO()
    Image.fromarray(np.tile(texel, (4, 4, 1))).save(png, format="PNG")
    doc = quad_document()
    doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png.getvalue()).decode()}]
    doc["textures"] = [{"source": 0}]
    doc["materials"][0]["normalTexture"] = {"index": 0}
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}}
    doc["nodes"].append({"extensions": {"KHR_lights_punctual": {"light": 0}},
                         "rotation": [math.sin(-0.4), 0, 0, math.cos(-0.4)]})  # from above-front
    doc["scenes"][0]["nodes"].append(1)

    def render(w=None):
        d = json.loads(json.dumps(doc))
        if w is not None:
            raw = base64.b64decode(d["buffers"][0]["uri"].split(",", 1)[1])
            raw += np.tile(np.array([1, 0, 0, w], np.float32), (4, 1)).tobytes()
            d["buffers"][0] = {"byteLength": len(raw),
                               "uri": "data:application/octet-stream;base64," + base64.b64encode(raw).decode()}
            d["bufferViews"].append({"buffer": 0, "byteOffset": 140, "byteLength": 64})
            d["accessors"].append({"bufferView": 4, "componentType": 5126, "count": 4, "type": "VEC4"})
            d["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = 4
        scene = load_gltf(write(tmp_path, d), size=(16, 16), emit_warnings=False).scene
        return render_scene(scene, gl_context).linear[8, 8, :3]

    computed, given, mirrored = render(), render(1.0), render(-1.0)
    np.testing.assert_array_equal(computed, given)
    assert mirrored[0] < computed[0] * 0.8  # tilted away from the light instead of towards it


def test_sub_scene_warnings_reach_render_and_features(tmp_path, capsys):
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps({"objects": [{"gltf": str(ASSETS / "features.gltf")}]}))
    assert cli.main(["render", str(scene_file), "-o", str(tmp_path / "s.png"), "--size", "32x16"]) == 0
    assert 'warning: features.gltf: KHR_materials_dispersion ignored in material "glass_like"' in capsys.readouterr().err
    assert cli.main(["features", str(scene_file)]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["warnings"] == ['features.gltf: KHR_materials_dispersion ignored in material "glass_like"']
    assert report["scene"]["orthographic"]  # the file's camera serves: the scene has none


def test_clearcoat_maps_to_the_coat_layer():
    result = load_gltf(ASSETS / "clearcoat.gltf", emit_warnings=False)
    assert result.warnings == []
    m = result.scene.materials
    assert m["uncoated"].clearcoat == 0.0
    assert (m["smooth_coat"].clearcoat, m["smooth_coat"].clearcoat_smoothness) == (1.0, 0.95)
    masked = m["masked_rough_coat"]
    assert masked.clearcoat == 0.9 and masked.clearcoat_smoothness == pytest.approx(0.3)
    assert {"clearcoat", "clearcoat_roughness"} <= set(masked.textures)
    assert not any(masked.texture_srgb[s] for s in ("clearcoat", "clearcoat_roughness"))  # data, not colour
    bumpy = m["bumpy_coat"]
    assert "clearcoat_normal" in bumpy.textures and "normal" not in bumpy.textures
    assert bumpy.clearcoat_normal_scale == 0.8


def test_an_unsupported_extension_is_one_warning_per_file_naming_its_materials(tmp_path):
    doc = quad_document()
    doc["materials"] = [dict(doc["materials"][0], name=f"m{i}", extensions={"KHR_materials_dispersion": {}})
                        for i in range(5)]
    doc["meshes"][0]["primitives"] = [dict(doc["meshes"][0]["primitives"][0], material=i) for i in range(5)]
    result = load_gltf(write(tmp_path, doc), emit_warnings=False)
    assert result.warnings == ['KHR_materials_dispersion ignored in 5 materials ("m0", "m1", "m2" and 2 more)']


def test_sheen_maps_to_the_sheen_layer():
    result = load_gltf(ASSETS / "sheen.gltf", emit_warnings=False)
    assert not result.warnings
    m = {mat.name: mat for mat in result.scene.materials.values()}
    assert max(m["no_sheen"].sheen_color) == 0.0
    assert m["white_sheen"].sheen_color == (1.0, 1.0, 1.0)
    assert m["white_sheen"].sheen_smoothness == pytest.approx(0.7)
    mapped = m["mapped_sheen"]
    assert mapped.sheen_color == pytest.approx((0.9, 0.7, 1.0)) and mapped.sheen_smoothness == pytest.approx(0.2)
    assert {"sheen_color", "sheen_roughness"} <= set(mapped.textures)
    assert mapped.texture_srgb["sheen_color"] and not mapped.texture_srgb["sheen_roughness"]  # colour, data
    assert m["coated_sheen"].clearcoat == 1.0 and max(m["coated_sheen"].sheen_color) > 0.0


def test_anisotropy_maps_to_the_anisotropic_base():
    """KHR_materials_anisotropy (anisotropy.gltf): strength, rotation (radians), the texture as
    a linear slot with its UV set and KHR_texture_transform; no warning."""
    result = load_gltf(ASSETS / "anisotropy.gltf", emit_warnings=False)
    assert not result.warnings
    m = {mat.name: mat for mat in result.scene.materials.values()}
    assert m["isotropic"].anisotropy_strength == 0.0 and not m["isotropic"].textures
    assert m["along_tangent"].anisotropy_strength == pytest.approx(0.8)
    assert m["along_tangent"].anisotropy_rotation == 0.0
    assert m["quarter_turn"].anisotropy_rotation == pytest.approx(math.pi / 2)
    swirl = m["swirl"]
    assert swirl.anisotropy_strength == 1.0 and swirl.anisotropy_rotation == pytest.approx(0.3)
    assert set(swirl.textures) == {"anisotropy"} and not swirl.texture_srgb["anisotropy"]  # RGB data
    assert swirl.texture_uv_set["anisotropy"] == 0 and "anisotropy" in swirl.texture_transform


def _anisotropic_quad(uv_along_y: bool, extension: dict | None):
    doc = quad_document()
    if uv_along_y:  # u grows along +y, so the MikkTSpace tangent is +y instead of +x
        data = bytearray(blob(doc))
        uv = np.array([[0, 0], [0, 1], [1, 1], [1, 0]], np.float32)  # (u, v) = ((y+1)/2, (x+1)/2)
        data[96:128] = uv.tobytes()
        set_blob(doc, bytes(data))
    if extension is not None:
        doc["materials"][0]["extensions"] = {"KHR_materials_anisotropy": extension}
        doc["extensionsUsed"] = ["KHR_materials_anisotropy"]
    return doc


def test_anisotropy_without_tangent_gets_mikktspace_tangents(tmp_path):
    """The anisotropy lies along TANGENT; without one the importer computes MikkTSpace
    tangents from the UVs (as for a normal map). Without anisotropy (and no normal map) the
    tangents stay unused at (1, 0, 0)."""
    def tangents(doc):
        return load_gltf(write(tmp_path, doc), emit_warnings=False).scene.objects[0].geometry.tangents
    np.testing.assert_allclose(tangents(_anisotropic_quad(True, {"anisotropyStrength": 0.5}))[:, :3],
                               np.tile([0.0, 1.0, 0.0], (4, 1)), atol=1e-6)
    np.testing.assert_array_equal(tangents(_anisotropic_quad(True, None))[:, :3], np.tile([1.0, 0.0, 0.0], (4, 1)))


def test_anisotropy_defaults_and_bad_values(tmp_path):
    """The specification's defaults (strength 0, rotation 0: the isotropic material), and a
    strength outside [0, 1] refused with the field's path."""
    m = load_gltf(write(tmp_path, _anisotropic_quad(False, {})), emit_warnings=False).scene.materials
    (material,) = m.values()
    assert material.anisotropy_strength == 0.0 and material.anisotropy_rotation == 0.0
    with pytest.raises(SceneError) as info:
        load_gltf(write(tmp_path, _anisotropic_quad(False, {"anisotropyStrength": 1.5})), emit_warnings=False)
    assert str(info.value).endswith("materials[0].extensions.KHR_materials_anisotropy: anisotropyStrength must be "
                                    "a number in [0, 1], got 1.5")


def test_anisotropy_gltf_renders_alike_in_glsl_hlsl_and_the_full_program(gl_context):
    """anisotropy.gltf through the GLSL library, its HLSL port and the full runtime-branching
    program: bit for bit (measured 0 ulp on llvmpipe). Against the same file with every
    anisotropy removed, the three anisotropic quads change (the lights' highlights smeared)."""
    scene = load_gltf(ASSETS / "anisotropy.gltf", size=(256, 64), emit_warnings=False).scene
    glsl = render_scene(scene, gl_context).linear
    hlsl = render_scene(scene, gl_context, language="hlsl").linear
    full = render_scene(scene, gl_context, specialise=False).linear
    np.testing.assert_array_equal(glsl.view(np.uint32), hlsl.view(np.uint32))
    np.testing.assert_array_equal(glsl.view(np.uint32), full.view(np.uint32))
    plain = load_gltf(ASSETS / "anisotropy.gltf", size=(256, 64), emit_warnings=False).scene
    for material in plain.materials.values():
        material.anisotropy_strength = 0.0
        material.textures.clear()
    isotropic = render_scene(plain, gl_context).linear
    changed = np.abs(glsl - isotropic)[..., :3].max(axis=-1) > 0.01
    assert changed.mean() > 0.1, changed.mean()


def test_iridescence_maps_to_the_thin_film():
    """KHR_materials_iridescence (iridescence.gltf): factor, IOR, thickness range, the mask (R)
    and thickness (G) textures as linear slots; the specification's defaults where a field is
    absent; no warning."""
    result = load_gltf(ASSETS / "iridescence.gltf", emit_warnings=False)
    assert not result.warnings
    m = {mat.name: mat for mat in result.scene.materials.values()}
    assert m["no_film"].iridescence == 0.0
    default = m["default_film"]
    assert (default.iridescence, default.iridescence_ior, default.iridescence_thickness_min,
            default.iridescence_thickness_max) == (1.0, 1.3, 100.0, 400.0)
    assert not default.textures
    mapped = m["mapped_film"]
    assert (mapped.iridescence_ior, mapped.iridescence_thickness_min, mapped.iridescence_thickness_max) == (1.8, 100.0,
                                                                                                           800.0)
    assert set(mapped.textures) == {"iridescence", "iridescence_thickness"}
    assert not mapped.texture_srgb["iridescence"] and not mapped.texture_srgb["iridescence_thickness"]
    layered = m["coated_brushed_film"]
    assert layered.iridescence == pytest.approx(0.8) and layered.anisotropy_strength == pytest.approx(0.6)
    assert layered.clearcoat == 1.0


def test_iridescence_bad_values_are_refused_by_path(tmp_path):
    doc = quad_document()
    doc["materials"][0]["extensions"] = {"KHR_materials_iridescence": {"iridescenceFactor": 1.0,
                                                                       "iridescenceIor": 0.5}}
    with pytest.raises(SceneError) as info:
        load_gltf(write(tmp_path, doc), emit_warnings=False)
    assert str(info.value).endswith("materials[0].extensions.KHR_materials_iridescence: iridescenceIor must be "
                                    "a number in [1, 16], got 0.5")


def test_iridescence_gltf_renders_alike_in_glsl_hlsl_and_the_full_program(gl_context):
    """iridescence.gltf through the GLSL library, its HLSL port and the full program (bit for
    bit). GLSL against HLSL: the film's interference phase is contracted differently by the two
    compilers (tests/gpu/hlsl/test_function_agreement.py's stated bound for pbr_F_Iridescence);
    measured 5.2e-6 relative, 9.2e-7 absolute; asked: 1e-6 + 1e-5 relative per channel (the
    float32 bound of tests/render/test_anisotropy_scene.py). Without its films the image
    changes on the three filmed quads."""
    scene = load_gltf(ASSETS / "iridescence.gltf", size=(256, 64), emit_warnings=False).scene
    glsl = render_scene(scene, gl_context).linear.astype(np.float64)
    hlsl = render_scene(scene, gl_context, language="hlsl").linear.astype(np.float64)
    full = render_scene(scene, gl_context, specialise=False).linear.astype(np.float64)
    np.testing.assert_allclose(hlsl[..., :3], glsl[..., :3], rtol=1e-5, atol=1e-6)
    np.testing.assert_array_equal(glsl, full)
    plain = load_gltf(ASSETS / "iridescence.gltf", size=(256, 64), emit_warnings=False).scene
    for material in plain.materials.values():
        material.iridescence = 0.0
        for slot in ("iridescence", "iridescence_thickness"):
            material.textures.pop(slot, None)
    filmless = render_scene(plain, gl_context).linear
    assert (np.abs(glsl - filmless)[..., :3].max(axis=-1) > 0.01).mean() > 0.1


def test_transmission_and_volume_map_to_the_transmission():
    """KHR_materials_transmission and KHR_materials_volume (transmission.gltf): the factor, the
    transmission (R) and thickness (G) textures as linear slots, the volume's attenuation and
    KHR_materials_ior's ior; the thickness scaled by the node's world scale (0.8); the
    specification's defaults (thin-walled, no attenuation) where a field is absent; no warning."""
    result = load_gltf(ASSETS / "transmission.gltf", emit_warnings=False)
    assert not result.warnings
    m = {mat.name: mat for mat in result.scene.materials.values()}
    assert m["opaque"].transmission == 0.0
    thin = m["thin"]
    assert (thin.transmission, thin.thickness, thin.attenuation_color, thin.attenuation_distance) == (
        1.0, 0.0, (1.0, 1.0, 1.0), float("inf"))
    assert not thin.textures
    striped = m["rough_striped"]
    assert striped.transmission == pytest.approx(0.9) and set(striped.textures) == {"transmission"}
    assert not striped.texture_srgb["transmission"]
    used = sorted({o.material for o in result.scene.objects if o.material.startswith("tinted_volume")})
    assert used == ["tinted_volume [volume scale 0.8]"]  # the node's copy; the file's material is unplaced
    volume = m[used[0]]
    assert volume.thickness == pytest.approx(0.4 * 0.8) and volume.ior == pytest.approx(1.33)
    assert volume.attenuation_color == pytest.approx((0.9, 0.5, 0.2)) and volume.attenuation_distance == 0.25
    assert set(volume.textures) == {"thickness"} and not volume.texture_srgb["thickness"]


@pytest.mark.parametrize("extensions, message", [
    ({"KHR_materials_transmission": {"transmissionFactor": 1.5}},
     "KHR_materials_transmission: transmissionFactor must be a number in [0, 1], got 1.5"),
    ({"KHR_materials_transmission": {"transmissionFactor": 1.0},
      "KHR_materials_volume": {"thicknessFactor": 1.0, "attenuationDistance": 0}},
     "KHR_materials_volume: attenuationDistance must be a number in (0, inf], got 0"),
    ({"KHR_materials_transmission": {"transmissionFactor": 1.0}, "KHR_materials_ior": {"ior": 20}},
     "KHR_materials_ior: ior must be a number in [1, 16], got 20"),
])
def test_transmission_bad_values_are_refused_by_path(extensions, message, tmp_path):
    doc = quad_document()
    doc["materials"][0]["extensions"] = extensions
    with pytest.raises(SceneError) as info:
        load_gltf(write(tmp_path, doc), emit_warnings=False)
    assert str(info.value).endswith(message), str(info.value)


def test_a_volume_without_transmission_is_named_in_a_warning(tmp_path):
    doc = quad_document()
    doc["materials"][0]["extensions"] = {"KHR_materials_volume": {"thicknessFactor": 1.0}}
    result = load_gltf(write(tmp_path, doc), emit_warnings=False)
    assert any("KHR_materials_volume ignored" in w and "without KHR_materials_transmission" in w
               for w in result.warnings), result.warnings


def test_transmission_gltf_renders_alike_in_glsl_hlsl_and_the_full_program(gl_context):
    """transmission.gltf through the GLSL library, its HLSL port (within the float32 bound of
    tests/render/test_anisotropy_scene.py: 1e-6 + 1e-5 relative per channel) and the full
    program (bit for bit). Without its transmission the three transmissive spheres change."""
    scene = load_gltf(ASSETS / "transmission.gltf", size=(256, 64), emit_warnings=False).scene
    glsl = render_scene(scene, gl_context).linear.astype(np.float64)
    hlsl = render_scene(scene, gl_context, language="hlsl").linear.astype(np.float64)
    full = render_scene(scene, gl_context, specialise=False).linear.astype(np.float64)
    np.testing.assert_allclose(hlsl[..., :3], glsl[..., :3], rtol=1e-5, atol=1e-6)
    np.testing.assert_array_equal(glsl, full)
    plain = load_gltf(ASSETS / "transmission.gltf", size=(256, 64), emit_warnings=False).scene
    for material in plain.materials.values():
        material.transmission = 0.0
        for slot in ("transmission", "thickness"):
            material.textures.pop(slot, None)
    opaque = render_scene(plain, gl_context).linear
    changed = np.abs(glsl - opaque)[..., :3].max(axis=-1) > 0.01
    assert changed.mean() > 0.05, changed.mean()


def test_specular_metal_gltf_renders_alike_in_glsl_hlsl_and_the_full_program(gl_context):
    """specular_metal.gltf (KHR_materials_ior / _specular on metallic 0, 0.5 and a metallic
    ramp texture, with the specular colour and strength textures) through the GLSL library, its
    HLSL port and the full program: the full program bit for bit, HLSL within the float32 bound
    of the iridescence test above. The metallic rows map to the metallic workflow with their
    dielectric F0 (the dielectric row to the specular workflow) and nothing is warned; without
    the dielectric F0 and F90 the metallic rows change."""
    result = load_gltf(ASSETS / "specular_metal.gltf", size=(128, 64), emit_warnings=False)
    assert result.warnings == []
    scene = result.scene
    workflows = {m.name: (m.workflow, m.dielectric_specular is not None) for m in scene.materials.values()}
    assert workflows["half_metal_specular_maps"] == ("metallic", True)
    assert workflows["metal_ramp_ior"] == ("metallic", True)
    assert workflows["dielectric_specular"] == ("specular", False)
    assert workflows["half_metal_plain"] == ("metallic", False)
    glsl = render_scene(scene, gl_context).linear.astype(np.float64)
    hlsl = render_scene(scene, gl_context, language="hlsl").linear.astype(np.float64)
    full = render_scene(scene, gl_context, specialise=False).linear.astype(np.float64)
    np.testing.assert_allclose(hlsl[..., :3], glsl[..., :3], rtol=1e-5, atol=1e-6)
    np.testing.assert_array_equal(glsl, full)
    for material in scene.materials.values():
        if material.workflow == "metallic":
            material.dielectric_specular, material.specular_f90 = None, None
    ignored = render_scene(scene, gl_context).linear
    assert (np.abs(glsl - ignored)[..., :3].max(axis=-1) > 0.01).mean() > 0.05
