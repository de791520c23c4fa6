// pbr/unity/brdf_unity.hlsl: Unity's built-in Standard BRDFs, formula for formula.
//
// Provides: UnityLight, UnityIndirect, UnityGI (aliases of pbr_Light, pbr_Indirect, pbr_GI);
//           Unity's terms by Unity's names: float Pow4(float), vec2 Pow4(vec2),
//           vec3 FresnelTerm(vec3 F0, float cosA), vec3 FresnelLerp(vec3 F0, vec3 F90, float cosA),
//           vec3 FresnelLerpFast(vec3 F0, vec3 F90, float cosA),
//           float DisneyDiffuse(float NdotV, float NdotL, float LdotH, float perceptualRoughness),
//           float SmithJointGGXVisibilityTerm(float NdotL, float NdotV, float roughness),
//           float GGXTerm(float NdotH, float roughness),
//           float PerceptualRoughnessToSpecPower(float perceptualRoughness),
//           vec3 Unity_SafeNormalize(vec3 inVec), float DotClamped(vec3 a, vec3 b);
//           Unity's BRDFs: vec4 BRDF1_Unity_PBS, BRDF2_Unity_PBS, BRDF3_Unity_PBS(vec3 diffColor,
//           vec3 specColor, float oneMinusReflectivity, float smoothness, vec3 normal,
//           vec3 viewDir, UnityLight light, UnityIndirect gi), vec3 BRDF3_Direct, BRDF3_Indirect;
//           the same with flat parameters (light colour and direction, indirect diffuse and
//           specular): vec3 pbr_unity_brdf1, pbr_unity_brdf2, pbr_unity_brdf3, and
//           vec3 pbr_unity_brdf_pbs (the tier's BRDF, PBR_UNITY_BRDF), and Unity's macro
//           UNITY_BRDF_PBS with Unity's signature: vec4 pbr_unity_BRDF_PBS(vec3 diffColor, ...,
//           UnityLight light, UnityIndirect gi) (a vertex/fragment pass calls it: the deferred
//           light passes);
//           float pbr_unity_NHxRoughness(float rlPow4, float perceptualRoughness);
//           float pbr_unity_glossy_environment_perceptual_roughness(float perceptualRoughness).
// Include:  "pbr/unity/brdf_unity.hlsl" (path relative to hlsl_ports/). pbr/unity/surface_standard.hlsl
//           includes it; LightingStandard uses it when PBR_BRDF_MODEL is PBR_BRDF_MODEL_UNITY.
// Config macros read: PBR_UNITY_BRDF (PBR_UNITY_BRDF_1 | _2 | _3; the default follows
//           PBR_QUALITY: HIGH -> 1, MEDIUM -> 2, LOW -> 3, in pbr/shading/dispatch.hlsl);
//           PBR_UNITY_NHXROUGHNESS_LOOKUP(rlPow4, perceptualRoughness), a hook an engine with
//           Unity's unity_NHxRoughness texture may define (it owns the sampler) to return
//           tex2D(unity_NHxRoughness, vec2(rlPow4, perceptualRoughness)).r; undefined, BRDF3
//           evaluates pbr_unity_NHxRoughness, the analytic function the texture stands for.
//
// Source: Unity 2019.4's built-in shaders, CGIncludes/UnityStandardBRDF.cginc (the BRDFs and
// their terms) and UnityImageBasedLighting.cginc (Unity_GlossyEnvironment), read and
// rewritten line by line in GLSL. The configuration reproduced is a desktop target in linear
// colour space: UNITY_BRDF_GGX 1 (UnityStandardConfig.cginc's default), no
// UNITY_COLORSPACE_GAMMA, no SHADER_API_MOBILE (BRDF2 neither subtracts 1e-4 nor clamps to
// 100), no _SPECULARHIGHLIGHTS_OFF, UNITY_HANDLE_CORRECTLY_NEGATIVE_NDOTV 0 (BRDF1 takes
// |n·v|). Units are Unity's, which are pbrlab's: Unity leaves the diffuse without its 1/π and
// multiplies the specular by π, pbrlab keeps 1/π and multiplies the light by π; a white
// Lambert surface under an intensity-1 light gives 1 in both, so these functions return
// radiance for pbrlab's light.color and indirect.diffuse (irradiance / π) unchanged.
// Its float64 transcription, written from Unity's source and not from this file, is
// harness/pbrlab/maths/reference/unity_brdf.py; tests/importers/unity/ compares the two.
// Where the maths is the library's, the pbr_ core is called (pbr_pow5, pbr_F_Schlick,
// pbr_max3, the remaps); the core never includes this file.
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_BRDF_UNITY_HLSL
#define PBR_UNITY_BRDF_UNITY_HLSL
#include "pbr/common/shim.hlsl"  // generated from glsl/pbr/unity/brdf_unity.glsl by harness/pbrlab/gpu/port_hlsl.py: edit the GLSL, then regenerate
#include "pbr/common/constants.hlsl"
#include "pbr/common/math.hlsl"
#include "pbr/brdf/f_schlick.hlsl"
#include "pbr/material/remap.hlsl"
#include "pbr/shading/dispatch.hlsl"
#include "pbr/surface/lighting_standard.hlsl"

