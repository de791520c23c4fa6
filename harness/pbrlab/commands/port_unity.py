"""`pbrlab port-unity SHADER -o surf.glsl`: a Unity surface shader's CGPROGRAM, renamed to GLSL.

The renames are mechanical (harness/pbrlab/importers/unity/port.py): Cg/HLSL types to GLSL (float3 ->
vec3, half -> float, float4x4 -> mat4), `uniform` on the program's globals, scalar-to-vector
assignments through the target's constructor (o.Albedo = 1 -> o.Albedo = vec3(1)), casts,
semantics, pow -> pbr_unity_pow. Intrinsics (saturate, lerp, tex2D, ...) keep their names:
unity_compat/cg_compat.glsl defines them. The output carries the shader's Properties and pass
state as //@ lines, so a scene material's `surface` may name it for the GLSL path.
"""

from __future__ import annotations

import argparse

from pathlib import Path

from ..foundation import outputs
from ..foundation.errors import PbrlabError
from ..importers.unity import load_shader
from ..importers.unity.port import port_file


def run(args) -> int:
    unity_shader = load_shader(Path(args.shader))
    shader = unity_shader.surface
    if shader is None:
        raise PbrlabError(f"{args.shader}: port-unity ports a surface program, and this shader has "
                          "vertex/fragment passes only; name the .shader file itself as a material's "
                          "surface (both languages port it on the fly)")
    text = port_file(shader)
    if args.output == "-":
        print(text, end="")
        return 0
    if Path(args.output).suffix.lower() not in (".glsl", ".txt", ""):
        raise PbrlabError(f"refusing to write GLSL text to {args.output}: name the port .glsl")
    with outputs.transaction([args.output], [(args.shader, "the shader being ported")]) as tx:
        tx.write_text(args.output, text)
    print(f"wrote {args.output} ({len(text.splitlines())} lines)")
    return 0


def register(sub, common):
    p = sub.add_parser("port-unity", parents=[common],
                       help="Rename a Unity surface shader's CGPROGRAM to GLSL for the GLSL path.",
                       description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("shader", help="a Unity .shader file (or bare CGPROGRAM text with #pragma surface)")
    p.add_argument("-o", "--output", default="-", help="output .glsl file (default: stdout)")
    p.set_defaults(run=run)
