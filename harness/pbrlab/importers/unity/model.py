"""What a Unity surface shader says, as data: the parse step's output and the generate
step's input (``parse.py`` -> this -> ``generate.py``).

Nothing here reads files or writes shader code: ``UnityShader.refused_keywords`` and
``keywords`` ask ``source_text``, the one stage below the model, which reads the includes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ...gpu.stencil_state import StencilState
from ...scene.surface_layers import FIELD_SIZES
from . import source_text

# Input members Unity's surface compiler fills by name (Unity manual, "Writing Surface
# Shaders", Input structure); uv<N>_<Texture> take the texture's _ST tiling and offset.
FILLED_INPUTS = ("viewDir", "worldPos", "worldNormal", "worldRefl", "screenPos", "color")
UV_PREFIXES = ("uv_", "uv2_", "uv3_", "uv4_")

# Built-in lighting models: the output struct each surface function must fill.
BUILTIN_MODELS = {
    "Standard": "SurfaceOutputStandard",
    "StandardSpecular": "SurfaceOutputStandardSpecular",
    "Lambert": "SurfaceOutput",
    "BlinnPhong": "SurfaceOutput",
    "StandardLayered": "SurfaceOutputStandardLayered",
    "StandardSpecularLayered": "SurfaceOutputStandardSpecularLayered",
}
# pbrlab's layered models (no such model in Unity's built-in pipeline; named by its rule
# struct = "SurfaceOutput" + model): the Standard struct with SurfaceOutputStandardLayers'
# fields beside it (URP's ClearCoatMask, ClearCoatSmoothness, ...), shaded as the harness
# shades a JSON material with those layers (generate.py). Model -> the Standard struct it extends.
LAYERED_MODELS = {"StandardLayered": "SurfaceOutputStandard",
                  "StandardSpecularLayered": "SurfaceOutputStandardSpecular"}
# Fields of Unity's output structs (Lighting.cginc, UnityPBSLighting.cginc) and their sizes.
OUTPUT_FIELDS = {
    "SurfaceOutput": {"Albedo": 3, "Normal": 3, "Emission": 3, "Specular": 1, "Gloss": 1, "Alpha": 1},
    "SurfaceOutputStandard": {"Albedo": 3, "Normal": 3, "Emission": 3, "Metallic": 1,
                              "Smoothness": 1, "Occlusion": 1, "Alpha": 1},
    "SurfaceOutputStandardSpecular": {"Albedo": 3, "Specular": 3, "Normal": 3, "Emission": 3,
                                      "Smoothness": 1, "Occlusion": 1, "Alpha": 1},
}
OUTPUT_FIELDS.update({BUILTIN_MODELS[model]: {**OUTPUT_FIELDS[base], **FIELD_SIZES}
                      for model, base in LAYERED_MODELS.items()})

# Lighting function forms (Unity manual, "Custom lighting models in Surface Shaders").
FORM_GI_VIEW = "s, viewDir, gi"          # + Lighting<Name>_GI(s, UnityGIInput data, inout UnityGI gi)
FORM_GI = "s, gi"                        # + Lighting<Name>_GI
FORM_LIGHT_DIR = "s, lightDir, atten"
FORM_LIGHT_VIEW_DIR = "s, lightDir, viewDir, atten"


@dataclass
class Property:
    """One line of a ShaderLab ``Properties`` block."""
    name: str
    display: str
    kind: str                 # Float, Range, Int, Color, Vector, 2D, Cube, 3D
    default: object           # float, 4-tuple, or a texture default name ("white", "bump", ...)
    attributes: tuple = ()    # e.g. ("Normal", "HDR")
    range: tuple | None = None

    @property
    def is_texture(self) -> bool:
        """A texture property (arrays too: a default-valued one is bound as its 2D default)."""
        return self.kind in ("2D", "Cube", "3D", "2DArray", "CubeArray")


@dataclass
class Pragma:
    """``#pragma surface <function> <Model> [options]``."""
    function: str
    model: str
    vertex: str | None = None
    finalcolor: str | None = None
    alpha_mode: str = "opaque"      # pbrlab's names: opaque, cutout, fade, transparent
    cutoff_property: str | None = None
    accepted: tuple = ()            # options with no effect in this harness (no shadows, ...)
    unsupported: tuple = ()         # options that would change the result: warned


