"""Harness programs built from ``templates/``, with the fragment stage in GLSL or HLSL.

    program = program_from_templates(ctx, "sphere.vert", "sphere.hlsl", defines, surface)
    set_uniform(program, "u_albedo", (1.0, 0.5, 0.2))

The fragment template's suffix picks the language (``FRAGMENT_SUFFIX``):

* ``.frag`` (GLSL): ``//@DEFINES`` and ``//@SURFACE`` filled in, includes expanded by
  ``shaders.expand``; errors are reported at the original file and line.
* ``.hlsl``: the same markers, then glslang's HLSL front end to SPIR-V and spirv-cross to
  GLSL 330 (``hlsl.py``): the Direct3D path of the library, run on this GL. Errors are
  glslang's, at the original file and line (a ``#line`` follows the defines). The vertex
  stage stays the harness's GLSL: it only places geometry, and the HLSL pixel shader's
  inputs keep its output names, which spirv-cross keeps.

HLSL globals form the ``$Global`` cbuffer. spirv-cross writes it as one uniform struct
(``--glsl-emit-ubo-as-plain-uniforms``: ``uniform _Global _29;``), so its members are GL
uniforms named ``_29.u_albedo``; ``set_uniform`` sets a value by its template name on the
loose uniform (GLSL, or the GLSL vertex stage) and on the struct member (the HLSL stage)
alike. Matrices: glslang declares HLSL's ``float4x4`` row-major in SPIR-V (HLSL indexes
rows first) and spirv-cross, with no layout to say so in a plain uniform, multiplies as
``v * M``; so a struct member receives the transpose of what a GLSL ``mat4`` receives,
and ``mul(M, v)`` in HLSL computes the same ``M v`` as ``M * v`` in GLSL
(tests/gpu/hlsl/test_scene_renders.py renders depth-tested scenes both ways).
"""

from __future__ import annotations

import atexit
import hashlib
import os
import re
import shutil
import struct
import tempfile
from pathlib import Path

import numpy as np

from . import hlsl, shaders, source_cache
from ..foundation import safe_paths
from ..foundation.errors import PbrlabError
from ..foundation.file_identity import FileCache, include_closure
from ..foundation.locations import PACKAGE_FOLDER

TEMPLATES = PACKAGE_FOLDER / "templates"
FRAGMENT_SUFFIX = {"glsl": ".frag", "hlsl": ".hlsl"}
LANGUAGES = tuple(FRAGMENT_SUFFIX)
DEFAULT_SURFACE = "default_surface.inc"  # shared by both languages
# A sphere program drawn into a multisampled target is compiled with this define, its value
# the samples per pixel: it writes which samples the sphere covers (scene_geometry.inc) to
# gl_SampleMask (GLSL 330 with ARB_sample_shading) or SV_Coverage (HLSL). spirv-cross writes
# gl_SampleMask only from GLSL 400 on ("not supported before GLSL 400"), so such an HLSL
# stage is cross-compiled to GLSL 400; every other one stays at 330.
SAMPLES_DEFINE = "PBRLAB_SAMPLES"
SAMPLE_MASK_GLSL_VERSION = 400


def cross_version(defines: dict) -> int:
    """The GLSL version an HLSL pixel shader with ``defines`` is cross-compiled to."""
    return SAMPLE_MASK_GLSL_VERSION if SAMPLES_DEFINE in defines else 330
