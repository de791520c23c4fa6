// A surface file that writes a layer beyond the Standard model: the same material as the
// JSON fields albedo [0.8, 0.3, 0.2], metallic 0.25, smoothness 0.4, clearcoat 1,
// clearcoat_smoothness 0.85 (tests/surface/test_surface_layers.py). Writing ClearCoat*
// compiles the coat in, and nothing of the other layers (harness/pbrlab/scene/surface_layers.py).
void surf(Input IN, inout SurfaceOutputStandard o, inout SurfaceOutputStandardLayers layers) {
    o.Albedo = vec3(0.8, 0.3, 0.2);
    o.Metallic = 0.25;
    o.Smoothness = 0.4;
    layers.ClearCoatMask = 1.0;
    layers.ClearCoatSmoothness = 0.85;
}
