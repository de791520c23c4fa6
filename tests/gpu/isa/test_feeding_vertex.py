"""pbrlab.gpu.isa.vertex: the generated vertex stage feeds every fragment input a value
that varies per vertex, so RADV cannot fold the inputs into the fragment program (which a
vertex stage writing constants lets it do: the control below)."""

import re

import pytest

from pbrlab.gpu.isa import compile as gpu
from pbrlab.gpu.isa.vertex import feeding_vertex

_FRAGMENT = """#version 450
layout(location = 0) in vec3 a;
layout(location = 1) in vec2 b;
layout(location = 2) flat in int k;
layout(location = 0) out vec4 colour;
void main() {
    vec3 n = normalize(a);
    colour = vec4(n * b.x + vec3(b.y), float(k));
}
"""

_CONSTANT_VERTEX = """#version 450
layout(location = 0) out vec3 a;
layout(location = 1) out vec2 b;
layout(location = 2) out int k;
void main() {
    gl_Position = vec4(float(gl_VertexIndex), 0.0, 0.0, 1.0);
    a = vec3(0.0, 0.0, 1.0);
    b = vec2(1.0, 0.5);
    k = 3;
}
"""


def test_every_input_gets_its_own_varying_output():
    reflection = {"inputs": [{"type": "vec2", "name": "uv", "location": 3},
                             {"type": "vec4", "name": "c", "location": 0},
                             {"type": "int", "name": "k", "location": 1}]}
    text = feeding_vertex(reflection)
    declared = re.findall(r"layout\(location = (\d+)\) out (\w+) ", text)
    assert sorted(declared) == [("0", "vec4"), ("1", "int"), ("3", "vec2")]
    # every component is its own expression of gl_VertexIndex: none constant, none repeated
    components = re.findall(r"pbrlab_x \* [0-9.]+ \+ [0-9.]+|gl_VertexIndex \* \d+ \+ \d+", text)
    assert len(components) == 4 + 1 + 2 and len(set(components)) == len(components)


def test_radv_keeps_the_inputs_a_varying_vertex_stage_feeds():
    if (why := gpu.available()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    result = gpu.run([gpu.Job("fed", _FRAGMENT), gpu.Job("constant", _FRAGMENT, vertex=_CONSTANT_VERTEX)],
                     families=("rdna3",))["rdna3"]
    # constants fold the normalize and the multiply-add away; fed inputs must be
    # interpolated and normalized (a reciprocal square root at least)
    assert result["fed"]["Instructions"] > result["constant"]["Instructions"] + 5, result
    assert result["fed"]["isa"]["transcendental"] >= 1
    assert result["constant"]["isa"]["transcendental"] == 0
