"""Compile a surface shader's programs and feed them (the renderer's one entry to Unity).

    program = build_program(ctx, material.source.shader, "hlsl", "sphere", defines)
    bind(program, material, obj, frame, cache, first_unit)

HLSL: the generated text (generate.py) through glslang and spirv-cross, as every HLSL scene
program (programs.py); a ``#line`` puts the CGPROGRAM at its line of the ``.shader``. GLSL:
the same glue around the ``port-unity`` port of the CGPROGRAM (port.py), which keeps its line
count; the port is included as an in-memory file (``shaders.VirtualFile``) named after the
``.shader`` and numbered from the CGPROGRAM's line, so compile errors on both paths read
``X.shader:28: ...`` (a local ``.cginc``'s at its own path and line). Both get the harness's
GLSL vertex stage. Unity's stand-in ``.cginc`` files (``cginc/``) resolve the built-in includes.

Programs are kept in the context's scene-program cache (``programs.program_cache``: at most
``programs.PROGRAMS_PER_CONTEXT``, least recently used released), each entry rebuilt when the
``.shader`` or any file it includes, recursively, changed on disk.
"""

from __future__ import annotations

import dataclasses
import functools

import re
import warnings
from pathlib import Path

import numpy as np

from ...gpu import hlsl, programs, shaders
from ...foundation.errors import PbrlabError
from ...foundation.file_identity import include_closure
from ...gpu.programs import TEMPLATES, template_source
from ...gpu.programs import set_uniform as _set
from ...gpu.programs import set_uniform_array
from . import body_includes, cg_spellings, cg_types, finite_texture_coordinates, generate, port, shadow_maps, texture_arrays
from . import vendored_library
from . import model as M
from . import unprovided
from .compared_textures import texture_reads
from .empty_arguments import empty_arguments_spelled
from .include_separators import forward_slashed_includes
from .normal_maps import stored_normal_map
from .properties import TextureValue
from .source_text import (CGINC, INCLUDE, PACKAGE_STAND_INS, includes_respelled, blank_comments, included_files,
                          included_text, read_source, resolve_included, top_level)

VERTEX = {"sphere": "sphere.vert", "mesh": "mesh.vert"}
# The include name under which the GLSL path's generated text pulls in the in-memory port
# (no file has it: shaders.expand finds it among its virtual files first).
_PORT_INCLUDE = "pbrlab-unity-port:{}"
# What an #include "..." line cannot carry (a double quote, a backslash, control
# characters) and the escape character itself: percent-encoded in a port's include name.
_NOT_IN_INCLUDE = re.compile(r'["\\%\x00-\x1f\x7f]')


def _port_include(path) -> str:
    """The include name of the port of ``path`` (one name per file, any file name)."""
    return _PORT_INCLUDE.format(_NOT_IN_INCLUDE.sub(lambda m: f"%{ord(m.group(0)):02X}", str(path)))


# Unity's _SpecColor when a shader's Properties lack it: Unity's legacy shaders' default
# ("Specular Color", Color) = (0.5, 0.5, 0.5, 1).
DEFAULT_SPEC_COLOR = (0.5, 0.5, 0.5, 1.0)
# unity_SpecCube0_HDR: the harness's environment is float radiance, so DecodeHDR's
# multiplier and exponent are 1 and alpha is unused.
SPECCUBE_HDR = (1.0, 1.0, 0.0, 0.0)


def _include_dirs(shader: M.SurfaceShader) -> list[Path]:
    return [TEMPLATES, CGINC, shader.path.parent]


_INCLUDE_LINE = re.compile(r'^([ \t]*#[ \t]*include[ \t]*")([^"]+)(")', re.M)


_STRUCT = re.compile(r"\bstruct\s+\w+\s*\{[^{}]*\}\s*;")
_GLOBAL_VARIABLE = re.compile(r"^[ \t]*(?:uniform\s+)?(?:float|half|fixed|int|uint|bool)(?:[1-4](?:x[1-4])?)?"
                              r"\s+\w+\s*;", re.M)
