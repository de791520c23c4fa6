"""ShaderLab's structure, as Unity reads a ``.shader`` file: ``Shader "name" { Properties {...}
CGINCLUDE ... ENDCG  SubShader { Tags {...} LOD n  state  Pass {...}  CGPROGRAM ... ENDCG
UsePass "..."  GrabPass {...} } ... Fallback "name" | Off }``.

    layout = read_layout(text, path)      # -> ShaderLabFile
    text = layout.program_text(block)     # a program with the CGINCLUDEs Unity puts before it

Only the structure is read here: program blocks (``CGPROGRAM``/``HLSLPROGRAM``/``GLSLPROGRAM``
and the ``...INCLUDE`` blocks) are cut out first, so braces inside code never confuse the
scan; a program's text keeps the file's line numbers (``program_text`` blanks what lies
between its CGINCLUDEs and itself, keeping the newlines). Keywords are case-insensitive, as
in ShaderLab. What the blocks mean (surface program, vertex/fragment pass) is ``parse.py``'s.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from ...foundation.errors import PbrlabError
from .source_text import blank_comments, line_of

_BLOCK = re.compile(r"\b(CGPROGRAM|CGINCLUDE|HLSLPROGRAM|HLSLINCLUDE|GLSLPROGRAM|GLSLINCLUDE)\b")
_BLOCK_END = {"CG": re.compile(r"\bENDCG\b"), "HLSL": re.compile(r"\bENDHLSL\b"),
              "GLSL": re.compile(r"\bENDGLSL\b")}
_UPGRADE_WARNING = re.compile(r"^[ \t]*#warning\b[^\n]*", re.M)
_TOKEN = re.compile(r'"[^"\n]*"|[A-Za-z_][\w.]*|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|\S')
# Commands of a Pass that belong to the fixed-function pipeline (no program runs them).
FIXED_FUNCTION = frozenset(w.lower() for w in (
    "SetTexture", "Material", "Lighting", "SeparateSpecular", "ColorMaterial", "BindChannels",
    "AlphaTest", "Combine", "Color"))


# ShaderLab's commands: a command's arguments end where the next command begins (several may
# share a line: ``ZTest Always Cull Off ZWrite Off``).
COMMANDS = frozenset(w.lower() for w in (
    "Cull", "ZWrite", "ZTest", "Blend", "BlendOp", "ColorMask", "Offset", "Lighting", "Fog", "AlphaTest",
    "AlphaToMask", "Stencil", "Name", "Tags", "LOD", "Pass", "UsePass", "GrabPass", "SetTexture",
    "Material", "SeparateSpecular", "ColorMaterial", "BindChannels", "Conservative", "ZClip", "SubShader",
    "Fallback", "CustomEditor", "Properties", "Dependency", "Color"))


# Blend's factors (ShaderLab's Blend command; BlendMode's names).
BLEND_FACTORS = ("Zero", "One", "DstColor", "SrcColor", "OneMinusDstColor", "SrcAlpha",
                 "OneMinusSrcColor", "DstAlpha", "OneMinusDstAlpha", "SrcAlphaSaturate", "OneMinusSrcAlpha")


class ShaderLabError(PbrlabError):
    """A ``.shader`` file whose structure ShaderLab would not accept; the message says where."""


def blank(text: str) -> str:
    """Everything but newlines replaced by spaces (offsets and line numbers survive)."""
    return re.sub(r"[^\n]", " ", text)


def blank_gap(text: str) -> str:
    """The ShaderLab between two program blocks, as a program sees it: its newlines, then its
    last line's characters as spaces (the next block's lines and columns survive, its offsets
    do not). Not ``blank``: that keeps every character, and a pass's program starts at the
    file's first CGINCLUDE, so a file of N passes would hand its last pass the blanked text of
    the N - 1 before it (programs O(N) long, parsed N times: O(N^2))."""
    return "\n" * text.count("\n") + " " * (len(text) - 1 - text.rfind("\n"))


@dataclass
class Block:
    """A ``CGPROGRAM ... ENDCG`` (or CGINCLUDE, HLSL..., GLSL...) block."""
    keyword: str          # CGPROGRAM, CGINCLUDE, HLSLPROGRAM, ...
    start: int            # offset of the keyword
    body_start: int       # offset of the code after the keyword
    body_end: int         # offset of ENDCG
    end: int              # offset after ENDCG
    line: int             # line of body_start

    @property
    def is_include(self) -> bool:
        return self.keyword.endswith("INCLUDE")

    @property
    def language(self) -> str:
        return self.keyword[:-len("INCLUDE") if self.is_include else -len("PROGRAM")]


@dataclass
class StateCommand:
    word: str             # as written (Cull, ZWrite, Blend, ...)
    args: str             # the rest of its line ("{...}" for a block)
    line: int
    body: str = ""        # a block's text between its braces (Material { ... }, SetTexture [_T] { ... })
    body_line: int = 0    # the line of its '{' (where ``body`` starts)


@dataclass
class PassBlock:
    line: int
    name: str | None = None
    tags: dict = field(default_factory=dict)
    state: list = field(default_factory=list)       # [StateCommand]
    program: Block | None = None
    fixed_function: list = field(default_factory=list)  # [(word, line)]
    fixed_commands: list = field(default_factory=list)  # [StateCommand]: the fixed-function commands
                                                        # in order, with their blocks' text

    @property
    def light_mode(self) -> str:
        """Its LightMode tag ("" when none); tag names are case-insensitive ("LIGHTMODE")."""
        return next((v for k, v in self.tags.items() if k.lower() == "lightmode"), "")


@dataclass
class SubShaderBlock:
    line: int
    tags: dict = field(default_factory=dict)
    tag_lines: dict = field(default_factory=dict)   # tag name -> the line it is written on
    lod: int | None = None
    state: list = field(default_factory=list)
    items: list = field(default_factory=list)       # in file order: ("surface", Block),
                                                    # ("pass", PassBlock), ("usepass", name, line),
                                                    # ("grabpass", name, line)
    includes: list = field(default_factory=list)    # CGINCLUDE blocks of this SubShader


@dataclass
class ShaderLabFile:
    path: Path
    text: str
    name: str
    properties_span: tuple | None = None            # (offset of '{' + 1, offset of '}')
    properties_line: int = 0
    includes: list = field(default_factory=list)    # Shader-level CGINCLUDE blocks
    subshaders: list = field(default_factory=list)
    fallback: str | None = None                     # None: none given; "Off" as "off"
    fallback_line: int = 0
    category_state: list = field(default_factory=list)  # [StateCommand] of a Category { ... }
                                                        # (every SubShader inside reads them first)

    def program_text(self, block: Block, subshader: SubShaderBlock | None) -> tuple[str, int]:
        """(text, first line): ``block``'s code after every CGINCLUDE of its language that
        Unity puts before it (the Shader's and its SubShader's), on the file's own lines."""
        includes = [b for b in self.includes + (subshader.includes if subshader else [])
                    if b.language == block.language]
        before = [b for b in includes if b.end <= block.start]
        after = [b for b in includes if b.start > block.start]
        first = min([b.body_start for b in before] + [block.body_start])
        pieces, pos = [], first
        for b in sorted(before, key=lambda b: b.body_start) + [block]:
            pieces.append(blank_gap(self.text[pos:b.body_start]))
            pieces.append(self.text[b.body_start:b.body_end])
            pos = b.body_end
        text = "".join(pieces)
        if after:  # Unity includes them too; they come before, off their own lines
            head = "".join(self.text[b.body_start:b.body_end] + "\n" for b in after)
            text = head + f"#line {line_of(self.text, first)}\n" + text
        return text, line_of(self.text, first)


