"""The importers: each turns a file format into the scene model (pbrlab.scene) and its
materials into the material interface (pbrlab.scene.material_passes). ``gltf`` reads glTF 2.0,
``unity`` reads Unity's shaders (ShaderLab, Cg/HLSL, the built-in pipeline's passes), ``urp``
gives a Universal Render Pipeline shader its own material source (read by ``unity``'s stages
for URP), and ``loader`` picks the importer a file needs (a JSON scene may take in glTF files
and name Unity shaders)."""
