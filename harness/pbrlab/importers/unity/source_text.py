"""The shader's text as the Unity front end reads it, before any model: the bottom of the
pipeline (the package's docstring), importing no other Unity module (but vendored_library, a leaf).

Comments blanked with offsets and line numbers kept (``blank_comments``, ``line_of``), braces
matched (``matching_brace``), the text at brace depth 0 (``top_level``), an identifier
(``IDENT``), a Cg/GLSL type name's component count (``component_count``); ``#include`` lines
resolved as Unity resolves them here, the shader's folder first, then pbrlab's stand-ins for
Unity's include files (``CGINC``: ``resolve_included``, ``included_text``); what those stand-ins
refuse, by ``#error`` (``check_refusals``) or by keyword (``refused_keywords``); the keywords a
program's ``#pragma multi_compile`` / ``shader_feature`` lines declare (``declared_keywords``);
the first line of a ``port-unity`` port (``PORT_MARKER``); and ``UnityShaderError``, the front
end's one error.
"""

from __future__ import annotations

import functools
import json
import re
from pathlib import Path

from ...foundation import safe_paths
from ...foundation.errors import PbrlabError
from . import vendored_library  # (a leaf: it imports no Unity module)

# pbrlab's stand-ins for Unity's include files (UnityCG.cginc, Lighting.cginc, ...).
CGINC = Path(__file__).parent / "cginc"
# pbrlab's stand-ins for files of Unity's packages (``#include "Packages/<package>/..."``): the
# Universal Render Pipeline's ShaderLibrary (importers/urp/ reads URP shaders), below this folder
# by their package paths; it is an include folder of its own.
PACKAGE_STAND_INS = Path(__file__).parent / "package_stand_ins"

PORT_MARKER = "// pbrlab port-unity:"  # port.py writes it first; the text is then GLSL


class UnityShaderError(PbrlabError):
    """A Unity shader the front end cannot run as Unity would; the message says where."""


_COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)
IDENT = r"[A-Za-z_]\w*"


@functools.lru_cache(maxsize=256)
def blank_comments(text: str) -> str:
    """Comments replaced by spaces, newlines kept (offsets and line numbers survive). Kept for
    the texts seen last: every pass of a shader blanks its includes' texts again (a 256-pass
    shader: 69 calls a pass, a quarter of reading it); a text is a str, never changed."""
    return _COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def line_of(text: str, index: int) -> int:
    return text.count("\n", 0, index) + 1


def matching_brace(text: str, open_index: int, opening: str = "{", closing: str = "}") -> int:
    """The offset of the ``closing`` that closes the ``opening`` at ``open_index``; -1 when
    none does."""
    depth = 0
    for i in range(open_index, len(text)):
        if text[i] == opening:
            depth += 1
        elif text[i] == closing:
            depth -= 1
            if depth == 0:
                return i
    return -1


def call_arguments(code: str, start: int):
    """(the arguments, the offset after ``)``) of a call whose ``(`` is at ``start``, split at
    top-level commas (a call may span lines); None when the parentheses do not close."""
    depth, args, begin = 0, [], start + 1
    for i in range(start, len(code)):
        c = code[i]
        if c == "#" and code[code.rfind("\n", 0, i) + 1:i].strip() == "":
            return None  # a preprocessor line inside: not a call this rule reads
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
            if depth == 0:
                args.append(code[begin:i].strip())
                return args, i + 1
        elif c == "," and depth == 1:
            args.append(code[begin:i].strip())
            begin = i + 1
    return None


def matching_paren(text: str, open_index: int) -> int:
    """The offset of the ``)`` that closes the ``(`` at ``open_index``; -1 when none does."""
    return matching_brace(text, open_index, "(", ")")


# A global declaration's name. A line's leading blanks are [^\S\n]*, not \s*: under re.M, \s* at
# each of K empty lines in a row (a function body top_level blanked, the ShaderLab between a
# pass and its file's CGINCLUDE) runs over all the rest of them, O(K^2) a text; the names found
# are the same (a match starting lines earlier starts again at its first word's line).
_GLOBAL_DECLARATION = re.compile(r"^[^\S\n]*(?:uniform\s+)?(?:static\s+)?(?:const\s+)?\w+\s+(" + IDENT
                                 + r")\s*(?:=[^;]*)?;", re.M)