def _blocks(masked: str, path: Path) -> list[Block]:
    out, pos = [], 0
    while True:
        m = _BLOCK.search(masked, pos)
        if not m:
            return out
        keyword = m.group(1)
        language = keyword[:-7]
        end = _BLOCK_END[language].search(masked, m.end())
        if end is None:
            raise ShaderLabError(f"{path}:{line_of(masked, m.start())}: {keyword} without END{language}")
        out.append(Block(keyword, m.start(), m.end(), end.start(), end.end(), line_of(masked, m.end())))
        pos = end.end()


class _Tokens:
    """ShaderLab tokens of the masked text (program blocks cut out), with their lines."""

    def __init__(self, masked: str, path: Path, blocks: list[Block]):
        self.path = path
        self.items = []   # (text, line, offset)
        starts = {b.start: b for b in blocks}
        line, last = 1, 0
        for m in _TOKEN.finditer(masked):
            line += masked.count("\n", last, m.start())
            last = m.start()
            self.items.append((m.group(0), line, m.start()))
        self.blocks = starts
        self.i = 0
        self.masked = masked

    def peek(self, k: int = 0):
        j = self.i + k
        return self.items[j] if j < len(self.items) else (None, self.items[-1][1] if self.items else 1, -1)

    def next(self):
        tok = self.peek()
        self.i += 1
        return tok

    def where(self, line: int) -> str:
        return f"{self.path}:{line}"

    def expect(self, text: str):
        tok, line, _ = self.next()
        if tok != text:
            raise ShaderLabError(f"{self.where(line)}: expected {text!r}, got {tok!r}")

    def skip_braces(self) -> int:
        """From a '{' to after its '}'; returns the offset of that '}'."""
        self.expect("{")
        depth = 1
        while True:
            tok, line, offset = self.next()
            if tok is None:
                raise ShaderLabError(f"{self.where(line)}: a '{{' is never closed")
            depth += {"{": 1, "}": -1}.get(tok, 0)
            if depth == 0:
                return offset

    def block_body(self) -> str:
        """From a '{' to after its '}': the text between them."""
        open_at = self.peek()[2]
        return self.masked[open_at + 1:self.skip_braces()]

    def state_block(self, word: str, line: int) -> StateCommand:
        """A state command with a block (``Stencil { ... }``, ``Fog { ... }``), at its '{'."""
        body_line = self.peek()[1]
        return StateCommand(word, "{...}", line, self.block_body(), body_line)

    def rest_of_line(self, line: int) -> str:
        words = []
        while (self.peek()[0] is not None and self.peek()[1] == line and self.peek()[0] not in ("{", "}")
               and self.peek()[0].lower() not in COMMANDS and self.peek()[2] not in self.blocks):
            words.append(self.next()[0])
        return " ".join(words)

    def command_args(self, word: str, line: int) -> str:
        """A state command's arguments: the rest of its line, and for a Blend whose factors do
        not all stand on its line (``Blend SrcAlpha`` with ``OneMinusSrcAlpha`` on the next:
        ShaderLab's grammar reads tokens, not lines, and Unity takes it) the factors that open
        the lines after it."""
        args = self.rest_of_line(line)
        if word.lower() != "blend":
            return args
        factors = {f.lower() for f in BLEND_FACTORS}
        words = args.split()
        while (words and len([w for w in words if not w.isdigit()]) in (1, 3) and words[-1].lower() in factors
               and self.peek()[0] is not None and self.peek()[0].lower() in factors):
            words += self.rest_of_line(self.peek()[1]).split()
        return " ".join(words)

    def tags(self) -> dict:
        return self.tags_and_lines()[0]

    def tags_and_lines(self) -> tuple:
        """A Tags block: ({name: value}, {name: the line its name stands on})."""
        self.expect("{")
        tags, lines = {}, {}
        while self.peek()[0] not in ("}", None):
            key, line, _ = self.next()
            if self.peek()[0] == "=":
                self.next()
            value = self.next()[0]
            tags[key.strip('"')] = (value or "").strip('"')
            lines[key.strip('"')] = line
        self.expect("}")
        return tags, lines


