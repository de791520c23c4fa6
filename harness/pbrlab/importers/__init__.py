"""The importers: each turns a file format into the scene model (pbrlab.scene) and its
materials into the material interface (pbrlab.scene.material_passes). ``gltf`` reads glTF 2.0,
``unity`` reads Unity's built-in-pipeline shaders, and ``loader`` picks the importer a file
needs (a JSON scene may take in glTF files and name Unity shaders). No importer imports
another; the loader sits above them."""
