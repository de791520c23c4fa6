// pbrlab stand-in for the Universal Render Pipeline's ShaderLibrary/Core.hlsl: the names a URP
// shader reads from it, written for pbrlab from Unity's documentation of their meaning (URP's
// own ShaderLibrary is under the Unity Companion License and is not copied here). Included
// after pbrlab's Unity prelude (importers/unity/generate.py: the scene's uniforms, Unity's
// built-in variables unity_ObjectToWorld, UNITY_MATRIX_VP, _WorldSpaceCameraPos, ...), in
// HLSL as written and in GLSL through port-unity, like the shader itself. No fog, no shadow
// maps, no lightmaps, no XR here: their names exist and do nothing.
#ifndef PBRLAB_URP_CORE_HLSL
#define PBRLAB_URP_CORE_HLSL

#define UNIVERSAL_PIPELINE_CORE_INCLUDED
// The URP these stand-ins follow: version 12 (Unity 2021 LTS).
#define SHADER_LIBRARY_VERSION_MAJOR 12
#define SHADER_LIBRARY_VERSION_MINOR 1
#define real float
#define real2 float2
#define real3 float3
#define real4 float4
#define real3x3 float3x3
#define real4x4 float4x4
// Unity's half-precision limits (Common.hlsl): the smallest normal half and its square root.
#define HALF_MIN 6.103515625e-5
#define HALF_MIN_SQRT 0.0078125
#define FLT_MIN 1.175494351e-38
// The constants below are left undefined where the shader #defines the name itself, as well
// as where it did so before including Core (FXC takes a redefinition's body, with a warning;
// importers/unity/user_definitions.py). No stand-in reads them.
#if !defined(FLT_EPS) && !defined(PBRLAB_USER_DEFINES_FLT_EPS)
#define FLT_EPS 5.960464478e-8
#endif
#if !defined(PI) && !defined(PBRLAB_USER_DEFINES_PI)
#define PI 3.14159265359
#endif
#if !defined(TWO_PI) && !defined(PBRLAB_USER_DEFINES_TWO_PI)
#define TWO_PI 6.28318530718
#endif
#if !defined(INV_PI) && !defined(PBRLAB_USER_DEFINES_INV_PI)
#define INV_PI 0.31830988618
#endif
// Core RP's Macros.hlsl constants: multiples of pi and their reciprocals, to the digits
// Core RP spells them (pi = 3.14159265358979...).
#if !defined(FOUR_PI) && !defined(PBRLAB_USER_DEFINES_FOUR_PI)
#define FOUR_PI 12.5663706144
#endif
#if !defined(INV_TWO_PI) && !defined(PBRLAB_USER_DEFINES_INV_TWO_PI)
#define INV_TWO_PI 0.15915494309
#endif
#if !defined(INV_FOUR_PI) && !defined(PBRLAB_USER_DEFINES_INV_FOUR_PI)
#define INV_FOUR_PI 0.07957747155
#endif
#if !defined(HALF_PI) && !defined(PBRLAB_USER_DEFINES_HALF_PI)
#define HALF_PI 1.57079632679
#endif
#if !defined(INV_HALF_PI) && !defined(PBRLAB_USER_DEFINES_INV_HALF_PI)
#define INV_HALF_PI 0.636619772367
#endif
#if !defined(LOG2_E) && !defined(PBRLAB_USER_DEFINES_LOG2_E)
#define LOG2_E 1.44269504089
#endif
#if !defined(INV_SQRT2) && !defined(PBRLAB_USER_DEFINES_INV_SQRT2)
#define INV_SQRT2 0.70710678118
#endif
#if !defined(FLT_MAX) && !defined(PBRLAB_USER_DEFINES_FLT_MAX)
#define FLT_MAX 3.402823466e+38
#endif
#if !defined(HALF_MAX) && !defined(PBRLAB_USER_DEFINES_HALF_MAX)
#define HALF_MAX 65504.0
#endif

// SRP-batcher constant buffers: plain uniforms here.
#define CBUFFER_START(name)
#define CBUFFER_END
#define UNITY_DOTS_INSTANCING_START(name)
#define UNITY_DOTS_INSTANCING_END(name)
#define UNITY_DOTS_INSTANCED_PROP(type, name)

