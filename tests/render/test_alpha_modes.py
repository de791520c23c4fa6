"""Unity's rendering modes: opaque, cutout (discard below the cutoff), fade (blend by
alpha) and transparent (premultiplied: the diffuse fades, the specular stays)."""

import numpy as np

from pbrlab.foundation import images
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene

from render_scenes import one_sphere

FRONT_LIGHT = [{"type": "directional", "direction": [0, 0, -1], "intensity": 1.0}]


def _facing_plane(material, size=(32, 32), z=0.0):
    """A plane at depth z facing the camera (+z), filling the view."""
    return {"mesh": {"primitive": "plane", "size": 4.0}, "material": material,
            "transform": {"translate": [0, 0, z], "rotate_deg": [90, 0, 0]}}


def _scene(materials, objects, size=(32, 32)):
    scene = one_sphere({}, FRONT_LIGHT, size=size)
    scene["camera"] = {"position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40, "size": list(size)}
    scene["materials"] = materials
    scene["objects"] = objects
    return scene


def test_cutout_discards_texels_below_the_cutoff(gl_context, tmp_path):
    texture = np.zeros((8, 8, 4), np.uint8)
    texture[..., :3] = 200
    texture[:, 4:, 3] = 255  # right half opaque, left half alpha 0
    images.write_png(tmp_path / "half.png", texture)
    material = {"workflow": "specular", "specular": [0, 0, 0], "alpha_mode": "cutout",
                "textures": {"albedo": "half.png"}}
    scene = parse_scene(_scene({"m": material}, [_facing_plane("m")]), base=tmp_path)
    coverage = render_scene(scene, gl_context).linear[..., 3]
    assert np.all(coverage[:, :14] == 0) and np.all(coverage[:, 18:] == 1)


def test_fade_blends_radiance_by_alpha(gl_context):
    back = {"workflow": "specular", "specular": [0, 0, 0], "albedo": [1, 0, 0]}
    front = {"workflow": "specular", "specular": [0, 0, 0], "albedo": [0, 0, 1],
             "alpha": 0.25, "alpha_mode": "fade"}
    both = render_scene(parse_scene(_scene({"b": back, "f": front},
                                           [_facing_plane("b", z=-1), _facing_plane("f", z=0)])), gl_context)
    centre = both.linear[16, 16]
    # Lambert, light along the normal, intensity 1: back (1,0,0), front (0,0,1) -> blend
    np.testing.assert_allclose(centre[:3], [0.75, 0.0, 0.25], atol=1e-6)
    assert centre[3] == 1.0


def test_transparent_keeps_the_specular_of_an_invisible_diffuse(gl_context):
    spec = {"workflow": "specular", "specular": [0.04, 0.04, 0.04], "smoothness": 0.7}
    light = [{"type": "directional", "direction": [0.3, -0.3, -1], "intensity": 2.0}]
    glass = one_sphere(dict(spec, albedo=[0.8, 0.8, 0.8], alpha=0.0, alpha_mode="transparent"), light)
    black = one_sphere(dict(spec, albedo=[0.0, 0.0, 0.0]), light)
    transparent = render_scene(parse_scene(glass), gl_context).linear
    reference = render_scene(parse_scene(black), gl_context).linear
    # Premultiplied alpha 0: the diffuse vanishes, the reflection stays (over black).
    covered = reference[..., 3] > 0
    np.testing.assert_allclose(transparent[covered, :3], reference[covered, :3], rtol=1e-6, atol=1e-7)
    assert reference[covered, :3].max() > 0.05  # there is a highlight to keep
    # Unity's output alpha: 1 - oneMinusReflectivity + alpha * oneMinusReflectivity = 0.04
    np.testing.assert_allclose(transparent[covered, 3], 0.04, atol=1e-6)
