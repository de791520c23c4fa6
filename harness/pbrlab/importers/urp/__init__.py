"""Unity's Universal Render Pipeline (URP) shaders as scene materials: a ``.shader`` whose
SubShader is tagged ``"RenderPipeline" = "UniversalPipeline"`` or whose programs include URP's
ShaderLibrary. The ShaderLab file is read by the Unity importer's stages (importers/unity/) for
URP (``parse.URP``: HLSLPROGRAM blocks, URP's LightMode tags, its SubShaders); its includes
resolve to pbrlab's stand-ins for URP's ShaderLibrary (importers/unity/package_stand_ins/);
and the material is drawn through this importer's own source (``material.URPSource``): each
forward pass once, lit by every light of the scene as URP's forward renderer does.
"""