def declared_globals(masked: str) -> frozenset:
    """The names of the global variables ``masked`` (comments blanked) declares."""
    return frozenset(_GLOBAL_DECLARATION.findall(top_level(masked)))


def top_level(masked: str) -> str:
    """Only the text at brace depth 0 (global declarations)."""
    out, depth = [], 0
    for ch in masked:
        if ch == "{":
            depth += 1
        if depth == 0 or ch == "\n":
            out.append(ch)
        if ch == "}":
            depth -= 1
            out.append(" ")
    return "".join(out)


_SIZE = {"": 1, "2": 2, "3": 3, "4": 4}


def component_count(kind: str) -> int:
    m = re.fullmatch(r"(?:float|half|fixed|int|uint|bool|min16float|real)([234]?)", kind)
    if m:
        return _SIZE[m.group(1)]
    m = re.fullmatch(r"[iub]?vec([234])", kind)  # a port-unity port's GLSL types
    return int(m.group(1)) if m else (1 if kind in ("float", "int", "uint", "bool") else 0)



# (``#include"x.hlsl"``, no blank before the name: the C preprocessor and FXC take it)
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"', re.M)
# A stand-in's refusal: an unconditional `#error "..."` line (cginc/SpeedTree*.cginc).
_ERROR = re.compile(r'^[ \t]*#[ \t]*error[ \t]+"?([^"\n]*)"?[ \t]*$', re.M)
_CONDITIONAL = re.compile(r"^[ \t]*#[ \t]*(if|ifdef|ifndef|endif)\b", re.M)


class UnityShaderWarning(UserWarning):
    """Something a surface shader asks for that the harness does not do (named in the text)."""


class UnityShaderNote(UnityShaderWarning):
    """What the harness chose for a shader: the SubShader that runs, a pass it skips, a Fallback."""


class UnityIncludeRefusal(UnityShaderError):
    """A shader includes one of pbrlab's stand-ins that refuses (Unity data the harness lacks):
    no SubShader or Fallback can help, so it is raised as it stands."""


def resolve_included(name: str, folder: Path, copies: bool = True):
    """The file ``#include "name"`` reads, as Unity resolves it here: the including file's
    folder first, then, for a package path (``Packages/...``), pbrlab's stand-ins for Unity's
    packages' files (before a copy of the package the project embeds: vendored_library), then
    the project's root and pbrlab's stand-ins for Unity's include files (``cginc/``); else None. A name that starts
    with ``/`` is read from the including file's folder, as Unity reads it (include_separators).
    A project's copy of a file of Unity's render-pipeline ShaderLibrary resolves to pbrlab's
    stand-in for it (vendored_library), unless ``copies`` is False (the file itself)."""
    name = name.lstrip("/")
    candidates = [(folder, folder / name)]  # (the user's folder it lies in, or None: pbrlab's own)
    if name.startswith("Packages/"):  # (before the project's own Packages/: the HLSL path's order too)
        candidates.append((None, PACKAGE_STAND_INS / name))
    root = project_root(name, folder)
    if root is not None:
        candidates.append((root, root / name))
    own = own_package_root(name, folder)
    if own is not None:
        candidates.append((own[1], own[1] / name.split("/", 2)[2]))
    candidates.append((None, CGINC / Path(name).name))
    for user_folder, candidate in candidates:
        if candidate.is_file():
            if user_folder is not None:  # read only through links that stay in the folder (safe_paths)
                safe_paths.inside(user_folder, name, f'#include "{name}" in {folder}', climb=True)
                if copies:
                    return vendored_library.stand_in_for(candidate, PACKAGE_STAND_INS) or candidate
            return candidate
    return None


# Include paths Unity resolves from the project's root: its assets and its packages.
_PROJECT_PATH = ("Assets/", "Packages/")


