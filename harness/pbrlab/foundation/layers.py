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
