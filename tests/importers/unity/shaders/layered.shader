Shader "pbrlab tests/Layered" {
// ShaderLab as Unity accepts it: type names in any case, attributes on their own line, a
// three-component colour, several properties on one line, a CGINCLUDE holding the surface
// function, a first SubShader this harness cannot run (a fixed-function pass with a texture
// matrix) and a second
// that it can.
Properties {
    [Header(Colours)]
    [HDR]
    _Tint ("Tint", color) = (0.5, 0.25, 1)
    _Gain ("Gain", float) = 2 _Bias ("Bias", RANGE(0, 1)) = 0.125
    [NoScaleOffset] _MainTex ("Base", 2d) = "white" {}
}
CGINCLUDE
fixed3 _Tint;
float _Gain, _Bias;
struct Input { float3 worldPos; };
void surf(Input IN, inout SurfaceOutput o) { o.Emission = _Tint * _Gain + _Bias; o.Albedo = 0; }
ENDCG
SubShader {
    Pass { SetTexture [_MainTex] { matrix [_Tint] combine texture } }
}
SubShader {
    LOD 200
    CGPROGRAM
    #pragma surface surf Lambert
    ENDCG
}
}
