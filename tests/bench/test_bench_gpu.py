"""pbrlab.bench.gpu: the AMD GPU ISA figures of the bench, on a few kernels and one scene.

The per-evaluation arithmetic is checked on hand-made statistics; the compiled figures
against what the variants do (an exact Fresnel with a square root and divisions against
Schlick's fifth power against a constant); the scene programs against what
specialisation removes; and the report when RADV is missing says so instead of crashing.
"""

import pytest

from pbrlab.bench import families, gpu, kernel, measure, report, report_gpu, worker


def _statistics(instructions, latency, throughput, vgprs, f16=0, packed=0, transcendental=0):
    return {"Instructions": instructions, "Latency": latency, "Inverse Throughput": throughput,
            "VGPRs": vgprs, "SGPRs": 16, "Subgroups per SIMD": 10, "Wave size": 64,
            "isa": {"valu_f16": f16, "valu_packed": packed, "transcendental": transcendental}}


def test_per_eval_is_the_difference_over_the_evaluations_of_one_loop_body():
    variant = _statistics(300, 5000, 900, 24, f16=16, packed=8, transcendental=24)
    baseline = _statistics(100, 1000, 100, 12, transcendental=8)
    figures = gpu.per_eval(variant, baseline)
    n = kernel.EVALS_PER_ITERATION
    assert figures["instructions_per_eval"] == 200 / n
    assert figures["latency_per_eval"] == 4000 / n
    assert figures["inverse_throughput_per_eval"] == 800 / n
    assert figures["valu_f16_per_eval"] == 16 / n and figures["valu_packed_per_eval"] == 8 / n
    assert figures["transcendental_per_eval"] == 16 / n
    assert figures["vgprs"] == 24 and figures["vgprs_baseline"] == 12  # absolute, not a difference


