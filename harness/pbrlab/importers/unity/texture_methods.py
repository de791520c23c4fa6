"""Direct3D 11's texture objects spelled in Cg's texture functions, for the GLSL port.

A built-in-pipeline program may declare its textures and samplers as Direct3D 11 objects and
sample through their methods (what UnityCG's ``UNITY_DECLARE_TEX2D`` expands to on D3D11)::

    Texture2D _Albedo, _Mask;            SamplerState sampler_linear_repeat;
    float4 c = _Albedo.Sample(sampler_linear_repeat, uv);

HLSL takes this as written. GLSL has no separate samplers: each texture object becomes a
combined sampler (``sampler2D _Albedo, _Mask;``, bound as every other texture property), the
sampler objects unused ints, and each method call the Cg function of the same lookup
(Microsoft's HLSL reference, "Texture2D"): ``Sample(s, uv)`` -> ``tex2D(t, uv)``,
``SampleLevel(s, uv, lod)`` -> ``tex2Dlod(t, float4(uv, 0, lod))``, ``SampleBias(s, uv, b)`` ->
``tex2Dbias(t, float4(uv, 0, b))``, ``SampleGrad(s, uv, dx, dy)`` -> ``tex2Dgrad(t, uv, dx, dy)``,
``Load(int3(x, y, mip))`` -> ``pbr_unity_load(t, int3(...))`` (texelFetch); the cube's
``Sample`` / ``SampleLevel`` -> ``texCUBE`` / ``texCUBElod``; a 2D array's (``Texture2DArray``, a ``sampler2DArray``) ``Sample`` / ``SampleLevel``
-> ``UNITY_SAMPLE_TEX2DARRAY`` / ``_LOD`` (the Unity prelude's). The sampler's own state (an inline
sampler's filter and wrap, by its name) is the texture's here, as for every combined sampler.
``Gather`` / ``GatherRed`` .. ``GatherAlpha(s, uv)`` -> ``textureGather(t, uv, channel)``. Any other method
(``GetDimensions``, a gather's offset forms) is left as written and the compiler names it.
A function's parameter of these types is spelled likewise (a texture's, a combined sampler; a
sampler's, an unused int), so a texture passed to a function with its sampler is. Lines are kept.

    text = spelled_texture_methods(cg_text)
"""

from __future__ import annotations

import re

from .compared_textures import TextureReads, compared_view, texture_reads
from .source_text import call_arguments

# (``sampler``: HLSL's legacy name of SamplerState; one a Cg intrinsic samples is a sampler2D by now,
# combined_samplers)
# (a ``uniform`` before it: HLSL's default for a global, GLSL's for a sampler; a sampler object's
# int is a static const, which takes none)
_DECLARATION = re.compile(r"(?:\buniform\s+)?\b(Texture2DArray|Texture2D|TextureCube|SamplerState|SamplerComparisonState|sampler)(?:\s*<\s*\w+\s*>)?"
                          r"(\s+\w+(?:\s*,\s*\w+)*)\s*;")
# a parameter of one of these types (``float2 Parallax(Texture2D t, SamplerState s, float2 uv)``):
# after the list's '(' or a ',' (a qualifier between), before the next ',' or ')'
_PARAMETER = re.compile(r"(?<=[(,])(\s*(?:(?:in|uniform)\s+)?)(Texture2DArray|Texture2D|TextureCube|SamplerState|SamplerComparisonState|sampler)"
                        r"(?:\s*<\s*\w+\s*>)?(\s+)(\w+)(?=\s*[,)])")
_COMBINED = {"Texture2D": "sampler2D", "TextureCube": "samplerCUBE", "Texture2DArray": "sampler2DArray"}
# Core RP's declaration macros (a URP program's ``TEXTURE2D(_Tex); SAMPLER(sampler_Tex);``, a
# function's ``TEXTURE2D_PARAM(t, s)``): the same objects (Core RP's API/D3D11.hlsl declares
# ``Texture2D t`` by them), whose methods are spelled here too; the macros themselves are left
# for port.py's SRP pass, which spells them as combined samplers after this one.
_MACRO_DECLARATION = re.compile(r"\b(TEXTURE2D|TEXTURE2D_X|TEXTURE2D_X_FLOAT|TEXTURECUBE|TEXTURE2D_SHADOW|TEXTURECUBE_SHADOW|TEXTURE2D_ARRAY)"
                                r"(?:_PARAM)?\s*\(\s*(\w+)\s*[,)]")
