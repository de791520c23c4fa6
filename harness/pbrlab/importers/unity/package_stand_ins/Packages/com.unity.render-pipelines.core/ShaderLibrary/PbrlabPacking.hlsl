// pbrlab's body of Core RP's Packing.hlsl stand-in, its encodings of a unit vector and of a
// [0, 1] value into texture channels: PackNormalOctQuadEncode / UnpackNormalOctQuadEncode (the
// octahedral map) and PackFloatToR8G8 / UnpackFloatFromR8G8 (16 bits in two 8-bit channels),
// written for pbrlab from Unity's documentation of the names and the papers cited (Core RP's own
// file is under the Unity Companion License and is not copied). Included by the stand-in
// Core.hlsl, so a program that includes Core.hlsl, Common.hlsl or Packing.hlsl reaches them.
#ifndef PBRLAB_CORE_RP_PACKING_BODY_HLSL
#define PBRLAB_CORE_RP_PACKING_BODY_HLSL

// The octahedral map of a direction n (Cigolle et al. 2014, "A Survey of Efficient
// Representations for Independent Unit Vectors", JCGT 3(2), the "oct" encoding): p = n / |n|_1
// (|n|_1 at least 1e-6, Unity's guard for a zero vector); where p.z < 0 the lower hemisphere is
// folded outwards, each of p.xy moved away from 0 by -p.z, its sign kept (0 counted positive),
// which is (1 - |p.y|, 1 - |p.x|) with p.xy's signs. The result is in [-1, 1]^2.
float2 PackNormalOctQuadEncode(float3 n) {
    float3 p = n / max(abs(n.x) + abs(n.y) + abs(n.z), 1e-6);
    float fold = saturate(-p.z);
    return float2(p.x >= 0.0 ? p.x + fold : p.x - fold, p.y >= 0.0 ? p.y + fold : p.y - fold);
}

// Its inverse (the same paper): (f, 1 - |f.x| - |f.y|), the lower hemisphere (z < 0) unfolded by
// moving each of xy towards 0 by -z, normalized.
float3 UnpackNormalOctQuadEncode(float2 f) {
    float3 n = float3(f.x, f.y, 1.0 - abs(f.x) - abs(f.y));
    float fold = max(-n.z, 0.0);
    n.xy = float2(n.x >= 0.0 ? n.x - fold : n.x + fold, n.y >= 0.0 ? n.y - fold : n.y + fold);
    return normalize(n);
}

// A [0, 1] value as a 16-bit integer i = round(65535 f) (Core RP's UnpackShort: f 65535 + 0.5,
// truncated), its low byte and its high byte each as a [0, 1] channel (byte / 255): an 8-bit
// texture's two channels hold f to 1 / 65535.
float2 PackFloatToR8G8(float f) {
    uint i = uint(f * 65535.0 + 0.5);
    return float2(float(i & 255u), float((i >> 8u) & 255u)) / 255.0;
}

// Its inverse: each channel back to its byte (round(255 c)), the 16-bit integer hi 256 + lo, over 65535.
float UnpackFloatFromR8G8(float2 f) {
    uint lo = uint(f.x * 255.0 + 0.5);
    uint hi = uint(f.y * 255.0 + 0.5);
    return saturate(float(hi * 256u + lo) / 65535.0);
}

#endif
