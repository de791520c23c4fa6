// pbr/material/ior.glsl: F0 <-> index of refraction at normal incidence.
//
// Provides: pbr_f0_from_ior(float eta), pbr_ior_from_f0(float f0).
// Include:  "pbr/material/ior.glsl" (path relative to glsl/)
// Config macros read: none.
//
// Fresnel's equations at normal incidence (Born & Wolf, "Principles of Optics", §1.5.3,
// eq. 1.5.(22) for theta = 0): F0 = ((eta - 1) / (eta + 1))², eta = n_inside / n_outside
// (real part only: valid for dielectrics, not metals). Inverse: eta = (1 + sqrt F0) /
// (1 - sqrt F0), for F0 in [0, 1). pbr_f0_from_ior(eta) == pbr_F_Dielectric(1.0, eta)
// (tested). float64 twin: reference/material.py.
#ifndef PBR_MATERIAL_IOR_GLSL
#define PBR_MATERIAL_IOR_GLSL

float pbr_f0_from_ior(float eta) {
    float r = (eta - 1.0) / (eta + 1.0);
    return r * r;
}

float pbr_ior_from_f0(float f0) {
    float s = sqrt(f0);
    return (1.0 + s) / (1.0 - s);
}

#endif // PBR_MATERIAL_IOR_GLSL
