"""`pbrlab port-unity SHADER -o surf.glsl`: a Unity surface shader's CGPROGRAM, renamed to GLSL.

The renames are mechanical (harness/pbrlab/unity/port.py): Cg/HLSL types to GLSL (float3 ->
vec3, half -> float, float4x4 -> mat4), `uniform` on the program's globals, scalar-to-vector
assignments through the target's constructor (o.Albedo = 1 -> o.Albedo = vec3(1)), casts,
semantics, pow -> pbr_unity_pow. Intrinsics (saturate, lerp, tex2D, ...) keep their names:
unity_compat/cg_compat.glsl defines them. The output carries the shader's Properties and pass
state as //@ lines, so a scene material's `surface` may name it for the GLSL path.
"""

from __future__ import annotations

import argparse

from pathlib import Path

from ..images import atomic_output
from ..unity import load_shader
from ..unity.port import port_file


def run(args) -> int:
    shader = load_shader(Path(args.shader))
    text = port_file(shader)
    if args.output == "-":
        print(text, end="")
        return 0
    with atomic_output(args.output) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")
    print(f"wrote {args.output} ({len(text.splitlines())} lines)")
    return 0


def register(sub, common):
    p = sub.add_parser("port-unity", parents=[common],
                       help="Rename a Unity surface shader's CGPROGRAM to GLSL for the GLSL path.",
                       description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("shader", help="a Unity .shader file (or bare CGPROGRAM text with #pragma surface)")
    p.add_argument("-o", "--output", default="-", help="output .glsl file (default: stdout)")
    p.set_defaults(run=run)