_GL_FLOAT_MATRICES = {0x8B5A: 2, 0x8B5B: 3, 0x8B5C: 4}  # GL_FLOAT_MAT2, MAT3, MAT4
# A uniform's GL type (glGetActiveUniform; the GL 4.6 core specification's table 7.3) by
# its GLSL name, for binding checks and messages.
GL_UNIFORM_TYPES = {
    0x1406: "float", 0x8B50: "vec2", 0x8B51: "vec3", 0x8B52: "vec4",
    0x1404: "int", 0x8B53: "ivec2", 0x8B54: "ivec3", 0x8B55: "ivec4",
    0x1405: "uint", 0x8DC6: "uvec2", 0x8DC7: "uvec3", 0x8DC8: "uvec4",
    0x8B56: "bool", 0x8B57: "bvec2", 0x8B58: "bvec3", 0x8B59: "bvec4",
    0x8B5A: "mat2", 0x8B5B: "mat3", 0x8B5C: "mat4",
    0x8B65: "mat2x3", 0x8B66: "mat2x4", 0x8B67: "mat3x2", 0x8B68: "mat3x4", 0x8B69: "mat4x2", 0x8B6A: "mat4x3",
    0x8B5D: "sampler1D", 0x8B5E: "sampler2D", 0x8B5F: "sampler3D", 0x8B60: "samplerCube",
    0x8B61: "sampler1DShadow", 0x8B62: "sampler2DShadow", 0x8DC1: "sampler2DArray",
    0x8DC4: "sampler2DArrayShadow", 0x8DC5: "samplerCubeShadow", 0x8DC9: "isampler2D", 0x8DD2: "usampler2D",
}
# Programs kept per GL context (in ctx.extra, so they go with it), least recently used
# dropped and released beyond this: about 0.5 MB of llvmpipe code each (issue 14 measured
# 2,002 programs in 1,186 MB), and a scene uses a few dozen at most.
PROGRAMS_PER_CONTEXT = 128
_EXTRA_KEY = "pbrlab_programs"


def fragment_template(stem: str, language: str) -> str:
    """The fragment template of ``stem`` ('sphere', 'mesh', 'resolve') in ``language``."""
    if language not in FRAGMENT_SUFFIX:
        raise ValueError(f"language={language!r}: expected one of {LANGUAGES}")
    return stem + FRAGMENT_SUFFIX[language]


def surface_file(surface: Path | None, language: str) -> Path | None:
    """A material's surface function in ``language``: the file the scene names for GLSL,
    its twin with the suffix ``.hlsl`` beside it for HLSL."""
    if surface is None or language == "glsl":
        return surface
    twin = surface.with_suffix(".hlsl")
    if not twin.is_file():
        raise PbrlabError(f"surface {surface}: rendering in HLSL needs its HLSL twin {twin.name} "
                          f"beside it, and there is none (scenes/unity_example/brick_surface.hlsl "
                          "is an example)")
    return twin


def _defines_block(defines: dict) -> str:
    return "\n".join(f"#define {k} {v}".rstrip() for k, v in sorted(defines.items()))


# A file name an #include line cannot carry: "..." has no escapes (C's header names, glslang),
# and a line ends at a newline. Such a surface (we"ird.glsl) is included through a symbolic
# link with a plain name in a folder of this process's own (_surface_alias).
_NOT_IN_INCLUDE = re.compile(r'["\\\x00-\x1f\x7f]')
SURFACE_ALIAS = "pbrlab-surface"  # + the surface's suffix
_alias_root: list[Path] = []


def _surface_alias(surface: Path) -> Path:
    """A folder holding SURFACE_ALIAS + suffix, a link to ``surface``: one per resolved file,
    under a temporary folder removed when the process exits. Both include expanders resolve
    the link to the file itself, so messages and the cache's file identities name the
    user's file, never the link."""
    if not _alias_root:
        root = Path(tempfile.mkdtemp(prefix="pbrlab-surfaces-"))
        atexit.register(shutil.rmtree, root, True)
        _alias_root.append(root)
        safe_paths.trust_links_in(root)  # its links are pbrlab's own, not a model's
    real = surface.resolve()
    folder = _alias_root[0] / hashlib.sha256(os.fsencode(real)).hexdigest()[:16]
    link = folder / (SURFACE_ALIAS + surface.suffix)
    if not link.is_symlink():
        folder.mkdir(exist_ok=True)
        link.symlink_to(real)
    return folder


