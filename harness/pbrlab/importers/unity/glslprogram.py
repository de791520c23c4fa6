"""Unity's ``GLSLPROGRAM`` blocks: a GLSL snippet holding both stages,

    GLSLPROGRAM
    #ifdef VERTEX
    varying vec2 uv;
    void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; uv = gl_MultiTexCoord0.xy; }
    #endif
    #ifdef FRAGMENT
    varying vec2 uv;
    uniform sampler2D _MainTex;
    void main() { gl_FragColor = texture2D(_MainTex, uv); }
    #endif
    ENDGLSL

compiled once per stage with ``VERTEX`` or ``FRAGMENT`` defined (Unity manual, "GLSL Shader
programs"), drawn as a vertex/fragment pass.

    vf = glsl_pass(program, path, first_line, pass_block)       # parse._pass
    program = build_glsl_program(ctx, vf, defines, blended)      # program_pass

The snippet is written in the GLSL of the fixed-function era, which a 3.30 core context does
not have; each such name is spelled as Unity's shader compiler spells it for a core profile
(``_spell``): the compatibility attributes (``gl_Vertex``, ``gl_Normal``, ``gl_MultiTexCoord0/1``,
``gl_Color``) are the mesh's attributes, the matrices (``gl_ModelViewProjectionMatrix`` =
P V M, ``gl_ModelViewMatrix``, ``gl_ProjectionMatrix``, ``gl_NormalMatrix``: the inverse
transpose of the upper 3x3 of the model-view matrix, GLSL 1.20 specification 7.5) Unity's
globals (UnityShaderVariables: UNITY_MATRIX_MVP = unity_MatrixVP * unity_ObjectToWorld),
``varying``/``attribute`` the 3.30 ``out``/``in``, ``gl_FragColor`` an output the harness's
``main`` writes to the float target (as a vertex/fragment pass's colour), ``texture2D`` /
``textureCube`` ``texture``. A ``sampler2DRect`` (unnormalised texel coordinates) is the
harness's 2D texture read at ``coord / size``, which is the same texel for coordinates inside
the texture (GL 3.3 core, 3.8.8: rectangle textures are addressed in texels).

Both languages run the snippet as written: Unity compiles ``GLSLPROGRAM`` only for OpenGL
platforms and has no HLSL of it, so pbrlab's HLSL language (the program as its author wrote
it) runs the same GLSL; a note says so.

A snippet for OpenGL ES only (``#pragma only_renderers gles3`` or ``gles``, no desktop renderer)
runs as Unity compiles it for that renderer: ``SHADER_API_GLES3`` (or ``SHADER_API_GLES``) and
``SHADER_API_MOBILE`` defined instead of ``SHADER_API_GLCORE`` (Unity manual, "Built-in shader
macros"), its ES-only constructs in their desktop spellings: ``#version 300 es`` gives way to the
harness's ``#version 330 core`` (as any ``#version``), precision qualifiers are accepted and
ignored by desktop GLSL (GLSL 3.30, 4.5.2: "no semantic meaning"), so the snippet computes at
float32 everywhere, where a device may compute a ``mediump`` value at half precision; external
images (``samplerExternalOES``) as 2D textures (external_images.py). A note says so.

Refused, naming the reason: ``#pragma only_renderers`` naming no OpenGL renderer (Unity compiles
the program for none of pbrlab's platforms).
"""

from __future__ import annotations

import re
from pathlib import Path

from . import external_images
from .graphics_api import GLSLPROGRAM_LANGUAGE
from . import model as M
from .source_text import UnityShaderError, blank_comments, line_of

# Unity's names of its OpenGL renderers that a desktop GL 3.3 context runs (Unity manual,
# "Targeting shader compilation APIs": glcore = OpenGL 3.x/4.x, opengl = the legacy name).
DESKTOP_GL_RENDERERS = {"glcore", "opengl"}
# Unity's OpenGL ES renderers, each with the macro its compilation defines (Unity manual, "Built-in
# shader macros": SHADER_API_GLES3 for OpenGL ES 3.x, SHADER_API_GLES for 2.0; both mobile APIs).
ES_RENDERERS = {"gles3": "SHADER_API_GLES3", "gles": "SHADER_API_GLES"}
_ONLY_RENDERERS = re.compile(r"^[ \t]*#[ \t]*pragma[ \t]+only_renderers[ \t]+([^\n]*)$", re.M)

