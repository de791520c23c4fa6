// pbrlab's own include (no URP file of this name): what the stand-ins UnlitPass.hlsl and
// PBRForwardPass.hlsl share, the vertex function and the fragment's start (the graph's
// surface description from the interpolated varyings, the alpha clip, the pass's alpha:
// blended or clipped passes, and Shader Graph before URP 10, keep the graph's Alpha; an
// opaque pass writes 1).
#ifndef PBRLAB_URP_SG_GRAPH_PASS_HLSL
#define PBRLAB_URP_SG_GRAPH_PASS_HLSL

PackedVaryings vert(Attributes input)
{
    Varyings output = BuildVaryings(input);
    return PackVaryings(output);
}

SurfaceDescription pbrlab_graph_surface(PackedVaryings packedInput, out Varyings unpacked, out float alpha)
{
    unpacked = UnpackVaryings(packedInput);
    SurfaceDescriptionInputs surfaceDescriptionInputs = BuildSurfaceDescriptionInputs(unpacked);
    SurfaceDescription surfaceDescription = SurfaceDescriptionFunction(surfaceDescriptionInputs);
#if defined(_AlphaClip) || defined(_ALPHATEST_ON)
    clip(surfaceDescription.Alpha - surfaceDescription.AlphaClipThreshold);
#endif
#if defined(_AlphaClip) || defined(_ALPHATEST_ON) || defined(_SURFACE_TYPE_TRANSPARENT) || !defined(SHADERPASS)
    alpha = surfaceDescription.Alpha;
#else
    alpha = 1.0;
#endif
    return surfaceDescription;
}

#endif
