"""The rendering layer: a scene to pixels. What a material uses and the programs that follows
(``features``), texture slots (``texture_slots``), GPU resources kept between renders
(``resource_cache``), depth range and framing (``depth_range``), instanced draws
(``instanced_draws``), the transmission copy (``transmission_copy``), the renderer
(``renderer``) and the float64 CPU renderer (``cpu_render``).

``pbrlab.render.render_scene`` (and the renderer's other public names) stay importable from
here, loaded on first use so that importing a sibling module costs only that module.
"""

import importlib
import importlib.util


def __getattr__(name: str):
    if name.startswith("__") or importlib.util.find_spec(f"{__name__}.{name}") is not None:
        # a submodule (imported by the import system, not forwarded)
        raise AttributeError(f"module 'pbrlab.render' has no attribute {name!r}")
    renderer = importlib.import_module(".renderer", __name__)
    try:
        return getattr(renderer, name)
    except AttributeError:
        raise AttributeError(f"module 'pbrlab.render' has no attribute {name!r}") from None
