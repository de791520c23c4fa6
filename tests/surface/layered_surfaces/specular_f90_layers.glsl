// A surface file that writes KHR_materials_specular's F90 with the layers that change the
// base: the same material as the JSON fields of tests/surface/test_surface_layers.py
// SPECULAR_BASE with specular_f90 0.5 and F90_LAYERS (anisotropy, a film, transmission).
void surf(Input IN, inout SurfaceOutputStandardSpecular o, inout SurfaceOutputStandardLayers layers) {
    o.Albedo = vec3(0.8, 0.3, 0.2);
    o.Specular = vec3(0.01, 0.01, 0.0);
    o.Smoothness = 0.6;
    layers.SpecularF90 = 0.5;
    layers.Anisotropy = 0.6;
    layers.IridescenceMask = 0.8;
    layers.IridescenceThickness = 500.0;
    layers.Transmission = 0.5;
}
