"""The package's folders are its layers (issue 37, STYLE 14): every import of every pbrlab
module, read from its source with ``ast`` (module level, function level and class level alike;
only ``if TYPE_CHECKING:`` blocks, which never run, are left out), goes to a module of the same
layer folder or a lower one of ``pbrlab.foundation.layers.LAYERS``; no module of a layer
imports a public front; and no group of modules imports itself in a circle. Reading the source
rather than importing it catches the lazy imports too, which an import-time check would only see
when they run."""

from __future__ import annotations

import ast
from pathlib import Path

import pbrlab
from pbrlab.foundation import layers

PACKAGE = Path(pbrlab.__file__).resolve().parent
DOCS = Path(__file__).resolve().parents[2] / "docs" / "layers.md"
# The package's top: the layer folders, the fronts (__init__, __main__) and the shader
# templates it ships (issue 37: at most 12 entries).
MAX_TOP_ENTRIES = 12


def _modules() -> dict[str, Path]:
    """Module name in the package (``render.renderer``, ``importers.unity``, ``__init__``) -> file."""
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


def _resolve(name: str) -> str:
    """The package's module that an imported dotted name (without ``pbrlab.``) is or is in:
    ``render.renderer.render_scene`` -> ``render.renderer``; a name of the package itself ->
    ``__init__``."""
    parts = name.split(".") if name else []
    for end in range(len(parts), 0, -1):
        candidate = ".".join(parts[:end])
        if candidate in MODULES:
            return candidate
    return "__init__"


def imports_of(module: str, source: str | None = None) -> list[tuple[int, str]]:
    """(line, module of the package) for each import in ``module``'s source (its file's,
    unless ``source`` is given). A module importing a name of its own package's
    ``__init__`` imports that package."""
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
            if target != module:
                found.append((node.lineno, target))
    return found


def _where(module: str, line: int) -> str:
    return f"pbrlab/{MODULES[module].relative_to(PACKAGE)}:{line}"


def test_the_package_top_is_its_layer_folders():
    entries = sorted(p.name for p in PACKAGE.iterdir() if p.name != "__pycache__")
    folders = [folder for _, folder in layers.LAYERS]
    assert len(entries) <= MAX_TOP_ENTRIES, f"harness/pbrlab/ holds {len(entries)} entries: {entries}"
    assert set(folders) <= set(entries)
    extra = set(entries) - set(folders) - {"__init__.py", "__main__.py", "templates"}
    assert not extra, f"harness/pbrlab/ holds {sorted(extra)} beside its layer folders and fronts"


def test_every_module_is_in_a_layer_or_a_front():
    for module in MODULES:
        if not layers.is_front(module):
            layers.layer_of(module)  # KeyError names a module outside every layer folder


def upward_imports(sources: dict[str, str] | None = None) -> list[str]:
    """``file:line: module (layer) imports module (layer)`` for each import against the
    layers, or of a front; ``sources`` replaces the text of some modules (the controls below)."""
    upward = []
    for module in MODULES:
        if layers.is_front(module):
            continue
        level = layers.layer_of(module)
        for line, target in imports_of(module, (sources or {}).get(module)):
            if module.startswith(target + "."):
                continue  # a module's own package (its __init__), in its own folder
            if layers.is_front(target):
                upward.append(f"{_where(module, line)}: {module} ({layers.LAYERS[level][0]}) imports the "
                              f"public front pbrlab.{target}".replace("pbrlab.__init__", "pbrlab"))
            elif layers.layer_of(target) > level:
                upward.append(f"{_where(module, line)}: {module} ({layers.LAYERS[level][0]}) imports {target} "
                              f"({layers.LAYERS[layers.layer_of(target)][0]})")
    return upward


def import_circles(sources: dict[str, str] | None = None) -> list[list[str]]:
    """The groups of modules that import one another in a circle (strongly connected
    components of more than one module, or a module importing itself), each sorted."""
    graph = {m: sorted({t for _, t in imports_of(m, (sources or {}).get(m))}) for m in MODULES}
    index, low, stack, on_stack, circles = {}, {}, [], set(), []

    def visit(start):  # Tarjan's algorithm, iterative (the graph is deep)
        work = [(start, 0)]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, i = work.pop()
            if i < len(graph[node]):
                work.append((node, i + 1))
                nxt = graph[node][i]
                if nxt not in index:
                    index[nxt] = low[nxt] = len(index)
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, 0))
                elif nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
                continue
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                group = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.append(member)
                    if member == node:
                        break
                if len(group) > 1:
                    circles.append(sorted(group))

    for module in MODULES:
        if module not in index:
            visit(module)
    return sorted(circles)