# a texture object's declaration (``TEXTURE2D(_BaseMap);``, ``Texture2D _Mask;``): a sibling
# include's lookup through its method is spelled for GLSL by it (texture_methods.texture_kinds)
_TEXTURE_OBJECT = re.compile(r"^[ \t]*(?:uniform\s+)?(?:(?:TEXTURE2D|TEXTURE2D_X|TEXTURECUBE)\s*\(\s*\w+\s*\)|"
                             r"(?:Texture2D|TextureCube)(?:\s*<\s*\w+\s*>)?\s+\w+)\s*;", re.M)


def _structs_and_globals(text: str) -> str:
    """The struct definitions (as written: their #if lines kept on lines of their own), the
    global numeric variables and the texture objects of Cg ``text``."""
    masked = blank_comments(text)
    outer = top_level(masked)
    return "\n".join(_STRUCT.findall(masked) + _GLOBAL_VARIABLE.findall(outer) + _TEXTURE_OBJECT.findall(outer))


# A function definition's head at brace depth 0 (source_text.top_level blanks the body): its
# return type, name and parameters, and any return semantic.
_FUNCTION_HEAD = re.compile(r"(?:^|(?<=[;\s]))((?:inline\s+)?[A-Za-z_]\w*\s+[A-Za-z_]\w*\s*\([^()]*\))"
                            r"(?:\s*:\s*\w+)?(?=\s*$)", re.M)
_NOT_A_RETURN_TYPE = {"return", "else", "if", "while", "for", "switch", "define", "undef", "include"}


def _prototypes(masked: str) -> list[str]:
    """``type name(params);`` for every function ``masked`` (comments blanked) defines."""
    out, outer = [], top_level(masked)
    for m in _FUNCTION_HEAD.finditer(outer):
        line_start = outer.rfind("\n", 0, m.start()) + 1
        head = m.group(1)
        if outer[line_start:m.start()].lstrip().startswith("#") or head.split()[0] in _NOT_A_RETURN_TYPE:
            continue
        if re.search(r"^[ \t]*#", head, re.M):
            continue  # a parameter list with #if lines: no one-line prototype says it
        out.append(re.sub(r"\s+", " ", re.sub(r"\binline\s+", "", head)) + ";")
    return out


def included_from(name: str, where: Path, shader_folder: Path):
    """The file ``#include "name"`` in a file of folder ``where`` reads, for the GLSL port: as
    resolve_included finds it, else from the shader's own folder, an include folder of both
    compiles (_include_dirs; glslang's HLSL path finds ``#include "Core/X.hlsl"`` written in
    ``Sub/Y.hlsl`` there, as lclandrews' URP toon shading's TwoTone passes are written). An
    include left unresolved here is left as written, and the GLSL expander then found it in that
    folder and read it unported, with the stand-ins it includes (``float3 albedo;`` of
    SurfaceData.hlsl: a syntax error)."""
    target = resolve_included(name, where)
    if target is None and Path(where).resolve() != Path(shader_folder).resolve():
        target = resolve_included(name, shader_folder)
    return target


def _reached_text(program: str, folder: Path) -> str:
    """source_text.included_text of ``program`` (a shader's, lying in ``folder``), each include
    resolved as the GLSL port resolves it (included_from): the files reached only from the
    shader's folder are the program's too (their shadow comparisons type the textures'
    declarations: compared_textures.texture_reads; their structs and globals the type pass's)."""
    return included_text(program, folder, resolve=lambda name, where: included_from(name, where, folder))


