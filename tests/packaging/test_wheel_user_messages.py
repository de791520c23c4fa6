"""Every message a user can see is valid for a wheel user: a hint that names something only
a checkout has (`scripts/setup.sh`, `make test`, `make demo`) says so ("in a pbrlab
checkout") and gives what works elsewhere. Checked over the package's string literals
(docstrings aside) and its HTML templates."""

from __future__ import annotations

import ast
import re
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "harness" / "pbrlab"
CHECKOUT_ONLY = re.compile(r"scripts/setup\.sh|make (test|demo)\b")


def _docstrings(tree) -> set[int]:
    ids = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                ids.add(id(body[0].value))
    return ids


def checkout_only_hints(source: str) -> list[str]:
    """The statements whose strings name a checkout-only command without saying so."""
    tree = ast.parse(source)
    docstrings = _docstrings(tree)
    found = []
    for statement in ast.walk(tree):
        if not isinstance(statement, ast.stmt) or isinstance(statement, (ast.FunctionDef, ast.ClassDef,
                                                                         ast.AsyncFunctionDef, ast.If,
                                                                         ast.For, ast.While, ast.With, ast.Try)):
            continue
        strings = [n.value for n in ast.walk(statement)
                   if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docstrings]
        text = " ".join(strings)
        if CHECKOUT_ONLY.search(text) and "checkout" not in text:
            found.append(ast.get_source_segment(source, statement)[:200])
    return found


def test_package_messages_qualify_checkout_only_hints():
    offenders = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        hints = checkout_only_hints(path.read_text(encoding="utf-8"))
        if hints:
            offenders[str(path.relative_to(PACKAGE))] = hints
    for path in sorted((PACKAGE / "templates").glob("*.html")):
        for paragraph in path.read_text(encoding="utf-8").split("</p>"):
            if CHECKOUT_ONLY.search(paragraph) and "checkout" not in paragraph:
                offenders.setdefault(path.name, []).append(paragraph.strip()[:200])
    assert not offenders, offenders


def test_the_check_finds_an_unqualified_hint():
    assert checkout_only_hints('raise PbrlabError("glslang is missing: run scripts/setup.sh")\n')
    assert not checkout_only_hints('raise PbrlabError("apt-get install glslang-tools (in a pbrlab checkout, '
                                   'scripts/setup.sh does)")\n')
    assert not checkout_only_hints('def f():\n    """Run make test first."""\n')