def test_imports_run_only_downward():
    upward = upward_imports()
    assert not upward, "imports against the layers (docs/layers.md):\n" + "\n".join(upward)


def test_no_modules_import_each_other_in_a_circle():
    circles = import_circles()
    assert not circles, "modules importing one another in a circle:\n" + "\n".join(
        " <-> ".join(group) for group in circles)


def test_the_check_sees_function_level_and_relative_imports():
    """A control: the reader finds the imports an upward one would hide behind."""
    assert "render.renderer" in {target for _, target in imports_of("commands.render")}  # lazy, in run()
    scene_imports = {target for _, target in imports_of("scene.model")}
    assert not any(t.startswith("importers") for t in scene_imports)  # the loader hands it the importers
    assert {"scene.model"} <= {target for _, target in imports_of("importers.loader")}


def test_an_upward_import_is_reported():
    """The check fails where it should: a foundation module that imported the renderer lazily."""
    errors = MODULES["foundation.errors"].read_text(encoding="utf-8")
    lazy = errors + "\n\ndef f():\n    from ..render.renderer import render_scene\n"
    assert (errors.count("\n") + 4, "render.renderer") in imports_of("foundation.errors", lazy)
    assert any("foundation.errors (foundation) imports render.renderer (rendering)" in line
               for line in upward_imports({"foundation.errors": lazy}))
    front = errors + "\n\ndef f():\n    from ..scene import Scene\n"
    assert any("imports the public front pbrlab.scene" in line
               for line in upward_imports({"foundation.errors": front}))


def test_a_circle_is_reported():
    """The check fails where it should: two foundation modules importing each other."""
    console = MODULES["foundation.console"].read_text(encoding="utf-8")
    errors = MODULES["foundation.errors"].read_text(encoding="utf-8")
    sources = {"foundation.console": console + "\nfrom . import errors\n",
               "foundation.errors": errors + "\nfrom . import console\n"}
    assert ["foundation.console", "foundation.errors"] in import_circles(sources)


def test_the_docs_page_draws_every_layer_folder():
    page = DOCS.read_text(encoding="utf-8")
    for name, folder in layers.LAYERS:
        assert f"{folder}/" in page, f"docs/layers.md does not draw the folder {folder}/"
    for module in MODULES:
        if module.count(".") == 1 and MODULES[module].name != "__init__.py" and not layers.is_front(module):
            assert f"{module.split('.')[1]}" in page, f"docs/layers.md does not name pbrlab.{module}"


def test_the_docs_tree_is_the_generated_one():
    """docs/layers.md's tree is ``python -m pbrlab.foundation.layers``'s output, not a copy that ages."""
    page = DOCS.read_text(encoding="utf-8")
    start = page.index("<!-- tree: python -m pbrlab.foundation.layers -->")
    block = page[start:page.index("<!-- /tree -->", start)]
    shown = block.split("```text\n", 1)[1].rsplit("```", 1)[0].rstrip("\n")
    assert shown == layers.tree(PACKAGE), "docs/layers.md's tree is stale: paste `python -m pbrlab.foundation.layers`"


def test_the_renderer_names_no_material_source():
    """The renderer draws every material through scene.material_passes: it names no importer or
    format (issue 37)."""
    text = MODULES["render.renderer"].read_text(encoding="utf-8").lower()
    for word in ("unity", "gltf", "json", "shaderlab"):
        assert word not in text, f"render/renderer.py names {word!r}"
    assert not [t for _, t in imports_of("render.renderer") if t.startswith("importers")]


def test_the_tests_mirror_the_layers():
    """One test folder per layer folder (tests/README.md)."""
    tests = Path(__file__).resolve().parents[1]
    missing = [folder for _, folder in layers.LAYERS if not (tests / folder).is_dir()]
    assert not missing, f"no tests/ folder for the layers {missing}"
