"""Read a vertex/fragment pass (``#pragma vertex v`` / ``#pragma fragment f``) into a
``model.VertexFragmentPass``: the two functions' signatures with their semantics and the
structs they pass, which ``generate_pass.py`` wires to the harness's meshes and target.

    vf = parse_pass(program_text, path, first_line, pass_block)
"""

from __future__ import annotations

import re
from pathlib import Path

from . import model as M
from .geometry_syntax import parse_geometry
from .tessellation_syntax import parse_tessellation
from .conditionals import active_text, defines_of
from .compute_buffers import check_compute_buffers, check_included_compute_buffers
from .engine_inputs import check_engine_inputs, fill_declared
from .dynamic_lightmaps import declares_dynamic_lightmap_on
from .lightmaps import declares_lightmap_on
from .light_probes import declares_light_probe_sh
from .unprovided import missing_include
from .user_definitions import text_defines
from .own_library_functions import renamed_in_own_files
from .macro_redefinitions import undefined_before_redefinition
from .shader_messages import dropped_printf_calls
from .written_globals import copied_across_includes, copied_in_includes, copied_written_globals
from .member_macros import expanded_member_macros
from .source_text import (IDENT, INCLUDE, UnityShaderError, blank_comments, check_refusals, declared_keywords,
                          included_text, line_of,
                          matching_brace, resolve_included, respelled, declared_globals)

_PRAGMA = re.compile(r"^[ \t]*#[ \t]*pragma[ \t]+(\w+)[ \t]*([^\n]*)$", re.M)
_STAGES = ("vertex", "fragment", "geometry", "hull", "domain")
# A stage whose text is built apart from the vertex and fragment stages' (geometry_stage.py):
# the program's engine-filled globals are not set there (tessellation_stage.py's entries set them
# as the vertex and fragment entries do); its written globals' copies are (geometry_stage's entries).
_APART = ("geometry",)


def _split_params(text: str) -> list[str]:
    out, depth, cur = [], 0, []
    for ch in text:
        if ch == "," and depth == 0:
            out.append("".join(cur))
            cur = []
            continue
        depth += {"(": 1, ")": -1}.get(ch, 0)
        cur.append(ch)
    if "".join(cur).strip():
        out.append("".join(cur))
    return [p.strip() for p in out if p.strip()]


def _leading(words: list, qualifiers: tuple) -> int:
    """How many of ``words`` lead as qualifiers, leaving a type and a name after them."""
    k = 0
    while k < len(words) - 2 and words[k] in qualifiers:
        k += 1
    return k


def _param(text: str, where: str) -> tuple:
    """(qualifier, type, name, semantic) of one parameter."""
    semantic = ""
    m = re.search(r":\s*(\w+)\s*$", text)
    if m:
        semantic, text = m.group(1), text[:m.start()].strip()
    words = text.split()
    # the qualifiers lead (a parameter named as one, ``float sample``, is a name: glslang's HLSL
    # reads ``sample`` as a modifier only before a type, and takes it as a name)
    lead = _leading(words, ("in", "out", "inout", "uniform", "nointerpolation", "linear", "centroid",
                            "noperspective", "sample", "const"))
    qualifiers, words = words[:lead], words[lead:]
    if len(words) != 2:
        raise UnityShaderError(f"{where}: cannot read the parameter {text!r}")
    qual = next((q for q in qualifiers if q in ("out", "inout")), "in")
    return qual, words[0], words[1], semantic


