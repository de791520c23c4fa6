"""Imports run only downward (issue 27, STYLE 14): every import of every pbrlab module, read
from its source with ``ast`` (module level, function level and class level alike; only
``if TYPE_CHECKING:`` blocks, which never run, are left out), goes to a module of the same
layer or a lower one of ``pbrlab.layers.LAYERS``. Reading the source rather than importing
it catches the lazy imports too, which an import-time check would only see when they run."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

import pbrlab
from pbrlab import layers

PACKAGE = Path(pbrlab.__file__).resolve().parent
DOCS = Path(__file__).resolve().parents[2] / "docs" / "layers.md"


def _modules() -> dict[str, Path]:
    """Module name in the package (``render``, ``unity.parse``, ``__init__``) -> file."""
    found = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE).with_suffix("").parts
        if parts[-1] == "__init__" and len(parts) > 1:
            parts = parts[:-1]
        found[".".join(parts)] = path
    return found


MODULES = _modules()


def _is_type_checking(node: ast.If) -> bool:
    test = node.test
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or \
        (isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _walk(node):
    """Every node under ``node`` except the bodies of ``if TYPE_CHECKING:``."""
    for child in ast.iter_child_nodes(node):
        if isinstance(child, ast.If) and _is_type_checking(child):
            yield from (n for part in child.orelse for n in [part, *_walk(part)])
            continue
        yield child
        yield from _walk(child)


def _resolve(name: str) -> str | None:
    """The package's module that an imported dotted name (without ``pbrlab.``) is or is in:
    ``render.render_scene`` -> ``render``; a name of the package itself -> ``__init__``."""
    parts = name.split(".") if name else []
    for end in range(len(parts), 0, -1):
        candidate = ".".join(parts[:end])
        if candidate in MODULES:
            return candidate
    return "__init__"


def imports_of(module: str, source: str | None = None) -> list[tuple[int, str]]:
    """(line, module of the package) for each import in ``module``'s source (its file's,
    unless ``source`` is given)."""
    path = MODULES[module]
    is_package = path.name == "__init__.py"
    package = module.split(".") if is_package and module != "__init__" else module.split(".")[:-1]
    found = []
    source = path.read_text(encoding="utf-8") if source is None else source
    for node in _walk(ast.parse(source)):
        names = []
        if isinstance(node, ast.Import):
            names = [a.name[len("pbrlab."):] if a.name.startswith("pbrlab.") else "" if a.name == "pbrlab" else None
                     for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - (node.level - 1)]
                stem = ".".join(base + ([node.module] if node.module else []))
            elif node.module == "pbrlab" or (node.module or "").startswith("pbrlab."):
                stem = node.module[len("pbrlab."):] if node.module != "pbrlab" else ""
            else:
                continue
            # `from . import x` imports the module x when there is one, else a name of the package
            names = [f"{stem}.{a.name}".lstrip(".") if f"{stem}.{a.name}".lstrip(".") in MODULES else stem
                     for a in node.names]
        for name in names:
            if name is None:
                continue
            target = _resolve(name)
            if target != module and not module.startswith(target + "."):  # a package's own modules
                found.append((node.lineno, target))
    return found


def test_every_module_is_in_exactly_one_layer():
    entries = [name for _, modules in layers.LAYERS for name in modules]
    assert len(entries) == len(set(entries)), "a module listed twice in pbrlab.layers.LAYERS"
    for name in entries:
        assert name in MODULES, f"pbrlab.layers.LAYERS names {name}, which is no module of pbrlab"
    missing = [m for m in MODULES if "." not in m and m not in entries]
    assert not missing, f"top-level modules in no layer of pbrlab.layers.LAYERS: {missing}"


def upward_imports(sources: dict[str, str] | None = None) -> list[str]:
    """``file:line: module (layer) imports module (layer)`` for each import against the
    layers; ``sources`` replaces the text of some modules (the control below)."""
    upward = []
    for module in MODULES:
        level = layers.layer_of(module)
        for line, target in imports_of(module, (sources or {}).get(module)):
            if layers.layer_of(target) > level:
                upward.append(f"pbrlab/{MODULES[module].relative_to(PACKAGE)}:{line}: {module} "
                              f"({layers.LAYERS[level][0]}) imports {target} "
                              f"({layers.LAYERS[layers.layer_of(target)][0]})")
    return upward


def test_imports_run_only_downward():
    upward = upward_imports()
    assert not upward, "imports against the layers (docs/layers.md):\n" + "\n".join(upward)


def test_the_check_sees_function_level_and_relative_imports():
    """A control: the reader finds the imports an upward one would hide behind."""
    assert "render" in {target for _, target in imports_of("commands.render")}  # lazy, in run()
    scene_imports = {target for _, target in imports_of("scene")}
    assert "gltf" not in scene_imports  # the scene model is handed the glTF reader (scene_files)
    assert {"scene", "gltf"} <= {target for _, target in imports_of("scene_files")}


def test_an_upward_import_is_reported():
    """The check fails where it should: a foundation module that imported the renderer lazily."""
    errors = MODULES["errors"].read_text(encoding="utf-8")
    lazy = errors + "\n\ndef f():\n    from .render import render_scene\n"
    assert (errors.count("\n") + 4, "render") in imports_of("errors", lazy)
    assert any("errors (foundation) imports render (rendering)" in line
               for line in upward_imports({"errors": lazy}))


def test_the_docs_page_names_every_layer_and_module():
    page = DOCS.read_text(encoding="utf-8")
    for name, modules in layers.LAYERS:
        assert name in page, f"docs/layers.md does not describe the layer {name!r}"
        for module in modules:
            assert f"`{module}`" in page, f"docs/layers.md does not place `{module}`"