# The globals the spelled built-ins read, declared where the snippet does not declare them
# (program.bind sets them, as for every Unity pass).
_GLOBALS = {"unity_ObjectToWorld": "mat4", "unity_WorldToObject": "mat4", "unity_MatrixVP": "mat4",
            "unity_MatrixV": "mat4", "unity_MatrixInvV": "mat4", "glstate_matrix_projection": "mat4",
            "_WorldSpaceCameraPos": "vec3", "_Time": "vec4", "_SinTime": "vec4", "_CosTime": "vec4",
            "_ScreenParams": "vec4", "_ProjectionParams": "vec4", "_ZBufferParams": "vec4"}
# The pass's light (generate_pass._main_light sets them in main, as in every Unity pass).
_LIGHT_GLOBALS = {"_LightColor0": "vec4", "_WorldSpaceLightPos0": "vec4"}

# The compatibility profile's names -> Unity's core-profile spellings (module docstring).
_VERTEX_BUILTINS = {
    "gl_Vertex": "vec4(in_position, 1.0)", "gl_Normal": "in_normal",
    "gl_MultiTexCoord0": "vec4(in_uv, 0.0, 1.0)", "gl_MultiTexCoord1": "vec4(in_uv1, 0.0, 1.0)",
    "gl_Color": "in_color",
}
_MATRICES = {
    "gl_ModelViewProjectionMatrix": "(unity_MatrixVP * unity_ObjectToWorld)",
    "gl_ModelViewMatrix": "(unity_MatrixV * unity_ObjectToWorld)",
    "gl_ProjectionMatrix": "glstate_matrix_projection",
    "gl_ModelViewMatrixInverseTranspose": "transpose(unity_WorldToObject * unity_MatrixInvV)",
    "gl_NormalMatrix": "mat3(transpose(unity_WorldToObject * unity_MatrixInvV))",
}
# Unity 5.4 renamed these built-ins (its upgrade guide); a snippet of before still declares the
# old names, which Unity kept setting.
_RENAMED = {"_Object2World": "unity_ObjectToWorld", "_World2Object": "unity_WorldToObject"}
_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)


def glsl_pass(program: str, path: Path, first_line: int, block) -> M.VertexFragmentPass:
    """The pass of a ``GLSLPROGRAM``; a refusal (UnityShaderError) names what it needs that
    desktop GL does not have."""
    masked = blank_comments(program)

    def where(index: int) -> str:
        return f"{path}:{first_line - 1 + line_of(program, index)}"

    m = _ONLY_RENDERERS.search(masked)
    if m and not (DESKTOP_GL_RENDERERS | set(ES_RENDERERS)) & set(m.group(1).split()):
        raise UnityShaderError(f"{where(m.start())}: #pragma only_renderers {m.group(1).strip()}: Unity compiles "
                               "this GLSLPROGRAM only for those renderers, none of them OpenGL (glcore, gles3, "
                               "gles), which pbrlab runs")
    for stage in ("VERTEX", "FRAGMENT"):
        if not re.search(r"^[ \t]*#[ \t]*if(?:def[ \t]+|[ \t]+defined[ \t]*\(?[ \t]*)" + stage + r"\b", masked, re.M):
            raise UnityShaderError(f"{where(0)}: a GLSLPROGRAM needs both stages, each under "
                                   f"#ifdef VERTEX / #ifdef FRAGMENT (no #ifdef {stage})")
    # Unity compiles a snippet's HULL, DOMAIN and GEOMETRY blocks as those stages; pbrlab builds
    # a GLSLPROGRAM's vertex and fragment stages only, so one with more is refused at its block
    # (drawn without them, the tessellated or generated primitives would be missing silently)
    m = re.search(r"^[ \t]*#[ \t]*if(?:def[ \t]+|[ \t]+defined[ \t]*\(?[ \t]*)(HULL|DOMAIN|GEOMETRY)\b", masked, re.M)
    if m:
        stage = {"HULL": "tessellation control", "DOMAIN": "tessellation evaluation"}.get(m.group(1), "geometry")
        raise UnityShaderError(f"{where(m.start())}: #ifdef {m.group(1)}: a GLSLPROGRAM's {stage} stage, which "
                               "pbrlab does not build (a GLSLPROGRAM runs its VERTEX and FRAGMENT stages here)")
    vf = M.VertexFragmentPass(
        path=path, name=block.name, light_mode=block.tags.get("LightMode", "Always"), program=program,
        program_line=first_line, vertex="main", fragment="main", vertex_params=[], vertex_return="void",
        vertex_return_semantic="", fragment_params=[], fragment_return="void", fragment_return_semantic="",
        structs={}, language=LANGUAGE)
    return vf


