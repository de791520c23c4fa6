"""GLSL or HLSL text -> Vulkan SPIR-V with glslang, and the resource bindings it declares.

The library's programs are OpenGL GLSL (``#version 330 core``, loose uniforms, no explicit
locations or bindings). glslang's ``-R`` gathers the loose uniforms into one uniform block
(Vulkan's rules relaxed, as its manual describes); ``--amb``/``--aml`` give every resource
a binding and every interface variable a location. The shader text is otherwise what the
OpenGL renderer compiles. ``spirv-cross --reflect`` then lists the descriptor bindings, so
a pipeline layout can be made that matches them."""

from __future__ import annotations

import json
import shutil
import subprocess
import tempfile
from pathlib import Path

from ...foundation.errors import PbrlabError
from . import vulkan as vk

_STAGE = {"vertex": "vert", "fragment": "frag", "compute": "comp"}


def _tool(name: str) -> str:
    path = shutil.which(name)
    if path is None:
        raise vk.VulkanUnavailable(f"{name} not found: install the Debian/Ubuntu packages "
                                   "glslang-tools and spirv-cross (sudo apt-get install glslang-tools "
                                   "spirv-cross; in a pbrlab checkout, scripts/setup.sh does)")
    return path


def compile_glsl(source: str, stage: str, *, hlsl: bool = False, entry: str = "main",
                 include_dirs=()) -> bytes:
    """SPIR-V words of ``source`` for Vulkan 1.2 (a readable error on a compile failure).

    HLSL: ``Texture2D`` + ``SamplerState`` pairs become combined image samplers
    (``--auto-sampled-textures``), as the harness's HLSL path compiles them (pbrlab.gpu.hlsl),
    so a GLSL program and its HLSL twin bind their textures alike; ``#include`` is
    resolved against ``include_dirs``."""
    with tempfile.TemporaryDirectory(prefix="pbrlab-spirv-") as tmp:
        src = Path(tmp) / f"shader.{_STAGE[stage]}"
        out = Path(tmp) / "shader.spv"
        src.write_text(source)
        args = [_tool("glslangValidator"), "-V", "--target-env", "vulkan1.2", "--amb", "--aml",
                "-S", _STAGE[stage], "-o", str(out)]
        args += (["-D", "-e", entry, "--hlsl-iomap", "--auto-sampled-textures"] if hlsl
                 else ["-R"])
        args += [f"-I{Path(d).resolve()}" for d in include_dirs]
        result = subprocess.run(args + [str(src)], capture_output=True, text=True)
        if result.returncode != 0 or not out.exists():
            lines = [l for l in result.stdout.splitlines() if "ERROR" in l or "error" in l]
            raise PbrlabError(f"glslang (Vulkan SPIR-V, {stage}): " + "; ".join(lines[:6] or
                              [result.stdout.strip()[-400:]]))
        return out.read_bytes()


_DESCRIPTOR = {"textures": vk.DESCRIPTOR_COMBINED_IMAGE_SAMPLER, "separate_images": vk.DESCRIPTOR_SAMPLED_IMAGE,
               "separate_samplers": vk.DESCRIPTOR_SAMPLER, "images": vk.DESCRIPTOR_STORAGE_IMAGE,
               "ubos": vk.DESCRIPTOR_UNIFORM_BUFFER, "ssbos": vk.DESCRIPTOR_STORAGE_BUFFER}


def reflect(spirv: bytes) -> dict:
    """spirv-cross's reflection JSON of a module."""
    with tempfile.NamedTemporaryFile(suffix=".spv") as f:
        f.write(spirv)
        f.flush()
        result = subprocess.run([_tool("spirv-cross"), f.name, "--reflect"], capture_output=True,
                                text=True)
    if result.returncode != 0:
        raise PbrlabError(f"spirv-cross --reflect: {result.stderr.strip()[-400:]}")
    return json.loads(result.stdout)


def descriptor_sets(*reflections: dict) -> dict:
    """``{set: [(binding, type, count), ...]}`` over all stages' reflections."""
    sets: dict = {}
    for reflection in reflections:
        for key, kind in _DESCRIPTOR.items():
            for resource in reflection.get(key, []):
                count = 1
                for n in resource.get("array", []) or []:
                    count *= max(1, int(n))
                row = (int(resource.get("binding", 0)), kind, count)
                rows = sets.setdefault(int(resource.get("set", 0)), [])
                if row[0] not in {r[0] for r in rows}:
                    rows.append(row)
    return sets


def colour_outputs(reflection: dict) -> int:
    """How many colour attachments a fragment module writes (highest location + 1)."""
    locations = [int(o.get("location", 0)) for o in reflection.get("outputs", [])]
    return max(locations) + 1 if locations else 1
