// pbrlab stand-in for Unity's UnityStandardParticles.cginc (Particles/Standard Unlit, Particles/
// Standard Surface and user shaders written on them).
//
// Provides: the vertex input appdata_particles (POSITION, NORMAL, COLOR, TEXCOORD0, the
//   flipbook blend in TEXCOORD1, TANGENT), the surface Input (color, texcoord,
//   texcoord2AndBlend, projectedPosition, grabPassPosition) and the unlit pass's VertexOutput
//   (the same, with SV_POSITION and the fog coordinate); readTexture(tex, Input) and readTexture(tex, VertexOutput); the material's
//   uniforms (_MainTex, _MainTex_ST, _Color, _BumpMap, _BumpScale, _EmissionMap,
//   _EmissionColor, _MetallicGlossMap, _Metallic, _Glossiness, _CameraDepthTexture,
//   _SoftParticleFadeParams, _CameraFadeParams, _Cutoff; _GrabTexture, _DistortionStrengthScaled,
//   _DistortionBlend with distortion; _ColorAddSubDiff with _COLORADDSUBDIFF_ON); RGBtoHSV and
//   HSVtoRGB (with _COLORCOLOR_ON); the macros vertTexcoord(v, o), vertFading(o),
//   vertDistortion(o), fragColorMode(i), ALBEDO_MUL, fragSoftParticles(i),
//   fragCameraFading(i), fragDistortion(i); the surface shader's vert(appdata_particles, Input)
//   and surf(Input, SurfaceOutputStandard); the unlit pass's vertParticleUnlit and
//   fragParticleUnlit.
// Unity's file: the same names (UnityStandardParticles.cginc, Unity 2019.4 built-in shaders,
//   MIT), read for their behaviour and written here anew. What they compute (Unity Manual,
//   "Standard Particle Shaders": Color Mode, Flip-Book Mode, Soft Particles, Camera Fading,
//   Distortion):
//   - albedo = readTexture(_MainTex) * _Color, then the particle's colour (the vertex colour)
//     by Color Mode: Multiply (no keyword) albedo * colour; Overlay (_COLOROVERLAY_ON) per
//     channel 2 a c where a <= 0.5, else 1 - 2 (1 - a)(1 - c), alpha multiplied; Color
//     (_COLORCOLOR_ON) the colour's hue and saturation with the albedo's value (HSV), alpha
//     multiplied; Additive / Subtractive / Difference (_COLORADDSUBDIFF_ON) albedo + colour *
//     _ColorAddSubDiff.x, then lerp(that, |that|, _ColorAddSubDiff.y), alpha multiplied (the
//     editor sets x = 1, -1 or 1 and y = 0, 0 or 1 for the three);
//   - flipbook blending (_REQUIRE_UV2): the second frame's UV in TEXCOORD0.zw and the blend in
//     TEXCOORD1.x, read as lerp(tex(uv), tex(uv2), blend); without it TEXCOORD0.xy by _MainTex_ST;
//   - camera fading (_FADING_ON): alpha (premultiplied: the colour) times
//     saturate((eye depth - _CameraFadeParams.x) * _CameraFadeParams.y);
//   - soft particles (SOFTPARTICLES_ON with _FADING_ON): times saturate(_SoftParticleFadeParams.y
//     ((scene eye depth - _SoftParticleFadeParams.x) - eye depth)), the scene's from
//     _CameraDepthTexture;
//   - distortion (EFFECT_BUMP): the GrabPass texture read at the grab position moved by the
//     normal's xy * _DistortionStrengthScaled * alpha, mixed in by saturate(alpha - _DistortionBlend);
//   - the unlit result: albedo (lerp(1, albedo.rgb, albedo.a) with _ALPHAMODULATE_ON) plus
//     emission * _EmissionColor (_EMISSION), alpha 1 unless a blended mode; _ALPHATEST_ON clips
//     albedo.a - _Cutoff + 0.0001. The surface: that albedo, metallic and smoothness (or
//     _MetallicGlossMap's r and a * _Glossiness), the normal map, emission, to Standard.
//   RGBtoHSV / HSVtoRGB: the branchless conversion of Sam Hocevar ("Fast branchless RGB to HSV
//   conversion in GLSL", lolengine.net, 2013), which Unity's are: hue from the largest channel's
//   sextant, with 1e-10 keeping a grey's division finite.
// Differences: the structs' members are there in every variant (see them). SOFTPARTICLES_ON is refused by keyword (source_text.STAND_IN_REFUSED_KEYWORDS):
//   it reads the camera's depth texture, which the harness does not supply; Unity sets it
//   globally only when soft particles are on and the camera renders a depth texture, so the
//   default variant, without it, is what runs. The Standard Particle shader GUI derives
//   _SoftParticleFadeParams, _CameraFadeParams, _ColorAddSubDiff and _DistortionStrengthScaled
//   from the user-facing properties; here they are the material's values as written (defaults
//   0, as a material saved without that GUI holds). No fog (the harness has none).
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_STANDARD_PARTICLES_CGINC
#define PBRLAB_UNITY_STANDARD_PARTICLES_CGINC

