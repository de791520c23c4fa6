"""A texture property a Unity program samples as a 2D texture array (``UNITY_DECLARE_TEX2DARRAY``:
GLSL ``sampler2DArray``, HLSL ``Texture2DArray``): bound as an array of one layer holding the
property's constant texel (its default texture's, ``white``, ``black``, ``gray``, ``bump``, ...,
or the default name the material gives), which every layer index reads (GL and Direct3D clamp the layer to
the array's: Unity's layer k of an array whose every layer is that colour). An image file for
such a property is refused by name: pbrlab reads no texture arrays from files.

    bound = bind_array(program, name, value, cache, unit)   # False: not an array sampler
"""

from __future__ import annotations

import numpy as np

from ...foundation.errors import PbrlabError
from ...gpu import programs
from ...gpu.programs import set_uniform as _set


def samples_array(program, name: str) -> bool:
    """Whether the program keeps a ``sampler2DArray`` named ``name``."""
    uniforms = programs.uniforms_named(program, name)
    return bool(uniforms) and programs.uniform_type(uniforms[0]) == "sampler2DArray"


def bind_array(program, name: str, value, cache, unit: int) -> bool:
    """Bind ``value`` (properties.TextureValue) as a one-layer array at ``unit`` when the program
    samples ``name`` as an array (and its _TexelSize: 1 x 1); False when it does not."""
    if not samples_array(program, name):
        return False
    if value.path is not None:
        shader = (getattr(program, "extra", None) or {}).get("shader", "surface shader")
        raise PbrlabError(f"{shader}: texture property {name} is sampled as a texture array "
                          f"(UNITY_DECLARE_TEX2DARRAY); pbrlab binds an array of one layer of a constant "
                          f"colour and does not read an array from {value.path.name}: give a default "
                          'name ("white", "gray", ...)')
    texel = tuple(float(x) for x in value.texel)
    texture = cache._textures.get(("constant-array", texel), lambda: cache.ctx.texture_array(
        (1, 1, 1), 4, np.array(texel, np.float32).tobytes(), dtype="f4"))
    texture.use(unit)
    _set(program, name, unit)
    if programs.uniforms_named(program, f"{name}_TexelSize"):
        _set(program, f"{name}_TexelSize", (1.0, 1.0, 1.0, 1.0))
    return True
