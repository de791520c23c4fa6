"""A material's values for a surface shader's ``Properties``: the ShaderLab defaults, overridden
by the scene material's ``properties`` object, checked with errors naming the field.

    values = resolve(shader, overrides, base, where="scene.json: materials.rim.properties")

Values, by property type: Float/Range/Int a number (Range inside its range); Color and Vector
``[r, g, b, a]`` (or three numbers, alpha 1); 2D and Cube ``{"path": ..., "srgb": bool,
"tiling": [x, y], "offset": [x, y]}`` or a default texture name. Colour values are taken as
linear, as pbrlab's colours are (Unity converts Color properties from sRGB in its linear
colour space; write linear values here: docs/unity.md, "Unity shaders").
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from ...foundation import safe_paths
from ...foundation.errors import SceneError
from . import model as M
from .normal_maps import normal_map_property, unpacked_textures

# Unity's built-in default textures (the Properties block's "white" {}, ...) as linear
# RGBA texels; "bump" unpacks to the flat normal (0, 0, 1).
DEFAULT_TEXELS = {"white": (1.0, 1.0, 1.0, 1.0), "black": (0.0, 0.0, 0.0, 0.0),
                  "gray": (0.5, 0.5, 0.5, 0.5), "grey": (0.5, 0.5, 0.5, 0.5),
                  "bump": (0.5, 0.5, 1.0, 1.0), "red": (1.0, 0.0, 0.0, 1.0), "": (0.5, 0.5, 0.5, 0.5)}


@dataclass
class TextureValue:
    path: Path | None          # None: a constant default texture
    texel: tuple | None        # the default's texel when path is None
    srgb: bool
    st: tuple                  # (tiling x, tiling y, offset x, offset y): Unity's _ST
    cube: bool = False
    normal_map: bool = False   # a file stored as Unity stores a normal map (normal_maps.py)


def _finite(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _vector(value, where: str, name: str) -> tuple:
    if not isinstance(value, list) or len(value) not in (3, 4) or not all(_finite(v) for v in value):
        raise SceneError(f"{where}.{name}: expected [r, g, b, a] (or [r, g, b]) of finite numbers, got {value!r}")
    return tuple(float(v) for v in value) + ((1.0,) if len(value) == 3 else ())


def _pair(value, where: str, default) -> tuple:
    if value is None:
        return default
    if not isinstance(value, list) or len(value) != 2 or not all(_finite(v) for v in value):
        raise SceneError(f"{where}: expected [x, y] of finite numbers, got {value!r}")
    return tuple(float(v) for v in value)


def _texture(prop: M.Property, value, where: str, base: Path, unpacked: frozenset = frozenset()) -> TextureValue:
    cube = prop.kind == "Cube"
    linear_by_default = normal_map_property(prop, unpacked)
    if value is None and cube:  # every Cube samples the scene's environment
        return TextureValue(None, DEFAULT_TEXELS["white"], False, (1.0, 1.0, 0.0, 0.0), cube)
    if value is None or isinstance(value, str):
        name = prop.default if value is None else value
        if name not in DEFAULT_TEXELS:
            raise SceneError(f"{where}: unknown default texture {name!r}; use one of "
                             f"{', '.join(k for k in DEFAULT_TEXELS if k)}")
        return TextureValue(None, DEFAULT_TEXELS[name], False, (1.0, 1.0, 0.0, 0.0), cube)
    if cube:
        raise SceneError(f"{where}: a Cube property samples the scene's environment here; "
                         "give no value (or a default name)")
    if not isinstance(value, dict):
        raise SceneError(f'{where}: expected {{"path": ..., "srgb": true|false, "tiling": [x, y], '
                         f'"offset": [x, y]}}, got {value!r}')
    unknown = set(value) - {"path", "srgb", "tiling", "offset"}
    if unknown:
        raise SceneError(f"{where}.{sorted(unknown)[0]}: unknown field; use path, srgb, tiling, offset")
    if "path" in value and prop.kind == "3D":
        raise SceneError(f"{where}.path: a 3D (volume) texture property takes one of Unity's default "
                         "textures here (give a name: white, black, gray, ...): pbrlab reads no volume file format")
    if "path" in value:
        if not isinstance(value["path"], str):
            raise SceneError(f"{where}.path: expected a file name")
        try:  # the folder rule first: a link out of the folder is refused, not followed (safe_paths)
            safe_paths.inside(base, value["path"], climb=True)
        except safe_paths.OutsideFolderError as exc:
            raise SceneError(f"{where}.path: {exc.reason}") from None
        try:
            path = (base / value["path"]).resolve()
            found = path.is_file()
        except (OSError, RuntimeError) as exc:  # a symlink loop, a component that is a file
            raise SceneError(f"{where}.path: cannot follow {base / value['path']} ({exc})") from None
        if not found:
            raise SceneError(f"{where}.path: no such file {path}")
    else:
        path = None
    srgb = value.get("srgb", not linear_by_default)
    if not isinstance(srgb, bool):
        raise SceneError(f"{where}.srgb: expected true (colour, sRGB-encoded) or false (linear data)")
    tiling = _pair(value.get("tiling"), f"{where}.tiling", (1.0, 1.0))
    offset = _pair(value.get("offset"), f"{where}.offset", (0.0, 0.0))
    texel = None if path is not None else DEFAULT_TEXELS[prop.default]
    return TextureValue(path, texel, srgb and path is not None, tiling + offset,
                        normal_map=path is not None and normal_map_property(prop, unpacked))


def resolve(shader: M.SurfaceShader, overrides: dict, base: Path, where: str) -> dict:
    """{property name: float | 4-tuple | TextureValue} for every property of ``shader``."""
    if not isinstance(overrides, dict):
        raise SceneError(f"{where}: expected an object of property values")
    for name in overrides:
        if name not in shader.properties:
            known = ", ".join(shader.properties) or "none"
            raise SceneError(f"{where}.{name}: the shader {shader.path.name} has no such property "
                             f"(its Properties: {known})")
    for name, value in overrides.items():
        if value is None:  # JSON null: not "the default" in silence
            raise SceneError(f"{where}.{name}: null is not a value; give one, or leave the property out "
                             f"to use the shader's default")
    values = {}
    unpacked = unpacked_textures(getattr(shader, "path", None))
    for name, prop in shader.properties.items():
        value = overrides.get(name)
        field = f"{where}.{name}"
        if prop.is_texture:
            values[name] = _texture(prop, value, field, base, unpacked)
        elif prop.kind in ("Color", "Vector"):
            values[name] = prop.default if value is None else _vector(value, where, name)
        else:
            if value is None:
                values[name] = float(prop.default)
                continue
            if not _finite(value):
                raise SceneError(f"{field}: expected a finite number, got {value!r}")
            if prop.range is not None and not prop.range[0] <= value <= prop.range[1]:
                raise SceneError(f"{field}: expected a number in [{prop.range[0]}, {prop.range[1]}] "
                                 f"(its Range), got {value}")
            if prop.kind == "Int" and float(value) != int(value):
                raise SceneError(f"{field}: expected an integer, got {value}")
            values[name] = float(value)
    return values
