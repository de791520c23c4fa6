// pbrlab stand-in for Core RP's ShaderLibrary/FoveatedRenderingKeywords.hlsl, which Shader
// Graph's and Amplify Shader Editor's generated passes include with #include_with_pragmas
// (written for pbrlab from Unity's documentation of foveated rendering; Core RP's own file is
// under the Unity Companion License and is not copied). Its one keyword,
// _FOVEATED_RENDERING_NON_UNIFORM_RASTER, is declared for the PlayStation 5's and Metal's APIs
// only; pbrlab renders one uniform view (FoveatedRendering.hlsl): nothing here.
#ifndef PBRLAB_CORE_RP_FOVEATED_RENDERING_KEYWORDS_HLSL
#define PBRLAB_CORE_RP_FOVEATED_RENDERING_KEYWORDS_HLSL
#endif
