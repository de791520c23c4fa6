"""Importing pyrender 0.1.45 under numpy 2 and PyOpenGL 3.1.10.

pyrender 0.1.45 uses ``np.infty`` (pyrender/mesh.py), an alias numpy 2 removed. Rather
than pinning numpy < 2 for the whole project, ``import_pyrender`` restores that one alias
(it equals ``np.inf``) before pyrender is imported. PyOpenGL must be told its platform
before its first import, so the platform is set here too.
"""

from __future__ import annotations

import os


def import_pyrender(platform: str = "egl"):
    """Import and return pyrender for headless use on ``platform`` ('egl' or 'osmesa')."""
    if platform not in ("egl", "osmesa"):
        raise ValueError(f"pyrender platform must be 'egl' or 'osmesa', got {platform!r}")
    os.environ.setdefault("PYOPENGL_PLATFORM", platform)
    import numpy as np

    if not hasattr(np, "infty"):
        np.infty = np.inf  # removed in numpy 2.0; pyrender 0.1.45 still reads it
    import pyrender

    return pyrender