def program_include(shader) -> tuple[str, dict]:
    """(the line that includes the GLSL program, the virtual files it needs): the port of the
    program (a surface program or a vertex/fragment pass) and the ports of the Cg files it
    includes (the shader's own .cginc files and pbrlab's stand-ins, resolved as the parser
    does), each include line relinked to its port, so an include's Cg goes through the same
    type pass and renames as the program's, and errors name the original file and line."""
    virtual: dict = {}
    names: dict = {}   # resolved include -> its virtual name
    # the structs and global variables the program and its includes declare, known to the type
    # pass of each included file too (a struct an earlier include declares, a property the
    # program declares before an include uses it: (Struct)0, a scalar's .rrr); their functions
    # are not (a file's own function, seen twice, would take part in overload resolution)
    # (built-in programs too: a global one include declares and a sibling include reads, as
    # ``float _MaskGlow;`` then ``if (_MaskGlow)``, needs its type for FXC's conversions)
    srp = getattr(shader, "srp", False)
    reached = _reached_text(shader.program, shader.path.parent)
    context = _structs_and_globals(shader.program + "\n" + reached)
    # and the functions the other included files define, as prototypes (the type of a call to
    # a function of another include: int GetAdditionalLightsCount() read into a uint)
    files = included_files(shader.program, shader.path.parent) if srp else {}
    prototypes = {key: _prototypes(text) for key, text in files.items()}

    def context_of(key) -> str:
        if not srp:
            return context
        others = [p for other, protos in prototypes.items() if other != key for p in protos]
        return context + "\n" + "\n".join(dict.fromkeys(others))

    rewritten = getattr(shader, "rewritten_includes", {})  # written globals' copies (written_globals.py)
    # which textures the whole program compares and reads plainly: its includes' declarations of
    # them are typed by the program's reads (compared_textures.py), as the HLSL path's
    reads = texture_reads(shader.program + "\n" + reached)

    def read(target: Path) -> str:
        return shaders.strip_bom(rewritten.get(target.resolve()) or read_source(target))

    def resolved(name: str, where: Path):
        return included_from(name, where, shader.path.parent)

    def ported(text: str, where: Path, port_of) -> str:
        """``text`` ported by ``port_of``, an include inside a function body spliced in
        (body_includes), each include line relinked to its port."""
        text, splices = body_includes.spliced(text, lambda n: resolved(n, where), read)
        text, files = body_includes.cut(relinked(port_of(text), where), splices,
                                        lambda i, target: _port_include(f"{target.resolve()}@{len(virtual) + i}"))
        for spliced_name, (body, target) in files.items():
            virtual[spliced_name] = shaders.VirtualFile(relinked(body, target.parent), str(target), 1)
        return text

    def relinked(text: str, where: Path) -> str:
        def relink(m):
            target = resolved(m.group(2), where)
            if target is None:
                return m.group(0)  # the GLSL expander names what it cannot find
            key = target.resolve()
            if key not in names:
                names[key] = _port_include(key)
                virtual[names[key]] = shaders.VirtualFile(
                    ported(read(target), target.parent,
                           lambda body: port.port_text(body, target.parent, context_of(key), srp=srp, reads=reads)),
                    str(target), 1)
            return m.group(1) + names[key] + m.group(3)
        return _INCLUDE_LINE.sub(relink, text)

    if shader.language == "glsl":  # a port-unity port: GLSL, included as written (as a virtual
        # file: its own name may be one an #include line cannot carry), the Cg files it includes
        # (pbrlab's stand-ins among them) ported as the in-memory port's are
        name = _port_include(shader.path)
        virtual[name] = shaders.VirtualFile(relinked(shaders.read_source(shader.path), shader.path.parent),
                                            str(shader.path), 1)
        return f'#include "{name}"', virtual
    name = _port_include(shader.path.name)
    text = ported(shader.program, shader.path.parent, lambda program: shaders.strip_bom(port.port_program(shader, program, reads)))
    virtual[name] = shaders.VirtualFile(text, str(shader.path), shader.program_line)
    return f'#include "{name}"', virtual


def ported_sources(virtual: dict) -> list[Path]:
    """The files the virtual ports were made from (their edits invalidate the program)."""
    return [Path(v.display) for v in virtual.values()]


def hlsl_program(shader) -> str:
    """The CGPROGRAM as written, less a byte-order mark opening a bare program file, in the
    spellings glslang takes (cg_spellings) and with the implicit conversions FXC makes where
    glslang refuses them spelled out (cg_types.fxc_conversions: the functions of the files it
    includes known too), a one-parameter macro's empty argument given (empty_arguments)."""
    included = included_text(shader.program, shader.path.parent)
    return _fxc_spelled(empty_arguments_spelled(cg_spellings.respelled(shaders.strip_bom(shader.program)), included),
                        included, getattr(shader, "srp", False))


@functools.lru_cache(maxsize=64)
def _fxc_spelled(text: str, included: str, srp: bool) -> str:
    """hlsl_program's type pass, once per text (each stage of a pass compiles the same program;
    the key holds the included files' text, so an edit to one is seen)."""
    symbols = cg_types.with_declarations(cg_spellings.respelled(included), srp) if included.strip() else None
    return cg_types.fxc_conversions(text, symbols, srp)


