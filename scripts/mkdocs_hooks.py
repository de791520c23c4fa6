"""MkDocs hooks of the pbrlab site (mkdocs.yml, ``hooks:``): pages generated from the code.

``library-files.md``: every GLSL file of the library (glsl/pbr/ and glsl/unity_compat/), by
folder, with its one-line summary and its header's Provides / Include / Config macros read
fields exactly as the file states them. The files are the truth; this page cannot drift from
them, since it is written from them at every build.
"""

from __future__ import annotations

import re
from pathlib import Path

from mkdocs.structure.files import File

PAGE = "library-files.md"
FIELD = re.compile(r"^// (Provides|Include|Config macros read):")
CONTINUATION = re.compile(r"^//\s{2,}\S")  # a field's next line: indented under it


def header_fields(text: str) -> tuple[str, list[str]]:
    """(the summary of the first line, the lines of the three header fields, verbatim)."""
    lines = text.splitlines()
    first = lines[0].removeprefix("//").strip()
    summary = [first.split(": ", 1)[1] if ": " in first else first]
    for line in lines[1:]:  # the summary may wrap, up to the header's empty comment line
        if line.strip() == "//" or FIELD.match(line) or not line.startswith("//"):
            break
        summary.append(line.removeprefix("//").strip())
    fields, inside = [], False
    for line in lines[1:]:
        if FIELD.match(line):
            inside = True
        elif not (inside and CONTINUATION.match(line)):
            inside = False
        if inside:
            fields.append(line)
    return " ".join(summary), fields


def library_files_page(glsl_root: Path) -> str:
    out = ["# Library files",
           "",
           "Every file of the GLSL library with the header it opens with (generated from the files at",
           "each build by `scripts/mkdocs_hooks.py`). The HLSL twins in `hlsl_ports/` have the same",
           "paths with `.hlsl` ([HLSL and engines](hlsl.md)); the naming rule, the variant selectors and",
           "the measured error of each function are on [The shader library](library.md).",
           ""]
    files = sorted(glsl_root.rglob("*.glsl"), key=lambda p: (p.parent.as_posix(), p.name))
    folder = None
    for path in files:
        relative = path.relative_to(glsl_root)
        if relative.parent != folder:
            folder = relative.parent
            out += [f"## `{folder.as_posix()}/`", ""]
        summary, fields = header_fields(path.read_text(encoding="utf-8"))
        out += [f"### `{relative.as_posix()}`", "", summary, "", "```glsl", *fields, "```", ""]
    return "\n".join(out)


def on_files(files, config):
    root = Path(config["config_file_path"]).parent
    files.append(File.generated(config, PAGE, content=library_files_page(root / "glsl")))
    return files
