// pbrlab stand-in for Unity's TerrainSplatmapCommon.cginc (the terrain splat shaders:
// TerrainShaders/Splats/FirstPass, AddPass, Standard-*, Specular-*).
//
// Provides: struct Input { float4 tc; }, the uniforms _Control (the control map: one layer
//   weight per channel), _Splat0..3 (layer albedo; Standard: smoothness in alpha),
//   _Normal0..3 and _NormalScale0..3 (with _NORMALMAP), _TerrainHolesTexture (with
//   _ALPHATEST_ON) and their _ST / _TexelSize; SplatmapVert, SplatmapMix (both signatures:
//   TERRAIN_STANDARD_SHADER's takes the per-layer default alpha), ClipHoles,
//   SplatmapFinalColor, SplatmapFinalPrepass, SplatmapFinalGBuffer.
// Unity's file: the same names (TerrainSplatmapCommon.cginc, Unity 2019.4 built-in shaders),
//   read for their behaviour and written here anew.
// Differences: the terrain engine binds _Control, _Splat*, _Normal* and sets _Control_TexelSize
//   from the terrain's data; in pbrlab they are ordinary material properties (give them in
//   `properties`: {"_Control": {"path": ...}, "_Splat0": ...}; unset textures are white;
//   _Control_TexelSize is set from the bound texture, as Unity sets every {name}_TexelSize).
//   No instanced terrain (no heightmap patches: the mesh is drawn as
//   it is), no fog (no fog here: Input has no fogCoord and the final colour is only weighted).
//   SplatmapFinalGBuffer exists so the pragma's finalgbuffer: resolves; the forward path never
//   calls it (UnityStandardDataApplyWeightToGbuffer is not needed).
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_TERRAIN_SPLATMAP_COMMON_CGINC
#define PBRLAB_TERRAIN_SPLATMAP_COMMON_CGINC

// Unity's two spellings of the normal-map keyword (since 2018.3) mean the same.
#if defined(_NORMALMAP) && !defined(_TERRAIN_NORMAL_MAP)
#define _TERRAIN_NORMAL_MAP
#elif defined(_TERRAIN_NORMAL_MAP) && !defined(_NORMALMAP)
#define _NORMALMAP
#endif

struct Input
{
    float4 tc;   // xy: the terrain UV (the mesh's UV0); zw unused here
};

sampler2D _Control;
float4 _Control_ST;
float4 _Control_TexelSize;   // (1/width, 1/height, width, height) of the control map
sampler2D _Splat0;
sampler2D _Splat1;
sampler2D _Splat2;
sampler2D _Splat3;
float4 _Splat0_ST;
float4 _Splat1_ST;
float4 _Splat2_ST;
float4 _Splat3_ST;

#if defined(_NORMALMAP)
sampler2D _Normal0;
sampler2D _Normal1;
sampler2D _Normal2;
sampler2D _Normal3;
float _NormalScale0;
float _NormalScale1;
float _NormalScale2;
float _NormalScale3;
#endif

#if defined(_ALPHATEST_ON)
sampler2D _TerrainHolesTexture;

// A hole (red 0 in the holes map) is cut (TerrainSplatmapCommon.cginc, ClipHoles).
void ClipHoles(float2 uv)
{
    float hole = tex2D(_TerrainHolesTexture, uv).r;
    clip(hole == 0.0 ? -1.0 : 1.0);
}
#endif

// The terrain UV passes through; the tangent is the one Unity gives terrain vertices,
// cross(normal, +z) with w = -1 (TerrainSplatmapCommon.cginc, SplatmapVert).
void SplatmapVert(inout appdata_full v, out Input data)
{
    UNITY_INITIALIZE_OUTPUT(Input, data);
    v.tangent = float4(cross(v.normal, float3(0.0, 0.0, 1.0)), -1.0);
    data.tc = float4(v.texcoord.xy, 0.0, 0.0);
}

#ifndef TERRAIN_BASE_PASS

