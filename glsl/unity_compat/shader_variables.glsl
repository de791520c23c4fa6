// unity_compat/shader_variables.glsl: the built-in globals a Unity surface shader reads
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
//           vec2 UnityStereoScreenSpaceUVAdjust(uv, scaleAndOffset), UnityStereoTransformScreenSpaceTex(uv)
//           (the identity: one eye);
//           vec3 ShadeVertexLightsFull(vec4 vertex, vec3 normal, int lightCount, bool spotLight),
//           vec3 ShadeVertexLights(vec4 vertex, vec3 normal) (UnityCG.cginc's vertex lighting);
//           vec4 Unity_LightmodelAmbient(), UNITY_LIGHTMODEL_AMBIENT (the ambient probe's mean);
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
//           vec4 UnityObjectToClipPos(vec3 pos) / (vec4 pos), vec4 UnityWorldToClipPos(vec3),
//           vec4 UnityViewToClipPos(vec3), vec3 UnityObjectToViewPos(vec3) / (vec4),
//           vec3 UnityWorldToViewPos(vec3), vec3 UnityObjectToWorldNormal(vec3),
//           vec3 UnityObjectToWorldDir(vec3), vec3 UnityWorldToObjectDir(vec3),
//           vec3 UnityWorldSpaceViewDir(vec3 worldPos), vec3 UnityWorldSpaceLightDir(vec3 worldPos),
//           vec3 WorldSpaceViewDir(vec4 localPos), vec3 WorldSpaceLightDir(vec4 localPos),
//           vec3 ObjSpaceViewDir(vec4 localPos), vec3 ObjSpaceLightDir(vec4 localPos),
//           vec2 / vec3 TransformViewToProjection(v) (the projection's upper-left 2x2 / 3x3),
//           vec4 ComputeScreenPos(vec4 clipPos), vec4 UnityPixelSnap(vec4 clipPos),
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
//           position member, HLSLSupport.cginc's float4 pos : SV_POSITION; the reader gives it
//           that semantic, parse_pass._structs); UNITY_BRANCH, UNITY_FLATTEN, UNITY_UNROLL,
//           UNITY_UNROLLX(n), UNITY_LOOP, UNITY_FASTOPT (HLSL attributes; nothing in GLSL);
//           AutoLight.cginc's macros without shadows (no shadow maps here; a light's falloff
//           is already in _LightColor0): SHADOW_COORDS(idx), UNITY_SHADOW_COORDS(idx),
//           LIGHTING_COORDS(idx1, idx2), UNITY_LIGHTING_COORDS(idx1, idx2), TRANSFER_SHADOW(a),
//           UNITY_TRANSFER_SHADOW(a, coord), TRANSFER_VERTEX_TO_FRAGMENT(a),
//           UNITY_TRANSFER_LIGHTING(a, coord) expand to nothing; SHADOW_ATTENUATION(a),
//           UNITY_SHADOW_ATTENUATION(a, worldPos), LIGHT_ATTENUATION(a) are 1.0;
//           UNITY_LIGHT_ATTENUATION(destName, input, worldPos) declares `float destName = 1.0;`.
//           Not provided: lightmaps (unity_Lightmap, DecodeLightmap), depth textures
//           (_CameraDepthTexture, SAMPLE_DEPTH_TEXTURE), shadow-caster macros: the harness has
//           none of these.
// Include:  "unity_compat/shader_variables.glsl" (path relative to glsl/). Its HLSL twin
//           hlsl_ports/unity_compat/shader_variables.hlsl is hand-written (matrices: GLSL M * v
//           is HLSL mul(M, v)); HLSL's instancing macro declares `type var;`.
// Config macros read: PBR_UNITY_SH_IRRADIANCE(n) (UNITY_LIGHTMODEL_AMBIENT: the caller's ambient
//           lookup, as pbr/unity/global_illumination reads it; default black);
//           PBR_UNITY_SH9 (the caller's nine SH9 radiance coefficients, as pbr_sh9_irradiance
//           reads them, with pbr/lighting/sh9.glsl's constants: unity_SHAr..unity_SHC; default zero).
// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.
#ifndef PBR_UNITY_COMPAT_SHADER_VARIABLES_GLSL
#define PBR_UNITY_COMPAT_SHADER_VARIABLES_GLSL