#include "UnityPBSLighting.cginc"

#if defined(_REQUIRE_UV2)
#define _FLIPBOOK_BLENDING 1
#endif
#if defined(EFFECT_BUMP)
#define _DISTORTION_ON 1
#endif

// The structs hold every member in every variant (Unity's declare the flipbook, fading and
// distortion members under their keywords): the harness reads a pass's structs once per shader,
// not per material keywords, and wires its stages by them; a member a variant does not use is
// written 0 and read by none. TEXCOORD0 is float4 (xy this frame's UV, zw the next frame's),
// as Unity's vertex fetch gives it whatever the variant reads.
struct appdata_particles
{
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float4 color : COLOR;
    float4 texcoords : TEXCOORD0;          // xy this frame, zw the next (flipbook blending)
    float texcoordBlend : TEXCOORD1;       // how far towards the next frame (flipbook blending)
    float4 tangent : TANGENT;
};

struct Input
{
    float4 color : COLOR;
    float2 texcoord;
    float3 texcoord2AndBlend;              // flipbook blending
    float4 projectedPosition;              // soft particles, camera fading: screen position, z the eye depth
    float4 grabPassPosition;               // distortion
};

struct VertexOutput
{
    float4 vertex : SV_POSITION;
    float4 color : COLOR;
    UNITY_FOG_COORDS(0)
    float2 texcoord : TEXCOORD1;
    float3 texcoord2AndBlend : TEXCOORD2;
    float4 projectedPosition : TEXCOORD3;
    float4 grabPassPosition : TEXCOORD4;
};

sampler2D _MainTex;
float4 _MainTex_ST;
half4 _Color;
sampler2D _BumpMap;
half _BumpScale;
sampler2D _EmissionMap;
half3 _EmissionColor;
sampler2D _MetallicGlossMap;
half _Metallic;
half _Glossiness;
UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
float4 _SoftParticleFadeParams;            // (near fade distance, 1 / fade distance)
float4 _CameraFadeParams;                  // (near fade distance, 1 / fade distance)
half _Cutoff;
#if defined(_DISTORTION_ON)
sampler2D _GrabTexture;
half _DistortionStrengthScaled;
half _DistortionBlend;
#endif
#if defined(_COLORADDSUBDIFF_ON)
half4 _ColorAddSubDiff;                    // (colour sign, how much of |result|)
#endif

#define SOFT_PARTICLE_NEAR_FADE _SoftParticleFadeParams.x
#define SOFT_PARTICLE_INV_FADE_DISTANCE _SoftParticleFadeParams.y
#define CAMERA_NEAR_FADE _CameraFadeParams.x
#define CAMERA_INV_FADE_DISTANCE _CameraFadeParams.y

// The texture at this frame's UV, blended towards the next frame's with flipbook blending.
fixed4 readTexture(sampler2D tex, Input IN)
{
    fixed4 sampled = tex2D(tex, IN.texcoord);
#if defined(_FLIPBOOK_BLENDING)
    sampled = lerp(sampled, tex2D(tex, IN.texcoord2AndBlend.xy), IN.texcoord2AndBlend.z);
#endif
    return sampled;
}

fixed4 readTexture(sampler2D tex, VertexOutput IN)
{
    fixed4 sampled = tex2D(tex, IN.texcoord);
#if defined(_FLIPBOOK_BLENDING)
    sampled = lerp(sampled, tex2D(tex, IN.texcoord2AndBlend.xy), IN.texcoord2AndBlend.z);
#endif
    return sampled;
}

#if defined(_COLORCOLOR_ON)
// Hocevar's branchless RGB -> HSV (header): order the channels by two selects, then hue from
// the largest one's sextant, saturation (max - min) / max, value max.
half3 RGBtoHSV(half3 rgb)
{
    half4 k = half4(0.0, -1.0 / 3.0, 2.0 / 3.0, -1.0);
    half4 gb = (rgb.g >= rgb.b) ? half4(rgb.g, rgb.b, k.x, k.y) : half4(rgb.b, rgb.g, k.w, k.z);
    half4 ordered = (rgb.r >= gb.x) ? half4(rgb.r, gb.y, gb.z, gb.x) : half4(gb.x, gb.y, gb.w, rgb.r);
    half range = ordered.x - min(ordered.w, ordered.y);
    half tiny = 1e-10;
    return half3(abs(ordered.z + (ordered.w - ordered.y) / (6.0 * range + tiny)), range / (ordered.x + tiny), ordered.x);
}

