"""A fixed-function ShaderLab pass as the Cg vertex/fragment program that computes it, as Unity
itself turns such passes into generated shaders: the program then runs through the same
vertex/fragment front end as any written one (both languages, one mechanism).

    program = translate(commands, properties, path)   # CGPROGRAM text (#pragma vertex/fragment)

``commands`` are the pass's fixed-function commands in ShaderLab order (a Category's and the
SubShader's first, the Pass's last; a later one wins): ``Lighting On|Off``, ``Material { Diffuse
Ambient Specular Shininess Emission }``, ``SeparateSpecular On|Off``, ``ColorMaterial
AmbientAndDiffuse|Emission``, ``SetTexture [_T] { constantColor ...  combine ... }``,
``AlphaTest <comparison> <value>``, ``BindChannels { Bind "source", target }``.

Semantics, from Unity's manual ("ShaderLab: legacy lighting", "ShaderLab: legacy texture
combining", "ShaderLab: legacy alpha testing", "ShaderLab: legacy BindChannels"):

* Lighting On: per-vertex lighting in view space over the vertex lights (unity_LightPosition[i],
  unity_LightColor[i], unity_LightAtten[i], unity_SpotDirection[i]; the harness sets them for a
  Vertex pass, generate_pass._vertex_lights): the primary colour is
  ``saturate(Emission + Ambient * UNITY_LIGHTMODEL_AMBIENT + sum_i Diffuse * color_i * max(0, N.L_i) * atten_i)``
  (+ the specular sum when SeparateSpecular is Off), alpha the Diffuse alpha; the specular sum is
  ``Specular * color_i * max(0, N.H_i)^(Shininess * 128) * atten_i`` where N.L_i > 0, H_i the half
  vector of L_i and the direction to the eye (a local viewer). A light's attenuation is
  ``1 / (1 + |d|^2 * atten.z)``, 0 beyond its range (|d|^2 > atten.w), times a spot's cone
  ``saturate((dot(L, spotDir) - atten.x) * atten.y)``, as Unity's vertex lights (UnityCG.cginc's
  ShadeVertexLightsFull computes the same terms). ColorMaterial AmbientAndDiffuse takes Ambient
  and Diffuse from the vertex colour, Emission the Emission.
* Lighting Off: the primary colour is the Color command's (``Color [_Prop]`` / ``Color (r, g, b, a)``),
  else the vertex colour where BindChannels binds "Color", else white; a pass with no command
  at all draws white.
* Each SetTexture stage combines ``previous`` (the last stage's result; the primary colour for the
  first), ``primary``, ``texture`` (the stage's texture at its mesh UV, tiling and offset applied)
  and ``constant`` (constantColor): ``a * b``, ``a + b``, ``a - b``, ``a +- b`` (a + b - 0.5),
  ``a lerp(b) c`` (c + (a - c) * b.alpha), ``a * b + c``, ``a * b +- c``, ``a * b - c``; a source
  may be ``one - x`` and ``x alpha``; DOUBLE / QUAD scale the expression they follow (colour, or
  the alpha after the comma), and each stage's result is clamped to [0, 1] (fixed-function
  colour). With one expression it gives both colour and alpha.
* SeparateSpecular On adds the specular sum after the last stage; AlphaTest discards what fails
  its comparison of the final alpha with its value.

Fog is not drawn here (the harness draws no fog, as for written passes). What this module does not
know is refused naming the command and its line (among them TexGen and texture matrices, which
Unity 5.0 removed: its "Upgrading to Unity 5.0" guide).
"""

from __future__ import annotations

import re

from . import model as M
from .source_text import UnityShaderError

# ShaderLab's AlphaTest comparisons as Cg operators (pass when ``alpha OP value``).
_ALPHA_TEST = {"greater": ">", "gequal": ">=", "less": "<", "lequal": "<=", "equal": "==",
               "notequal": "!=", "always": None, "never": "never"}
