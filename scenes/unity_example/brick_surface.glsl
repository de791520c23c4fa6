// A Unity surface function ported to pbrlab. The Unity original (Standard shader model):
//
//     sampler2D _MainTex, _BumpMap, _MetallicGlossMap, _EmissionMap;
//     fixed4 _Color; half _Glossiness; half3 _EmissionColor;
//     struct Input { float2 uv_MainTex; };
//     void surf (Input IN, inout SurfaceOutputStandard o) {
//         fixed4 c = tex2D(_MainTex, IN.uv_MainTex) * _Color;
//         o.Albedo = c.rgb;
//         fixed4 mg = tex2D(_MetallicGlossMap, IN.uv_MainTex);
//         o.Metallic = mg.r;
//         o.Smoothness = mg.a * _Glossiness;
//         o.Normal = UnpackNormal(tex2D(_BumpMap, IN.uv_MainTex));
//         o.Emission = tex2D(_EmissionMap, IN.uv_MainTex).rgb * _EmissionColor;
//         o.Alpha = c.a;
//     }
//
// The port renames types (fixed4/half3 -> vec4/vec3), tex2D -> texture, and the one UV
// set IN.uv_MainTex -> IN.uv; the body is otherwise line for line the same. The harness
// binds each sampler from the scene's "textures" (sRGB colour or linear data).
uniform sampler2D _MainTex;
uniform sampler2D _BumpMap;
uniform sampler2D _MetallicGlossMap;
uniform sampler2D _EmissionMap;

const vec4 _Color = vec4(1.0, 1.0, 1.0, 1.0);
const float _Glossiness = 0.9;
const vec3 _EmissionColor = vec3(4.0, 4.0, 4.0);

void surf(Input IN, inout SurfaceOutputStandard o) {
    vec4 c = texture(_MainTex, IN.uv) * _Color;
    o.Albedo = c.rgb;
    vec4 mg = texture(_MetallicGlossMap, IN.uv);
    o.Metallic = mg.r;
    o.Smoothness = mg.a * _Glossiness;
    o.Normal = UnpackNormal(texture(_BumpMap, IN.uv));
    o.Emission = texture(_EmissionMap, IN.uv).rgb * _EmissionColor;
    o.Alpha = c.a;
}
