// pbrlab harness: the surface function of scene materials without a `surface` file.
// Material numbers arrive as uniforms; emission, occlusion and alpha are compiled in only
// when the material can show them (PBRLAB_EMISSION, _OCCLUSION, _ALPHA: features.py), each
// texture slot only when the material has it: colour maps (albedo, emission) are sRGB textures decoded by the
// hardware, data maps (metallic_smoothness, normal, occlusion) are linear.
uniform vec3 u_albedo;
uniform vec3 u_specular;
uniform float u_metallic;
uniform float u_smoothness;
#ifdef PBRLAB_EMISSION
uniform vec3 u_emission;
#endif
#ifdef PBRLAB_OCCLUSION
uniform float u_occlusion;
#endif
#ifdef PBRLAB_ALPHA
uniform float u_alpha;
#endif
#ifdef PBRLAB_ALBEDO_MAP
uniform sampler2D u_albedo_map;
#endif
#ifdef PBRLAB_METALLIC_SMOOTHNESS_MAP
uniform sampler2D u_metallic_smoothness_map;  // Unity's packing: R metallic, A smoothness
#endif
#ifdef PBRLAB_NORMAL_MAP
uniform sampler2D u_normal_map;               // tangent space, RGB = xyz * 0.5 + 0.5
#endif
#ifdef PBRLAB_EMISSION_MAP
uniform sampler2D u_emission_map;
#endif
#ifdef PBRLAB_OCCLUSION_MAP
uniform sampler2D u_occlusion_map;            // R channel (Unity's _OcclusionMap .g also works: grey)
#endif

void surf(Input IN, inout PbrlabSurfaceOutput o) {
    vec4 albedo = vec4(u_albedo, 1.0);
#ifdef PBRLAB_ALPHA
    albedo.a = u_alpha;
#endif
#ifdef PBRLAB_ALBEDO_MAP
    albedo *= texture(u_albedo_map, IN.uv);
#endif
    o.Albedo = albedo.rgb;
#ifdef PBRLAB_ALPHA
    o.Alpha = albedo.a;
#endif
    float smoothness = u_smoothness;
#ifdef PBRLAB_WORKFLOW_SPECULAR
    o.Specular = u_specular;
#else
    float metallic = u_metallic;
#ifdef PBRLAB_METALLIC_SMOOTHNESS_MAP
    vec4 ms = texture(u_metallic_smoothness_map, IN.uv);
    metallic *= ms.r;
    smoothness *= ms.a;
#endif
    o.Metallic = metallic;
#endif
    o.Smoothness = smoothness;
#ifdef PBRLAB_EMISSION
    o.Emission = u_emission;
#ifdef PBRLAB_EMISSION_MAP
    o.Emission *= texture(u_emission_map, IN.uv).rgb;
#endif
#endif
#ifdef PBRLAB_OCCLUSION
    o.Occlusion = u_occlusion;
#ifdef PBRLAB_OCCLUSION_MAP
    o.Occlusion *= texture(u_occlusion_map, IN.uv).r;
#endif
#endif
#ifdef PBRLAB_NORMAL_MAP
    o.Normal = UnpackNormal(texture(u_normal_map, IN.uv));
#endif
}