def project_root(name: str, folder: Path) -> Path | None:
    """For an include written as a project path (``Assets/...``, ``Packages/...``), the
    nearest folder at or above ``folder`` that holds it (the Unity project's root), else None."""
    if not name.startswith(_PROJECT_PATH):
        return None
    for ancestor in [folder, *folder.parents]:
        if (ancestor / name).is_file():
            return ancestor
    return None


def missing_project_file(name: str, folder: Path) -> str:
    """Why ``#include "Assets/..."`` (``name``) found nothing from ``folder``: Unity reads such a
    path from the project's root, the folder that holds ``Assets/`` (Unity's ScriptReference,
    ShaderIncludePathAttribute: shader libraries must lie under the Assets folder or in a
    package, included by their project paths), which project_root looks for at and above the
    including file's folder."""
    root = next((a for a in [folder, *folder.parents] if (a / "Assets").is_dir()), None)
    if root is None:
        return (f"Unity reads an Assets/ path from the Unity project's root (the folder that holds Assets/), "
                f"and no folder at or above {folder} holds an Assets/ folder: the shader lies outside its "
                "project, whose file this is")
    return f"Unity reads an Assets/ path from the Unity project's root, here {root}, which has no {name}"


def own_package_root(name: str, folder: Path):
    """For ``Packages/<package>/<rest>`` written in a file of that package itself (Unity maps
    ``Packages/<package>/`` to the package's folder, wherever the package lies), (package, the
    package's folder): the nearest folder at or above ``folder`` whose package.json names the
    package, or else (a package copied without its package.json) the nearest that holds
    ``<rest>``; None for Unity's own packages (com.unity.*: pbrlab's stand-ins), for other
    paths, and where a project folder holds the path (project_root)."""
    parts = name.split("/", 2)
    if len(parts) < 3 or parts[0] != "Packages" or parts[1].startswith("com.unity.") or not parts[2]:
        return None
    package, rest = parts[1], parts[2]
    ancestors = [folder, *folder.parents]
    if any((a / name).is_file() for a in ancestors):
        return None
    for ancestor in ancestors:
        try:
            named = json.loads((ancestor / "package.json").read_text(encoding="utf-8")).get("name")
        except (OSError, ValueError, AttributeError):
            continue
        if named == package:
            return (package, ancestor) if (ancestor / rest).is_file() else None
    for ancestor in ancestors:
        if (ancestor / rest).is_file():
            return package, ancestor
    return None


def read_source(path: Path) -> str:
    """A Unity source file's text (a .shader, .cginc, .hlsl), without its byte-order mark.
    Unity's editor writes UTF-8, but files saved in a legacy code page (comments in Korean
    CP949, Chinese GBK, Windows-1252...) compile in Unity: its compilers read bytes, and such
    bytes sit in comments. A file that is not UTF-8 is read byte for byte (Latin-1: one
    character a byte, so lines and columns keep their numbers), with a note naming the file and
    the line of its first such byte. Windows line ends (CR LF) are read as LF: one line each
    either way, and the Cg type pass reads a line's end as LF only: a macro continued by a backslash
    before CR LF kept Tessellation.hlsl's ``patch`` from its GLSL rename. OSError is the caller's."""
    data = Path(path).read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        import warnings
        line = data.count(b"\n", 0, exc.start) + 1
        warnings.warn(f"{path}:{line}: not UTF-8 (byte 0x{data[exc.start]:02x}, a legacy code page's); "
                      "read byte for byte, as Unity's compilers read it", UnityShaderNote, stacklevel=2)
        # byte 0x85 (a Shift-JIS trail byte: "ュ" is 83 85) is Latin-1's NEL, which Python's
        # str.splitlines takes for a line break where a compiler reads a byte: a comment split
        # there put the rest of its line into the code. Read as "?" (a byte only a comment
        # holds: FXC refuses it in code as it refuses "?" there), one character still.
        text = data.decode("latin-1").replace("\x85", "?")
    return plain_includes(text.removeprefix("\ufeff").replace("\r\n", "\n"))