def _vendored_copies(program: str, folder: Path) -> dict:
    """{path: text} for each project's copy of a file of Unity's ShaderLibrary the program reaches
    (vendored_library): an include of pbrlab's stand-in for it, which glslang, resolving the
    program's includes itself, reads in the copy's place (the port reads the stand-in through
    resolve_included)."""
    out, seen, pending = {}, set(), [(program, folder)]
    stand_ins = (CGINC.resolve(), PACKAGE_STAND_INS.resolve())
    while pending:
        text, where = pending.pop()
        for m in INCLUDE.finditer(blank_comments(text)):
            path = resolve_included(m.group(1), where, copies=False)
            if path is None or path in seen or any(path.resolve().is_relative_to(r) for r in stand_ins):
                continue
            seen.add(path)
            stand_in = vendored_library.stand_in_for(path, PACKAGE_STAND_INS)
            if stand_in is not None:
                out[path] = f'#include "{vendored_library.own_include(stand_in, PACKAGE_STAND_INS)}"\n'
            else:
                pending.append((read_source(path), path.parent))
    return out


def hlsl_includes(shader) -> dict:
    """{path: text} that the HLSL path compiles in place of files the program includes: the
    written globals' copies (``rewritten_includes``, written_globals.py) and every included file
    of the shader's own (not pbrlab's stand-ins) whose HLSL needs FXC's implicit conversions
    spelled out, as the program's are (``_fxc_spelled``: Core RP's ``LinearEyeDepth(tex2Dproj(t,
    p), _ZBufferParams)`` passes a float4 to a float, which FXC truncates and glslang refuses)."""
    out = dict(getattr(shader, "rewritten_includes", {}) or {})
    out.update(_vendored_copies(shader.program, shader.path.parent))
    included = included_text(shader.program, shader.path.parent)
    stand_ins = (CGINC.resolve(), PACKAGE_STAND_INS.resolve())
    for path in included_files(shader.program, shader.path.parent):
        if any(Path(path).is_relative_to(root) for root in stand_ins):
            continue
        text = out.get(path) or shaders.strip_bom(read_source(path))
        # (in the spellings glslang takes, as the program's: cg_spellings)
        # (its include names as Unity reads them: include_separators)
        spelled = _fxc_spelled(empty_arguments_spelled(cg_spellings.respelled(forward_slashed_includes(text)), included),
                               included, getattr(shader, "srp", False))
        # (read_source spelled an #include_with_pragmas as #include, <name> as "name"; glslang reads the file raw)
        if spelled != text or includes_respelled(Path(path)):
            out[path] = spelled
    return out


def fragment_text(shader: M.SurfaceShader, language: str, stem: str, defines: dict):
    """(text, include dirs, virtual files) of the fragment program."""
    if shader.language == "glsl" and language == "hlsl":
        raise PbrlabError(f"surface {shader.path}: a port-unity GLSL port renders only in GLSL; "
                          "for --language hlsl name the original .shader file")
    if language == "hlsl":
        return (generate.fragment_source(shader, "hlsl", stem, hlsl_program(shader), str(shader.path), defines),
                _include_dirs(shader), {})
    include, virtual = program_include(shader)
    text = generate.fragment_source(shader, "glsl", stem, include, shader.path.name, defines)
    return text, _include_dirs(shader), virtual


def _vertex_stage(shader: M.SurfaceShader, language: str, defines: dict, dirs) -> tuple:
    """(the vertex stage running the shader's vertex: function (generate.vertex_source),
    the files it read)."""
    display = f"{shader.path.name} (generated {language} vertex stage)"
    if language == "hlsl":
        text = generate.vertex_source(shader, "hlsl", hlsl_program(shader), str(shader.path), defines)
        glsl = rename_vertex_globals(
            hlsl.cross_to_glsl(hlsl.compile_spirv(text, display, dirs, stage="vert"), plain_uniforms=True))
        return (shaders.Source(glsl, [f"{display} (GLSL from spirv-cross)"]),
                include_closure(text, [*dirs, hlsl.HLSL_ROOT]))
    include, virtual = program_include(shader)
    virtual = {name: dataclasses.replace(file, text=generate.input_starts_zero(file.text))
               for name, file in virtual.items()}
    text = generate.vertex_source(shader, "glsl", include, shader.path.name, defines)
    source = shaders.expand(text, display, include_dirs=dirs, virtual=virtual)
    return source, source.paths + ported_sources(virtual)