uniform vec4 _Time;
uniform vec4 _SinTime;
uniform vec4 _CosTime;
uniform vec4 unity_DeltaTime;
uniform vec3 _WorldSpaceCameraPos;
uniform vec4 _ProjectionParams;
uniform vec4 _ScreenParams;
uniform mat4 unity_ObjectToWorld;
uniform mat4 unity_WorldToObject;
// w: -1 where the object's transform mirrors (a negative determinant), else 1; x, y, z 0
// (UnityShaderVariables.cginc; the tangent basis's handedness flips with it)
uniform vec4 unity_WorldTransformParams;
uniform mat4 unity_MatrixVP;
uniform mat4 unity_MatrixV;
uniform mat4 unity_MatrixInvV;
uniform mat4 glstate_matrix_projection;
uniform mat4 unity_CameraProjection;
uniform mat4 unity_CameraInvProjection;
// the camera transform's own frame (+z forward, unlike the view matrix's -z): world to it and back
uniform mat4 unity_WorldToCamera;
uniform mat4 unity_CameraToWorld;
uniform vec4 _ZBufferParams;
uniform vec4 unity_OrthoParams;
// the camera's frustum planes in world space, left, right, bottom, top, near, far: xyz the unit
// normal pointing into the frustum, w the offset (dot(float4(p, 1), plane) is p's distance
// inside), as UnityShaderVariables.cginc's; pbrlab sets them (importers/unity/program.py)
uniform vec4 unity_CameraWorldClipPlanes[6];
uniform vec4 _SpecColor;
uniform vec4 unity_SpecCube0_HDR;
// The reflection probe's box (UnityShaderVariables.cginc / URP's UnityInput.hlsl): the scene's
// one reflection source is its environment, Unity's default reflection (the sky's probe), which
// is not box-projected: ProbePosition.w = 0 (box projection off: BoxProjectedCubemapDirection
// returns the direction as given), its box unbounded (the environment at infinity, here +-1e30,
// float32-safe) and BoxMin.w, the weight of probe 0 against probe 1, 1 (no blending).
const vec4 unity_SpecCube0_ProbePosition = vec4(0.0, 0.0, 0.0, 0.0);
const vec4 unity_SpecCube0_BoxMin = vec4(-1e30, -1e30, -1e30, 1.0);
const vec4 unity_SpecCube0_BoxMax = vec4(1e30, 1e30, 1e30, 0.0);
// The second probe (UnityShaderVariables.cginc's unity_SpecCube1*, the probe an object blends
// toward): with one reflection source Unity's weight of probe 0 is 1 (BoxMin.w above), so a
// shader that blends reads probe 0 alone; probe 1 is the same sky with the same box and decode
// (its reads are the sky's: importers/unity/texture_methods.py).
#define unity_SpecCube1_HDR unity_SpecCube0_HDR
const vec4 unity_SpecCube1_ProbePosition = vec4(0.0, 0.0, 0.0, 0.0);
const vec4 unity_SpecCube1_BoxMin = vec4(-1e30, -1e30, -1e30, 1.0);
const vec4 unity_SpecCube1_BoxMax = vec4(1e30, 1e30, 1e30, 0.0);
uniform vec4 unity_FogColor;
// pbr/unity/lighting_legacy reads the BlinnPhong specular colour through this hook.
#define PBR_UNITY_SPEC_COLOR _SpecColor
vec4 _LightColor0;
vec4 _WorldSpaceLightPos0;
// Unity's vertex lights (UnityShaderVariables.cginc; legacy vertex-lit rendering): plain
// globals the caller's vertex stage sets (pbrlab: 8 black lights, but a Vertex pass's lights).
vec4 unity_LightColor[8];
vec4 unity_LightPosition[8];
vec4 unity_LightAtten[8];
vec4 unity_SpotDirection[8];
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
vec4 unity_4LightPosX0;
vec4 unity_4LightPosY0;
vec4 unity_4LightPosZ0;
vec4 unity_4LightAtten0;

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_V unity_MatrixV
#define UNITY_MATRIX_I_V unity_MatrixInvV
#define UNITY_MATRIX_P glstate_matrix_projection
#define UNITY_MATRIX_VP unity_MatrixVP
#define UNITY_MATRIX_MVP (unity_MatrixVP * unity_ObjectToWorld)
// UnityShaderVariables.cginc builds these three from the per-camera and per-object matrices;
// the inverse transpose of M V (for normals) is transpose(M^-1 V^-1) with no inversion.
#define UNITY_MATRIX_MV (unity_MatrixV * unity_ObjectToWorld)
#define UNITY_MATRIX_T_MV transpose(unity_MatrixV * unity_ObjectToWorld)
#define UNITY_MATRIX_IT_MV transpose(unity_WorldToObject * unity_MatrixInvV)
#define TRANSFORM_TEX(tex, name) ((tex).xy * name##_ST.xy + name##_ST.zw)