#define UnityLight pbr_Light
#define UnityIndirect pbr_Indirect
#define UnityGI pbr_GI

// The tier block of pbr/shading/dispatch.hlsl (included above) has set PBR_UNITY_BRDF from
// PBR_QUALITY; this file's own default is the same as the HIGH tier's.
#ifndef PBR_UNITY_BRDF
// PBR_UNITY_BRDF_1 as a number (glsl/README.md, one-level preprocessors)
#define PBR_UNITY_BRDF 1
#endif

// Unity's epsilons and clamps, each as UnityStandardBRDF.cginc writes it (shared with
// harness/pbrlab/maths/reference/unity_brdf.py, tested equal).
#define PBR_UNITY_GGX_EPSILON 1e-7            // GGXTerm: a² / (π (d² + 1e-7)); caps the peak
#define PBR_UNITY_SMITH_JOINT_EPSILON 1e-5    // SmithJointGGXVisibilityTerm's denominator
#define PBR_UNITY_BRDF1_MIN_ROUGHNESS 0.002   // BRDF1: max(roughness, 0.002) ("match HDRP")
#define PBR_UNITY_SAFE_NORMALIZE_MIN_LENGTH2 0.001  // Unity_SafeNormalize: max(0.001, dot(v, v))
#define PBR_UNITY_BRDF2_D_OFFSET 1.00001      // BRDF2: d = nh² (a² - 1) + 1.00001
#define PBR_UNITY_BRDF2_MIN_LH2 0.1           // BRDF2: max(0.1, lh²)
#define PBR_UNITY_SPEC_POWER_MIN_M2 1e-4      // PerceptualRoughnessToSpecPower: max(1e-4, m²)
#define PBR_UNITY_SPEC_POWER_MIN 1e-4         // ... and max(n, 1e-4)
#define PBR_UNITY_NHXROUGHNESS_LUT_RANGE 16.0 // BRDF3_Direct: texture value * LUT_RANGE
#define PBR_UNITY_NHXROUGHNESS_WARP_EXPONENT 4.0  // the texture's x is (R·L)^4 (kHorizontalWarpExp)
// 2 π², the normalisation's denominator, written out: compilers fold 2.0 * PBR_PI * PBR_PI at
// different precisions (the GLSL and HLSL twins differed by 3 ulp).
#define PBR_UNITY_TWO_PI_SQUARED 19.7392088021787

// ---- Unity's terms (UnityStandardBRDF.cginc) ----------------------------------------------

float Pow4(float x) { return x * x * x * x; }
float2  Pow4(float2 x)  { return x * x * x * x; }

// Schlick's Fresnel, Unity's FresnelTerm: F0 + (1 - F0) (1 - cosA)^5 (pbrlab's pbr_F_Schlick).
float3 FresnelTerm(float3 F0, float cosA) {
    return pbr_F_Schlick(F0, cosA);
}

// Schlick towards a chosen F90: lerp(F0, F90, (1 - cosA)^5).
float3 FresnelLerp(float3 F0, float3 F90, float cosA) {
    return lerp(F0, F90, pbr_pow5(1.0 - cosA));
}

// Unity's cheaper form with the fourth power.
float3 FresnelLerpFast(float3 F0, float3 F90, float cosA) {
    return lerp(F0, F90, Pow4(1.0 - cosA));
}

// Burley's diffuse without its 1/π (Unity's diffuse carries none): Burley 2012,
// "Physically-Based Shading at Disney", §5.3.
float DisneyDiffuse(float NdotV, float NdotL, float LdotH, float perceptualRoughness) {
    float fd90 = 0.5 + 2.0 * LdotH * LdotH * perceptualRoughness;
    float lightScatter = 1.0 + (fd90 - 1.0) * pbr_pow5(1.0 - NdotL);
    float viewScatter = 1.0 + (fd90 - 1.0) * pbr_pow5(1.0 - NdotV);
    return lightScatter * viewScatter;
}

