"""Scene-driven specialisation: programs compile only the effects a scene can show, and
change nothing but the cost (harness/pbrlab/render/features.py)."""

import base64
import json
import re
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

from pbrlab.commands import cli
from pbrlab.render import features, renderer as render
from pbrlab.gpu import programs
from pbrlab.checking.charts import CHARTS
from pbrlab.scene import load_scene, parse_scene

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "tests" / "render"))
from render_scenes import light_zoo, one_sphere  # noqa: E402

TEST_SCENES = {
    **{name: (lambda build=build: parse_scene(build())) for name, build in CHARTS.items()},
    "light_zoo": lambda: parse_scene(light_zoo()),
    "unity_example": lambda: load_scene(ROOT / "scenes" / "unity_example" / "scene.json"),
    "torture": lambda: load_scene(ROOT / "scenes" / "torture" / "scene.json"),
    "readme_example": lambda: load_scene(ROOT / "scenes" / "example.json"),
    "coated_light_zoo": lambda: parse_scene(_coated(light_zoo())),
    "sheened_light_zoo": lambda: parse_scene(_sheened(light_zoo())),
    "anisotropic_light_zoo": lambda: parse_scene(_anisotropic(light_zoo())),
    "iridescent_light_zoo": lambda: parse_scene(_iridescent(light_zoo())),
    "transmissive_light_zoo": lambda: parse_scene(_transmissive(light_zoo())),
    "specular_f90_light_zoo": lambda: parse_scene(_specular_f90(light_zoo())),
    "specular_metal_light_zoo": lambda: parse_scene(_specular_metal(light_zoo())),
}


def _coated(scene):
    """The light zoo with its materials clear-coated (a layer: compiled in both programs)."""
    for i, material in enumerate(scene["materials"].values()):
        material.update(clearcoat=1.0 - 0.3 * i, clearcoat_smoothness=0.9 - 0.4 * i)
    scene["environment"] = {"color": [0.3, 0.3, 0.3]}
    return scene


def _sheened(scene):
    """The light zoo with sheens on its materials (one also coated): a layer, compiled in both
    programs."""
    for i, material in enumerate(scene["materials"].values()):
        material.update(sheen_color=[1.0 - 0.3 * i, 0.5, 0.2 + 0.3 * i], sheen_smoothness=0.9 - 0.4 * i)
        if i == 1:
            material.update(clearcoat=0.7, clearcoat_smoothness=0.6)
    scene["environment"] = {"color": [0.3, 0.3, 0.3]}
    return scene


def _anisotropic(scene):
    """The light zoo with anisotropic bases (one also sheened and coated): a setting of the
    material, compiled in both programs."""
    for i, material in enumerate(scene["materials"].values()):
        material.update(anisotropy_strength=1.0 - 0.3 * i, anisotropy_rotation=0.7 * i)
        if i == 1:
            material.update(clearcoat=0.7, clearcoat_smoothness=0.6, sheen_color=[0.4, 0.5, 0.6])
    scene["environment"] = {"color": [0.3, 0.3, 0.3]}
    return scene


def _iridescent(scene):
    """The light zoo with thin films on its bases (one also anisotropic and coated): a setting
    of the material, compiled in both programs."""
    for i, material in enumerate(scene["materials"].values()):
        material.update(iridescence=1.0 - 0.3 * i, iridescence_ior=1.3 + 0.3 * i,
                        iridescence_thickness_max=250.0 + 300.0 * i)
        if i == 1:
            material.update(anisotropy_strength=0.5, clearcoat=0.7)
    scene["environment"] = {"color": [0.3, 0.3, 0.3]}
    return scene


def _transmissive(scene):
    """The light zoo with transmissive bases (a thin wall, a tinted volume, one also filmed and
    coated) and a light behind them: a setting of the material, compiled in both programs."""
    for i, material in enumerate(scene["materials"].values()):
        material.update(transmission=1.0 - 0.3 * i)
        if i == 1:
            material.update(thickness=0.8, attenuation_color=[0.9, 0.5, 0.2], attenuation_distance=0.6, ior=1.4,
                            iridescence=0.5, clearcoat=0.7)
    scene["lights"].append({"type": "directional", "direction": [0.2, 0.1, 1.0], "intensity": 2.0})
    scene["environment"] = {"color": [0.3, 0.3, 0.3]}
    return scene


