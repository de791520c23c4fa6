"""Batched GLSL-vs-HLSL evaluation of every library function (used by test_function_agreement.py).

Every function signature of glsl/ (parsed, so a new function is covered or the coverage
test fails) becomes an *entry*: a call of the function, or of a wrapper from
wrappers/pbrlab_test/wrappers.glsl for out parameters and arrays, with struct arguments
built by wrapper calls. All entries of a configuration are evaluated by ONE program per
language: the expression is a chain ``case_id < 0.5 ? pbrlab_to_vec4(E0) : case_id < 1.5 ?
...`` (``pbrlab_to_vec4`` exists in both evaluator templates), and element i belongs to entry
``i // SAMPLES``. The same GLSL expression is ported to HLSL with ``port_expression``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from pbrlab import evaluate, vec3
from pbrlab.gpu.port_hlsl import port_expression, port_text

import hlsl_helpers as H

WRAPPERS_DIR = Path(__file__).resolve().parent / "wrappers"
WRAPPERS = "pbrlab_test/wrappers.glsl"
SAMPLES = 384          # per entry and configuration
# Entries per program. llvmpipe gives up on control flow nested deeper than ~80 levels
# (gallivm's LP_MAX_TGSI_NESTING): a Mesa GLSL chain of 123 ternaries returned the final
# else for entries 79 and up, while the HLSL path (OpSelect, no nesting) was right.
BATCH = 32
FLOAT_SLOTS = 13  # pbr_unity_lighting_layers_base: its 6 (F90s, reflectivity, smoothness, occlusion, alpha), the layers' 7
VEC3_SLOTS = 13  # pbr_unity_lighting_layers_base: 3 colours, normal, view, GI (4), 3 layer vec3s, the transmitted term

# Struct parameters are built by these wrappers (their parameters are expanded in turn).
STRUCT_BUILDERS = {
    "pbr_GI": ("test_gi", (("vec3", "lightColor"), ("vec3", "lightDir"), ("vec3", "indirectDiffuse"),
                           ("vec3", "indirectSpecular"))),
    "SurfaceOutputStandard": ("test_surface", (("vec3", "albedo"), ("vec3", "normal"), ("vec3", "emission"),
                                               ("float", "metallic"), ("float", "smoothness"),
                                               ("float", "occlusion"), ("float", "alpha"))),
    "SurfaceOutputStandardSpecular": ("test_surface_specular", (
        ("vec3", "albedo"), ("vec3", "specular"), ("vec3", "normal"), ("vec3", "emission"),
        ("float", "smoothness"), ("float", "occlusion"), ("float", "alpha"))),
}
STRUCT_BUILDERS["UnityGI"] = STRUCT_BUILDERS["pbr_GI"]
STRUCT_BUILDERS["pbr_ClearCoat"] = ("test_clearcoat", (("float", "mask"), ("float", "perceptualRoughness"),
                                                      ("vec3", "normal")))
STRUCT_BUILDERS["SurfaceOutputStandardLayers"] = ("test_surface_layers", (
    ("float", "clearCoatMask"), ("float", "clearCoatSmoothness"), ("vec3", "clearCoatNormal"),
    ("vec3", "sheenColor"), ("float", "sheenSmoothness"), ("float", "anisotropy"), ("vec3", "anisotropyDirection"),
    ("float", "iridescenceMask"), ("float", "iridescenceIor"), ("float", "iridescenceThickness")))
STRUCT_BUILDERS["pbr_Iridescence"] = ("test_iridescence", (("float", "factor"), ("float", "ior"),
                                                          ("float", "thicknessNm")))
STRUCT_BUILDERS["pbr_ThinFilm"] = ("test_thin_film", (("float", "outsideIor"), ("float", "filmIor"),
                                                     ("float", "cosTheta1"), ("float", "thicknessNm")))
STRUCT_BUILDERS["pbr_Transmission"] = ("test_transmission", (("float", "factor"), ("float", "thickness"),
                                                            ("vec3", "attenuationColor"),
                                                            ("float", "attenuationDistance"), ("float", "volumeIor")))
STRUCT_BUILDERS["pbr_Anisotropy"] = ("test_anisotropy", (("float", "strength"), ("vec3", "direction")))
STRUCT_BUILDERS["pbr_PreparedSurface"] = ("test_prepared_surface", (
    ("vec3", "diffuseColor"), ("vec3", "f0"), ("vec3", "coatF0"), ("float", "perceptualRoughness"),
    ("float", "occlusion"), ("vec3", "n"), ("vec3", "v"), ("vec2", "dfg")))
STRUCT_BUILDERS["pbr_AnisotropicFrame"] = ("test_anisotropic_frame_of", (("vec3", "n"), ("float", "strength"),
                                                                        ("vec3", "direction")))
STRUCT_BUILDERS["pbr_Sheen"] = ("test_sheen", (("vec3", "color"), ("float", "perceptualRoughness")))
STRUCT_BUILDERS["UnityLight"] = ("test_light", (("vec3", "lightColor"), ("vec3", "lightDir")))
STRUCT_BUILDERS["UnityIndirect"] = ("test_indirect", (("vec3", "indirectDiffuse"), ("vec3", "indirectSpecular")))
STRUCT_BUILDERS["SurfaceOutput"] = ("test_surface_legacy", (
    ("vec3", "albedo"), ("vec3", "normal"), ("vec3", "emission"), ("float", "specular"), ("float", "gloss"),
    ("float", "alpha")))
STRUCT_BUILDERS["UnityGIInput"] = ("test_gi_input", (
    ("vec3", "lightColor"), ("vec3", "lightDir"), ("vec3", "worldPos"), ("vec3", "viewDir"), ("float", "atten"),
    ("vec3", "ambient")))
STRUCT_BUILDERS["Unity_GlossyEnvironmentData"] = ("test_glossy_environment", (("float", "roughness"),
                                                                              ("vec3", "dir")))

STRUCT_BUILDERS["pbr_PreparedTransmission"] = ("test_prepared_transmission", (
    ("vec3", "diffuseColor"), ("vec3", "coatF0"), ("float", "perceptualRoughness"), ("float", "occlusion"),
    ("vec3", "n"), ("vec3", "v"), ("pbr_Transmission", "tr"), ("vec2", "dfg")))
STRUCT_BUILDERS["pbr_Light"] = STRUCT_BUILDERS["UnityLight"]
STRUCT_BUILDERS["pbr_Indirect"] = STRUCT_BUILDERS["UnityIndirect"]

_F90_PREPARE = (("vec3", "diffuseColor"), ("vec3", "f0"), ("float", "f90"), ("vec3", "coatF0"), ("float", "coatF90"),
                ("float", "perceptualRoughness"), ("float", "occlusion"), ("vec3", "n"), ("vec3", "v"), ("vec2", "dfg"))
_F90_TRANSMISSION = (("vec3", "diffuseColor"), ("vec3", "coatF0"), ("float", "coatF90"),
                     ("float", "perceptualRoughness"), ("float", "occlusion"), ("vec3", "n"), ("vec3", "v"),
                     ("pbr_Transmission", "tr"), ("vec2", "dfg"))

# Functions with out parameters or array parameters: evaluated through wrappers.
SPECIAL = {
    # struct results (issue 25's prepared surface and anisotropic frame): their fields, summed
    "pbr_prepare_surface_dfg": [("test_prepare_surface_dfg", STRUCT_BUILDERS["pbr_PreparedSurface"][1])],
    "pbr_prepare_surface": [("test_prepare_surface", STRUCT_BUILDERS["pbr_PreparedSurface"][1][:-1])],
    # the same with an explicit F90 (KHR_materials_specular): f90 after f0, coatF90 after coatF0
    "pbr_prepare_surface_f90_dfg": [("test_prepare_surface_f90_dfg", _F90_PREPARE)],
    "pbr_prepare_surface_f90": [("test_prepare_surface_f90", _F90_PREPARE[:-1])],
    "pbr_prepare_transmission_f90_dfg": [(f"test_prepare_transmission_f90_dfg_{part}", _F90_TRANSMISSION)
                                         for part in ("surface", "rho", "weight")],
    "pbr_prepare_transmission_from_surface": [(f"test_prepare_transmission_from_surface_{part}", (
        ("pbr_PreparedSurface", "s"), ("vec3", "diffuseColor"), ("vec3", "coatF0"), ("pbr_Transmission", "tr")))
        for part in ("rho", "weight")],
    "pbr_brdf_anisotropic_terms": [("test_pbr_brdf_anisotropic_terms", (
        ("vec3", "n"), ("vec3", "v"), ("vec3", "l"), ("vec3", "a"), ("vec3", "b"), ("float", "perceptualRoughness"),
        ("float", "strength")))],
    "pbr_anisotropic_frame": [("test_anisotropic_frame", STRUCT_BUILDERS["pbr_AnisotropicFrame"][1])],
    "pbr_prepare_transmission_dfg": [(f"test_prepare_transmission_dfg_{part}",
                                      STRUCT_BUILDERS["pbr_PreparedTransmission"][1])
                                     for part in ("surface", "rho", "weight")],
    # the film's base-independent terms and both films at once (issue 35): their fields, summed
    "pbr_thin_film": [("test_thin_film_fields", STRUCT_BUILDERS["pbr_ThinFilm"][1])],
    "pbr_iridescent_f0_with_coat": [("test_iridescent_f0_with_coat", (
        ("vec3", "f0"), ("vec3", "coatF0"), ("float", "NdotV"), ("pbr_Iridescence", "film")))],
    "pbr_iridescent_f0_f90_with_coat": [("test_iridescent_f0_f90_with_coat", (
        ("vec3", "f0"), ("float", "f90"), ("vec3", "coatF0"), ("float", "coatF90"), ("float", "NdotV"),
        ("pbr_Iridescence", "film")))],
    "pbr_sh9_irradiance": [("test_sh9_irradiance", (("vec3", "a"), ("vec3", "b"), ("vec3", "n")))],
    "pbr_brdf_standard_terms": [("test_pbr_brdf_standard_terms", (("vec3", "n"), ("vec3", "v"), ("vec3", "l"),
                                                                  ("float", "perceptualRoughness")))],
    "DiffuseAndSpecularFromMetallic": [
        ("test_DiffuseAndSpecularFromMetallic", (("vec3", "albedo"), ("float", "metallic"))),
        ("test_DiffuseAndSpecularFromMetallic_specColor", (("vec3", "albedo"), ("float", "metallic")))],
    "EnergyConservationBetweenDiffuseAndSpecular": [
        ("test_EnergyConservationBetweenDiffuseAndSpecular", (("vec3", "albedo"), ("vec3", "specColor")))],
    "PreMultiplyAlpha": [("test_PreMultiplyAlpha", (("vec3", "diffColor"), ("float", "alpha"),
                                                     ("float", "oneMinusReflectivity")))],
    # pbr/unity/global_illumination: struct results and inout UnityGI, through wrappers
    "UnityGlossyEnvironmentSetup": [("test_UnityGlossyEnvironmentSetup", (
        ("float", "smoothness"), ("vec3", "viewDir"), ("vec3", "normal"), ("vec3", "fresnel0")))],
    "UnityGlobalIllumination": [
        ("test_UnityGlobalIllumination", (("UnityGIInput", "data"), ("float", "occlusion"), ("vec3", "normal"))),
        ("test_UnityGlobalIllumination_indirect", (("UnityGIInput", "data"), ("float", "occlusion"),
                                                   ("vec3", "normal"))),
        ("test_UnityGlobalIllumination_gloss", (("UnityGIInput", "data"), ("float", "occlusion"), ("vec3", "normal"),
                                                ("Unity_GlossyEnvironmentData", "glossIn")))],
    # (the inout gi is overwritten by every _GI function: the wrapper starts it at ones)
    **{f"Lighting{model}_GI": [(f"test_Lighting{model}_GI", ((output, "s"), ("UnityGIInput", "data")))]
       for model, output in (("Standard", "SurfaceOutputStandard"),
                             ("StandardSpecular", "SurfaceOutputStandardSpecular"),
                             ("Lambert", "SurfaceOutput"), ("BlinnPhong", "SurfaceOutput"))},
}

# What the non-default configurations change: the dispatchers and everything above them.
VARIANT_DEPENDENT = {
    "pbr_specular_D", "pbr_specular_V", "pbr_specular_F", "pbr_specular_lobe_limit", "pbr_diffuse_Fd",
    "pbr_clamp_perceptual_roughness", "pbr_brdf_standard", "pbr_shade_punctual", "pbr_env_brdf",
    "pbr_indirect_specular_split_sum", "pbr_lighting_standard", "pbr_lighting_standard_dfg",
    "pbr_unity_lighting", "LightingStandard", "pbr_unity_brdf_pbs", "pbr_unity_gi_occlusion",
    "pbr_unity_environment_lod", "pbr_specular_albedo_bound", "pbr_indirect_diffuse_color",
    "LightingStandardSpecular", "PreMultiplyAlpha", "pbr_tonemap", "pbr_decode_color_texel",
    "pbr_encode_final_color", "pbr_lighting_anisotropic", "pbr_lighting_anisotropic_dfg",
    "pbr_anisotropic_reflection_normal", "pbr_prepare_surface_dfg", "pbr_prepare_surface",
    "pbr_lighting_standard_light", "pbr_lighting_standard_add_environment", "pbr_lighting_anisotropic_light",
    # the explicit F90's (KHR_materials_specular) F, its lobe and its whole lighting
    "pbr_specular_F_f90", "pbr_shade_punctual_f90", "pbr_lighting_standard_f90_dfg",
    # the explicit F90's preparation and the anisotropic lighting with it
    "pbr_prepare_surface_f90_dfg", "pbr_prepare_surface_f90", "pbr_lighting_anisotropic_f90",
}

# Every value of every selector, each in at least one configuration (the default
# configuration {} is the first): configuration i takes the i-th non-default value of each
# selector (the selectors are independent #if chains, so combining them loses nothing a
# one-at-a-time sweep would see, and costs 7 programs per language instead of 27).
SELECTOR_VALUES = {
    "PBR_QUALITY": ["PBR_QUALITY_LOW", "PBR_QUALITY_MEDIUM"],
    "PBR_SPECULAR_D": ["PBR_SPECULAR_D_BECKMANN", "PBR_SPECULAR_D_BLINN_PHONG"],
    "PBR_SPECULAR_V": [f"PBR_SPECULAR_V_{v}" for v in (
        "SMITH_GGX_CORRELATED_FAST", "SMITH_GGX", "SCHLICK_GGX", "COOK_TORRANCE", "KELEMEN", "IMPLICIT",
        "SMITH_GGX_CORRELATED")],
    "PBR_SPECULAR_F": ["PBR_SPECULAR_F_SCHLICK_SG", "PBR_SPECULAR_F_NONE"],
    "PBR_DIFFUSE": ["PBR_DIFFUSE_BURLEY"],
    "PBR_COLOR_TRANSFER": [f"PBR_COLOR_TRANSFER_{v}" for v in ("SRGB", "GAMMA22", "FAST")],
    "PBR_TONEMAP": [f"PBR_TONEMAP_{v}" for v in ("NONE", "REINHARD", "HABLE", "ACES_FITTED", "ACES_NARKOWICZ")],
    "PBR_BRDF_MODEL": ["PBR_BRDF_MODEL_UNITY"] * 3,
    "PBR_UNITY_BRDF": [f"PBR_UNITY_BRDF_{i}" for i in (3, 2, 1)],
    "PBR_ENERGY_COMPENSATION": ["0"],
    "PBR_ALPHA_MODE": [f"PBR_ALPHA_MODE_{v}" for v in ("CUTOUT", "FADE", "TRANSPARENT")],
    "PBR_DFG_LUT_LOOKUP(NdotV, perceptualRoughness)": ["vec2(NdotV, perceptualRoughness * 0.5)"],
}
CONFIGURATIONS = [
    {name: values[i] for name, values in SELECTOR_VALUES.items() if i < len(values)}
    for i in range(max(len(v) for v in SELECTOR_VALUES.values()))
]



@dataclass(frozen=True)
class Entry:
    label: str                 # the library signature (plus the wrapper, if any)
    name: str                  # the library function's name
    callee: str
    params: tuple              # ((type, name), ...) of the callee


def entries(tree: H.Tree) -> list[Entry]:
    out = []
    for fn in tree.functions.values():
        if fn.name in SPECIAL:
            for callee, params in SPECIAL[fn.name]:
                out.append(Entry(f"{fn.signature} via {callee}", fn.name, callee, params))
        else:
            assert not any(p.qualifier in ("out", "inout") or p.array for p in fn.params), fn.signature
            out.append(Entry(fn.signature, fn.name, fn.name, tuple((p.type, p.name) for p in fn.params)))
    return out


# ---- inputs: one domain per parameter name ---------------------------------------------

UNIT_VECTORS = {"n", "v", "l", "h", "a", "b", "dir", "spotDirection", "normal", "viewDir", "lightDir"}
HDR_COLOURS = {"color", "x", "linearColor", "lightRadiance", "lightColor", "prefiltered",
               "indirectSpecular", "indirectDiffuse", "emission"}
SPECIALS = np.array([np.nan, np.inf, -np.inf, -1.0, -0.0, 0.0, 1.0, 65504.0, 1e30, 1e-40], np.float32)


def _unit(rng, count, hemisphere=True):
    v = rng.normal(size=(count, 3))
    if hemisphere:
        v[:, 2] = np.abs(v[:, 2]) + 0.05
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def float_values(name: str, rng, count: int) -> np.ndarray:
    lower = name.lower()
    if "dot" in lower or name in ("cosTheta", "cosOuter"):
        x = rng.uniform(-0.1, 1.05, count)
        x[:8] = [0.0, 1.0, -0.0, 1e-5, 1.0 - 2 ** -24, 1e-4, 0.5, -1.0]
    elif name in ("specPower",):
        x = np.exp(rng.uniform(math.log(0.5), math.log(1e4), count))
    elif name in ("eta",):
        x = rng.uniform(0.3, 4.0, count)
    elif name in ("volumeIor",):  # pbr_Transmission.ior: a volume denser than air
        x = rng.uniform(1.0, 4.0, count)
    elif name in ("DV",):
        x = np.exp(rng.uniform(-3, 13, count))
    elif name in ("distance2",):
        x = np.exp(rng.uniform(math.log(1e-9), math.log(400), count))
    elif name in ("range", "whitePoint", "lodCount", "invCosRange", "hi"):
        x = rng.uniform(0.5, 30.0, count)
    elif name in ("exposureEV",):
        x = rng.uniform(-8, 8, count)
    elif name in ("s",):
        x = rng.uniform(0, 64, count)
    elif name in ("x", "c"):
        x = rng.uniform(-0.2, 1.5, count)
        x[: len(SPECIALS)] = SPECIALS
    elif name == "i":
        x = rng.integers(0, 4096, count)
    elif name == "count":
        x = rng.integers(1, 4096, count)
    elif name == "bumpScale":
        x = rng.uniform(0, 2, count)
    else:  # roughness, alpha, k, smoothness, metallic, occlusion, f0, f90, gloss, uv, xi, dfg ...
        x = rng.uniform(0.0, 1.0, count)
        x[:4] = [0.0, 1.0, 1e-7, 0.5]
    return x.astype(np.float32)


def vec3_values(function: str, name: str, rng, count: int) -> np.ndarray:
    if function == "pbr_safe_normalize":
        v = rng.normal(size=(count, 3)) * np.exp(rng.uniform(-60, 60, (count, 1)))
        v[:2] = 0.0
    elif function == "pbr_one_minus_dot2" or name in UNIT_VECTORS:
        v = _unit(rng, count, hemisphere=name not in ("a", "b", "dir", "spotDirection"))
        if name == "n":
            v = _unit(rng, count) * 0.2 + np.array([0, 0, 1.0])
            v /= np.linalg.norm(v, axis=-1, keepdims=True)
    elif name in HDR_COLOURS:
        v = np.exp(rng.uniform(-7, 7, (count, 3)))
        v[: len(SPECIALS)] = SPECIALS[:, None]
    else:
        v = rng.uniform(0.0, 1.1, (count, 3))
    return v.astype(np.float32)


def _expand(ptype: str, pname: str) -> tuple[str, list[tuple[str, str]]]:
    """(template with {} per leaf, leaves [(type, name)]) for one parameter."""
    if ptype in STRUCT_BUILDERS:
        callee, params = STRUCT_BUILDERS[ptype]
        parts, leaves = [], []
        for t, n in params:
            tpl, sub = _expand(t, n)
            parts.append(tpl)
            leaves += sub
        return f"{callee}({', '.join(parts)})", leaves
    if ptype == "vec2":
        return "vec2({}, {})", [("float", pname + ".x"), ("float", pname + ".y")]
    if ptype == "vec4":
        return "vec4({}, {})", [("vec3", pname), ("float", pname + ".w")]
    if ptype == "uint":
        return "uint({})", [("float", pname)]
    if ptype == "int":  # a flag (DecodeHDR's colorspaceIsGamma): inputs in [0, 1.1) give 0 and 1
        return "int({})", [("float", pname)]
    return "{}", [(ptype, pname)]


def call_and_leaves(entry: Entry) -> tuple[str, list[tuple[str, str, str]]]:
    """The GLSL call with slot names, and [(slot, type, parameter name)]."""
    parts, leaves = [], []
    for t, n in entry.params:
        tpl, sub = _expand(t, n)
        parts.append(tpl)
        leaves += sub
    slots, counters = [], {"float": 0, "vec3": 0}
    for t, n in leaves:
        if t not in counters:
            raise AssertionError(f"{entry.label}: no input slot for type {t}")
        slot = ("f" if t == "float" else "v") + str(counters[t])
        counters[t] += 1
        slots.append((slot, t, n))
    assert counters["float"] <= FLOAT_SLOTS and counters["vec3"] <= VEC3_SLOTS, entry.label
    call = f"{entry.callee}({', '.join(parts)})".format(*[s for s, _, _ in slots])
    return call, slots


def build(batch: list[Entry], seed: int = 6):
    """(GLSL expression, inputs) for a batch of entries."""
    rng = np.random.default_rng(seed)
    total = SAMPLES * len(batch)
    floats = np.zeros((FLOAT_SLOTS, total), np.float32)
    vecs = np.zeros((VEC3_SLOTS, total, 3), np.float32)
    vecs[:, :, 2] = 1.0
    calls = []
    for k, entry in enumerate(batch):
        call, slots = call_and_leaves(entry)
        calls.append(call)
        rows = slice(k * SAMPLES, (k + 1) * SAMPLES)
        for slot, t, pname in slots:
            index = int(slot[1:])
            base = pname.split(".")[0]
            if t == "float":
                floats[index, rows] = float_values(base, rng, SAMPLES)
                if entry.name == "pbr_hable_curve":  # its domain: x >= 0 (callers sanitise first);
                    floats[index, rows] = np.abs(floats[index, rows])  # a pole sits at x = -0.13
            else:
                vecs[index, rows] = vec3_values(entry.name, base, rng, SAMPLES)
    expression = "pbrlab_to_vec4(vec4(0.0, 0.0, 0.0, 0.0))"
    for k in reversed(range(len(batch))):
        expression = f"case_id < {k}.5 ? pbrlab_to_vec4({calls[k]}) : ({expression})"
    inputs = {"case_id": np.repeat(np.arange(len(batch), dtype=np.float32), SAMPLES)}
    inputs |= {f"f{i}": floats[i] for i in range(FLOAT_SLOTS)}
    inputs |= {f"v{i}": vec3(vecs[i]) for i in range(VEC3_SLOTS)}
    return expression, inputs


def hlsl_wrappers_dir(tmp: Path) -> Path:
    """The wrappers ported to HLSL by the library's generator, under ``tmp``."""
    src = WRAPPERS_DIR / WRAPPERS
    dst = tmp / "pbrlab_test" / "wrappers.hlsl"
    dst.parent.mkdir(parents=True, exist_ok=True)
    dst.write_text(port_text(src.read_text(encoding="utf-8"), "tests/gpu/hlsl/wrappers/" + WRAPPERS), encoding="utf-8")
    return tmp


def batches(items: list[Entry]) -> list[list[Entry]]:
    return [items[i:i + BATCH] for i in range(0, len(items), BATCH)]


def run(batch: list[Entry], defines: dict, hlsl_dir: Path):
    """(glsl values, hlsl values), each (len(batch), SAMPLES, 4)."""
    assert len(batch) <= BATCH
    expression, inputs = build(batch)
    glsl = evaluate(expression, [WRAPPERS], include_dirs=[WRAPPERS_DIR], defines=defines, **inputs)
    hlsl_defines = {k: port_expression(v) for k, v in defines.items()}
    hlsl = evaluate(port_expression(expression), ["pbrlab_test/wrappers.hlsl"], include_dirs=[hlsl_dir],
                    defines=hlsl_defines, language="hlsl", **inputs)
    shape = (len(batch), SAMPLES, 4)
    return glsl.reshape(shape), hlsl.reshape(shape)
