// A surface file that writes the metallic workflow's dielectric F0 and F90 (KHR_materials_ior /
// _specular on a partly metallic material): the same material as the JSON fields albedo
// [0.8, 0.3, 0.2], metallic 0.5, smoothness 0.6, dielectric_specular [0.12, 0.05, 0.0],
// specular_f90 0.6 (tests/surface/test_surface_layers.py). Writing DielectricSpecular compiles
// the dielectric F0 in, SpecularF90 the explicit F90 (harness/pbrlab/scene/surface_layers.py).
void surf(Input IN, inout SurfaceOutputStandard o, inout SurfaceOutputStandardLayers layers) {
    o.Albedo = vec3(0.8, 0.3, 0.2);
    o.Metallic = 0.5;
    o.Smoothness = 0.6;
    layers.DielectricSpecular = vec3(0.12, 0.05, 0.0);
    layers.SpecularF90 = 0.6;
}