#define UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_BUFFER_END(name)
#define UNITY_DEFINE_INSTANCED_PROP(type, var) uniform type var;
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
const vec4 unity_StereoScaleOffset[2] = vec4[2](vec4(1.0, 1.0, 0.0, 0.0), vec4(1.0, 1.0, 0.0, 0.0));
// the fixed-function pipeline's texture matrices (UnityShaderVariables.cginc's glstate_matrix_texture0..3):
// the identity unless a legacy SetTexture's Matrix sets one, which no program-drawn pass does
#define UNITY_MATRIX_TEXTURE0 mat4(1.0)
#define UNITY_MATRIX_TEXTURE1 mat4(1.0)
#define UNITY_MATRIX_TEXTURE2 mat4(1.0)
#define UNITY_MATRIX_TEXTURE3 mat4(1.0)
// UnityCG.cginc's single-pass stereo helpers: one eye, so the coordinates as given
vec2 UnityStereoScreenSpaceUVAdjust(vec2 uv, vec4 scaleAndOffset) { return uv; }
vec4 UnityStereoScreenSpaceUVAdjust(vec4 uv, vec4 scaleAndOffset) { return uv; }
#ifndef UnityStereoTransformScreenSpaceTex
#define UnityStereoTransformScreenSpaceTex(uv) (uv)
#endif
#define UNITY_INITIALIZE_OUTPUT(type, name)
#define UNITY_POSITION(pos) vec4 pos

// HLSLSupport.cginc's flow-control hints: HLSL attributes on Direct3D, nothing on Unity's GLSL
// targets (GLSL has no attributes); a hint, never a change of what is computed.
#define UNITY_BRANCH
#define UNITY_FLATTEN
#define UNITY_UNROLL
#define UNITY_UNROLLX(n)
#define UNITY_LOOP
#define UNITY_FASTOPT

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
#define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) float destName = 1.0;

// UnityCG.cginc's camera depth texture: a shader declares and samples it by these names.
// The harness draws no depth pre-pass, so the material's texture of that name is Unity's
// default when none is set: white, depth 1, the far plane (nothing in front: a soft
// particle does not fade). A shader's own value may be given in the material's properties.
#define UNITY_DECLARE_DEPTH_TEXTURE(tex) uniform sampler2D tex
#define SAMPLE_DEPTH_TEXTURE(tex, uv) (texture(tex, (uv).xy).r)
#define SAMPLE_DEPTH_TEXTURE_PROJ(tex, uv) (textureProj(tex, uv).r)
#define SAMPLE_DEPTH_TEXTURE_LOD(tex, uv) (textureLod(tex, (uv).xy, (uv).w).r)
// a depth read from a depth texture's texel (UnityCG.cginc; its red channel outside GLES 2)
#define UNITY_SAMPLE_DEPTH(value) ((value).r)
// HLSLSupport.cginc's single-channel read, shipped in Unity 4.0 and kept: the texel's alpha
#define UNITY_SAMPLE_1CHANNEL(tex, uv) (texture(tex, uv).a)
#define UNITY_ALPHA_CHANNEL a
// HLSLSupport.cginc's clip-space depths of the near and far planes, per graphics API: pbrlab
// draws in OpenGL's clip space (no reversed Z, z from -w to w: render/depth_range.py), where
// Unity defines the near plane's as -1 and the raw far plane's as 1.
#define UNITY_NEAR_CLIP_VALUE (-1.0)
#define UNITY_RAW_FAR_CLIP_VALUE (1.0)

