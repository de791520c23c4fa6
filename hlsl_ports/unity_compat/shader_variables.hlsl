// unity_compat/shader_variables.hlsl: the built-in globals a Unity surface shader reads
// (UnityShaderVariables.cginc, UnityLightingCommon.cginc), and the UnityCG.cginc helpers
// that read them.
//
// THIS FILE DECLARES UNIFORMS, as Unity's UnityShaderVariables.cginc does: it is the one
// file that does (the caller sets them; the pbrlab harness sets every one), and it lives
// outside pbr/ (whose files declare no resources) in unity_compat/, the opt-in Unity room.
//
// Provides: uniforms _Time (t/20, t, 2t, 3t), _SinTime (sin t/8, t/4, t/2, t), _CosTime,
//           unity_DeltaTime, _WorldSpaceCameraPos, _ProjectionParams (1, near, far, 1/far),
//           _ScreenParams (w, h, 1 + 1/w, 1 + 1/h), unity_ObjectToWorld, unity_WorldToObject, unity_WorldTransformParams,
//           unity_MatrixVP, unity_MatrixV, unity_MatrixInvV, glstate_matrix_projection,
//           unity_CameraProjection, unity_CameraInvProjection, unity_WorldToCamera and
//           unity_CameraToWorld (the camera transform's frame, +z forward), _ZBufferParams (GL depth,
//           not reversed: 1 - far/near, far/near, x/far, y/far), unity_OrthoParams (half
//           width, half height, 0, 1 orthographic / 0 perspective; 0, 0, 0, 0 perspective
//           here), _SpecColor (Lighting.cginc's BlinnPhong specular colour),
//           unity_CameraWorldClipPlanes (the frustum's six world-space planes),
//           unity_SpecCube0_HDR (DecodeHDR instructions of the environment), unity_SpecCube0_ProbePosition,
//           unity_SpecCube0_BoxMin, unity_SpecCube0_BoxMax (constants: the sky's probe, not box-projected),
//           unity_FogColor
//           (RenderSettings.fogColor: its default, (0.5, 0.5, 0.5, 1); pbrlab draws no fog);
//           float2 UnityStereoScreenSpaceUVAdjust(uv, scaleAndOffset), UnityStereoTransformScreenSpaceTex(uv)
//           (the identity: one eye);
//           float3 ShadeVertexLightsFull(float4 vertex, float3 normal, int lightCount, bool spotLight),
//           float3 ShadeVertexLights(float4 vertex, float3 normal) (UnityCG.cginc's vertex lighting);
//           float4 Unity_LightmodelAmbient(), UNITY_LIGHTMODEL_AMBIENT (the ambient probe's mean);
//           unity_AmbientSky, unity_AmbientEquator, unity_AmbientGround (its irradiance from above,
//           the sides, below);
//           unity_SHAr, unity_SHAg, unity_SHAb, unity_SHBr, unity_SHBg, unity_SHBb, unity_SHC (its SH
//           polynomial's coefficients as Unity packs them);
//           vertex-light globals unity_LightColor[8], unity_LightPosition[8] (view space),
//           unity_LightAtten[8], unity_SpotDirection[8] (NOT uniforms: the caller's vertex stage sets them);
//           unity_4LightPosX0/Y0/Z0, unity_4LightAtten0 (the forward base pass's four vertex point
//           lights, NOT uniforms: the pass's stages set them) and Shade4PointLights;
//           per-light globals _LightColor0 and _WorldSpaceLightPos0 (NOT uniforms: plain
//           globals the caller's light loop sets before each Lighting<Name> call, since one
//           program here shades every light; w = 0 directional, 1 positional);
//           UNITY_MATRIX_M, UNITY_MATRIX_V, UNITY_MATRIX_I_V, UNITY_MATRIX_P, UNITY_MATRIX_VP,
//           UNITY_MATRIX_MVP, UNITY_MATRIX_MV, UNITY_MATRIX_T_MV, UNITY_MATRIX_IT_MV,
//           TRANSFORM_TEX(tex, name);
//           float4 UnityObjectToClipPos(float3 pos) / (float4 pos), float4 UnityWorldToClipPos(float3),
//           float4 UnityViewToClipPos(float3), float3 UnityObjectToViewPos(float3) / (float4),
//           float3 UnityWorldToViewPos(float3), float3 UnityObjectToWorldNormal(float3),
//           float3 UnityObjectToWorldDir(float3), float3 UnityWorldToObjectDir(float3),
//           float3 UnityWorldSpaceViewDir(float3 worldPos), float3 UnityWorldSpaceLightDir(float3 worldPos),
//           float3 WorldSpaceViewDir(float4 localPos), float3 WorldSpaceLightDir(float4 localPos),
//           float3 ObjSpaceViewDir(float4 localPos), float3 ObjSpaceLightDir(float4 localPos),
//           float2 / float3 TransformViewToProjection(v) (the projection's upper-left 2x2 / 3x3),
//           float4 ComputeScreenPos(float4 clipPos), float4 UnityPixelSnap(float4 clipPos),
//           bool IsGammaSpace() (false: linear colour space), float Linear01Depth(float z), float LinearEyeDepth(float z) (z: a [0, 1] depth-
//           buffer value, perspective cameras, as Unity's);
//           COMPUTE_EYEDEPTH(o), COMPUTE_DEPTH_01, COMPUTE_VIEW_NORMAL, TANGENT_SPACE_ROTATION (read the vertex
//           input `v`, as Unity's); appdata_img, v2f_img, v2f_img vert_img(appdata_img);
//           instancing and stereo macros as no-ops (UNITY_INSTANCING_BUFFER_START/END,
//           UNITY_DECLARE_TEX2D(_NOSAMPLER), UNITY_SAMPLE_TEX2D(_SAMPLER), UNITY_DECLARE_TEXCUBE,
//           UNITY_DECLARE_TEX2DARRAY(_NOSAMPLER), UNITY_SAMPLE_TEX2DARRAY(_LOD) (coord.z the layer),
//           UNITY_SAMPLE_TEXCUBE(_LOD), UNITY_DECLARE/SAMPLE_SCREENSPACE_TEXTURE;
//           UNITY_DECLARE_DEPTH_TEXTURE, SAMPLE_DEPTH_TEXTURE(_PROJ, _LOD) (the texture a material
//           gives, white = the far plane by default: no depth pre-pass here);
//           UNITY_DEFINE_INSTANCED_PROP declares a plain uniform, UNITY_ACCESS_INSTANCED_PROP,
//           UNITY_SETUP_INSTANCE_ID, UNITY_TRANSFER_INSTANCE_ID, UNITY_VERTEX_INPUT_INSTANCE_ID,
//           UNITY_VERTEX_OUTPUT_STEREO, UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO,
//           UNITY_TRANSFER_VERTEX_OUTPUT_STEREO, UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX,
//           UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX, UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(o): no
//           instancing, one eye; unity_StereoEyeIndex is 0, the left eye's, as in mono); UNITY_INITIALIZE_OUTPUT(type, name) (a no-op in GLSL, as
//           Unity defines it for its GLSL targets); UNITY_POSITION(pos) (a struct's clip-space
//           position member, HLSLSupport.cginc's float4 pos : SV_POSITION); UNITY_BRANCH, UNITY_FLATTEN, UNITY_UNROLL,
//           UNITY_UNROLLX(n), UNITY_LOOP, UNITY_FASTOPT (HLSL attributes; nothing in GLSL);
//           AutoLight.cginc's macros without shadows (no shadow maps here; a light's falloff
//           is already in _LightColor0): SHADOW_COORDS(idx), UNITY_SHADOW_COORDS(idx),
//           LIGHTING_COORDS(idx1, idx2), UNITY_LIGHTING_COORDS(idx1, idx2), TRANSFER_SHADOW(a),
//           UNITY_TRANSFER_SHADOW(a, coord), TRANSFER_VERTEX_TO_FRAGMENT(a),
//           UNITY_TRANSFER_LIGHTING(a, coord) expand to nothing; SHADOW_ATTENUATION(a),
//           UNITY_SHADOW_ATTENUATION(a, worldPos), LIGHT_ATTENUATION(a) are 1.0;
//           UNITY_LIGHT_ATTENUATION(destName, input, worldPos) declares `fixed destName = 1.0;`.
//           Not provided: lightmaps (unity_Lightmap, DecodeLightmap), depth textures
//           (_CameraDepthTexture, SAMPLE_DEPTH_TEXTURE), shadow-caster macros: the harness has
//           none of these.
// Include:  "unity_compat/shader_variables.hlsl" (path relative to hlsl_ports/). HAND-WRITTEN
//           twin of glsl/unity_compat/shader_variables.glsl (matrices: GLSL M * v is HLSL
//           mul(M, v), which the generator refuses to guess; harness/pbrlab/gpu/port_hlsl.py
//           generates pbr/ only); the per-light globals are `static` (mutable) here, and
//           UNITY_INITIALIZE_OUTPUT zero-fills, as Unity's Direct3D 11 definition does.
// Config macros read: PBR_UNITY_SH_IRRADIANCE(n) (UNITY_LIGHTMODEL_AMBIENT: the caller's ambient
//           lookup, as pbr/unity/global_illumination reads it; default black);
//           PBR_UNITY_SH9 (the caller's nine SH9 radiance coefficients, as pbr_sh9_irradiance
//           reads them, with pbr/lighting/sh9.glsl's constants: unity_SHAr..unity_SHC; default zero).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_COMPAT_SHADER_VARIABLES_HLSL
#define PBR_UNITY_COMPAT_SHADER_VARIABLES_HLSL
#include "pbr/common/shim.hlsl"