_SOURCES = {"previous", "primary", "texture", "constant"}
# Unity's Shininess is a [0, 1] property scaled to the specular exponent (legacy lighting).
SHININESS_SCALE = 128.0


def _value(text: str, properties: dict, where: str, kind: str = "color") -> str:
    """A Cg expression of a ShaderLab value: ``[_Prop]`` or ``(r, g, b, a)`` / a number."""
    text = text.strip()
    m = re.fullmatch(r"\[\s*(\w+)\s*\]", text)
    if m:
        if m.group(1) not in properties:
            raise UnityShaderError(f"{where}: [{m.group(1)}] is not one of the shader's Properties")
        return m.group(1)
    m = re.fullmatch(r"\(([^()]*)\)", text)
    if m:
        parts = [p.strip() for p in m.group(1).split(",")]
        parts += ["1"] * (4 - len(parts)) if len(parts) == 3 else []
        if len(parts) != 4:
            raise UnityShaderError(f"{where}: expected (r, g, b, a), got {text!r}")
        return "float4(" + ", ".join(f"{float(p)!r}" for p in parts) + ")"
    try:
        return repr(float(text))
    except ValueError:
        raise UnityShaderError(f"{where}: expected [_Property] or a value, got {text!r}") from None


class _Pass:
    """The fixed-function settings of one pass, read from its commands."""

    def __init__(self, commands, properties: dict, path):
        self.lighting = False
        self.material = {}            # Diffuse, Ambient, Specular, Shininess, Emission -> Cg
        self.separate_specular = False
        self.color_material = None    # "ambientanddiffuse" | "emission"
        self.stages = []              # [(texture property, constant Cg or None, combine text, line)]
        self.alpha_test = None        # (operator, value Cg)
        self.binds_color = False
        self.color = None             # the Color command's (the unlit primary colour)
        self.texcoord = {}            # stage index (or -1: every) -> mesh channel "in UV n"
        self.used = set()             # properties the program reads
        for c in commands:
            where = f"{path}:{c.line}"
            word, args = c.word.lower(), c.args.strip()
            if word == "lighting":
                self.lighting = args.lower() == "on"
            elif word == "separatespecular":
                self.separate_specular = args.lower() == "on"
            elif word == "colormaterial":
                mode = args.lower()
                if mode not in ("ambientanddiffuse", "emission"):
                    raise UnityShaderError(f"{where}: ColorMaterial {args}: expected AmbientAndDiffuse or Emission")
                self.color_material = mode
            elif word == "material":
                for m in re.finditer(r"(\w+)\s+(\[\s*\w+\s*\]|\([^()]*\)|[-+\d.eE]+)", c.body):
                    key = m.group(1).lower()
                    if key not in ("diffuse", "ambient", "specular", "shininess", "emission"):
                        raise UnityShaderError(f"{where}: Material {{ {m.group(1)} }}: not a fixed-function "
                                               "material colour (Diffuse, Ambient, Specular, Shininess, Emission)")
                    self.material[key] = self._read(m.group(2), properties, where)
            elif word == "settexture":
                self._set_texture(c, properties, where)
            elif word == "alphatest":
                words = args.split()
                if not words or words[0].lower() == "off":
                    self.alpha_test = None
                    continue
                op = words[0].lower()
                if op not in _ALPHA_TEST:
                    raise UnityShaderError(f"{where}: AlphaTest {args}: unknown comparison {words[0]!r}")
                value = self._read(" ".join(words[1:]) or "0", properties, where) if op not in ("always", "never") else "0.0"
                self.alpha_test = (_ALPHA_TEST[op], value) if op != "always" else None
            elif word == "bindchannels":
                for m in re.finditer(r'Bind\s*"(\w+)"\s*,\s*(\w+)', c.body, re.I):
                    source, target = m.group(1).lower(), m.group(2).lower()
                    if source == "color" and target == "color":
                        self.binds_color = True
                    elif source in ("texcoord", "texcoord0", "texcoord1") and target.startswith("texcoord"):
                        stage = int(target[len("texcoord"):]) if target[len("texcoord"):].isdigit() else -1
                        self.texcoord[stage] = "in1" if source == "texcoord1" else "in0"
                    elif not (source in ("vertex", "normal", "tangent") and target == source):
                        raise UnityShaderError(f'{where}: BindChannels Bind "{m.group(1)}", {m.group(2)}: '
                                               "a binding pbrlab does not run")
            elif word == "color":
                self.color = self._read(args, properties, where)
            elif word == "combine":
                raise UnityShaderError(f"{where}: combine outside a SetTexture block")

    def _read(self, text, properties, where):
        value = _value(text, properties, where)
        if re.fullmatch(r"\w+", value) and not value[0].isdigit():
            self.used.add(value)
        return value

    def _set_texture(self, c, properties, where):
        m = re.match(r"\[\s*(\w+)\s*\]", c.args.strip())
        if m is None:
            raise UnityShaderError(f"{where}: SetTexture needs a texture property: SetTexture [_Name] {{ ... }}")
        texture = m.group(1)
        if texture not in properties:  # as a sampler no Properties line declares: white, as in Unity
            properties[texture] = M.Property(texture, texture, "2D", "white", ("implicit",))
        prop = properties[texture]
        if prop.kind.lower() != "2d":
            raise UnityShaderError(f"{where}: SetTexture [{texture}]: a {prop.kind} texture in a fixed-function "
                                   "stage needs texture-coordinate generation (TexGen), which Unity removed in "
                                   "5.0 and pbrlab does not run")
        self.used.add(texture)
        constant, combine = None, None
        # its commands, several may share a line: constantColor (...) combine a * b, c
        pieces = re.split(r"\b(constantColor|combine|matrix)\b", c.body, flags=re.I)
        if pieces[0].strip():
            raise UnityShaderError(f"{where}: SetTexture [{texture}] {{ {pieces[0].strip()} }}: not a command "
                                   "pbrlab knows (constantColor, combine)")
        for word, rest in zip(pieces[1::2], pieces[2::2]):
            key, rest = word.lower(), " ".join(rest.split())
            if key == "constantcolor":
                constant = self._read(rest, properties, where)
            elif key == "combine":
                combine = rest
            elif key == "matrix":
                raise UnityShaderError(f"{where}: SetTexture [{texture}] {{ matrix }}: texture matrices are not "
                                       "supported by pbrlab (Unity removed them in 5.0)")
        if combine is None:
            raise UnityShaderError(f"{where}: SetTexture [{texture}] has no combine")
        self.stages.append((texture, constant, combine, where))


