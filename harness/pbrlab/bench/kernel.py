"""The timing kernel: a fragment shader that evaluates one variant many times per pixel.

Method (issue 7, measured facts about llvmpipe): a loop with a *uniform* trip count (so the
compiler cannot unroll it), and inside each iteration ``EVALS_PER_ITERATION`` independent
evaluations of the term, each on its own inputs (a cheap per-pixel, per-iteration,
per-slot hash mapped onto the family's input domain), all summed into the output so
none is eliminated. The *baseline* kernel of a family is the same loop with the same
input generation whose "term" is the sum of its inputs; its cost is subtracted, so a
figure is the cost of the term alone.

Inputs of a family are ``(name, lo, hi)`` ranges plus optional derived values
``(glsl_type, name, glsl, ...)`` (e.g. f0 from an IOR) that belong to the baseline too.
"""

from __future__ import annotations

from pathlib import Path

from ..gpu import shaders

# Peer engines' code the bench compares with (bench/peers/*.glsl, not the library).
PEERS_DIR = Path(__file__).resolve().parent / "peers"

EVALS_PER_ITERATION = 8  # independent evaluations per loop iteration (issue 7: "e.g. 8")

_VERTEX = """#version 330 core
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
"""

_FRAGMENT = """#version 330 core
//@DEFINES
#include "pbr/pbr.glsl"
uniform int pbrlab_trips;
uniform float pbrlab_seed;
uniform sampler2D pbrlab_tex;  // texture kernels only
out vec4 pbrlab_result;
float pbrlab_reduce(float x) { return x; }
float pbrlab_reduce(vec2 x) { return x.x + x.y; }
float pbrlab_reduce(vec3 x) { return x.x + x.y + x.z; }
float pbrlab_reduce(vec4 x) { return x.x + x.y + x.z + x.w; }
void main() {
    vec2 pbrlab_q = gl_FragCoord.xy * 0.0078125;
    float pbrlab_acc = 0.0;
    for (int pbrlab_i = 0; pbrlab_i < pbrlab_trips; ++pbrlab_i) {
        float pbrlab_s = float(pbrlab_i) * 0.6180339 + pbrlab_seed;
//@BODY
    }
    pbrlab_result = vec4(pbrlab_acc);
}
"""

# Per input slot j and evaluation k: r = fract(q.x * a + q.y * b + s * c + k * d) in [0, 1).
_HASH = (0.7548777, 0.5698403, 0.3247179, 0.1324718, 0.8191725, 0.2451223)


def _slot_hash(j: int, k: int) -> str:
    a, b = _HASH[j % 6], _HASH[(j + 3) % 6]
    return (f"fract(pbrlab_q.x * {1.0 + a:.7f} + pbrlab_q.y * {1.0 + b:.7f} + "
            f"pbrlab_s * {0.5 + a:.7f} + {(k * 0.381966 + j * 0.2360680) % 1.0:.7f})")


def body(inputs, derived, expression, evals=EVALS_PER_ITERATION) -> str:
    """GLSL of one loop iteration: ``evals`` scoped blocks, each with fresh inputs.

    Every block adds the term *and* all its inputs and derived values to the
    accumulator, so the baseline (``expression`` None: inputs only) computes exactly
    what a variant computes besides the term, whichever inputs the term reads."""
    names = [name for name, _, _ in inputs] + [d[1] for d in derived]
    inputs_sum = " + ".join(f"pbrlab_reduce({name})" for name in names)
    out = []
    for k in range(evals):
        lines = []
        for j, (name, lo, hi) in enumerate(inputs):
            lines.append(f"float {name} = mix({float(lo):.9g}, {float(hi):.9g}, {_slot_hash(j, k)});")
        for glsl_type, name, glsl, *_ in derived:
            lines.append(f"{glsl_type} {name} = {glsl};")
        term = inputs_sum if expression is None else f"pbrlab_reduce({expression}) + {inputs_sum}"
        lines.append(f"pbrlab_acc += {term};")
        out.append("        {\n" + "\n".join("            " + line for line in lines) + "\n        }")
    return "\n".join(out)


def fragment_source(inputs, derived, expression, defines=None, evals=EVALS_PER_ITERATION, peer="") -> str:
    """Unexpanded fragment text (``expression`` None: the family's baseline; ``peer``: a file
    of PEERS_DIR the expression calls, included after the library)."""
    define_lines = "\n".join(f"#define {k} {v}" for k, v in sorted((defines or {}).items()))
    text = _FRAGMENT.replace("//@DEFINES", define_lines).replace("//@BODY", body(inputs, derived, expression, evals))
    if peer:
        text = text.replace('#include "pbr/pbr.glsl"', f'#include "pbr/pbr.glsl"\n#include "{peer}"', 1)
    return text


def expanded(text: str) -> str:
    """The fragment with the library's includes resolved (what the worker compiles)."""
    return shaders.expand(text, "<bench kernel>", include_dirs=(PEERS_DIR,)).text


def vertex_source() -> str:
    return _VERTEX