# Unity 2022's ``#include_with_pragmas "file"``: an #include whose file's #pragma lines count as
# the pass's (Unity's manual, "Declaring and using shader keywords": include_with_pragmas); the
# compilers know only #include. Every file read is spelled so, blanks keeping its columns
# (a ``#pragma`` of the file is read where the pass's are, or is the compiler's to ignore).
_INCLUDE_WITH_PRAGMAS = re.compile(r"^([ \t]*#[ \t]*)include_with_pragmas\b", re.M)
INCLUDE_WITH_PRAGMAS = "include_with_pragmas"


# ``#include <UnityInstancing.cginc>``: Unity's compiler reads an include named in angle brackets
# as it reads a quoted one (the including file's folder, then Unity's CGIncludes: the built-in
# shaders' own UnityCG.cginc includes its siblings either way); pbrlab's expander and glslang's
# -I search take quoted names only. Every file read is spelled with quotes (offsets kept).
_ANGLE_INCLUDE = re.compile(r'^([ \t]*#[ \t]*include[ \t]*)<([^<>"\n]+)>', re.M)


def plain_includes(text: str) -> str:
    """``text`` with each ``#include_with_pragmas`` line an ``#include`` line and each include's
    name in angle brackets quoted (offsets kept)."""
    pad = " " * (len(INCLUDE_WITH_PRAGMAS) - len("include"))
    text = _INCLUDE_WITH_PRAGMAS.sub(lambda m: m.group(1) + "include" + pad, text)
    return _ANGLE_INCLUDE.sub(lambda m: f'{m.group(1)}"{m.group(2)}"', text)


def includes_respelled(path: Path) -> bool:
    """Whether ``read_source`` spells an include line of the file otherwise than written
    (``plain_includes``): glslang, reading the file itself, needs the spelled copy."""
    raw = Path(path).read_bytes().decode("latin-1")
    return plain_includes(raw) != raw


def _read_include(path: Path):
    try:
        return read_source(path)
    except OSError:
        return None


def stand_in_refusal(text: str) -> str | None:
    """The message of a ``#error`` line outside every #if of ``text`` (None if there is none)."""
    masked = blank_comments(text)
    depth = 0
    for m in sorted([*_CONDITIONAL.finditer(masked), *_ERROR.finditer(masked)], key=lambda m: m.start()):
        if m.re is _ERROR:
            if depth == 0:
                return m.group(1).strip()
            continue
        depth += -1 if m.group(1) == "endif" else 1
    return None


def check_refusals(program: str, path: Path, first_line: int, folder: Path, seen=None) -> None:
    """Raise ``UnityIncludeRefusal`` at the shader's ``#include`` line when what it includes
    (directly or further down) is a stand-in that refuses with ``#error``."""
    seen = set() if seen is None else seen
    for m in INCLUDE.finditer(blank_comments(program)):
        target = resolve_included(m.group(1), folder)
        if target is None and m.group(1).startswith("Assets/"):
            line = first_line - 1 + line_of(program, m.start())
            raise UnityIncludeRefusal(f'{path}:{line}: #include "{m.group(1)}": '
                                      + missing_project_file(m.group(1), folder))
        if target is None or target.resolve() in seen:
            continue
        seen.add(target.resolve())
        text = _read_include(target)
        if text is None:
            continue
        line = first_line - 1 + line_of(program, m.start())
        ours = target.parent.resolve() == CGINC.resolve() or target.resolve().is_relative_to(PACKAGE_STAND_INS.resolve())
        message = stand_in_refusal(text) if ours else None
        if message:
            raise UnityIncludeRefusal(f'{path}:{line}: #include "{m.group(1)}": {message}')
        try:
            check_refusals(text, path, first_line, target.parent, seen)
        except UnityIncludeRefusal as exc:  # found further down: name this line of the shader
            raise UnityIncludeRefusal(f'{path}:{line}: #include "{m.group(1)}" -> '
                                      + str(exc).split(": ", 1)[1]) from None


_DEFINE_LINE = re.compile(r"^[ \t]*#[ \t]*define\b")