def _function_signature(masked: str, name: str, where_of):
    m = None
    for cand in re.finditer(r"\b(" + IDENT + r")\s+" + re.escape(name) + r"\s*\(", masked):
        if cand.group(1) not in ("return", "else"):
            m = cand
            break
    if m is None:
        return None
    depth, i = 1, m.end()
    while i < len(masked) and depth:
        depth += {"(": 1, ")": -1}.get(masked[i], 0)
        i += 1
    # the #if lines of a parameter list (`, out half4 c : SV_Target0 #ifdef _WRITE_RENDERING_LAYERS
    # , out float4 layers : SV_Target1 #endif`): the text is the active branch's, the lines go
    params_text = re.sub(r"^[ \t]*#[^\n]*", "", masked[m.end():i - 1], flags=re.M)
    # (and the #if lines between it and the body: `fragOut frag(g2f i) #else half4 frag(g2f i) :
    # SV_Target #endif {`, the inactive branch already blanked)
    rest = re.match(r"(?:\s|#[^\n]*)*+(?::\s*(\w+))?(?:\s|#[^\n]*)*+\{", masked[i:])
    if rest is None:
        return None
    where = where_of(m.start())
    params = [_param(p, where) for p in _split_params(params_text) if p != "void"]
    kind = m.group(1)
    if masked[:m.start(1)].rstrip().endswith("#"):  # a return type chosen by #if lines (`#ifdef
        # UNITY_HDR_ON half4 #else fixed4 #endif frag(...)`, Internal-DeferredShading): the last type
        # written before them (the variants' types are the same type here: half and fixed are float)
        code = [line for line in masked[:m.start(1)].splitlines() if not line.lstrip().startswith("#")]
        words = re.findall(IDENT, "\n".join(code)[-200:])
        kind = words[-1] if words else kind
    return kind, params, rest.group(1) or "", m.start()


# HLSLSupport.cginc's clip-space position member, UNITY_POSITION(pos): float4 pos : SV_POSITION.
_UNITY_POSITION = re.compile(r"\bUNITY_POSITION\s*\(\s*(" + IDENT + r")\s*\)")
# Upper-case macro words (with their arguments) at the start of a struct member's text.
_LEADING_MACROS = re.compile(r"^(?:[A-Z][A-Z0-9_]*(?:\s*\([^()]*\))?\s+)+(?=[A-Za-z_])")


# UnityCG.cginc's vertex functions a #pragma may name and the structs they take and give, as
# Unity declares them (Unity manual, "Built-in shader include files": vert_img, the image
# effects' vertex stage); their bodies are the Unity layer's (unity_compat/shader_variables).
UNITY_CG_FUNCTIONS = """
struct appdata_img { float4 vertex : POSITION; half2 texcoord : TEXCOORD0; };
struct v2f_img { float4 pos : SV_POSITION; half2 uv : TEXCOORD0; };
v2f_img vert_img(appdata_img v) { }
"""


def _leaves(inner, names: list, semantic: str) -> list:
    """The members ``name.leaf`` of a struct member of the struct ``inner`` (a struct varying:
    ``struct Inner { float2 uv; float tint; }; struct v2f { ...; Inner inner : TEXCOORD0; }``):
    each of ``inner``'s (already flattened) members as a member of its own, at each leaf's own
    semantic, or, where the member carries one (``Inner inner : TEXCOORD0``), at that semantic
    with consecutive indices (TEXCOORD0, TEXCOORD1, ...), as an array member's elements take
    theirs here (an assumption for a struct, not checked against FXC: pbrlab's stages are linked
    by semantic on both sides, so any consistent numbering links). Each leaf is then a varying of
    its own, as a vector member is (pbrlab writes its stages' entries, which pass each member by
    its semantic; GLSL 3.30 takes no struct as a vertex output)."""
    out = []
    base = re.fullmatch(r"(\D*?)(\d*)", semantic) if semantic else None
    for name in names:
        for k, (kind, leaf, own) in enumerate(inner.members):
            at = f"{base.group(1)}{int(base.group(2) or 0) + k}" if base else own
            out.append((kind, f"{name}.{leaf}", at))
    return out