@dataclass
class RenderState:
    cull: str = "back"              # back, front, off
    zwrite: bool | None = None      # None: the alpha mode decides
    blend: str | None = None        # the Blend line as written (a surface program's is warned)
    blend_factors: tuple | None = None  # (src, dst[, src alpha, dst alpha]): ShaderLab factor names
    ztest: str = "lequal"           # less, greater, lequal, gequal, equal, notequal, always
    color_mask: str = "rgba"        # "0" draws depth only
    stencil: StencilState | None = None  # its Stencil block's (stencil_block.py); None: the test off


@dataclass
class LightingFunction:
    name: str                       # the model, without "Lighting"
    form: str                       # one of the FORM_* constants
    output_type: str
    has_gi: bool


@dataclass
class VertexFunction:
    name: str
    appdata: str                    # appdata_full, appdata_base, appdata_tan or a user struct
    writes_input: tuple = ()        # custom Input members it writes (Unity: out Input o)
    input_param: str | None = None
    appdata_members: list = field(default_factory=list)  # a struct of the shader's own (appdata_t):
                                                          # [(type, name, semantic)]


@dataclass
class SurfaceShader:
    path: Path
    name: str
    program: str                    # the CGPROGRAM text (the globals it writes read through copies:
    program_line: int               # written_globals.py); its first line in the file (1-based)
    pragma: Pragma
    properties: dict = field(default_factory=dict)       # name -> Property
    input_members: list = field(default_factory=list)    # [(type, name)]
    internal_data: bool = False
    facing_members: list = field(default_factory=list)  # Input members with the VFACE semantic
    color_members: list = field(default_factory=list)   # ... with COLOR: the vertex colour, as `color`
    output_type: str = "SurfaceOutputStandard"
    output_fields: dict = field(default_factory=dict)    # field -> component count
    writes_normal: bool = False
    layers: frozenset = frozenset()  # the layers beyond the Standard model it writes (surface_layers.py)
    lighting: LightingFunction | None = None
    vertex: VertexFunction | None = None
    declared: frozenset = frozenset()  # global names the program declares itself
    state: RenderState = field(default_factory=RenderState)
    warnings: list = field(default_factory=list)
    light_keywords: bool = False    # tests USING_DIRECTIONAL_LIGHT, POINT, SPOT...: a program per light type
    written_globals: tuple = ()     # ((name, type), ...) globals the program writes (written_globals.py)
    language: str = "hlsl"          # the program's language: "hlsl" (Cg/HLSL, as in Unity) or
                                    # "glsl" (a port-unity port)

    kind = "surface"

    def uv_members(self):
        """[(member, uv set index 1..4, texture name)] of the Input."""
        out = []
        for _, name in self.input_members:
            for i, prefix in enumerate(UV_PREFIXES):
                if name.startswith(prefix):
                    out.append((name, i + 1, name[len(prefix) - 1:]))  # uv_MainTex -> _MainTex
        return out

    def is_color(self, member: str) -> bool:
        return member == "color" or member in self.color_members

    def custom_members(self):
        filled = set(FILLED_INPUTS) | set(self.color_members) | {m for m, _, _ in self.uv_members()}
        return [(t, n) for t, n in self.input_members if n not in filled]


@dataclass
class ShaderStruct:
    """A struct of a vertex/fragment program: [(type, name, semantic or "")] in order;
    ``flat``: the members declared ``nointerpolation`` (HLSL's flat varyings)."""
    name: str
    members: list
    flat: frozenset = frozenset()