// Textures and samplers (Core RP's API macros), in HLSL: a texture object and a sampler state
// each (the GL texture's own filtering applies). In GLSL, port-unity spells every use in Cg's
// forms (importers/unity/port.py), so these are HLSL's alone.
#ifndef __VERSION__
#define TEXTURE2D(t) Texture2D t
#define TEXTURECUBE(t) TextureCube t
#define SAMPLER(s) SamplerState s
#define TEXTURE2D_PARAM(t, s) Texture2D t, SamplerState s
#define TEXTURECUBE_PARAM(t, s) TextureCube t, SamplerState s
#define TEXTURE2D_ARGS(t, s) t, s
#define TEXTURECUBE_ARGS(t, s) t, s
#define SAMPLE_TEXTURE2D(t, s, uv) t.Sample(s, uv)
#define SAMPLE_TEXTURE2D_LOD(t, s, uv, lod) t.SampleLevel(s, uv, lod)
#define SAMPLE_TEXTURE2D_BIAS(t, s, uv, bias) t.SampleBias(s, uv, bias)
#define SAMPLE_TEXTURE2D_GRAD(t, s, uv, dpdx, dpdy) t.SampleGrad(s, uv, dpdx, dpdy)
#define SAMPLE_TEXTURECUBE(t, s, d) t.Sample(s, d)
#define SAMPLE_TEXTURECUBE_LOD(t, s, d, lod) t.SampleLevel(s, d, lod)
#define TEXTURE3D(t) Texture3D t
#define TEXTURE3D_PARAM(t, s) Texture3D t, SamplerState s
#define TEXTURE3D_ARGS(t, s) t, s
#define SAMPLE_TEXTURE3D(t, s, uvw) t.Sample(s, uvw)
#define SAMPLE_TEXTURE3D_LOD(t, s, uvw, lod) t.SampleLevel(s, uvw, lod)
// The _X forms (a texture array per eye in XR; one 2D texture without XR, as here).
#define TEXTURE2D_X(t) Texture2D t
#define TEXTURE2D_X_FLOAT(t) Texture2D t
#define SAMPLE_TEXTURE2D_X(t, s, uv) t.Sample(s, uv)
#define SAMPLE_TEXTURE2D_X_LOD(t, s, uv, lod) t.SampleLevel(s, uv, lod)
// 2D texture arrays (Core RP's API: the layer index after the uv) and shadow-map textures with
// their comparison samplers (SAMPLE_TEXTURE2D_SHADOW: the comparison of coord.z with the texel,
// Texture2D.SampleCmpLevelZero).
#define TEXTURE2D_ARRAY(t) Texture2DArray t
#define TEXTURE2D_ARRAY_PARAM(t, s) Texture2DArray t, SamplerState s
#define TEXTURE2D_ARRAY_ARGS(t, s) t, s
#define SAMPLE_TEXTURE2D_ARRAY(t, s, uv, index) t.Sample(s, float3(uv, index))
#define SAMPLE_TEXTURE2D_ARRAY_LOD(t, s, uv, index, lod) t.SampleLevel(s, float3(uv, index), lod)
#define TEXTURE2D_SHADOW(t) Texture2D t
#define SAMPLER_CMP(s) SamplerComparisonState s
#define TEXTURE2D_SHADOW_PARAM(t, s) Texture2D t, SamplerComparisonState s
#define TEXTURE2D_SHADOW_ARGS(t, s) t, s
#define SAMPLE_TEXTURE2D_SHADOW(t, s, coord3) t.SampleCmpLevelZero(s, (coord3).xy, (coord3).z)
// their array and cube forms (Core RP's API: the array's layer after the coordinate; the
// cube's coord4.xyz the direction, coord4.w the reference)
#define TEXTURE2D_ARRAY_SHADOW(t) Texture2DArray t
#define TEXTURE2D_ARRAY_SHADOW_PARAM(t, s) Texture2DArray t, SamplerComparisonState s
#define TEXTURE2D_ARRAY_SHADOW_ARGS(t, s) t, s
#define SAMPLE_TEXTURE2D_ARRAY_SHADOW(t, s, coord3, index) t.SampleCmpLevelZero(s, float3((coord3).xy, index), (coord3).z)
#define TEXTURECUBE_SHADOW(t) TextureCube t
#define TEXTURECUBE_SHADOW_PARAM(t, s) TextureCube t, SamplerComparisonState s
#define TEXTURECUBE_SHADOW_ARGS(t, s) t, s
#define SAMPLE_TEXTURECUBE_SHADOW(t, s, coord4) t.SampleCmpLevelZero(s, (coord4).xyz, (coord4).w)
// Core RP's texel loads: integer texel coordinates, mip 0 unless given (Texture2D.Load)
#define LOAD_TEXTURE2D(t, coord) t.Load(int3(coord, 0))
#define LOAD_TEXTURE2D_LOD(t, coord, lod) t.Load(int3(coord, lod))
#define LOAD_TEXTURE2D_X(t, coord) t.Load(int3(coord, 0))
#define LOAD_TEXTURE2D_X_LOD(t, coord, lod) t.Load(int3(coord, lod))
// Core RP's depth reads take a sampler (three arguments; the built-in pipeline's, which the
// Unity prelude defines, take two): in a program that includes Core.hlsl, Core's win, as in
// Unity where URP programs never see UnityCG.cginc's. The red channel of the texture's sample.
#undef SAMPLE_DEPTH_TEXTURE
#undef SAMPLE_DEPTH_TEXTURE_LOD
#define SAMPLE_DEPTH_TEXTURE(t, s, uv) t.Sample(s, uv).r
#define SAMPLE_DEPTH_TEXTURE_LOD(t, s, uv, lod) t.SampleLevel(s, uv, lod).r
// the platform's header: the declarations' precision forms (TEXTURE2D_FLOAT, ...)
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/API/GLCore.hlsl"
#endif