def indexed(program, shader: Path):
    """``program`` with its struct members indexed (``bind`` sets an HLSL stage's globals
    through them) and the shader it runs named (for binding errors)."""
    members: dict = {}
    for gl_name in (n for n in program if "." in n):
        members.setdefault(gl_name.split(".", 1)[1], []).append(gl_name)
    program.extra = {"members": members, "shader": str(shader)}
    return program


def rename_vertex_globals(glsl: str) -> str:
    """Both HLSL stages hold a `uniform _Global <id>;` of their own members: rename the
    vertex stage's so the program links (programs.set_uniform then sets the member in each)."""
    instance = re.search(r"uniform _Global (\w+);", glsl)
    if instance:
        glsl = re.sub(r"\b_Global\b", "_GlobalVertex", glsl)
        glsl = re.sub(r"\b" + instance.group(1) + r"\b", "pbrlab_vertex_globals", glsl)
    return glsl


def build_program(ctx, shader: M.SurfaceShader, language: str, stem: str, defines: dict):
    """The program of ``shader`` for a sphere or mesh draw; with a vertex: function always
    the mesh one (spheres are tessellated: tessellate.py)."""
    if shader.vertex is not None:
        stem = "mesh"
    key = ("unity", str(shader.path), shader.language, shader.program, shader.program_line,
           language, stem, tuple(sorted(defines.items())))

    def build():
        text, dirs, virtual = fragment_text(shader, language, stem, defines)
        display = f"{shader.path.name} (generated {language} {stem} program)"
        paths = [shader.path]
        if language == "hlsl":
            glsl = hlsl.hlsl_to_glsl(text, display, dirs, plain_uniforms=True,
                                     version=programs.cross_version(defines))
            glsl = finite_texture_coordinates.applied(glsl)  # lookups at NaN / inf: as Direct3D's
            fragment = shaders.Source(glsl, [f"{display} (GLSL from spirv-cross)"])
            paths += include_closure(text, [*dirs, hlsl.HLSL_ROOT])
        else:
            fragment = shaders.expand(text, display, include_dirs=dirs, virtual=virtual)
            paths += fragment.paths + ported_sources(virtual)
        if shader.vertex is not None:
            vertex, vertex_paths = _vertex_stage(shader, language, defines, dirs)
        else:
            vertex = template_source(VERTEX[stem], defines)
            vertex_paths = [TEMPLATES / VERTEX[stem], *vertex.paths]
        program = indexed(shaders.build_program(ctx, vertex, fragment), shader.path)
        return program, [*paths, *vertex_paths]

    try:
        return programs.program_cache(ctx).get(key, build)
    except PbrlabError as exc:  # a Unity name pbrlab leaves out on purpose: say which feature
        unprovided.raise_named(exc, shader.path)


def object_matrix(obj) -> np.ndarray:
    """Object to world: a sphere's object space is the unit sphere at its centre."""
    if obj.sphere is not None:
        centre, radius = obj.sphere
        m = np.diag([radius, radius, radius, 1.0])
        m[:3, 3] = centre
        return m
    return obj.transform