def _specular_f90(scene):
    """The light zoo's bases in the specular workflow with KHR_materials_specular's explicit F90
    (one also coated, one also sheened): a setting of the material, compiled in both programs."""
    for i, material in enumerate(scene["materials"].values()):
        material.pop("metallic", None)
        material.update(workflow="specular", specular=[0.02, 0.01 * i, 0.0], specular_f90=0.9 - 0.3 * i)
        if i == 1:
            material.update(clearcoat=0.7, sheen_color=[0.3, 0.2, 0.4])
    scene["environment"] = {"color": [0.3, 0.3, 0.3]}
    return scene


def _specular_metal(scene):
    """The light zoo's bases partly metallic with their own dielectric F0 (KHR_materials_ior /
    _specular on a metal; one with the explicit F90, one also coated): a setting of the
    material, compiled in both programs."""
    for i, material in enumerate(scene["materials"].values()):
        material.pop("specular", None)
        material.update(workflow="metallic", metallic=0.3 + 0.3 * i, dielectric_specular=[0.08, 0.02 * i, 0.05])
        if i == 0:
            material.update(specular_f90=0.6)
        if i == 1:
            material.update(clearcoat=0.7)
    scene["environment"] = {"color": [0.3, 0.3, 0.3]}
    return scene


# Radiance below this counts as 0 in the bit-for-bit comparison: the denormal range and what
# products of its values reach. Whether llvmpipe's rasteriser threads flush denormals depends
# on the state the process gives them, and where a lobe underflows into that range (the
# Blinn-Phong D's pow at a sphere's rim in chart_terms: 9e-39, and 9e-38 after a product) the
# two programs' different instruction orders then round differently: seen in 3 of 7 full-suite
# runs, never alone. 2^-100 (8e-31) is 23 orders below the half-float EXR's smallest step.
BELOW_ANY_OUTPUT = 2.0 ** -100


def _bits(linear):
    return np.where(np.abs(linear) < BELOW_ANY_OUTPUT, np.float32(0.0), linear).view(np.uint32)


@pytest.mark.parametrize("name", sorted(TEST_SCENES))
def test_specialised_and_full_programs_render_bit_identical_images(name, gl_context):
    # The full program adds exact neutral values (0 emission, x1 occlusion and maps, a
    # black environment, zero spare lights) in the same order of operations, so the
    # images agree bit for bit (measured: 0 ulp on every scene here, once values below
    # BELOW_ANY_OUTPUT are taken as 0).
    specialised = render.render_scene(TEST_SCENES[name](), gl_context)
    full = render.render_scene(TEST_SCENES[name](), gl_context, specialise=False)
    assert specialised.programs.specialised and not full.programs.specialised
    np.testing.assert_array_equal(_bits(specialised.linear), _bits(full.linear))
    np.testing.assert_array_equal(specialised.srgb8, full.srgb8)


MINIMAL = one_sphere({"albedo": [0.8, 0.5, 0.3], "smoothness": 0.6},
                     [{"type": "directional", "direction": [0.2, -0.3, -1]}], size=(16, 16))
# (u_dfg_lut is not in the list: the diffuse-specular coupling of every light reads the DFG
# table, so a lit scene without an environment uses it too.)
ABSENT_WHEN_UNUSED = ["u_emission", "u_occlusion", "u_alpha", "u_point_", "u_spot_", "u_env_sh",
                      "u_env_prefiltered", "u_albedo_map", "u_normal_map",
                      # call sites (the library's definitions stay, unused):
                      "pbr_spot_attenuation(gi.light.dir", "textureLod(u_env_irradiance",
                      "u_directional_active"]


