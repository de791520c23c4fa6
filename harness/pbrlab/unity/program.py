"""Compile a surface shader's programs and feed them (the renderer's one entry to Unity).

    program = build_program(ctx, material.unity, "hlsl", "sphere", defines)
    bind(program, material, obj, frame, cache, first_unit)

HLSL: the generated text (generate.py) through glslang and spirv-cross, as every HLSL scene
program (programs.py). GLSL: the same glue around the ``port-unity`` port of the CGPROGRAM
(port.py), included as its own file so compile errors name it. Both get the harness's GLSL
vertex stage. Unity's stand-in ``.cginc`` files (``cginc/``) resolve the shader's includes.
"""

from __future__ import annotations

import atexit
import re
import shutil
import tempfile
from pathlib import Path

import numpy as np

from .. import hlsl, shaders
from ..errors import PbrlabError
from ..programs import TEMPLATES, template_source
from ..programs import set_uniform as _set
from . import generate, parse, port
from . import model as M
from .properties import TextureValue

CGINC = Path(__file__).parent / "cginc"
VERTEX = {"sphere": "sphere.vert", "mesh": "mesh.vert"}
_PROGRAMS: dict = {}
# The GLSL path's in-memory ports, written where the include resolver finds them; removed at exit.
_PORTS = Path(tempfile.mkdtemp(prefix="pbrlab-unity-ports-"))
atexit.register(shutil.rmtree, _PORTS, ignore_errors=True)
# Unity's _SpecColor when a shader's Properties lack it: Unity's legacy shaders' default
# ("Specular Color", Color) = (0.5, 0.5, 0.5, 1).
DEFAULT_SPEC_COLOR = (0.5, 0.5, 0.5, 1.0)
# unity_SpecCube0_HDR: the harness's environment is float radiance, so DecodeHDR's
# multiplier and exponent are 1 and alpha is unused.
SPECCUBE_HDR = (1.0, 1.0, 0.0, 0.0)


def fragment_text(shader: M.SurfaceShader, language: str, stem: str, defines: dict):
    """(text, include dirs) of the fragment program. In GLSL the port's folder comes first
    (the ports of the shader's includes are there, under the names the port includes)."""
    dirs = [TEMPLATES, CGINC, shader.path.parent]
    if shader.language == "glsl":  # a port-unity port: GLSL only, included as written
        if language == "hlsl":
            raise PbrlabError(f"surface {shader.path}: a port-unity GLSL port renders only in GLSL; "
                              "for --language hlsl name the original .shader file")
        text = generate.fragment_source(shader, "glsl", stem, f'#include "{shader.path.name}"',
                                        shader.path.name, defines)
        return text, [TEMPLATES, shader.path.parent, CGINC]
    if language == "hlsl":
        return generate.fragment_source(shader, "hlsl", stem, shader.program, shader.path.name, defines), dirs
    ported = write_port(shader)
    text = generate.fragment_source(shader, "glsl", stem, f'#include "{ported.name}"', ported.name, defines)
    return text, [TEMPLATES, ported.parent, CGINC, shader.path.parent]


_INCLUDE_LINE = re.compile(r'^([ \t]*#[ \t]*include[ \t]+")([^"]+)(")', re.M)


def write_port(unit) -> Path:
    """The GLSL path's port of a program (a surface program or a vertex/fragment pass), written
    with ports of the files it includes (the shader's own .cginc files and pbrlab's stand-ins,
    resolved as the parser does) beside it: each include line then names its port, so the Cg
    text of an include goes through the same renames as the program's."""
    folder = _PORTS / f"{abs(hash((str(unit.path), unit.program)))}"
    folder.mkdir(parents=True, exist_ok=True)
    ports: dict = {}   # resolved include -> the file name of its port in ``folder``

    def ported(text: str, where: Path) -> str:
        def relink(m):
            target = parse.resolve_included(m.group(2), where)
            if target is None:
                return m.group(0)  # the GLSL expander names what it cannot find
            key = target.resolve()
            if key not in ports:
                name = target.name
                while name in ports.values() or name == unit.path.stem + ".glsl":
                    name = f"{len(ports)}_{target.name}"
                ports[key] = name
                body = target.read_text(encoding="utf-8").removeprefix("\ufeff")
                (folder / name).write_text(ported(port.port_text(body, unit), target.parent), encoding="utf-8")
            return m.group(1) + ports[key] + m.group(3)
        return _INCLUDE_LINE.sub(relink, text)

    path = folder / (unit.path.stem + ".glsl")
    path.write_text(ported(port.port_program(unit), unit.path.parent), encoding="utf-8")
    return path


