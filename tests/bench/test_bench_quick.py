"""`pbrlab bench --quick` runs end to end and writes a report that follows its schema.

A benchmark is not a timed test: nothing here asserts a time or a ratio. What is checked:
the command exits 0, accuracy_cost.json validates (pbrlab.bench.report.validate), every
variant of every family the library ships has an error and a time (instruction counts are
skipped under --quick, see pbrlab.bench), the markdown has a table per family and every
family has a plot; the AMD GPU ISA columns (RADV's null device, which `make bench` requires:
scripts/setup.sh installs it) exist for the three families, are finite and respond to the
work a variant does.
"""

import json
import sys

import pytest

from pbrlab.commands import cli
from pbrlab.bench import families, report


@pytest.fixture(scope="module")
def quick_report(tmp_path_factory):
    out = tmp_path_factory.mktemp("bench")
    assert cli.main(["bench", "--quick", "--out", str(out)]) == 0
    return out, json.loads((out / "accuracy_cost.json").read_text(encoding="utf-8"))


def test_bench_quick_json_follows_the_schema(quick_report):
    _, doc = quick_report
    assert report.validate(doc) == []
    assert doc["quick"] is True


def test_bench_quick_covers_every_family_and_variant_with_error_and_time(quick_report):
    _, doc = quick_report
    measured = {f["name"]: {v["name"]: v for v in f["variants"]} for f in doc["families"]}
    for family in families.FAMILIES:
        assert set(measured[family.name]) == {v.name for v in family.variants}, family.name
        for name, v in measured[family.name].items():
            assert v["error"]["max_rel"] is not None and v["error"]["samples"] > 0, (family.name, name)
            assert v["time_ns"]["median"] is not None, (family.name, name)
            assert "per_eval" in v["instructions"], (family.name, name)


def test_bench_quick_writes_a_table_and_a_plot_per_family(quick_report):
    out, doc = quick_report
    text = (out / "accuracy_cost.md").read_text(encoding="utf-8")
    for fam in doc["families"]:
        assert f"(`{fam['name']}`)" in text
        png = out / f"{fam['name']}.png"
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "noise" in text


def test_bench_validate_rejects_a_variant_without_error():
    doc = {"schema": report.SCHEMA_ID, "quick": False, "machine": {"valgrind": "valgrind-3.19.0"},
           "method": {}, "frame": {"tiers": {}}, "tier_images": {"tiers": {}},
           "specialisation": {"scenes": {}},
           "gpu_isa": {"available": False, "reason": "RADV missing (test)"},
           "families": [{"name": "f", "title": "t", "reference": "r", "domain": "d", "exact": "a",
                         "unit": "u", "variants": [{"name": "a", "expression": "x", "note": "",
                                                    "defines": {}, "self_error": None,
                                                    "time_ns": {}, "instructions": {}}]}]}
    problems = report.validate(doc)
    assert any("missing 'error'" in p for p in problems)
    assert any("instructions.per_eval: not counted" in p for p in problems)
    assert any("frame.tiers: missing high" in p for p in problems)


def test_bench_quick_reports_specialised_against_full_programs_per_scene(quick_report):
    from pbrlab.bench.measure import SPECIALISATION_SCENES

    _, doc = quick_report
    scenes = doc["specialisation"]["scenes"]
    assert set(scenes) == set(SPECIALISATION_SCENES)
    for name, record in scenes.items():
        assert record["programs_specialised"] >= 1 and record["programs_full"] >= 1
        assert record["specialised_ms_median"] > 0 and record["full_ms_median"] > 0


_FAKE_WORKER = """
import json, sys
for _ in range(4):
    print("round", file=sys.stderr, flush=True)
print("a warning the worker wrote", file=sys.stderr)
if sys.argv[2] == "fail":
    sys.exit(3)
open(sys.argv[1], "w").write(json.dumps({"seconds": [1, 2]}))
"""


def test_rounds_drive_a_progress_bar_and_the_result_comes_back(tmp_path, capsys):
    from pbrlab.bench import measure

    out = tmp_path / "result.json"
    result = measure._run_with_rounds([sys.executable, "-c", _FAKE_WORKER, str(out), "ok"], out,
                                      None, rounds=4, what="fake rounds")
    assert result == {"seconds": [1, 2]}
    err = capsys.readouterr().err
    assert "fake rounds" in err and "/4 [" in err  # tqdm's bar (n/4 [elapsed<left]), on stderr