def respelled(text: str, spellings) -> str:
    """``text`` with a pipeline's spellings (parse.Pipeline.spellings: ``(pattern, replacement)``)
    applied on every line but a ``#define``'s (a stand-in's ``#define FRONT_FACE_TYPE bool``
    stays the definition it is); lines are kept."""
    if not spellings:
        return text
    out = []
    for line in text.splitlines(keepends=True):
        if not _DEFINE_LINE.match(line):
            for pattern, replacement in spellings:
                line = pattern.sub(replacement, line)
        out.append(line)
    return "".join(out)


def included_files(program: str, folder: Path, seen=None) -> dict:
    """{resolved path: text, comments blanked} of the files ``program`` includes (recursively,
    resolved as ``included_text`` resolves them), in the order ``included_text`` reads them."""
    seen = {} if seen is None else seen
    for name in INCLUDE.findall(blank_comments(program)):
        candidate = resolve_included(name, folder)
        if candidate is None or candidate.resolve() in seen:
            continue
        text = _read_include(candidate)
        seen[candidate.resolve()] = "" if text is None else blank_comments(text)
        if text is not None:
            included_files(text, candidate.parent, seen)
    return seen


def included_text(program: str, folder: Path, seen=None, resolve=None) -> str:
    """The text of the files ``program`` includes (recursively; the shader's folder first, then
    pbrlab's stand-ins for Unity's includes), comments blanked: where the model looks for a
    struct Input, a vertex: or Lighting<Name> function defined in an include. ``resolve(name,
    folder)`` finds each include (resolve_included unless given: the GLSL port's also looks in the
    shader's own folder, program.included_from)."""
    seen = set() if seen is None else seen
    resolve = resolve_included if resolve is None else resolve
    out = []
    for name in INCLUDE.findall(blank_comments(program)):
        candidate = resolve(name, folder)
        if candidate is None or candidate.resolve() in seen:
            continue
        seen.add(candidate.resolve())
        text = _read_include(candidate)
        if text is None:
            continue
        out.append(blank_comments(text))
        out.append(included_text(text, candidate.parent, seen, resolve))
    return "\n".join(out)


# Keywords a stand-in of pbrlab's declares through the shader but does not honour: a material
# that enables one is refused by name (scene.py), never drawn as if it were off.
STAND_IN_REFUSED_KEYWORDS = {
    "UnityStandardCore.cginc": {
        "_SPECULARHIGHLIGHTS_OFF": "the Standard shader's Specular Highlights toggle (off: no direct "
                                   "specular) is not honoured by pbrlab's UnityStandardCore.cginc",
        # a lightmapped object's (importers/unity/lightmaps.py)
        "LIGHTMAP_ON": "a lightmapped object's GI (from its lightmap) is not drawn by pbrlab's "
                       "UnityStandardCore.cginc, which lights by the environment",
        # an object lit by realtime GI (importers/unity/dynamic_lightmaps.py)
        "DYNAMICLIGHTMAP_ON": "an object's realtime GI (from its realtime lightmap) is not drawn by pbrlab's "
                              "UnityStandardCore.cginc, which lights by the environment",
    },
    "UnityGlobalIllumination.cginc": {
        "LIGHTMAP_ON": "a lightmapped object's GI (from its lightmap) is not drawn by pbrlab's "
                       "UnityGlobalIllumination.cginc, which lights by the environment",
        "DYNAMICLIGHTMAP_ON": "an object's realtime GI (from its realtime lightmap) is not drawn by pbrlab's "
                              "UnityGlobalIllumination.cginc, which lights by the environment",
    },
    "UnityStandardParticles.cginc": {
        "SOFTPARTICLES_ON": "soft particles fade by the scene's depth in the camera's depth texture "
                            "(_CameraDepthTexture), which pbrlab does not supply",
    },
}


def refused_keywords(program: str, folder: Path, seen=None) -> dict:
    """{keyword: reason} of the stand-ins ``program`` includes (recursively) that refuse it."""
    seen = set() if seen is None else seen
    out = {}
    for name in INCLUDE.findall(blank_comments(program)):
        target = resolve_included(name, folder)
        if target is None or target.resolve() in seen:
            continue
        seen.add(target.resolve())
        if target.parent.resolve() == CGINC.resolve():
            out.update(STAND_IN_REFUSED_KEYWORDS.get(target.name, {}))
        text = _read_include(target)
        if text is not None:
            out.update(refused_keywords(text, target.parent, seen))
    return out


