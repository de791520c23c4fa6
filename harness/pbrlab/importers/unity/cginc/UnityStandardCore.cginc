// pbrlab stand-in for Unity's UnityStandardCore.cginc: the Standard shader's forward passes.
//
// Provides: struct FragmentCommonData; MetallicSetup, SpecularSetup, RoughnessSetup (the
//   three UNITY_SETUP_BRDF_INPUT workflows: Standard, StandardSpecular, AutodeskInteractive);
//   FragmentSetup; struct VertexOutputForwardBase; vertForwardBase(VertexInput),
//   fragForwardBaseInternal(VertexOutputForwardBase), fragForwardAddInternal (the ForwardAdd
//   pass's one light, on the same vertex output); OutputForward(color, alpha).
// Unity's file: the same names and keywords (_NORMALMAP, _PARALLAXMAP, _ALPHATEST_ON,
//   _ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON, _EMISSION, ...), read for their behaviour
//   (UnityStandardCore.cginc, Unity 2019.4 built-in shaders) and written here anew.
// Shading: what a `#pragma surface surf Standard` (or StandardSpecular) surface shader with the
//   same albedo, metallic or specular, smoothness, normal, occlusion and emission shows, pixel
//   for pixel: the lighting is pbr_unity_lighting, the body of pbrlab's LightingStandard
//   (pbr/unity/surface_standard.glsl; its PBR_BRDF_MODEL picks pbrlab's BRDF or Unity's
//   BRDF1-3), the GI is UnityGlobalIllumination with the prefiltered environment
//   (pbr/unity/global_illumination.glsl), the light is the pass's (_LightColor0,
//   _WorldSpaceLightPos0).
// Differences: one path for Unity's two (UNITY_STANDARD_SIMPLE's per-vertex shortcuts are not
//   taken); the view vector and the tangent frame are per pixel (Unity interpolates a
//   per-vertex eye vector); no lightmaps, shadows or fog (the harness has none).
//   _GLOSSYREFLECTIONS_OFF reflects the environment's most blurred level (perceptual
//   roughness 1) along the reflection, where Unity reflects unity_IndirectSpecColor (the
//   sky's average colour). _SPECULARHIGHLIGHTS_OFF is refused when a material enables it
//   (harness/pbrlab/importers/unity/parse.py, STAND_IN_REFUSED_KEYWORDS).
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_STANDARD_CORE_CGINC
#define PBRLAB_UNITY_STANDARD_CORE_CGINC

#include "UnityStandardConfig.cginc"
#include "UnityStandardInput.cginc"

struct FragmentCommonData
{
    half3 diffColor;
    half3 specColor;
    half3 coatF0;          // the dielectric layer over the diffuse (pbr_unity_lighting's coatF0)
    half oneMinusReflectivity;
    half smoothness;
    float3 normalWorld;
    float3 eyeVec;         // unit, from the camera to the point
    half alpha;
    float3 posWorld;
};

// Metallic workflow (Standard): albedo and metallic to diffuse and specular colours.
FragmentCommonData MetallicSetup(float4 i_tex)
{
    half2 metallicGloss = MetallicGloss(i_tex.xy);
    FragmentCommonData o;
    o.diffColor = DiffuseAndSpecularFromMetallic(Albedo(i_tex), metallicGloss.x, o.specColor,
                                                 o.oneMinusReflectivity);
    o.coatF0 = unity_ColorSpaceDielectricSpec.rgb;
    o.smoothness = metallicGloss.y;
    return o;
}

// Specular workflow (StandardSpecular): the diffuse keeps what the specular colour leaves.
FragmentCommonData SpecularSetup(float4 i_tex)
{
    half4 specGloss = SpecularGloss(i_tex.xy);
    FragmentCommonData o;
    o.specColor = specGloss.rgb;
    o.diffColor = EnergyConservationBetweenDiffuseAndSpecular(Albedo(i_tex), specGloss.rgb,
                                                              o.oneMinusReflectivity);
    o.coatF0 = specGloss.rgb;
    o.smoothness = specGloss.a;
    return o;
}

// Roughness workflow (AutodeskInteractive): the metallic workflow with smoothness 1 - roughness.
FragmentCommonData RoughnessSetup(float4 i_tex)
{
    half2 metallicRough = MetallicRough(i_tex.xy);
    FragmentCommonData o;
    o.diffColor = DiffuseAndSpecularFromMetallic(Albedo(i_tex), metallicRough.x, o.specColor,
                                                 o.oneMinusReflectivity);
    o.coatF0 = unity_ColorSpaceDielectricSpec.rgb;
    o.smoothness = metallicRough.y;
    return o;
}

// The unit tangent of the pixel's frame: the interpolated tangent made orthogonal to the unit
// normal n (Gram-Schmidt), any tangent where it is parallel to n.
float3 StandardPixelTangent(float3 n, float4 tangentWorld)
{
    float3 t = tangentWorld.xyz - n * dot(n, tangentWorld.xyz);
    float tl = dot(t, t);
    return tl > 1e-12 ? t * rsqrt(tl) : pbr_tangent_to_world(float3(1.0, 0.0, 0.0), n);
}

