"""What one more light costs: the per-light increment of a lit program on AMD GPUs (issue 25,
"the energy coupling once per pixel"), from ACO's static instruction counts (pbrlab.gpu.isa,
RADV on a null device; no GPU).

Two measurements:

* **An engine's light loop** (``engine_loop_increments``): a fragment program whose normal,
  view and material vary per pixel (inputs) and whose lights come from uniform arrays in a
  loop with a uniform trip count (not unrolled: what an engine's clustered or forward loop
  is). The per-light increment of a way of lighting is the program with *two* such loops
  minus the program with one (a static count holds a loop body once, and the second loop's
  body is not dominated by the first's, so nothing of it is shared with it), minus the same
  difference of the baseline (a loop that only sums the lights' inputs). The ways compared:
  ``uncoupled`` (pbr_shade_punctual with the raw diffuse colour: the BRDF alone),
  ``prepared`` (pbr_prepare_surface before the loops, pbr_lighting_standard_light in them)
  and ``composed`` (pbr_lighting_standard_dfg per light with the DFG values read before the
  loops: the coupling inside the loop, what calling the one-light function in a loop gives),
  and the same three for the anisotropic lobe.
* **The scene programs** (``scene_increments``): the real specialised program of a test
  scene (the templates of pbrlab.gpu.programs) with 1, 2 and 4 directional lights, coupled as
  shipped and uncoupled (the same program text with pbr_coupled_diffuse_color replaced by
  its diffuse colour after the library's definition). Their light loops are unrolled, and
  the environment's call before them computes the same coupling, so the compiler's common
  subexpression elimination already shares it between lights (measured: docs/shading.md).
"""

from __future__ import annotations

from ..foundation.errors import PbrlabError
from ..gpu.isa import compile as gpu_isa
from . import kernel

FAMILIES = ("rdna3",)

_HEAD = """#version 330 core
#include "pbr/pbr.glsl"
in vec3 pbrlab_n;
in vec3 pbrlab_v;
in vec3 pbrlab_albedo;
in vec3 pbrlab_material;  // metallic, perceptual roughness, anisotropy strength
in vec3 pbrlab_direction;
in vec3 pbrlab_specular;
uniform sampler2D pbrlab_dfg;
uniform int pbrlab_count;
uniform vec3 pbrlab_light_dir[LIGHT_CAPACITY];
uniform vec3 pbrlab_light_color[LIGHT_CAPACITY];
out vec4 pbrlab_result;
void main() {
    vec3 n = normalize(pbrlab_n);
    vec3 v = normalize(pbrlab_v);
    float r = pbrlab_material.y;
WORKFLOW    pbr_Anisotropy anisotropy;
    anisotropy.strength = pbrlab_material.z;
    anisotropy.direction = pbrlab_direction;
    vec3 c = vec3(0.0);
"""
# The arrays' size: a loop bounded by a small array is unrolled by the compiler (its trip
# count is bounded by the array), a loop over 256 lights is not.
LIGHT_CAPACITY = 256
# The workflows: metallic (the coat's F0 a constant, PBR_DIELECTRIC_F0: the coupling folds
# partly) and specular (the coat's F0 the specular colour, varying per pixel).
WORKFLOWS = {
    "metallic": """    vec3 f0 = pbr_f0_from_metallic(pbrlab_albedo, pbrlab_material.x);
    vec3 diffuseColor = pbr_diffuse_from_metallic(pbrlab_albedo, pbrlab_material.x);
    vec3 coatF0 = vec3(PBR_DIELECTRIC_F0);
""",
    "specular": """    vec3 f0 = pbrlab_specular;
    vec3 diffuseColor = pbr_diffuse_from_specular(pbrlab_albedo, pbrlab_specular);
    vec3 coatF0 = pbrlab_specular;
"""}
_DFG = ("    vec2 dfg = texture(pbrlab_dfg, pbr_dfg_lut_uv(max(dot(n, v), PBR_MIN_NDOTV), "
        "pbr_clamp_perceptual_roughness(r))).rg;\n")
_PREPARED = ("    pbr_PreparedSurface s = pbr_prepare_surface_dfg(diffuseColor, f0, coatF0, r, 1.0, n, v, dfg);\n"
             "    pbr_AnisotropicFrame frame = pbr_anisotropic_frame(n, anisotropy);\n")
_LOOP = """    for (int i = 0; i < pbrlab_count; ++i) {
        pbr_GI gi;
        gi.light.dir = pbrlab_light_dir[i];
        gi.light.color = pbrlab_light_color[i];
        gi.indirect.diffuse = vec3(0.0);
        gi.indirect.specular = vec3(0.0);
        c += BODY;
    }
"""
_TAIL = "    pbrlab_result = vec4(c, 1.0);\n}\n"

