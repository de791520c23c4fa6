"""Every scene the repository's goldens are rendered from, by golden name, in one place.

The golden tests, ``pbrlab demo``, the code-path independence test and the GPU tolerance
measurement all render these; ``python -m pbrlab.checking.golden_scenes OUT`` writes each one as
``OUT/NAME.exr`` (linear float32) and ``OUT/NAME.png`` (display sRGB) on the default GL
context, so a render can be made in a process with another environment (another llvmpipe
code path, another GPU) and compared with the goldens.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .charts import CHARTS
from ..foundation.locations import locate
from ..importers.loader import load_scene, parse_scene
from ..scene.model import QUALITIES, Scene

SCENES_DIR = locate("scenes")
LIT_SCENE = SCENES_DIR / "unity_example" / "scene.json"
TORTURE_SCENE = SCENES_DIR / "torture" / "scene.json"
GLTF_DIR = SCENES_DIR / "gltf"
GLTF_SIZE = (256, 128)
# golden name -> (glTF asset, environment option or None); features.gltf also under a
# constant environment (occlusion, image-based light)
GLTF_GOLDENS = {
    "gltf_hierarchy_lights": ("hierarchy_lights.glb", None),
    "gltf_textured": ("textured.gltf", None),
    "gltf_texture_transform": ("texture_transform.gltf", None),
    "gltf_alpha_modes": ("alpha_modes.glb", None),
    "gltf_features": ("features.gltf", None),
    "gltf_features_environment": ("features.gltf", "0.25,0.3,0.35"),
}
# The layered assets (KHR_materials_clearcoat, _sheen, _anisotropy, _iridescence,
# _transmission and _volume) at the high tier, the glTF goldens' size; their untextured
# materials are also checked against the float64 CPU renderer
# (tests/importers/gltf/test_layered_goldens_cpu.py). KHR_materials_specular and _ior are in features.gltf.
LAYERED_GLTF_GOLDENS = {
    "gltf_clearcoat": ("clearcoat.gltf", None),
    "gltf_sheen": ("sheen.gltf", None),
    "gltf_anisotropy": ("anisotropy.gltf", None),
    "gltf_iridescence": ("iridescence.gltf", None),
    "gltf_transmission_environment": ("transmission.gltf", "0.25,0.3,0.35"),  # the sky seen through
    "gltf_transmission_slab": ("transmission_slab.gltf", None),  # an emissive backdrop seen through
    "gltf_specular_layers": ("specular_layers.gltf", "0.25,0.3,0.35"),  # KHR_materials_specular's F90 in each layer
}
GLTF_GOLDENS.update(LAYERED_GLTF_GOLDENS)


def lit_scene(quality: str = "high") -> Scene:
    """The Unity-style example (textured, three light types, HDR environment) at a tier."""
    scene = load_scene(LIT_SCENE)
    scene.render.quality = quality
    return scene


def gltf_scene(asset: str, environment: str | None = None) -> Scene:
    """A glTF test asset of scenes/gltf at the goldens' size, optionally lit by an
    environment given as the command line's ``--environment`` value."""
    from ..importers.gltf import load_gltf
    from ..importers.gltf.settings import parse_environment_option

    env = parse_environment_option(environment) if environment else None
    return load_gltf(GLTF_DIR / asset, size=GLTF_SIZE, environment=env, emit_warnings=False).scene


def _chart(name):
    return lambda: parse_scene(CHARTS[name](), origin=f"chart {name}")


GOLDEN_SCENES = {name: _chart(name) for name in CHARTS}
GOLDEN_SCENES.update({f"lit_scene_{q}": (lambda q=q: lit_scene(q)) for q in QUALITIES})
GOLDEN_SCENES["torture_chart"] = lambda: load_scene(TORTURE_SCENE)
GOLDEN_SCENES.update({name: (lambda a=asset, e=env: gltf_scene(a, e))
                      for name, (asset, env) in GLTF_GOLDENS.items()})


def render_all(out: Path, names=None, backend: str | None = None, language: str = "glsl") -> list[str]:
    """Render the named golden scenes (default: all) into ``out``, shading in ``language``;
    returns the names."""
    from ..gpu import gl
    from ..foundation import images
    from ..render.renderer import render_scene

    names = list(names or GOLDEN_SCENES)
    out.mkdir(parents=True, exist_ok=True)
    ctx = gl.shared_context(backend)
    for name in names:
        rendering = render_scene(GOLDEN_SCENES[name](), ctx, language=language)
        images.write_exr(out / f"{name}.exr", rendering.linear, metadata=gl.context_info(ctx))
        images.write_png(out / f"{name}.png", rendering.srgb8)
    return names


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pbrlab.checking.golden_scenes",
                                     description="Render the golden scenes to EXR and PNG files.")
    parser.add_argument("out", type=Path, help="folder for NAME.exr and NAME.png")
    parser.add_argument("names", nargs="*", help=f"golden names (default: all of {', '.join(GOLDEN_SCENES)})")
    parser.add_argument("--backend", choices=("egl", "osmesa"), default=None,
                        help="GL backend (default: $PBRLAB_GL_BACKEND, else EGL then OSMesa)")
    parser.add_argument("--language", choices=("glsl", "hlsl"), default="glsl",
                        help="shade with the GLSL library or its HLSL twins (default: glsl)")
    args = parser.parse_args(argv)
    unknown = sorted(set(args.names) - set(GOLDEN_SCENES))
    if unknown:
        parser.error(f"no golden scene named {', '.join(unknown)}")
    for name in render_all(args.out, args.names, args.backend, args.language):
        print(args.out / f"{name}.exr")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