def _vertex_stage(shader: M.SurfaceShader, language: str, defines: dict, dirs) -> shaders.Source:
    """The vertex stage running the shader's vertex: function (generate.vertex_source)."""
    display = f"{shader.path.name} (generated {language} vertex stage)"
    if language == "hlsl":
        text = generate.vertex_source(shader, "hlsl", shader.program, shader.path.name, defines)
        glsl = hlsl.cross_to_glsl(hlsl.compile_spirv(text, display, dirs, stage="vert"), plain_uniforms=True)
        # Both stages hold a `uniform _Global <id>;` of their own members: rename this one so
        # the program links (programs.set_uniform then sets the member in each stage).
        instance = re.search(r"uniform _Global (\w+);", glsl)
        if instance:
            glsl = re.sub(r"\b_Global\b", "_GlobalVertex", glsl)
            glsl = re.sub(r"\b" + instance.group(1) + r"\b", "pbrlab_vertex_globals", glsl)
        return shaders.Source(glsl, [f"{display} (GLSL from spirv-cross)"])
    ported = dirs[1] / (shader.path.name if shader.language == "glsl" else shader.path.stem + ".glsl")
    text = generate.vertex_source(shader, "glsl", f'#include "{ported.name}"', ported.name, defines)
    return shaders.expand(text, display, include_dirs=dirs)


def remember_program(key, build):
    """The program cached under ``key``, else ``build()``'s, with its struct members indexed
    (``bind`` sets an HLSL stage's globals through them)."""
    if key not in _PROGRAMS:
        program = build()
        members: dict = {}
        for gl_name in (n for n in program if "." in n):
            members.setdefault(gl_name.split(".", 1)[1], []).append(gl_name)
        program.extra = {"members": members}
        _PROGRAMS[key] = program
    return _PROGRAMS[key]


def build_program(ctx, shader: M.SurfaceShader, language: str, stem: str, defines: dict):
    """The program of ``shader`` for a sphere or mesh draw; with a vertex: function always
    the mesh one (spheres are tessellated: tessellate.py)."""
    if shader.vertex is not None:
        stem = "mesh"
    key = (id(ctx), str(shader.path), shader.program, language, stem, tuple(sorted(defines.items())))
    if key not in _PROGRAMS:
        text, dirs = fragment_text(shader, language, stem, defines)
        display = f"{shader.path.name} (generated {language} {stem} program)"
        if language == "hlsl":
            glsl = hlsl.hlsl_to_glsl(text, display, dirs, plain_uniforms=True)
            fragment = shaders.Source(glsl, [f"{display} (GLSL from spirv-cross)"])
        else:
            fragment = shaders.expand(text, display, include_dirs=dirs)
        if shader.vertex is not None:
            vertex = _vertex_stage(shader, language, defines, dirs)
        else:
            vertex = template_source(VERTEX[stem], defines)
        program = shaders.build_program(ctx, vertex, fragment)
        members: dict = {}
        for gl_name in (n for n in program if "." in n):
            members.setdefault(gl_name.split(".", 1)[1], []).append(gl_name)
        program.extra = {"members": members}
        _PROGRAMS[key] = program
    return _PROGRAMS[key]


def object_matrix(obj) -> np.ndarray:
    """Object to world: a sphere's object space is the unit sphere at its centre."""
    if obj.sphere is not None:
        centre, radius = obj.sphere
        m = np.diag([radius, radius, radius, 1.0])
        m[:3, 3] = centre
        return m
    return obj.transform


def _column_major(m: np.ndarray) -> tuple:
    return tuple(np.asarray(m, np.float64).T.reshape(-1))


def bind(program, material, obj, frame, cache, environment_cube, first_unit: int) -> None:
    """Unity's globals, the material's property values, _ST and textures."""
    model = object_matrix(obj)
    _set(program, "_Time", (0.0, 0.0, 0.0, 0.0))
    _set(program, "_SinTime", (0.0, 0.0, 0.0, 0.0))
    _set(program, "_CosTime", (1.0, 1.0, 1.0, 1.0))
    _set(program, "unity_DeltaTime", (0.0, 0.0, 0.0, 0.0))
    _set(program, "_WorldSpaceCameraPos", tuple(frame.position))
    _set(program, "unity_ObjectToWorld", _column_major(model))
    _set(program, "unity_WorldToObject", _column_major(np.linalg.inv(model)))
    _set(program, "unity_MatrixVP", _column_major(frame.view_proj))
    w, h = frame.size
    _set(program, "_ScreenParams", (float(w), float(h), 1.0 + 1.0 / w, 1.0 + 1.0 / h))
    _set(program, "_ProjectionParams", (1.0, 0.0, 0.0, 0.0))
    _set(program, "unity_SpecCube0_HDR", SPECCUBE_HDR)
    if "_SpecColor" not in material.properties:
        _set(program, "_SpecColor", DEFAULT_SPEC_COLOR)
    unit = first_unit
    for name, value in sorted(material.properties.items()):
        if isinstance(value, TextureValue):
            if value.cube:
                texture = environment_cube()
            elif value.path is not None:
                texture = cache.texture(value.path, value.srgb)
            else:
                texture = cache.constant_texture(value.texel)
            texture.use(unit)
            _set(program, name, unit)
            _set(program, f"{name}_ST", value.st)
            w, h = texture.size[:2]  # Unity's {name}_TexelSize: (1/width, 1/height, width, height)
            _set(program, f"{name}_TexelSize", (1.0 / w, 1.0 / h, float(w), float(h)))
            unit += 1
        else:
            _set(program, name, value)
