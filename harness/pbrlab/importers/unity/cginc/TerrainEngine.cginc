// pbrlab stand-in for Unity's TerrainEngine.cginc (terrain grass, tree and billboard helpers:
// TerrainShaders/Details/*, Nature/TreeCreator/*, TerrainShaders/Trees/*).
//
// Provides: the terrain globals (_WavingTint, _WaveAndDistance, _CameraPosition, _CameraRight,
//   _CameraUp, _TreeInstanceColor, _TreeInstanceScale, _TerrainEngineBendTree,
//   _SquashPlaneNormal, _SquashAmount, _TreeBillboardCamera*, _TreeBillboardDistances, _Wind),
//   appdata_tree, appdata_tree_billboard, FastSinCos, TerrainWaveGrass, TerrainBillboardGrass,
//   WavingGrassVert, WavingGrassBillboardVert, Squash, TerrainAnimateTree,
//   TerrainBillboardTree, ExpandBillboard, SmoothCurve, TriangleWave, SmoothTriangleWave,
//   AnimateVertex.
// Unity's file: the same names (TerrainEngine.cginc, Unity 2019.4 built-in shaders), read for
//   their behaviour and written here anew.
// Differences, and why: every one of these globals is set by Unity's terrain engine or a
//   WindZone, per terrain, tree instance or camera; pbrlab has none of them, so the helpers
//   draw the REST POSE, without wind:
//   * grass (TerrainWaveGrass): no sway (Unity's wind strength _WaveAndDistance.z taken as 0),
//     the waving tint at its no-wave value (Unity's 2 lerp(0.5, _WavingTint, wave) with wave
//     0 is 1: the vertex colour unchanged) and no fade with distance (Unity fades by the
//     camera's distance the terrain sets in _CameraPosition.w: alpha is kept);
//   * grass billboards (TerrainBillboardGrass): not expanded (Unity extrudes the quad the
//     terrain builds along its camera vectors; pbrlab's meshes carry real tangents, not
//     terrain extrusions, so the mesh is drawn as it is);
//   * trees (TerrainAnimateTree, Squash): scale 1, no bend, no squash (Unity's instance
//     scale, bend matrix and squash plane are per instance);
//   * AnimateVertex (Tree Creator wind): Unity's formula with _Wind, a WindZone's global,
//     which nothing here sets: 0, so the vertex stays where it is;
//   * TerrainBillboardTree: not expanded, as grass billboards.
//   The globals are still declared (a shader's Properties may list them: WavingGrass's
//   _WavingTint and _WaveAndDistance bind and have no effect here).
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_TERRAIN_ENGINE_CGINC
#define PBRLAB_TERRAIN_ENGINE_CGINC

// grass
fixed4 _WavingTint;
float4 _WaveAndDistance;   // wind speed, wave size, wind amount, max squared distance
float4 _CameraPosition;    // xyz camera position, w 1 / max squared distance
float3 _CameraRight;
float3 _CameraUp;
// trees
fixed4 _TreeInstanceColor;
float4 _TreeInstanceScale;
float4x4 _TerrainEngineBendTree;
float4 _SquashPlaneNormal;
float _SquashAmount;
// billboards
float3 _TreeBillboardCameraRight;
float4 _TreeBillboardCameraUp;
float4 _TreeBillboardCameraFront;
float4 _TreeBillboardCameraPos;
float4 _TreeBillboardDistances;
// Tree Creator wind (xyz direction times strength, w its amount): a WindZone's, 0 here
float4 _Wind;

struct appdata_tree
{
    float4 vertex : POSITION;
    float4 tangent : TANGENT;    // Unity: directional ambient occlusion
    float3 normal : NORMAL;
    fixed4 color : COLOR;        // w: bend factor
    float4 texcoord : TEXCOORD0;
};

struct appdata_tree_billboard
{
    float4 vertex : POSITION;
    fixed4 color : COLOR;
    float4 texcoord : TEXCOORD0;
    float2 texcoord1 : TEXCOORD1;   // the billboard's extrusion
};

// Sine and cosine of 2 pi val - pi for val in [0, 1], by Unity's odd and even Taylor
// polynomials (TerrainEngine.cginc, FastSinCos; its coefficients as Unity wrote them, the
// sine's 1/3! rounded to 0.16161616).
void FastSinCos(float4 val, out float4 s, out float4 c)
{
    float4 x = val * 6.408849 - 3.1415927;
    float4 x2 = x * x;
    float4 x3 = x2 * x;
    float4 x4 = x2 * x2;
    float4 x5 = x3 * x2;
    float4 x6 = x4 * x2;
    float4 x7 = x5 * x2;
    s = x - 0.16161616 * x3 + 0.0083333 * x5 - 0.00019841 * x7;
    // Unity's "r8" is x^6 again, not x^8: its last term is kept as written
    c = 1.0 - 0.5 * x2 + 0.041666666 * x4 - 0.0013888889 * x6 + 0.000024801587 * x6;
}