def api_macro(program: str) -> str:
    """The SHADER_API_ macro of the renderer the snippet is compiled for: desktop OpenGL's
    (glcore) unless ``#pragma only_renderers`` names only OpenGL ES renderers (module docstring)."""
    m = _ONLY_RENDERERS.search(blank_comments(program))
    named = set(m.group(1).split()) if m else DESKTOP_GL_RENDERERS
    if named & DESKTOP_GL_RENDERERS:
        return "SHADER_API_GLCORE"
    return next(macro for name, macro in ES_RENDERERS.items() if name in named)


def note(path: Path, first_line: int, program: str = "") -> str:
    """The note a drawn GLSLPROGRAM pass gets (the shader's notes)."""
    text = (f"{path}:{first_line}: a GLSLPROGRAM: Unity compiles it for OpenGL only; both of pbrlab's "
            "languages run the GLSL as written")
    api = api_macro(program)
    if api != "SHADER_API_GLCORE":
        text += (f"; for OpenGL ES only ({api}), run on desktop GL: precision qualifiers ignored (float32 "
                 "throughout)")
    if external_images.uses_external_images(blank_comments(program)):
        text += ("; its external image (samplerExternalOES) is the property's 2D texture, read as the RGB "
                 "a device's driver returns (no YUV conversion here)")
    return text


# VertexFragmentPass.language of a GLSLPROGRAM pass (program_pass builds it here).
LANGUAGE = GLSLPROGRAM_LANGUAGE  # (graphics_api: the language whose pass defines its own API macro)


def implicit_samplers(program: str) -> list[tuple]:
    """[(kind, name)] of the snippet's sampler uniforms (Unity binds a default texture to each:
    parse's implicit texture properties)."""
    found = re.findall(r"\buniform\s+(sampler2D|sampler2DRect|samplerCube|samplerExternalOES)\s+(\w+)\s*;",
                       blank_comments(program))
    return [("Cube" if kind == "samplerCube" else "2D", name) for kind, name in found]


def _code_only(text: str, edit) -> str:
    """``edit`` applied to the code of ``text`` (comments kept as written)."""
    out, last = [], 0
    for m in _COMMENT.finditer(text):
        out += [edit(text[last:m.start()]), m.group(0)]
        last = m.end()
    return "".join(out + [edit(text[last:])])


def _declared(code: str, name: str) -> bool:
    return re.search(r"\buniform\s+\w+\s+" + name + r"\s*(?:\[[^\]]*\])?\s*;", code) is not None


def _spell(program: str, stage: str) -> str:
    """The snippet in GLSL 3.30 core for ``stage`` (module docstring), line for line."""
    rects = re.findall(r"\buniform\s+sampler2DRect\s+(\w+)\s*;", blank_comments(program))

    def edit(code: str) -> str:
        for name in _LIGHT_GLOBALS:  # set in main from the scene's light
            code = re.sub(r"\buniform\s+\w+\s+" + name + r"\s*;", f"/* {name}: the pass's light */", code)
        code = re.sub(r"^([ \t]*#[ \t]*version\b[^\n]*)", r"// \1", code, flags=re.M)
        code = external_images.spelled_for_desktop(code)
        code = re.sub(r"\bvarying\b", "out" if stage == "VERTEX" else "in", code)
        code = re.sub(r"\battribute\b", "in", code)
        code = re.sub(r"\btexture(?:2D|Cube)\b", "texture", code)
        code = re.sub(r"\bgl_FragColor\b", "pbrlab_frag_color", code)
        for old, new in _RENAMED.items():
            code = re.sub(r"\b" + old + r"\b", new, code)
        code = re.sub(r"\bgl_FragData\s*\[\s*0\s*\]", "pbrlab_frag_color", code)
        for name, spelled in _MATRICES.items():
            code = re.sub(r"\b" + name + r"\b", spelled, code)
        if stage == "VERTEX":
            for name, spelled in _VERTEX_BUILTINS.items():
                code = re.sub(r"\b" + name + r"\b", spelled, code)
        for name in rects:  # a rectangle texture: the 2D texture at coord / size
            code = re.sub(r"\bsampler2DRect\s+" + name + r"\b", f"sampler2D {name}", code)
            code = re.sub(r"\btexture\s*\(\s*" + name + r"\s*,", f"pbrlab_texture_rect({name},", code)
            code = re.sub(r"\btextureSize\s*\(\s*" + name + r"\s*\)", f"textureSize({name}, 0)", code)
        return re.sub(r"\bvoid\s+main\s*\(", "void pbrlab_snippet_main(", code)

    return _code_only(program, edit)


