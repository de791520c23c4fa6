// pbrlab stand-in for Core RP's ShaderLibrary/Random.hlsl: the hashes and pseudo-random numbers
// URP shaders call, written for pbrlab from the published algorithms each name stands for and
// Unity's documentation of the names (Core RP's own file is under the Unity Companion License).
#ifndef PBRLAB_CORE_RP_RANDOM_HLSL
#define PBRLAB_CORE_RP_RANDOM_HLSL

#ifndef UINT_MAX
#define UINT_MAX 0xFFFFFFFFu
#endif

// Bob Jenkins' one-at-a-time hash, one round on a 32-bit word (Jenkins, "A hash function for hash
// table lookup", Dr. Dobb's 1997: add the word shifted left 10, xor right 6, add left 3, xor right
// 11, add left 15); a vector is hashed from its last component to its first, each component xored
// into the hash of the ones after it.
uint JenkinsHash(uint x) {
    x += x << 10u;
    x ^= x >> 6u;
    x += x << 3u;
    x ^= x >> 11u;
    x += x << 15u;
    return x;
}
uint JenkinsHash(uint2 v) { return JenkinsHash(v.x ^ JenkinsHash(v.y)); }
uint JenkinsHash(uint3 v) { return JenkinsHash(v.x ^ JenkinsHash(uint2(v.y, v.z))); }
uint JenkinsHash(uint4 v) { return JenkinsHash(v.x ^ JenkinsHash(uint3(v.y, v.z, v.w))); }

// A float in [0, 1) from a word's low 23 bits: those bits as the mantissa of a number in [1, 2)
// (IEEE 754 single: exponent bits of 1.0, 0x3F800000), minus 1.
float ConstructFloat(uint m) { return asfloat((m & 0x007FFFFFu) | 0x3F800000u) - 1.0; }
float ConstructFloat(int m) { return ConstructFloat(asuint(m)); }

// A pseudo-random float in [0, 1) from one to four words: their hash made a float.
float GenerateHashedRandomFloat(uint x) { return ConstructFloat(JenkinsHash(x)); }
float GenerateHashedRandomFloat(uint2 v) { return ConstructFloat(JenkinsHash(v)); }
float GenerateHashedRandomFloat(uint3 v) { return ConstructFloat(JenkinsHash(v)); }
float GenerateHashedRandomFloat(uint4 v) { return ConstructFloat(JenkinsHash(v)); }

// A word to [0, 1): xor with 2747636419, then three rounds of a multiply by 2654435769
// (2^32 / golden ratio, Knuth's multiplicative hash), the first two each followed by an xor
// with the word shifted right 16; the word over 2^32.
float Hash(uint s) {
    s = s ^ 2747636419u;
    s = s * 2654435769u;
    s = s ^ (s >> 16u);
    s = s * 2654435769u;
    s = s ^ (s >> 16u);
    s = s * 2654435769u;
    return float(s) * (1.0 / 4294967296.0);
}
// Each component of a [0, 1] pair scaled to a word and hashed.
float2 InitRandom(float2 input) {
    return float2(Hash(uint(input.x * 4294967295.0)), Hash(uint(input.y * 4294967295.0)));
}

// Interleaved gradient noise (Jimenez, "Next Generation Post Processing in Call of Duty: Advanced
// Warfare", SIGGRAPH 2014): frac(52.9829189 frac(dot(pixel, (0.06711056, 0.00583715)))), the
// pixel moved by the frame count times (2.083, 4.867).
float InterleavedGradientNoise(float2 pixCoord, int frameCount) {
    pixCoord += float(frameCount) * float2(2.083, 4.867);
    return frac(52.9829189 * frac(dot(pixCoord, float2(0.06711056, 0.00583715))));
}

// Marsaglia's 32-bit xorshift (Marsaglia, "Xorshift RNGs", J. Stat. Software 2003: shifts 13, 17,
// 5): the state advanced and returned.
uint XorShift(inout uint rngState) {
    rngState ^= rngState << 13u;
    rngState ^= rngState >> 17u;
    rngState ^= rngState << 5u;
    return rngState;
}

#endif