def _string(tok: str | None) -> str | None:
    return tok[1:-1] if tok and tok.startswith('"') else None


def _pass(t: _Tokens, line: int) -> PassBlock:
    p = PassBlock(line)
    t.expect("{")
    while True:
        tok, tline, offset = t.peek()
        if tok is None:
            raise ShaderLabError(f"{t.where(line)}: Pass {{ is never closed")
        if tok == "}":
            t.next()
            return p
        if offset in t.blocks:
            block = t.blocks[offset]
            t.next()
            if block.is_include:
                raise ShaderLabError(f"{t.where(tline)}: {block.keyword} inside a Pass: Unity allows it "
                                     "in the Shader or a SubShader only")
            p.program = block
            continue
        word = tok.lower()
        t.next()
        if word == "name":
            p.name = _string(t.next()[0])
        elif word == "tags":
            p.tags = t.tags()
        elif word in FIXED_FUNCTION:
            p.fixed_function.append((tok, tline))
            args = t.rest_of_line(tline)
            body = t.block_body() if t.peek()[0] == "{" else ""
            p.fixed_commands.append(StateCommand(tok, args, tline, body))
        elif t.peek()[0] == "{":   # Stencil { ... }, Fog { ... }
            p.state.append(t.state_block(tok, tline))
        else:
            p.state.append(StateCommand(tok, t.command_args(tok, tline), tline))