// HLSL intrinsics GLSL lacks, for the GLSL port (HLSL has them built in): rcp(x) = 1 / x;
// fwidth in a vertex stage, which has no derivatives, is 0 (as cg_compat.glsl's ddx, ddy).
#ifdef __VERSION__
float rcp(float x) { return 1.0 / x; }
vec2 rcp(vec2 x) { return 1.0 / x; }
vec3 rcp(vec3 x) { return 1.0 / x; }
vec4 rcp(vec4 x) { return 1.0 / x; }
#ifdef PBR_UNITY_VERTEX_STAGE
#define fwidth(x) ((x) * 0.0)
#endif
#endif

// Instancing and stereo: one instance, one eye (the built-in prelude's names, where it has them).
// UNITY_INSTANCING_INCLUDED: Core RP's UnityInstancing.hlsl's include guard, which URP's Core.hlsl
// includes; shaders test it to learn that the instancing macros exist.
#define UNITY_INSTANCING_INCLUDED
#define UNITY_ANY_INSTANCING_ENABLED 0
// A local set to its type's zero (Core RP's ZERO_INITIALIZE; the GLSL port spells it out first).
#define ZERO_INITIALIZE(type, name) name = (type)0
#ifndef UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_VERTEX_INPUT_INSTANCE_ID
#endif
#ifndef UNITY_VERTEX_OUTPUT_STEREO
#define UNITY_VERTEX_OUTPUT_STEREO
#endif
#ifndef UNITY_SETUP_INSTANCE_ID
#define UNITY_SETUP_INSTANCE_ID(v)
#endif
#ifndef UNITY_TRANSFER_INSTANCE_ID
#define UNITY_TRANSFER_INSTANCE_ID(a, b)
#endif
#ifndef UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO
#define UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o)
#endif
#ifndef UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX
#define UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i)
#endif

// A fragment's facing (FRONT_FACE_TYPE and FRONT_FACE_SEMANTIC are read as bool and
// SV_IsFrontFace: importers/unity/parse.py's URP spellings).
#define IS_FRONT_VFACE(VAL, FRONT, BACK) ((VAL) ? (FRONT) : (BACK))
#define FRONT_FACE_TYPE bool
#define FRONT_FACE_SEMANTIC SV_IsFrontFace

// Fog: none here (ComputeFogFactor 0, MixFog leaves the colour).
float ComputeFogFactor(float z) { return 0.0; }
float3 MixFog(float3 color, float fogFactor) { return color; }
float3 MixFogColor(float3 color, float3 fogColor, float fogFactor) { return color; }
// URP 12+'s per-pixel fog factor: the vertex stage's where fog is not computed per pixel
// (no _FOG_FRAGMENT fog here), so with no fog the vertex stage's 0
float InitializeInputDataFog(float4 positionWS, float vertFogFactor) { return vertFogFactor; }
// URP's rendering debugger's texture data (Debugging3D.hlsl): nothing without the debugger
#define SETUP_DEBUG_TEXTURE_DATA(inputData, uv, texture)
#define SETUP_DEBUG_TEXTURE_DATA_2D(inputData, positionWS, texture)

// URP's ShaderVariablesFunctions: the alpha a pass writes, the surface's own for a transparent
// surface (surfaceType 1) and 1 for an opaque one (0, the default); AlphaDiscard clips
// alpha - cutoff + offset below 0 where _ALPHATEST_ON is defined (and does nothing elsewhere)
// and returns the alpha (URP 12 and later return it, for alpha to coverage, which needs MSAA:
// without it the kept alpha is the input; URP 10's returned nothing, and a call that ignores
// the value is the same); AlphaModulate fakes a multiply blend's alpha under _ALPHAMODULATE_ON,
// the albedo lerped from white by alpha, and leaves it elsewhere.
float OutputAlpha(float outputAlpha, float surfaceType = 0.0) { return surfaceType == 1.0 ? outputAlpha : 1.0; }
// surfaceType 1: transparent (URP's SurfaceType enum, Opaque 0)
bool IsSurfaceTypeTransparent(float surfaceType) { return surfaceType == 1.0; }
float AlphaDiscard(float alpha, float cutoff, float offset = 0.0) {
#ifdef _ALPHATEST_ON
    clip(alpha - cutoff + offset);
#endif
    return alpha;
}
float3 AlphaModulate(float3 albedo, float alpha) {
#if defined(_ALPHAMODULATE_ON)
    return lerp(float3(1.0, 1.0, 1.0), albedo, alpha);
#else
    return albedo;
#endif
}

// numer / denom, and 1 where they are equal (Core RP's SafeDiv: 0 / 0 and inf / inf are 1).
float SafeDiv(float numer, float denom) { return (numer != denom) ? numer / denom : 1.0; }