def test_a_failing_worker_reports_its_own_stderr_without_the_round_lines(tmp_path):
    from pbrlab.bench import measure

    out = tmp_path / "result.json"
    with pytest.raises(RuntimeError, match="a warning the worker wrote") as failure:
        measure._run_with_rounds([sys.executable, "-c", _FAKE_WORKER, str(out), "fail"], out,
                                 None, rounds=4, what="fake rounds")
    assert "round\nround" not in str(failure.value)  # the progress lines are not the error


# ---- AMD GPU ISA columns (pbrlab.bench.gpu) --------------------------------------------------

def _variants(doc):
    return {(f["name"], v["name"]): v for f in doc["families"] for v in f["variants"]}


def test_bench_quick_compiles_for_the_three_amd_families(quick_report):
    out, doc = quick_report
    isa = doc["gpu_isa"]
    assert isa["available"], f"RADV null device unavailable (scripts/setup.sh installs it): {isa['reason']}"
    assert set(isa["devices"]) == {"rdna3", "rdna2", "gcn5"}
    assert doc["machine"]["gpu_isa_devices"] == isa["devices"]
    text = (out / "accuracy_cost.md").read_text(encoding="utf-8")
    for name in isa["devices"].values():
        assert name.startswith("Null hardware (RADV") and f"`{name}`" in text
    assert "RDNA3 instr/eval" in text and "GLSL versus HLSL" in text


def test_bench_quick_gpu_costs_respond_to_the_work_a_variant_does(quick_report):
    _, doc = quick_report
    variants = _variants(doc)
    kinds = {(f.name, v.name): v.kind for f in families.FAMILIES for v in f.variants}
    for family in ("rdna3", "rdna2", "gcn5"):
        for key, v in variants.items():
            if kinds[key] == "alu":  # an expression: its per-evaluation static cost is not negative
                assert v["gpu_isa"]["families"][family]["instructions_per_eval"] >= 0, (key, family)
        ggx = variants[("distribution", "ggx")]["gpu_isa"]["families"][family]
        implicit = variants[("visibility", "implicit")]["gpu_isa"]["families"][family]
        # D_GGX: a division and a square of a polynomial; V_Implicit: the constant 1/4
        assert ggx["instructions_per_eval"] > implicit["instructions_per_eval"] + 4, family
        high = variants[("brdf_tier", "high")]["gpu_isa"]["families"][family]
        assert high["vgprs"] >= high["vgprs_baseline"] and high["instructions_per_eval"] > 20, family
        # the sRGB decode is the texture unit's: the same program as the UNORM8 fetch
        assert variants[("srgb_decode", "hardware")]["gpu_isa"]["families"][family]["instructions_per_eval"] == 0
    assert "colour-buffer" in variants[("srgb_encode", "hardware")]["gpu_isa"]["na"]


def test_bench_quick_float16_reaches_the_amd_isa_as_16_bit_arithmetic(quick_report):
    """The LOW tier with PBR_FLOAT16 compiles to 16-bit VALU instructions on every family;
    as it is (mediump ignored by RADV) it has none."""
    out, doc = quick_report
    study = doc["gpu_isa"]["float16_study"]
    for family in ("rdna3", "rdna2", "gcn5"):
        f32, f16 = study["families"][family]["float32"], study["families"][family]["float16"]
        assert f32["valu_f16_per_eval"] == 0 and f16["valu_f16_per_eval"] >= 5, family
        assert f16["instructions_per_eval"] > 0 and f32["instructions_per_eval"] > 0, family
    assert "Half precision on AMD GPUs" in (out / "accuracy_cost.md").read_text(encoding="utf-8")


def test_bench_quick_compiles_every_scene_program_in_glsl_and_hlsl(quick_report):
    _, doc = quick_report
    for name, scene in doc["specialisation"]["scenes"].items():
        isa = scene["gpu_isa"]
        kinds = [p["kind"] for p in isa["programs"]]
        assert "specialised" in kinds and "full" in kinds, name
        for program in isa["programs"]:
            for language in ("glsl", "hlsl"):
                assert set(program["languages"][language]) == {"rdna3", "rdna2", "gcn5"}, (name, language)
        for material, pair in isa["materials"].items():
            assert set(pair) == {"specialised", "full"}, (name, material)
    # one program per kind: the full one compiles every effect, the specialised two lights
    metallic = doc["specialisation"]["scenes"]["chart_metallic"]["gpu_isa"]["summary"]
    for language in ("glsl", "hlsl"):
        for family, row in metallic[language].items():
            assert row["full"]["instructions_max"] > row["specialised"]["instructions_max"], (language, family)
            assert row["full"]["vgprs_max"] >= row["specialised"]["vgprs_max"], (language, family)
