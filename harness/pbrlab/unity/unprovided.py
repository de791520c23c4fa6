"""Unity names pbrlab does not provide on purpose, each with the engine feature behind it: a
compile error that names one becomes a refusal that says what is missing, instead of a
compiler's "undeclared identifier".

    raise_named(exc, shader_path)   # inside ``except PbrlabError``: re-raise, named if one is known
"""

from __future__ import annotations

import re

from .parse import UnityShaderError

# name -> the Unity feature it belongs to (README, "Unity shaders": what is refused and why).
UNPROVIDED = {
    **dict.fromkeys(("unity_Lightmap", "unity_LightmapST", "unity_LightmapInd", "unity_DynamicLightmap",
                     "unity_DynamicLightmapST", "unity_DynamicDirectionality", "DecodeLightmap",
                     "DecodeDirectionalLightmap", "DecodeRealtimeLightmap", "UNITY_SAMPLE_TEX2D_SAMPLER",
                     "unity_ShadowMask", "UNITY_SAMPLE_SHADOWMASK"),
                    "baked lightmaps, which the harness does not bake"),
    **dict.fromkeys(("UnityMetaVertexPosition", "UnityMetaFragment", "UnityMetaInput",
                     "unity_MetaVertexControl", "unity_MetaFragmentControl"),
                    "the lightmap-baking meta pass"),
    **dict.fromkeys(("unity_4LightPosX0", "unity_4LightPosY0", "unity_4LightPosZ0", "unity_4LightAtten0",
                     "unity_LightColor", "Shade4PointLights", "unity_LightPosition", "unity_LightAtten",
                     "ShadeVertexLights", "ShadeVertexLightsFull", "unity_VertexLightParams"),
                    "Unity's per-vertex lights (the vertex-lit path and Shade4PointLights)"),
    **dict.fromkeys(("_LightTexture0", "_LightTextureB0", "unity_WorldToLight", "_LightMatrix0"),
                    "light cookies and attenuation textures"),
    **dict.fromkeys(("_ShadowMapTexture", "unity_WorldToShadow", "_ShadowCoord", "V2F_SHADOW_CASTER",
                     "TRANSFER_SHADOW_CASTER", "TRANSFER_SHADOW_CASTER_NORMALOFFSET", "SHADOW_CASTER_FRAGMENT",
                     "UnityApplyLinearShadowBias", "UnityClipSpaceShadowCasterPos"),
                    "shadow maps and shadow-caster passes"),
    **dict.fromkeys(("UNITY_DECLARE_TEX2DARRAY", "UNITY_SAMPLE_TEX2DARRAY", "UNITY_DECLARE_TEX3D",
                     "sampler2DArray"),
                    "texture arrays and 3D textures as Unity declares them"),
    **dict.fromkeys(("unity_SpecCube1", "unity_SpecCube0_BoxMax", "unity_SpecCube0_BoxMin",
                     "unity_SpecCube0_ProbePosition", "BoxProjectedCubemapDirection"),
                    "box-projected and blended reflection probes"),
    **dict.fromkeys(("unity_ProbeVolumeSH", "unity_ProbeVolumeWorldToObject", "SHEvalLinearL0L1_SampleProbeVolume"),
                    "light probe proxy volumes"),
    **dict.fromkeys(("_CameraDepthNormalsTexture", "DecodeDepthNormal", "_CameraMotionVectorsTexture",
                     "_CameraGBufferTexture0", "_CameraGBufferTexture1", "_CameraGBufferTexture2"),
                    "the camera's depth-normals, motion-vector and G-buffer textures"),
}
_NAME = re.compile(r"\b(" + "|".join(sorted(UNPROVIDED, key=len, reverse=True)) + r")\b")


def named_missing(message: str):
    """(name, feature) of the first unprovided Unity name an error line mentions, or None."""
    for line in message.splitlines():
        if "error" in line.lower():
            m = _NAME.search(line)
            if m:
                return m.group(1), UNPROVIDED[m.group(1)]
    return None


def raise_named(exc: Exception, path) -> None:
    """Re-raise ``exc`` as a refusal naming the missing Unity feature when its message names one."""
    found = named_missing(str(exc))
    if found is None:
        raise exc
    name, feature = found
    raise UnityShaderError(f"{path}: uses {name}, part of {feature}; pbrlab does not provide it "
                           f"(the compiler's words follow)\n{exc}") from None