uniform float4 _Time;
uniform float4 _SinTime;
uniform float4 _CosTime;
uniform float4 unity_DeltaTime;
uniform float3 _WorldSpaceCameraPos;
uniform float4 _ProjectionParams;
uniform float4 _ScreenParams;
uniform float4x4 unity_ObjectToWorld;
uniform float4x4 unity_WorldToObject;
// w: -1 where the object's transform mirrors (a negative determinant), else 1; x, y, z 0
uniform float4 unity_WorldTransformParams;
uniform float4x4 unity_MatrixVP;
uniform float4x4 unity_MatrixV;
uniform float4x4 unity_MatrixInvV;
uniform float4x4 glstate_matrix_projection;
uniform float4x4 unity_CameraProjection;
uniform float4x4 unity_CameraInvProjection;
// the camera transform's own frame (+z forward, unlike the view matrix's -z): world to it and back
uniform float4x4 unity_WorldToCamera;
uniform float4x4 unity_CameraToWorld;
uniform float4 _ZBufferParams;
uniform float4 unity_OrthoParams;
// the camera's frustum planes in world space, left, right, bottom, top, near, far: xyz the unit
// normal pointing into the frustum, w the offset (dot(float4(p, 1), plane) is p's distance
// inside), as UnityShaderVariables.cginc's; pbrlab sets them (importers/unity/program.py)
uniform float4 unity_CameraWorldClipPlanes[6];
uniform float4 _SpecColor;
uniform float4 unity_SpecCube0_HDR;
// The reflection probe's box (UnityShaderVariables.cginc / URP's UnityInput.hlsl): the scene's
// one reflection source is its environment, Unity's default reflection (the sky's probe), which
// is not box-projected: ProbePosition.w = 0 (box projection off: BoxProjectedCubemapDirection
// returns the direction as given), its box unbounded (the environment at infinity, here +-1e30,
// float32-safe) and BoxMin.w, the weight of probe 0 against probe 1, 1 (no blending).
static const float4 unity_SpecCube0_ProbePosition = float4(0.0, 0.0, 0.0, 0.0);
static const float4 unity_SpecCube0_BoxMin = float4(-1e30, -1e30, -1e30, 1.0);
static const float4 unity_SpecCube0_BoxMax = float4(1e30, 1e30, 1e30, 0.0);
// The second probe (UnityShaderVariables.cginc's unity_SpecCube1*, the probe an object blends
// toward): with one reflection source Unity's weight of probe 0 is 1 (BoxMin.w above), so a
// shader that blends reads probe 0 alone; probe 1 is the same sky with the same box and decode
// (its reads are the sky's: importers/unity/texture_methods.py).
#define unity_SpecCube1_HDR unity_SpecCube0_HDR
static const float4 unity_SpecCube1_ProbePosition = float4(0.0, 0.0, 0.0, 0.0);
static const float4 unity_SpecCube1_BoxMin = float4(-1e30, -1e30, -1e30, 1.0);
static const float4 unity_SpecCube1_BoxMax = float4(1e30, 1e30, 1e30, 0.0);
uniform float4 unity_FogColor;
// pbr/unity/lighting_legacy reads the BlinnPhong specular colour through this hook.
#define PBR_UNITY_SPEC_COLOR _SpecColor
static float4 _LightColor0;
static float4 _WorldSpaceLightPos0;
// Unity's vertex lights (UnityShaderVariables.cginc; legacy vertex-lit rendering): plain
// globals the caller's vertex stage sets (pbrlab: 8 black lights, but a Vertex pass's lights).
static float4 unity_LightColor[8];
static float4 unity_LightPosition[8];
static float4 unity_LightAtten[8];
static float4 unity_SpotDirection[8];
// UnityShaderVariables.cginc's older names of the first four vertex lights' colours (its
// UnityLightingOld buffer, "kept for existing shaders"; Unity 3's Shade4PointLights took them as
// arguments): the colours unity_LightColor[0..3] carries, rgb.
#define unity_LightColor0 unity_LightColor[0].rgb
#define unity_LightColor1 unity_LightColor[1].rgb
#define unity_LightColor2 unity_LightColor[2].rgb
#define unity_LightColor3 unity_LightColor[3].rgb
// The forward path's four per-vertex point lights of a ForwardBase pass (UnityShaderVariables.cginc,
// read by Shade4PointLights): world-space positions by component (x of lights 0..3 in
// unity_4LightPosX0, ...), their quadratic attenuation in unity_4LightAtten0, their colours in
// unity_LightColor[0..3]. Plain globals the pass's stages set (generate_pass._four_lights), zero
// where the pass has none.
static float4 unity_4LightPosX0;
static float4 unity_4LightPosY0;
static float4 unity_4LightPosZ0;
static float4 unity_4LightAtten0;

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_V unity_MatrixV
#define UNITY_MATRIX_I_V unity_MatrixInvV
#define UNITY_MATRIX_P glstate_matrix_projection
#define UNITY_MATRIX_VP unity_MatrixVP
#define UNITY_MATRIX_MVP mul(unity_MatrixVP, unity_ObjectToWorld)
// UnityShaderVariables.cginc builds these three from the per-camera and per-object matrices;
// the inverse transpose of M V (for normals) is transpose(M^-1 V^-1) with no inversion.
#define UNITY_MATRIX_MV mul(unity_MatrixV, unity_ObjectToWorld)
#define UNITY_MATRIX_T_MV transpose(mul(unity_MatrixV, unity_ObjectToWorld))
#define UNITY_MATRIX_IT_MV transpose(mul(unity_WorldToObject, unity_MatrixInvV))
#define TRANSFORM_TEX(tex, name) ((tex).xy * name##_ST.xy + name##_ST.zw)

