"""The WebGPU example: a pbrlab scene of analytic spheres, directional lights and a constant
environment (scene.json, the file `pbrlab render` reads) drawn by wgpu (wgpu-py, on whatever
Vulkan driver the machine has: Mesa's lavapipe in CI), each sphere a full-screen draw whose
fragment program is the pbrlab library in WGSL, made one of two ways:

  --route naga   sphere.frag.glsl + the GLSL library, amalgamated (`pbrlab amalgamate`) and
                 translated by naga (the translator inside wgpu, Bevy and Firefox's WebGPU);
  --route slang  sphere.frag.hlsl + the HLSL ports (hlsl_ports/), compiled by Slang.

The DFG table (`pbrlab tables`) is bound through the library's PBR_DFG_LUT_LOOKUP hook.

    python examples/wgpu/render.py examples/wgpu/scene.json OUT [--route naga|slang]

writes OUT.npy (float32 RGBA, rows top to bottom, linear radiance; alpha 0 where no sphere),
OUT.json (the adapter, the route, the translator's version) and OUT.wgsl (the fragment program
as WebGPU compiled it). tests/examples/test_wgpu_example.py compares OUT.npy with `pbrlab render`.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
LAVAPIPE_ICD = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json"  # Debian's mesa-vulkan-drivers
MAX_LIGHTS = 4               # sphere.frag.glsl's
DRAW_UNIFORM_VEC4S = 10 + 2 * MAX_LIGHTS  # the SphereDraw block: 10 vec4s, then two vec4 arrays (std140)
COLOR_FORMAT = "rgba32float"
DEPTH_FORMAT = "depth32float"


def fragment_wgsl(route: str) -> tuple[str, str]:
    """The fragment program in WGSL and what made it (translator and version)."""
    if route == "naga":
        from pbrlab.gpu import naga, shaders
        glsl = shaders.amalgamate(HERE / "sphere.frag.glsl")
        return naga.glsl_to_wgsl(glsl, "frag", "examples/wgpu/sphere.frag.glsl"), naga.naga_version()
    if route == "slang":
        import slangpy
        from pbrlab.gpu import hlsl, slang_wgsl
        text = (HERE / "sphere.frag.hlsl").read_text(encoding="utf-8")
        wgsl = slang_wgsl.hlsl_to_wgsl(text, "examples/wgpu/sphere.frag.hlsl", [hlsl.HLSL_ROOT])
        return wgsl, f"Slang (slangpy {slangpy.__version__})"
    raise ValueError(f"unknown route {route!r} (naga or slang)")


def _draw_uniforms(frame, scene, sphere, material) -> np.ndarray:
    """One sphere's SphereDraw block, std140: every member a vec4 (16 bytes)."""
    block = np.zeros((DRAW_UNIFORM_VEC4S, 4), np.float32)
    block[0, :3], block[1, :3] = frame.position, frame.forward
    block[2, :3], block[3, :3] = frame.right, frame.up
    block[4, :2] = frame.size
    block[5, :3], block[5, 3] = sphere[0], sphere[1]
    block[6, :3] = material.albedo
    block[7, :2] = material.metallic, material.smoothness
    env = scene.environment
    if env is not None:
        block[8, :3] = env.color * env.intensity
    block[9].view(np.int32)[0] = len(scene.lights)
    for i, light in enumerate(scene.lights):
        block[10 + i, :3] = light.direction
        block[10 + MAX_LIGHTS + i, :3] = light.color * light.intensity
    return block


def _check_scene(scene) -> None:
    """What this example draws: spheres of metallic materials, directional lights, a constant
    environment (or none); anything else is refused by name."""
    from pbrlab.foundation.errors import SceneError
    if len(scene.lights) > MAX_LIGHTS:
        raise SceneError(f"{scene.source}: at most {MAX_LIGHTS} lights in this example")
    for light in scene.lights:
        if light.type != "directional":
            raise SceneError(f"{scene.source}: this example draws directional lights only, not {light.type}")
    if scene.environment is not None and scene.environment.path is not None:
        raise SceneError(f"{scene.source}: this example takes a constant environment ({{\"color\": ...}}) only")
    for obj in scene.objects:
        if obj.sphere is None:
            raise SceneError(f"{obj.where}: this example draws spheres only")
        if getattr(scene.materials[obj.material], "workflow", "metallic") != "metallic":
            raise SceneError(f"{obj.where}: this example takes the metallic workflow only")


def _adapter(wgpu):
    """The Vulkan adapter (lavapipe where VK_ICD_FILENAMES names it, as main() does)."""
    for adapter in wgpu.gpu.enumerate_adapters_sync():
        if adapter.info["backend_type"] == "Vulkan":
            return adapter
    raise RuntimeError("wgpu found no Vulkan adapter (Mesa's lavapipe: apt-get install mesa-vulkan-drivers)")


