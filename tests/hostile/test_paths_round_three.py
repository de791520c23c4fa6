"""Issue 39 (round three), reads outside the model's folder through symbolic links. Models
arrive as archives, and archives carry links: each case here is a tar file holding a model
folder and a sibling "secret" folder, unpacked as tar unpacks it (links kept), then rendered.
A link inside the model's folder that leads out of it (to a buffer, an image, a whole folder,
the glTF or scene file itself, a mesh, an environment, a surface, an include, a Unity
texture) must be refused by name without ``--allow-outside``: exit 2, one message naming the
link and the flag, no output written, and no file under secret/ opened by Python (an audit
hook records every ``open``). Controls: links that stay inside, and ``..`` written in a JSON
scene, still render; with ``--allow-outside`` the linked files are read, and the secret red
texture then shows in the image (so the cases do lead to the secret)."""

import base64
import io
import json
import os
import sys
import tarfile
from pathlib import Path

import numpy as np
import pytest

from hostile_common import UNITY_TEXTURE, base_scene
from pbrlab.commands import cli
from pbrlab.foundation import images

# Every path Python opens while a case runs (sys.audit's "open" event: open(), io.open,
# os.open, Path.read_bytes; C libraries' own reads are not seen, the refusal covers them).
_OPENED: list | None = None


def _record_open(event, args):
    if event == "open" and _OPENED is not None and isinstance(args[0], (str, bytes, os.PathLike)):
        _OPENED.append(os.fsdecode(args[0]))


sys.addaudithook(_record_open)

RED, GREEN = (255, 0, 0, 255), (0, 255, 0, 255)


def _quad(image_uri: str | None = None, buffer_uri: str | None = None) -> dict:
    """One indexed quad facing +Z with UVs, base colour from ``image_uri`` when given; its
    buffer a data: URI, or the file ``buffer_uri``. The image is its base colour and its emission
    (the file has no lights: the emission is what shows)."""
    positions = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], np.float32)
    normals = np.tile(np.array([0, 0, 1], np.float32), (4, 1))
    uv = np.array([[0, 1], [1, 1], [1, 0], [0, 0]], np.float32)
    indices = np.array([0, 1, 2, 0, 2, 3], np.uint16)
    blob = positions.tobytes() + normals.tobytes() + uv.tobytes() + indices.tobytes()
    uri = buffer_uri or "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    material = {"pbrMetallicRoughness": {"metallicFactor": 0.0, "roughnessFactor": 0.9}}
    doc = {"asset": {"version": "2.0"},
           "buffers": [{"byteLength": len(blob), "uri": uri}],
           "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n}
                           for o, n in ((0, 48), (48, 48), (96, 32), (128, 12))],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                          "min": [-1, -1, 0], "max": [1, 1, 0]},
                         {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                         {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                         {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}],
           "materials": [material],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                       "indices": 3, "material": 0}]}],
           "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0}
    if image_uri is not None:
        doc["images"] = [{"uri": image_uri}]
        doc["textures"] = [{"source": 0}]
        material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
        material.update(emissiveTexture={"index": 0}, emissiveFactor=[1, 1, 1])  # seen without lights
    return doc, blob


SURFACE = "void surf(Input IN, inout SurfaceOutputStandard o) {\n    o.Albedo = vec3(0.8, 0.4, 0.2);\n}\n"
SURFACE_INCLUDING = '#include "helper.glsl"\n' + SURFACE.replace("vec3(0.8, 0.4, 0.2)", "helper_albedo()")
HELPER = "vec3 helper_albedo() { return vec3(1.0, 0.0, 0.0); }\n"
UNITY_INCLUDING = UNITY_TEXTURE.replace("#pragma surface surf Lambert",
                                        '#pragma surface surf Lambert\n        #include "helper.cginc"')
UNITY_HELPER = "float helper_value() { return 1.0; }\n"


def _scene(**material) -> dict:
    scene = base_scene()
    scene["materials"]["m"] = material or {"albedo": [0.5, 0.5, 0.5]}
    return scene


