"""pbr/surface/lighting_anisotropy.glsl and LightingStandardLayersBase with an anisotropy
(pbr/unity/surface_layers.glsl) against their float64 twins (reference/surface.py
lighting_anisotropic, anisotropic_tangent), the frame's fallbacks, and strength 0 against
LightingStandard."""

import numpy as np
import pytest

from pbrlab import evaluate, vec3
from pbrlab.maths.reference import anisotropy as ref_anisotropy
from pbrlab.maths.reference import material as ref_material
from pbrlab.maths.reference import shading
from pbrlab.maths.reference import surface as ref_surface

LAYERS = ["pbr/unity/surface_layers.glsl"]
RNG = np.random.default_rng(23)
N = 20000


def _unit(n):
    v = RNG.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _inputs(n):
    normal = np.tile([0.0, 0.0, 1.0], (n, 1))
    v = _unit(n)
    v[:, 2] = np.abs(v[:, 2]) + 0.05
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    direction = RNG.normal(size=(n, 3))  # any length, not in the tangent plane
    direction[:64] = [0.0, 0.0, 2.0]     # along n: the fallback tangent
    direction[64:128] = 0.0              # none: the fallback tangent
    return dict(n=normal, v=v, l=_unit(n), albedo=RNG.uniform(0, 1, (n, 3)), metallic=RNG.uniform(0, 1, n),
                smoothness=RNG.uniform(0, 1, n), occlusion=RNG.uniform(0, 1, n), light=RNG.uniform(0, 2, (n, 3)),
                idiff=RNG.uniform(0, 1, (n, 3)), ispec=RNG.uniform(0, 1, (n, 3)), strength=RNG.uniform(0, 1, n),
                d=direction)


def _gpu(x):
    return {k: (vec3(a) if a.ndim == 2 else a.astype(np.float32)) for k, a in x.items()}


def _layers(strength="strength", direction="d"):
    return (f"SurfaceOutputStandardLayers(0.0, 1.0, vec3(0.0, 0.0, 1.0), vec3(0.0), 1.0, {strength}, {direction}, "
            "0.0, 1.3, 400.0, 0.0, 0.0, vec3(1.0), 1.0, 1.5, 1.0, vec3(0.04))")  # no film, no transmission, F90 1


LIGHTING_ANISOTROPIC = ("LightingStandardLayersBase(SurfaceOutputStandard(albedo, n, vec3(0.0), metallic, "
                        "smoothness, occlusion, 1.0), " + _layers() + ", v, UnityGI(UnityLight(light, l), "
                        "UnityIndirect(idiff, ispec)))")


def test_lighting_standard_layers_base_with_anisotropy_matches_the_float64_reference():
    x = _inputs(N)
    got = evaluate(LIGHTING_ANISOTROPIC, LAYERS, **_gpu(x))
    diffuse = ref_material.diffuse_from_metallic(x["albedo"], x["metallic"])
    f0 = ref_material.f0_from_metallic(x["albedo"], x["metallic"])
    rough = 1 - x["smoothness"]
    r = shading.clamp_perceptual_roughness(rough)
    dfg = ref_surface.env_brdf_approx(np.maximum(x["v"][:, 2], shading.MIN_NDOTV), r)  # no table hook
    coat_f0 = np.full(3, ref_material.DIELECTRIC_F0)
    want = ref_surface.lighting_anisotropic(diffuse, f0, coat_f0, rough, x["occlusion"], x["n"], x["v"], x["l"],
                                            x["light"], x["idiff"], x["ispec"], dfg, x["strength"], x["d"])
    # Relative to the lit total, as test_unity_surface_api.py's LightingStandard: near-mirror
    # lobes (alphaB at the floor, D up to 1/(π α²) ≈ 8e4) are float32-conditioned in h.
    # Measured on llvmpipe: p99.9 4.4e-6, worst 4.9e-5 (the coat's bounds: 1e-4 and 5e-3).
    err = np.abs(got[:, :3] - want) / (1e-3 + np.abs(want))
    assert np.quantile(err, 0.999) < 1e-4 and err.max() < 5e-3, (np.quantile(err, 0.999), err.max())
    assert np.all(got[:, 3] == 1.0)


def test_strength_zero_is_lighting_standard():
    """At strength 0 the lobe is the isotropic GGX / height-correlated Smith / Schlick one:
    LightingStandardLayersBase equals LightingStandard (HIGH tier) to float32 rounding of D · V
    (measured: 89 % of the samples bit for bit, worst 7.5e-7 relative to the lit total; 1e-5
    asked, 84 ulp)."""
    x = _inputs(N)
    x["strength"] = np.zeros(N)
    plain = ("LightingStandard(SurfaceOutputStandard(albedo, n, vec3(0.0), metallic, smoothness, occlusion, 1.0),"
             " v, UnityGI(UnityLight(light, l), UnityIndirect(idiff, ispec)))")
    got = evaluate(LIGHTING_ANISOTROPIC, LAYERS, **_gpu(x))
    want = evaluate(plain, LAYERS, **_gpu(x))
    err = np.abs(got - want) / (1e-3 + np.abs(want))
    assert err.max() < 1e-5, err.max()


def test_the_anisotropic_tangent_is_orthogonal_to_n_with_fallbacks():
    n = _unit(4096)
    d = RNG.normal(size=(4096, 3))
    d[:32] = n[:32] * 3.0   # parallel to n
    d[32:64] = 0.0          # nothing
    got = evaluate("pbr_anisotropic_tangent(n, d)", ["pbr/surface/lighting_anisotropy.glsl"],
                   n=vec3(n), d=vec3(d))[:, :3]
    want = ref_surface.anisotropic_tangent(n, d)
    np.testing.assert_allclose(got, want, atol=2e-6)
    # float32 rounding of d - n (n·d) (about 6e-8 per component) grows by 1/|t| <= 1/sin, up to
    # 1e3 at PBR_ANISOTROPY_MIN_SIN: 6e-5 derived; measured 2.4e-6 over these samples
    assert np.abs(np.sum(got * n, axis=1)).max() < 6e-5
    np.testing.assert_allclose(np.linalg.norm(got, axis=1), 1.0, atol=2e-6)


@pytest.mark.parametrize("strength", [0.0, 0.6, 1.0])
def test_the_reflection_normal_is_the_bent_normal_of_the_anisotropic_bitangent(strength):
    x = _inputs(4096)
    got = evaluate(f"AnisotropicReflectionNormal(n, v, {_layers(str(strength))}, smoothness)", LAYERS,
                   **_gpu({k: x[k] for k in ("n", "v", "d", "smoothness")}))[:, :3]
    t = ref_surface.anisotropic_tangent(x["n"], x["d"])
    b = np.cross(x["n"], t)
    want = ref_anisotropy.anisotropic_bent_normal(x["n"], x["v"], b, strength,
                                                  shading.clamp_perceptual_roughness(1 - x["smoothness"]))
    np.testing.assert_allclose(got, want, atol=5e-6)
    if strength == 0.0:
        np.testing.assert_allclose(got, x["n"], atol=1e-7)  # no bend: the normal itself