// Everything the lighting needs at one pixel: parallax applied to the UVs, alpha tested,
// the workflow's colours, the world normal (normal-mapped with _NORMALMAP), and the
// transparent mode's premultiplied diffuse (_ALPHAPREMULTIPLY_ON).
FragmentCommonData FragmentSetup(float4 i_tex, float3 posWorld, float3 normalVertex, float4 tangentWorld)
{
    float3 n = normalize(normalVertex);
    float3 eyeVec = normalize(posWorld - _WorldSpaceCameraPos);
#if defined(_PARALLAXMAP)
    float3 t = StandardPixelTangent(n, tangentWorld);
    float3 b = cross(n, t) * (tangentWorld.w < 0.0 ? -1.0 : 1.0);
    i_tex = Parallax(i_tex, half3(dot(-eyeVec, t), dot(-eyeVec, b), dot(-eyeVec, n)));
#endif
    half alpha = Alpha(i_tex.xy);
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
    FragmentCommonData o = UNITY_SETUP_BRDF_INPUT(i_tex);
#if defined(_NORMALMAP)
    o.normalWorld = pbrlab_tangent_to_world_normal(NormalInTangentSpace(i_tex), n, tangentWorld);
#else
    o.normalWorld = n;
#endif
    o.eyeVec = eyeVec;
    o.posWorld = posWorld;
#if defined(_ALPHAPREMULTIPLY_ON)
    // the diffuse fades with alpha, the reflection does not; alpha grows with reflectivity
    o.diffColor *= alpha;
    o.alpha = 1.0 - o.oneMinusReflectivity + alpha * o.oneMinusReflectivity;
#else
    o.alpha = alpha;
#endif
    return o;
}

// The pass's colour: alpha kept only where the pass blends by it (fade, transparent).
half4 OutputForward(half4 output, half alphaFromSurface)
{
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
    output.a = alphaFromSurface;
#else
    UNITY_OPAQUE_ALPHA(output.a);
#endif
    return output;
}

struct VertexOutputForwardBase
{
    float4 pos : SV_POSITION;
    float4 tex : TEXCOORD0;          // xy: main UV, zw: detail UV
    float3 posWorld : TEXCOORD1;
    float3 normalWorld : TEXCOORD2;
    float4 tangentWorld : TEXCOORD3; // w: the bitangent's sign
};

VertexOutputForwardBase vertForwardBase(VertexInput v)
{
    VertexOutputForwardBase o;
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.posWorld = mul(unity_ObjectToWorld, float4(v.vertex.xyz, 1.0)).xyz;
    o.normalWorld = UnityObjectToWorldNormal(v.normal);
    o.tangentWorld = float4(UnityObjectToWorldDir(v.tangent.xyz), v.tangent.w);
    return o;
}

// The main light, the ambient and the environment, then the emission.
half4 fragForwardBaseInternal(VertexOutputForwardBase i)
{
    FragmentCommonData s = FragmentSetup(i.tex, i.posWorld, i.normalWorld, i.tangentWorld);
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    half occlusion = Occlusion(i.tex.xy);
    UnityGIInput d;
    d.light.color = _LightColor0.rgb;
    d.light.dir = _WorldSpaceLightPos0.xyz;
    d.worldPos = s.posWorld;
    d.worldViewDir = -s.eyeVec;
    d.atten = atten;
    d.ambient = half3(0.0, 0.0, 0.0);
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.smoothness, -s.eyeVec, s.normalWorld, s.specColor);
#if defined(_GLOSSYREFLECTIONS_OFF)
    g.roughness = 1.0;
#endif
    UnityGI gi = UnityGlobalIllumination(d, pbr_unity_gi_occlusion(occlusion), s.normalWorld, g);
    half4 c = pbr_unity_lighting(s.diffColor, s.specColor, s.coatF0, s.oneMinusReflectivity, s.smoothness,
                                 occlusion, 1.0, s.normalWorld, -s.eyeVec, gi);
    c.rgb += Emission(i.tex.xy);
    return OutputForward(c, s.alpha);
}

// One additional light (ForwardAdd): no ambient, environment or emission, which the base pass
// drew. _WorldSpaceLightPos0.w is 0 for a directional light, 1 for a positional one; the
// light's falloff is already in _LightColor0 (README, "Unity shaders").
half4 fragForwardAddInternal(VertexOutputForwardBase i)
{
    FragmentCommonData s = FragmentSetup(i.tex, i.posWorld, i.normalWorld, i.tangentWorld);
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    UnityGI gi;
    gi.light.color = _LightColor0.rgb * atten;
    gi.light.dir = normalize(_WorldSpaceLightPos0.xyz - s.posWorld * _WorldSpaceLightPos0.w);
    gi.indirect.diffuse = half3(0.0, 0.0, 0.0);
    gi.indirect.specular = half3(0.0, 0.0, 0.0);
    half4 c = pbr_unity_lighting(s.diffColor, s.specColor, s.coatF0, s.oneMinusReflectivity, s.smoothness,
                                 1.0, 1.0, s.normalWorld, -s.eyeVec, gi);
    return OutputForward(c, s.alpha);
}

#endif
