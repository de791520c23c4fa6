// The HLSL twin of every_layer.glsl: the JSON material of
// tests/surface/test_surface_layers.py EVERY_LAYER, field for field.
void surf(Input IN, inout SurfaceOutputStandard o, inout SurfaceOutputStandardLayers layers) {
    o.Albedo = float3(0.8, 0.3, 0.2);
    o.Metallic = 0.25;
    o.Smoothness = 0.4;
    layers.ClearCoatMask = 0.7;
    layers.ClearCoatSmoothness = 0.85;
    layers.SheenColor = float3(0.5, 0.4, 0.9);
    layers.SheenSmoothness = 0.6;
    layers.Anisotropy = 0.6;
    layers.IridescenceMask = 0.8;
    layers.IridescenceThickness = 500.0;
    layers.Transmission = 0.5;
}