_MACRO_KIND = {"TEXTURE2D": "Texture2D", "TEXTURE2D_X": "Texture2D", "TEXTURE2D_X_FLOAT": "Texture2D",
               "TEXTURECUBE": "TextureCube", "TEXTURE2D_SHADOW": "Texture2D", "TEXTURECUBE_SHADOW": "TextureCube",
               "TEXTURE2D_ARRAY": "Texture2DArray"}
_METHOD = re.compile(r"\b(\w+)\s*\.\s*(SampleCmpLevelZero|SampleCmp|Sample|SampleLevel|SampleBias|SampleGrad|Load|"
                     r"GatherRed|GatherGreen|GatherBlue|GatherAlpha|Gather)\s*\(")
# A 2D texture's gathers (Microsoft's HLSL reference, "Texture2D.Gather", "GatherRed" ..: one
# channel of the four texels a bilinear read weighs): GLSL's textureGather with the channel's
# index (the extensions it needs in GLSL 3.30: texture_gather.py)
_GATHER_CHANNELS = {"Gather": 0, "GatherRed": 0, "GatherGreen": 1, "GatherBlue": 2, "GatherAlpha": 3}
# A texture some method compares (``t.SampleCmp(s, uv, z)`` with a SamplerComparisonState s): a
# GLSL comparison sampler, a depth texture with its comparison on (shadow_maps.py); its reads are
# cg_compat's pbr_unity_sample_cmp (Microsoft's HLSL reference, "SampleCmp": the reference z against
# each texel read, the 0/1 results filtered; SampleCmpLevelZero: the same on mip 0, a depth
# texture's one level). Which textures are compared is compared_textures.texture_reads' answer
# for the whole program, also through the functions a texture is passed to; a texture both
# compared and read plainly is two samplers, the plain one under its name and the comparison
# view (compared_textures.compared_view) its comparisons read.
_COMPARED = {"Texture2D": "sampler2DShadow", "TextureCube": "samplerCubeShadow"}


def _call(kind: str, method: str, texture: str, args: list, both=frozenset()):
    """The Cg spelling of ``texture.method(args)`` (args with the sampler first, except Load);
    a comparison of a texture in ``both`` reads its comparison view."""
    if method in ("SampleCmp", "SampleCmpLevelZero") and len(args) == 3:
        texture = compared_view(texture) if texture in both else texture
        # (a location longer than the texture's cut to its first components, as FXC passes it)
        location = f"({args[1]}).xy" if kind == "Texture2D" else f"({args[1]}).xyz"
        return f"pbr_unity_sample_cmp({texture}, float{3 if kind == 'Texture2D' else 4}({location}, {args[2]}))"
    if kind == "Texture2D":
        if method == "Load" and len(args) == 1:
            return f"pbr_unity_load({texture}, {args[0]})"
        if method == "Sample" and len(args) == 2:
            return f"tex2D({texture}, {args[1]})"
        if method == "SampleLevel" and len(args) == 3:  # a longer location cut to its first
            # two, as FXC passes it (warning X3206, implicit truncation of a vector type)
            return f"tex2Dlod({texture}, float4(({args[1]}).xy, 0.0, {args[2]}))"
        # The offset forms (an immediate offset in texels: Microsoft's HLSL reference, "Sample"):
        # GLSL's textureOffset / textureLodOffset, which take a constant offset too
        # (sample_offsets.py makes one of a parameter); wrapped in a float4 constructor so the
        # type pass knows the lookup's type (a float3 it initialises is truncated).
        if method == "Sample" and len(args) == 3:
            return f"float4(textureOffset({texture}, pbr_unity_finite_coordinate({args[1]}), {args[2]}))"
        if method == "SampleLevel" and len(args) == 4:
            return (f"float4(textureLodOffset({texture}, pbr_unity_finite_coordinate(({args[1]}).xy), {args[2]},"
                    f" {args[3]}))")
        if method == "SampleBias" and len(args) == 3:
            return f"tex2Dbias({texture}, float4(({args[1]}).xy, 0.0, {args[2]}))"
        if method == "SampleGrad" and len(args) == 4:
            return f"tex2Dgrad({texture}, {args[1]}, {args[2]}, {args[3]})"
        if method in _GATHER_CHANNELS and len(args) == 2:
            return f"float4(textureGather({texture}, ({args[1]}).xy, {_GATHER_CHANNELS[method]}))"
    if kind == "TextureCube":
        if method == "Sample" and len(args) == 2:
            return f"texCUBE({texture}, {args[1]})"
        if method == "SampleLevel" and len(args) == 3:  # a longer location cut to its first
            # three, as FXC passes it (warning X3206, implicit truncation of a vector type)
            return f"texCUBElod({texture}, float4(({args[1]}).xyz, {args[2]}))"
    if kind == "Texture2DArray":
        # a 2D array's location is (u, v, layer) (Microsoft's HLSL reference, "Texture2DArray"
        # and "Sample (DirectX HLSL Texture Object)": float3 for Texture2DArray); the Unity
        # prelude's UNITY_SAMPLE_TEX2DARRAY(_LOD) reads the array as Unity's macros of the same
        # names do (a longer location cut to three, as FXC passes it)
        if method == "Sample" and len(args) == 2:
            return f"UNITY_SAMPLE_TEX2DARRAY({texture}, float3(({args[1]}).xyz))"
        if method == "SampleLevel" and len(args) == 3:
            return f"UNITY_SAMPLE_TEX2DARRAY_LOD({texture}, float3(({args[1]}).xyz), {args[2]})"
    return None  # another method or form: left for the compiler to name


