"""The default material charts: scene dicts (the JSON scene format) built from tables.

Each chart is a grid of analytic spheres under the same two directional lights, so a
chart is a golden that the float64 CPU renderer can check. ``CHARTS`` maps a chart name
to the function building its scene; ``pbrlab demo`` renders all of them.
"""

from __future__ import annotations

import math

SPACING = 2.25   # sphere centres apart, radius 1
KEY_LIGHT = {"type": "directional", "direction": [0.45, -0.55, -0.70], "color": [1.0, 0.97, 0.92],
             "intensity": 2.0}
FILL_LIGHT = {"type": "directional", "direction": [-0.6, -0.1, -0.8], "color": [0.55, 0.65, 1.0],
              "intensity": 0.35}
SMOOTHNESS_STEPS = [0.0, 0.2, 0.4, 0.6, 0.8, 0.95, 1.0]

# F0 tables from the lecture (Lagarde 2011, "Feeding a physically based shading model"),
# linear values. Dielectrics are grey (one value), metals coloured.
DIELECTRIC_F0 = {
    "quartz": 0.045593921, "ice": 0.017908907, "water": 0.020373188, "alcohol": 0.01995505,
    "glass": 0.04, "milk": 0.022181983, "ruby": 0.077271957, "crystal": 0.111111111,
    "diamond": 0.171968833, "skin": 0.028,
}
METAL_F0 = {
    "silver": [0.971519, 0.959915, 0.915324], "aluminium": [0.913183, 0.921494, 0.924524],
    "gold": [1.0, 0.765557, 0.336057], "copper": [0.955008, 0.637427, 0.538163],
    "chromium": [0.549585, 0.556114, 0.554256], "nickel": [0.659777, 0.608679, 0.525649],
    "titanium": [0.541931, 0.496791, 0.449419], "cobalt": [0.662124, 0.654864, 0.633732],
    "platinum": [0.672411, 0.637331, 0.585456],
}


def _grid_scene(rows: list[list[tuple[str, dict]]], pixels_per_sphere: int = 96) -> dict:
    """A scene with one sphere per (name, material) cell, rows top to bottom."""
    n_rows, n_cols = len(rows), max(len(r) for r in rows)
    width, height = n_cols * pixels_per_sphere, n_rows * pixels_per_sphere
    extent_y = n_rows * SPACING
    distance = 40.0
    fov = 2 * math.degrees(math.atan(extent_y / 2 / distance))
    materials, objects = {}, []
    for i, row in enumerate(rows):
        for j, (name, material) in enumerate(row):
            materials[name] = material
            x = (j - (n_cols - 1) / 2) * SPACING
            y = ((n_rows - 1) / 2 - i) * SPACING
            objects.append({"sphere": {"center": [x, y, 0.0], "radius": 1.0}, "material": name})
    return {
        "camera": {"position": [0.0, 0.0, distance], "target": [0.0, 0.0, 0.0], "up": [0, 1, 0],
                   "fov_y_deg": fov, "size": [width, height]},
        "lights": [KEY_LIGHT, FILL_LIGHT],
        "environment": None,
        "materials": materials,
        "objects": objects,
        "render": {"quality": "high", "tonemap": "none", "exposure": 0.0},
    }


def metallic_chart() -> dict:
    """Metallic workflow: metallic 0..1 (rows) x smoothness 0..1 (columns), one albedo."""
    albedo = [0.9, 0.45, 0.2]
    rows = [[(f"m{m:.2f}_s{s:.2f}", {"workflow": "metallic", "albedo": albedo, "metallic": m,
                                    "smoothness": s}) for s in SMOOTHNESS_STEPS]
            for m in (1.0, 0.75, 0.5, 0.25, 0.0)]
    return _grid_scene(rows)


# The environment of chart_metallic_environment: a constant grey sky (linear radiance), so a
# smooth metal reflects something (its F0 times the sky) instead of the black of an empty
# world; constant, so the float64 CPU renderer checks the golden (cpu_render.py).
GREY_SKY = [0.35, 0.35, 0.35]


def metallic_environment_chart() -> dict:
    """chart_metallic under the grey sky: the same spheres and lights, image-based light added."""
    scene = metallic_chart()
    scene["environment"] = {"color": GREY_SKY}
    return scene


def specular_chart() -> dict:
    """Specular workflow: specular colour (rows) x smoothness (columns), grey albedo."""
    speculars = {"f0_0.02": [0.02] * 3, "f0_0.04": [0.04] * 3, "f0_0.17": [0.17] * 3,
                 "gold": METAL_F0["gold"], "copper": METAL_F0["copper"]}
    rows = []
    for name, spec in speculars.items():
        albedo = [0.0, 0.0, 0.0] if max(spec) > 0.5 else [0.5, 0.5, 0.5]  # metals: no diffuse
        rows.append([(f"{name}_s{s:.2f}", {"workflow": "specular", "albedo": albedo,
                                           "specular": spec, "smoothness": s})
                     for s in SMOOTHNESS_STEPS])
    return _grid_scene(rows)


def f0_chart() -> dict:
    """The lecture's F0 tables: one sphere per dielectric (top rows) and metal (bottom)."""
    dielectrics = [(name, {"workflow": "specular", "albedo": [0.35, 0.35, 0.35],
                           "specular": [f0] * 3, "smoothness": 0.8})
                   for name, f0 in DIELECTRIC_F0.items()]
    metals = [(name, {"workflow": "metallic", "albedo": rgb, "metallic": 1.0, "smoothness": 0.8})
              for name, rgb in METAL_F0.items()]
    cols = 5
    rows = [dielectrics[i:i + cols] for i in range(0, len(dielectrics), cols)]
    rows += [metals[i:i + cols] for i in range(0, len(metals), cols)]
    return _grid_scene(rows)


def terms_chart() -> dict:
    """Each BRDF term variant side by side on one material, the others at their defaults:
    rows D, G/V, F and diffuse (selected per material through its ``brdf`` field)."""
    from ..scene.model import BRDF_TERMS

    specular_base = {"workflow": "metallic", "albedo": METAL_F0["gold"], "metallic": 1.0,
                     "smoothness": 0.55}  # specular only: the D, V and F rows
    diffuse_base = {"workflow": "metallic", "albedo": [0.75, 0.35, 0.15], "metallic": 0.0,
                    "smoothness": 0.2}  # rough dielectric: Burley's retro-reflection shows
    rows = [[(f"{term}_{variant.lower()}",
              dict(diffuse_base if term == "diffuse" else specular_base, brdf={term: variant.lower()}))
             for variant in BRDF_TERMS[term]]
            for term in ("specular_d", "specular_v", "specular_f", "diffuse")]
    return _grid_scene(rows)


CHARTS = {
    "chart_metallic": metallic_chart,
    "chart_metallic_environment": metallic_environment_chart,
    "chart_specular": specular_chart,
    "chart_f0": f0_chart,
    "chart_terms": terms_chart,
}
