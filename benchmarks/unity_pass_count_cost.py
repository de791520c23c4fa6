"""The corpus runner's time against a shader's number of passes: a generated ``.shader`` of N
untagged passes after one CGINCLUDE, each its own ``frag`` returning a different swizzle of a
texture (the form of Amplify Shader Editor's preview shaders: Preview_SwizzleNode has 256 of
them and did not finish in 40 minutes, docs/unity.md), rendered as the corpus renders it
(``unity_corpus.run_shader``). A measurement, not a test: it prints figures and asserts nothing.

    LP_NUM_THREADS=1 PYTHONPATH=harness .venv/bin/python benchmarks/unity_pass_count_cost.py \\
        [--passes 8 16 32 64] [--language glsl|hlsl]

For each N: the seconds of one ``read_shader`` (the front end: every pass parsed), of the whole
``run_shader`` (the scene's questions, the read, every pass's program built and drawn), and
seconds per pass. Each run gets a new empty disk cache (``PBRLAB_CACHE_DIR``), as a shader the
corpus has not seen. To measure another checkout's harness, point PYTHONPATH at it.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

HEAD = """Shader "Benchmark/Passes"
{
    Properties { _A ("_A", 2D) = "white" {} _Mask ("_Mask", Vector) = (1, 1, 1, 1) }
    SubShader
    {
        CGINCLUDE
        #include "UnityCG.cginc"
        #pragma vertex vert_img
        #pragma fragment frag
        sampler2D _A;
        float4 _Mask;
        ENDCG
"""
PASS = """        Pass
        {
            Name "P%(k)d"
            CGPROGRAM
            float4 frag(v2f_img i) : SV_Target
            {
                float4 a = tex2D(_A, i.uv);
                return float4(%(swizzle)s) * _Mask;
            }
            ENDCG
        }
"""


def shader_text(passes: int) -> str:
    """N passes, pass k the k-th swizzle of xyzw in base 4 (256 distinct ones, then again)."""
    body = []
    for k in range(passes):
        digits = [(k >> (2 * i)) & 3 for i in (3, 2, 1, 0)]
        body.append(PASS % {"k": k, "swizzle": ",".join("a." + "xyzw"[d] for d in digits)})
    return HEAD + "".join(body) + "    }\n}\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--passes", type=int, nargs="+", default=[8, 16, 32, 64])
    parser.add_argument("--language", default="glsl", choices=("glsl", "hlsl"))
    args = parser.parse_args()
    from pbrlab.checking.unity_corpus import run_shader
    from pbrlab.importers.unity import BUILTIN, read_shader
    print(f"LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', '(unset)')}, language {args.language}")
    print(f"{'passes':>6} {'read_shader s':>13} {'run_shader s':>12} {'s/pass':>7} status")
    with tempfile.TemporaryDirectory() as folder:
        warm = Path(folder) / "warm.shader"
        warm.write_text(shader_text(1))
        run_shader(warm, args.language)  # imports, the GL context, the compiler
        for n in args.passes:
            os.environ["PBRLAB_CACHE_DIR"] = tempfile.mkdtemp(dir=folder)
            path = Path(folder) / f"passes{n}.shader"
            path.write_text(shader_text(n))
            start = time.perf_counter()
            read_shader(path, BUILTIN)
            read = time.perf_counter() - start
            start = time.perf_counter()
            outcome = run_shader(path, args.language)
            total = time.perf_counter() - start
            print(f"{n:>6} {read:>13.2f} {total:>12.1f} {total / n:>7.2f} {outcome.status}", flush=True)


if __name__ == "__main__":
    main()
