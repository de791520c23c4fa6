// The HLSL twin of dielectric_specular.glsl.
void surf(Input IN, inout SurfaceOutputStandard o, inout SurfaceOutputStandardLayers layers) {
    o.Albedo = float3(0.8, 0.3, 0.2);
    o.Metallic = 0.5;
    o.Smoothness = 0.6;
    layers.DielectricSpecular = float3(0.12, 0.05, 0.0);
    layers.SpecularF90 = 0.6;
}
