"""Parity of the two trees: files, include guards, headers, functions (signatures), structs
(fields) and macros (values) exist in both languages and agree; constants are equal on the GPU.

The parser (hlsl_helpers.py) reads both trees independently of the generator, with HLSL
type spellings mapped to GLSL ones (float3 -> vec3), so a hand-edited or hand-written port
is held to the same inventory.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from pbrlab import evaluate
from pbrlab.gpu.port_hlsl import port_expression

import hlsl_helpers as H


@pytest.fixture(scope="module")
def trees():
    return H.parse_tree(H.GLSL_ROOT, "glsl"), H.parse_tree(H.HLSL_ROOT, "hlsl")


def test_trees_have_the_same_inventory(trees):
    glsl, hlsl = trees
    assert len(glsl.files) >= 40 and len(glsl.functions) >= 100 and glsl.structs
    assert H.parity_problems(glsl, hlsl, port_expression) == []


def test_unity_names_exist_in_hlsl(trees):
    _, hlsl = trees
    names = {f.name for f in hlsl.functions.values()}
    assert {"LightingStandard", "LightingStandardSpecular", "DiffuseAndSpecularFromMetallic",
            "EnergyConservationBetweenDiffuseAndSpecular", "UnpackNormal", "PreMultiplyAlpha"} <= names
    assert {"SurfaceOutputStandard", "SurfaceOutputStandardSpecular", "pbr_Light", "pbr_Indirect",
            "pbr_GI"} <= set(hlsl.structs)
    macros = {name for _, name in hlsl.macros}
    assert {"UnityLight", "UnityIndirect", "UnityGI", "unity_ColorSpaceDielectricSpec"} <= macros


def _mutated(tree, edit):
    import copy
    t = copy.deepcopy(tree)
    edit(t)
    return t


def test_parity_check_fails_on_each_kind_of_difference(trees):
    """The checker itself: a missing function, a changed signature, a changed out qualifier,
    a missing struct field, a changed constant and a missing file are each reported."""
    glsl, hlsl = trees
    key = next(k for k in hlsl.functions if k[0] == "pbr_D_GGX")
    fn = hlsl.functions[key]

    def drop_function(t):
        del t.functions[next(k for k in t.functions if k[0] == "pbr_V_Kelemen")]

    def change_signature(t):
        del t.functions[key]
        p = fn.params[0]
        changed = H.Function(fn.file, fn.return_type, fn.name,
                             (H.Param(p.qualifier, "vec2", p.name, p.array),) + fn.params[1:])
        t.functions[changed.key] = changed

    def change_qualifier(t):
        k = next(k for k in t.functions if k[0] == "PreMultiplyAlpha")
        f = t.functions[k]
        t.functions[k] = H.Function(f.file, f.return_type, f.name,
                                    f.params[:-1] + (H.Param("inout", *[getattr(f.params[-1], a) for a in ("type", "name", "array")]),))

    def drop_field(t):
        t.structs["SurfaceOutputStandard"] = t.structs["SurfaceOutputStandard"][:-1]

    def change_constant(t):
        k = next(k for k in t.macros if k[1] == "PBR_PI")
        t.macros[k] = "3.1415926"

    def drop_file(t):
        del t.files["pbr/tonemap/aces"]

    for edit, expected in [(drop_function, "missing in the HLSL"), (change_signature, "signature differs"),
                           (change_qualifier, "differ"), (drop_field, "struct SurfaceOutputStandard"),
                           (change_constant, "macro PBR_PI"), (drop_file, "without an HLSL twin")]:
        problems = H.parity_problems(glsl, _mutated(hlsl, edit), port_expression)
        assert any(expected in p for p in problems), (edit.__name__, problems)


_VALUE = re.compile(r"^(?:[-+]?[\d.]+(?:e[-+]?\d+)?|vec[234]\(.*\)|\(.*\)|PBR_[A-Z0-9_]+)$")


def _constants(tree):
    """(file, name) of object-like macros whose value is a number, a vector of numbers or an
    expression of them (function-like macros, type aliases and per-branch defines excluded)."""
    out = []
    for (stem, name), value in sorted(tree.macros.items()):
        if value.startswith("(") and not value.startswith("(0.8"):  # function-like "(args) body"
            if re.match(r"^\(\w+(,\s*\w+)*\)(\s|$)", value):  # (an empty body: a no-op macro)
                continue
        if "|" in value or not _VALUE.match(value):
            continue
        out.append((stem, name))
    return out


def test_constants_are_bit_equal_on_the_gpu(trees):
    """Every numeric macro, evaluated in both languages: the same float32 bits. This is
    where a literal parsed or folded differently by the two compilers would show."""
    glsl, _ = trees
    constants = _constants(glsl)
    assert len(constants) >= 60, constants
    names = [name for _, name in constants]
    by_name = {}
    for stem, name in constants:
        by_name.setdefault(name, stem)
    mismatched = []
    for start in range(0, len(names), 24):
        chunk = names[start:start + 24]
        expr = "pbrlab_to_vec4(vec4(0.0))"
        for k in reversed(range(len(chunk))):
            expr = f"case_id < {k}.5 ? pbrlab_to_vec4({chunk[k]}) : ({expr})"
        includes_g = sorted({by_name[n] + ".glsl" for n in chunk} | {"pbr/pbr.glsl"})
        includes_h = [i[:-5] + ".hlsl" for i in includes_g]
        case = np.arange(len(chunk), dtype=np.float32)
        g = evaluate(expr, includes_g, case_id=case)
        h = evaluate(port_expression(expr), includes_h, language="hlsl", case_id=case)
        for name, a, b in zip(chunk, g, h):
            if not np.array_equal(a.view(np.uint32), b.view(np.uint32)):
                mismatched.append(f"{name}: GLSL {a} HLSL {b}")
    assert not mismatched, "\n".join(mismatched)
