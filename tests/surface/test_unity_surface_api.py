"""pbr/unity/surface_standard.glsl: Unity's names with Unity's semantics, on pbrlab's core."""

import numpy as np
import pytest

from pbrlab import evaluate, vec3
from pbrlab.maths.reference import material as ref_material
from pbrlab.maths.reference import surface as ref_surface

UNITY = ["pbr/unity/surface_standard.glsl"]
RNG = np.random.default_rng(11)
N = 20000

# Unity's helpers return through out-parameters; this file exposes them to the evaluator.
WRAPPERS = """#include "pbr/unity/surface_standard.glsl"
vec4 wrap_dsfm(vec3 a, float m) {
    vec3 s; float o; vec3 d = DiffuseAndSpecularFromMetallic(a, m, s, o); return vec4(d.r, s.g, o, 0.0);
}
vec4 wrap_ec(vec3 a, vec3 sp) {
    float o; vec3 d = EnergyConservationBetweenDiffuseAndSpecular(a, sp, o); return vec4(d, o);
}
vec4 wrap_pma(vec3 d, float al, float omr) {
    float oa; vec3 c = PreMultiplyAlpha(d, al, omr, oa); return vec4(c, oa);
}
"""


@pytest.fixture(scope="module")
def wrappers(tmp_path_factory):
    folder = tmp_path_factory.mktemp("unity")
    (folder / "wrap.glsl").write_text(WRAPPERS)
    return {"includes": ["wrap.glsl"], "include_dirs": [folder]}


def _unit(n):
    v = RNG.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def test_diffuse_and_specular_from_metallic_follow_unity(wrappers):
    albedo, metallic = RNG.uniform(0, 1, (N, 3)), RNG.uniform(0, 1, N)
    got = evaluate("wrap_dsfm(a, m)", a=vec3(albedo), m=metallic, **wrappers)
    omr = 0.96 * (1 - metallic)  # Unity: (1 - 0.04) - metallic * (1 - 0.04)
    np.testing.assert_allclose(got[:, 0], albedo[:, 0] * omr, atol=2e-7)
    np.testing.assert_allclose(got[:, 1], ref_material.f0_from_metallic(albedo, metallic)[:, 1], atol=2e-7)
    np.testing.assert_allclose(got[:, 2], omr, atol=2e-7)


def test_energy_conservation_between_diffuse_and_specular_follows_unity(wrappers):
    albedo, spec = RNG.uniform(0, 1, (N, 3)), RNG.uniform(0, 1, (N, 3))
    got = evaluate("wrap_ec(a, s)", a=vec3(albedo), s=vec3(spec), **wrappers)
    omr = 1 - spec.max(axis=1)  # Unity: 1 - SpecularStrength(specColor), the max channel
    np.testing.assert_allclose(got[:, 3], omr, atol=2e-7)
    np.testing.assert_allclose(got[:, :3], albedo * omr[:, None], atol=2e-7)


@pytest.mark.parametrize("mode", ["OPAQUE", "CUTOUT", "FADE", "TRANSPARENT"])
def test_premultiply_alpha_only_in_transparent_mode(mode, wrappers):
    diffuse, alpha, omr = RNG.uniform(0, 1, (N, 3)), RNG.uniform(0, 1, N), RNG.uniform(0, 1, N)
    got = evaluate("wrap_pma(d, al, omr)", d=vec3(diffuse), al=alpha, omr=omr,
                   defines={"PBR_ALPHA_MODE": f"PBR_ALPHA_MODE_{mode}"}, **wrappers)
    want_diffuse, want_alpha = ref_surface.premultiply_alpha(diffuse, alpha[:, None], omr[:, None],
                                                             transparent=mode == "TRANSPARENT")
    np.testing.assert_allclose(got[:, :3], want_diffuse, atol=2e-7)
    np.testing.assert_allclose(got[:, 3], np.broadcast_to(want_alpha, (N, 1))[:, 0], atol=2e-7)


def _lighting_inputs(n):
    normal = np.tile([0.0, 0.0, 1.0], (n, 1))
    v, l = _unit(n), _unit(n)
    v[:, 2] = np.abs(v[:, 2]) + 0.05
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    return dict(n=normal, v=v, l=l, albedo=RNG.uniform(0, 1, (n, 3)), metallic=RNG.uniform(0, 1, n),
                smoothness=RNG.uniform(0, 1, n), occlusion=RNG.uniform(0, 1, n),
                light=RNG.uniform(0, 2, (n, 3)), idiff=RNG.uniform(0, 1, (n, 3)), ispec=RNG.uniform(0, 1, (n, 3)))


