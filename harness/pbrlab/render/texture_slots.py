"""The default surface's texture slots: one table, and the per-slot code a program compiles.

Every slot of ``templates/default_surface.inc`` (``scene.TEXTURE_SLOTS``) is the same three
things: a texture ``u_<slot>_map``, the UV set it reads (``IN.uv``, or ``IN.uv2`` for glTF's
``texCoord`` 1) and an optional UV transform ``u_<slot>_uv_transform`` (KHR_texture_transform's
2x3 affine as two rows). What differs from slot to slot is only how the surface uses the texel,
which stays in the shader. This module writes the rest, for the slots a program compiles:

* ``PBRLAB_SAMPLE_<SLOT>(IN)``: the texel at the slot's UVs, through
  ``PBRLAB_SAMPLE_COLOR_TEX2D`` for a colour slot (sRGB-decoded by the hardware) or
  ``PBRLAB_SAMPLE_TEX2D`` for a data slot;
* ``PBRLAB_TEXTURE_SLOT_DECLARATIONS``: every such slot's sampler and transform uniform, which
  ``default_surface.inc`` expands once, after its own uniforms.

A slot is compiled where its map is (``PBRLAB_<SLOT>_MAP``, features.py); a layer's slot
(the clear coat's, the sheen's, ...) only where the layer is compiled as well, as the layer's
code that samples it.
"""

from __future__ import annotations

from ..scene.model import (ANISOTROPY_SLOTS, CLEARCOAT_SLOTS, IRIDESCENCE_SLOTS, SHEEN_SLOTS, TEXTURE_SLOTS, TRANSMISSION_SLOTS)

# slot -> the layer (features.MaterialFeatures field) whose code samples it
LAYER_OF_SLOT = {slot: layer for layer, slots in (("clearcoat", CLEARCOAT_SLOTS), ("sheen", SHEEN_SLOTS),
                                                   ("anisotropy", ANISOTROPY_SLOTS),
                                                   ("iridescence", IRIDESCENCE_SLOTS),
                                                   ("transmission", TRANSMISSION_SLOTS))
                 for slot in slots}
DECLARATIONS = "PBRLAB_TEXTURE_SLOT_DECLARATIONS"


def slot_uv(slot: str, uv1: bool, transform: bool) -> str:
    """The UVs ``slot`` reads at ``IN``: its set, through its transform if it has one."""
    uv = "IN.uv2" if uv1 else "IN.uv"
    if not transform:
        return uv
    return f"pbrlab_transform_uv(u_{slot}_uv_transform[0], u_{slot}_uv_transform[1], {uv})"


def slot_defines(slots, uv1_slots=(), transform_slots=(), layers=()) -> dict:
    """The sampling macro of each of ``slots`` (the maps a program compiles) whose layer, if
    any, is among ``layers``, and the one macro declaring their resources."""
    defines, declarations = {}, []
    for slot in sorted(slots):
        if LAYER_OF_SLOT.get(slot, None) not in (None, *layers):
            continue
        sample = "PBRLAB_SAMPLE_COLOR_TEX2D" if TEXTURE_SLOTS[slot] == "srgb" else "PBRLAB_SAMPLE_TEX2D"
        uv = slot_uv(slot, slot in uv1_slots, slot in transform_slots)
        defines[f"PBRLAB_SAMPLE_{slot.upper()}(IN)"] = f"{sample}(u_{slot}_map, {uv})"
        declarations.append(f"PBRLAB_DECLARE_TEX2D(u_{slot}_map);")
        if slot in transform_slots:
            declarations.append(f"uniform vec3 u_{slot}_uv_transform[2];")
    if declarations:
        defines[DECLARATIONS] = " ".join(declarations)
    return defines
