"""pbr_hammersley_float, the GLSL ES 1.00 / WebGL 1 form of pbr_hammersley (no uint there).

Reference: the base-2 radical inverse (Hammersley & Handscomb 1964) computed from Python
integers by reversing the 32-bit binary string, independent of both GLSL forms. The float
form is exact for whole i below 2^24 (glsl/pbr/ibl/importance_sampling.glsl), so the
comparison is bit for bit, against the reference and against the uint form.
"""

import subprocess

import numpy as np

from pbrlab import evaluate

INCLUDES = ["pbr/ibl/importance_sampling.glsl"]


def radical_inverse(i: int) -> float:
    return int(f"{i:032b}"[::-1], 2) / 2.0 ** 32


INDICES = np.array([*range(1024), 4095, 65535, 65536, 1_000_003, 12_345_678, 2**24 - 2, 2**24 - 1],
                   dtype=np.float32)


def test_float_form_matches_the_radical_inverse_bit_for_bit():
    count = np.float32(2**24)
    got = evaluate("pbr_hammersley_float(i, n)", INCLUDES, i=INDICES, n=count)
    expected = np.array([[i / float(count), radical_inverse(int(i))] for i in INDICES]).astype(np.float32)
    np.testing.assert_array_equal(got, expected)


def test_float_form_equals_the_uint_form_bit_for_bit():
    got_float = evaluate("pbr_hammersley_float(i, 4096.0)", INCLUDES, i=INDICES)
    got_uint = evaluate("pbr_hammersley(uint(i), 4096u)", INCLUDES, i=INDICES)
    np.testing.assert_array_equal(got_float, got_uint)


def _compiles_as_es_100(call: str) -> bool:
    from pbrlab.gpu import hlsl, shaders
    source = shaders.expand('#version 100\nprecision mediump float;\n'
                            '#include "pbr/ibl/importance_sampling.glsl"\n'
                            f"void main() {{ gl_FragColor = vec4({call}, 0.0, 1.0); }}\n", "<es100>")
    proc = subprocess.run([hlsl.tool(hlsl.GLSLANG), "--stdin", "-S", "frag"], input=source.text,
                          capture_output=True, text=True, timeout=60)
    return proc.returncode == 0


def test_an_es_100_shader_calls_the_float_form_and_has_no_uint_form():
    assert _compiles_as_es_100("pbr_hammersley_float(3.0, 16.0)")
    assert not _compiles_as_es_100("pbr_hammersley(3u, 16u)")  # no uint in GLSL ES 1.00
