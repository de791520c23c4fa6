"""The energy compensation's error for coloured F0 (docs/shading.md, "Multiple scattering"):
forms of the compensated GGX albedo against the float64 random walk on the Smith
microsurface (Heitz et al. 2016; harness/pbrlab/maths/reference/multiple_scattering.py) over
perceptual roughness {0.2 .. 1} x NdotV {0.05 .. 1} x F0 {gold, copper, red, dielectric}.

    PYTHONPATH=harness python benchmarks/multiple_scattering_error.py [--paths N]

Forms (all multiply the single-scattering E_F = F0 A + B, with E = A + B, F_avg = F0 + (1 - F0)/21):
f0_scaled 1 + f0 (1/E - 1) (Filament, pbrlab's), fresnel_series 1 / (1 - F_avg (1 - E))
(Fdez-Aguera 2019, three.js), kulla_conty (the closed form in float64), cycles (Cycles'
microfacet_ggx_preserve_energy multiplier with float64 E_avg), single (no compensation).
About 100 s on one core at 1e6 paths. First, without Monte Carlo, the same forms against
Kulla-Conty over perceptual roughness 0.045 .. 1 (20) x NdotV 0.02 .. 1 (25), F0 white too.
"""

import argparse

import numpy as np

from pbrlab.maths.reference import directional_albedo as da
from pbrlab.maths.reference import multiple_scattering as ms

F0 = {"gold": (1.0, 0.766, 0.336), "copper": (0.955, 0.638, 0.538), "red": (0.8, 0.05, 0.05),
      "dielectric": (0.04, 0.04, 0.04)}
ROUGHNESS = (0.2, 0.4, 0.6, 0.8, 1.0)
NDOTV = (0.05, 0.2, 0.5, 0.8, 1.0)


def forms(mu, alpha, f0, e_avg):
    a, b = da.split_sum_terms_at_alpha(np.array([mu]), alpha)[0]
    f0 = np.asarray(f0, np.float64)
    e, single, f_avg = a + b, f0 * a + b, ms.schlick_f_avg(f0)
    return {"f0_scaled": single * (1 + f0 * (1 / e - 1)),
            "fresnel_series": single / (1 - f_avg * (1 - e)),
            "kulla_conty": ms.kulla_conty_albedo(mu, alpha, f0),
            "cycles": single * (1 + f_avg * e_avg / (1 - f_avg * (1 - e_avg)) * (1 / e - 1)),
            "single": single}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--paths", type=int, default=1_000_000)
    args = parser.parse_args()
    print("against Kulla-Conty (float64), max |err| per F0: f0_scaled / fresnel_series")
    for name, f0 in {"white": (1.0, 1.0, 1.0), **F0}.items():
        worst = {"f0_scaled": 0.0, "fresnel_series": 0.0}
        for roughness in np.linspace(0.045, 1.0, 20):
            alpha = roughness * roughness
            e_avg = ms.e_avg(alpha)
            for mu in np.linspace(0.02, 1.0, 25):
                values = forms(mu, alpha, f0, e_avg)
                for form in worst:
                    worst[form] = max(worst[form], np.abs(values[form] - values["kulla_conty"]).max())
        print(f"{name:10s} {worst['f0_scaled']:.4f} / {worst['fresnel_series']:.4f}")
    errors, worst_se = {}, 0.0
    for roughness in ROUGHNESS:
        alpha = roughness * roughness
        e_avg = ms.e_avg(alpha)
        for mu in NDOTV:
            for seed, f0 in enumerate(F0.values()):
                walk, se = ms.random_walk_albedo(mu, alpha, f0, paths=args.paths, seed=seed)
                worst_se = max(worst_se, se.max())
                for name, value in forms(mu, alpha, f0, e_avg).items():
                    errors.setdefault(name, []).append(value - walk)
    print(f"against the random walk ({args.paths} paths a point, standard error <= {worst_se:.1e})")
    for name, err in errors.items():
        err = np.array(err)
        print(f"{name:15s} max |err| {np.abs(err).max():.4f}  mean |err| {np.abs(err).mean():.4f}  "
              f"signed [{err.min():+.4f}, {err.max():+.4f}]")


if __name__ == "__main__":
    main()
