// pbrlab stand-in for Unity's UnityDeferredLibrary.cginc: the helpers of the deferred path's
// light passes (Internal-DeferredShading, Internal-DeferredReflections, Internal-PrePassLighting).
//
// Provides: unity_v2f_deferred (pos, uv = the screen position, ray = the view-space ray),
//   vert_deferred(vertex, normal), UnityDeferredCalculateLightParams(i, out wpos, out uv,
//   out lightDir, out atten, out fadeDist), UnityDeferredComputeFadeDistance(wpos, z), the
//   light of the draw (_LightPos, _LightColor, _LightDir, _LightAsQuad) and the camera's depth
//   texture (_CameraDepthTexture).
// Include: #include "UnityDeferredLibrary.cginc" (after UnityCG.cginc, as Unity's shaders do).
// Config macros read: DIRECTIONAL, POINT, SPOT (Unity's multi_compile_lightpass keywords: the
//   harness draws a light pass once per scene light with its keyword, importers/unity/deferred.py).
// Unity's file (UnityDeferredLibrary.cginc, Unity 2019.4 built-in shaders, read for its
//   behaviour and written here anew): a light pass is drawn over the light's volume (a sphere
//   for a point light, a full-screen quad for a directional one, _LightAsQuad 1), each pixel
//   reads the camera's depth texture and rebuilds the view-space point from the ray through
//   the volume's vertex scaled to the far plane (_ProjectionParams.z) times Linear01Depth, and
//   the world point through unity_CameraToWorld (whose +z is the camera's forward axis).
// The harness's render (harness/pbrlab/render/camera_textures.py) fills _CameraDepthTexture
//   from a depth pre-pass of the scene's opaque objects, GL's window depth in [0, 1] (not
//   reversed: the _ZBufferParams of UnityShaderVariables for a GL depth buffer, as pbrlab sets
//   them), and the G-buffer (_CameraGBufferTexture0..2) in Unity's layout.
// Differences: a point or spot light's falloff is the harness's (pbr_distance_attenuation
//   with the light's range, as pbrlab's Unity forward passes take it) where Unity reads its
//   falloff texture _LightTextureB0; a spot's cone is pbrlab's (pbr_spot_attenuation) where
//   Unity reads a cookie (_LightTexture0); no light casts a shadow (SHADOWS_* are not drawn)
//   and no cookie is drawn (POINT_COOKIE, DIRECTIONAL_COOKIE refused by the shader's keywords).
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_DEFERRED_LIBRARY_CGINC
#define PBRLAB_UNITY_DEFERRED_LIBRARY_CGINC

// The light's falloff and cookie textures and unity_WorldToLight, which Unity's file declares
// too (a light pass that samples _LightTextureB0 itself, as a ray-marched volume light does):
// AutoLight.cginc's stand-in declares them (white: the falloff is the harness's, see above).
#include "AutoLight.cginc"

// The light of this draw, set per draw by the harness (importers/unity/deferred.py) as Unity
// sets them: _LightPos xyz the light's position, w 1 / range^2; _LightColor its colour times
// intensity (pbrlab's radiance units, which are Unity's); _LightDir xyz the direction the
// light travels (a directional light's forward axis); _LightAsQuad 0: the harness draws the
// pass over the object's own mesh as a light volume (the ray comes from the vertex position).
// They are plain globals the fragment entry fills from the scene's light arrays
// (importers/unity/deferred.py, light_assignments), not uniforms (initialised: the port keeps
// an initialised static global a plain GLSL global).
static float4 _LightPos = float4(0.0, 0.0, 0.0, 0.0);
static float4 _LightColor = float4(0.0, 0.0, 0.0, 0.0);
static float4 _LightDir = float4(0.0, 0.0, 0.0, 0.0);
static float4 pbrlab_LightCone = float4(0.0, 0.0, 0.0, 0.0);  // a spot's (cos outer, 1 / (cos inner - cos outer)): pbrlab's cone
static float pbrlab_LightRange = 0.0;    // the light's range (pbrlab's falloff reaches 0 there)
static const float _LightAsQuad = 0.0;
// The legacy lighting pre-pass's fade of realtime light into Unity 4's dual lightmaps (near
// lightmap + realtime light close by, far lightmap beyond: fade = distance * z + w, the light
// scaled by 1 - fade). Unity 5 removed dual lightmaps (Unity 5.0 upgrade guide: "Dual lightmaps
// ... removed"); with no fade active the term is zero, Unity's value of a global nothing sets, and
// the light is drawn unfaded: (0, 0, 0, 0).
static const float4 unity_LightmapFade = float4(0.0, 0.0, 0.0, 0.0);

UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);