def _operand(text: str, where: str) -> str:
    """A combiner source as a Cg float4: ``texture``, ``one - previous``, ``constant alpha``, ``(x)``."""
    text = text.strip()
    while text.startswith("(") and text.endswith(")"):
        text = text[1:-1].strip()
    one_minus = re.match(r"one\s*-\s*(.*)$", text, re.I)
    if one_minus:
        return f"(1.0 - {_operand(one_minus.group(1), where)})"
    words = text.lower().split()
    if len(words) == 2 and words[1] == "alpha" and words[0] in _SOURCES:
        return f"s_{words[0]}.aaaa"
    if len(words) == 1 and words[0] in _SOURCES:
        return f"s_{words[0]}"
    raise UnityShaderError(f"{where}: combine: {text!r} is not a source (previous, primary, texture, "
                           "constant, with one - or alpha)")


def combine_expression(text: str, where: str) -> str:
    """One combiner expression (colour or alpha part, without DOUBLE/QUAD) as Cg."""
    text = text.strip()
    m = re.fullmatch(r"(.+?)\s+lerp\s*\((.+?)\)\s*(.+)", text, re.I)
    if m:  # a lerp(b) c: c where b.alpha is 0, a where 1
        a, b, c = (_operand(x, where) for x in m.groups())
        return f"lerp({c}, {a}, ({b}).a)"
    m = re.fullmatch(r"(.+?)\s*\*\s*(.+?)\s*(\+-|\+|-)\s*(.+)", text)
    if m and not re.match(r"one\s*$", m.group(1), re.I):
        a, b, c = _operand(m.group(1), where), _operand(m.group(2), where), _operand(m.group(4), where)
        tail = {"+": f" + {c}", "-": f" - {c}", "+-": f" + {c} - 0.5"}[m.group(3)]
        return f"{a} * {b}{tail}"
    m = re.fullmatch(r"(.+?)\s*(\+-|\*|\+|(?<!one)\s-)\s*(.+)", text, re.I)
    if m and not re.fullmatch(r"one", m.group(1).strip(), re.I):
        a, b = _operand(m.group(1), where), _operand(m.group(3), where)
        op = m.group(2).strip()
        return {"*": f"{a} * {b}", "+": f"{a} + {b}", "-": f"{a} - {b}", "+-": f"{a} + {b} - 0.5"}[op]
    return _operand(text, where)


