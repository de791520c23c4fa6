// pbrlab stand-in for Unity's UnitySprites.cginc (Sprites-Default, Sprites-Diffuse,
// Sprites-Mask and user sprite shaders).
//
// Provides: the uniforms _Color, _RendererColor, _Flip, _EnableExternalAlpha, _MainTex,
//   _AlphaTex; the sprite vertex path's structs appdata_t (POSITION, COLOR, TEXCOORD0) and v2f
//   (SV_POSITION, COLOR, TEXCOORD0); UnityFlipSprite(pos, flip) (float3 and float4 positions),
//   SpriteVert(appdata_t), SampleSpriteTexture(uv), SpriteFrag(v2f).
// Unity's file: the same names (UnitySprites.cginc, Unity 2019.4 built-in shaders), read for
//   their behaviour and written here anew.
// Differences: Unity's SpriteRenderer sets _RendererColor and _Flip per renderer (an
//   instanced array under instancing); here they are ordinary uniforms, set from the
//   material's properties (Sprites-Default/-Diffuse declare them: (1,1,1,1)). PIXELSNAP_ON
//   (UnityPixelSnap) is not supported: the default variant, without it, is what runs.
//   UnityFlipSprite also takes a float4 position (Unity's takes float3 and relies on HLSL's
//   implicit truncation, which GLSL does not have).
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_SPRITES_CGINC
#define PBRLAB_UNITY_SPRITES_CGINC

fixed4 _RendererColor;        // SpriteRenderer.color (Unity: set per renderer)
fixed2 _Flip;                 // SpriteRenderer.flipX/Y as (+1 | -1, +1 | -1)
float _EnableExternalAlpha;   // 1: alpha from _AlphaTex (ETC1_EXTERNAL_ALPHA only)
fixed4 _Color;                // the material's tint
sampler2D _MainTex;
sampler2D _AlphaTex;

struct appdata_t
{
    float4 vertex : POSITION;
    float4 color : COLOR;
    float2 texcoord : TEXCOORD0;
};

struct v2f
{
    float4 vertex : SV_POSITION;
    fixed4 color : COLOR;
    float2 texcoord : TEXCOORD0;
};

// The sprite mirrored in its plane: x and y scaled by flip (+1 or -1), w = 1
// (UnitySprites.cginc, UnityFlipSprite).
float4 UnityFlipSprite(float3 pos, fixed2 flip)
{
    return float4(pos.x * flip.x, pos.y * flip.y, pos.z, 1.0);
}

float4 UnityFlipSprite(float4 pos, fixed2 flip)
{
    return UnityFlipSprite(pos.xyz, flip);
}

// Flip, then to clip space; the vertex colour tinted by the material and the renderer
// (UnitySprites.cginc, SpriteVert).
v2f SpriteVert(appdata_t IN)
{
    v2f OUT;
    float4 flipped = UnityFlipSprite(IN.vertex.xyz, _Flip);
    OUT.vertex = UnityObjectToClipPos(flipped);
    OUT.texcoord = IN.texcoord;
    OUT.color = IN.color * _Color * _RendererColor;
    return OUT;
}

// The sprite's texel; with ETC1_EXTERNAL_ALPHA its alpha blends towards _AlphaTex's red by
// _EnableExternalAlpha (UnitySprites.cginc, SampleSpriteTexture).
fixed4 SampleSpriteTexture(float2 uv)
{
    fixed4 color = tex2D(_MainTex, uv);
#if defined(ETC1_EXTERNAL_ALPHA)
    fixed externalAlpha = tex2D(_AlphaTex, uv).r;
    color.a = lerp(color.a, externalAlpha, _EnableExternalAlpha);
#endif
    return color;
}

// Texel times the interpolated colour, premultiplied by its alpha (Sprites-Default blends
// One OneMinusSrcAlpha) (UnitySprites.cginc, SpriteFrag).
fixed4 SpriteFrag(v2f IN) : SV_Target
{
    fixed4 c = SampleSpriteTexture(IN.texcoord) * IN.color;
    return fixed4(c.rgb * c.a, c.a);
}

#endif
