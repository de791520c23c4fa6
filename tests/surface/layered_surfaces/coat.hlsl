// The HLSL twin of coat.glsl.
void surf(Input IN, inout SurfaceOutputStandard o, inout SurfaceOutputStandardLayers layers) {
    o.Albedo = float3(0.8, 0.3, 0.2);
    o.Metallic = 0.25;
    o.Smoothness = 0.4;
    layers.ClearCoatMask = 1.0;
    layers.ClearCoatSmoothness = 0.85;
}