// Unity's visibility V = G / (4 NdotL NdotV): its approximation of the height-correlated Smith
// term (Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 99) with each
// sqrt(n²(1 - a²) + a²) replaced by n(1 - a) + a; takes roughness = alpha.
float SmithJointGGXVisibilityTerm(float NdotL, float NdotV, float roughness) {
    float a = roughness;
    float lambdaV = NdotL * (NdotV * (1.0 - a) + a);
    float lambdaL = NdotV * (NdotL * (1.0 - a) + a);
    return 0.5 / (lambdaV + lambdaL + PBR_UNITY_SMITH_JOINT_EPSILON);
}

// GGX (Walter 2007, eq. 33) with Unity's 1e-7 in the denominator: at NdotH = 1 the peak is
// a² / (π (a⁴ + 1e-7)), which for a² below ~3e-4 is far under pbrlab's 1 / (π a²).
float GGXTerm(float NdotH, float roughness) {
    float a2 = roughness * roughness;
    float d = (NdotH * a2 - NdotH) * NdotH + 1.0;
    return PBR_INV_PI * a2 / (d * d + PBR_UNITY_GGX_EPSILON);
}

// Blinn-Phong exponent for a perceptual roughness: n = 2 / m² - 2 with m = roughness² (Walter
// 2007, eq. 21 inverted for Beckmann), floored as Unity does.
float PerceptualRoughnessToSpecPower(float perceptualRoughness) {
    float m = pbr_alpha_from_perceptual_roughness(perceptualRoughness);
    float sq = max(PBR_UNITY_SPEC_POWER_MIN_M2, m * m);
    float n = (2.0 / sq) - 2.0;
    return max(n, PBR_UNITY_SPEC_POWER_MIN);
}

float3 Unity_SafeNormalize(float3 inVec) {
    float dp3 = max(PBR_UNITY_SAFE_NORMALIZE_MIN_LENGTH2, dot(inVec, inVec));
    return inVec * rsqrt(dp3);
}

// max(0, a·b): UnityStandardBRDF.cginc's form for shader target 3.0 and above (below it,
// saturate; the two agree for unit vectors).
float DotClamped(float3 a, float3 b) {
    return max(0.0, dot(a, b));
}

// What BRDF3 reads from Unity's lookup texture unity_NHxRoughness (.r * LUT_RANGE), as the
// analytic function the texture stands for. Unity bakes the texture in GeneratedTextures.cpp,
// which is not public; this is Unity's own un-baked form, the fallback branch of BRDF3_Unity_PBS
// in Unity 5.0's UnityStandardBRDF.cginc ("n = RoughnessToSpecPower(roughness) * .25;
// specular = (n + 2) / (2 π²) · pow(dot(reflDir, light.dir), n)"): a normalized Phong lobe
// around the mirror direction with a quarter of the Blinn-Phong exponent. Differences from
// that line, each forced by the texture's form: today's PerceptualRoughnessToSpecPower; the
// texture's coordinates (x = (R·L)^4, so (R·L)^n = x^(n/4)); no `* nl` (BRDF3_Unity_PBS
// multiplies by nl after the lookup); clamped to the texture's range [0, LUT_RANGE].
// Measured against the same function baked into a texture and filtered (README, "Unity BRDF
// mode"); an engine with Unity's texture defines PBR_UNITY_NHXROUGHNESS_LOOKUP instead.
float pbr_unity_NHxRoughness(float rlPow4, float perceptualRoughness) {
    float n = PerceptualRoughnessToSpecPower(perceptualRoughness) * 0.25;
    float lobe = pow(max(rlPow4, 0.0), n / PBR_UNITY_NHXROUGHNESS_WARP_EXPONENT);
    return min((n + 2.0) / PBR_UNITY_TWO_PI_SQUARED * lobe, PBR_UNITY_NHXROUGHNESS_LUT_RANGE);
}

float pbr_unity_NHxRoughness_lookup(float rlPow4, float perceptualRoughness) {
#ifdef PBR_UNITY_NHXROUGHNESS_LOOKUP
    return PBR_UNITY_NHXROUGHNESS_LOOKUP(rlPow4, perceptualRoughness) * PBR_UNITY_NHXROUGHNESS_LUT_RANGE;
#else
    return pbr_unity_NHxRoughness(rlPow4, perceptualRoughness);
#endif
}

