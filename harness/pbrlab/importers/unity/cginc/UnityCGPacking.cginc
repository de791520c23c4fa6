// pbrlab stand-in for the packing helpers and depth-texture macros of Unity's UnityCG.cginc and
// HLSLSupport.cginc that the harness's UnityCG (glsl/unity_compat/shader_variables.glsl) lacks;
// UnityCG.cginc's stand-in includes this file.
//
// Provides: SAMPLE_RAW_DEPTH_TEXTURE(tex, uv), SAMPLE_RAW_DEPTH_TEXTURE_PROJ(tex, uv),
//   SAMPLE_RAW_DEPTH_TEXTURE_LOD(tex, uv) (every channel of the sample, where
//   SAMPLE_DEPTH_TEXTURE keeps red); EncodeFloatRG(v), DecodeFloatRG(enc), EncodeFloatRGBA(v),
//   DecodeFloatRGBA(enc); EncodeViewNormalStereo(n), DecodeViewNormalStereo(enc4);
//   EncodeDepthNormal(depth01, viewNormal), DecodeDepthNormal(enc, out depth, out normal);
//   UnpackHeightmap(texel), PackHeightmap(height); UnityObjectToClipPosODS(pos);
//   CBUFFER_START(name) / CBUFFER_END (empty: plain globals, as Unity's GL targets);
//   UNITY_DECLARE_DEPTH_TEXTURE_MS(tex) (a plain depth texture, as on Unity's GL targets);
//   UNITY_VPOS_TYPE (float4: the type of a fragment input with the VPOS semantic);
//   UNITY_TRANSFER_DEPTH(o) (nothing) and UNITY_OUTPUT_DEPTH(i) (return 0), UnityCG's legacy
//   depth macros as Unity defines them now that every platform has native depth textures.
// Unity's file: the same names (UnityCG.cginc and HLSLSupport.cginc, Unity 2019.4 built-in
//   shaders; the encodings are the ones Unity's manual describes for _CameraDepthNormalsTexture:
//   "depth and view space normals packed into one texture", normals stereographically
//   projected into two 8-bit channels, depth into two), read for their behaviour and written
//   here anew.
// Differences: none in the maths. UnpackHeightmap/PackHeightmap take Unity's path for APIs with
//   guaranteed 16-bit red textures (desktop GL and D3D11: the height is red alone); the 8-bit
//   two-channel path of GLES/Vulkan is not the one the harness's GL runs. UnityObjectToClipPosODS
//   is Unity's mono path (STEREO_CUBEMAP_RENDER_ON, the omni-directional stereo capture, is not a
//   keyword the harness sets): the object position to clip space, as UnityObjectToClipPos.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_CG_PACKING_CGINC
#define PBRLAB_UNITY_CG_PACKING_CGINC

// HLSLSupport.cginc's constant-buffer brackets: on GL (and in one program with no SRP batcher)
// a named buffer is plain globals, which is how Unity spells it for its GL targets.
#ifndef CBUFFER_START
#define CBUFFER_START(name)
#define CBUFFER_END
#endif

// HLSLSupport.cginc's multisampled depth texture: a Texture2DMS on the APIs whose variant reads
// samples (SHADER_API_D3D11 and its kin); the harness compiles as Unity's other targets do,
// where the declaration is a plain depth texture (and Unity's own shaders that declare one
// read it only under SHADER_API_D3D11).
#define UNITY_DECLARE_DEPTH_TEXTURE_MS(tex) uniform sampler2D tex

// HLSLSupport.cginc: VPOS's type, float4 (x, y the pixel's window position, as SV_POSITION in a
// fragment) on every target but Direct3D 9, where it was float2.
#ifndef UNITY_VPOS_TYPE
#define UNITY_VPOS_TYPE float4
#endif

// UnityCG.cginc's legacy depth macros, kept by Unity for old shaders: they once wrote depth into
// a colour target on platforms without depth textures. Unity now defines the first as nothing
// and the second as ``return 0`` (the fragment returns 0, which a shader that renders its own
// depth texture draws as black with alpha 0).
#define UNITY_TRANSFER_DEPTH(o)
#define UNITY_OUTPUT_DEPTH(i) return 0

