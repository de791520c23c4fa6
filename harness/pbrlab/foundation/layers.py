"""The package's layers, bottom up, as data flows: files and messages, then maths, then the
GPU, then the scene model, its importers and the loader that picks one, then rendering,
checking, the bench and the commands. Each layer is one folder of ``harness/pbrlab/``; a
module imports only from its own folder or the folders of the layers below it, function-level
(lazy) imports included, and no group of modules imports itself in a circle.
tests/foundation/test_layers.py reads every module's imports and fails on an upward import or
a circle; docs/layers.md draws the tree and follows one scene through it.

The public fronts sit outside the layers: ``pbrlab`` itself (``evaluate``, ``PbrlabError``,
``__version__``), ``pbrlab.__main__`` (``python -m pbrlab``), and the two package fronts that
keep the documented paths ``pbrlab.scene.load_scene`` / ``parse_scene`` and
``pbrlab.render.render_scene`` working. A front forwards a name on first use; no module of a
layer imports a front (``pbrlab.foundation.version`` holds the version they share).
"""

from __future__ import annotations

# (layer, its folder under harness/pbrlab/), bottom up
LAYERS: tuple[tuple[str, str], ...] = (
    ("foundation", "foundation"),
    ("maths and references", "maths"),
    ("GPU", "gpu"),
    ("scene", "scene"),
    ("importers", "importers"),
    ("rendering", "render"),
    ("checking", "checking"),
    ("bench", "bench"),
    ("commands", "commands"),
)

# Modules named in the package (a package's own ``__init__`` by its package's name): the fronts.
FRONTS = ("__init__", "__main__", "scene", "render")


def is_front(module: str) -> bool:
    """Whether ``module`` (named in the package: ``render``, ``render.renderer``) is a front."""
    return module in FRONTS


def layer_of(module: str) -> int:
    """The index in LAYERS of a module named in the package (``importers.unity.parse``,
    ``render.renderer``): its top folder's layer. Fronts have none (KeyError)."""
    if is_front(module):
        raise KeyError(f"pbrlab.{module} is a public front, in no layer")
    folder = module.split(".")[0]
    for index, (_, name) in enumerate(LAYERS):
        if folder == name:
            return index
    raise KeyError(f"pbrlab.{module} is in no layer folder of pbrlab.foundation.layers.LAYERS")


def _summary(path) -> str:
    """The first sentence of a module's (or package's) docstring, read without importing it."""
    import ast

    source = path / "__init__.py" if path.is_dir() else path
    if not source.is_file():
        return ""
    doc = ast.get_docstring(ast.parse(source.read_text(encoding="utf-8"))) or ""
    text = " ".join(doc.split("\n\n")[0].split())
    end = text.find(". ")
    text = text if end < 0 else text[:end + 1]
    return text if len(text) <= 92 else text[:89].rstrip() + "..."


def tree(package=None) -> str:
    """The package's folders as a text tree, bottom layer first: each layer folder, its modules
    and subpackages with the first sentence of their docstrings (docs/layers.md embeds it;
    ``python -m pbrlab.foundation.layers`` prints it)."""
    from pathlib import Path

    package = Path(package or Path(__file__).resolve().parents[1])
    lines = ["harness/pbrlab/"]
    fronts = [p for p in sorted(package.iterdir()) if p.is_file() and p.suffix == ".py"]
    folders = [package / folder for _, folder in LAYERS]
    others = [p for p in sorted(package.iterdir())
              if p.is_dir() and p not in folders and p.name != "__pycache__"]
    entries = [(p, f"front: {_summary(p)}") for p in fronts]
    entries += [(p, f"layer {i}, {LAYERS[i][0]}: {_summary(p)}") for i, p in enumerate(folders)]
    entries += [(p, "shader templates the programs are built from (package data)") for p in others]
    for n, (path, text) in enumerate(entries):
        last = n == len(entries) - 1
        name = path.name + ("/" if path.is_dir() else "")
        lines.append(f"{'└── ' if last else '├── '}{name:<20}{text}".rstrip())
        if path.is_dir() and path in folders:
            children = [c for c in sorted(path.iterdir()) if c.name not in ("__init__.py", "__pycache__")
                        and (c.suffix == ".py" or (c.is_dir() and (c / "__init__.py").is_file()))]
            for k, child in enumerate(children):
                branch = "    " if last else "│   "
                corner = "└── " if k == len(children) - 1 else "├── "
                child_name = child.name + ("/" if child.is_dir() else "")
                lines.append(f"{branch}{corner}{child_name:<30}{_summary(child)}".rstrip())
    return "\n".join(lines)


if __name__ == "__main__":
    print(tree())
