"""Samplers of a Unity program that nothing binds: a texture the program declares with no
Properties line and no engine input of pbrlab's behind it (an HLSL ``TEXTURE2D(_X)`` or
``TEXTURECUBE(_X)`` of a name the material does not have, often a misspelt property).

Unity binds a default texture to every texture slot a material leaves unset. pbrlab's rule for
such a sampler is parse._implicit_texture_properties' (Cg ``sampler2D`` / ``samplerCUBE``
declared without a Properties line): white for a 2D or 3D texture, the scene's environment for
a cube. Left unbound, the sampler stays on texture unit 0, the renderer's 2D DFG table: a 2D
sampler read that table, and a cube sampler there made the whole draw invalid (OpenGL 3.3 core
2.11.7: samplers of different types on one unit fail the draw), so the object vanished.

    bind_unset(program, cache, environment_cube, unit)   # after every other binding; units used
"""

from __future__ import annotations

from ...gpu.programs import set_uniform as _set

WHITE = (1.0, 1.0, 1.0, 1.0)
GL_SAMPLER_2D, GL_SAMPLER_3D, GL_SAMPLER_CUBE = 0x8B5E, 0x8B5F, 0x8B60  # OpenGL 3.3 core, table 2.10
_KINDS = (GL_SAMPLER_2D, GL_SAMPLER_3D, GL_SAMPLER_CUBE)


def unset(program) -> list[tuple[str, int]]:
    """[(name, GL type)] of the program's 2D, 3D and cube samplers still on unit 0 (every
    binder of pbrlab's puts a Unity program's textures on units 8 and up; the harness's own
    ``u_`` samplers keep their fixed units, unit 0 among them)."""
    out = []
    for name in program:
        member = program[name]
        if name.startswith("u_") or getattr(member, "gl_type", None) not in _KINDS:
            continue
        if member.array_length == 1 and member.value == 0:
            out.append((name, member.gl_type))
    return out


def bind_unset(program, cache, environment_cube, unit: int) -> int:
    """Bind the default texture to each unset sampler from ``unit`` on; returns the units used."""
    found = unset(program)
    for i, (name, kind) in enumerate(found):
        texture = (environment_cube() if kind == GL_SAMPLER_CUBE else cache.constant_volume(WHITE)
                   if kind == GL_SAMPLER_3D else cache.constant_texture(WHITE))
        texture.use(unit + i)
        _set(program, name, unit + i)
    return len(found)
