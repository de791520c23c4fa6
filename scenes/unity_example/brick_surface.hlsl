// The Unity surface function of brick_surface.glsl, ported to pbrlab's HLSL: here the port
// keeps Unity's own types (fixed4, half, half3: pbr/common/shim.hlsl defines fixed* where
// Unity has not) and Direct3D 11 texture macros (UNITY_DECLARE_TEX2D, UNITY_SAMPLE_TEX2D,
// which Unity's HLSLSupport.cginc defines and the harness's scene_shading.hlsl stands in
// for); tex2D becomes UNITY_SAMPLE_TEX2D and IN.uv_MainTex becomes IN.uv, nothing else
// changes. `pbrlab render --language hlsl` (or render_scene(..., language="hlsl")) uses
// this file in place of brick_surface.glsl; tests/gpu/hlsl/test_scene_renders.py checks the
// two render the same image.
UNITY_DECLARE_TEX2D(_MainTex);
UNITY_DECLARE_TEX2D(_BumpMap);
UNITY_DECLARE_TEX2D(_MetallicGlossMap);
UNITY_DECLARE_TEX2D(_EmissionMap);

static const fixed4 _Color = fixed4(1.0, 1.0, 1.0, 1.0);
static const half _Glossiness = 0.9;
static const half3 _EmissionColor = half3(4.0, 4.0, 4.0);

void surf(Input IN, inout SurfaceOutputStandard o) {
    fixed4 c = UNITY_SAMPLE_TEX2D(_MainTex, IN.uv) * _Color;
    o.Albedo = c.rgb;
    fixed4 mg = UNITY_SAMPLE_TEX2D(_MetallicGlossMap, IN.uv);
    o.Metallic = mg.r;
    o.Smoothness = mg.a * _Glossiness;
    o.Normal = UnpackNormal(UNITY_SAMPLE_TEX2D(_BumpMap, IN.uv));
    o.Emission = UNITY_SAMPLE_TEX2D(_EmissionMap, IN.uv).rgb * _EmissionColor;
    o.Alpha = c.a;
}
