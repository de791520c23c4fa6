// pbrlab stand-in for URP's ShaderLibrary/ProbeVolumeVariants.hlsl, a keywords file a pass
// includes with #include_with_pragmas: in URP it declares the adaptive probe volumes' variants
// PROBE_VOLUMES_OFF, PROBE_VOLUMES_L1 and PROBE_VOLUMES_L2 (written for pbrlab from Unity's
// documentation of the names; URP's own file is under the Unity Companion License and is not
// copied). pbrlab's scenes have no probe volumes: neither L1 nor L2 is on, and ambient light is
// the spherical harmonics' (GlobalIllumination.hlsl), as in URP's PROBE_VOLUMES_OFF variant.
#ifndef PBRLAB_URP_PROBE_VOLUME_VARIANTS_HLSL
#define PBRLAB_URP_PROBE_VOLUME_VARIANTS_HLSL
#endif