def _subshader(t: _Tokens, line: int) -> SubShaderBlock:
    s = SubShaderBlock(line)
    t.expect("{")
    while True:
        tok, tline, offset = t.peek()
        if tok is None:
            raise ShaderLabError(f"{t.where(line)}: SubShader {{ is never closed")
        if tok == "}":
            t.next()
            return s
        if offset in t.blocks:
            block = t.blocks[offset]
            t.next()
            (s.includes.append(block) if block.is_include else s.items.append(("program", block)))
            continue
        word = tok.lower()
        t.next()
        if word == "tags":
            s.tags, s.tag_lines = t.tags_and_lines()
        elif word == "lod":
            value, vline, _ = t.next()
            try:
                s.lod = int(value)
            except (TypeError, ValueError):
                raise ShaderLabError(f"{t.where(vline)}: LOD takes a whole number, got {value!r}") from None
        elif word == "pass":
            s.items.append(("pass", _pass(t, tline)))
        elif word == "usepass":
            s.items.append(("usepass", _string(t.next()[0]) or "", tline))
        elif word == "grabpass":  # GrabPass { [Name "x"] [Tags {...}] ["_TextureName"] }
            t.expect("{")
            name = None
            while t.peek()[0] not in ("}", None):
                tok = t.next()[0]
                if tok.lower() == "tags":
                    t.i -= 1
                    t.next()
                    t.tags()
                elif tok.lower() == "name":
                    t.next()
                elif _string(tok) is not None:
                    name = _string(tok)
            t.expect("}")
            s.items.append(("grabpass", name or "_GrabTexture", tline))
        elif t.peek()[0] == "{":
            s.state.append(t.state_block(tok, tline))
        else:
            s.state.append(StateCommand(tok, t.command_args(tok, tline), tline))


def read_layout(text: str, path: Path) -> ShaderLabFile:
    """The structure of a ShaderLab file (``text``: the file's text, a BOM already removed)."""
    masked = blank_comments(text)
    # strings may hold '//' (a Fallback name with a slash does not): comments went first
    blocks = _blocks(masked, path)
    structure = masked
    for b in blocks:  # the code is not ShaderLab: keep only the keyword's first letter as a token
        structure = structure[:b.start] + "P" + blank(structure[b.start + 1:b.end]) + structure[b.end:]
    # Unity's shader upgrader writes ``#warning Upgrade NOTE: ...`` lines above ``Shader``
    # (observed in upgraded files, Unity imports them): a note, not structure
    structure = _UPGRADE_WARNING.sub(lambda m: blank(m.group(0)), structure)
    t = _Tokens(structure, path, blocks)
    tok, line, _ = t.next()
    if tok is None or tok.lower() != "shader":
        raise ShaderLabError(f"{path}:{line}: a .shader file starts with Shader \"name\" {{ ... }}, got {tok!r}")
    name = _string(t.next()[0])
    if name is None:
        raise ShaderLabError(f"{path}:{line}: Shader needs its name in quotes")
    layout = ShaderLabFile(path, text, name)
    t.expect("{")
    while True:
        tok, tline, offset = t.peek()
        if tok is None:
            raise ShaderLabError(f"{path}:{line}: Shader {{ is never closed")
        if tok == "}":
            return layout
        if offset in t.blocks:
            block = t.blocks[offset]
            t.next()
            if not block.is_include:
                raise ShaderLabError(f"{path}:{tline}: {block.keyword} outside a SubShader")
            layout.includes.append(block)
            continue
        word = tok.lower()
        t.next()
        if word == "properties":
            open_at = t.peek()[2]
            close_at = t.skip_braces()
            layout.properties_span = (open_at + 1, close_at)
            layout.properties_line = tline
        elif word == "subshader":
            sub = _subshader(t, tline)
            sub.state[:0] = layout.category_state   # a Category's commands come first
            layout.subshaders.append(sub)
        elif word == "fallback":
            value = t.next()[0]
            layout.fallback = "off" if (value or "").lower() == "off" else _string(value)
            layout.fallback_line = tline
            if t.peek()[0] and t.peek()[0].lower() == "off" and t.peek()[1] == tline:
                t.next()
        elif word in ("customeditor", "category"):
            if t.peek()[0] == "{":   # Category { ... } groups SubShaders: read them
                t.next()
                continue
            t.next()
        elif word == "dependency":
            t.next()
            if t.peek()[0] == "=":
                t.next()
                t.next()
        elif word == "tags" and t.peek()[0] == "{":   # a Category's tags: not the passes' state
            t.skip_braces()
        elif t.peek()[0] == "{":   # a Category's Material { ... }, Fog { ... }, BindChannels { ... }
            layout.category_state.append(t.state_block(tok, tline))
        elif word in COMMANDS:     # a Category's Blend, Cull, Lighting, ...
            layout.category_state.append(StateCommand(tok, t.command_args(tok, tline), tline))
        else:
            t.rest_of_line(tline)