def _preprocessed(source_text: str, tmp_path) -> str:
    """The fragment shader after the C preprocessor (glslangValidator -E)."""
    path = tmp_path / "shader.frag"
    path.write_text(source_text)
    out = subprocess.run(["glslangValidator", "-E", str(path)], capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    return re.sub(r"\s+", "", out.stdout)  # glslang re-spaces tokens ("gi . light")


def _programs_for(scene, specialise):
    plan = features.plan_programs(scene, specialise)
    defines = plan.defines["m"]
    source = programs.template_source("sphere.frag", defines).text
    return defines, source


def test_unused_effects_are_absent_from_the_specialised_source_and_uniforms(gl_context, tmp_path):
    scene = parse_scene(MINIMAL)
    defines, source = _programs_for(scene, specialise=True)
    text = _preprocessed(source, tmp_path)
    for token in ABSENT_WHEN_UNUSED:
        assert token not in text, token
    program = programs.program_from_templates(gl_context, "sphere.vert", "sphere.frag", defines)
    members = set(program)
    assert not [m for m in members if re.match(r"u_(emission|occlusion|alpha$|point|spot|env)", m)]
    assert "u_directional_radiance" in members
    assert "u_dfg_lut" in members  # the light's diffuse-specular coupling reads the table


def test_a_scene_without_light_has_no_dfg_table(gl_context, tmp_path):
    # emission only: no light, no environment, so nothing reads the DFG table
    scene = parse_scene(one_sphere({"albedo": [0.5, 0.5, 0.5], "emission": [1, 0, 0]}, [], size=(8, 8)))
    _, source = _programs_for(scene, specialise=True)
    assert "u_dfg_lut" not in _preprocessed(source, tmp_path)


def test_the_full_program_contains_every_effect(gl_context, tmp_path):
    _, source = _programs_for(parse_scene(MINIMAL), specialise=False)
    text = _preprocessed(source, tmp_path)
    for token in ABSENT_WHEN_UNUSED:
        assert token in text, token


def test_material_and_scene_features_follow_what_the_scene_can_show():
    scene = load_scene(ROOT / "scenes" / "unity_example" / "scene.json")
    report = features.features_report(scene)
    assert report["scene"]["directional"] == 1 and report["scene"]["point"] == 1 and report["scene"]["spot"] == 1
    assert report["scene"]["environment"] is True
    m = report["materials"]
    assert m["neon"]["emission"] and not m["neon"]["occlusion"] and not m["neon"]["alpha"]
    assert m["glass"]["alpha"] and m["smoke"]["alpha"] and m["leaf"]["alpha"]
    assert list(m["leaf"]["maps"]) == ["albedo"] and list(m["leaf"]["srgb_maps"]) == ["albedo"]
    assert not m["floor"]["emission"] and not m["floor"]["alpha"]
    assert m["bricks"]["custom_surface"].endswith("brick_surface.glsl") and m["bricks"]["emission"]


def test_programs_are_cached_across_renders(gl_context):
    scene = parse_scene(CHARTS["chart_f0"]())
    render.render_scene(scene, gl_context)
    compiled = programs.program_cache(gl_context).builds
    render.render_scene(parse_scene(CHARTS["chart_f0"]()), gl_context)
    assert programs.program_cache(gl_context).builds == compiled


def test_variant_explosion_falls_back_to_the_full_program_with_a_warning():
    scene = parse_scene(CHARTS["chart_terms"]())  # 17 distinct specialised programs (one per term variant)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        plan = features.plan_programs(scene, limit=8)
    assert not plan.specialised and "17 specialised programs, more than 8" in str(caught[0].message)
    assert features.plan_programs(scene, limit=17).specialised


def test_features_command_prints_json_for_a_scene(capsys):
    assert cli.main(["features", str(ROOT / "scenes" / "example.json")]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["programs"] == {"specialised": True, "distinct": 2, "limit": features.MAX_SPECIALISED_PROGRAMS}


def test_render_no_specialise_writes_the_same_image(tmp_path, capsys):
    scene_file = ROOT / "scenes" / "example.json"
    a, b = tmp_path / "a.exr", tmp_path / "b.exr"
    assert cli.main(["render", str(scene_file), "--hdr", str(a), "--size", "64x40"]) == 0
    assert cli.main(["render", str(scene_file), "--hdr", str(b), "--size", "64x40", "--no-specialise"]) == 0
    out = capsys.readouterr().out
    assert "2 specialised program(s)" in out and "2 full program(s)" in out
    assert a.read_bytes() != b"" and a.read_bytes() == b.read_bytes()


def _png_bytes(pixels) -> bytes:
    import io

    from PIL import Image

    out = io.BytesIO()
    Image.fromarray(pixels).save(out, format="PNG")
    return out.getvalue()


def _write_gltf(tmp_path) -> Path:
    import trimesh

    box = trimesh.creation.box()
    box.visual = trimesh.visual.TextureVisuals(material=trimesh.visual.material.PBRMaterial(
        name="painted", baseColorFactor=[200, 30, 30, 255], metallicFactor=0.0, roughnessFactor=0.4))
    files = trimesh.Scene(box).export(file_type="gltf")
    for name, data in files.items():
        (tmp_path / name).write_bytes(data)
    doc = json.loads((tmp_path / "model.gltf").read_text())
    flat_normal_png = base64.b64encode(_png_bytes(np.full((1, 1, 3), (128, 128, 255), np.uint8))).decode()
    doc["images"] = [{"uri": "data:image/png;base64," + flat_normal_png}]
    doc["textures"] = [{"source": 0}]
    doc["materials"].append({"name": "lamp", "emissiveFactor": [1.0, 0.8, 0.5], "alphaMode": "BLEND",
                             "normalTexture": {"index": 0}})
    lamp_primitive = dict(doc["meshes"][0]["primitives"][0], material=1)
    count = doc["accessors"][lamp_primitive["attributes"]["POSITION"]]["count"]
    uv = np.zeros((count, 2), np.float32).tobytes()  # the normal map reads TEXCOORD_0
    doc["buffers"].append({"byteLength": len(uv),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(uv).decode()})
    doc["bufferViews"].append({"buffer": len(doc["buffers"]) - 1, "byteLength": len(uv)})
    doc["accessors"].append({"bufferView": len(doc["bufferViews"]) - 1, "componentType": 5126,
                             "count": count, "type": "VEC2"})
    lamp_primitive["attributes"] = dict(lamp_primitive["attributes"], TEXCOORD_0=len(doc["accessors"]) - 1)
    doc["meshes"].append({"primitives": [lamp_primitive]})
    doc.setdefault("extensionsUsed", []).append("KHR_lights_punctual")
    doc.setdefault("extensions", {})["KHR_lights_punctual"] = {"lights": [
        {"type": "directional"}, {"type": "spot", "spot": {}}, {"type": "spot", "spot": {}}]}
    doc["nodes"] += [{"mesh": 1, "translation": [2, 0, 0]}] + [
        {"extensions": {"KHR_lights_punctual": {"light": i}}} for i in range(3)]
    doc["scenes"][0]["nodes"] += list(range(1, len(doc["nodes"])))
    (tmp_path / "model.gltf").write_text(json.dumps(doc))
    return tmp_path / "model.gltf"


def test_gltf_features_read_materials_and_punctual_lights(tmp_path, capsys):
    path = _write_gltf(tmp_path)
    assert cli.main(["features", str(path)]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["scene"]["directional"] == 1 and report["scene"]["spot"] == 2 and report["scene"]["point"] == 0
    painted, lamp = report["materials"]["painted"], report["materials"]["lamp"]
    assert not painted["emission"] and painted["alpha_mode"] == "opaque" and not painted["alpha"]
    assert lamp["emission"] and lamp["alpha_mode"] == "fade" and lamp["maps"] == ["normal"]


def test_bad_gltf_is_a_clear_error(tmp_path, capsys):
    (tmp_path / "broken.gltf").write_text("{not json")
    assert cli.main(["features", str(tmp_path / "broken.gltf")]) == 2
    assert "not a readable glTF 2.0 file" in capsys.readouterr().err


# The clear coat's uniforms and call sites: only where a material has a coat, in the
# specialised and the full program alike (a layer is a setting of the material).
COAT_TOKENS = ["u_clearcoat", ",layers,o.Normal,v,gi,", "pbrlab_surf_layers(IN,layers)"]


@pytest.mark.parametrize("specialise", [True, False], ids=["specialised", "full"])
def test_a_material_without_a_coat_has_none_of_its_code(tmp_path, specialise):
    _, plain = _programs_for(parse_scene(MINIMAL), specialise)
    coated_scene = json.loads(json.dumps(MINIMAL))
    coated_scene["materials"]["m"].update(clearcoat=1.0)
    _, coated = _programs_for(parse_scene(coated_scene), specialise)
    plain_text, coated_text = _preprocessed(plain, tmp_path), _preprocessed(coated, tmp_path)
    for token in COAT_TOKENS:
        assert token not in plain_text and token in coated_text, token


# The sheen's uniforms, table and call sites: only where a material has a sheen.
SHEEN_TOKENS = ["u_sheen_color", "u_sheen_smoothness", "u_sheen_lut", "pbrlab_surf_sheen(IN,layers)",
                ",layers,o.Normal,v,gi,"]


@pytest.mark.parametrize("specialise", [True, False], ids=["specialised", "full"])
def test_a_material_without_a_sheen_has_none_of_its_code(tmp_path, specialise):
    _, plain = _programs_for(parse_scene(MINIMAL), specialise)
    sheened_scene = json.loads(json.dumps(MINIMAL))
    sheened_scene["materials"]["m"].update(sheen_color=[0.5, 0.4, 0.9])
    _, sheened = _programs_for(parse_scene(sheened_scene), specialise)
    plain_text, sheened_text = _preprocessed(plain, tmp_path), _preprocessed(sheened, tmp_path)
    for token in SHEEN_TOKENS:
        assert token not in plain_text and token in sheened_text, token


# The anisotropy's uniforms and call sites: only where a material's base is anisotropic.
ANISOTROPY_TOKENS = ["u_anisotropy_strength", "u_anisotropy_rotation", "pbrlab_surf_anisotropy(IN,layers)",
                     "pbr_lighting_anisotropic(diffColor,specColor", "AnisotropicReflectionNormal(o.Normal"]


# The thin film's uniforms and call sites: only where a material's base has a film.
IRIDESCENCE_TOKENS = ["u_iridescence", "u_iridescence_ior", "u_iridescence_thickness",
                      "pbrlab_surf_iridescence(IN,layers)", "filmF0=pbr_iridescent_f0_with_coat(specColor"]
# The transmission's uniforms and call sites, and the scene's transmission copy it reads
# (templates/transmission_scene.inc): only where a material transmits.
TRANSMISSION_TOKENS = ["u_transmission", "u_attenuation_color", "pbrlab_surf_transmission(IN,layers)",
                       "c+=pbr_layers_lighting_transmission(", "TransmittedDirection(o.Normal",
                       "u_transmission_scene", "u_transmission_view_proj", "u_transmission_lod_scale",
                       "pbrlab_transmitted_radiance("]
_NO_SHEEN_OR_COAT = ["u_sheen_color", "u_clearcoat", ",layers,o.Normal,v,gi,"]
# The explicit F90's uniform and call sites (KHR_materials_specular): only where a material has one.
SPECULAR_F90_TOKENS = ["u_specular_f90", "pbrlab_surf_specular_f90(IN,layers)",
                       "pbr_lighting_standard_f90(diffColor,specColor,f90,coatF0,coatF90"]
# The metallic workflow's own dielectric F0's uniform and call sites: only where a material has one.
DIELECTRIC_SPECULAR_TOKENS = ["u_dielectric_specular", "pbrlab_surf_dielectric_specular(IN,layers)",
                              "returnlayers.DielectricSpecular;"]
# layer: (the material fields that turn it on, its tokens, tokens of the other layers its
# program must still lack)
BASE_LAYERS = {
    "anisotropy": ({"anisotropy_strength": 0.6, "anisotropy_rotation": 0.5}, ANISOTROPY_TOKENS,
                   _NO_SHEEN_OR_COAT),
    "iridescence": ({"iridescence": 0.8, "iridescence_thickness_max": 500.0}, IRIDESCENCE_TOKENS,
                    ANISOTROPY_TOKENS[:1] + ["pbr_lighting_anisotropic(diffColor,specColor"] + _NO_SHEEN_OR_COAT),
    "transmission": ({"transmission": 0.7, "thickness": 0.5}, TRANSMISSION_TOKENS,
                     IRIDESCENCE_TOKENS[-1:] + ANISOTROPY_TOKENS[:1] + _NO_SHEEN_OR_COAT),
    "specular_f90": ({"workflow": "specular", "specular": [0.02, 0.02, 0.02], "specular_f90": 0.5},
                     SPECULAR_F90_TOKENS, IRIDESCENCE_TOKENS[-1:] + ANISOTROPY_TOKENS[:1] + TRANSMISSION_TOKENS[:1]
                     + _NO_SHEEN_OR_COAT),
    "dielectric_specular": ({"metallic": 0.5, "dielectric_specular": [0.08, 0.02, 0.05]}, DIELECTRIC_SPECULAR_TOKENS,
                            SPECULAR_F90_TOKENS[:2] + IRIDESCENCE_TOKENS[-1:] + ANISOTROPY_TOKENS[:1]
                            + TRANSMISSION_TOKENS[:1] + _NO_SHEEN_OR_COAT),
}


@pytest.mark.parametrize("specialise", [True, False], ids=["specialised", "full"])
@pytest.mark.parametrize("layer", sorted(BASE_LAYERS))
def test_a_material_without_a_base_layer_has_none_of_its_code(tmp_path, layer, specialise):
    """Anisotropy, a thin film, transmission, an explicit F90, a dielectric F0: none of a layer's code in a program whose
    material lacks it, and a material with one layer has none of the others' code."""
    fields, tokens, absent = BASE_LAYERS[layer]
    _, plain = _programs_for(parse_scene(MINIMAL), specialise)
    layered_scene = json.loads(json.dumps(MINIMAL))
    layered_scene["materials"]["m"].update(fields)
    _, layered = _programs_for(parse_scene(layered_scene), specialise)
    plain_text, layered_text = _preprocessed(plain, tmp_path), _preprocessed(layered, tmp_path)
    for token in tokens:
        assert token not in plain_text and token in layered_text, token
    for token in absent:
        assert token not in layered_text, token


# A surface file's layers are the ones it writes (harness/pbrlab/scene/surface_layers.py): the
# brick surface writes none, coat.glsl the clear coat only.
LAYERED_SURFACES = ROOT / "tests" / "surface" / "layered_surfaces"
LAYER_CALL_SITES = {"clearcoat": ",layers,o.Normal,v,gi,", "sheen": "u_sheen_lut",
                    "anisotropy": "AnisotropicReflectionNormal(o.Normal",
                    "iridescence": "filmF0=pbr_iridescent_f0_with_coat(specColor",
                    "transmission": "TransmittedDirection(o.Normal"}


@pytest.mark.parametrize("specialise", [True, False], ids=["specialised", "full"])
@pytest.mark.parametrize("surface, written", [
    (ROOT / "scenes" / "unity_example" / "brick_surface.glsl", ()),
    (LAYERED_SURFACES / "coat.glsl", ("clearcoat",)),
    (LAYERED_SURFACES / "every_layer.glsl", tuple(LAYER_CALL_SITES))], ids=["brick", "coat", "every_layer"])
def test_a_surface_file_compiles_only_the_layers_it_writes(tmp_path, surface, written, specialise):
    data = json.loads(json.dumps(MINIMAL))
    data["materials"]["m"] = {"surface": str(surface)}
    if surface.name == "brick_surface.glsl":
        data["materials"]["m"]["textures"] = {
            name: {"path": str(ROOT / "scenes" / "assets" / f"bricks_{file}.png"), "srgb": False}
            for name, file in (("_MainTex", "albedo"), ("_BumpMap", "normal"),
                               ("_MetallicGlossMap", "metallic_smoothness"), ("_EmissionMap", "emission"))}
    defines = features.plan_programs(parse_scene(data), specialise).defines["m"]
    text = _preprocessed(programs.template_source("sphere.frag", defines, surface).text, tmp_path)
    for layer, token in LAYER_CALL_SITES.items():
        assert (token in text) == (layer in written), (layer, token)
    assert ("pbrlab_default_layers()" in text) == bool(written)