// v / |v|, and 0-safe: |v|^2 floored at FLT_MIN (Unity's SafeNormalize).
float3 SafeNormalize(float3 v) { return v * rsqrt(max(FLT_MIN, dot(v, v))); }

// SRP's names for the object's inverse matrix and the view's (the built-in prelude has
// UNITY_MATRIX_M, _V, _I_V, _P, _VP).
#define UNITY_MATRIX_I_M unity_WorldToObject
#define UNITY_PREV_MATRIX_M unity_ObjectToWorld
#define UNITY_PREV_MATRIX_I_M unity_WorldToObject
// URP's inverse camera matrices (UnityInput.hlsl: unity_MatrixInvV, unity_MatrixInvP and
// unity_MatrixInvVP, and their UNITY_MATRIX_I_ names), all from the one camera the harness
// sets: the inverse projection is unity_CameraInvProjection (the GL projection's inverse: URP's
// GPU projection on GL is the camera's own), and the inverse view-projection is
// (P V)^-1 = V^-1 P^-1.
#define unity_MatrixInvP unity_CameraInvProjection
#define unity_MatrixInvVP mul(unity_MatrixInvV, unity_CameraInvProjection)
#define UNITY_MATRIX_I_P unity_MatrixInvP
#define UNITY_MATRIX_I_VP unity_MatrixInvVP
// UnityPerDraw's LOD cross-fade (UnityInput.hlsl's unity_LODFade: x the fade, y x quantized to
// 16 levels): pbrlab's scenes have no LOD Group, every object is its only level, fully shown,
// the value Unity gives a renderer that is not fading: (1, 1, 0, 0) (LODCrossFade.hlsl reads it).
static const float4 unity_LODFade = float4(1.0, 1.0, 0.0, 0.0);
// Core RP's camera-relative rendering (SpaceTransforms.hlsl): a world position relative to the
// camera and back. URP renders with camera-relative rendering off (Core's ShaderConfig
// SHADEROPTIONS_CAMERA_RELATIVE_RENDERING is 0 for URP; HDRP's is 1), so both are the identity.
float3 GetAbsolutePositionWS(float3 positionRWS) { return positionRWS; }
float3 GetCameraRelativePositionWS(float3 positionWS) { return positionWS; }
// GL's clip-space near plane: z = -w (Unity's UNITY_NEAR_CLIP_VALUE on OpenGL, not reversed-Z).
#define UNITY_NEAR_CLIP_VALUE (-1.0)
// the far plane's raw depth (Core RP's API files: 1 where depth is not reversed, as on GL)
#define UNITY_RAW_FAR_CLIP_VALUE (1.0)
// URP's time globals (UnityInput.hlsl: _TimeParameters = (t, sin t, cos t, 0)) from the built-in
// _Time the harness sets (t = _Time.y: 0 in a still frame)
#define _TimeParameters float4(_Time.y, sin(_Time.y), cos(_Time.y), 0.0)
// The screen's size at URP's render scale, which is 1 here: _ScreenParams.
#define _ScaledScreenParams _ScreenParams
// URP's _ScreenSize (UnityInput.hlsl: width, height, 1 / width, 1 / height of the camera's target),
// the same screen: the size from _ScreenParams.xy and its reciprocal.
#define _ScreenSize float4(_ScreenParams.xy, 1.0 / _ScreenParams.xy)
// URP's main light globals (Input.hlsl): the direction towards the scene's first directional
// light (w 0) and its radiance; with none, URP's defaults: (0, 0, 1, 0) and black.
#if defined(PBRLAB_DIRECTIONAL_COUNT) && PBRLAB_DIRECTIONAL_COUNT > 0
#define _MainLightPosition float4(-u_directional_direction[0], 0.0)
#define _MainLightColor float4(u_directional_radiance[0], 1.0)
#else
#define _MainLightPosition float4(0.0, 0.0, 1.0, 0.0)
#define _MainLightColor float4(0.0, 0.0, 0.0, 0.0)
#endif
// URP's sky reflection cube (Input.hlsl: _GlossyEnvironmentCubeMap, its sampler and its HDR
// decode _GlossyEnvironmentCubeMap_HDR), which URP sets to the sky's reflection probe, the one
// unity_SpecCube0 holds where no other probe covers the object: here the scene environment's
// prefiltered chain, read by its mip in Unity's steps, as unity_SpecCube0 is
// (templates/unity_surface.inc: pbrlab_unity_reflection_probe); its decode is the identity, as
// unity_SpecCube0_HDR's. HLSL reads it through the probe's object (unity_hlsl_support.hlsl), GLSL
// through the port's spelling of SAMPLE_TEXTURECUBE(_LOD) (importers/unity/port.py).
#define _GlossyEnvironmentCubeMap_HDR unity_SpecCube0_HDR
#ifndef __VERSION__
static PbrlabUnityReflectionProbe _GlossyEnvironmentCubeMap;
SamplerState sampler_GlossyEnvironmentCubeMap;
#endif