// The rest pose of Unity's waving grass (header): position unchanged, colour 2 * 0.5 * rgb,
// alpha kept (TerrainEngine.cginc, TerrainWaveGrass: sway by the wind amount, tint by the wave,
// fade by the camera's distance).
fixed4 TerrainWaveGrass(inout float4 vertex, float waveAmount, fixed4 color)
{
    fixed3 noWaveTint = fixed3(0.5, 0.5, 0.5);   // lerp(0.5, _WavingTint, wave) at wave 0
    return fixed4(2.0 * noWaveTint * color.rgb, color.a);
}

// Unity extrudes a grass billboard along the camera's right and up vectors; pbrlab draws
// the mesh as it is (header).
void TerrainBillboardGrass(inout float4 pos, float2 offset)
{
}

// Grass: Unity's wave amount is the vertex colour's alpha times the wind amount.
void WavingGrassVert(inout appdata_full v)
{
    float waveAmount = 0.0;   // the wind amount _WaveAndDistance.z, 0 here (header)
    v.color = TerrainWaveGrass(v.vertex, waveAmount, v.color);
}

void WavingGrassBillboardVert(inout appdata_full v)
{
    TerrainBillboardGrass(v.vertex, v.tangent.xy);
    float waveAmount = 0.0;   // Unity: the grass height v.tangent.y, times the wind (header)
    v.color = TerrainWaveGrass(v.vertex, waveAmount, v.color);
}

// Unity pushes a squashed tree towards its squash plane by 1 - _SquashAmount; a tree not
// being squashed (amount 1) is unchanged, which is what pbrlab draws (header).
float4 Squash(float4 pos)
{
    return float4(pos.xyz, 1.0);
}

// Unity scales by the instance scale and bends by the engine's bend matrix; the rest pose
// is the model as it is (header).
void TerrainAnimateTree(inout float4 pos, float alpha)
{
    pos = Squash(pos);
}

// Unity moves a tree billboard's vertices along its camera vectors (header): not here.
void TerrainBillboardTree(inout float4 pos, float2 offset, float offsetz)
{
}

// A billboard leaf (tangent.w = 0) is turned to face the camera with the matrix mat (Unity:
// UNITY_MATRIX_IT_MV); other vertices (|tangent.w| = 1) are unchanged
// (TerrainEngine.cginc, ExpandBillboard).
void ExpandBillboard(float4x4 mat, inout float4 pos, inout float3 normal, inout float4 tangent)
{
    float isBillboard = 1.0 - abs(tangent.w);
    float3 billboardNormal = normalize(mul(float4(normal, 0.0), mat).xyz);
    float3 billboardTangent = normalize(mul(float4(tangent.xyz, 0.0), mat).xyz);
    pos = pos + mul(float4(normal.xy, 0.0, 0.0), mat) * isBillboard;
    normal = lerp(normal, billboardNormal, float3(isBillboard, isBillboard, isBillboard));
    tangent = lerp(tangent, float4(billboardTangent, -1.0), float4(isBillboard, isBillboard, isBillboard, isBillboard));
}

// Hermite smoothstep of x in [0, 1], a triangle wave of period 1, and the two composed
// (TerrainEngine.cginc).
float4 SmoothCurve(float4 x)
{
    return x * x * (3.0 - 2.0 * x);
}

float4 TriangleWave(float4 x)
{
    return abs(frac(x + 0.5) * 2.0 - 1.0);
}

float4 SmoothTriangleWave(float4 x)
{
    return SmoothCurve(TriangleWave(x));
}

// Tree Creator wind: edge flutter and branch bending by smoothed triangle waves in _Time,
// plus the primary bend along the wind; every term is scaled by _Wind, which is 0 here, so
// pos comes back unchanged (TerrainEngine.cginc, AnimateVertex; animParams: x branch phase,
// y edge flutter, z primary factor, w secondary factor).
float4 AnimateVertex(float4 pos, float3 normal, float4 animParams)
{
    float detailAmplitude = 0.1;   // Unity's fDetailAmp
    float branchAmplitude = 0.3;   // Unity's fBranchAmp
    float4 objectOrigin = mul(unity_ObjectToWorld, float4(0.0, 0.0, 0.0, 1.0));
    float objectPhase = dot(objectOrigin.xyz, float3(1.0, 1.0, 1.0));
    float branchPhase = objectPhase + animParams.x;
    float vertexPhase = dot(pos.xyz, float3(1.0, 1.0, 1.0) * (animParams.y + branchPhase));
    float2 wavesIn = float2(_Time.y, _Time.y) + float2(vertexPhase, branchPhase);
    float4 waves = frac(float4(wavesIn.x, wavesIn.x, wavesIn.y, wavesIn.y)
                        * float4(1.975, 0.793, 0.375, 0.193)) * 2.0 - 1.0;
    waves = SmoothTriangleWave(waves);
    float2 wavesSum = waves.xz + waves.yw;
    float3 bend = animParams.y * detailAmplitude * normal;
    bend.y = animParams.w * branchAmplitude;
    float3 flutter = float3(wavesSum.x, wavesSum.y, wavesSum.x) * bend + _Wind.xyz * wavesSum.y * animParams.w;
    float3 moved = pos.xyz + flutter * _Wind.w + animParams.z * _Wind.xyz;
    return float4(moved, pos.w);
}

#endif
