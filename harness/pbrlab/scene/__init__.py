"""The scene layer: the scene model (``model``: cameras, lights, materials, objects), its
fields and schema (``fields``, ``schema``), meshes (``meshes``), the environment and its cube
map (``environment``, ``cubemap``), the layered surface's fields (``surface_layers``) and the
interface every material gives the renderer (``material_passes``).

``pbrlab.scene.parse_scene`` and ``load_scene`` are the public way to read a scene: they are
pbrlab.importers.loader's, which hands the model the importers a file needs (glTF objects,
Unity shaders); the model's other names (``Scene``, ``Material``, ...) are the model's. Both
are loaded on first use. Code inside the package imports ``pbrlab.scene.model`` or
``pbrlab.importers.loader`` directly, never this front.
"""

import importlib
import importlib.util

_FROM_LOADER = ("parse_scene", "load_scene")


def __getattr__(name: str):
    if name.startswith("__") or importlib.util.find_spec(f"{__name__}.{name}") is not None:
        # a submodule (imported by the import system, not forwarded)
        raise AttributeError(f"module 'pbrlab.scene' has no attribute {name!r}")
    if name in _FROM_LOADER:
        return getattr(importlib.import_module("pbrlab.importers.loader"), name)
    model = importlib.import_module(".model", __name__)
    try:
        return getattr(model, name)
    except AttributeError:
        raise AttributeError(f"module 'pbrlab.scene' has no attribute {name!r}") from None
