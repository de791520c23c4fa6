"""GLSL text without its comments, for `pbrlab amalgamate --strip-comments`.

A comment becomes one space, as the GLSL preprocessor takes it (GLSL ES 3.00 §3.4, after
C99 §5.1.1.2 phase 3: "Each comment is replaced by one space character"), so a comment
between two tokens still separates them. Lines that held only a comment are dropped, trailing
blanks go and runs of blank lines shrink to one. Double-quoted text (the message of an
`#error`, the name of an `#include`) is kept as it is, `//` and all. The library's licence
notice (its first `// SPDX-License-Identifier:` line) opens the result, since the MIT licence
asks that copies carry it.
"""

from __future__ import annotations

import re

LICENCE_NOTICE = re.compile(r"^//\s*SPDX-License-Identifier:.*$", re.M)


def _without_comments(text: str) -> str:
    """Each comment as one space. A block comment's line breaks move to the end of the line
    it closes on, so that line k of the result still stands for line k of ``text``."""
    out, i, n, pending = [], 0, len(text), 0
    while i < n:
        if text[i] == '"':
            end = text.find('"', i + 1)
            newline = text.find("\n", i + 1)
            if end < 0 or (0 <= newline < end):  # an unclosed quote ends with its line
                end = (newline if newline >= 0 else n) - 1
            out.append(text[i:end + 1])
            i = end + 1
        elif text.startswith("//", i):
            newline = text.find("\n", i)
            i = n if newline < 0 else newline
            out.append(" ")
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            pending += text.count("\n", i, end)
            out.append(" ")
            i = end
        else:
            j = i
            while j < n and text[j] not in '"/':
                j += 1
            if j == i:  # a lone "/" (division)
                j += 1
            segment = text[i:j]
            if pending and "\n" in segment:
                segment = segment.replace("\n", "\n" * (pending + 1), 1)
                pending = 0
            out.append(segment)
            i = j
    out.append("\n" * pending)
    return "".join(out)


def strip_comments(text: str) -> str:
    """``text`` without comments, its licence notice first (see the module's docstring)."""
    notice = LICENCE_NOTICE.search(text)
    lines, blank = [], False
    for original, stripped in zip(text.split("\n"), _without_comments(text).split("\n")):
        stripped = stripped.rstrip()
        if not stripped:
            if original.strip() or blank or not lines:
                continue  # a comment-only line, or a second blank line
            blank = True
        else:
            blank = False
        lines.append(stripped)
    while lines and not lines[-1]:
        lines.pop()
    head = [notice.group(0)] if notice else []
    return "\n".join(head + lines) + "\n"