def _scaled(part: str, where: str) -> tuple[str, float]:
    m = re.fullmatch(r"(.*?)\s+(double|quad)\s*", part, re.I)
    if m:
        return combine_expression(m.group(1), where), 2.0 if m.group(2).lower() == "double" else 4.0
    return combine_expression(part, where), 1.0


def stage_code(combine: str, where: str) -> str:
    """``s_previous = ...;`` for one ``combine`` line (colour[, alpha])."""
    colour, _, alpha = combine.partition(",")
    c, cs = _scaled(colour, where)
    lines = [f"    float4 s_colour = saturate(({c}) * {cs!r});"]
    if alpha.strip():
        a, as_ = _scaled(alpha, where)
        lines.append(f"    float s_alpha = saturate((({a}).a) * {as_!r});")
    else:
        lines.append("    float s_alpha = s_colour.a;")
    lines.append("    s_previous = float4(s_colour.rgb, s_alpha);")
    return "\n".join(lines)


def lit_command(commands):
    """The ``Lighting On`` command that is in force at the end of ``commands`` (ShaderLab order: a
    later one wins), or None where the pass is unlit (Lighting Off, or no Lighting command)."""
    last = None
    for c in commands:
        if c.word.lower() == "lighting":
            last = c if c.args.strip().lower() == "on" else None
    return last