#define UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_BUFFER_END(name)
#define UNITY_DEFINE_INSTANCED_PROP(type, var) type var;
#define UNITY_ACCESS_INSTANCED_PROP(arr, var) var
#define UNITY_SETUP_INSTANCE_ID(v)
#define UNITY_TRANSFER_INSTANCE_ID(v, o)
#define UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_VERTEX_OUTPUT_STEREO
#define UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o)
#define UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)
#define UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
#define UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)
#define unity_StereoEyeIndex 0
// unity_StereoScaleOffset[eye]: the per-eye scale (xy) and offset (zw) that maps a full-screen uv
// into that eye's part of the render target (URP UnityInput.hlsl declares float4[2] under
// USING_STEREO_MATRICES; UnityCG.cginc's TransformStereoScreenSpaceTex applies it as
// uv * s.xy + s.zw * w). pbrlab draws one eye per target (mono, as single-pass instanced's
// per-eye slices are), where an eye covers the whole target: (1, 1, 0, 0), the identity map
static const float4 unity_StereoScaleOffset[2] = { float4(1.0, 1.0, 0.0, 0.0), float4(1.0, 1.0, 0.0, 0.0) };
// the fixed-function pipeline's texture matrices (UnityShaderVariables.cginc's glstate_matrix_texture0..3):
// the identity unless a legacy SetTexture's Matrix sets one, which no program-drawn pass does
#define UNITY_MATRIX_TEXTURE0 float4x4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)
#define UNITY_MATRIX_TEXTURE1 float4x4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)
#define UNITY_MATRIX_TEXTURE2 float4x4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)
#define UNITY_MATRIX_TEXTURE3 float4x4(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)
// UnityCG.cginc's single-pass stereo helpers: one eye, so the coordinates as given
float2 UnityStereoScreenSpaceUVAdjust(float2 uv, float4 scaleAndOffset) { return uv; }
float4 UnityStereoScreenSpaceUVAdjust(float4 uv, float4 scaleAndOffset) { return uv; }
#ifndef UnityStereoTransformScreenSpaceTex
#define UnityStereoTransformScreenSpaceTex(uv) (uv)
#endif
#define UNITY_INITIALIZE_OUTPUT(type, name) name = (type)0;
#define UNITY_POSITION(pos) float4 pos : SV_POSITION

