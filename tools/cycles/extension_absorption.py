"""render.py with KHR_materials_volume's absorption instead of Blender's importer's: a diagnostic
reference (benchmarks/volume_absorption_reference.py; docs/fidelity.md, "The volume step").

Blender's glTF importer (io_scene_gltf2/blender/imp/pbrMetallicRoughness.py, `volume`) gives a
Volume Absorption node the attenuation colour c and a density k = 1 / attenuationDistance;
Cycles absorbs (1 - c) k per unit length (node_absorption_volume.osl). The extension's
coefficient is sigma = -ln(c) / attenuationDistance per channel. After render.py has built the
scene, each such node gets density sigma_max and colour 1 - sigma / sigma_max, so that
(1 - colour) x density = sigma in every channel. Everything else is render.py's.

    .venv-bpy/bin/python tools/cycles/extension_absorption.py SPEC.json OUT [render.py's options]
"""

import importlib.util
import math
import sys
from pathlib import Path

_SPEC = importlib.util.spec_from_file_location("cycles_render", Path(__file__).with_name("render.py"))
render = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(render)
_build_scene = render._build_scene


def extension_sigma(colour, density):
    """KHR_materials_volume's sigma per channel from the importer's colour and density (1 / D)."""
    return [-math.log(max(c, sys.float_info.min)) * density for c in colour]


def _with_extension_absorption(bpy, spec: dict, light_paths: dict) -> None:
    _build_scene(bpy, spec, light_paths)
    for material in bpy.data.materials:
        for node in material.node_tree.nodes if material.node_tree else ():
            if node.bl_idname != "ShaderNodeVolumeAbsorption":
                continue
            if node.inputs[0].is_linked or node.inputs[1].is_linked:
                render._fail(f"{spec['gltf']}: material {material.name!r}: a textured absorption is not rewritten")
            sigma = extension_sigma(list(node.inputs[0].default_value)[:3], node.inputs[1].default_value)
            top = max(sigma)
            if top > 0.0:
                node.inputs[1].default_value = top
                node.inputs[0].default_value = [1.0 - s / top for s in sigma] + [1.0]


render._build_scene = _with_extension_absorption

if __name__ == "__main__":
    sys.exit(render.main(sys.argv[1:]))