def translate(commands, properties: dict, path) -> str:
    """The Cg program (vertex function ``pbrlab_ff_vert``, fragment ``pbrlab_ff_frag``) of a
    fixed-function pass (module doc)."""
    ff = _Pass(commands, properties, path)
    mat = ff.material
    black = "float4(0.0, 0.0, 0.0, 0.0)"
    decls = []
    for name in sorted(ff.used):
        kind = properties[name].kind.lower()
        if kind == "2d":
            decls += [f"sampler2D {name};", f"float4 {name}_ST;"]
        elif kind in ("float", "range", "int", "integer"):
            decls.append(f"float {name};")
        else:
            decls.append(f"float4 {name};")
    out = ["#pragma vertex pbrlab_ff_vert", "#pragma fragment pbrlab_ff_frag", '#include "UnityCG.cginc"', *decls,
           "struct pbrlab_ff_in { float4 vertex : POSITION; float3 normal : NORMAL; float4 color : COLOR;",
           "    float4 texcoord : TEXCOORD0; float4 texcoord1 : TEXCOORD1; };",
           "struct pbrlab_ff_v2f { float4 pos : SV_POSITION; float4 primary : COLOR0; float4 specular : COLOR1;"]
    out += [f"    float2 uv{i} : TEXCOORD{i};" for i in range(len(ff.stages))]
    out += ["};", "pbrlab_ff_v2f pbrlab_ff_vert(pbrlab_ff_in v) {", "    pbrlab_ff_v2f o;",
            "    o.pos = UnityObjectToClipPos(v.vertex);"]
    for i, (texture, _, _, _) in enumerate(ff.stages):
        channel = ff.texcoord.get(i, ff.texcoord.get(-1, "in0"))
        uv = "v.texcoord1.xy" if channel == "in1" else "v.texcoord.xy"
        out.append(f"    o.uv{i} = TRANSFORM_TEX({uv}, {texture});")
    if ff.lighting:
        vertex_colour = "v.color"
        ambient = vertex_colour if ff.color_material == "ambientanddiffuse" else mat.get("ambient", black)
        diffuse = vertex_colour if ff.color_material == "ambientanddiffuse" else mat.get("diffuse", black)
        emission = vertex_colour if ff.color_material == "emission" else mat.get("emission", black)
        specular = mat.get("specular", black)
        shininess = mat.get("shininess", "0.0")
        out += [
            "    float3 viewPos = UnityObjectToViewPos(v.vertex.xyz);",
            "    float3 viewN = normalize(mul((float3x3)UNITY_MATRIX_IT_MV, v.normal));",
            "    float3 toEye = normalize(-viewPos);",
            f"    float4 diffuseColour = {diffuse};",
            f"    float3 lit = ({emission}).rgb + ({ambient}).rgb * UNITY_LIGHTMODEL_AMBIENT.rgb;",
            "    float3 spec = float3(0.0, 0.0, 0.0);",
            f"    float exponent = {shininess} * {SHININESS_SCALE!r};",
            "    for (int i = 0; i < 8; i++) {",
            "        float3 toLight = unity_LightPosition[i].xyz - viewPos * unity_LightPosition[i].w;",
            "        float lengthSq = max(dot(toLight, toLight), 1e-6);",
            "        toLight *= rsqrt(lengthSq);",
            "        float atten = 1.0 / (1.0 + lengthSq * unity_LightAtten[i].z);",
            "        if (unity_LightPosition[i].w != 0.0 && lengthSq > unity_LightAtten[i].w) atten = 0.0;",
            "        atten *= saturate((max(dot(toLight, unity_SpotDirection[i].xyz), 0.0) - unity_LightAtten[i].x)"
            " * unity_LightAtten[i].y);",
            "        float NdotL = max(dot(viewN, toLight), 0.0);",
            "        lit += diffuseColour.rgb * unity_LightColor[i].rgb * (NdotL * atten);",
            "        if (NdotL > 0.0) {",
            "            float NdotH = max(dot(viewN, normalize(toLight + toEye)), 0.0);",
            "            spec += unity_LightColor[i].rgb * (pow(NdotH, exponent) * atten);",
            "        }",
            "    }",
            f"    spec *= ({specular}).rgb;",
        ]
        if ff.separate_specular:
            out += ["    o.primary = saturate(float4(lit, diffuseColour.a));",
                    "    o.specular = float4(saturate(spec), 0.0);"]
        else:
            out += ["    o.primary = saturate(float4(lit + spec, diffuseColour.a));",
                    "    o.specular = float4(0.0, 0.0, 0.0, 0.0);"]
    else:
        unlit = ff.color or ("v.color" if ff.binds_color else "float4(1.0, 1.0, 1.0, 1.0)")
        out += [f"    o.primary = {unlit};",
                "    o.specular = float4(0.0, 0.0, 0.0, 0.0);"]
    out += ["    return o;", "}", "float4 pbrlab_ff_frag(pbrlab_ff_v2f i) : SV_Target {",
            "    float4 s_primary = i.primary;", "    float4 s_previous = i.primary;"]
    for n, (texture, constant, combine, where) in enumerate(ff.stages):
        out += ["    {", f"    float4 s_texture = tex2D({texture}, i.uv{n});",
                f"    float4 s_constant = {constant or black};", stage_code(combine, where), "    }"]
    if ff.lighting and ff.separate_specular:
        out.append("    s_previous.rgb = saturate(s_previous.rgb + i.specular.rgb);")
    if ff.alpha_test is not None:
        op, value = ff.alpha_test
        out.append("    clip(-1.0);" if op == "never" else f"    if (!(s_previous.a {op} {value})) discard;")
    out += ["    return s_previous;", "}"]
    return "\n".join(out) + "\n"