// HLSLSupport.cginc's flow-control hints: HLSL attributes, as Unity defines them for Direct3D
// (glslang's HLSL front end reads [branch], [flatten], [unroll], [unroll(n)], [loop], [fastopt]).
#define UNITY_BRANCH [branch]
#define UNITY_FLATTEN [flatten]
#define UNITY_UNROLL [unroll]
#define UNITY_UNROLLX(n) [unroll(n)]
#define UNITY_LOOP [loop]
#define UNITY_FASTOPT [fastopt]

// AutoLight.cginc with no shadow keyword (SHADOWS_SCREEN, SHADOWS_DEPTH, SHADOWS_CUBE) and the
// light's attenuation left to _LightColor0: Unity's own definitions of that case, where
// its directional light gives LIGHT_ATTENUATION(a) = SHADOW_ATTENUATION(a) = 1.0.
#define SHADOW_COORDS(idx1)
#define UNITY_SHADOW_COORDS(idx1)
#define LIGHTING_COORDS(idx1, idx2)
#define UNITY_LIGHTING_COORDS(idx1, idx2)
#define TRANSFER_SHADOW(a)
#define UNITY_TRANSFER_SHADOW(a, coord)
#define TRANSFER_VERTEX_TO_FRAGMENT(a)
#define UNITY_TRANSFER_LIGHTING(a, coord)
#define SHADOW_ATTENUATION(a) 1.0
#define UNITY_SHADOW_ATTENUATION(a, worldPos) 1.0
#define LIGHT_ATTENUATION(a) 1.0
#define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) fixed destName = 1.0;

// UnityCG.cginc's camera depth texture: a shader declares and samples it by these names.
// The harness draws no depth pre-pass, so the material's texture of that name is Unity's
// default when none is set: white, depth 1, the far plane (nothing in front: a soft
// particle does not fade). A shader's own value may be given in the material's properties.
#define UNITY_DECLARE_DEPTH_TEXTURE(tex) sampler2D tex
#define SAMPLE_DEPTH_TEXTURE(tex, uv) (tex2D(tex, (uv).xy).r)
#define SAMPLE_DEPTH_TEXTURE_PROJ(tex, uv) (tex2Dproj(tex, uv).r)
#define SAMPLE_DEPTH_TEXTURE_LOD(tex, uv) (tex2Dlod(tex, uv).r)
// a depth read from a depth texture's texel (UnityCG.cginc; its red channel outside GLES 2)
#define UNITY_SAMPLE_DEPTH(value) ((value).r)
// HLSLSupport.cginc's single-channel read, shipped in Unity 4.0 and kept: the texel's alpha
#define UNITY_SAMPLE_1CHANNEL(tex, uv) (tex2D(tex, uv).a)
#define UNITY_ALPHA_CHANNEL a
// HLSLSupport.cginc's clip-space depths of the near and far planes, per graphics API: pbrlab
// draws in OpenGL's clip space (no reversed Z, z from -w to w: render/depth_range.py), where
// Unity defines the near plane's as -1 and the raw far plane's as 1.
#define UNITY_NEAR_CLIP_VALUE (-1.0)
#define UNITY_RAW_FAR_CLIP_VALUE (1.0)

