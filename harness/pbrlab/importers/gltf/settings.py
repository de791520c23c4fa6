"""What a glTF file cannot say about its rendering: the environment and the render
settings, from the command line (``--environment sky.exr`` or ``--environment 0.2,0.2,0.25``)
or a small side file ``<model>.pbrlab.json`` beside the model:

    {"environment": {"path": "sky.exr", "intensity": 1} | {"color": [r, g, b]},
     "render": {"tonemap": "aces_fitted", "exposure": 0, ...}}

Both sections have the JSON scene format's fields and checks (pbrlab.scene.model); the command
line's environment wins over the side file's.

A file with KHR_lights_punctual lights is in physical light units (lux, candela): when
the side file sets neither ``tonemap`` nor ``exposure``, `pbrlab render` shows it through
Khronos PBR Neutral with a metered exposure (``light_units_default``, pbrlab.maths.exposure).
"""

from __future__ import annotations

import json
from pathlib import Path

from ...foundation import safe_paths
from ...foundation.errors import SceneError
from ...maths.exposure import METERED_TONEMAP
from ...scene.model import Environment, RenderSettings, parse_scene

SIDE_FILE_SUFFIX = ".pbrlab.json"
_SECTIONS = ("environment", "render")


def side_file(model: Path) -> Path:
    return model.with_name(model.stem + SIDE_FILE_SUFFIX)


def _sections(data: dict, origin: str, base: Path) -> tuple[Environment | None, RenderSettings]:
    """The environment and render sections, validated by the scene parser itself (a
    placeholder camera and object complete the scene it checks)."""
    scene = parse_scene({"camera": {"position": [0, 0, 1], "target": [0, 0, 0]},
                         "materials": {"m": {}}, "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1},
                                                              "material": "m"}],
                         "environment": data.get("environment"), "render": data.get("render", {})},
                        origin, base)
    return scene.environment, scene.render


def chosen_render_fields(model: Path) -> set:
    """The render fields the side file sets (read_settings has checked it)."""
    path = side_file(model)
    if not path.is_file():
        return set()
    return set(json.loads(path.read_text(encoding="utf-8")).get("render", {}))


def light_units_default(model: Path, scene) -> str | None:
    """Khronos PBR Neutral and a metered exposure for a scene lit by the file's punctual
    lights whose side file chose no tonemap or exposure; a line saying so (None: unchanged)."""
    if not scene.lights or chosen_render_fields(model) & {"tonemap", "exposure"}:
        return None
    scene.render.tonemap = METERED_TONEMAP
    scene.render.exposure_metered = True
    return (f"physical light units (KHR_lights_punctual): tonemap {METERED_TONEMAP}, exposure metered "
            f"(set render.tonemap / render.exposure in {side_file(model).name} to choose)")


def read_settings(model: Path, environment_option: str | None = None):
    """(environment, render settings) for a glTF file."""
    environment, render = None, RenderSettings()
    path = side_file(model)
    if path.is_file():
        try:  # a side file that is a link out of the model's folder is refused, not read (safe_paths)
            safe_paths.inside(path.parent, path.name)
        except safe_paths.OutsideFolderError as exc:
            raise SceneError(str(exc)) from None
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (json.JSONDecodeError, UnicodeDecodeError) as exc:
            raise SceneError(f"{path}: not a readable JSON file ({exc})") from None
        if not isinstance(data, dict) or set(data) - set(_SECTIONS):
            raise SceneError(f"{path}: expected an object with {' and/or '.join(_SECTIONS)}")
        environment, render = _sections(data, str(path), path.parent)
    if environment_option is not None:
        environment = parse_environment_option(environment_option)
    return environment, render


def parse_environment_option(text: str) -> Environment:
    """``--environment``: an image file, or a constant radiance ``r,g,b``."""
    parts = text.split(",")
    if len(parts) == 3:
        try:
            colour = [float(p) for p in parts]
        except ValueError:
            colour = None
        if colour is not None:
            return _sections({"environment": {"color": colour}}, "--environment", Path("."))[0]
    with safe_paths.allowing_outside():  # typed on the command line: no model's folder to keep to
        return _sections({"environment": {"path": text}}, "--environment", Path("."))[0]
