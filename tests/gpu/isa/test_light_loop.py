"""Issue 25, the energy coupling once per pixel: one more light costs the BRDF, not the
coupling (the DFG values, the coat's albedo bound, the coupled diffuse colour, the
environment's albedo). RDNA3 / RDNA2 / GCN5 instructions from RADV's null device
(pbrlab.bench.light_loop; docs/shading.md, "The diffuse-specular coupling, once per pixel", has the figures).

Bounds, from the measurement (RDNA3 / RDNA2 / GCN5, instructions per light above the
baseline loop):
* An engine's light loop (uniform trip count, not unrolled). The prepared way
  (pbr_prepare_surface before the loop, pbr_lighting_standard_light in it) costs 56 / 53 / 50
  (metallic; 59 / 56 / 53 before the prepared F90) and 56 / 53 / 50 (specular workflow), *below*
  pbr_shade_punctual with the raw diffuse colour (66 / 62 / 62: it also re-derives the roughness
  terms per light): bound
  prepared <= uncoupled + 2. The control: calling the one-light pbr_lighting_standard_dfg in
  the loop (the coupling inside it) costs 71 / 68 / 66 and 79 / 75 / 73, at least 12 above the
  prepared way on every family and workflow (anisotropic: 82 to 96 above, the tangent frame
  included): bound composed >= prepared + 8, so the kernel does see a coupling left in the loop.
* The scene programs (specialised, 1, 2 and 4 directional lights, HIGH and LOW): per-light
  increments coupled 57, 57.5 (HIGH) and 51, 51.5 (LOW, with Schlick's Fresnel since issue 35;
  38, 38 before) RDNA3, uncoupled 58, 58 and 52, 52.5 (39, 38.5);
  anisotropic 89, 91.5 against 89, 91.5 (139, 140.5 against 138, 140.5 before
  pbr_anisotropic_tangent's fallback became a select: each light kept a branch of its own;
  175, 177.5 earlier). Bound: |coupled - uncoupled| <= 3 per light.
"""

import pytest

from pbrlab.bench import light_loop
from pbrlab.gpu.isa import compile as gpu

FAMILIES = ("rdna3", "rdna2", "gcn5")
PREPARED_OVER_UNCOUPLED = 2
COUPLING_IN_THE_LOOP = 8
SCENE_COUPLED_VS_UNCOUPLED = 3


@pytest.fixture(scope="module")
def engine_loop():
    if (why := gpu.available()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    return light_loop.engine_loop_increments(FAMILIES)


@pytest.mark.parametrize("family", FAMILIES)
@pytest.mark.parametrize("workflow", tuple(light_loop.WORKFLOWS))
@pytest.mark.parametrize("lobe", ["", "anisotropic_"])
def test_a_prepared_light_costs_the_brdf_not_the_coupling(engine_loop, family, workflow, lobe):
    cost = engine_loop[family][workflow]
    prepared, uncoupled, composed = (cost[f"{lobe}{way}"] for way in ("prepared", "uncoupled", "composed"))
    print(f"{family} {workflow} {lobe or 'standard_'}: prepared {prepared}, uncoupled {uncoupled}, "
          f"composed {composed} per light")
    assert prepared <= uncoupled + PREPARED_OVER_UNCOUPLED
    # control: the same kernel sees the coupling where it is left inside the loop
    assert composed >= prepared + COUPLING_IN_THE_LOOP


@pytest.fixture(scope="module")
def scenes():
    if (why := gpu.available()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    return light_loop.scene_increments(qualities=("high", "low"), families=("rdna3",))["rdna3"]


@pytest.mark.parametrize("material", tuple(light_loop.SCENE_MATERIALS))
@pytest.mark.parametrize("quality", ["high", "low"])
def test_scene_programs_pay_no_coupling_per_light(scenes, material, quality):
    coupled = light_loop.per_light(scenes[(material, quality, "coupled")])
    uncoupled = light_loop.per_light(scenes[(material, quality, "uncoupled")])
    print(f"{material} {quality}: per light coupled {coupled}, uncoupled {uncoupled} (RDNA3)")
    assert all(abs(a - b) <= SCENE_COUPLED_VS_UNCOUPLED for a, b in zip(coupled, uncoupled))
    # and the uncoupled program is the cheaper one overall: the patch removed the coupling
    assert scenes[(material, quality, "uncoupled")][0] < scenes[(material, quality, "coupled")][0]


def test_uncoupling_a_program_without_the_coupling_is_an_error():
    from pbrlab.foundation.errors import PbrlabError
    with pytest.raises(PbrlabError, match="energy-conservation"):
        light_loop.uncoupled("void main() {}")