# `#pragma multi_compile[_local] ...` / `shader_feature[_local] ...`: the keywords a program
# declares (a material's `keywords` may enable them; `_` and `__` are Unity's "none").
_KEYWORD_PRAGMA = re.compile(r"^[ \t]*#[ \t]*pragma[ \t]+(?:multi_compile|shader_feature)(?:_local)?"
                             r"(?:_vertex|_fragment)?[ \t]+([^\n]*)$", re.M)


def spliced_lines(text: str) -> str:
    """``text`` with each backslash-newline removed, as the C preprocessor splices lines before
    it reads a directive (C99 5.1.1.2 phase 2; HLSL's preprocessor is C's): a ``#pragma
    multi_compile A \\`` line goes on with the next line's keywords. White space between the
    backslash and the line's end is taken as GCC and Clang take it (a warning, still a splice)."""
    return re.sub(r"\\[ \t]*\r?\n", "", text)


def declared_keywords(program: str) -> frozenset:
    """The keywords ``#pragma multi_compile`` / ``shader_feature`` lines of ``program`` declare."""
    words = set()
    for m in _KEYWORD_PRAGMA.finditer(spliced_lines(blank_comments(program))):
        words.update(w for w in m.group(1).split() if re.fullmatch(IDENT, w) and set(w) != {"_"})
    return frozenset(words)


# Keywords Unity's engine sets (per light, lightmap, shadow, fog, pipeline feature), never a
# material: a set holding one is the engine's to choose, not first_keywords'.
_ENGINE_KEYWORD = re.compile(r"(?:DIRECTIONAL|POINT|SPOT|POINT_COOKIE|DIRECTIONAL_COOKIE|LIGHTPROBE_SH|VERTEXLIGHT_ON|"
                             r"INSTANCING_ON|LOD_FADE_CROSSFADE|EDITOR_VISUALIZATION|DEBUG_DISPLAY|"
                             r"(?:(?:DYNAMIC)?LIGHTMAP|DIRLIGHTMAP|SHADOWS|FOG|UNITY|STEREO)_\w+|"
                             r"_(?:MAIN_LIGHT|ADDITIONAL|SHADOWS|MIXED_LIGHTING|SCREEN_SPACE|LIGHT_|REFLECTION_PROBE|"
                             r"DBUFFER|FORWARD_PLUS|CLUSTERED|GBUFFER|RENDER_PASS|WRITE_RENDERING_LAYERS)\w*)")


def keyword_sets(program: str) -> list:
    """The keyword sets of ``program``'s ``#pragma multi_compile`` / ``shader_feature`` lines, each
    a tuple of its words (``_`` and ``__`` included: Unity's "none")."""
    return [tuple(m.group(1).split()) for m in _KEYWORD_PRAGMA.finditer(spliced_lines(blank_comments(program)))
            if m.group(1).split()]


def first_keywords(program: str, enabled=()) -> tuple:
    """The keyword Unity draws for each keyword set of ``program`` none of whose keywords is
    ``enabled``: the set's first. Unity's manual ("Shader variants and keywords", "Declare
    shader keywords"): a set without ``_`` has no variant with all its keywords off, and where
    none is enabled Unity uses the first keyword's variant. A set with ``_`` (or ``__``) has that
    variant, and a one-keyword ``shader_feature`` line is short for ``_ KEYWORD``; a set of one
    ``multi_compile`` keyword, or one holding a keyword the engine sets (_ENGINE_KEYWORD), is
    left as it is."""
    out = []
    for words in keyword_sets(program):
        if (len(words) < 2 or any(set(w) == {"_"} or not re.fullmatch(IDENT, w) for w in words)
                or any(_ENGINE_KEYWORD.fullmatch(w) for w in words) or set(words) & set(enabled)):
            continue
        out.append(words[0])
    return tuple(dict.fromkeys(out))