// A depth texture read whole: the raw texel (a blit copies every channel it stores). Functions,
// not Unity's macros, so that the GLSL port's type pass sees a float4 (a shader that assigns it
// to a float, as HLSL truncates, is ported with the truncation).
float4 SAMPLE_RAW_DEPTH_TEXTURE(sampler2D tex, float2 uv)
{
    return tex2D(tex, uv);
}

float4 SAMPLE_RAW_DEPTH_TEXTURE_PROJ(sampler2D tex, float4 uv)
{
    return tex2Dproj(tex, uv);
}

float4 SAMPLE_RAW_DEPTH_TEXTURE_LOD(sampler2D tex, float4 uv)
{
    return tex2Dlod(tex, uv);
}

// A value in [0, 1) as two 8-bit channels: x keeps v's fraction, y the fraction of 255 v (the
// next 8 bits); x then loses the part y carries, so x + y / 255 = v exactly (before rounding
// to 8 bits) and each channel stays in [0, 1).
float2 EncodeFloatRG(float v)
{
    float2 enc = frac(float2(1.0, 255.0) * v);
    enc.x -= enc.y * (1.0 / 255.0);
    return enc;
}

// The inverse: x + y / 255.
float DecodeFloatRG(float2 enc)
{
    return dot(enc, float2(1.0, 1.0 / 255.0));
}

// The same in four channels, each the fraction of v times a further power of 255.
float4 EncodeFloatRGBA(float v)
{
    float4 enc = frac(float4(1.0, 255.0, 65025.0, 16581375.0) * v);
    enc -= enc.yzww * float4(1.0 / 255.0, 1.0 / 255.0, 1.0 / 255.0, 0.0);
    return enc;
}

float DecodeFloatRGBA(float4 enc)
{
    return dot(enc, float4(1.0, 1.0 / 255.0, 1.0 / 65025.0, 1.0 / 16581375.0));
}

// A unit view-space normal facing the camera (z > -1) as two [0, 1] numbers: its stereographic
// projection from (0, 0, -1), n.xy / (1 + n.z), scaled by 1 / 1.7777 (the span that the normals
// a camera sees reach) and mapped from [-1, 1] to [0, 1]. A float2, as Unity's (a program
// writes float4(EncodeViewNormalStereo(n), 0, 0)).
float2 EncodeViewNormalStereo(float3 n)
{
    const float kScale = 1.7777;
    float2 enc = n.xy / (n.z + 1.0);
    enc /= kScale;
    enc = enc * 0.5 + 0.5;
    return enc;
}

// The inverse projection: p = the scaled point back in [-kScale, kScale]^2 with z = 1 (as
// (p, 1)); the unit normal is (2 p, 2 - |(p, 1)|^2) / |(p, 1)|^2, i.e. g = 2 / |(p, 1)|^2 gives
// n.xy = g p, n.z = g - 1.
float3 DecodeViewNormalStereo(float4 enc4)
{
    const float kScale = 1.7777;
    float3 nn = enc4.xyz * float3(2.0 * kScale, 2.0 * kScale, 0.0) + float3(-kScale, -kScale, 1.0);
    float g = 2.0 / dot(nn.xyz, nn.xyz);
    float3 n;
    n.xy = g * nn.xy;
    n.z = g - 1.0;
    return n;
}

// _CameraDepthNormalsTexture's texel: the view normal in xy (EncodeViewNormalStereo), the
// [0, 1] linear depth in zw (EncodeFloatRG).
float4 EncodeDepthNormal(float depth, float3 normal)
{
    float4 enc;
    enc.xy = EncodeViewNormalStereo(normal);
    enc.zw = EncodeFloatRG(depth);
    return enc;
}

void DecodeDepthNormal(float4 enc, out float depth, out float3 normal)
{
    depth = DecodeFloatRG(enc.zw);
    normal = DecodeViewNormalStereo(enc);
}

// A terrain heightmap texel's height in [0, 1]: its red channel (a 16-bit R16 texture where
// the API guarantees one), and back.
float UnpackHeightmap(float4 height)
{
    return height.r;
}

float4 PackHeightmap(float height)
{
    return float4(height, 0.0, 0.0, 0.0);
}

// The omni-directional stereo clip position, mono: world position through the view-projection.
float4 UnityObjectToClipPosODS(float3 inPos)
{
    float3 posWorld = mul(unity_ObjectToWorld, float4(inPos, 1.0)).xyz;
    return mul(UNITY_MATRIX_VP, float4(posWorld, 1.0));
}

#endif
