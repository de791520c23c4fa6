"""Unity's ``LIGHTPROBE_SH`` keyword: the ForwardBase variant of an object that has no lightmap.

Why: UnityCG.cginc's ``UNITY_SHOULD_SAMPLE_SH`` (Unity 2017 to 2022: ``defined(LIGHTPROBE_SH)``
and none of the ForwardAdd, PrepassBase, ShadowCaster and Meta passes; the stand-in defines it
so, cginc/UnityCG.cginc) says whether a pass adds the ambient probe's SH, and programs copied
from a surface shader's generated code test it. Unity's engine enables LIGHTPROBE_SH in the
variant drawn for an object without a baked or realtime lightmap (Unity manual, "Shader variants
and keywords": ``multi_compile_fwdbase`` compiles the ForwardBase variants with ``LIGHTPROBE_SH``
beside ``LIGHTMAP_ON`` / ``DYNAMICLIGHTMAP_ON``), where the program has that variant: its
``multi_compile_fwdbase`` or a keyword line naming it. pbrlab draws that variant likewise: the
keyword is on where the program declares it and the material supplies no lightmap
(lightmaps.py, dynamic_lightmaps.py turn LIGHTMAP_ON / DYNAMICLIGHTMAP_ON on instead).

    if declares_light_probe_sh(program): ...                  # the reader's variant (parse_pass)
    defines = program_defines(unity_pass, lightmap, dynamic)  # {"LIGHTPROBE_SH": 1} or {}
"""

from __future__ import annotations

import re

from .source_text import blank_comments, declared_keywords

KEYWORD = "LIGHTPROBE_SH"
_FWDBASE = re.compile(r"^[ \t]*#[ \t]*pragma[ \t]+multi_compile_fwdbase\b", re.M)


def declares_light_probe_sh(program: str) -> bool:
    """Whether ``program`` has a LIGHTPROBE_SH variant: a multi_compile/shader_feature line naming
    it, or multi_compile_fwdbase."""
    return KEYWORD in declared_keywords(program) or bool(_FWDBASE.search(blank_comments(program)))


def program_defines(unity_pass, lightmap=None, dynamic_lightmap=None) -> dict:
    """LIGHTPROBE_SH for a vertex/fragment program that declares it, drawn for an object with no
    supplied lightmap (module docstring); else nothing."""
    if unity_pass.kind == "surface" or lightmap is not None or dynamic_lightmap is not None:
        return {}
    return {KEYWORD: 1} if declares_light_probe_sh(unity_pass.program) else {}