// Unity_GlossyEnvironment (UnityImageBasedLighting.cginc) remaps the perceptual roughness
// before choosing the mip (mip = r' · UNITY_SPECCUBE_LOD_STEPS): r' = r (1.7 - 0.7 r), Mittring's
// "surprisingly close approximation" of the spec-power based mapping in its disabled branch.
float pbr_unity_glossy_environment_perceptual_roughness(float perceptualRoughness) {
    return perceptualRoughness * (1.7 - 0.7 * perceptualRoughness);
}

// ---- BRDF1_Unity_PBS: GGX, Unity's joint Smith, Disney diffuse ---------------------------

float3 pbr_unity_brdf1(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                     float3 normal, float3 viewDir, float3 lightColor, float3 lightDir,
                     float3 indirectDiffuse, float3 indirectSpecular) {
    float perceptualRoughness = pbr_perceptual_roughness_from_smoothness(smoothness);
    float3 halfDir = Unity_SafeNormalize(lightDir + viewDir);
    float nv = abs(dot(normal, viewDir));
    float nl = pbr_saturate(dot(normal, lightDir));
    float nh = pbr_saturate(dot(normal, halfDir));
    float lh = pbr_saturate(dot(lightDir, halfDir));
    float diffuseTerm = DisneyDiffuse(nv, nl, lh, perceptualRoughness) * nl;
    float roughness = max(pbr_alpha_from_perceptual_roughness(perceptualRoughness), PBR_UNITY_BRDF1_MIN_ROUGHNESS);
    float V = SmithJointGGXVisibilityTerm(nl, nv, roughness);
    float D = GGXTerm(nh, roughness);
    float specularTerm = V * D * PBR_PI;
    specularTerm = max(0.0, specularTerm * nl);
    float surfaceReduction = 1.0 / (roughness * roughness + 1.0);
    // Unity's any(specColor): a black specular has no direct highlight (for "true Lambert").
    // Written as max|c| > 0, equal to any(c != 0) for every non-NaN colour.
    specularTerm *= pbr_max3(abs(specColor)) > 0.0 ? 1.0 : 0.0;
    float grazingTerm = pbr_saturate(smoothness + (1.0 - oneMinusReflectivity));
    return diffColor * (indirectDiffuse + lightColor * diffuseTerm)
         + specularTerm * lightColor * FresnelTerm(specColor, lh)
         + surfaceReduction * indirectSpecular * FresnelLerp(specColor, ((float3)(grazingTerm)), nv);
}

// ---- BRDF2_Unity_PBS: GGX with Unity's combined visibility-Fresnel approximation ----------
// ("Optimizing PBR for Mobile", Siggraph 2015 course: D · V · F ≈ a² / (4 d² lh² (roughness +
// 0.5)) with lh² floored at 0.1); polynomial surfaceReduction; Schlick with the 4th power.

float3 pbr_unity_brdf2(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                     float3 normal, float3 viewDir, float3 lightColor, float3 lightDir,
                     float3 indirectDiffuse, float3 indirectSpecular) {
    float3 halfDir = Unity_SafeNormalize(lightDir + viewDir);
    float nl = pbr_saturate(dot(normal, lightDir));
    float nh = pbr_saturate(dot(normal, halfDir));
    float nv = pbr_saturate(dot(normal, viewDir));
    float lh = pbr_saturate(dot(lightDir, halfDir));
    float perceptualRoughness = pbr_perceptual_roughness_from_smoothness(smoothness);
    float roughness = pbr_alpha_from_perceptual_roughness(perceptualRoughness);
    float a = roughness;
    float a2 = a * a;
    float d = nh * nh * (a2 - 1.0) + PBR_UNITY_BRDF2_D_OFFSET;
    float specularTerm = a2 / (max(PBR_UNITY_BRDF2_MIN_LH2, lh * lh) * (roughness + 0.5) * (d * d) * 4.0);
    // 1 - x³ (0.6 - 0.08 x), Unity's polynomial for 1 / (x⁴ + 1), x = perceptual roughness.
    float surfaceReduction = 1.0 - roughness * perceptualRoughness * (0.6 - 0.08 * perceptualRoughness);
    float grazingTerm = pbr_saturate(smoothness + (1.0 - oneMinusReflectivity));
    return (diffColor + specularTerm * specColor) * lightColor * nl
         + indirectDiffuse * diffColor
         + surfaceReduction * indirectSpecular * FresnelLerpFast(specColor, ((float3)(grazingTerm)), nv);
}

// ---- BRDF3_Unity_PBS: normalized Phong by lookup, implicit visibility, no direct Fresnel ----

