// The HLSL twin of specular_f90_layers.glsl.
void surf(Input IN, inout SurfaceOutputStandardSpecular o, inout SurfaceOutputStandardLayers layers) {
    o.Albedo = float3(0.8, 0.3, 0.2);
    o.Specular = float3(0.01, 0.01, 0.0);
    o.Smoothness = 0.6;
    layers.SpecularF90 = 0.5;
    layers.Anisotropy = 0.6;
    layers.IridescenceMask = 0.8;
    layers.IridescenceThickness = 500.0;
    layers.Transmission = 0.5;
}