def _files(root: Path) -> dict:
    """Every regular file and link of the archive: {relative path: bytes, or ("link", target)}."""
    blob = _quad()[1]
    return {
        "secret/quad.bin": blob,
        "secret/scene.gltf": json.dumps(_quad("albedo.png")[0]).encode(),
        "secret/scene.json": json.dumps(_scene()).encode(),
        "secret/mesh.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "secret/surface.glsl": SURFACE.encode(),
        "secret/helper.glsl": HELPER.encode(),
        "secret/helper.cginc": UNITY_HELPER.encode(),
        "model/mesh_local.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        "model/surface_including.glsl": SURFACE_INCLUDING.encode(),
        "model/texture.shader": UNITY_TEXTURE.encode(),
        "model/including.shader": UNITY_INCLUDING.encode(),
        # links that lead out of model/
        "model/quad.bin": ("link", "../secret/quad.bin"),
        "model/abs.bin": ("link", str(root / "secret" / "quad.bin")),
        "model/albedo.png": ("link", "../secret/albedo.png"),
        "model/textures": ("link", "../secret"),
        "model/hop.png": ("link", "../secret/albedo.png"),
        "model/chain.png": ("link", "hop.png"),
        "model/linked.gltf": ("link", "../secret/scene.gltf"),
        "model/linked.json": ("link", "../secret/scene.json"),
        "model/sky.exr": ("link", "../secret/sky.exr"),
        "model/mesh.obj": ("link", "../secret/mesh.obj"),
        "model/surface.glsl": ("link", "../secret/surface.glsl"),
        "model/helper.glsl": ("link", "../secret/helper.glsl"),
        "model/helper.cginc": ("link", "../secret/helper.cginc"),
        "model/shared/tex.png": ("link", "../../secret/albedo.png"),
        # links that stay inside model/
        "model/inside.png": ("link", "ok.png"),
        "model/sub/inside_up.png": ("link", "../ok.png"),
        "secret/side.pbrlab.json": json.dumps({"environment": {"color": [1, 0, 0]}}).encode(),
        "model/side.pbrlab.json": ("link", "../secret/side.pbrlab.json"),
    }


def _gltf(name, **kw):
    return name, json.dumps(_quad(**kw)[0]).encode()


# case: (the file rendered, files that name the links, the link named in the refusal)
REFUSED = {
    "glTF buffer through a link": ("buffer.gltf", dict([_gltf("buffer.gltf", buffer_uri="quad.bin")]), "quad.bin"),
    "glTF buffer through an absolute link": ("abs.gltf", dict([_gltf("abs.gltf", buffer_uri="abs.bin")]), "abs.bin"),
    "glTF image through a link": ("image.gltf", dict([_gltf("image.gltf", image_uri="albedo.png")]), "albedo.png"),
    "glTF image in a linked folder": ("folder.gltf", dict([_gltf("folder.gltf", image_uri="textures/albedo.png")]),
                                      "textures"),
    "glTF image through two links": ("chain.gltf", dict([_gltf("chain.gltf", image_uri="chain.png")]), "hop.png"),
    "the glTF itself a link": ("linked.gltf", {}, "linked.gltf"),
    "the JSON scene itself a link": ("linked.json", {}, "linked.json"),
    "JSON texture": ("tex.json", {"tex.json": _scene(textures={"albedo": "albedo.png"})}, "albedo.png"),
    "JSON environment": ("env.json", {"env.json": {**_scene(), "environment": {"path": "sky.exr"}}}, "sky.exr"),
    "JSON mesh": ("mesh.json", {"mesh.json": {**_scene(), "objects": [{"mesh": "mesh.obj", "material": "m"}]}},
                  "mesh.obj"),
    "JSON glTF object": ("gltfobj.json", {"gltfobj.json": {**_scene(), "objects": [{"gltf": "linked.gltf"}]}},
                         "linked.gltf"),
    "JSON surface": ("surf.json", {"surf.json": _scene(surface="surface.glsl")}, "surface.glsl"),
    "surface #include": ("inc.json", {"inc.json": _scene(surface="surface_including.glsl")}, "helper.glsl"),
    "Unity texture property": ("unity.json", {"unity.json": _scene(
        surface="texture.shader", properties={"_MainTex": {"path": "albedo.png"}})}, "albedo.png"),
    "Unity #include": ("unityinc.json", {"unityinc.json": _scene(surface="including.shader")}, "helper.cginc"),
    "glTF's side file (model.pbrlab.json)": ("side.gltf", dict([_gltf("side.gltf")]), "side.pbrlab.json"),
    "JSON .. then a link": ("sub/dotdot.json", {"sub/dotdot.json": _scene(textures={"albedo": "../shared/tex.png"})},
                            "tex.png"),
}

HANDLED = {
    "glTF image through a link that stays inside": ("inside.gltf", dict([_gltf("inside.gltf", image_uri="inside.png")])),
    "JSON texture through links that stay inside": ("inside.json", {"inside.json": _scene(
        textures={"albedo": "sub/inside_up.png"})}),
    "JSON .. written, no link": ("sub/up.json", {"sub/up.json": _scene(textures={"albedo": "../ok.png"})}),
    "JSON mesh, a plain file": ("plain_mesh.json", {"plain_mesh.json": {
        **_scene(), "objects": [{"mesh": "mesh_local.obj", "material": "m"}]}}),
}