// The deferred reflection pass's probe. The harness's one reflection source is the scene's
// environment: Unity's default reflection (the sky's probe), which Unity's deferred path draws
// with this pass over the whole screen. Its box is unbounded (the environment lies at
// infinity), here +-1e30 (float32-safe), so Internal-DeferredReflections' distance to the box is
// 0 and its falloff saturate(1 - 0 / blend distance) is 1 for any positive blend distance
// (unity_SpecCube1_ProbePosition.w, "set to the blend distance for this probe": 1 here).
// (unity_SpecCube0_BoxMin, _BoxMax, _ProbePosition: the Unity prelude's, unity_compat/shader_variables;
// the prelude's unity_SpecCube1_ProbePosition is the forward path's second probe, w its box
// projection, 0: the deferred pass reads this one instead)
static const float4 pbrlab_unity_deferred_probe_position = float4(0.0, 0.0, 0.0, 1.0);
#define unity_SpecCube1_ProbePosition pbrlab_unity_deferred_probe_position

// UnityGIInput as the deferred reflection pass fills it (UnityGlobalIllumination.cginc's, with
// the per-probe arrays the forward GI input of pbrlab's library leaves out), and
// UnityGI_IndirectSpecular of one probe: the environment's radiance at the mip of the
// perceptual roughness along reflUVW (Unity_GlossyEnvironment; DecodeHDR with probeHDR is the
// identity for the harness's float environment, as unity_SpecCube0_HDR says) times occlusion.
// No box projection (UNITY_SPECCUBE_BOX_PROJECTION is not drawn), no blending of two probes
// (boxMin[0].w = 1 turns it off in Unity's deferred pass too).
struct pbrlab_DeferredGIInput
{
    UnityLight light;
    float3 worldPos;
    half3 worldViewDir;
    half atten;
    half3 ambient;
    float4 probeHDR[2];
    float4 boxMin[2];
    float4 boxMax[2];
    float4 probePosition[2];
};
#define UnityGIInput pbrlab_DeferredGIInput

half3 UnityGI_IndirectSpecular(pbrlab_DeferredGIInput data, half occlusion, Unity_GlossyEnvironmentData glossIn)
{
    return Unity_GlossyEnvironment(glossIn) * occlusion;
}

struct unity_v2f_deferred {
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
    float3 ray : TEXCOORD1;
};

// The volume's vertex: its clip position, its screen position (ComputeScreenPos, divided per
// pixel), and the view-space position with x and y negated: Unity's view space looks down -z,
// so the per-pixel scale by far / ray.z (negative) turns x and y back and gives the ray to the
// far plane with +z forward, the frame of unity_CameraToWorld. A full-screen quad's ray is its
// normal (_LightAsQuad 1), which the harness never draws.
unity_v2f_deferred vert_deferred(float4 vertex : POSITION, float3 normal : NORMAL)
{
    unity_v2f_deferred o;
    o.pos = UnityObjectToClipPos(vertex);
    o.uv = ComputeScreenPos(o.pos);
    float3 viewRay = UnityObjectToViewPos(vertex) * float3(-1.0, -1.0, 1.0);
    o.ray = lerp(viewRay, normal, _LightAsQuad);
    return o;
}

// The distance the deferred path fades realtime shadows by (Unity: the view depth, or the
// distance to the shadow fade centre by unity_ShadowFadeCenterAndType.w): the harness has no
// shadow fade centre, so the view depth.
float UnityDeferredComputeFadeDistance(float3 wpos, float z)
{
    return z;
}

// The pixel's surface point (from the depth texture), its screen uv, the direction to the
// light, the light's attenuation and the fade distance (module comment).
void UnityDeferredCalculateLightParams(unity_v2f_deferred i, out float3 outWorldPos, out float2 outUV,
                                       out half3 outLightDir, out float outAtten, out float outFadeDist)
{
    float3 ray = i.ray * (_ProjectionParams.z / i.ray.z);
    float2 uv = i.uv.xy / i.uv.w;
    float depth = Linear01Depth(SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, uv));
    float4 viewPos = float4(ray * depth, 1.0);
    float3 wpos = mul(unity_CameraToWorld, viewPos).xyz;
    float fadeDist = UnityDeferredComputeFadeDistance(wpos, viewPos.z);
    float atten = 1.0;
#if defined(SPOT) || defined(POINT)
    float3 toLight = _LightPos.xyz - wpos;
    float d2 = dot(toLight, toLight);
    half3 lightDir = toLight * rsqrt(max(d2, PBR_MIN_LIGHT_DISTANCE_SQUARED));
    atten = pbr_distance_attenuation(d2, pbrlab_LightRange);
#if defined(SPOT)
    atten *= pbr_spot_attenuation(lightDir, _LightDir.xyz, pbrlab_LightCone.x, pbrlab_LightCone.y);
#endif
#else
    half3 lightDir = -_LightDir.xyz;
#endif
    outWorldPos = wpos;
    outUV = uv;
    outLightDir = lightDir;
    outAtten = atten;
    outFadeDist = fadeDist;
}

#endif