def _structs(masked: str) -> dict:
    out = {}
    for m in re.finditer(r"\bstruct\s+(" + IDENT + r")\s*\{", masked):
        end = matching_brace(masked, m.end() - 1)
        members, flat = [], set()
        body = expanded_member_macros(masked[m.end():end], masked)  # the project's member macros
        body = re.sub(r"^[ \t]*#[^\n]*", "", body, flags=re.M)  # every #if branch
        body = _UNITY_POSITION.sub(r"float4 \1 : SV_POSITION", body)
        for decl in body.split(";"):
            # macro members without a ';' of their own (UNITY_FOG_COORDS(1), UNITY_VERTEX_OUTPUT_STEREO)
            # lead the member written after them: cut them off so that member is read
            decl = _LEADING_MACROS.sub("", decl.strip())
            if not decl or "(" in decl:  # a macro (UNITY_FOG_COORDS(1), SHADOW_COORDS(2)): no member here
                continue
            semantic = ""
            sm = re.search(r":\s*(\w+)\s*$", decl)
            if sm:
                semantic, decl = sm.group(1), decl[:sm.start()].strip()
            all_words = decl.replace(",", " , ").split()
            # interpolation modifiers lead; a member named as one (``half3 sample``) is a name
            words = all_words[_leading(all_words, ("nointerpolation", "linear", "centroid", "noperspective", "sample")):]
            if len(words) < 2:
                continue
            kind, names = words[0], [w for w in words[1:] if w != ","]
            array = re.fullmatch(r"(" + IDENT + r")\s*\[\s*(\d+)\s*\]", "".join(names))
            if array and semantic:
                # ``half2 uv[9] : TEXCOORD0``: one varying per element, at consecutive semantics
                # (TEXCOORD0 .. TEXCOORD8; Microsoft's HLSL reference, "Semantics")
                base = re.fullmatch(r"(\D*?)(\d*)", semantic)
                first = int(base.group(2) or 0)
                names = [f"{array.group(1)}[{k}]" for k in range(int(array.group(2)))]
                members.extend((kind, n, f"{base.group(1)}{first + k}") for k, n in enumerate(names))
            elif kind in out and not array:
                # a member of an earlier struct's type: its leaves, flattened
                leaves = _leaves(out[kind], names, semantic)
                members.extend(leaves)
                flat.update(n for _, n, _ in leaves if "nointerpolation" in all_words
                            or n.split(".", 1)[1] in out[kind].flat)
                continue
            else:
                members.extend((kind, n, semantic) for n in names)
            if "nointerpolation" in all_words:
                flat.update(names)
        out[m.group(1)] = M.ShaderStruct(m.group(1), members, frozenset(flat))
    return out


# HLSL's and Cg's built-in scalar, vector and matrix types (float, half3, fixed4x4, uint2, ...).
_BUILTIN_TYPE = re.compile(r"(?:void|bool|int|uint|dword|half|float|double|fixed|min16float|min10float|min16int|"
                           r"min16uint)(?:[1-4](?:x[1-4])?)?")


# `#define MY_V2F v2f_full`: an object-like #define naming one word, a type's alias a signature may use
_TYPE_ALIAS = re.compile(r"^[ \t]*#[ \t]*define[ \t]+(" + IDENT + r")[ \t]+(" + IDENT + r")[ \t]*$", re.M)


def _dealiased(found: dict, text: str) -> dict:
    """``found``'s signatures with each type that is a #define alias (``float4 frag(MY_V2F i)``
    after ``#define MY_V2F v2f_full``) the type it names, as the preprocessor reads it (a chain
    followed to its end, a cycle left as written)."""
    aliases = dict(_TYPE_ALIAS.findall(text))

    def kind(name: str) -> str:
        seen = {name}
        while name in aliases and aliases[name] not in seen:
            name = aliases[name]
            seen.add(name)
        return name
    return {role: (kind(ret), [(q, kind(t), n, s) for q, t, n, s in params], semantic, start)
            for role, (ret, params, semantic, start) in found.items()}


def _undefined_type(found: dict, structs: dict, functions: dict):
    """(type, function) of the first type the vertex or fragment signature names that is neither
    a built-in type nor a struct the program (with its includes) defines; None when all are."""
    for role in ("vertex", "fragment"):
        kind, params, _, _ = found[role]
        for name in [kind] + [p[1] for p in params]:
            if name not in structs and not _BUILTIN_TYPE.fullmatch(name):
                return name, functions[role]
    return None


def _unresolved_include(program: str, folder: Path):
    """(name, offset) of the first ``#include`` of ``program`` that neither the shader's folder
    nor pbrlab's stand-ins hold (None when every one resolves)."""
    for m in INCLUDE.finditer(blank_comments(program)):
        if resolve_included(m.group(1), folder) is None:
            return m.group(1), m.start()
    return None