// A [0, 1] depth to the eye's distance and to [0, 1] of the far plane, with the
// _ZBufferParams the caller passes (Core RP's signatures; the built-in ones take z alone):
// 1 / (zBufferParam.z z + zBufferParam.w) and 1 / (zBufferParam.x z + zBufferParam.y).
float LinearEyeDepth(float depth, float4 zBufferParam) { return 1.0 / (zBufferParam.z * depth + zBufferParam.w); }
float Linear01Depth(float depth, float4 zBufferParam) { return 1.0 / (zBufferParam.x * depth + zBufferParam.y); }
// A vector depth (a depth texture's whole sample, SAMPLE_TEXTURE2D(...)): FXC has no exact
// overload and truncates it to its first component (implicit truncation, warning X3206), the
// (float, float4) form's, since no vector converts to float4x4; glslang would refuse, so the
// truncation is spelled out here.
float LinearEyeDepth(float2 depth, float4 zBufferParam) { return LinearEyeDepth(depth.x, zBufferParam); }
float LinearEyeDepth(float4 depth, float4 zBufferParam) { return LinearEyeDepth(depth.x, zBufferParam); }
float Linear01Depth(float2 depth, float4 zBufferParam) { return Linear01Depth(depth.x, zBufferParam); }
float Linear01Depth(float4 depth, float4 zBufferParam) { return Linear01Depth(depth.x, zBufferParam); }
// Core RP's other LinearEyeDepth: a world position's distance along the view axis, |view z| of
// mul(viewMatrix, float4(positionWS, 1)) (a right-handed view looks down -z: the absolute value).
float LinearEyeDepth(float3 positionWS, float4x4 viewMatrix) { return abs(mul(viewMatrix, float4(positionWS, 1.0)).z); }
// URP's ShaderVariablesFunctions.hlsl: a depth that is already linear in [0, 1] (an orthographic
// camera's) to the eye's distance, near + (far - near) depth with _ProjectionParams' y = near and
// z = far (UNITY_REVERSED_Z is undefined on GL, so 0 is the near plane).
float LinearDepthToEyeDepth(float rawDepth) { return _ProjectionParams.y + (_ProjectionParams.z - _ProjectionParams.y) * rawDepth; }

// Core RP's Common.hlsl: x remapped so that start -> 0 and start + length -> 1, clamped, from
// 1 / length and start / length: saturate(x rcpLength - startTimesRcpLength).
float Remap01(float x, float rcpLength, float startTimesRcpLength) { return saturate(x * rcpLength - startTimesRcpLength); }
// Core RP's Common.hlsl: the smallest and the largest of three values, per component.
float Min3(float a, float b, float c) { return min(min(a, b), c); }
float2 Min3(float2 a, float2 b, float2 c) { return min(min(a, b), c); }
float3 Min3(float3 a, float3 b, float3 c) { return min(min(a, b), c); }
float4 Min3(float4 a, float4 b, float4 c) { return min(min(a, b), c); }
float Max3(float a, float b, float c) { return max(max(a, b), c); }
float2 Max3(float2 a, float2 b, float2 c) { return max(max(a, b), c); }
float3 Max3(float3 a, float3 b, float3 c) { return max(max(a, b), c); }
float4 Max3(float4 a, float4 b, float4 c) { return max(max(a, b), c); }
// Core RP's Common.hlsl FastSign: -1 for a negative value, 1 for a positive one; zero, +0 or -0,
// is 1 (Core's default, ignoreNegZero true: -0 counted as +0, as mathematics treats 0);
// with ignoreNegZero false, -0 is -1 (its sign bit).
float FastSign(float s) { return s >= 0.0 ? 1.0 : -1.0; }
float FastSign(float s, bool ignoreNegZero) { return ignoreNegZero ? FastSign(s) : ((asuint(s) >> 31) != 0u ? -1.0 : 1.0); }
// Core RP's Color.hlsl Luminance: Rec. 709 relative luminance of a linear colour (ITU-R BT.709,
// the sRGB primaries; weights sum to 1). The Unity prelude's Luminance is the built-in pipeline's
// (unity_ColorSpaceLuminance, linear weights summing to 0.504): URP programs never see it, so
// from here on a call of Luminance in a URP program is Core RP's.
float PbrlabCoreLuminance(float3 linearRgb) { return dot(linearRgb, float3(0.2126729, 0.7151522, 0.0721750)); }
#define Luminance(linearRgb) PbrlabCoreLuminance(linearRgb)
// Core RP's Color.hlsl: the colour's deviation from the mean of its channels scaled by
// saturation (0: grey at the mean, 1: unchanged).
float3 Desaturate(float3 value, float saturation) {
    float mean = (value.r + value.g + value.b) / 3.0;
    return mean + (value - mean) * saturation;
}
// Core RP's Color.hlsl ApplyLut2D (here, where the texture macros are: pbrlab's Color.hlsl stand-in
// is read without them): a colour graded through a 3D lookup table stored as a 2D strip, N slices
// of N x N side by side (width N^2, height N), scaleOffset = (1 / width, 1 / height, N - 1).
// The blue channel picks two neighbouring slices (its scaled value's floor and the next one),
// red and green address a texel inside each, mapped onto the texel centres (half a texel in from
// each side: x N-1 / N + 1 / (2 N) of a slice's width); the two bilinear samples are blended by
// the blue's fraction: trilinear interpolation of the table.
float3 ApplyLut2D(TEXTURE2D_PARAM(tex, samplerTex), float3 uvw, float3 scaleOffset) {
    float slice = uvw.z * scaleOffset.z;
    float shift = floor(slice);
    float2 uv = uvw.xy * scaleOffset.z * scaleOffset.xy + scaleOffset.xy * 0.5;
    uv.x += shift * scaleOffset.y;
    float3 lower = SAMPLE_TEXTURE2D_LOD(tex, samplerTex, uv, 0.0).rgb;
    float3 upper = SAMPLE_TEXTURE2D_LOD(tex, samplerTex, uv + float2(scaleOffset.y, 0.0), 0.0).rgb;
    return lerp(lower, upper, slice - shift);
}

