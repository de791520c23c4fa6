"""Cross-check of glTF 2.0 files against pyrender 0.1.45, which reads them itself.

pyrender side (a subprocess, as in pyrender_check): ``trimesh.load`` of the file and
``pyrender.Scene.from_trimesh_scene``: trimesh's glTF reader places the meshes by their
nodes and reads the materials (factors, baseColor / metallicRoughness / normal /
emissive textures, alpha mode, doubleSided); pyrender uploads and samples the textures.
Neither reads KHR_lights_punctual or the camera's node, so the worker adds them from
the file's JSON: intensity and colour as written (pyrender shades with no pi: its units
are glTF's), cone angles as written, poses from the node hierarchy.

pbrlab side: ``pbrlab.importers.gltf.load_gltf`` (the importer under test: nodes, primitives, the
material mapping, textures, samplers, UV sets, lights with their unit conversion,
camera) rendered by ``render_scene`` with templates/pyrender_mesh.frag, which lights the
default surface's output with pyrender's terms (templates/pyrender_brdf.inc, the
composition pyrender_check measured on the sphere grid) and encodes and blends as
pyrender does. The comparison, mask and tolerances are pyrender_check's.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

from ...foundation.errors import PbrlabError
from .check import PYRENDER_GAMMA, PyrenderImage

COMPOSITION_TEMPLATE = "pyrender_mesh.frag"
PYRENDER_ZFAR = 1000.0  # the assets' cameras give no zfar (infinite); pyrender needs one


def _worker(platform: str, size: str, out_folder: str, paths: list[str]) -> None:
    """pyrender's renders of glTF files (this process only): out_folder/<i>.npz each
    with srgb8, coverage, info."""
    from ...gpu import gl
    from .compat import import_pyrender

    gl.pin_llvmpipe_cpu_caps()
    pyrender = import_pyrender(platform)
    w, h = (int(x) for x in size.split("x"))
    for i, path in enumerate(paths):
        _render_one(pyrender, platform, path, w, h, str(Path(out_folder) / f"{i}.npz"))


def _render_one(pyrender, platform, path, w, h, out_path) -> None:
    import math

    import trimesh

    from ...importers.gltf.document import read_document
    from ...importers.gltf.nodes import walk

    loaded = trimesh.load(path, force="scene")
    scene = pyrender.Scene.from_trimesh_scene(loaded, bg_color=[0.0, 0.0, 0.0, 0.0], ambient_light=[0.0, 0.0, 0.0])
    doc = read_document(path)
    lights = doc.json.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    camera_added = False
    for index, world in walk(doc, None):
        node = doc.json["nodes"][index]
        pose = world.copy()
        pose[:3, :3] /= np.linalg.norm(pose[:3, :3], axis=0)  # rotation only (pyrender reads -Z)
        light_ref = node.get("extensions", {}).get("KHR_lights_punctual")
        if light_ref is not None:
            spec = lights[light_ref["light"]]
            colour = [float(c) for c in spec.get("color", [1.0, 1.0, 1.0])]
            intensity = float(spec.get("intensity", 1.0))
            if spec["type"] == "directional":
                light = pyrender.DirectionalLight(color=colour, intensity=intensity)
            elif spec["type"] == "point":
                light = pyrender.PointLight(color=colour, intensity=intensity)
            else:
                cone = spec.get("spot", {})
                light = pyrender.SpotLight(color=colour, intensity=intensity,
                                           innerConeAngle=float(cone.get("innerConeAngle", 0.0)),
                                           outerConeAngle=float(cone.get("outerConeAngle", math.pi / 4)))
            scene.add(light, pose=pose)
        if "camera" in node and not camera_added:
            spec = doc.json["cameras"][node["camera"]]["perspective"]
            scene.add(pyrender.PerspectiveCamera(yfov=float(spec["yfov"]), aspectRatio=w / h,
                                                 znear=float(spec.get("znear", 0.05)), zfar=PYRENDER_ZFAR),
                      pose=pose)
            camera_added = True
    renderer = pyrender.OffscreenRenderer(w, h)
    try:
        color, depth = renderer.render(scene, flags=pyrender.RenderFlags.RGBA)
        from OpenGL import GL
        info = {"platform": platform, "GL_RENDERER": GL.glGetString(GL.GL_RENDERER).decode(),
                "pyrender": getattr(pyrender, "__version__", "?")}
    finally:
        renderer.delete()
    np.savez(out_path, rgb8=np.ascontiguousarray(color[..., :3]), coverage=depth > 0, info=json.dumps(info))


def render_pyrender_gltf(path, platform: str, size, timeout: float = 120.0) -> PyrenderImage:
    """pyrender's render of a glTF file with its perspective camera, at ``size`` (w, h)."""
    return render_pyrender_gltf_files([path], platform, size, timeout)[0]


def render_pyrender_gltf_files(paths, platform: str, size, timeout: float = 300.0) -> list[PyrenderImage]:
    """pyrender's renders of several glTF files, in one subprocess on ``platform``."""
    if platform not in ("egl", "osmesa"):
        raise ValueError(f"platform must be 'egl' or 'osmesa', got {platform!r}")
    with tempfile.TemporaryDirectory(prefix="pbrlab-pyrender-gltf-") as tmp:
        env = dict(os.environ, PYOPENGL_PLATFORM=platform)
        proc = subprocess.run([sys.executable, "-m", "pbrlab.checking.pyrender.gltf_check", "--worker", platform,
                               f"{size[0]}x{size[1]}", tmp, *(str(p) for p in paths)],
                              capture_output=True, text=True, env=env, timeout=timeout)
        outs = [Path(tmp) / f"{i}.npz" for i in range(len(paths))]
        if proc.returncode != 0 or not all(o.is_file() for o in outs):
            raise PbrlabError(f"pyrender ({platform}) failed on {[str(p) for p in paths]} with exit code "
                              f"{proc.returncode}:\n{proc.stderr[-3000:]}")
        images = []
        for out in outs:
            with np.load(out) as data:
                images.append(PyrenderImage(data["rgb8"].copy(), data["coverage"].copy(),
                                            json.loads(str(data["info"]))))
        return images


def render_pbrlab_gltf_terms(path, ctx=None, size=None) -> np.ndarray:
    """pbrlab's import of the file, lit with pyrender's terms: HxWx4 float32, RGB linear
    (pyrender's display codes' values before quantisation, decoded with pow 2.2),
    alpha = coverage."""
    from ...importers.gltf import load_gltf
    from ...render.renderer import render_scene

    scene = load_gltf(path, size=size, emit_warnings=False).scene
    for material in scene.materials.values():  # decoded after filtering, in the shader
        material.texture_srgb = {slot: False for slot in material.texture_srgb}
    rendering = render_scene(scene, ctx, size=size, mesh_fragment=COMPOSITION_TEMPLATE)
    out = rendering.linear.copy()
    out[..., :3] = np.clip(out[..., :3], 0.0, 1.0) ** PYRENDER_GAMMA
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="pyrender glTF cross-check (worker entry point)")
    parser.add_argument("--worker", nargs=3, metavar=("PLATFORM", "WxH", "OUT_FOLDER"), required=True)
    parser.add_argument("files", nargs="+", help="glTF files")
    args = parser.parse_args(argv)
    _worker(*args.worker, args.files)
    return 0


if __name__ == "__main__":
    sys.exit(main())