def camera_world_clip_planes(view_proj: np.ndarray) -> np.ndarray:
    """The frustum's six planes in world space, in unity_CameraWorldClipPlanes' order (left,
    right, bottom, top, near, far), each (unit inward normal, offset): a point p is inside
    where dot((p, 1), plane) >= 0. Gribb & Hartmann 2001, "Fast Extraction of Viewing Frustum
    Planes from the World-View-Projection Matrix": with r_i the rows of the view-projection
    matrix, a GL clip space (-w <= x, y, z <= w) gives the planes r3 + r0, r3 - r0, r3 + r1,
    r3 - r1, r3 + r2, r3 - r2; each is divided by its normal's length (Unity's planes are
    normalised, GeometryUtility.CalculateFrustumPlanes)."""
    m = np.asarray(view_proj, np.float64)
    planes = np.array([m[3] + m[0], m[3] - m[0], m[3] + m[1], m[3] - m[1], m[3] + m[2], m[3] - m[2]])
    return planes / np.linalg.norm(planes[:, :3], axis=1, keepdims=True)


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
    _set(program, "unity_WorldTransformParams", (0.0, 0.0, 0.0, -1.0 if np.linalg.det(model[:3, :3]) < 0.0 else 1.0))
    _set(program, "unity_MatrixVP", _column_major(frame.view_proj))
    _set(program, "unity_MatrixV", _column_major(frame.view))
    _set(program, "unity_MatrixInvV", _column_major(np.linalg.inv(frame.view)))
    _set(program, "glstate_matrix_projection", _column_major(frame.proj))
    _set(program, "unity_CameraProjection", _column_major(frame.proj))
    _set(program, "unity_CameraInvProjection", _column_major(np.linalg.inv(frame.proj)))
    # the camera transform's local frame, +z forward (Camera.transform: the view matrix with z
    # negated; Unity's own Internal-CombineDepthNormals negates z after it to reach view space)
    world_to_camera = np.diag([1.0, 1.0, -1.0, 1.0]) @ frame.view
    _set(program, "unity_WorldToCamera", _column_major(world_to_camera))
    _set(program, "unity_CameraToWorld", _column_major(np.linalg.inv(world_to_camera)))
    w, h = frame.size
    _set(program, "_ScreenParams", (float(w), float(h), 1.0 + 1.0 / w, 1.0 + 1.0 / h))
    near, far = frame.near, frame.far
    _set(program, "_ProjectionParams", (1.0, near, far, 1.0 / far))
    # UnityShaderVariables.cginc, a GL depth buffer (not reversed): 1/eyeDepth = z/far (1 - far/near) + 1/near.
    _set(program, "_ZBufferParams", (1.0 - far / near, far / near, (1.0 - far / near) / far, 1.0 / near))
    orthographic = frame.proj[3, 3] == 1.0
    _set(program, "unity_OrthoParams", (1.0 / frame.proj[0, 0], 1.0 / frame.proj[1, 1], 0.0, 1.0)
         if orthographic else (0.0, 0.0, 0.0, 0.0))
    set_uniform_array(program, "unity_CameraWorldClipPlanes", camera_world_clip_planes(frame.view_proj))
    _set(program, "unity_SpecCube0_HDR", SPECCUBE_HDR)
    _set(program, "unity_FogColor", FOG_COLOR)
    spec_color = material.properties.get("_SpecColor", DEFAULT_SPEC_COLOR)
    spec_color = tuple(spec_color) if isinstance(spec_color, (tuple, list)) and len(spec_color) == 4 else DEFAULT_SPEC_COLOR
    if "_SpecColor" not in material.properties:
        _bind_vector(program, "_SpecColor", "Unity's default _SpecColor", DEFAULT_SPEC_COLOR)  # (a half3's: rgb)
    # the prelude's own _SpecColor where the program declares one of another type (generate.prelude:
    # Lighting.cginc's BlinnPhong reads it, with the colour the material gives the program's)
    _set(program, "pbrlab_prelude_SpecColor", spec_color)
    unit = first_unit
    for name, value in sorted(material.properties.items()):
        kind = material.source.shader.properties[name].kind  # properties.resolve: one value per property
        if isinstance(value, TextureValue):
            arrayed = (texture_arrays.bind_array(program, name, value, cache, unit)  # a one-layer array
                       or shadow_maps.bind_compared(program, name, value, cache, unit))  # a depth texture
            unit += arrayed
            bound = not arrayed and _bind_texture(program, name, kind, unit)  # False: the compiler dropped it
            sized = not arrayed and bool(programs.uniforms_named(program, f"{name}_TexelSize"))
            if bound or sized:
                file = stored_normal_map(value.path) if value.normal_map else value.path
                texture = (environment_cube() if value.cube else cache.texture(file, value.srgb)
                           if value.path is not None else cache.constant_volume(value.texel)
                           if _volume_sampled(program, name) else cache.constant_texture(value.texel))
                if bound:
                    texture.use(unit)
                    unit += 1
                if sized:  # Unity fills <texture>_TexelSize for every texture: (1/w, 1/h, w, h)
                    w, h = texture.size[:2]
                    _bind_vector(program, f"{name}_TexelSize", f"{kind} property {name}'s _TexelSize",
                                 (1.0 / w, 1.0 / h, float(w), float(h)))
            _bind_vector(program, f"{name}_ST", f"{kind} property {name}'s tiling/offset _ST", value.st)
            # and <texture>_HDR, DecodeHDR's instructions: the textures here are linear (or float
            # radiance, the environment's), so the decode is the identity, as unity_SpecCube0_HDR's
            _bind_vector(program, f"{name}_HDR", f"{kind} property {name}'s _HDR", SPECCUBE_HDR)
        elif kind in ("Color", "Vector"):
            _bind_vector(program, name, f"{kind} property {name}", value)
        else:
            _bind_number(program, name, kind, value)