# way -> (what is computed before the loops, one light's radiance)
WAYS = {
    "baseline": ("", "gi.light.color + gi.light.dir"),
    "uncoupled": ("", "pbr_shade_punctual(n, v, gi.light.dir, gi.light.color, diffuseColor, f0, r)"),
    "prepared": (_DFG + _PREPARED, "pbr_lighting_standard_light(s, gi.light)"),
    "composed": (_DFG, "pbr_lighting_standard_dfg(diffuseColor, f0, coatF0, r, 1.0, n, v, gi, dfg)"),
    "anisotropic_uncoupled": (_PREPARED.split("\n")[1] + "\n",
                              "pbr_lighting_anisotropic_light(pbr_PreparedSurface(n, v, f0, pbr_f90_from_f0(f0), "
                              "pbr_clamp_perceptual_roughness(r), 1.0, diffuseColor, vec3(0.0), vec3(0.0), 0.0), "
                              "frame, gi.light)"),
    "anisotropic_prepared": (_DFG + _PREPARED, "pbr_lighting_anisotropic_light(s, frame, gi.light)"),
    "anisotropic_composed": (_DFG, "pbr_lighting_anisotropic_dfg(diffuseColor, f0, coatF0, r, 1.0, n, v, gi, "
                                   "anisotropy, dfg)"),
}


def engine_loop_source(way: str, loops: int, workflow: str = "specular") -> str:
    """The fragment program of one way of lighting with ``loops`` light loops (expanded)."""
    before, light = WAYS[way]
    head = _HEAD.replace("LIGHT_CAPACITY", str(LIGHT_CAPACITY)).replace("WORKFLOW", WORKFLOWS[workflow])
    text = head + before + _LOOP.replace("BODY", light) * loops + _TAIL
    return kernel.expanded(text)


def engine_loop_increments(families=FAMILIES, workflows=tuple(WORKFLOWS)) -> dict:
    """``{family: {workflow: {way: instructions one more light adds}}}`` (baseline subtracted)."""
    jobs = [gpu_isa.Job(f"{workflow}|{way}|{loops}", engine_loop_source(way, loops, workflow))
            for workflow in workflows for way in WAYS for loops in (1, 2)]
    compiled = gpu_isa.run(jobs, families)
    out = {}
    for family in families:
        out[family] = {}
        for workflow in workflows:
            one = {way: compiled[family][f"{workflow}|{way}|2"]["Instructions"]
                   - compiled[family][f"{workflow}|{way}|1"]["Instructions"] for way in WAYS}
            out[family][workflow] = {way: one[way] - one["baseline"] for way in WAYS if way != "baseline"}
    return out


# ---- the scene programs ---------------------------------------------------------------------

LIGHT_COUNTS = (1, 2, 4)
SCENE_MATERIALS = {
    "standard": {"workflow": "metallic", "albedo": [0.8, 0.5, 0.3], "metallic": 0.5, "smoothness": 0.6},
    "anisotropic": {"workflow": "metallic", "albedo": [0.8, 0.5, 0.3], "metallic": 0.5, "smoothness": 0.6,
                    "anisotropy_strength": 0.6},
}
_COUPLING_END = "#endif // PBR_SHADING_ENERGY_CONSERVATION_GLSL"
_UNCOUPLED = "\n#define pbr_coupled_diffuse_color(diffuseColor, coatF0, coatAlbedo) (diffuseColor)\n"


def _scene(lights: int, material: dict, quality: str):
    from ..importers import loader as scene_model
    data = {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "size": [64, 64]},
            "lights": [{"type": "directional", "direction": [-0.3 + 0.1 * i, -0.6, -1.0]} for i in range(lights)],
            "materials": {"m": material},
            "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}],
            "render": {"quality": quality}}
    return scene_model.parse_scene(data)


def uncoupled(text: str) -> str:
    """The program text with the diffuse-specular coupling removed: every later use of
    pbr_coupled_diffuse_color returns the diffuse colour itself."""
    if _COUPLING_END not in text:
        raise PbrlabError("scene program: the energy-conservation include's end was not found")
    return text.replace(_COUPLING_END, _COUPLING_END + _UNCOUPLED, 1)


def scene_program_text(lights: int, material: str, quality: str) -> str:
    from . import gpu
    (program, _), = gpu.scene_programs(_scene(lights, SCENE_MATERIALS[material], quality), "specialised").items()
    return program.job("glsl").fragment


def scene_increments(materials=tuple(SCENE_MATERIALS), qualities=("high",), families=FAMILIES) -> dict:
    """``{family: {(material, quality, coupling): [instructions per program at LIGHT_COUNTS]}}``,
    coupling "coupled" (as shipped) or "uncoupled"."""
    jobs, keys = [], []
    for material in materials:
        for quality in qualities:
            for lights in LIGHT_COUNTS:
                text = scene_program_text(lights, material, quality)
                for coupling, program in (("coupled", text), ("uncoupled", uncoupled(text))):
                    key = f"{material}|{quality}|{coupling}|{lights}"
                    jobs.append(gpu_isa.Job(key, program))
                    keys.append(key)
    compiled = gpu_isa.run(jobs, families)
    out = {}
    for family in families:
        rows = {}
        for material in materials:
            for quality in qualities:
                for coupling in ("coupled", "uncoupled"):
                    rows[(material, quality, coupling)] = [
                        compiled[family][f"{material}|{quality}|{coupling}|{lights}"]["Instructions"]
                        for lights in LIGHT_COUNTS]
        out[family] = rows
    return out


def per_light(counts: list) -> list:
    """The increments between consecutive LIGHT_COUNTS, per light."""
    return [(counts[i + 1] - counts[i]) / (LIGHT_COUNTS[i + 1] - LIGHT_COUNTS[i]) for i in range(len(counts) - 1)]