float3 GetCameraPositionWS() { return _WorldSpaceCameraPos; }
// Core RP's SpaceTransforms.hlsl: the position of the view being drawn, in world space. Unity
// returns the primary camera's (URP: _WorldSpaceCameraPos) in a camera's pass, or the view
// matrix's inverse's translation in a shadow-caster pass, where the view is the light's; every
// pass here is drawn from the camera, so both are the camera's position.
float3 GetPrimaryCameraPosition() { return _WorldSpaceCameraPos; }
float3 GetCurrentViewPosition() { return _WorldSpaceCameraPos; }
// A screen position ([0, 1], y up as on GL, where UNITY_UV_STARTS_AT_TOP is undefined) and a
// device depth (GL clip z / w, [-1, 1]) to world space through the inverse view-projection:
// clip (ndc * 2 - 1, depth, 1), then the homogeneous divide (Core RP's ComputeClipSpacePosition
// and ComputeWorldSpacePosition).
float4 ComputeClipSpacePosition(float2 positionNDC, float deviceDepth) {
    return float4(positionNDC * 2.0 - 1.0, deviceDepth, 1.0);
}
// Core RP's Common.hlsl's other overload: a position (clip space already, or view or world
// space with UNITY_MATRIX_P or UNITY_MATRIX_VP) through the transform, w = 1:
// mul(clipSpaceTransform, float4(position, 1)). Unity declares only the float3 position; FXC
// truncates a float4 argument to its xyz (warning X3206, implicit truncation of vector type),
// which the float4 overload does explicitly.
float4 ComputeClipSpacePosition(float3 position, float4x4 clipSpaceTransform) { return mul(clipSpaceTransform, float4(position, 1.0)); }
float4 ComputeClipSpacePosition(float3 position) { return float4(position, 1.0); }
float4 ComputeClipSpacePosition(float4 position) { return float4(position.xyz, 1.0); }
float4 ComputeClipSpacePosition(float4 position, float4x4 clipSpaceTransform) { return mul(clipSpaceTransform, float4(position.xyz, 1.0)); }
float3 ComputeWorldSpacePosition(float2 positionNDC, float deviceDepth, float4x4 invViewProjMatrix) {
    float4 positionHWS = mul(invViewProjMatrix, ComputeClipSpacePosition(positionNDC, deviceDepth));
    return positionHWS.xyz / positionHWS.w;
}
// The same position in view space through the inverse projection, its z negated (Core RP's
// ComputeViewSpacePosition: Unity's view space looks down -z, the position's z is the eye depth,
// positive in front of the camera).
float3 ComputeViewSpacePosition(float2 positionNDC, float deviceDepth, float4x4 invProjMatrix) {
    float4 positionHVS = mul(invProjMatrix, ComputeClipSpacePosition(positionNDC, deviceDepth));
    return float3(positionHVS.x, positionHVS.y, -positionHVS.z) / positionHVS.w;
}
// The screen's size and 1 + 1 / size at URP's render scale, which is 1 here: _ScreenParams.
float4 GetScaledScreenParams() { return _ScreenParams; }
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/PbrlabSpaceTransforms.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/PbrlabFullScreenTriangle.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/PbrlabPacking.hlsl"
// Core RP's Common.hlsl includes Random.hlsl (after Macros.hlsl, Core RP 14.0.9), so a URP
// program that includes only Core.hlsl calls InterleavedGradientNoise, GenerateHashedRandomFloat,
// Hash, ...; and Common.hlsl's float tests and positive powers (PbrlabCommonMath.hlsl).
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Random.hlsl"
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/PbrlabCommonMath.hlsl"
// URP's Input.hlsl (which Core.hlsl includes): the most additional lights a draw sees, by
// platform (URP 12+, which UNITY_VERSION 2021.3 here means: 16 on mobile GLES 3.0, 32 on
// mobile, OpenGL Core and GLES, 256 elsewhere). pbrlab compiles for SHADER_API_GLCORE
// (graphics_api.py): 32. A program that #defines it first keeps its own (user_definitions;
// FXC would warn and take this later body, glslang refuses the redefinition).
#if !defined(MAX_VISIBLE_LIGHTS) && !defined(PBRLAB_USER_DEFINES_MAX_VISIBLE_LIGHTS)
#define MAX_VISIBLE_LIGHTS 32
#endif
// Core RP's gathers (API/D3D11.hlsl and TextureXR.hlsl: Texture2D.Gather and GatherRed ..
// GatherAlpha, the one channel of the four texels a bilinear read at the location weighs; the _X
// forms one 2D texture without XR), in HLSL; the GLSL port spells them (port.py).
#ifndef __VERSION__
#define GATHER_TEXTURE2D(t, s, uv) t.Gather(s, uv)
#define GATHER_RED_TEXTURE2D(t, s, uv) t.GatherRed(s, uv)
#define GATHER_GREEN_TEXTURE2D(t, s, uv) t.GatherGreen(s, uv)
#define GATHER_BLUE_TEXTURE2D(t, s, uv) t.GatherBlue(s, uv)
#define GATHER_ALPHA_TEXTURE2D(t, s, uv) t.GatherAlpha(s, uv)
#define GATHER_TEXTURE2D_X(t, s, uv) t.Gather(s, uv)
#define GATHER_RED_TEXTURE2D_X(t, s, uv) t.GatherRed(s, uv)
#define GATHER_GREEN_TEXTURE2D_X(t, s, uv) t.GatherGreen(s, uv)
#define GATHER_BLUE_TEXTURE2D_X(t, s, uv) t.GatherBlue(s, uv)
#endif
// The view vector to the camera, not normalized (a perspective camera; orthographic: its axis).
float3 GetWorldSpaceViewDir(float3 positionWS) {
    if (unity_OrthoParams.w == 1.0) return -UNITY_MATRIX_V[2].xyz;
    return _WorldSpaceCameraPos - positionWS;
}
float3 GetWorldSpaceNormalizeViewDir(float3 positionWS) { return normalize(GetWorldSpaceViewDir(positionWS)); }
// The camera's forward direction in world space (the view matrix's -z row: Core RP's
// GetViewForwardDir).
float3 GetViewForwardDir() { return -UNITY_MATRIX_V[2].xyz; }
// Core RP's Common.hlsl: a position through a clip-space transform (the identity when none is
// given: the position is taken as clip space already), divided by w, x and y mapped from
// [-1, 1] to [0, 1] (no flip of y: UNITY_UV_STARTS_AT_TOP is undefined on GL), z kept.
float3 ComputeNormalizedDeviceCoordinatesWithZ(float3 position, float4x4 clipSpaceTransform) {
    float4 positionCS = mul(clipSpaceTransform, float4(position, 1.0));
    positionCS = positionCS / positionCS.w;
    return float3(positionCS.xy * 0.5 + 0.5, positionCS.z);
}
float3 ComputeNormalizedDeviceCoordinatesWithZ(float3 position) {
    return ComputeNormalizedDeviceCoordinatesWithZ(position, float4x4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                                                                      0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0));
}
float2 ComputeNormalizedDeviceCoordinates(float3 position, float4x4 clipSpaceTransform) {
    return ComputeNormalizedDeviceCoordinatesWithZ(position, clipSpaceTransform).xy;
}
float2 ComputeNormalizedDeviceCoordinates(float3 position) { return ComputeNormalizedDeviceCoordinatesWithZ(position).xy; }