// Hocevar's HSV -> RGB: each channel a clamped triangle wave of the hue, mixed with white by
// the saturation, times the value.
half3 HSVtoRGB(half3 hsv)
{
    half3 wave = abs(frac(hsv.xxx + half3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
    return hsv.z * lerp(half3(1.0, 1.0, 1.0), saturate(wave - 1.0), hsv.y);
}
#endif

#if defined(_FLIPBOOK_BLENDING)
#define vertTexcoord(v, o) \
    o.texcoord = v.texcoords.xy; \
    o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#else
#define vertTexcoord(v, o) \
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#endif

#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
#define vertFading(o) \
    o.projectedPosition = ComputeScreenPos(clipPosition); \
    COMPUTE_EYEDEPTH(o.projectedPosition.z);
#else
#define vertFading(o)
#endif

#if defined(_DISTORTION_ON)
#define vertDistortion(o) \
    o.grabPassPosition = ComputeGrabScreenPos(clipPosition);
#else
#define vertDistortion(o)
#endif

// The particle's colour applied to `albedo` by Color Mode (header).
#if defined(_COLOROVERLAY_ON)
#define fragColorMode(i) \
    albedo.rgb = lerp(1.0 - 2.0 * (1.0 - albedo.rgb) * (1.0 - i.color.rgb), 2.0 * albedo.rgb * i.color.rgb, step(albedo.rgb, half3(0.5, 0.5, 0.5))); \
    albedo.a *= i.color.a;
#elif defined(_COLORCOLOR_ON)
#define fragColorMode(i) \
    half3 particleHSV = RGBtoHSV(i.color.rgb); \
    albedo = fixed4(HSVtoRGB(half3(particleHSV.x, particleHSV.y, RGBtoHSV(albedo.rgb).z)), albedo.a * i.color.a);
#elif defined(_COLORADDSUBDIFF_ON)
#define fragColorMode(i) \
    albedo.rgb = albedo.rgb + i.color.rgb * _ColorAddSubDiff.x; \
    albedo.rgb = lerp(albedo.rgb, abs(albedo.rgb), _ColorAddSubDiff.y); \
    albedo.a *= i.color.a;
#else
#define fragColorMode(i) \
    albedo *= i.color;
#endif

// What a fade scales: the colour when it is premultiplied by alpha, else alpha.
#if defined(_ALPHAPREMULTIPLY_ON)
#define ALBEDO_MUL albedo
#else
#define ALBEDO_MUL albedo.a
#endif

#if defined(SOFTPARTICLES_ON) && defined(_FADING_ON)
#define fragSoftParticles(i) \
    if (SOFT_PARTICLE_NEAR_FADE > 0.0 || SOFT_PARTICLE_INV_FADE_DISTANCE > 0.0) \
    { \
        float sceneZ = LinearEyeDepth(SAMPLE_DEPTH_TEXTURE_PROJ(_CameraDepthTexture, UNITY_PROJ_COORD(i.projectedPosition))); \
        ALBEDO_MUL *= saturate(SOFT_PARTICLE_INV_FADE_DISTANCE * ((sceneZ - SOFT_PARTICLE_NEAR_FADE) - i.projectedPosition.z)); \
    }
#else
#define fragSoftParticles(i)
#endif

#if defined(_FADING_ON)
#define fragCameraFading(i) \
    ALBEDO_MUL *= saturate((i.projectedPosition.z - CAMERA_NEAR_FADE) * CAMERA_INV_FADE_DISTANCE);
#else
#define fragCameraFading(i)
#endif

#if defined(_DISTORTION_ON)
#define fragDistortion(i) \
    float4 grabPosUV = UNITY_PROJ_COORD(i.grabPassPosition); \
    grabPosUV.xy += normal.xy * _DistortionStrengthScaled * albedo.a; \
    albedo.rgb = lerp(tex2Dproj(_GrabTexture, grabPosUV).rgb, albedo.rgb, saturate(albedo.a - _DistortionBlend));
#else
#define fragDistortion(i)
#endif

// The surface shader's vertex function (#pragma surface ... vertex:vert): vertTexcoord,
// vertFading and vertDistortion written out (the harness reads which Input members a vertex:
// function writes from its own text).
void vert(inout appdata_particles v, out Input o)
{
    UNITY_INITIALIZE_OUTPUT(Input, o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    o.texcoord2AndBlend = float3(0.0, 0.0, 0.0);
    o.projectedPosition = float4(0.0, 0.0, 0.0, 0.0);
    o.grabPassPosition = float4(0.0, 0.0, 0.0, 0.0);
#if defined(_FLIPBOOK_BLENDING)
    o.texcoord = v.texcoords.xy;
    o.texcoord2AndBlend = float3(v.texcoords.zw, v.texcoordBlend);
#else
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    o.projectedPosition = ComputeScreenPos(clipPosition);
    o.projectedPosition.z = -UnityObjectToViewPos(v.vertex).z;   // COMPUTE_EYEDEPTH
#endif
#if defined(_DISTORTION_ON)
    o.grabPassPosition = ComputeGrabScreenPos(clipPosition);
#endif
}

// The surface function: the particle's albedo (header), metallic, smoothness, normal, emission.
void surf(Input IN, inout SurfaceOutputStandard o)
{
    half4 albedo = readTexture(_MainTex, IN) * _Color;
    fragColorMode(IN);
    fragSoftParticles(IN);
    fragCameraFading(IN);
#if defined(_METALLICGLOSSMAP)
    fixed2 metallicGloss = readTexture(_MetallicGlossMap, IN).ra * fixed2(1.0, _Glossiness);
#else
    fixed2 metallicGloss = fixed2(_Metallic, _Glossiness);
#endif
#if defined(_NORMALMAP)
    float3 normal = normalize(UnpackScaleNormal(readTexture(_BumpMap, IN), _BumpScale));
#else
    float3 normal = float3(0.0, 0.0, 1.0);
#endif
#if defined(_EMISSION)
    half3 emission = readTexture(_EmissionMap, IN).rgb;
#else
    half3 emission = half3(0.0, 0.0, 0.0);
#endif
    fragDistortion(IN);
    o.Albedo = albedo.rgb;
#if defined(_NORMALMAP)
    o.Normal = normal;
#endif
    o.Emission = emission * _EmissionColor;
    o.Metallic = metallicGloss.r;
    o.Smoothness = metallicGloss.g;
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON) || defined(_ALPHAOVERLAY_ON)
    o.Alpha = albedo.a;
#else
    o.Alpha = 1.0;
#endif
#if defined(_ALPHAMODULATE_ON)
    o.Albedo = lerp(half3(1.0, 1.0, 1.0), albedo.rgb, albedo.a);
#endif
#if defined(_ALPHATEST_ON)
    clip(albedo.a - _Cutoff + 0.0001);
#endif
}

// The unlit pass's vertex function.
void vertParticleUnlit(appdata_particles v, out VertexOutput o)
{
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    o.vertex = clipPosition;
    o.color = v.color;
    o.texcoord2AndBlend = float3(0.0, 0.0, 0.0);
    o.projectedPosition = float4(0.0, 0.0, 0.0, 0.0);
    o.grabPassPosition = float4(0.0, 0.0, 0.0, 0.0);
    vertTexcoord(v, o);
    vertFading(o);
    vertDistortion(o);
    UNITY_TRANSFER_FOG(o, o.vertex);
}

// The unlit pass's fragment function: albedo (header), plus emission; alpha 1 unless blended.
half4 fragParticleUnlit(VertexOutput IN) : SV_Target
{
    half4 albedo = readTexture(_MainTex, IN) * _Color;
    fragColorMode(IN);
    fragSoftParticles(IN);
    fragCameraFading(IN);
#if defined(_NORMALMAP)
    float3 normal = normalize(UnpackScaleNormal(readTexture(_BumpMap, IN), _BumpScale));
#else
    float3 normal = float3(0.0, 0.0, 1.0);
#endif
#if defined(_EMISSION)
    half3 emission = readTexture(_EmissionMap, IN).rgb;
#else
    half3 emission = half3(0.0, 0.0, 0.0);
#endif
    fragDistortion(IN);
    half4 result = albedo;
#if defined(_ALPHAMODULATE_ON)
    result.rgb = lerp(half3(1.0, 1.0, 1.0), albedo.rgb, albedo.a);
#endif
    result.rgb += emission * _EmissionColor;
#if !defined(_ALPHABLEND_ON) && !defined(_ALPHAPREMULTIPLY_ON) && !defined(_ALPHAOVERLAY_ON)
    result.a = 1.0;
#endif
#if defined(_ALPHATEST_ON)
    clip(albedo.a - _Cutoff + 0.0001);
#endif
    UNITY_APPLY_FOG_COLOR(IN.fogCoord, result, fixed4(0.0, 0.0, 0.0, 0.0));
    return result;
}

#endif // PBRLAB_UNITY_STANDARD_PARTICLES_CGINC