# How Unity binds a property to the uniform of its name: a Float/Range/Int to a float (or an
# int, truncated as a D3D cast does), a Color/Vector to a float4, float3, float2 or float (the
# leading components: `half3 _Emission;` takes rgb), a texture to a sampler of its dimension.
_FLOAT_VECTORS = {"float": 1, "vec2": 2, "vec3": 3, "vec4": 4}
_SAMPLERS = {"2D": ("sampler2D",), "Cube": ("samplerCube",), "3D": ("sampler3D", "sampler2D")}


def _mismatch(program, what: str, name: str, uniform) -> PbrlabError:
    return PbrlabError(f"{_shader_name(program)}: {what} cannot be bound to the uniform '{name}', "
                       f"declared {programs.uniform_type(uniform)} in the program")


def _shader_name(program) -> str:
    return (getattr(program, "extra", None) or {}).get("shader", "surface shader")


# RenderSettings.fogColor's default (Unity's Lighting window: Fog Color (0.5, 0.5, 0.5, 1)); pbrlab
# draws no fog, so a shader that mixes towards it by its own factor sees Unity's default colour.
FOG_COLOR = (0.5, 0.5, 0.5, 1.0)


def _bind_vector(program, name: str, what: str, value) -> None:
    """A Color/Vector (or a texture's _ST) to a float4/3/2/1 uniform: its leading components."""
    uniforms = programs.uniforms_named(program, name)
    for uniform in uniforms:
        if programs.uniform_type(uniform) not in _FLOAT_VECTORS:
            raise _mismatch(program, f"{what} (4 numbers)", name, uniform)
    if uniforms:
        n = _FLOAT_VECTORS[programs.uniform_type(uniforms[0])]
        _set(program, name, tuple(value[:n]) if n > 1 else value[0])


def _bind_number(program, name: str, kind: str, value: float) -> None:
    uniforms = programs.uniforms_named(program, name)
    for uniform in uniforms:
        gl_type = programs.uniform_type(uniform)
        if gl_type not in ("float", "int", "uint", "bool", *_FLOAT_VECTORS):
            raise _mismatch(program, f"{kind} property {name} (a number)", name, uniform)
    if uniforms:
        gl_type = programs.uniform_type(uniforms[0])
        if gl_type in _FLOAT_VECTORS and gl_type != "float":
            # a Float property over a float4 uniform: a script's SetColor/SetVector fills it in
            # Unity (image effects declare it so); here the number, promoted as HLSL promotes a
            # scalar to a vector, with a note
            from .source_text import UnityShaderNote
            warnings.warn(f"{_shader_name(program)}: {kind} property {name} is bound to the {gl_type} uniform "
                          f"'{name}': its value {value:g} in every component (in Unity a script sets such a "
                          "uniform with SetVector/SetColor)", UnityShaderNote, stacklevel=2)
            _set(program, name, (float(value),) * _FLOAT_VECTORS[gl_type])
            return
        _set(program, name, value if gl_type == "float" else
             bool(value) if gl_type == "bool" else int(value))


def _volume_sampled(program, name: str) -> bool:
    """Whether the program samples texture ``name`` as a 3D texture (a 3D property's sampler3D:
    its default is a 1x1x1 volume, properties.py)."""
    return any(programs.uniform_type(u) == "sampler3D" for u in programs.uniforms_named(program, name))


def _bind_texture(program, name: str, kind: str, unit: int) -> bool:
    """The texture unit to a sampler of the property's dimension; False if none is kept."""
    uniforms = programs.uniforms_named(program, name)
    for uniform in uniforms:
        if programs.uniform_type(uniform) not in _SAMPLERS.get(kind, ("sampler2D",)):
            raise _mismatch(program, f"{kind} texture property {name}", name, uniform)
    if uniforms:
        _set(program, name, unit)
    return bool(uniforms)