@dataclass
class VertexFragmentPass:
    """A ``Pass { CGPROGRAM #pragma vertex v  #pragma fragment f ... ENDCG }``: Unity's
    plain shader, drawn as written (``generate_pass.py``)."""
    path: Path
    name: str | None                # the Pass's Name
    light_mode: str                 # its LightMode tag ("Always" when none)
    program: str
    program_line: int
    vertex: str                     # function names
    fragment: str
    vertex_params: list             # [(qualifier, type, name, semantic)]
    vertex_return: str              # its return type ("void" with out parameters)
    vertex_return_semantic: str
    fragment_params: list
    fragment_return: str
    fragment_return_semantic: str
    structs: dict                   # name -> ShaderStruct (the program's own)
    declared: frozenset = frozenset()
    geometry: object = None         # geometry_syntax.GeometryFunction of a #pragma geometry
    tessellation: object = None     # tessellation_syntax.Tessellation of #pragma hull / domain
    state: RenderState = field(default_factory=RenderState)
    language: str = "hlsl"
    properties: dict = field(default_factory=dict)       # the file's, shared by its passes
    warnings: list = field(default_factory=list)
    # a Scriptable Render Pipeline's program (URP): its GLSL port spells SRP's texture macros in
    # Cg, and the port of each included file knows the structs and globals the whole program
    # declares (a struct of one include built in another, a property of the program read in an
    # include); the built-in pipeline's programs keep per-file ports, as Unity's Cg
    srp: bool = False
    engine_filled: tuple = ()       # engine-set globals the scene fills (engine_inputs.FILLED)
    written_globals: tuple = ()     # ((name, type), ...) globals the program writes (written_globals.py)
    rewritten_includes: dict = field(default_factory=dict)  # {path: text}: its own includes so rewritten
    output_fields = {}              # (a surface program's output struct; none here)
    kind = "vertex-fragment"


@dataclass
class GrabPass:
    """``GrabPass { "_Name" }``: what is drawn so far, as a texture for the passes after it."""
    texture: str                    # the sampler it binds (_GrabTexture by default)
    line: int
    state: RenderState = field(default_factory=RenderState)
    vertex = None
    kind = "grab"


@dataclass
class UnityShader:
    """A whole ``.shader`` file as Unity runs it: the Properties, and the passes of the first
    SubShader the harness can run, in draw order (surface programs and vertex/fragment passes)."""
    path: Path
    name: str
    passes: list                                         # [SurfaceShader | VertexFragmentPass]
    properties: dict = field(default_factory=dict)
    warnings: list = field(default_factory=list)
    notes: list = field(default_factory=list)            # which SubShader ran, passes skipped

    @property
    def surface(self):
        """The first surface program, or None."""
        return next((p for p in self.passes if p.kind == "surface"), None)

    @property
    def moves_vertices(self) -> bool:
        """Whether a sphere must be drawn as a mesh: a vertex: function or a vertex stage of its own."""
        return any(p.kind == "vertex-fragment" or (p.kind == "surface" and p.vertex is not None)
                   for p in self.passes)

    @property
    def refused_keywords(self) -> dict:
        """{keyword: reason} of keywords a pbrlab stand-in its passes include does not honour."""
        out = {}
        for p in self.passes:
            if p.kind != "grab":
                out.update(source_text.refused_keywords(p.program, self.path.parent))
        return out

    @property
    def keywords(self) -> frozenset:
        """The keywords its passes' ``#pragma multi_compile`` / ``shader_feature`` lines declare
        (a material's ``keywords`` enables some; with none of a set enabled, see first_keywords)."""
        return frozenset().union(*(source_text.declared_keywords(p.program) for p in self.passes if p.kind != "grab"))

    def unset_keywords(self, wanted, enabled=()) -> tuple:
        """Those of ``wanted`` (a property drawer's keywords) that a pass declares in a set none of
        whose keywords is ``enabled`` (the material's own choice stands)."""
        out = []
        for p in self.passes:
            if p.kind == "grab":
                continue
            for words in source_text.keyword_sets(p.program):
                out += [k for k in wanted if k in words and not set(words) & set(enabled)]
        return tuple(dict.fromkeys(out))

    def first_keywords(self, enabled=()) -> tuple:
        """The keywords Unity draws its passes with where ``enabled`` holds none of a keyword
        set without ``_``: each such set's first (source_text.first_keywords)."""
        out = [k for p in self.passes if p.kind != "grab" for k in source_text.first_keywords(p.program, enabled)]
        return tuple(dict.fromkeys(out))
