// pbrlab stand-in for Core RP's ShaderLibrary/VolumeRendering.hlsl: participating media in a
// homogeneous slab (optical depth, transmittance, opacity) and the phase functions, written for
// pbrlab from the formulas each name stands for (Beer-Lambert's law; Henyey and Greenstein 1941;
// Cornette and Shanks 1992; Rayleigh) as Core RP 14.0.9 documents and normalises them (Unity's
// own file is under the Unity Companion License and is not copied). Not provided, and refused by
// name where called (unity_library_names): the height fog (ComputeHeightFogMultiplier,
// OpticalDepthHeightFog, TransmittanceHeightFog), the importance samplers
// (ImportanceSampleHomogeneousMedium, ImportanceSampleExponentialMedium,
// ImportanceSamplePunctualLight, ImportanceSampleRayleighPhase) and the deep-compositing
// conversions (LinearizeRGBA, LinearizeRGBD, DelinearizeRGBA, DelinearizeRGBD).
#ifndef PBRLAB_CORE_RP_VOLUME_RENDERING_HLSL
#define PBRLAB_CORE_RP_VOLUME_RENDERING_HLSL

#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Core.hlsl"

// Optical depth of a homogeneous medium: extinction coefficient times the path length.
float OpticalDepthHomogeneousMedium(float extinction, float intervalLength) { return extinction * intervalLength; }
float3 OpticalDepthHomogeneousMedium(float3 extinction, float intervalLength) { return extinction * intervalLength; }
// Beer-Lambert: transmittance exp(-optical depth); opacity its complement, and back.
float TransmittanceFromOpticalDepth(float opticalDepth) { return exp(-opticalDepth); }
float3 TransmittanceFromOpticalDepth(float3 opticalDepth) { return exp(-opticalDepth); }
float OpacityFromOpticalDepth(float opticalDepth) { return 1.0 - TransmittanceFromOpticalDepth(opticalDepth); }
float3 OpacityFromOpticalDepth(float3 opticalDepth) { return 1.0 - TransmittanceFromOpticalDepth(opticalDepth); }
float OpticalDepthFromOpacity(float opacity) { return -log(1.0 - opacity); }
float TransmittanceHomogeneousMedium(float extinction, float intervalLength) {
    return TransmittanceFromOpticalDepth(OpticalDepthHomogeneousMedium(extinction, intervalLength));
}
float3 TransmittanceHomogeneousMedium(float3 extinction, float intervalLength) {
    return TransmittanceFromOpticalDepth(OpticalDepthHomogeneousMedium(extinction, intervalLength));
}
// The transmittance integrated over the path, from 0 to L of exp(-s t) dt = (1 - exp(-s L)) / s.
float TransmittanceIntegralHomogeneousMedium(float extinction, float intervalLength) {
    return (1.0 - exp(-extinction * intervalLength)) / extinction;
}
float3 TransmittanceIntegralHomogeneousMedium(float3 extinction, float intervalLength) {
    return (1.0 - exp(-extinction * intervalLength)) / extinction;
}
// The absorption coefficient that leaves the given colour after the given distance (Burley,
// "Extending the Disney BRDF to a BSDF with Integrated Subsurface Scattering", 2015): -ln(c) / d,
// c and d held off zero by FLT_EPS (2^-24) as Core does.
float3 TransmittanceColorAtDistanceToAbsorption(float3 transmittanceColor, float atDistance) {
    return -log(transmittanceColor + 5.960464478e-8) / max(atDistance, 5.960464478e-8);
}

// Phase functions, each normalised to integrate to 1 over the sphere; cosTheta the cosine of the
// angle between the light's travel direction and the scattered one.
float IsotropicPhaseFunction() { return 0.07957747155; }  // 1 / (4 pi)
// Rayleigh: 3 / (16 pi) (1 + cos^2).
float RayleighPhaseFunction(float cosTheta) { return (3.0 / (16.0 * 3.14159265359)) * (1.0 + cosTheta * cosTheta); }
// Henyey-Greenstein with asymmetry g: (1 - g^2) / (4 pi) times (1 + g^2 - 2 g cos)^(-3/2), the
// base held at least FLT_EPS (g = +-1 looking straight along the light).
float HenyeyGreensteinPhasePartConstant(float anisotropy) {
    return 0.07957747155 * (1.0 - anisotropy * anisotropy);
}
float HenyeyGreensteinPhasePartVarying(float anisotropy, float cosTheta) {
    float f = rsqrt(max(1.0 + anisotropy * anisotropy - 2.0 * anisotropy * cosTheta, 5.960464478e-8));
    return f * f * f;
}
float HenyeyGreensteinPhaseFunction(float anisotropy, float cosTheta) {
    return HenyeyGreensteinPhasePartConstant(anisotropy) * HenyeyGreensteinPhasePartVarying(anisotropy, cosTheta);
}
// Cornette-Shanks: 3 / (8 pi) (1 - g^2) / (2 + g^2) times (1 + cos^2) (the symmetrical part, as
// Rayleigh's) times (1 + g^2 - 2 g cos)^(-3/2) (the asymmetrical part, as Henyey-Greenstein's).
float CornetteShanksPhasePartConstant(float anisotropy) {
    float g2 = anisotropy * anisotropy;
    return (3.0 / (8.0 * 3.14159265359)) * (1.0 - g2) / (2.0 + g2);
}
float CornetteShanksPhasePartSymmetrical(float cosTheta) { return 1.0 + cosTheta * cosTheta; }
float CornetteShanksPhasePartAsymmetrical(float anisotropy, float cosTheta) {
    return HenyeyGreensteinPhasePartVarying(anisotropy, cosTheta);
}
float CornetteShanksPhasePartVarying(float anisotropy, float cosTheta) {
    return CornetteShanksPhasePartSymmetrical(cosTheta) * CornetteShanksPhasePartAsymmetrical(anisotropy, cosTheta);
}
float CornetteShanksPhaseFunction(float anisotropy, float cosTheta) {
    return CornetteShanksPhasePartConstant(anisotropy) * CornetteShanksPhasePartVarying(anisotropy, cosTheta);
}

#endif