def _arguments(pragma: str, text: str) -> list:
    """A ``#pragma``'s arguments, as words; a stage's function name is the identifier that opens
    them, so ``#pragma fragment frag;`` (a semicolon after the name, as a C statement ends) names
    frag: Unity's preprocessor reads a pragma's arguments as preprocessing tokens, of which the
    identifier and ';' are two (C99 6.4; HLSL's preprocessor is C's), and two sampled projects
    (a URP port of a shader book's edge detection, a course's sun shader) write it so and draw."""
    words = text.split()
    if pragma in _STAGES and words:
        words[0] = re.match(r"\w*", words[0]).group(0) or words[0]
    return words


def parse_pass(program: str, path: Path, first_line: int, block, spellings=(), keywords=(),
               notes: list | None = None, srp: bool = False) -> M.VertexFragmentPass:
    """``spellings``: the pipeline's (parse.Pipeline.spellings), already applied to ``program``
    and applied here to the files it includes (the functions and structs they define);
    ``keywords``: the pipeline's (parse.Pipeline.keywords), on where the program declares them,
    as when it is drawn (a varying under ``#ifdef _ADDITIONAL_LIGHTS`` is one of its stages');
    ``notes``: gets a line for each macro the shader defines again (macro_redefinitions.py)."""
    masked = blank_comments(program)
    check_refusals(program, path, first_line, path.parent)
    everything = masked + "\n" + respelled(included_text(program, path.parent), spellings)
    on = [k for k in keywords if k in declared_keywords(program)
          or (k == "LIGHTMAP_ON" and declares_lightmap_on(program))  # a lightmapped object's (lightmaps.py)
          or (k == "DYNAMICLIGHTMAP_ON" and declares_dynamic_lightmap_on(program))  # (dynamic_lightmaps.py)
          or (k == "LIGHTPROBE_SH" and declares_light_probe_sh(program))]  # no lightmap's (light_probes.py)
    defines = defines_of(everything, on, srp)  # (srp: a Scriptable Render Pipeline's program)
    if srp:  # the stand-ins' branches for the names the shader defines or reads (user_definitions.py)
        defines.update(text_defines(program, path.parent))
    everything = active_text(everything, defines)  # the drawn variant's branches
    # a global only Unity's engine sets: filled from the scene where the program declares it
    # (engine_inputs.FILLED; a geometry stage's text is built apart and gets none), else refused
    drawn_text, filled = fill_declared(program, everything[:len(masked)], everything[len(masked):])
    staged = {m.group(1) for m in _PRAGMA.finditer(masked)}
    if filled and not staged & set(_APART):
        program = drawn_text
    else:
        filled = ()
    check_engine_inputs(everything[:len(masked)], path, first_line, filled)
    check_compute_buffers(everything[:len(masked)], path, first_line)  # data only the application has
    check_included_compute_buffers(everything[:len(masked)], everything[len(masked):], program, path.parent)
    written, rewritten = (), {}
    # globals the program writes (a geometry function's too: anohis's Blocking; geometry_stage sets the copies)
    program, written = copied_written_globals(program, active_text(blank_comments(program), defines))
    rewritten, in_includes = copied_in_includes(program, path.parent, defines)  # or its own includes
    written += in_includes
    # (a global of the program's that one of its own includes writes)
    program, rewritten, across = copied_across_includes(program, path.parent, defines, rewritten, written)
    written += across
    program, rewritten = renamed_in_own_files(program, path.parent, rewritten)  # Unity's functions defined again
    program, rewritten, redefined = undefined_before_redefinition(program, path, first_line, rewritten)  # FXC's warning
    if notes is not None:
        notes.extend(redefined)
    program, dropped = dropped_printf_calls(program, path, first_line)  # HLSL's shader messages
    if notes is not None:
        notes.extend(dropped)

    def where(index: int) -> str:
        return f"{path}:{first_line - 1 + line_of(program, min(index, len(program)))}"

    pragmas = {}
    for m in _PRAGMA.finditer(masked):
        pragmas.setdefault(m.group(1), (_arguments(m.group(1), m.group(2)), m.start()))
    # A stage's #pragma in a file the program includes (SRLS's `#pragma fragment frag` in its
    # Core.hlsl): Unity's shader compiler reads #pragma directives in include files since its
    # caching preprocessor (Unity 2020.1 on, the only one from 2021.2; manual, "HLSL pragma
    # directives reference"). Only the stage names are taken from there, placed at the
    # program's first line; the program's own pragma wins.
    for m in _PRAGMA.finditer(everything[len(masked):]):
        if m.group(1) in _STAGES and m.group(1) not in pragmas and m.group(2).split():
            pragmas[m.group(1)] = (_arguments(m.group(1), m.group(2)), 0)
    if "surface" in pragmas:
        raise UnityShaderError(f"{where(pragmas['surface'][1])}: #pragma surface inside a Pass: Unity "
                               "allows surface programs only directly in a SubShader")
    if ("hull" in pragmas) != ("domain" in pragmas):
        given, missing = ("hull", "domain") if "hull" in pragmas else ("domain", "hull")
        raise UnityShaderError(f"{where(pragmas[given][1])}: #pragma {given} without #pragma {missing}: "
                               "tessellation needs both a hull and a domain function")
    if "vertex" not in pragmas or "fragment" not in pragmas:
        missing = "vertex" if "vertex" not in pragmas else "fragment"
        raise UnityShaderError(f"{where(0)}: a Pass program needs #pragma vertex and #pragma fragment "
                               f"(no #pragma {missing})")
    vertex, fragment = pragmas["vertex"][0][0], pragmas["fragment"][0][0]
    found = {}
    for role, name in (("vertex", vertex), ("fragment", fragment)):
        sig = _function_signature(everything, name, where) or _function_signature(UNITY_CG_FUNCTIONS, name, where)
        if sig is None:
            unresolved = _unresolved_include(program, path.parent)
            if unresolved:  # most likely where the function lives: name the file, not the function
                raise UnityShaderError(f"{where(unresolved[1])}: uses {unresolved[0]}, {missing_include(unresolved[0], path.parent)}; "
                                       "pbrlab does not provide it "
                                       f"(#pragma {role} {name} names a function none of the rest defines)")
            raise UnityShaderError(f"{where(pragmas[role][1])}: #pragma {role} {name}: no function {name}(...) "
                                   "is defined")
        found[role] = sig
    found = _dealiased(found, everything)
    structs = _structs(UNITY_CG_FUNCTIONS + "\n" + everything)  # the program's own struct of a name wins
    undefined = _undefined_type(found, structs, {"vertex": vertex, "fragment": fragment})
    # (an include of the drawn variant: one under a branch not taken is not read)
    unresolved = _unresolved_include(everything[:len(masked)], path.parent) if undefined else None
    if unresolved:  # a struct the signatures name that an include pbrlab lacks defines (URP's 2D shadows')
        raise UnityShaderError(f"{where(unresolved[1])}: uses {unresolved[0]}, {missing_include(unresolved[0], path.parent)}; "
                               f"pbrlab does not provide it ({undefined[1]}() takes or gives "
                               f"{undefined[0]}, a type none of the rest defines)")
    geometry = (parse_geometry(everything, pragmas["geometry"][0][0], where, pragmas["geometry"][1])
                if "geometry" in pragmas else None)
    tessellation = (parse_tessellation(everything, pragmas["hull"][0][0], pragmas["domain"][0][0], structs, where,
                                       (pragmas["hull"][1], pragmas["domain"][1])) if "hull" in pragmas else None)
    vf = M.VertexFragmentPass(
        path=path, name=block.name, light_mode=block.light_mode or "Always",
        program=program, program_line=first_line, vertex=vertex, fragment=fragment,
        vertex_params=found["vertex"][1], vertex_return=found["vertex"][0],
        vertex_return_semantic=found["vertex"][2],
        fragment_params=found["fragment"][1], fragment_return=found["fragment"][0],
        fragment_return_semantic=found["fragment"][2], structs=structs, geometry=geometry, tessellation=tessellation,
        engine_filled=filled,
        written_globals=written, rewritten_includes=rewritten)
    vf.declared = declared_globals(everything)
    return vf
