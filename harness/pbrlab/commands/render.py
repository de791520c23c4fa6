"""`pbrlab render SCENE [-o out.png] [--hdr out.exr] [--size WxH] [--antialias N] [--language hlsl]`: render a scene file.

SCENE is a JSON scene, a glTF 2.0 file, or a Unity .shader: that is drawn on the default sphere
(one unit sphere, one directional light, a dim grey environment, the shader's Properties at their
defaults); for other lights or property values, name it as a material's "surface" in a scene.

Writes atomically and all or nothing: the PNG and the EXR are written to temporary files,
each fsync'ed and read back, and only then renamed over the targets, so a failed render or
write (a full disk, SIGTERM) leaves no partial file and never replaces a good one. An
output that is one of the scene's own files (the scene, a texture, a mesh, a surface or a
file it includes, the environment) is refused before rendering.
"""

from __future__ import annotations

import argparse
import re

import numpy as np

from ..foundation import console
from ..foundation.errors import PbrlabError


def parse_size(text: str | None):
    if text is None:
        return None
    m = re.fullmatch(r"(\d+)x(\d+)", text.strip())
    if not m or not (1 <= int(m.group(1)) <= 16384 and 1 <= int(m.group(2)) <= 16384):
        raise PbrlabError(f"--size {text!r}: expected WIDTHxHEIGHT, each 1..16384 (e.g. 640x480)")
    return int(m.group(1)), int(m.group(2))


def check_finite(linear: np.ndarray, what: str):
    bad = int((~np.isfinite(linear)).any(axis=-1).sum())
    if bad:
        raise PbrlabError(f"{what}: {bad} pixels are NaN or Inf (a surface function writing NaN or "
                          "Inf into an output field, or a non-finite input); nothing was written")


def load_scene_with_gltf_warnings(path):
    """A JSON scene and the warnings of the glTF files it takes in (GltfWarning)."""
    import sys
    import warnings

    from ..importers.loader import load_scene

    # Every warning is recorded: the glTF importer (and its GltfWarning) is loaded only if the
    # scene takes in a glTF file, so its warnings are told apart after the load.
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scene = load_scene(path)
    gltf = sys.modules.get("pbrlab.importers.gltf")
    messages, passed_on = [], set()
    for w in caught:
        if gltf is not None and issubclass(w.category, gltf.GltfWarning):
            messages.append(str(w.message))
        elif (key := (str(w.message), w.category, w.filename, w.lineno)) not in passed_on:
            passed_on.add(key)  # once per message and place, as the default filter would
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return scene, messages


def parse_antialias(text: str | None) -> int | None:
    """``--antialias 4``: samples per pixel, one of the scene format's (render.antialias)."""
    from ..scene.fields import ANTIALIAS_SAMPLES

    if text is None:
        return None
    if not text.strip().isdigit() or int(text) not in ANTIALIAS_SAMPLES:
        raise PbrlabError(f"--antialias {text}: expected samples per pixel, one of "
                          f"{', '.join(map(str, ANTIALIAS_SAMPLES))} (1: none), that this GL takes")
    return int(text)


def with_antialias(scene, samples: int | None):
    """``scene`` with ``render.antialias`` = ``samples`` (None: as the scene says), on a copy."""
    import dataclasses

    if samples is None:
        return scene
    return dataclasses.replace(scene, render=dataclasses.replace(scene.render, antialias=samples))


def parse_weights(text: str | None) -> tuple | None:
    """``--weights 0.5,0,1``: morph target weights, finite numbers separated by commas."""
    if text is None:
        return None
    try:
        weights = tuple(float(part) for part in text.split(","))
    except ValueError:
        weights = ()
    if not weights or not all(np.isfinite(weights)):
        raise PbrlabError(f"--weights {text}: expected finite numbers separated by commas, e.g. 0.5,0,1")
    return weights


def parse_time(text: str | None) -> float | None:
    """``--time 1.25``: an animation time in seconds, a finite number."""
    if text is None:
        return None
    try:
        time = float(text)
    except ValueError:
        time = float("nan")
    if not np.isfinite(time):
        raise PbrlabError(f"--time {text}: expected a finite number of seconds, e.g. 1.25")
    return time


def load_any_scene(path, camera=None, environment=None, size=None, variant=None, scene=None, weights=None,
                   time=None, animation=None, allow_outside=False):
    """A JSON scene, or a glTF 2.0 file (.gltf, .glb) with its warnings printed to stderr."""
    import sys
    from pathlib import Path

    from ..importers.loader import is_gltf

    if not is_gltf(path):
        if any(option is not None for option in (camera, environment, variant, scene, weights, time, animation)):
            raise PbrlabError("--camera, --environment, --variant, --scene, --weights, --time and --animation "
                              "are for glTF files; a JSON scene names its own")
        scene, messages = load_scene_with_gltf_warnings(path)
        for message in messages:
            print(f"warning: {message}", file=sys.stderr)
        return scene
    from ..importers.gltf import load_gltf
    from ..importers.gltf.settings import light_units_default, read_settings

    env, render = read_settings(Path(path), environment)
    result = load_gltf(path, camera=camera, environment=env, render=render, size=size, emit_warnings=False,
                       variant=variant, scene=scene, weights=weights, time=time, animation=animation,
                       allow_outside=allow_outside)
    for message in result.warnings:
        print(f"warning: {message}", file=sys.stderr)
    chosen = light_units_default(Path(path), result.scene)
    if chosen:
        console.detail(chosen)
    return result.scene