// HLSLSupport.cginc's texture macros, as its sampler2D path declares them (one sampler per
// texture: the GL texture's own filtering applies).
#ifndef UNITY_DECLARE_TEX2D
#define UNITY_DECLARE_TEX2D(tex) sampler2D tex
#endif
#define UNITY_DECLARE_TEX2D_NOSAMPLER(tex) sampler2D tex
#ifndef UNITY_SAMPLE_TEX2D
#define UNITY_SAMPLE_TEX2D(tex, uv) tex2D(tex, uv)
#endif
#define UNITY_SAMPLE_TEX2D_SAMPLER(tex, samplertex, uv) tex2D(tex, uv)
#define UNITY_DECLARE_TEXCUBE(tex) samplerCUBE tex
#define UNITY_SAMPLE_TEXCUBE(tex, dir) texCUBE(tex, dir)
#define UNITY_SAMPLE_TEXCUBE_LOD(tex, dir, lod) texCUBElod(tex, float4(dir, lod))
// HLSLSupport.cginc's further 2D and cube forms: a level of detail; another texture's sampler (the
// shared sampler state serves, as for UNITY_SAMPLE_TEX2D_SAMPLER); half and float precision
// declarations (one texture type here); a cube passed to a function (UNITY_ARGS_TEXCUBE in its
// parameter list, UNITY_PASS_TEXCUBE at the call).
#define UNITY_DECLARE_TEX2D_HALF(tex) UNITY_DECLARE_TEX2D(tex)
#define UNITY_DECLARE_TEX2D_FLOAT(tex) UNITY_DECLARE_TEX2D(tex)
#define UNITY_DECLARE_TEX2D_NOSAMPLER_HALF(tex) UNITY_DECLARE_TEX2D_NOSAMPLER(tex)
#define UNITY_DECLARE_TEX2D_NOSAMPLER_FLOAT(tex) UNITY_DECLARE_TEX2D_NOSAMPLER(tex)
#define UNITY_SAMPLE_TEX2D_LOD(tex, uv, lod) tex2Dlod(tex, float4((uv).xy, 0.0, (lod)))
#define UNITY_SAMPLE_TEX2D_SAMPLER_LOD(tex, samplertex, uv, lod) UNITY_SAMPLE_TEX2D_LOD(tex, uv, lod)
#define UNITY_DECLARE_TEXCUBE_NOSAMPLER(tex) samplerCUBE tex
#define UNITY_SAMPLE_TEXCUBE_SAMPLER(tex, samplertex, dir) texCUBE(tex, dir)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD(tex, samplertex, dir, lod) texCUBElod(tex, float4(dir, lod))
#define UNITY_ARGS_TEXCUBE(tex) samplerCUBE tex
#define UNITY_ARGS_TEXCUBE_NOSAMPLER(tex) samplerCUBE tex
#ifndef UNITY_PASS_TEXCUBE
#define UNITY_PASS_TEXCUBE(tex) tex
#endif
#define UNITY_PASS_TEXCUBE_NOSAMPLER(tex) tex
#define UNITY_DECLARE_SCREENSPACE_TEXTURE(tex) sampler2D tex
#define UNITY_SAMPLE_SCREENSPACE_TEXTURE(tex, uv) tex2D(tex, (uv).xy)
// HLSLSupport.cginc's 2D texture arrays (coord.z the layer), sampled with the one shared sampler
// state of unity_hlsl_support.hlsl (glslang combines it into the texture).
#define UNITY_DECLARE_TEX2DARRAY(tex) Texture2DArray tex
#define UNITY_DECLARE_TEX2DARRAY_NOSAMPLER(tex) Texture2DArray tex
#define UNITY_SAMPLE_TEX2DARRAY(tex, coord) (tex).Sample(pbrlab_unity_sampler, (coord))
#define UNITY_SAMPLE_TEX2DARRAY_LOD(tex, coord, lod) (tex).SampleLevel(pbrlab_unity_sampler, (coord), (lod))
// HLSLSupport.cginc's 3D textures (a material's 3D property: a 1x1x1 volume, unity/program.py).
#define UNITY_DECLARE_TEX3D(tex) Texture3D tex
#define UNITY_DECLARE_TEX3D_NOSAMPLER(tex) Texture3D tex
#define UNITY_SAMPLE_TEX3D(tex, coord) (tex).Sample(pbrlab_unity_sampler, (coord))
#define UNITY_SAMPLE_TEX3D_LOD(tex, coord, lod) (tex).SampleLevel(pbrlab_unity_sampler, (coord), (lod))
#define UNITY_SAMPLE_TEX3D_SAMPLER(tex, samplertex, coord) UNITY_SAMPLE_TEX3D(tex, coord)

float4 UnityObjectToClipPos(float3 pos) {
    return mul(unity_MatrixVP, mul(unity_ObjectToWorld, float4(pos, 1.0)));
}

float4 UnityObjectToClipPos(float4 pos) {
    return UnityObjectToClipPos(pos.xyz);
}

float4 UnityWorldToClipPos(float3 pos) {
    return mul(unity_MatrixVP, float4(pos, 1.0));
}

float4 UnityViewToClipPos(float3 pos) {
    return mul(glstate_matrix_projection, float4(pos, 1.0));
}

// Eye space: the camera at the origin looking down -z (Unity's view matrix is GL-style too),
// so a point in front of the camera has view z = -(its eye depth).
float3 UnityObjectToViewPos(float3 pos) {
    return mul(unity_MatrixV, mul(unity_ObjectToWorld, float4(pos, 1.0))).xyz;
}

float3 UnityObjectToViewPos(float4 pos) {
    return UnityObjectToViewPos(pos.xyz);
}