def render(scene_path: Path, wgsl: str) -> tuple[np.ndarray, dict]:
    """Draw the scene with the fragment program ``wgsl``: (H x W x 4 float32, adapter info)."""
    import wgpu
    from pbrlab.gpu.ibl import dfg_lut
    from pbrlab.maths.camera import camera_frame
    from pbrlab.scene import load_scene

    scene = load_scene(scene_path)
    _check_scene(scene)
    frame = camera_frame(scene.camera, scene_radius=1.0)  # the basis does not depend on the radius
    width, height = frame.size
    adapter = _adapter(wgpu)
    # rg32float is filterable only with this feature (WebGPU spec, "float32-filterable"); the GL
    # renderer reads the same float32 table bilinearly.
    device = adapter.request_device_sync(required_features=["float32-filterable"])

    table = np.ascontiguousarray(np.flipud(dfg_lut()), np.float32)  # bottom row first: v = 0 there
    dfg = device.create_texture(size=(table.shape[1], table.shape[0], 1), format="rg32float",
                                usage=wgpu.TextureUsage.TEXTURE_BINDING | wgpu.TextureUsage.COPY_DST)
    device.queue.write_texture({"texture": dfg}, table.tobytes(),
                               {"bytes_per_row": table.shape[1] * 8, "rows_per_image": table.shape[0]},
                               (table.shape[1], table.shape[0], 1))
    sampler = device.create_sampler(mag_filter="linear", min_filter="linear", mipmap_filter="nearest",
                                    address_mode_u="clamp-to-edge", address_mode_v="clamp-to-edge")

    vertex = device.create_shader_module(code=(HERE / "fullscreen.wgsl").read_text(encoding="utf-8"))
    fragment = device.create_shader_module(code=wgsl)
    pipeline = device.create_render_pipeline(
        layout="auto",
        vertex={"module": vertex, "entry_point": "main"},
        fragment={"module": fragment, "entry_point": "main", "targets": [{"format": COLOR_FORMAT}]},
        primitive={"topology": "triangle-list"},
        depth_stencil={"format": DEPTH_FORMAT, "depth_write_enabled": True, "depth_compare": "less"},
    )
    color = device.create_texture(size=(width, height, 1), format=COLOR_FORMAT,
                                  usage=wgpu.TextureUsage.RENDER_ATTACHMENT | wgpu.TextureUsage.COPY_SRC)
    depth = device.create_texture(size=(width, height, 1), format=DEPTH_FORMAT,
                                  usage=wgpu.TextureUsage.RENDER_ATTACHMENT)
    bind_groups = []
    for obj in scene.objects:
        block = _draw_uniforms(frame, scene, obj.sphere, scene.materials[obj.material])
        buffer = device.create_buffer_with_data(data=block.tobytes(), usage=wgpu.BufferUsage.UNIFORM)
        bind_groups.append(device.create_bind_group(layout=pipeline.get_bind_group_layout(0), entries=[
            {"binding": 0, "resource": {"buffer": buffer, "offset": 0, "size": block.nbytes}},
            {"binding": 1, "resource": dfg.create_view()},
            {"binding": 2, "resource": sampler},
        ]))

    encoder = device.create_command_encoder()
    rpass = encoder.begin_render_pass(
        color_attachments=[{"view": color.create_view(), "load_op": "clear", "store_op": "store",
                            "clear_value": (0.0, 0.0, 0.0, 0.0)}],
        depth_stencil_attachment={"view": depth.create_view(), "depth_load_op": "clear",
                                  "depth_store_op": "discard", "depth_clear_value": 1.0})
    rpass.set_pipeline(pipeline)
    for group in bind_groups:
        rpass.set_bind_group(0, group)
        rpass.draw(3)
    rpass.end()
    device.queue.submit([encoder.finish()])
    data = device.queue.read_texture({"texture": color}, {"bytes_per_row": width * 16, "rows_per_image": height},
                                     (width, height, 1))
    pixels = np.frombuffer(data, np.float32).reshape(height, width, 4).copy()  # row 0 is the top row
    info = {key: adapter.info[key] for key in ("device", "description", "backend_type", "adapter_type")}
    return pixels, info


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", type=Path)
    parser.add_argument("out", type=Path, help="output prefix: OUT.npy, OUT.json, OUT.wgsl")
    parser.add_argument("--route", choices=("naga", "slang"), default="naga")
    args = parser.parse_args(argv)
    if "VK_ICD_FILENAMES" not in os.environ and Path(LAVAPIPE_ICD).is_file():
        os.environ["VK_ICD_FILENAMES"] = LAVAPIPE_ICD  # read when wgpu first opens Vulkan
    from pbrlab.foundation.errors import PbrlabError
    try:
        wgsl, translator = fragment_wgsl(args.route)
        pixels, info = render(args.scene, wgsl)
    except PbrlabError as exc:
        print(f"render.py: error: {exc}", file=sys.stderr)
        return 1
    np.save(args.out.with_suffix(".npy"), pixels)
    args.out.with_suffix(".wgsl").write_text(wgsl, encoding="utf-8")
    args.out.with_suffix(".json").write_text(json.dumps({"route": args.route, "translator": translator,
                                                         "adapter": info, "size": [pixels.shape[1], pixels.shape[0]]},
                                                        indent=1), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