def run(args) -> int:
    from ..foundation import safe_paths

    if not args.output and not args.hdr:
        raise PbrlabError("nothing to write: give -o OUT.png and/or --hdr OUT.exr")
    for path, suffix in ((args.output, ".png"), (args.hdr, ".exr")):
        if path and not path.lower().endswith(suffix):
            raise PbrlabError(f"{path}: expected a {suffix} file name")
    with safe_paths.allowing_outside(args.allow_outside):  # every reader below, shaders' includes too
        return _render(args)


def _render(args) -> int:
    import sys

    from ..gpu import gl
    from ..foundation import images, outputs, progress
    from ..render.empty_frame import empty_frame_reason
    from ..render.renderer import input_files, render_scene

    size = parse_size(args.size)
    antialias = parse_antialias(args.antialias)
    scene = load_any_scene(args.scene, args.camera, args.environment, size, args.variant, args.gltf_scene,
                           parse_weights(args.weights), parse_time(args.time), args.animation, args.allow_outside)
    scene = with_antialias(scene, antialias)
    context = gl.shared_context(args.backend)
    info = gl.context_info(context)
    console.detail(f"renderer: {info['GL_RENDERER']} ({info['GL_VERSION']}, backend {info['backend']})")
    targets = [p for p in (args.hdr, args.output) if p]
    with outputs.transaction(targets, [(args.scene, "the scene file")]
                             + input_files(scene, args.language)) as tx:
        with progress.stage(f"rendering {args.scene}"):  # a live line on a terminal past 2 s
            rendering = render_scene(scene, context, size=size,
                                     specialise=not args.no_specialise, language=args.language)
        if scene.render.exposure_metered:
            console.note(f"exposure {rendering.exposure_ev:+.2f} EV (metered), tonemap {scene.render.tonemap}")
        kind = "specialised" if rendering.programs.specialised else "full"
        console.note(f"{rendering.programs.distinct} {kind} program(s)")
        check_finite(rendering.linear, args.scene)
        empty = empty_frame_reason(scene, rendering.linear)  # written anyway, never silently
        if empty:
            print(f"warning: {args.scene}: {empty}", file=sys.stderr)
        if args.hdr:
            images.write_exr(args.hdr, rendering.linear, metadata=rendering.info, tx=tx)
        if args.output:
            images.write_png(args.output, rendering.srgb8, tx=tx)
    for path in targets:
        console.note(f"wrote {path}")
    return 0


def register(sub, common):
    p = sub.add_parser("render", parents=[common],
                       help="Render a JSON scene or a glTF 2.0 file to a PNG and/or an EXR file.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", help="a JSON scene file (see docs/scenes.md), a glTF 2.0 file (.gltf, .glb) or a "
                                 "Unity .shader, drawn on the default sphere with its default properties")
    p.add_argument("--camera", type=int, default=None, metavar="N",
                   help="glTF: render from camera N (default: the first camera, else a framing view)")
    p.add_argument("--environment", default=None, metavar="FILE|R,G,B",
                   help="glTF: an equirectangular image or a constant radiance (overrides <model>.pbrlab.json)")
    p.add_argument("--variant", default=None, metavar="NAME",
                   help="glTF: the KHR_materials_variants variant to render (default: the file's default materials)")
    p.add_argument("--scene", dest="gltf_scene", type=int, default=None, metavar="N",
                   help="glTF: draw scene N (default: the file's default scene)")
    p.add_argument("--weights", default=None, metavar="W0,W1,...",
                   help="glTF: morph target weights for every mesh with targets (default: the node's or mesh's)")
    p.add_argument("--time", default=None, metavar="T",
                   help="glTF: sample an animation at T seconds (--animation; default: the nodes as written, skins in "
                        "that pose)")
    p.add_argument("--animation", default=None, metavar="N|NAME|all",
                   help="glTF: sample this animation (an index or a name), or all of them together "
                        "(default: the first, with a warning naming the others)")
    p.add_argument("--allow-outside", action="store_true",
                   help="read files outside the model's folder: a glTF's buffers and images named by "
                        "absolute paths or .., and (every format) files reached through symbolic links "
                        "that lead out of the folder; refused by default (docs/faults.md)")
    p.add_argument("-o", "--output", help="sRGB 8-bit PNG (exposure + tonemap + sRGB encode)")
    p.add_argument("--hdr", help="linear float EXR of the scene radiance (before exposure)")
    p.add_argument("--size", help="override the camera size, WIDTHxHEIGHT")
    p.add_argument("--antialias", default=None, metavar="N",
                   help="samples per pixel, overriding the scene's render.antialias (1: none; "
                        "resolved in linear before exposure; llvmpipe takes 1 or 4)")
    p.add_argument("--no-specialise", action="store_true",
                   help="render with the full program (every effect compiled in) to compare")
    add_language_option(p)
    p.set_defaults(run=run)


def add_language_option(parser):
    from ..gpu.programs import LANGUAGES
    parser.add_argument("--language", choices=LANGUAGES, default="glsl",
                        help="shade with the GLSL library (default) or its HLSL twins in hlsl_ports/, "
                             "compiled by glslang and spirv-cross; a material's surface file then "
                             "needs its .hlsl twin beside it")
