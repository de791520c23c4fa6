// pbrlab stand-in for Unity's UnityUI.cginc (the UI shaders' helpers: UI/UI-Default,
// UI-Lit-*, UI-Unlit-*).
//
// Provides: UnityGet2DClipping(position, clipRect), UnityGetUIDiffuseColor(uv, mainTex,
//   alphaTex, textureSampleAdd), UIGammaToLinear(value).
// Unity's file: the first two functions (UnityUI.cginc, Unity 2019.4 built-in shaders), read for
//   their behaviour and written here anew; UIGammaToLinear is Unity 2020's addition (TextMesh
//   Pro's shaders of that version call it).
// Differences: none in the maths of the first two. UIGammaToLinear here is the sRGB decode
//   itself (IEC 61966-2-1, UnityCG's GammaToLinearSpaceExact per channel), where Unity fits the
//   same curve with a polynomial of its own (its coefficients are not reproduced here).
//   In Unity the canvas enables UNITY_UI_CLIP_RECT (a
//   RectMask2D) and sets _ClipRect; in pbrlab a material enables the keyword itself
//   ("keywords": ["UNITY_UI_CLIP_RECT"]) and gives _ClipRect as a Vector property
//   (README, "Unity shaders"). Without the keyword, Unity's default variant, nothing
//   is clipped.
// Cg text in the plain subset harness/pbrlab/importers/unity/port.py ports to GLSL.
#ifndef PBRLAB_UNITY_UI_CGINC
#define PBRLAB_UNITY_UI_CGINC

// 1 inside the rectangle clipRect = (xmin, ymin, xmax, ymax), edges included, 0 outside
// (UnityUI.cginc: step on each side, both axes multiplied).
float UnityGet2DClipping(float2 position, float4 clipRect)
{
    float2 aboveMin = step(clipRect.xy, position);
    float2 belowMax = step(position, clipRect.zw);
    float2 inside = aboveMin * belowMax;
    return inside.x * inside.y;
}

// The colour of the main texture plus the add colour's rgb, and alpha from the red channel of
// the separate alpha texture plus the add colour's alpha (UnityUI.cginc; the ETC1 path).
fixed4 UnityGetUIDiffuseColor(float2 position, sampler2D mainTexture, sampler2D alphaTexture,
                              fixed4 textureSampleAdd)
{
    fixed3 rgb = tex2D(mainTexture, position).rgb + textureSampleAdd.rgb;
    fixed alpha = tex2D(alphaTexture, position).r + textureSampleAdd.a;
    return fixed4(rgb, alpha);
}

// A UI vertex colour given in gamma space (sRGB-encoded) -> linear: the sRGB decode of each
// channel (UnityCG.cginc's GammaToLinearSpaceExact).
half3 UIGammaToLinear(half3 value)
{
    return half3(GammaToLinearSpaceExact(value.r), GammaToLinearSpaceExact(value.g),
                 GammaToLinearSpaceExact(value.b));
}

#endif
