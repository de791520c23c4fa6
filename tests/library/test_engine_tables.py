"""Engine-ready tables (`pbrlab tables`, pbrlab.gpu.engine_tables) and the engine snippet
examples/engine/pbrlab_tables.glsl / .hlsl: the files hold the library's tables (EXR exactly,
16-bit PNG to half a code), read with the documented orientation at the library's texture
coordinates they give the library's values (and the float64 integrals within the library's
1e-3), and the snippet's coordinates are the library's, bit for bit, in GLSL and HLSL."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from library_helpers import as_f32, evaluate
from pbrlab.commands import cli
from pbrlab.gpu import engine_tables, ibl, sheen_table
from pbrlab.foundation import images
from pbrlab.maths.reference import surface as ref_surface

ROOT = Path(__file__).resolve().parents[2]
SNIPPETS = ROOT / "examples" / "engine"
BY_NAME = {t.name: t for t in engine_tables.TABLES}


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    out = tmp_path_factory.mktemp("tables")
    assert cli.main(["tables", "-q", "--out", str(out)]) == 0
    return out


def _bilinear(image_rows, u, v):
    """What a GPU reads from an image loaded with its bottom row at v = 0 (the documented
    orientation): bilinear at (u, v), clamp to edge, float64."""
    t = np.asarray(image_rows, np.float64)[::-1]  # bottom row first: GL row j
    h, w = t.shape[:2]
    fx, fy = u * w - 0.5, v * h - 0.5
    i0 = np.clip(np.floor(fx).astype(int), 0, w - 1)
    j0 = np.clip(np.floor(fy).astype(int), 0, h - 1)
    i1, j1 = np.minimum(i0 + 1, w - 1), np.minimum(j0 + 1, h - 1)
    tx, ty = (fx - np.floor(fx))[..., None], (fy - np.floor(fy))[..., None]
    return ((t[j0, i0] * (1 - tx) + t[j0, i1] * tx) * (1 - ty) + (t[j1, i0] * (1 - tx) + t[j1, i1] * tx) * ty)


def _off_grid(width, height, seed):
    rng = np.random.default_rng(seed)
    x = (rng.integers(0, width - 1, 120) + rng.uniform(0.2, 0.8, 120)) / (width - 1)
    y = (rng.integers(0, height - 1, 120) + rng.uniform(0.2, 0.8, 120)) / (height - 1)
    return x, y


def test_the_exr_files_are_the_library_tables_exactly(written):
    for table in engine_tables.TABLES:
        np.testing.assert_array_equal(images.read_image(written / f"{table.name}.exr"), table.load())


def test_the_png_files_are_the_tables_to_half_a_code(written):
    for table in engine_tables.TABLES:
        codes = engine_tables.read_png16(written / f"{table.name}.png")
        assert codes.dtype == np.uint16 and codes.shape == table.load().shape
        error = np.abs(engine_tables.decode_png(codes, table) - table.load().astype(np.float64))
        half_code = 0.5 / engine_tables.PNG_MAX * table.png_scale
        assert error.max() <= half_code * (1 + 1e-6), f"{table.name}: {error.max():.3g} > {half_code:.3g}"


def test_read_as_documented_the_dfg_file_gives_the_integral(written):
    """At pbr_dfg_lut_uv, bottom row at v = 0: the float64 split-sum integral within the
    library's 1e-3 (tests/surface/test_dfg_table.py); read top row at v = 0 it is far off."""
    x, y = _off_grid(ref_surface.DFG_LUT_WIDTH, ref_surface.DFG_LUT_HEIGHT, 2013)
    NdotV, rough = ref_surface.dfg_lut_texel_coordinates(x, y)
    NdotV, rough = as_f32(NdotV), as_f32(rough)
    reference = ibl.integrate_dfg(NdotV, rough)
    u, v = ref_surface.dfg_lut_uv(NdotV, rough)
    for suffix in (".exr", ".png"):
        path = written / f"pbrlab_dfg{suffix}"
        data = images.read_image(path) if suffix == ".exr" else \
            engine_tables.decode_png(engine_tables.read_png16(path), BY_NAME["pbrlab_dfg"])
        got = _bilinear(data, u, v)[:, :2]
        assert np.abs(got - reference).max() < 1e-3, suffix
        upside_down = _bilinear(data[::-1], u, v)[:, :2]
        assert np.abs(upside_down - reference).max() > 1e-2