// Unity's vertex lighting (UnityCG.cginc's ShadeVertexLightsFull, as Unity's manual and
// UnityCG.cginc describe it): in view space, the ambient colour plus, for each of the first
// lightCount vertex lights, its colour * max(0, N.L) * 1 / (1 + |d|^2 * atten.z), times the spot
// cone saturate((max(0, L.spotDir) - atten.x) * atten.y) when spotLight; ShadeVertexLights is
// four lights without spots.
//
// UNITY_LIGHTMODEL_AMBIENT (glstate_lightmodel_ambient, the one ambient colour of Unity's legacy
// vertex lighting): here the ambient probe's mean over all directions, read through the
// caller's PBR_UNITY_SH_IRRADIANCE(n) (what ShadeSH9 returns; black where the caller defines
// none, as pbr/unity/global_illumination's default). For an SH of bands 0-2 the mean over the
// sphere equals the mean of its values on the six axes: every band-1 and band-2 function
// (x, xy, 3z^2 - 1, x^2 - y^2, ...) averages to 0 on +-x, +-y, +-z as over the sphere; exact
// where the lookup needs no clamp at 0 (a sky's irradiance is positive everywhere).
float4 Unity_LightmodelAmbient() {
#ifdef PBR_UNITY_SH_IRRADIANCE
    float3 sum = PBR_UNITY_SH_IRRADIANCE(float3(1.0, 0.0, 0.0)) + PBR_UNITY_SH_IRRADIANCE(float3(-1.0, 0.0, 0.0))
             + PBR_UNITY_SH_IRRADIANCE(float3(0.0, 1.0, 0.0)) + PBR_UNITY_SH_IRRADIANCE(float3(0.0, -1.0, 0.0))
             + PBR_UNITY_SH_IRRADIANCE(float3(0.0, 0.0, 1.0)) + PBR_UNITY_SH_IRRADIANCE(float3(0.0, 0.0, -1.0));
    return float4(sum / 6.0, 1.0);
#else
    return float4(0.0, 0.0, 0.0, 1.0);
#endif
}
#define UNITY_LIGHTMODEL_AMBIENT Unity_LightmodelAmbient()

// unity_AmbientSky, unity_AmbientEquator, unity_AmbientGround (UnityShaderVariables.cginc's and
// URP UnityInput.hlsl's globals; RenderSettings.ambientSkyColor / ambientEquatorColor /
// ambientGroundColor, documented as the ambient light "coming from above", "from the sides" and
// "from below"; a flat ambient colour is all three). pbrlab's scene has no gradient setting: its
// ambient is the environment's SH, so the three are that SH's irradiance (the caller's
// PBR_UNITY_SH_IRRADIANCE(n), what ShadeSH9 returns) from above (+y), the mean of the four
// horizontal axes (+-x, +-z), and from below (-y); a uniform environment L gives L for all three,
// as Unity's flat mode. Black where the caller defines no lookup. Alpha 1.
float4 Unity_AmbientSkyColor() {
#ifdef PBR_UNITY_SH_IRRADIANCE
    return float4(PBR_UNITY_SH_IRRADIANCE(float3(0.0, 1.0, 0.0)), 1.0);
#else
    return float4(0.0, 0.0, 0.0, 1.0);
#endif
}
float4 Unity_AmbientEquatorColor() {
#ifdef PBR_UNITY_SH_IRRADIANCE
    float3 sum = PBR_UNITY_SH_IRRADIANCE(float3(1.0, 0.0, 0.0)) + PBR_UNITY_SH_IRRADIANCE(float3(-1.0, 0.0, 0.0))
             + PBR_UNITY_SH_IRRADIANCE(float3(0.0, 0.0, 1.0)) + PBR_UNITY_SH_IRRADIANCE(float3(0.0, 0.0, -1.0));
    return float4(sum * 0.25, 1.0);
#else
    return float4(0.0, 0.0, 0.0, 1.0);
#endif
}
float4 Unity_AmbientGroundColor() {
#ifdef PBR_UNITY_SH_IRRADIANCE
    return float4(PBR_UNITY_SH_IRRADIANCE(float3(0.0, -1.0, 0.0)), 1.0);
#else
    return float4(0.0, 0.0, 0.0, 1.0);
#endif
}
#define unity_AmbientSky Unity_AmbientSkyColor()
#define unity_AmbientEquator Unity_AmbientEquatorColor()
#define unity_AmbientGround Unity_AmbientGroundColor()
#ifdef PBR_UNITY_SH9
#include "pbr/lighting/sh9.hlsl"
#endif
// unity_SHAr, unity_SHAg, unity_SHAb, unity_SHBr, unity_SHBg, unity_SHBb, unity_SHC
// (UnityShaderVariables.cginc's and URP UnityInput.hlsl's UnityPerDraw globals; Unity's manual,
// "Built-in shader variables": the ambient probe's spherical-harmonics coefficients): the
// order-2 polynomial Unity's ShadeSH9 / URP's SampleSH9 evaluates per colour channel from them,
// SHA.w + dot(SHA.xyz, n) + dot(SHB, n.xyzz * n.yzzx) + SHC * (n.x^2 - n.y^2), here the
// caller's PBR_UNITY_SH9 irradiance / pi (pbr_sh9_irradiance's five Ramamoorthi-Hanrahan terms
// per monomial, its constant -C5 L20 part in SHA.w as Unity packs it), so a shader evaluating
// them by hand gets what PBR_UNITY_SH_IRRADIANCE returns (before its clamp at 0). Zero where
// the caller defines no PBR_UNITY_SH9. channel: 0 red, 1 green, 2 blue.
float4 Unity_SHA(int channel) {
#ifdef PBR_UNITY_SH9
    return float4(2.0 * PBR_SH9_C2 * PBR_UNITY_SH9[3][channel], 2.0 * PBR_SH9_C2 * PBR_UNITY_SH9[1][channel],
                2.0 * PBR_SH9_C2 * PBR_UNITY_SH9[2][channel],
                PBR_SH9_C4 * PBR_UNITY_SH9[0][channel] - PBR_SH9_C5 * PBR_UNITY_SH9[6][channel]) * PBR_INV_PI;
#else
    return float4(0.0, 0.0, 0.0, 0.0);
#endif
}
float4 Unity_SHB(int channel) {
#ifdef PBR_UNITY_SH9
    return float4(2.0 * PBR_SH9_C1 * PBR_UNITY_SH9[4][channel], 2.0 * PBR_SH9_C1 * PBR_UNITY_SH9[5][channel],
                PBR_SH9_C3 * PBR_UNITY_SH9[6][channel], 2.0 * PBR_SH9_C1 * PBR_UNITY_SH9[7][channel]) * PBR_INV_PI;
#else
    return float4(0.0, 0.0, 0.0, 0.0);
#endif
}
float4 Unity_SHC() {
#ifdef PBR_UNITY_SH9
    return float4(PBR_SH9_C1 * PBR_UNITY_SH9[8] * PBR_INV_PI, 1.0);
#else
    return float4(0.0, 0.0, 0.0, 1.0);
#endif
}
#define unity_SHAr Unity_SHA(0)
#define unity_SHAg Unity_SHA(1)
#define unity_SHAb Unity_SHA(2)
#define unity_SHBr Unity_SHB(0)
#define unity_SHBg Unity_SHB(1)
#define unity_SHBb Unity_SHB(2)
#define unity_SHC Unity_SHC()

