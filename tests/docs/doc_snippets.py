"""The runnable snippets of README.md and docs/: the marker, and the blocks it marks.

A fenced code block preceded (on the line just above its opening fence) by

    <!-- runs: PATH -->   is a file of the example's project, written to PATH;
    <!-- runs -->         is a shell block: its commands run in order in that project,
                          each must exit 0.

A file's block may carry ``title="PATH"`` after its language (shown by the site); it must
name the same PATH as the marker.

All runnable blocks of one document form one project. A marker not followed by a fence is
an error, so a typo cannot silently drop a snippet from the test.
"""

from __future__ import annotations

import re
import shlex
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

MARKER = re.compile(r"^<!--\s*runs(?::\s*(?P<path>\S+))?\s*-->\s*$")
FENCE = re.compile(r'^(?P<fence>```+|~~~+)\s*(?P<lang>[\w+-]*)(?:\s+title="(?P<title>[^"]*)")?\s*$')


@dataclass
class Snippet:
    line: int                # 1-based line of the opening fence
    lang: str
    text: str
    path: str | None = None  # None: a shell block


@dataclass
class Project:
    document: Path
    files: list[Snippet] = field(default_factory=list)
    shell: list[Snippet] = field(default_factory=list)

    def commands(self) -> list[list[str]]:
        """Every command of the shell blocks, in order, as argument lists (comments dropped)."""
        out = []
        for block in self.shell:
            for line in block.text.splitlines():
                words = shlex.split(line, comments=True)
                if words:
                    out.append(words)
        return out

    def write(self, where: Path) -> None:
        for snippet in self.files:
            target = where / snippet.path
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(snippet.text, encoding="utf-8")


def parse(document: Path) -> Project:
    lines = document.read_text(encoding="utf-8").splitlines()
    project = Project(document)
    i = 0
    while i < len(lines):
        marker = MARKER.match(lines[i].strip())
        if not marker:
            i += 1
            continue
        fence = FENCE.match(lines[i + 1]) if i + 1 < len(lines) else None
        if not fence:
            raise ValueError(f"{document}:{i + 1}: a runs marker must be followed by a fenced code block")
        if fence["title"] is not None and fence["title"] != marker["path"]:
            raise ValueError(f"{document}:{i + 2}: the block's title {fence['title']!r} is not the file "
                             f"its marker writes ({marker['path']!r})")
        close = fence["fence"]
        end = next((j for j in range(i + 2, len(lines)) if lines[j].strip() == close), None)
        if end is None:
            raise ValueError(f"{document}:{i + 2}: the code block is not closed")
        snippet = Snippet(i + 2, fence["lang"], "\n".join(lines[i + 2:end]) + "\n", marker["path"])
        if snippet.path is None:
            project.shell.append(snippet)
        else:
            relative = PurePosixPath(snippet.path)
            if relative.is_absolute() or ".." in relative.parts:
                raise ValueError(f"{document}:{i + 1}: {snippet.path} must be a path inside the project")
            project.files.append(snippet)
        i = end + 1
    return project