def _unpacked(tmp_path: Path, extra: dict) -> Path:
    """The archive of _files (plus ``extra``: model files by name) made with tarfile and
    unpacked into tmp_path/unpacked, links and all, as `tar x` would; returns that folder."""
    root = tmp_path / "unpacked"
    entries = {**_files(root), **{f"model/{k}": (json.dumps(v).encode() if isinstance(v, dict) else v)
                                  for k, v in extra.items()}}
    archive = tmp_path / "model.tar"
    with tarfile.open(archive, "w") as tar:
        for name, content in sorted(entries.items()):
            info = tarfile.TarInfo(name)
            if isinstance(content, tuple):
                info.type, info.linkname = tarfile.SYMTYPE, content[1]
                tar.addfile(info)
            else:
                info.size = len(content)
                tar.addfile(info, io.BytesIO(content))
    with tarfile.open(archive) as tar:
        kwargs = {"filter": "fully_trusted"} if hasattr(tarfile, "fully_trusted_filter") else {}
        tar.extractall(root, **kwargs)
    images.write_png(root / "secret" / "albedo.png", np.full((4, 4, 4), RED, np.uint8))
    images.write_png(root / "model" / "ok.png", np.full((4, 4, 4), GREEN, np.uint8))
    images.write_exr(root / "secret" / "sky.exr", np.ones((8, 16, 3), np.float32))
    assert (root / "model" / "quad.bin").is_symlink() and (root / "model" / "textures").is_symlink()
    return root


def _render(root: Path, name: str, capsys, *flags) -> tuple[int, str, list]:
    global _OPENED
    out = root / "out.png"
    _OPENED = []
    try:
        status = cli.main(["render", str(root / "model" / name), "-o", str(out), "--size", "8x8", *flags])
    finally:
        opened, _OPENED = _OPENED, None
    secret = os.path.realpath(root / "secret")
    read = sorted({p for p in opened if os.path.realpath(p).startswith(secret + os.sep)})
    return status, capsys.readouterr().err, read


@pytest.mark.parametrize("case", list(REFUSED))
def test_a_link_out_of_the_models_folder_is_refused_by_name(tmp_path, capsys, case, census):
    name, extra, link = REFUSED[case]
    root = _unpacked(tmp_path, extra)
    status, err, read = _render(root, name, capsys)
    assert status == 2, err
    assert "Traceback" not in err and err.count("\n") == 1, err
    assert link in err and "symbolic link" in err and "--allow-outside" in err, err
    assert not (root / "out.png").exists(), "a refused render wrote its output"
    assert read == [], f"files outside the model's folder were opened: {read}"
    census["path outside the folder", "refused cleanly"] += 1


@pytest.mark.parametrize("case", list(HANDLED))
def test_links_and_dotdot_that_stay_where_they_may_still_render(tmp_path, capsys, case, census):
    name, extra = HANDLED[case]
    root = _unpacked(tmp_path, extra)
    status, err, read = _render(root, name, capsys)
    assert status == 0, err
    assert read == []
    assert images.read_image(root / "out.png").shape[:2] == (8, 8)
    census["path inside the folder", "handled"] += 1


def _lit_channels(path: Path) -> tuple[float, set]:
    """(the fraction of pixels not black, the channels that are non-zero in any pixel)."""
    rgb = images.read_image(path)[..., :3].reshape(-1, 3)
    lit = rgb.max(axis=1) > 0
    return float(lit.mean()), {int(c) for c in np.nonzero(rgb[lit].max(axis=0))[0]}


def test_allow_outside_reads_the_linked_secret_and_it_shows(tmp_path, capsys, census):
    """The control that the links lead where the refusals say: with the flag, the quad whose
    image is ``albedo.png -> ../secret/albedo.png`` (pure red, emissive, no lights) shows only
    red, where the same quad through ``inside.png -> ok.png`` (pure green) shows only green.
    Per pixel, exactly: an emissive pure colour with no light leaves the other channels at 0
    through the tonemap and the sRGB encode (measured: 40 of 64 pixels lit, each 255 in the one
    channel and 0 in the others, in both images; the bound 0.5 is "the quad fills most of the
    framing view", which is what the framing does)."""
    root = _unpacked(tmp_path, dict([_gltf("image.gltf", image_uri="albedo.png"),
                                     _gltf("inside.gltf", image_uri="inside.png")]))
    status, err, read = _render(root, "image.gltf", capsys, "--allow-outside")
    assert status == 0, err
    assert read, "the secret image was not read through the link"
    red = _lit_channels(root / "out.png")
    status, err, _ = _render(root, "inside.gltf", capsys)
    assert status == 0, err
    green = _lit_channels(root / "out.png")
    assert red[0] >= 0.5 and red[1] == {0}, red
    assert green[0] >= 0.5 and green[1] == {1}, green
    census["path outside the folder", "handled (--allow-outside)"] += 1


@pytest.mark.parametrize("case", ["JSON texture", "Unity #include", "the glTF itself a link", "surface #include"])
def test_allow_outside_reads_through_the_links(tmp_path, capsys, case, census):
    name, extra, _ = REFUSED[case]
    root = _unpacked(tmp_path, extra)
    status, err, _ = _render(root, name, capsys, "--allow-outside")
    assert status == 0, err
    census["path outside the folder", "handled (--allow-outside)"] += 1