float3 ShadeVertexLightsFull(float4 vertex, float3 normal, int lightCount, bool spotLight) {
    float3 viewpos = UnityObjectToViewPos(vertex.xyz);
    float3 viewN = normalize(mul((float3x3)UNITY_MATRIX_IT_MV, normal));
    float3 lightColor = Unity_LightmodelAmbient().xyz;
    for (int i = 0; i < lightCount; i++) {
        float3 toLight = unity_LightPosition[i].xyz - viewpos * unity_LightPosition[i].w;
        float lengthSq = max(dot(toLight, toLight), 0.000001);
        toLight *= rsqrt(lengthSq);
        float atten = 1.0 / (1.0 + lengthSq * unity_LightAtten[i].z);
        if (spotLight) {
            float rho = max(0.0, dot(toLight, unity_SpotDirection[i].xyz));
            atten *= saturate((rho - unity_LightAtten[i].x) * unity_LightAtten[i].y);
        }
        float diff = max(0.0, dot(viewN, toLight));
        lightColor += unity_LightColor[i].rgb * (diff * atten);
    }
    return lightColor;
}

float3 ShadeVertexLights(float4 vertex, float3 normal) {
    return ShadeVertexLightsFull(vertex, normal, 4, false);
}

// UnityCG.cginc's Shade4PointLights: the diffuse light of four point lights at world position pos
// with world normal normal, each light's colour times max(0, n.l) / (1 + d^2 * attenSq), its
// squared distance d^2 kept from 0 (at least 1e-6, as Unity's): the formula as Unity states it,
// evaluated four lights at a time.
float3 Shade4PointLights(float4 lightPosX, float4 lightPosY, float4 lightPosZ, float3 lightColor0,
                         float3 lightColor1, float3 lightColor2, float3 lightColor3, float4 lightAttenSq,
                         float3 pos, float3 normal) {
    float4 toX = lightPosX - pos.x;
    float4 toY = lightPosY - pos.y;
    float4 toZ = lightPosZ - pos.z;
    float4 distanceSq = max(toX * toX + toY * toY + toZ * toZ, float4(0.000001, 0.000001, 0.000001, 0.000001));
    float4 cosine = max(float4(0.0, 0.0, 0.0, 0.0), (toX * normal.x + toY * normal.y + toZ * normal.z) * rsqrt(distanceSq));
    float4 diffuse = cosine / (1.0 + distanceSq * lightAttenSq);
    return lightColor0 * diffuse.x + lightColor1 * diffuse.y + lightColor2 * diffuse.z + lightColor3 * diffuse.w;
}

float3 UnityWorldToViewPos(float3 pos) {
    return mul(unity_MatrixV, float4(pos, 1.0)).xyz;
}

// Normals transform with the inverse transpose: n^T M^-1 (Unity: mul(norm, (float3x3)unity_WorldToObject)).
float3 UnityObjectToWorldNormal(float3 norm) {
    return normalize(mul(norm, (float3x3)unity_WorldToObject));
}

float3 UnityObjectToWorldDir(float3 dir) {
    return normalize(mul((float3x3)unity_ObjectToWorld, dir));
}

float3 UnityWorldToObjectDir(float3 dir) {
    return normalize(mul((float3x3)unity_WorldToObject, dir));
}