// Weights from the control map, normalised (their sum returned as `weight`, restored by the
// final colour functions), each layer's texel scaled by its weight and summed; with
// _NORMALMAP the layers' normals likewise (TerrainSplatmapCommon.cginc, SplatmapMix). The
// control map is read at texel centres: uv (size - 1) / size + half a texel.
void PbrlabSplatmapMixCore(Input IN, half4 defaultAlpha, out half4 splat_control, out half weight,
                           out fixed4 mixedDiffuse, inout fixed3 mixedNormal)
{
#if defined(_ALPHATEST_ON)
    ClipHoles(IN.tc.xy);
#endif
    float2 splatUV = (IN.tc.xy * (_Control_TexelSize.zw - 1.0) + 0.5) * _Control_TexelSize.xy;
    half4 control = tex2D(_Control, splatUV);
    weight = dot(control, half4(1.0, 1.0, 1.0, 1.0));
#if defined(TERRAIN_SPLAT_ADDPASS)
    clip(weight == 0.0 ? -1.0 : 1.0);   // Unity: not on mobile; an empty add pass draws nothing
#endif
    // 1e-3: Unity's guard against a zero sum (TerrainSplatmapCommon.cginc)
    splat_control = control / (weight + 1e-3);

    float2 uv0 = TRANSFORM_TEX(IN.tc.xy, _Splat0);
    float2 uv1 = TRANSFORM_TEX(IN.tc.xy, _Splat1);
    float2 uv2 = TRANSFORM_TEX(IN.tc.xy, _Splat2);
    float2 uv3 = TRANSFORM_TEX(IN.tc.xy, _Splat3);
    fixed4 layer0 = tex2D(_Splat0, uv0) * half4(1.0, 1.0, 1.0, defaultAlpha.r);
    fixed4 layer1 = tex2D(_Splat1, uv1) * half4(1.0, 1.0, 1.0, defaultAlpha.g);
    fixed4 layer2 = tex2D(_Splat2, uv2) * half4(1.0, 1.0, 1.0, defaultAlpha.b);
    fixed4 layer3 = tex2D(_Splat3, uv3) * half4(1.0, 1.0, 1.0, defaultAlpha.a);
    mixedDiffuse = splat_control.r * layer0 + splat_control.g * layer1
                 + splat_control.b * layer2 + splat_control.a * layer3;
#if defined(_NORMALMAP)
    fixed3 n0 = UnpackNormalWithScale(tex2D(_Normal0, uv0), _NormalScale0);
    fixed3 n1 = UnpackNormalWithScale(tex2D(_Normal1, uv1), _NormalScale1);
    fixed3 n2 = UnpackNormalWithScale(tex2D(_Normal2, uv2), _NormalScale2);
    fixed3 n3 = UnpackNormalWithScale(tex2D(_Normal3, uv3), _NormalScale3);
    mixedNormal = n0 * splat_control.r + n1 * splat_control.g + n2 * splat_control.b + n3 * splat_control.a;
    mixedNormal.z += 1e-5;   // Unity's: keeps a zero mix normalisable
#endif
}

#if defined(TERRAIN_STANDARD_SHADER)
void SplatmapMix(Input IN, half4 defaultAlpha, out half4 splat_control, out half weight,
                 out fixed4 mixedDiffuse, inout fixed3 mixedNormal)
{
    PbrlabSplatmapMixCore(IN, defaultAlpha, splat_control, weight, mixedDiffuse, mixedNormal);
}
#else
// The legacy (Lambert / BlinnPhong) terrain keeps each layer's alpha as it is.
void SplatmapMix(Input IN, out half4 splat_control, out half weight, out fixed4 mixedDiffuse,
                 inout fixed3 mixedNormal)
{
    PbrlabSplatmapMixCore(IN, half4(1.0, 1.0, 1.0, 1.0), splat_control, weight, mixedDiffuse, mixedNormal);
}
#endif

#ifndef TERRAIN_SURFACE_OUTPUT
#define TERRAIN_SURFACE_OUTPUT SurfaceOutput
#endif

// The lit colour weighted back by the control map's sum (TerrainSplatmapCommon.cginc,
// SplatmapFinalColor; Unity also applies fog here, which the harness has not).
void SplatmapFinalColor(Input IN, TERRAIN_SURFACE_OUTPUT o, inout fixed4 color)
{
    color *= o.Alpha;
}

void SplatmapFinalPrepass(Input IN, TERRAIN_SURFACE_OUTPUT o, inout fixed4 normalSpec)
{
    normalSpec *= o.Alpha;
}

void SplatmapFinalGBuffer(Input IN, TERRAIN_SURFACE_OUTPUT o, inout half4 outGBuffer0, inout half4 outGBuffer1,
                          inout half4 outGBuffer2, inout half4 emission)
{
    outGBuffer0 *= o.Alpha;
    outGBuffer1 *= o.Alpha;
    outGBuffer2 *= o.Alpha;
    emission *= o.Alpha;
}

#endif // TERRAIN_BASE_PASS

#endif
