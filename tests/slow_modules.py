"""The slow modules: the one list that `make check` (pytest -m "not slow") leaves out."""

from pathlib import Path

# `make check`: the quick subset, `pytest -m "not slow"`. A module is slow when one full run
# spent 10 s or more in it (seconds beside each: `--junitxml` of the whole suite with -n 2 on this
# project's 2-core machine, 2026-12-06, per-test times summed per module). These 28 modules held
# 85 % of the suite's time and 43 % of its tests (1,634 of 3,824); every test folder keeps modules in the quick subset
# (tests/packaging/test_quick_subset.py checks both). Adding a module here is the only way to
# make a test slow: one list, one place.
SLOW_MODULES = {
    "importers/gltf/test_khronos_models.py": 217,
    "importers/gltf/test_sample_viewer_agreement.py": 216,
    "render/test_white_furnace.py": 215,
    "render/test_prefiltered_environment.py": 193,
    "checking/hardcases/test_catalogue.py": 155,
    "render/test_cpu_independence.py": 131,
    "importers/unity/test_corpus.py": 123,
    "bench/test_bench_quick.py": 79,
    "gpu/hlsl/test_hardcase_sweeps_hlsl.py": 68,
    "render/test_gpu_matches_cpu_reference.py": 38,
    "render/specialisation/test_specialisation.py": 37,
    "library/test_transmission.py": 34,
    "importers/unity/test_unity_standard.py": 31,
    "importers/unity/test_unity_surface_shaders.py": 31,
    "library/test_sheen.py": 30,
    "library/test_brdf_properties.py": 24,
    "checking/fidelity/test_benchmark.py": 21,
    "gpu/hlsl/test_scene_renders.py": 20,
    "bench/test_bench_gpu.py": 18,
    "importers/urp/test_urp_corpus.py": 17,
    "foundation/test_import_cost.py": 16,
    "commands/test_render_cli.py": 15,
    "gpu/hlsl/test_function_agreement.py": 14,
    "importers/gltf/test_gltf_pyrender.py": 14,
    "gpu/isa/test_light_loop.py": 12,
    "library/test_anisotropy.py": 12,
    "gpu/hlsl/test_compile_matrix.py": 11,
    "library/test_horizon_occlusion.py": 10,
    # added after that run, timed alone (-n 1, one worker) when they joined:
    "examples/test_babylonjs_example.py": 32,
    "hostile/test_limits_round_three.py": 32,  # child processes: llvmpipe compiles, signals, a 10^6-instance glTF
    "hostile/test_cache_round_three.py": 15,   # child processes reading FIFO and device entries, a render
}
TESTS = Path(__file__).resolve().parent