LIGHTING_STANDARD = ("LightingStandard(SurfaceOutputStandard(albedo, n, vec3(0.0), metallic, smoothness,"
                     " occlusion, 1.0), v, UnityGI(UnityLight(light, l), UnityIndirect(idiff, ispec)))")


def _gpu_inputs(x):
    return {k: (vec3(a) if a.ndim == 2 else a) for k, a in x.items()}


def test_lighting_standard_matches_the_float64_reference():
    x = _lighting_inputs(N)
    got = evaluate(LIGHTING_STANDARD, UNITY, **_gpu_inputs(x))
    diffuse = ref_material.diffuse_from_metallic(x["albedo"], x["metallic"])
    f0 = ref_material.f0_from_metallic(x["albedo"], x["metallic"])
    rough = 1 - x["smoothness"]
    from pbrlab.maths.reference import shading
    r = shading.clamp_perceptual_roughness(rough)
    NdotV = np.maximum(x["v"][:, 2], shading.MIN_NDOTV)
    dfg = ref_surface.env_brdf_approx(NdotV, r)  # no DFG table hook: the analytic fit
    coat_f0 = np.full(3, ref_material.DIELECTRIC_F0)  # LightingStandard's coat: Unity's dielectric
    want = ref_surface.lighting_standard(diffuse, f0, coat_f0, rough, x["occlusion"], x["n"], x["v"],
                                         x["l"], x["light"], x["idiff"], x["ispec"], dfg)
    # Tolerance: the direct specular of near-mirror lobes is float32-conditioned (see
    # tests/library/test_shading.py); relative to the lit total, measured 2e-3 at worst.
    err = np.abs(got[:, :3] - want) / (1e-3 + np.abs(want))
    assert np.quantile(err, 0.999) < 1e-4 and err.max() < 5e-3
    assert np.all(got[:, 3] == 1.0)  # opaque: alpha passes through


def test_specular_workflow_with_f0_004_equals_metallic_workflow_at_metallic_0():
    x = _lighting_inputs(N)
    x["metallic"] = np.zeros(N)
    metallic = evaluate(LIGHTING_STANDARD, UNITY, **_gpu_inputs(x))
    specular = evaluate(
        "LightingStandardSpecular(SurfaceOutputStandardSpecular(albedo, vec3(0.04), n, vec3(0.0), smoothness,"
        " occlusion, 1.0), v, UnityGI(UnityLight(light, l), UnityIndirect(idiff, ispec)))",
        UNITY, **{k: v for k, v in _gpu_inputs(x).items() if k != "metallic"})
    np.testing.assert_allclose(specular, metallic, rtol=1e-6, atol=1e-7)


def test_unity_model_indirect_specular_is_unity_brdf1_for_dark_metals():
    """Replaces the removed PBR_INDIRECT_SPECULAR_UNITY_LEGACY, whose grazing term came from
    max(F0) (up to 94.5 % off Unity for metals with albedo below 1) and whose test built its
    reference with the same approximation. The unity model's environment term against the
    independent transcription of Unity's BRDF1 (grazing term saturate(smoothness + 1 -
    oneMinusReflectivity), surfaceReduction, occlusion from the GI step): dark metals,
    environment light only."""
    from pbrlab.maths.reference import unity_brdf
    x = _lighting_inputs(N)
    x["light"] = np.zeros((N, 3))
    x["idiff"] = np.zeros((N, 3))
    x["metallic"] = np.ones(N)
    x["albedo"] = RNG.uniform(0.02, 1.0, (N, 1)) * RNG.uniform(0.5, 1.0, (N, 3))
    got = evaluate(LIGHTING_STANDARD, UNITY, defines={"PBR_BRDF_MODEL": "PBR_BRDF_MODEL_UNITY"}, **_gpu_inputs(x))
    f = {k: a.astype(np.float32).astype(np.float64) for k, a in x.items()}
    want = unity_brdf.lighting_standard(f["albedo"], f["metallic"], f["smoothness"], f["n"], f["v"], f["light"],
                                        f["l"], f["idiff"], f["ispec"], tier=1)
    # environment term only: products and one pow5 of float32 inputs; measured 2.4e-7 relative
    np.testing.assert_allclose(got[:, :3], want, rtol=2e-6, atol=1e-7)