// HLSLSupport.cginc's texture macros, as its sampler2D path declares them (one sampler per
// texture: the GL texture's own filtering applies).
#ifndef UNITY_DECLARE_TEX2D
#define UNITY_DECLARE_TEX2D(tex) uniform sampler2D tex
#endif
#define UNITY_DECLARE_TEX2D_NOSAMPLER(tex) uniform sampler2D tex
// UNITY_SAMPLE_TEX2D: a function, so that the port's type pass knows the float4 it returns (a
// program that assigns it to a float3 is ported with FXC's truncation, as HLSL compiles it).
#ifndef UNITY_SAMPLE_TEX2D
vec4 UNITY_SAMPLE_TEX2D(sampler2D tex, vec2 uv) { return texture(tex, uv); }
#endif
#define UNITY_SAMPLE_TEX2D_SAMPLER(tex, samplertex, uv) texture(tex, uv)
#define UNITY_DECLARE_TEXCUBE(tex) uniform samplerCube tex
#define UNITY_SAMPLE_TEXCUBE(tex, dir) texture(tex, dir)
#define UNITY_SAMPLE_TEXCUBE_LOD(tex, dir, lod) textureLod(tex, dir, lod)
// HLSLSupport.cginc's further 2D and cube forms: a level of detail; another texture's sampler (the
// GL texture's own sampler serves, as for UNITY_SAMPLE_TEX2D_SAMPLER); half and float precision
// declarations (one texture type here); a cube passed to a function (UNITY_ARGS_TEXCUBE in its
// parameter list, UNITY_PASS_TEXCUBE at the call).
#define UNITY_DECLARE_TEX2D_HALF(tex) UNITY_DECLARE_TEX2D(tex)
#define UNITY_DECLARE_TEX2D_FLOAT(tex) UNITY_DECLARE_TEX2D(tex)
#define UNITY_DECLARE_TEX2D_NOSAMPLER_HALF(tex) UNITY_DECLARE_TEX2D_NOSAMPLER(tex)
#define UNITY_DECLARE_TEX2D_NOSAMPLER_FLOAT(tex) UNITY_DECLARE_TEX2D_NOSAMPLER(tex)
vec4 UNITY_SAMPLE_TEX2D_LOD(sampler2D tex, vec2 uv, float lod) { return textureLod(tex, uv, lod); }
#define UNITY_SAMPLE_TEX2D_SAMPLER_LOD(tex, samplertex, uv, lod) UNITY_SAMPLE_TEX2D_LOD(tex, uv, lod)
#define UNITY_DECLARE_TEXCUBE_NOSAMPLER(tex) uniform samplerCube tex
#define UNITY_SAMPLE_TEXCUBE_SAMPLER(tex, samplertex, dir) texture(tex, dir)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD(tex, samplertex, dir, lod) textureLod(tex, dir, lod)
#define UNITY_ARGS_TEXCUBE(tex) samplerCube tex
#define UNITY_ARGS_TEXCUBE_NOSAMPLER(tex) samplerCube tex
#ifndef UNITY_PASS_TEXCUBE
#define UNITY_PASS_TEXCUBE(tex) tex
#endif
#define UNITY_PASS_TEXCUBE_NOSAMPLER(tex) tex
#define UNITY_DECLARE_SCREENSPACE_TEXTURE(tex) uniform sampler2D tex
#define UNITY_SAMPLE_SCREENSPACE_TEXTURE(tex, uv) texture(tex, (uv).xy)
// HLSLSupport.cginc's 2D texture arrays: coord.z is the layer (rounded to the nearest, clamped
// to the layers there are: GL's rule, as Direct3D's). Functions, so the port's type pass knows
// the float4 they return. A material binds a one-layer array (unity/texture_arrays.py).
#define UNITY_DECLARE_TEX2DARRAY(tex) uniform sampler2DArray tex
#define UNITY_DECLARE_TEX2DARRAY_NOSAMPLER(tex) uniform sampler2DArray tex
vec4 UNITY_SAMPLE_TEX2DARRAY(sampler2DArray tex, vec3 coord) { return texture(tex, coord); }
vec4 UNITY_SAMPLE_TEX2DARRAY_LOD(sampler2DArray tex, vec3 coord, float lod) { return textureLod(tex, coord, lod); }
// HLSLSupport.cginc's 3D textures (a material's 3D property: a 1x1x1 volume, unity/program.py).
#define UNITY_DECLARE_TEX3D(tex) uniform sampler3D tex
#define UNITY_DECLARE_TEX3D_NOSAMPLER(tex) uniform sampler3D tex
vec4 UNITY_SAMPLE_TEX3D(sampler3D tex, vec3 coord) { return texture(tex, coord); }
vec4 UNITY_SAMPLE_TEX3D_LOD(sampler3D tex, vec3 coord, float lod) { return textureLod(tex, coord, lod); }
#define UNITY_SAMPLE_TEX3D_SAMPLER(tex, samplertex, coord) UNITY_SAMPLE_TEX3D(tex, coord)