def _surface_include(surface: Path | None) -> tuple[str, list[Path]]:
    """(the name the template includes the surface function by, the include folders)."""
    if surface is None:
        return DEFAULT_SURFACE, [TEMPLATES]
    if _NOT_IN_INCLUDE.search(surface.name):
        return SURFACE_ALIAS + surface.suffix, [_surface_alias(surface), TEMPLATES, surface.parent]
    return surface.name, [TEMPLATES, surface.parent]


def _fill(text: str, defines: dict, include: str, display: str, line_marker: bool) -> str:
    """The template with its defines and surface include (``include``: its name, from
    _surface_include); with ``line_marker``, a #line after the defines keeps the template's
    own line numbers in error messages."""
    surface_line = f'#include "{include}"'
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.strip() == "//@DEFINES":
            block = _defines_block(defines)
            if line_marker:
                block += f'\n#line {i + 2} "{display}"'
            lines[i] = block
        elif line.strip() == "//@SURFACE":
            lines[i] = surface_line
    return "\n".join(lines) + "\n"


def template_source(name: str, defines: dict, surface: Path | None = None) -> shaders.Source:
    """A GLSL harness template with its defines and surface function, includes expanded."""
    include, include_dirs = _surface_include(surface)
    text = _fill((TEMPLATES / name).read_text(encoding="utf-8"), defines, include,
                 f"pbrlab/templates/{name}", line_marker=False)
    return source_cache.expand(text, f"pbrlab/templates/{name}", include_dirs)


def hlsl_template_text(name: str, defines: dict, surface: Path | None = None) -> tuple[str, list]:
    """(HLSL text, include directories) of an HLSL pixel-shader template with its defines
    and surface function; glslang resolves the includes (then ``hlsl.HLSL_ROOT``)."""
    include, include_dirs = _surface_include(surface)
    text = _fill((TEMPLATES / name).read_text(encoding="utf-8"), defines, include,
                 f"pbrlab/templates/{name}", line_marker=True)
    return text, include_dirs


def hlsl_template_source(name: str, defines: dict, surface: Path | None = None) -> shaders.Source:
    """An HLSL pixel-shader template, compiled to SPIR-V and cross-compiled to GLSL 330."""
    display = f"pbrlab/templates/{name}"
    text, include_dirs = hlsl_template_text(name, defines, surface)
    glsl = hlsl.hlsl_to_glsl(text, display, include_dirs, plain_uniforms=True, version=cross_version(defines))
    return shaders.Source(glsl, [f"{display} (GLSL from spirv-cross)"])


def program_from_templates(ctx, vert: str, frag: str, defines: dict, surface: Path | None = None):
    """Compile (once per context, shader pair, defines and surface file version) a program.

    ``frag`` ending in ``.hlsl`` builds the HLSL twin (module doc). ``surface`` is a file
    defining ``surf(Input IN, inout ...)`` in the fragment's language; None uses the
    harness's default_surface.inc. The cached program is rebuilt when the surface file,
    a template or any file they include changed on disk (file_identity.FileCache).
    """
    key = (vert, frag, tuple(sorted(defines.items())), surface)

    def build():
        vertex = template_source(vert, defines)
        paths = [TEMPLATES / vert, TEMPLATES / frag, *vertex.paths]
        if frag.endswith(FRAGMENT_SUFFIX["hlsl"]):
            fragment = hlsl_template_source(frag, defines, surface)
            search = [TEMPLATES] + ([surface.parent] if surface is not None else []) + [hlsl.HLSL_ROOT]
            paths += include_closure((TEMPLATES / frag).read_text(encoding="utf-8"), search)
            if surface is not None:
                paths += [surface, *include_closure(shaders.read_source(surface), search, surface.parent)]
        else:
            fragment = template_source(frag, defines, surface)
            paths += fragment.paths
        program = shaders.build_program(ctx, vertex, fragment)
        program.extra = {"members": _struct_members(program),
                         "shader": str(surface) if surface is not None else None}
        return program, paths

    return program_cache(ctx).get(key, build)