struct VertexPositionInputs {
    float3 positionWS;
    float3 positionVS;
    float4 positionCS;
    float4 positionNDC;
};

VertexPositionInputs GetVertexPositionInputs(float3 positionOS) {
    VertexPositionInputs o;
    o.positionWS = TransformObjectToWorld(positionOS);
    o.positionVS = TransformWorldToView(o.positionWS);
    o.positionCS = TransformWorldToHClip(o.positionWS);
    float4 ndc = o.positionCS * 0.5;
    o.positionNDC.xy = float2(ndc.x, ndc.y * _ProjectionParams.x) + ndc.w;
    o.positionNDC.zw = o.positionCS.zw;
    return o;
}

struct VertexNormalInputs {
    float3 tangentWS;
    float3 bitangentWS;
    float3 normalWS;
};

VertexNormalInputs GetVertexNormalInputs(float3 normalOS) {
    VertexNormalInputs o;
    o.tangentWS = float3(1.0, 0.0, 0.0);
    o.bitangentWS = float3(0.0, 1.0, 0.0);
    o.normalWS = TransformObjectToWorldNormal(normalOS);
    return o;
}

VertexNormalInputs GetVertexNormalInputs(float3 normalOS, float4 tangentOS) {
    VertexNormalInputs o;
    float sign = tangentOS.w * GetOddNegativeScale();
    o.normalWS = TransformObjectToWorldNormal(normalOS);
    o.tangentWS = TransformObjectToWorldDir(tangentOS.xyz);
    o.bitangentWS = cross(o.normalWS, o.tangentWS) * sign;
    return o;
}