float3 UnityWorldSpaceViewDir(float3 worldPos) {
    return _WorldSpaceCameraPos - worldPos;
}

float3 UnityWorldSpaceLightDir(float3 worldPos) {
    return _WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w;
}

float3 WorldSpaceViewDir(float4 localPos) {
    return UnityWorldSpaceViewDir(mul(unity_ObjectToWorld, localPos).xyz);
}

float3 WorldSpaceLightDir(float4 localPos) {
    return UnityWorldSpaceLightDir(mul(unity_ObjectToWorld, localPos).xyz);
}

// Object-space directions (not normalised, as Unity's): the camera, or the light
// (w = 0: its direction; w = 1: its position), taken into object space, minus the point.
float3 ObjSpaceViewDir(float4 localPos) {
    return mul(unity_WorldToObject, float4(_WorldSpaceCameraPos, 1.0)).xyz - localPos.xyz;
}

float3 ObjSpaceLightDir(float4 localPos) {
    return mul(unity_WorldToObject, _WorldSpaceLightPos0).xyz - localPos.xyz * _WorldSpaceLightPos0.w;
}

// UnityCG.cginc's TransformViewToProjection: a view-space direction through the projection's
// upper-left 2x2 or 3x3 (an outline's screen-space offset).
float2 TransformViewToProjection(float2 v) {
    return mul((float2x2)UNITY_MATRIX_P, v);
}

float3 TransformViewToProjection(float3 v) {
    return mul((float3x3)UNITY_MATRIX_P, v);
}

// UnityCG.cginc's MultiplyUV: a texture coordinate through a texture matrix, as (u, v, 0, 0)
float2 MultiplyUV(float4x4 mat, float2 inUV) {
    return mul(mat, float4(inUV, 0.0, 0.0)).xy;
}

// Unity's ComputeNonStereoScreenPos with _ProjectionParams.x = 1 (no flip on GL): xy in
// [0, w] from the bottom-left, zw the clip zw; divide by w for [0, 1].
float4 ComputeScreenPos(float4 pos) {
    float4 o = pos * 0.5;
    o.xy = float2(o.x, o.y * _ProjectionParams.x) + o.w;
    o.zw = pos.zw;
    return o;
}

// UnityCG.cginc's ComputeNonStereoScreenPos itself: ComputeScreenPos without the stereo eye's
// offset, which one eye (pbrlab's camera) does not have, so the same position.
float4 ComputeNonStereoScreenPos(float4 pos) {
    return ComputeScreenPos(pos);
}

// Unity's UnityPixelSnap (UnityCG.cginc): a clip position moved to the nearest pixel corner
// of the viewport (NDC xy times half the size in pixels, rounded, undone). roundEven is the
// rounding of HLSL's round (SPIR-V RoundEven), roundEven in the GLSL twin.
float4 UnityPixelSnap(float4 pos) {
    float2 halfSize = 0.5 * _ScreenParams.xy;
    float2 pixel = round(pos.xy / pos.w * halfSize);
    return float4(pixel / halfSize * pos.w, pos.zw);
}

// Depth-buffer value z in [0, 1] to linear depth (UnityCG.cginc), the inverse of a
// perspective projection's depth: 1/eyeDepth is affine in z, 1/near at z = 0 and 1/far at
// z = 1, i.e. 1/eyeDepth = z (1/far - 1/near) + 1/near = _ZBufferParams.z z + _ZBufferParams.w;
// Linear01Depth is eyeDepth / far. An orthographic camera's depth is linear already (Unity's
// shaders branch on unity_OrthoParams.w instead of calling these).
// UnityCG.cginc's IsGammaSpace(): whether the project renders in gamma colour space; pbrlab
// lights in linear space (docs/conventions.md), Unity's linear colour space: false.
bool IsGammaSpace() { return false; }

float Linear01Depth(float z) {
    return 1.0 / (_ZBufferParams.x * z + _ZBufferParams.y);
}

float LinearEyeDepth(float z) {
    return 1.0 / (_ZBufferParams.z * z + _ZBufferParams.w);
}

// UnityCG.cginc's vertex-stage shorthands, reading the vertex input `v` by name as Unity's do.
#define COMPUTE_EYEDEPTH(o) o = -UnityObjectToViewPos(v.vertex).z
#define COMPUTE_DEPTH_01 (-(UnityObjectToViewPos(v.vertex).z * _ProjectionParams.w))
#define COMPUTE_VIEW_NORMAL normalize(mul((float3x3)UNITY_MATRIX_IT_MV, v.normal))
// UnityCG.cginc's object-space tangent frame of the vertex input `v` (rows tangent, binormal, normal).
#define TANGENT_SPACE_ROTATION float3 binormal = cross(normalize(v.normal), normalize(v.tangent.xyz)) * v.tangent.w; float3x3 rotation = float3x3(v.tangent.xyz, binormal, v.normal)

// UnityCG.cginc's minimal image-effect vertex stage: position to clip space, UV passed on.
struct appdata_img {
    float4 vertex : POSITION;
    float2 texcoord : TEXCOORD0;
};

struct v2f_img {
    float4 pos : SV_POSITION;
    float2 uv : TEXCOORD0;
};

v2f_img vert_img(appdata_img v) {
    v2f_img o;
    UNITY_INITIALIZE_OUTPUT(v2f_img, o);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    return o;
}
#endif
