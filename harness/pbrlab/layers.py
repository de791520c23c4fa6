"""The package's layers, bottom up, as data flows: files and messages, then maths, then GL,
then the sources a scene is made of, the scene model, its importers and the loader that picks
one, then rendering, checking, the bench and the commands. A module imports only from its
own layer or the layers below it, function-level (lazy) imports included; there are no
folders per layer yet (modules are listed by name), and tests/harness/test_layers.py reads
every module's imports and fails on an upward one. docs/layers.md says why each layer is
where it is.

``LAYERS`` lists each layer's modules by their name in the package: a top-level module or a
subpackage (all its modules), and a subpackage's module where it sits elsewhere than its
package (``unity.corpus``, a check that renders, sits with the checks). Every module of the
package is in exactly one entry; a new module needs its line here.
"""

from __future__ import annotations

LAYERS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("foundation", (
        "errors", "locations", "console", "progress", "outputs", "file_identity", "disk_cache",
        "json_input", "images", "golden_names", "layers")),
    ("maths and references", (
        "reference", "srgb8", "mipmaps", "camera", "exposure")),
    ("GL and programs", (
        "gl", "gl_limits", "shaders", "source_cache", "hlsl", "programs", "surface_bindings", "targets", "evaluator",
        "ibl", "sheen_table", "engine_tables", "port_hlsl", "gpu_isa", "__init__")),
    ("scene sources", (
        "meshes", "environment", "unity", "surface_layers")),
    ("scene model", (
        "scene_fields", "scene", "scene_schema")),
    ("importers", (
        "gltf",)),
    ("scene files", (
        "scene_files",)),
    ("rendering", (
        "texture_slots", "features", "depth_range", "resource_cache", "instanced_draws", "transmission_copy", "render", "cpu_render")),
    ("checking", (
        "compare", "goldens", "charts", "golden_scenes", "contact_sheets", "codescan", "hardcases",
        "pyrender_compat", "pyrender_check", "pyrender_figure", "pyrender_gltf_check", "sample_viewer",
        "sample_viewer_prediction", "unity.corpus", "pytest_plugin")),
    ("bench", (
        "bench",)),
    ("commands", (
        "commands", "cli")),
)


def layer_of(module: str) -> int:
    """The index in LAYERS of a module named in the package (``unity.parse``,
    ``render``, ``__init__`` for the package itself): its own entry, else its package's."""
    parts = module.split(".")
    for end in range(len(parts), 0, -1):
        name = ".".join(parts[:end])
        for index, (_, modules) in enumerate(LAYERS):
            if name in modules:
                return index
    raise KeyError(f"pbrlab.{module} is in no layer of pbrlab.layers.LAYERS")
