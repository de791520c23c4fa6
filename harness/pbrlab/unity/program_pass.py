"""Compile a vertex/fragment pass (``model.VertexFragmentPass``) into a GL program.

    program = build_pass_program(ctx, vf, "hlsl", defines, blended=False)

HLSL: each stage's generated text (``generate_pass``) through glslang and spirv-cross, as the
surface path's HLSL vertex stage. GLSL: the same entry points around the ``port-unity`` port
of the program. Binding is ``program.bind``'s, as for a surface program (same Unity globals,
same properties).
"""

from __future__ import annotations

import re

from .. import hlsl, shaders
from . import generate, generate_pass
from . import model as M
from .program import CGINC, TEMPLATES, remember_program, write_port

_STAGES = {"vertex": "vert", "fragment": "frag"}


def _ported_file(vf: M.VertexFragmentPass):
    return write_port(vf)


def _stage_text(vf, language: str, stage: str, defines: dict, blended: bool, program_text: str,
                display: str) -> str:
    where = f"{vf.path}:{vf.program_line}"
    head = generate.prelude(language, defines, vertex_stage=stage == "vertex")
    first = vf.program_line if language == "hlsl" else 1
    line = f'#line {first} "{display}"' if language == "hlsl" else f"#line {first}"
    if stage == "vertex":
        entry = generate_pass.vertex_entry(vf, language, where)
    else:
        entry = generate_pass.fragment_entry(vf, language, where, blended)
    return "\n".join(head) + "\n" + line + "\n" + program_text + "\n" + entry


def _hlsl_stage(text: str, display: str, dirs, stage: str) -> shaders.Source:
    glsl = hlsl.cross_to_glsl(hlsl.compile_spirv(text, display, dirs, stage=_STAGES[stage]),
                              plain_uniforms=True)
    if stage == "vertex":  # each stage holds a `uniform _Global <id>;`: rename this one to link
        instance = re.search(r"uniform _Global (\w+);", glsl)
        if instance:
            glsl = re.sub(r"\b_Global\b", "_GlobalVertex", glsl)
            glsl = re.sub(r"\b" + instance.group(1) + r"\b", "pbrlab_vertex_globals", glsl)
    return shaders.Source(glsl, [f"{display} (GLSL from spirv-cross)"])


def build_pass_program(ctx, vf: M.VertexFragmentPass, language: str, defines: dict, blended: bool):
    key = (id(ctx), "pass", str(vf.path), vf.program, language, blended, tuple(sorted(defines.items())))

    def build():
        dirs = [TEMPLATES, CGINC, vf.path.parent]
        stages = {}
        if language == "hlsl":
            for stage in ("vertex", "fragment"):
                display = f"{vf.path.name} (generated hlsl {stage} stage)"
                text = _stage_text(vf, "hlsl", stage, defines, blended, vf.program, vf.path.name)
                stages[stage] = _hlsl_stage(text, display, dirs, stage)
        else:
            ported = _ported_file(vf)
            for stage in ("vertex", "fragment"):
                display = f"{vf.path.name} (generated glsl {stage} stage)"
                text = _stage_text(vf, "glsl", stage, defines, blended, f'#include "{ported.name}"', ported.name)
                stages[stage] = shaders.expand(text, display, include_dirs=[TEMPLATES, ported.parent] + dirs[1:])
        return shaders.build_program(ctx, stages["vertex"], stages["fragment"])

    return remember_program(key, build)