# The second probe unity_SpecCube1 reads the same sky: the scene has one reflection source, and
# Unity binds its one probe to both slots with blend weight unity_SpecCube0_BoxMin.w = 1
# (unity_compat/shader_variables.glsl).
_PROBE_READ = re.compile(r"\b(UNITY_SAMPLE_TEXCUBE_LOD|UNITY_SAMPLE_TEXCUBE|texCUBElod|texCUBE)\s*\(\s*unity_SpecCube[01]\s*,")


# Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(unity_SpecCube0), hdr, glossIn), or on the second
# probe with the first one's sampler, UNITY_PASS_TEXCUBE_SAMPLER(unity_SpecCube1, unity_SpecCube0):
# the stand-in UnityImageBasedLighting.cginc's pbrlab_unity_glossy_probe(hdr, glossIn) (line
# breaks kept)
_GLOSSY_PROBE = re.compile(r"\bUnity_GlossyEnvironment\s*\(\s*(?:UNITY_PASS_TEXCUBE\s*\(\s*unity_SpecCube[01]|"
                           r"UNITY_PASS_TEXCUBE_SAMPLER\s*\(\s*unity_SpecCube[01]\s*,\s*unity_SpecCube[01])\s*\)\s*,")


def spelled_probe_reads(code: str) -> str:
    """Each read of the reflection probe ``unity_SpecCube0`` (UNITY_SAMPLE_TEXCUBE(_LOD),
    texCUBE(lod)) as a call of the Unity layer's pbrlab_unity_reflection_probe(direction, mip)
    (templates/unity_surface.inc), and Unity_GlossyEnvironment on it (_GLOSSY_PROBE): GLSL has
    no object to stand for the probe."""
    code = _GLOSSY_PROBE.sub(lambda m: "pbrlab_unity_glossy_probe(" + "\n" * m.group(0).count("\n"), code)
    out, pos = [], 0
    for m in _PROBE_READ.finditer(code):
        if m.start() < pos:
            continue
        found = call_arguments(code, code.index("(", m.start()))
        if found is None:
            continue
        args, end = found
        form = m.group(1)
        if form in ("UNITY_SAMPLE_TEXCUBE", "texCUBE") and len(args) == 2:
            spelled = f"pbrlab_unity_reflection_probe({args[1]}, 0.0)"
        elif form == "UNITY_SAMPLE_TEXCUBE_LOD" and len(args) == 3:
            spelled = f"pbrlab_unity_reflection_probe({args[1]}, {args[2]})"
        elif form == "texCUBElod" and len(args) == 2:
            spelled = f"pbrlab_unity_reflection_probe(({args[1]}).xyz, ({args[1]}).w)"
        else:
            continue
        spelled += "\n" * (code.count("\n", m.start(), end) - spelled.count("\n"))
        out += [code[pos:m.start()], spelled]
        pos = end
    return "".join(out) + code[pos:]