vec4 UnityObjectToClipPos(vec3 pos) {
    return unity_MatrixVP * (unity_ObjectToWorld * vec4(pos, 1.0));
}

vec4 UnityObjectToClipPos(vec4 pos) {
    return UnityObjectToClipPos(pos.xyz);
}

vec4 UnityWorldToClipPos(vec3 pos) {
    return unity_MatrixVP * vec4(pos, 1.0);
}

vec4 UnityViewToClipPos(vec3 pos) {
    return glstate_matrix_projection * vec4(pos, 1.0);
}

// Eye space: the camera at the origin looking down -z (Unity's view matrix is GL-style too),
// so a point in front of the camera has view z = -(its eye depth).
vec3 UnityObjectToViewPos(vec3 pos) {
    return (unity_MatrixV * (unity_ObjectToWorld * vec4(pos, 1.0))).xyz;
}

vec3 UnityObjectToViewPos(vec4 pos) {
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
vec4 Unity_LightmodelAmbient() {
#ifdef PBR_UNITY_SH_IRRADIANCE
    vec3 sum = PBR_UNITY_SH_IRRADIANCE(vec3(1.0, 0.0, 0.0)) + PBR_UNITY_SH_IRRADIANCE(vec3(-1.0, 0.0, 0.0))
             + PBR_UNITY_SH_IRRADIANCE(vec3(0.0, 1.0, 0.0)) + PBR_UNITY_SH_IRRADIANCE(vec3(0.0, -1.0, 0.0))
             + PBR_UNITY_SH_IRRADIANCE(vec3(0.0, 0.0, 1.0)) + PBR_UNITY_SH_IRRADIANCE(vec3(0.0, 0.0, -1.0));
    return vec4(sum / 6.0, 1.0);
#else
    return vec4(0.0, 0.0, 0.0, 1.0);
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
vec4 Unity_AmbientSkyColor() {
#ifdef PBR_UNITY_SH_IRRADIANCE
    return vec4(PBR_UNITY_SH_IRRADIANCE(vec3(0.0, 1.0, 0.0)), 1.0);
#else
    return vec4(0.0, 0.0, 0.0, 1.0);
#endif
}
vec4 Unity_AmbientEquatorColor() {
#ifdef PBR_UNITY_SH_IRRADIANCE
    vec3 sum = PBR_UNITY_SH_IRRADIANCE(vec3(1.0, 0.0, 0.0)) + PBR_UNITY_SH_IRRADIANCE(vec3(-1.0, 0.0, 0.0))
             + PBR_UNITY_SH_IRRADIANCE(vec3(0.0, 0.0, 1.0)) + PBR_UNITY_SH_IRRADIANCE(vec3(0.0, 0.0, -1.0));
    return vec4(sum * 0.25, 1.0);
#else
    return vec4(0.0, 0.0, 0.0, 1.0);
#endif
}
vec4 Unity_AmbientGroundColor() {
#ifdef PBR_UNITY_SH_IRRADIANCE
    return vec4(PBR_UNITY_SH_IRRADIANCE(vec3(0.0, -1.0, 0.0)), 1.0);
#else
    return vec4(0.0, 0.0, 0.0, 1.0);
#endif
}
#define unity_AmbientSky Unity_AmbientSkyColor()
#define unity_AmbientEquator Unity_AmbientEquatorColor()
#define unity_AmbientGround Unity_AmbientGroundColor()
#ifdef PBR_UNITY_SH9
#include "pbr/lighting/sh9.glsl"
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
vec4 Unity_SHA(int channel) {
#ifdef PBR_UNITY_SH9
    return vec4(2.0 * PBR_SH9_C2 * PBR_UNITY_SH9[3][channel], 2.0 * PBR_SH9_C2 * PBR_UNITY_SH9[1][channel],
                2.0 * PBR_SH9_C2 * PBR_UNITY_SH9[2][channel],
                PBR_SH9_C4 * PBR_UNITY_SH9[0][channel] - PBR_SH9_C5 * PBR_UNITY_SH9[6][channel]) * PBR_INV_PI;
#else
    return vec4(0.0, 0.0, 0.0, 0.0);
#endif
}
vec4 Unity_SHB(int channel) {
#ifdef PBR_UNITY_SH9
    return vec4(2.0 * PBR_SH9_C1 * PBR_UNITY_SH9[4][channel], 2.0 * PBR_SH9_C1 * PBR_UNITY_SH9[5][channel],
                PBR_SH9_C3 * PBR_UNITY_SH9[6][channel], 2.0 * PBR_SH9_C1 * PBR_UNITY_SH9[7][channel]) * PBR_INV_PI;
#else
    return vec4(0.0, 0.0, 0.0, 0.0);
#endif
}
vec4 Unity_SHC() {
#ifdef PBR_UNITY_SH9
    return vec4(PBR_SH9_C1 * PBR_UNITY_SH9[8] * PBR_INV_PI, 1.0);
#else
    return vec4(0.0, 0.0, 0.0, 1.0);
#endif
}
#define unity_SHAr Unity_SHA(0)
#define unity_SHAg Unity_SHA(1)
#define unity_SHAb Unity_SHA(2)
#define unity_SHBr Unity_SHB(0)
#define unity_SHBg Unity_SHB(1)
#define unity_SHBb Unity_SHB(2)
#define unity_SHC Unity_SHC()

vec3 ShadeVertexLightsFull(vec4 vertex, vec3 normal, int lightCount, bool spotLight) {
    vec3 viewpos = UnityObjectToViewPos(vertex.xyz);
    vec3 viewN = normalize(mat3(UNITY_MATRIX_IT_MV) * normal);
    vec3 lightColor = Unity_LightmodelAmbient().xyz;
    for (int i = 0; i < lightCount; i++) {
        vec3 toLight = unity_LightPosition[i].xyz - viewpos * unity_LightPosition[i].w;
        float lengthSq = max(dot(toLight, toLight), 0.000001);
        toLight *= inversesqrt(lengthSq);
        float atten = 1.0 / (1.0 + lengthSq * unity_LightAtten[i].z);
        if (spotLight) {
            float rho = max(0.0, dot(toLight, unity_SpotDirection[i].xyz));
            atten *= clamp((rho - unity_LightAtten[i].x) * unity_LightAtten[i].y, 0.0, 1.0);
        }
        float diff = max(0.0, dot(viewN, toLight));
        lightColor += unity_LightColor[i].rgb * (diff * atten);
    }
    return lightColor;
}

vec3 ShadeVertexLights(vec4 vertex, vec3 normal) {
    return ShadeVertexLightsFull(vertex, normal, 4, false);
}

// UnityCG.cginc's Shade4PointLights: the diffuse light of four point lights at world position pos
// with world normal normal, each light's colour times max(0, n.l) / (1 + d^2 * attenSq), its
// squared distance d^2 kept from 0 (at least 1e-6, as Unity's): the formula as Unity states it,
// evaluated four lights at a time.
vec3 Shade4PointLights(vec4 lightPosX, vec4 lightPosY, vec4 lightPosZ, vec3 lightColor0,
                         vec3 lightColor1, vec3 lightColor2, vec3 lightColor3, vec4 lightAttenSq,
                         vec3 pos, vec3 normal) {
    vec4 toX = lightPosX - pos.x;
    vec4 toY = lightPosY - pos.y;
    vec4 toZ = lightPosZ - pos.z;
    vec4 distanceSq = max(toX * toX + toY * toY + toZ * toZ, vec4(0.000001, 0.000001, 0.000001, 0.000001));
    vec4 cosine = max(vec4(0.0, 0.0, 0.0, 0.0), (toX * normal.x + toY * normal.y + toZ * normal.z) * inversesqrt(distanceSq));
    vec4 diffuse = cosine / (1.0 + distanceSq * lightAttenSq);
    return lightColor0 * diffuse.x + lightColor1 * diffuse.y + lightColor2 * diffuse.z + lightColor3 * diffuse.w;
}

vec3 UnityWorldToViewPos(vec3 pos) {
    return (unity_MatrixV * vec4(pos, 1.0)).xyz;
}

// Normals transform with the inverse transpose: n^T M^-1 (Unity: mul(norm, (float3x3)unity_WorldToObject)).
vec3 UnityObjectToWorldNormal(vec3 norm) {
    return normalize(norm * mat3(unity_WorldToObject));
}

vec3 UnityObjectToWorldDir(vec3 dir) {
    return normalize(mat3(unity_ObjectToWorld) * dir);
}

vec3 UnityWorldToObjectDir(vec3 dir) {
    return normalize(mat3(unity_WorldToObject) * dir);
}

vec3 UnityWorldSpaceViewDir(vec3 worldPos) {
    return _WorldSpaceCameraPos - worldPos;
}

vec3 UnityWorldSpaceLightDir(vec3 worldPos) {
    return _WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w;
}

vec3 WorldSpaceViewDir(vec4 localPos) {
    return UnityWorldSpaceViewDir((unity_ObjectToWorld * localPos).xyz);
}

vec3 WorldSpaceLightDir(vec4 localPos) {
    return UnityWorldSpaceLightDir((unity_ObjectToWorld * localPos).xyz);
}

// Object-space directions (not normalised, as Unity's): the camera, or the light
// (w = 0: its direction; w = 1: its position), taken into object space, minus the point.
vec3 ObjSpaceViewDir(vec4 localPos) {
    return (unity_WorldToObject * vec4(_WorldSpaceCameraPos, 1.0)).xyz - localPos.xyz;
}

vec3 ObjSpaceLightDir(vec4 localPos) {
    return (unity_WorldToObject * _WorldSpaceLightPos0).xyz - localPos.xyz * _WorldSpaceLightPos0.w;
}

// UnityCG.cginc's TransformViewToProjection: a view-space direction through the projection's
// upper-left 2x2 or 3x3 (an outline's screen-space offset).
vec2 TransformViewToProjection(vec2 v) {
    return mat2(UNITY_MATRIX_P) * v;
}

vec3 TransformViewToProjection(vec3 v) {
    return mat3(UNITY_MATRIX_P) * v;
}

// UnityCG.cginc's MultiplyUV: a texture coordinate through a texture matrix, as (u, v, 0, 0)
vec2 MultiplyUV(mat4 mat, vec2 inUV) {
    return (mat * vec4(inUV, 0.0, 0.0)).xy;
}

// Unity's ComputeNonStereoScreenPos with _ProjectionParams.x = 1 (no flip on GL): xy in
// [0, w] from the bottom-left, zw the clip zw; divide by w for [0, 1].
vec4 ComputeScreenPos(vec4 pos) {
    vec4 o = pos * 0.5;
    o.xy = vec2(o.x, o.y * _ProjectionParams.x) + o.w;
    o.zw = pos.zw;
    return o;
}

// UnityCG.cginc's ComputeNonStereoScreenPos itself: ComputeScreenPos without the stereo eye's
// offset, which one eye (pbrlab's camera) does not have, so the same position.
vec4 ComputeNonStereoScreenPos(vec4 pos) {
    return ComputeScreenPos(pos);
}

// Unity's UnityPixelSnap (UnityCG.cginc): a clip position moved to the nearest pixel corner
// of the viewport (NDC xy times half the size in pixels, rounded, undone). roundEven is the
// rounding of HLSL's round (SPIR-V RoundEven; GLSL's round may go either way at 1/2).
vec4 UnityPixelSnap(vec4 pos) {
    vec2 halfSize = 0.5 * _ScreenParams.xy;
    vec2 pixel = roundEven(pos.xy / pos.w * halfSize);
    return vec4(pixel / halfSize * pos.w, pos.zw);
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
#define COMPUTE_VIEW_NORMAL normalize(mat3(UNITY_MATRIX_IT_MV) * v.normal)
// UnityCG.cginc's object-space tangent frame of the vertex input `v`: `binormal` (n x t, signed
// by tangent.w) and `rotation`, whose rows are tangent, binormal and normal (object to tangent
// space: mul(rotation, x)); GLSL's mat3 takes columns, hence the transpose.
#define TANGENT_SPACE_ROTATION vec3 binormal = cross(normalize(v.normal), normalize(v.tangent.xyz)) * v.tangent.w; mat3 rotation = transpose(mat3(v.tangent.xyz, binormal, v.normal))

// UnityCG.cginc's minimal image-effect vertex stage: position to clip space, UV passed on.
struct appdata_img {
    vec4 vertex;
    vec2 texcoord;
};

struct v2f_img {
    vec4 pos;
    vec2 uv;
};

v2f_img vert_img(appdata_img v) {
    v2f_img o;
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    return o;
}
#endif