float3 BRDF3_Direct(float3 diffColor, float3 specColor, float rlPow4, float smoothness) {
    float specular = pbr_unity_NHxRoughness_lookup(rlPow4, pbr_perceptual_roughness_from_smoothness(smoothness));
    return diffColor + specular * specColor;
}

float3 BRDF3_Indirect(float3 diffColor, float3 specColor, UnityIndirect indirect, float grazingTerm,
                    float fresnelTerm) {
    float3 c = indirect.diffuse * diffColor;
    c += indirect.specular * lerp(specColor, ((float3)(grazingTerm)), fresnelTerm);
    return c;
}

// reflect(viewDir, normal) with viewDir towards the eye is minus the mirror direction; R·L
// only enters as (R·L)^4, so the sign is immaterial (as in Unity).
float3 pbr_unity_brdf3(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                     float3 normal, float3 viewDir, float3 lightColor, float3 lightDir,
                     float3 indirectDiffuse, float3 indirectSpecular) {
    float3 reflDir = reflect(viewDir, normal);
    float nl = pbr_saturate(dot(normal, lightDir));
    float nv = pbr_saturate(dot(normal, viewDir));
    float2 rlPow4AndFresnelTerm = Pow4(float2(dot(reflDir, lightDir), 1.0 - nv));
    float rlPow4 = rlPow4AndFresnelTerm.x;
    float fresnelTerm = rlPow4AndFresnelTerm.y;
    float grazingTerm = pbr_saturate(smoothness + (1.0 - oneMinusReflectivity));
    float3 color = BRDF3_Direct(diffColor, specColor, rlPow4, smoothness);
    color *= lightColor * nl;
    UnityIndirect gi;
    gi.diffuse = indirectDiffuse;
    gi.specular = indirectSpecular;
    color += BRDF3_Indirect(diffColor, specColor, gi, grazingTerm, fresnelTerm);
    return color;
}

// UNITY_BRDF_PBS: the BRDF of the tier (PBR_UNITY_BRDF, set by the tier block of
// pbr/shading/dispatch.hlsl). The only conditional chain of the unity model's BRDF.
float3 pbr_unity_brdf_pbs(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                        float3 normal, float3 viewDir, float3 lightColor, float3 lightDir,
                        float3 indirectDiffuse, float3 indirectSpecular) {
#if PBR_UNITY_BRDF == PBR_UNITY_BRDF_1
    return pbr_unity_brdf1(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
                           lightColor, lightDir, indirectDiffuse, indirectSpecular);
#elif PBR_UNITY_BRDF == PBR_UNITY_BRDF_2
    return pbr_unity_brdf2(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
                           lightColor, lightDir, indirectDiffuse, indirectSpecular);
#elif PBR_UNITY_BRDF == PBR_UNITY_BRDF_3
    return pbr_unity_brdf3(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
                           lightColor, lightDir, indirectDiffuse, indirectSpecular);
#else
#error "PBR_UNITY_BRDF: unknown value (PBR_UNITY_BRDF_1, _2 or _3)"
#endif
}

// ---- Unity's entry points, Unity's signatures ---------------------------------------------

float4 BRDF1_Unity_PBS(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                     float3 normal, float3 viewDir, UnityLight light, UnityIndirect gi) {
    return float4(pbr_unity_brdf1(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
                                light.color, light.dir, gi.diffuse, gi.specular), 1.0);
}

float4 BRDF2_Unity_PBS(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                     float3 normal, float3 viewDir, UnityLight light, UnityIndirect gi) {
    return float4(pbr_unity_brdf2(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
                                light.color, light.dir, gi.diffuse, gi.specular), 1.0);
}

float4 BRDF3_Unity_PBS(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                     float3 normal, float3 viewDir, UnityLight light, UnityIndirect gi) {
    return float4(pbr_unity_brdf3(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
                                light.color, light.dir, gi.diffuse, gi.specular), 1.0);
}

// UNITY_BRDF_PBS (UnityPBSLighting.cginc): the BRDF of the graphics tier (UNITY_PBS_USE_BRDF1/2/3),
// here the quality tier's (pbr_unity_brdf_pbs).
float4 pbr_unity_BRDF_PBS(float3 diffColor, float3 specColor, float oneMinusReflectivity, float smoothness,
                        float3 normal, float3 viewDir, UnityLight light, UnityIndirect gi) {
    return float4(pbr_unity_brdf_pbs(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir,
                                   light.color, light.dir, gi.diffuse, gi.specular), 1.0);
}
#define UNITY_BRDF_PBS pbr_unity_BRDF_PBS
#endif