@pytest.fixture(scope="module")
def measured():
    if (why := gpu.unavailable_reason()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    fams = [families.FRESNEL, families.SRGB_DECODE, families.SRGB_ENCODE]
    kernels, plans = measure.kernel_specs(fams)
    scenes = {"chart_metallic": worker._bench_scene("chart_metallic")}
    return gpu.measure(kernels, plans, families.BY_NAME, scenes)


def test_fresnel_costs_rank_as_the_work_they_do(measured):
    for family in gpu.GPU_FAMILIES:
        cost = {name: measured["kernels"][("fresnel", name)]["families"][family]["instructions_per_eval"]
                for name in ("dielectric", "schlick", "none")}
        assert cost["dielectric"] > cost["schlick"] > cost["none"] >= 0, (family, cost)


def test_texture_and_framebuffer_srgb_are_reported_as_what_they_are(measured):
    decode = measured["kernels"][("srgb_decode", "hardware")]
    assert "texture unit" in decode["note"]
    for family in gpu.GPU_FAMILIES:
        # the same fetch from the UNORM8 texture is the baseline; the fetch itself costs VGPRs
        assert decode["families"][family]["instructions_per_eval"] == 0
        assert decode["families"][family]["vgprs"] > 0
    assert measured["kernels"][("srgb_encode", "hardware")] == {"na": gpu.HARDWARE_ENCODE_NA}


def test_scene_programs_specialised_and_full_in_both_languages(measured):
    record = measured["scenes"]["chart_metallic"]
    assert [p["kind"] for p in record["programs"]] == ["specialised", "full"]
    spec, full = record["programs"]
    assert spec["defines"].get("PBRLAB_FULL") is None and full["defines"]["PBRLAB_FULL"] == 1
    for family in gpu.GPU_FAMILIES:
        for language in gpu.LANGUAGES:
            a, b = spec["languages"][language][family], full["languages"][language][family]
            assert b["instructions"] > a["instructions"], (family, language)
            assert b["subgroups_per_simd"] <= a["subgroups_per_simd"], (family, language)
        # the two libraries through the same compiler: within 5 % of each other
        g, h = (spec["languages"][lang][family]["instructions"] for lang in gpu.LANGUAGES)
        assert abs(g - h) <= 0.05 * g, (family, g, h)


def test_unity_materials_are_marked_not_compiled(monkeypatch):
    program = gpu.SceneProgram("sphere", (), None, unity=True)
    monkeypatch.setattr(gpu, "scene_programs", lambda scene, kind: {program: ["shaderlab"]})
    jobs, layout = gpu.scene_jobs({"s": object()})
    assert jobs == {}
    assert set(layout["skipped"].values()) == {gpu.UNITY_NA}


def test_without_radv_the_report_says_so(monkeypatch):
    monkeypatch.setattr(gpu, "unavailable_reason", lambda: "no Vulkan loader (libvulkan.so.1)")
    result = gpu.measure([], [], families.BY_NAME, {})
    assert result["available"] is False and "libvulkan" in result["reason"]
    doc = {"gpu_isa": {"available": False, "reason": result["reason"]},
           "families": [], "specialisation": {"scenes": {}}}
    assert report_gpu.validate(doc) == []
    assert "NOT MEASURED" in report_gpu.machine_line(doc) and "libvulkan" in report_gpu.machine_line(doc)
    doc["gpu_isa"]["reason"] = None
    assert report_gpu.validate(doc) == ["$.gpu_isa: not available, and no reason given"]


def test_validate_rejects_a_non_finite_gpu_figure():
    figures = dict.fromkeys(report_gpu.KERNEL_FIELDS, 1.0)
    bad = dict(figures, instructions_per_eval=float("nan"))
    doc = {"gpu_isa": {"available": True, "families": dict(gpu.FORCE_FAMILY)},
           "specialisation": {"scenes": {}},
           "families": [{"name": "f", "variants": [
               {"name": "v", "gpu_isa": {"families": {"rdna3": figures, "rdna2": bad}}}]}]}
    problems = report_gpu.validate(doc)
    assert any("rdna2.instructions_per_eval" in p for p in problems)
    assert any("missing gcn5" in p for p in problems)
    assert report.SCHEMA_ID == "pbrlab-bench/2"


# ---- the whole-BRDF kernels cannot fold the shading frame (issue 25) -------------------------

def test_tier_kernel_frame_turns_per_evaluation_and_keeps_the_domain():
    """n, l and v of the brdf_tier (and layers) kernels: unit, NdotL and NdotV as the inputs
    say, tx and ty orthonormal to n, and every component of n varying over the domain."""
    import numpy as np
    rng = np.random.default_rng(0)
    d = {name: rng.uniform(lo, hi, 4096) for name, lo, hi in families.BRDF_TIER.inputs}
    for _, name, _, fn in families.BRDF_TIER.derived:
        d[name] = fn(d)
    dot = lambda a, b: (d[a] * d[b]).sum(-1)  # noqa: E731
    for name in ("n", "l", "v", "tx", "ty"):
        assert np.allclose(dot(name, name), 1.0)
    assert np.allclose(dot("n", "l"), d["NdotL"]) and np.allclose(dot("n", "v"), d["NdotV"])
    assert np.allclose(dot("n", "tx"), 0.0) and np.allclose(dot("n", "ty"), 0.0) and np.allclose(dot("tx", "ty"), 0.0)
    assert (d["n"].std(axis=0) > 0.1).all()


def test_tier_kernel_with_the_turning_frame_costs_what_a_constant_normal_folds_away():
    """The bench's HIGH-tier kernel (the turning frame) against the same kernel with n = +z
    (the first bench's): the constant normal lets the compiler fold the products with n's
    zeros and ones, so it reports fewer instructions per evaluation on every family."""
    if (why := gpu.unavailable_reason()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    from dataclasses import replace
    high = next(v for v in families.BRDF_TIER.variants if v.name == "high")
    constant = (("vec3", "n", "vec3(0.0, 0.0, 1.0)", None),
                ("vec3", "l", "vec3(sqrt(max(1.0 - NdotL * NdotL, 0.0)), 0.0, NdotL)", None),
                ("vec3", "v", "vec3(sqrt(max(1.0 - NdotV * NdotV, 0.0)) * cos(phi), "
                              "sqrt(max(1.0 - NdotV * NdotV, 0.0)) * sin(phi), NdotV)", None))
    costs = {}
    for label, family in (("turning", families.BRDF_TIER), ("constant", replace(families.BRDF_TIER, derived=constant))):
        kernels, plans = measure.kernel_specs([replace(family, variants=(high,))])
        costs[label] = gpu.measure(kernels, plans, {family.name: family}, {})["kernels"][("brdf_tier", "high")]
    for fam in gpu.GPU_FAMILIES:
        turning, folded = (costs[k]["families"][fam]["instructions_per_eval"] for k in ("turning", "constant"))
        assert turning > folded + 4, (fam, turning, folded)


@pytest.fixture(scope="module")
def tier_costs():
    """ACO's instructions per evaluation of the tiers and the Filament peer in the bench's
    turning-frame kernel, {variant: {family: count}}."""
    if (why := gpu.unavailable_reason()) is not None:
        pytest.fail(f"RADV null device unavailable (scripts/setup.sh installs it): {why}")
    from dataclasses import replace
    names = ("high", "medium", "low", "filament")
    family = replace(families.BRDF_TIER, variants=tuple(v for v in families.BRDF_TIER.variants if v.name in names))
    kernels, plans = measure.kernel_specs([family])
    costs = gpu.measure(kernels, plans, {family.name: family}, {})["kernels"]
    return {name: {fam: costs[("brdf_tier", name)]["families"][fam]["instructions_per_eval"]
                   for fam in gpu.GPU_FAMILIES} for name in names}


def test_high_tier_costs_no_more_than_the_filament_peer_on_every_amd_family(tier_costs):
    """Issue 25's cost target: the whole HIGH-tier BRDF (pbr_brdf_standard with its edges)
    at or below Filament's per-light code (bench/peers/filament_standard.glsl) in ACO's
    instructions per evaluation, on RDNA3, RDNA2 and GCN5, in the bench's turning-frame
    kernel. Measured 61.625 / 57.625 / 57.625 against 63.5 / 58.5 / 58.5 (docs/shading.md
    lists what each instruction buys)."""
    for fam in gpu.GPU_FAMILIES:
        high, peer = tier_costs["high"][fam], tier_costs["filament"][fam]
        assert high <= peer, (fam, high, peer)


def test_tier_costs_are_ordered_low_medium_high_on_every_amd_family(tier_costs):
    """The tiers' order in cost: MEDIUM strictly between LOW and HIGH on every family (measured
    56.625 / 54.625 / 54.625 between 49.5 / 47.5 / 48.5 and 61.625 / 57.625 / 57.625), the
    order their errors take the other way (LOW > MEDIUM > HIGH: the bench's accuracy table,
    docs/bench). No ratio is asserted: issue 25's 0.641x (39.5) dropped the Fresnel rise and
    wrote D in a cancelling form; issue 35 put back Schlick's rise (+6) and |n x h|^2 (+4,
    rotated frames), 0.803x, and a ratio pinned at a measured value is no derived bound. The
    ratio the README states is generated from the bench's own run (bench.headline)."""
    for fam in gpu.GPU_FAMILIES:
        low, medium, high = (tier_costs[name][fam] for name in ("low", "medium", "high"))
        assert low < medium < high, (fam, low, medium, high)
