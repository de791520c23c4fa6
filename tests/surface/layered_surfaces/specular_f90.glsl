// A surface file that writes KHR_materials_specular's F90: the same material as the JSON
// fields workflow specular, albedo [0.8, 0.3, 0.2], specular [0.01, 0.01, 0.0], smoothness 0.6,
// specular_f90 0.5 (tests/surface/test_surface_layers.py). Writing SpecularF90 compiles the
// explicit F90 in (harness/pbrlab/scene/surface_layers.py).
void surf(Input IN, inout SurfaceOutputStandardSpecular o, inout SurfaceOutputStandardLayers layers) {
    o.Albedo = vec3(0.8, 0.3, 0.2);
    o.Specular = vec3(0.01, 0.01, 0.0);
    o.Smoothness = 0.6;
    layers.SpecularF90 = 0.5;
}