def texture_kinds(text: str) -> dict:
    """The texture objects ``text`` declares (``Texture2D t;``, ``TEXTURE2D(t);``), by name: their
    kinds, for a file that samples a texture another include declares (MasonJohnHawver42's
    GrassPass.hlsl: ``_BaseMap.Sample(...)``, _BaseMap declared by URP's SurfaceInput.hlsl)."""
    kinds = {}
    for m in _DECLARATION.finditer(text):
        for name in m.group(2).split(","):
            kinds[name.strip()] = m.group(1)
    for m in _MACRO_DECLARATION.finditer(text):
        kinds.setdefault(m.group(2), _MACRO_KIND[m.group(1)])
    return {name: kind for name, kind in kinds.items() if kind in _COMBINED}


def spelled_texture_methods(code: str, known: dict | None = None, reads: TextureReads | None = None) -> str:
    """``code`` with its Direct3D 11 texture and sampler objects and their lookups spelled in Cg,
    and its reads of the reflection probe as the Unity layer's calls (spelled_probe_reads);
    ``known``: textures the files it includes or sits beside declare (texture_kinds), whose
    lookups are spelled too (its own declarations take precedence); ``reads``: the whole
    program's (compared_textures.texture_reads; by default ``code``'s own)."""
    code = spelled_probe_reads(code)
    kinds = dict(known or {})
    for m in _DECLARATION.finditer(code):
        for name in m.group(2).split(","):
            kinds[name.strip()] = m.group(1)
    for m in _PARAMETER.finditer(code):
        kinds.setdefault(m.group(4), m.group(2))
    for m in _MACRO_DECLARATION.finditer(code):
        kinds.setdefault(m.group(2), _MACRO_KIND[m.group(1)])
    if not kinds:
        return code
    reads = reads if reads is not None else texture_reads(code)
    compared, both = reads.compared, reads.both

    def combined(kind: str, name: str) -> str:
        return (_COMPARED if name in compared and kind in _COMPARED else _COMBINED)[kind]

    def declared(kind: str, name: str, keep: str) -> str:  # (both: the plain sampler and the view)
        if name in both and kind in _COMPARED:
            return f"{keep}{_COMBINED[kind]} {name}; {keep}{_COMPARED[kind]} {compared_view(name)};"
        return f"{keep}{combined(kind, name)} {name};"
    # a parameter: the texture a combined sampler (GLSL takes one as an ``in`` parameter), the
    # sampler an unused int (the caller passes the sampler's int: the declarations below)
    code = _PARAMETER.sub(lambda m: f"{m.group(1)}{combined(m.group(2), m.group(4)) if m.group(2) in _COMBINED else 'int'}"
                                    f"{m.group(3)}{m.group(4)}", code)

    def declaration(m):
        names = [n.strip() for n in m.group(2).split(",")]
        if m.group(1) in _COMBINED:
            keep = "uniform " if m.group(0).startswith("uniform") else ""
            if not compared.intersection(names):
                return f"{keep}{_COMBINED[m.group(1)]} {', '.join(names)};"
            return " ".join(declared(m.group(1), n, keep) for n in names)
        return "static const int " + ", ".join(f"{n} = 0" for n in names) + ";"
    code = _DECLARATION.sub(declaration, code)
    out, pos = [], 0
    for m in _METHOD.finditer(code):
        if m.start() < pos or kinds.get(m.group(1)) not in _COMBINED:
            continue
        found = call_arguments(code, m.end() - 1)
        if found is None:
            continue
        args, end = found
        spelled = _call(kinds[m.group(1)], m.group(2), m.group(1), args, both)
        if spelled is None:
            continue
        spelled += "\n" * (code.count("\n", m.start(), end) - spelled.count("\n"))
        out += [code[pos:m.start()], spelled]
        pos = end
    return "".join(out) + code[pos:]