float3 NormalizeNormalPerPixel(float3 normalWS) { return normalize(normalWS); }
float3 NormalizeNormalPerVertex(float3 normalWS) { return normalize(normalWS); }

// Normal maps (Packing.hlsl's UnpackNormalScale on desktop: RG or AG, DXT5nm or BC5, and RGB
// maps alike: x = a * r, y = g), scaled in xy, z rebuilt.
float3 UnpackNormalScale(float4 packedNormal, float scale) {
    float2 xy = float2(packedNormal.a * packedNormal.r, packedNormal.g) * 2.0 - 1.0;
    xy *= scale;
    return float3(xy, max(1.0e-16, sqrt(1.0 - saturate(dot(xy, xy)))));
}
float3 UnpackNormalRGB(float4 packedNormal, float scale) {
    float3 n = packedNormal.rgb * 2.0 - 1.0;
    n.xy *= scale;
    return n;
}
// Core RP's two-argument UnpackNormalmapRGorAG is that same unpacking; and URP's UnpackNormal is
// it with scale 1 (Packing.hlsl on desktop, where Unity stores normal maps as DXT5nm or BC5),
// not the built-in UnityCG's RGB form (xyz * 2 - 1) the Unity prelude defines: a grey (0.5)
// texel is the flat normal (0, 0, 1) here, as in URP, where the RGB form gives (0, 0, 0). A
// macro, as the prelude's function has the same signature (a shader's own UnpackNormal(float4)
// is renamed before this is read: cg_spellings).
float3 UnpackNormalmapRGorAG(float4 packedNormal, float scale) { return UnpackNormalScale(packedNormal, scale); }
#define UnpackNormal(packedNormal) UnpackNormalScale(packedNormal, 1.0)

// Core RP's SharpenAlpha: an alpha-tested edge anti-aliased over one pixel for alpha to
// coverage, (alpha - cutoff) / fwidth(alpha) + 1/2 clamped to [0, 1] (fwidth floored at 1e-4)
float SharpenAlpha(float alpha, float alphaClipTreshold) {
    return saturate((alpha - alphaClipTreshold) / max(fwidth(alpha), 0.0001) + 0.5);
}

// The screen position a fragment program reads (ComputeScreenPos: the built-in's, already in the prelude).
// Shader Graph's (URP 10-12 generated code) with the projection's sign given, _ProjectionParams.x
// where its Screen Position node calls it: xy = (clip xy (1, sign) + w) / 2, zw the clip zw.
float4 ComputeScreenPos(float4 positionCS, float projectionSign) {
    float4 o = positionCS * 0.5;
    o.xy = float2(o.x, o.y * projectionSign) + o.w;
    o.zw = positionCS.zw;
    return o;
}
float2 GetNormalizedScreenSpaceUV(float4 positionCS) { return positionCS.xy / _ScreenParams.xy; }

// Shadows: none here (no shadow map): a coordinate of 0, full light; no shadow mask.
#define SAMPLE_SHADOWMASK(uv) float4(1.0, 1.0, 1.0, 1.0)
float4 TransformWorldToShadowCoord(float3 positionWS) { return float4(0.0, 0.0, 0.0, 0.0); }

// UnityPerDraw's lightmap scale-offsets (URP's UnityInput.hlsl). A lightmapped object's (its
// material supplies a `lightmap`: importers/unity/lightmaps.py sets LIGHTMAP_ON and binds
// unity_LightmapST) is a uniform; an object that is not lightmapped has the default: Unity sets them from the renderer's
// lightmapScaleOffset / realtimeLightmapScaleOffset (ScriptReference: "The UV scale & offset
// used for a lightmap", xy scale, zw offset), which keep their default, the identity (scale 1,
// offset 0), while no lightmapper has assigned a lightmap (lightmapIndex -1, 0xFFFF: "no
// lightmap has been assigned, which is the default", ScriptReference Renderer.lightmapIndex).
#if defined(LIGHTMAP_ON)
float4 unity_LightmapST;
#else
#define unity_LightmapST float4(1.0, 1.0, 0.0, 0.0)
#endif
#define unity_DynamicLightmapST float4(1.0, 1.0, 0.0, 0.0)

// URP's Core.hlsl brings Input.hlsl (InputData, the lights' and camera's globals), as here.
#include "Packages/com.unity.render-pipelines.universal/ShaderLibrary/Input.hlsl"

#endif