def program_cache(ctx) -> FileCache:
    """The context's scene programs (templates and Unity surface shaders alike): a FileCache
    of ``PROGRAMS_PER_CONTEXT``, entries released when dropped."""
    extra = ctx.extra if isinstance(ctx.extra, dict) else {}
    if _EXTRA_KEY not in extra:
        extra[_EXTRA_KEY] = FileCache(PROGRAMS_PER_CONTEXT, lambda program: program.release())
        ctx.extra = extra
    return extra[_EXTRA_KEY]


def _struct_members(program) -> dict:
    """Template name -> GL name of the uniforms inside a uniform struct (HLSL's $Global)."""
    return {name.split(".", 1)[1]: name for name in program if "." in name}


def uniform_type(uniform) -> str:
    """A uniform's GLSL type name (``vec3``, ``sampler2D``; ``vec3[4]`` for an array)."""
    name = GL_UNIFORM_TYPES.get(uniform.gl_type, f"GL type 0x{uniform.gl_type:04x}")
    return name + (f"[{uniform.array_length}]" if uniform.array_length > 1 else "")


def uniforms_named(program, name) -> list:
    """The GL uniforms that hold the template uniform ``name``: the loose one and the HLSL
    stages' struct members (none when the compiler dropped it as unused)."""
    return [uniform for uniform, _ in _uniforms(program, name)]


def _describe(value) -> str:
    if isinstance(value, (bool, int, float, np.number)):
        return f"a {type(value).__name__} ({value!r})"
    try:
        return f"{len(value)} numbers"
    except TypeError:
        return repr(value)


def _uniforms(program, name):
    """(uniform, transposed) for each GL uniform that holds the template uniform ``name``."""
    found = []
    loose = program.get(name, None)
    if loose is not None:
        found.append((loose, False))
    member = (getattr(program, "extra", None) or {}).get("members", {}).get(name)
    for gl_name in [member] if isinstance(member, str) else (member or []):  # one per HLSL stage
        found.append((program[gl_name], True))
    return found


def set_uniform(program, name, value):
    """Set a uniform if the compiler kept it (unused uniforms are optimised away)."""
    for uniform, in_struct in _uniforms(program, name):
        size = _GL_FLOAT_MATRICES.get(uniform.gl_type)
        try:
            data = value
            if in_struct and size is not None:  # column-major data of M -> that of M^T (module doc)
                # (per uniform: the vertex and fragment stages' members each take M^T once)
                data = tuple(np.asarray(value, np.float32).reshape(size, size).T.reshape(-1).tolist())
            uniform.value = data
        except (struct.error, TypeError, ValueError):
            # the harness sets its own uniforms by name; a shader's uniform of another type
            # under one of those names (a surface sampler called u_albedo) lands here
            shader = (getattr(program, "extra", None) or {}).get("shader")
            raise PbrlabError(
                f"{shader + ': ' if shader else ''}uniform '{name}': the program declares it "
                f"{uniform_type(uniform)}, and pbrlab sets a uniform of that name to "
                f"{_describe(value)}: the shader's '{name}' clashes with one of the harness's own "
                "uniforms; rename it in the shader") from None


def set_uniform_array(program, name, values):
    """Set a uniform array; entries past ``values`` (the full program's spare light
    slots) are zero and never read (its loops stop at the runtime count). The compiler may
    keep fewer entries than declared (a program that reads only element 0, as a Unity pass
    reads only its main light): those it keeps get the first values."""
    for uniform, _ in _uniforms(program, name):
        data = np.ascontiguousarray(values, dtype=np.float32).reshape(len(values), -1)
        padded = np.zeros((uniform.array_length, data.shape[1]), np.float32)
        kept = min(len(data), uniform.array_length)
        padded[:kept] = data[:kept]
        uniform.write(padded.tobytes())
