"""The pyrender cross-check: pbrlab's shading run inside pyrender's renderer (``compat``,
``check``), its figure (``figure``) and the glTF variant (``gltf_check``)."""