def stage_text(vf, stage: str, defines: dict, blended: bool) -> tuple:
    """The whole text of one stage: the harness's defines and scene shading (its names are
    pbrlab_/pbr_/u_ prefixed), Unity's globals the snippet leaves undeclared, the spelled
    snippet on its own lines, then the harness's main around the snippet's: (head, snippet, tail)."""
    from .generate import _defines
    from .generate_pass import _POSITIONAL_ADD, _main_light, _world_position
    code = blank_comments(vf.program)
    for old, new in _RENAMED.items():
        code = re.sub(r"\b" + old + r"\b", new, code)
    head = ["#version 330 core", _defines({**defines, stage: 1, **_api_defines(vf.program)}),
            '#include "scene_shading.glsl"']
    head += [f"uniform {t} {n};" for n, t in _GLOBALS.items() if not _declared(code, n)]
    head += [f"{t} {n};" for n, t in _LIGHT_GLOBALS.items()]
    head.append("vec4 pbrlab_texture_rect(sampler2D s, vec2 p) { return texture(s, p / vec2(textureSize(s, 0))); }")
    if stage == "VERTEX":
        head += ["in vec3 in_position;", "in vec3 in_normal;", "in vec2 in_uv;", "in vec4 in_tangent;",
                 "in vec2 in_uv1;", "in vec4 in_color;", _POSITIONAL_ADD, "out vec3 pbrlab_vary_world_position;",
                 "#endif"]
        main = [_POSITIONAL_ADD, f"    vec3 pbrlab_world_position = {_world_position('glsl')};",
                "    pbrlab_vary_world_position = pbrlab_world_position;", "#endif", _main_light("glsl"),
                "    pbrlab_snippet_main();"]
    else:
        head += ["vec4 pbrlab_frag_color = vec4(0.0);", "out vec4 pbrlab_radiance;", _POSITIONAL_ADD,
                 "in vec3 pbrlab_vary_world_position;", "#endif"]
        alpha = "pbrlab_frag_color.a" if blended else "1.0"
        main = [_POSITIONAL_ADD, "    vec3 pbrlab_world_position = pbrlab_vary_world_position;", "#endif",
                _main_light("glsl"), "    pbrlab_snippet_main();",
                f"    pbrlab_radiance = vec4(pbrlab_target_radiance(pbrlab_frag_color.rgb), {alpha});"]
    return "\n".join(head) + "\n", _spell(vf.program, stage), "void main() {\n" + "\n".join(main) + "\n}\n"


def _api_defines(program: str) -> dict:
    """The renderer's macros (api_macro; an ES renderer is a mobile one: SHADER_API_MOBILE)."""
    api = api_macro(program)
    return {api: 1} if api == "SHADER_API_GLCORE" else {api: 1, "SHADER_API_MOBILE": 1}


def build_glsl_program(ctx, vf, defines: dict, blended: bool, dirs: list):
    """(the program, the files it read): both stages expanded (the snippet numbered from its
    line of the ``.shader``, as a virtual file: errors read ``X.shader:LINE``)."""
    from ...gpu import shaders
    stages, paths = {}, [vf.path]
    for stage in ("VERTEX", "FRAGMENT"):
        head, snippet, tail = stage_text(vf, stage, defines, blended)
        name = f"pbrlab-unity-glsl:{stage.lower()}"
        virtual = {name: shaders.VirtualFile(snippet, str(vf.path), vf.program_line)}
        source = shaders.expand(head + f'#include "{name}"\n' + tail, f"{vf.path.name} ({stage.lower()} stage)",
                                include_dirs=dirs, virtual=virtual)
        stages[stage] = source
        paths += source.paths
    return shaders.build_program(ctx, stages["VERTEX"], stages["FRAGMENT"]), paths
