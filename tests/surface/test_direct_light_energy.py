"""Direct light, furnace-style: the albedo int BRDF(l, v) cos(theta_l) dl of the library's
coupled BRDF (what pbr_lighting_standard_dfg gives one light), integrated over the
hemisphere of light directions through the GPU evaluator, for white dielectrics with
F0 in [0, 0.08], every tier, smoothness 0 ... 1 and view angles from grazing to normal.

The quadrature is reference.directional_albedo.light_quadrature (half-vector panels adapted
to the GGX lobe; it integrates cos/pi to 1 within 1e-15 and the GGX albedo to 2e-8). The
DFG values the coupling reads are the shipped table as the GPU samples it (bilinear at
pbr_dfg_lut_uv), as in the renderer."""

import numpy as np
import pytest

from pbrlab import evaluate, vec2, vec3
from pbrlab.gpu import ibl
from pbrlab.maths.reference import directional_albedo as ref_albedo
from pbrlab.maths.reference import shading as ref_shading
from pbrlab.maths.reference import surface as ref_surface

INCLUDES = ["pbr/pbr.glsl"]
# pbr_lighting_standard_dfg's direct term for one light of radiance 1 along l.
DIRECT = ("pbr_shade_punctual(vec3(0.0, 0.0, 1.0), v, l, vec3(1.0), "
          "pbr_coupled_diffuse_color(diffuseColor, f0, pbr_specular_albedo_bound(f0, dfg)), f0, r)")
F0_VALUES = [0.0, 0.005, 0.01, 0.02, 0.04, 0.06, 0.08]
MU_VALUES = [1e-3, 0.01, 0.05, 0.2, 0.5, 0.8, 1.0]
SMOOTHNESS = [i / 8 for i in range(9)]
# Albedo bound (unitless): at most 1 + 1e-4. Measured worst: 1 + 2.6e-5 (HIGH), 1 + 1e-9
# (MEDIUM), 1 + 2.6e-7 (LOW). What can exceed 1: the table's interpolation
# error where it underestimates E (measured <= 4e-5 in A or B), float32 sums (~1e-6) and the
# quadrature (2e-8).
ENERGY_GAIN_LIMIT = 1e-4


def _albedos(quality):
    table = ibl.dfg_lut()[::-1]
    tier = quality.upper()
    rows, index = [], []
    for mu in MU_VALUES:
        for s in SMOOTHNESS:
            rough = float(ref_shading.clamp_perceptual_roughness(1.0 - s, tier))
            l, w = ref_albedo.light_quadrature(mu, rough ** 2)
            dfg = ref_surface.sample_dfg_lut(table, max(mu, ref_shading.MIN_NDOTV), rough)
            rows.append((mu, rough, l, w, dfg))
    out = {}
    for f0 in F0_VALUES:
        l = np.concatenate([r[2] for r in rows])
        v = np.concatenate([np.broadcast_to([np.sqrt(1 - r[0] ** 2), 0.0, r[0]], r[2].shape) for r in rows])
        rough = np.concatenate([np.full(len(r[3]), r[1]) for r in rows])
        dfg = np.concatenate([np.broadcast_to(r[4], (len(r[3]), 2)) for r in rows])
        # the specular workflow's white dielectric: diffuse colour 1 - max(f0) (Unity's
        # EnergyConservationBetweenDiffuseAndSpecular), i.e. diffuse albedo 1
        value = evaluate(DIRECT, INCLUDES, defines=ref_shading.glsl_defines(quality=tier),
                         v=vec3(v), l=vec3(l), r=rough, dfg=vec2(dfg),
                         f0=vec3(np.full((len(l), 3), f0)), diffuseColor=vec3(np.full((len(l), 3), 1 - f0)))
        radiance = value[:, 0].astype(np.float64) / np.pi  # BRDF cos = C / (pi * radiance)
        start = 0
        for mu, r, _, w, _ in rows:
            out[f0, mu, r] = float(np.sum(w * radiance[start:start + len(w)]))
            start += len(w)
    return out


@pytest.mark.parametrize("quality", ["high", "medium", "low"])
def test_direct_light_albedo_of_white_dielectrics_is_at_most_one(quality):
    albedos = _albedos(quality)
    worst = max(albedos, key=albedos.get)
    assert albedos[worst] <= 1 + ENERGY_GAIN_LIMIT, (worst, albedos[worst])
    # and the coupling is not trivially dark: F0 = 0 is exactly Lambert (1), and the high
    # tier keeps what the table says the specular leaves (its albedo stays near 1)
    for mu in MU_VALUES:
        for r in {k[2] for k in albedos}:
            assert abs(albedos[0.0, mu, r] - 1) < 1e-5
    if quality == "high":
        assert min(albedos.values()) > 0.99