def test_read_as_documented_the_sheen_file_gives_the_integral(written):
    x, y = _off_grid(sheen_table.LUT_WIDTH, sheen_table.LUT_HEIGHT, 2017)
    NdotV, rough = sheen_table.lut_texel_coordinates(x, y)
    NdotV, rough = as_f32(NdotV), as_f32(rough)
    reference = sheen_table.integrate_sheen_albedo(NdotV, rough)
    u, v = sheen_table.lut_uv(NdotV, rough)
    for suffix in (".exr", ".png"):
        path = written / f"pbrlab_sheen_albedo{suffix}"
        data = images.read_image(path) if suffix == ".exr" else \
            engine_tables.decode_png(engine_tables.read_png16(path), BY_NAME["pbrlab_sheen_albedo"])
        got = _bilinear(data, u, v)[:, 0]
        assert np.abs(got - reference).max() < 1e-3, suffix
        assert np.abs(_bilinear(data[::-1], u, v)[:, 0] - reference).max() > 1e-2


def _defines(path: Path) -> dict[str, str]:
    return dict(re.findall(r"^#define (PBR_\w+) (.+?)\s*(?://.*)?$", path.read_text(encoding="utf-8"), re.M))


def test_the_snippet_constants_are_the_library_constants():
    snippet = _defines(SNIPPETS / "pbrlab_tables.glsl")
    library = {**_defines(ROOT / "glsl/pbr/ibl/environment_brdf.glsl"), **_defines(ROOT / "glsl/pbr/shading/sheen.glsl"),
               **_defines(ROOT / "glsl/pbr/common/guards.glsl"), **_defines(ROOT / "glsl/pbr/brdf/d_charlie.glsl")}
    pairs = {"PBR_TABLE_DFG_NDOTV_INV_SCALE": "PBR_DFG_LUT_NDOTV_INV_SCALE",
             "PBR_TABLE_DFG_NDOTV_LOG_NORM": "PBR_DFG_LUT_NDOTV_LOG_NORM",
             "PBR_TABLE_DFG_ALPHA_OFFSET": "PBR_DFG_LUT_ALPHA_OFFSET",
             "PBR_TABLE_DFG_ALPHA_MIN_INV": "PBR_DFG_LUT_ALPHA_MIN_INV",
             "PBR_TABLE_DFG_ALPHA_LOG_NORM": "PBR_DFG_LUT_ALPHA_LOG_NORM",
             "PBR_TABLE_SHEEN_MIN_NDOTV": "PBR_MIN_NDOTV",
             "PBR_TABLE_SHEEN_MIN_ROUGHNESS": "PBR_SHEEN_MIN_PERCEPTUAL_ROUGHNESS",
             "PBR_TABLE_SHEEN_NDOTV_LOG_NORM": "PBR_SHEEN_LUT_NDOTV_LOG_NORM",
             "PBR_TABLE_SHEEN_ROUGHNESS_LOG_NORM": "PBR_SHEEN_LUT_ROUGHNESS_LOG_NORM"}
    for ours, theirs in pairs.items():
        assert float(snippet[ours]) == float(library[theirs]), ours
    assert snippet["PBR_TABLE_DFG_SIZE"] == f"vec2({library['PBR_DFG_LUT_WIDTH']}, {library['PBR_DFG_LUT_HEIGHT']})"
    assert snippet["PBR_TABLE_SHEEN_SIZE"] == f"vec2({library['PBR_SHEEN_LUT_WIDTH']}, {library['PBR_SHEEN_LUT_HEIGHT']})"


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
@pytest.mark.parametrize("ours, theirs, library_include", [
    ("pbr_table_dfg_uv", "pbr_dfg_lut_uv", "pbr/ibl/environment_brdf"),
    ("pbr_table_sheen_albedo_uv", "pbr_sheen_lut_uv", "pbr/shading/sheen"),
])
def test_the_snippet_reads_where_the_library_reads(language, ours, theirs, library_include):
    """Through the evaluator: the snippet's coordinates equal the library's, bit for bit,
    over NdotV and roughness including 0, 1 and values outside [0, 1]."""
    mu = np.concatenate([np.linspace(-0.5, 1.5, 81), [0.0, 1e-4, 1e-3, 1.0]]).astype(np.float32)
    rough = np.concatenate([np.linspace(-0.5, 1.5, 81), [0.0, 0.045, 0.07, 1.0]]).astype(np.float32)
    mu, rough = [a.ravel() for a in np.meshgrid(mu, rough)]
    got = evaluate(f"{ours}(NdotV, r)", (f"pbrlab_tables.{language}",), include_dirs=[SNIPPETS],
                   language=language, NdotV=mu, r=rough)
    want = evaluate(f"{theirs}(NdotV, r)", (f"{library_include}.{language}",), language=language, NdotV=mu, r=rough)
    np.testing.assert_array_equal(got, want)
