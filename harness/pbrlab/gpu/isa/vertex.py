"""A vertex stage that feeds a fragment stage's inputs, for compiling the fragment alone.

RADV compiles a graphics pipeline's stages together and optimises across them: an output
the vertex stage does not write, or writes as a constant, is folded into the fragment
stage (Mesa's varying linking propagates constants and drops duplicated outputs), which
would shrink the fragment program being measured. So each input the fragment reads (its
location and type, from spirv-cross's reflection) gets an output of its own that varies
per vertex: every component is a different affine function of ``gl_VertexIndex``, so no
two outputs are equal and none is constant. Position: the full-screen triangle."""

from __future__ import annotations

from ...foundation.errors import PbrlabError

# matrices: the peers' captured WebGL programs pass one (the Sample Viewer's v_TBN, a mat3);
# a matrix's constructor takes its components column by column, so it is fed like a vector
_FLOAT = {"float": 1, "vec2": 2, "vec3": 3, "vec4": 4, "mat2": 4, "mat3": 9, "mat4": 16}
_INT = {"int": ("int", 1), "ivec2": ("int", 2), "ivec3": ("int", 3), "ivec4": ("int", 4),
        "uint": ("uint", 1), "uvec2": ("uint", 2), "uvec3": ("uint", 3), "uvec4": ("uint", 4)}

_MAIN = """void main() {
    vec2 pbrlab_p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
    gl_Position = vec4(pbrlab_p * 2.0 - 1.0, 0.0, 1.0);
    float pbrlab_x = float(gl_VertexIndex);
"""


def _components(glsl_type: str, slot: int, count: int) -> list:
    # component c of output slot s: x * (1 + s + c/8) + (s + c)/16 (distinct for every s, c)
    if glsl_type in _FLOAT:
        return [f"pbrlab_x * {1.0 + slot + c / 8.0:.4f} + {(slot + c) / 16.0:.4f}"
                for c in range(count)]
    scalar, _ = _INT[glsl_type]
    return [f"{scalar}(gl_VertexIndex * {2 + slot + c} + {slot + c})" for c in range(count)]


def feeding_vertex(reflection: dict) -> str:
    """GLSL (Vulkan) of a vertex stage writing every input of a fragment module, given the
    module's ``spirv-cross --reflect`` JSON."""
    declarations, writes = [], []
    for slot, item in enumerate(sorted(reflection.get("inputs", []), key=lambda i: i["location"])):
        glsl_type, location = item["type"], int(item["location"])
        if item.get("array"):
            raise PbrlabError(f"fragment input {item['name']}: arrays are not fed (no such input yet)")
        if glsl_type in _FLOAT:
            count = _FLOAT[glsl_type]
        elif glsl_type in _INT:
            count = _INT[glsl_type][1]
        else:
            raise PbrlabError(f"fragment input {item['name']}: type {glsl_type} is not fed")
        name = f"pbrlab_out{location}"
        declarations.append(f"layout(location = {location}) out {glsl_type} {name};")
        values = _components(glsl_type, slot, count)
        writes.append(f"    {name} = {glsl_type}({', '.join(values)});")
    return "\n".join(["#version 450", *declarations, _MAIN + "\n".join(writes), "}", ""])
