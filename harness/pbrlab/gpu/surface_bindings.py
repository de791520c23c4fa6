"""A surface file's samplers against the textures its material binds: both ways, by name.

A material with a ``surface`` file binds textures by sampler name
(``"textures": {"_MainTex": {...}}``). Two mistakes once rendered without a word
(issue 14): a binding under a name the surface does not declare (a typo: the texture is
never sampled) and a sampler the material never binds (it samples whatever texture unit 0
holds, the DFG table). Both raise SceneError before rendering, naming the material, the
sampler and the file. Declarations are read from the surface file and every file it
includes, comments removed: ``uniform sampler2D NAME`` in GLSL; ``UNITY_DECLARE_TEX2D(NAME)``,
``PBRLAB_DECLARE_TEX2D(NAME)``, ``Texture2D NAME`` or ``sampler2D NAME`` in HLSL.
"""

from __future__ import annotations

import re
from pathlib import Path

from ..foundation.errors import SceneError
from ..foundation.file_identity import include_closure
from .shaders import read_source

_COMMENTS = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
_GLSL = re.compile(r"\buniform\s+(?:(?:lowp|mediump|highp)\s+)?sampler2D\s+([\w\s,\[\]]+);")
_HLSL = (re.compile(r"\b(?:UNITY|PBRLAB)_DECLARE_TEX2D\s*\(\s*(\w+)\s*\)"),
         re.compile(r"\bTexture2D(?:\s*<[^>]*>)?\s+(\w+)"),
         re.compile(r"\bsampler2D\s+(\w+)"))


def surface_sources(surface: Path, search_dirs=()) -> list[str]:
    """The text of ``surface`` and of the files it includes, comments removed."""
    text = read_source(surface)
    files = [text] + [read_source(p) for p in include_closure(text, search_dirs, surface.parent)]
    return [_COMMENTS.sub(" ", body) for body in files]


def declared_samplers(surface: Path, search_dirs=()) -> set[str]:
    """Sampler names declared by ``surface`` and the files it includes."""
    names: set[str] = set()
    for body in surface_sources(surface, search_dirs):
        if surface.suffix == ".hlsl":
            for pattern in _HLSL:
                names.update(pattern.findall(body))
        else:
            for group in _GLSL.findall(body):
                names.update(re.sub(r"\[.*?\]", "", n).strip() for n in group.split(","))
    return {n for n in names if n}


def check_bindings(scene, surfaces: dict, search_dirs=()) -> None:
    """Raise SceneError when a material's textures and its surface's samplers disagree.

    ``surfaces`` maps material name -> the surface file in the render's language.
    """
    for name, material in scene.materials.items():
        surface = surfaces.get(name)
        if surface is None:
            continue
        declared = declared_samplers(surface, search_dirs)
        bound = set(material.textures)
        where = f"{scene.source}: materials.{name}.textures"
        for binding in sorted(bound - declared):
            raise SceneError(f"{where}.{binding}: {surface.name} declares no sampler named "
                             f"{binding!r} (it declares: {', '.join(sorted(declared)) or 'none'})")
        for sampler in sorted(declared - bound):
            raise SceneError(f"{where}: {surface.name} declares sampler {sampler!r}, and the "
                             f"material binds no texture to it (bound: {', '.join(sorted(bound)) or 'none'})")
