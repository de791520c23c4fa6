// pbrlab stand-in for Unity's AutoLight.cginc: the names a surface shader reads from it are
// already included by the generated program (harness/pbrlab/importers/unity/generate.py; README,
// "Unity shaders", lists them). Declared here: the forward pass's light textures and matrix a
// program samples itself (Unity Shaders Book style forward-add passes), which Unity's file
// declares for its light keywords: _LightTexture0 and _LightTextureB0 (white: the light's
// falloff is in _LightColor0 already) and unity_WorldToLight, filled by the entry points for
// the pass's light (importers/unity/light_space.py).
#ifndef PBRLAB_AUTOLIGHT_CGINC
#define PBRLAB_AUTOLIGHT_CGINC
// The attenuation texture's channel (HLSLSupport.cginc's: red on desktop GL and Direct3D 11).
#ifndef UNITY_ATTEN_CHANNEL
#define UNITY_ATTEN_CHANNEL r
#endif
sampler2D _LightTexture0;
sampler2D _LightTextureB0;
static float4x4 unity_WorldToLight;
#endif
