"""The per-pixel prepared surface (issue 25): pbr_prepare_surface before a loop over lights,
pbr_lighting_standard_light / pbr_lighting_anisotropic_light per light,
pbr_lighting_standard_add_environment once, against the float64 model
(reference.surface.lighting_standard / lighting_anisotropic: the direct term of each light
with the environment's zero, plus the environment once), and the one-light functions as
that composition, bit for bit.

Tolerance 2e-5 relative per channel (+1e-6 absolute): three lights' float32 BRDFs summed,
each within the tier's measured 6.0e-4 worst of the bench domain only near sharp mirrors;
here the random directions and roughness >= 0.1 keep each term within a few 1e-6
(measured worst 1.5e-6 standard, 3.7e-6 anisotropic)."""

import numpy as np
import pytest

from pbrlab import evaluate, vec2, vec3
from pbrlab.maths.reference import surface as ref_surface

RNG = np.random.default_rng(2525)
COUNT = 4096
LIGHTS = 3
INCLUDES = ["pbr/surface/lighting_standard.glsl", "pbr/surface/lighting_anisotropy.glsl"]


def _unit(count, up=True):
    v = RNG.normal(size=(count, 3))
    if up:
        v[:, 2] = np.abs(v[:, 2]) + 0.2
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


@pytest.fixture(scope="module")
def inputs():
    d = {"diffuse": RNG.uniform(0, 0.9, (COUNT, 3)), "f0": RNG.uniform(0.02, 1.0, (COUNT, 3)),
         "coat": np.full((COUNT, 3), 0.04), "r": RNG.uniform(0.1, 1.0, COUNT), "ao": RNG.uniform(0.3, 1.0, COUNT),
         "n": _unit(COUNT), "dfg": RNG.uniform(0.05, 0.6, (COUNT, 2)),
         "idiff": RNG.uniform(0, 2, (COUNT, 3)), "ispec": RNG.uniform(0, 2, (COUNT, 3)),
         "strength": RNG.uniform(0, 1, COUNT), "direction": _unit(COUNT, up=False)}
    d["v"] = _unit(COUNT)
    for i in range(LIGHTS):
        d[f"l{i}"], d[f"c{i}"] = _unit(COUNT), RNG.uniform(0, 3, (COUNT, 3))
    return {k: v.astype(np.float32) for k, v in d.items()}


def _glsl_inputs(d):
    out = {k: (vec3(v) if v.ndim == 2 and v.shape[1] == 3 else vec2(v) if v.ndim == 2 else v) for k, v in d.items()}
    return out


_PREPARE = "pbr_prepare_surface_dfg(diffuse, f0, coat, r, ao, n, v, dfg)"


@pytest.mark.parametrize("lobe", ["standard", "anisotropic"])
def test_a_prepared_loop_over_lights_matches_the_float64_model(inputs, lobe):
    frame = "pbr_anisotropic_frame(n, pbr_Anisotropy(strength, direction))"
    if lobe == "standard":
        lights = [f"pbr_lighting_standard_light({_PREPARE}, pbr_Light(c{i}, l{i}))" for i in range(LIGHTS)]
    else:
        lights = [f"pbr_lighting_anisotropic_light({_PREPARE}, {frame}, pbr_Light(c{i}, l{i}))" for i in range(LIGHTS)]
    expression = (f"pbr_lighting_standard_add_environment({_PREPARE}, pbr_Indirect(idiff, ispec), "
                  + " + ".join(lights) + ")")
    got = np.asarray(evaluate(expression, INCLUDES, **_glsl_inputs(inputs)), np.float64)[:, :3]
    d = {k: v.astype(np.float64) for k, v in inputs.items()}
    zero = np.zeros_like(d["idiff"])
    common = (d["diffuse"], d["f0"], d["coat"], d["r"], d["ao"], d["n"], d["v"])
    if lobe == "standard":
        def one(l, c, idiff, ispec):
            return ref_surface.lighting_standard(*common, l, c, idiff, ispec, d["dfg"])
    else:
        def one(l, c, idiff, ispec):
            return ref_surface.lighting_anisotropic(*common, l, c, idiff, ispec, d["dfg"], d["strength"],
                                                    d["direction"])
    want = one(d["l0"], zero, d["idiff"], d["ispec"])  # the environment once
    for i in range(LIGHTS):
        want = want + one(d[f"l{i}"], d[f"c{i}"], zero, zero)
    rel = np.abs(got - want) / np.maximum(np.abs(want), 1e-6)
    print(f"{lobe}: worst {float(rel.max()):.3g} relative")
    assert np.all(np.abs(got - want) <= 2e-5 * np.abs(want) + 1e-6), float(rel.max())


def test_the_one_light_function_is_the_composition_bit_for_bit(inputs):
    one = evaluate("pbr_lighting_standard_dfg(diffuse, f0, coat, r, ao, n, v, "
                   "pbr_GI(pbr_Light(c0, l0), pbr_Indirect(idiff, ispec)), dfg)", INCLUDES, **_glsl_inputs(inputs))
    composed = evaluate(f"pbr_lighting_standard_add_environment({_PREPARE}, pbr_Indirect(idiff, ispec), "
                        f"pbr_lighting_standard_light({_PREPARE}, pbr_Light(c0, l0)))", INCLUDES,
                        **_glsl_inputs(inputs))
    np.testing.assert_array_equal(one, composed)
