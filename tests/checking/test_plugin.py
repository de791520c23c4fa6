"""The pytest plugin, run on small throw-away projects through pytester.

numpy and OpenImageIO are imported here, before any in-process run: pytester drops the modules
a run imported, and neither extension loads twice in a process (numpy: "cannot load module
more than once per process"; OpenImageIO's nanobind module aborts the process), which a lone
run of this file otherwise hit (the whole suite imports both first)."""

import re

import numpy  # noqa: F401
import OpenImageIO  # noqa: F401
import pytest

from pbrlab.gpu import gl
from pbrlab.foundation.errors import GLUnavailableError

CHART_TEST = """
import numpy as np

LEVEL = {level}

def test_chart(golden):
    linear = np.full((4, 6, 4), LEVEL, np.float32)
    srgb8 = np.full((4, 6, 4), round(LEVEL * 255), np.uint8)
    golden.check("charts/flat", linear, srgb8)
"""


@pytest.fixture
def project(pytester):
    pytester.makeini("[pytest]\n")  # the rootdir: goldens/ and test-output/ land here
    return pytester


def _assert_names_the_renderer(lines):
    text = "\n".join(line for line in lines if line.startswith("pbrlab:"))
    info = gl.context_info(gl.shared_context())
    for fact in ("GL_RENDERER", "GL_VERSION", info["GL_RENDERER"], "Mesa", "moderngl",
                 info["moderngl"], "OpenImageIO", info["openimageio"],
                 f"llvmpipe CPU caps {info['llvmpipe_cpu_caps']}"):
        assert fact in text, fact


INERT_TEST = """
import os

def test_runs_without_pbrlab():
    from pbrlab.gpu import gl
    assert "GALLIUM_OVERRIDE_CPU_CAPS" not in os.environ
    assert not gl._shared  # no GL context was made in this process
"""


def test_plugin_is_inert_in_a_project_that_uses_none_of_it(project, monkeypatch):
    """Installing pbrlab registers the plugin in every project: there it must open no GL
    context, set no environment variable, print nothing and write nothing."""
    monkeypatch.delenv("GALLIUM_OVERRIDE_CPU_CAPS", raising=False)
    (project.path / "test-output").mkdir()
    (project.path / "test-output" / "index.html").write_text("the project's own page")
    project.makepyfile(test_inert=INERT_TEST)
    result = project.runpytest_subprocess()  # a fresh process: nothing inherited from this one
    result.assert_outcomes(passed=1)
    assert not [line for line in result.outlines if line.startswith("pbrlab")], result.outlines
    assert (project.path / "test-output" / "index.html").read_text() == "the project's own page"
    assert sorted(p.name for p in (project.path / "test-output").iterdir()) == ["index.html"]


def test_summary_names_the_renderer_once_a_test_used_a_context(project):
    project.makepyfile(test_gl="def test_gl(gl_context): assert gl_context.version_code >= 330")
    result = project.runpytest()
    result.assert_outcomes(passed=1)
    _assert_names_the_renderer(result.outlines)


def test_a_pbrlab_option_puts_the_renderer_in_the_header(project):
    project.makepyfile(test_nothing="def test_nothing(): pass")
    result = project.runpytest("--pbrlab-tolerance-profile", "llvmpipe")
    result.assert_outcomes(passed=1)
    header = result.outlines[:result.outlines.index(next(l for l in result.outlines if "collected" in l))]
    _assert_names_the_renderer(header)


def test_header_without_gl_prints_the_reason_and_tests_still_run(project, monkeypatch):
    def no_gl(backend=None):
        raise GLUnavailableError("no OpenGL library could be loaded (test)")
    monkeypatch.setattr(gl, "shared_context", no_gl)
    project.makepyfile(test_nothing="def test_nothing(): pass")
    result = project.runpytest("--pbrlab-tolerance-profile", "llvmpipe")
    result.assert_outcomes(passed=1)
    result.stdout.fnmatch_lines(["pbrlab: no OpenGL library could be loaded (test)"])


def test_update_goldens_is_the_only_way_a_golden_is_written(project):
    project.makepyfile(test_chart=CHART_TEST.format(level=0.5))
    goldens_dir = project.path / "goldens" / "charts"

    missing = project.runpytest()
    missing.assert_outcomes(failed=1)
    missing.stdout.fnmatch_lines(["*golden 'charts/flat' is missing*",
                                  "*rerun pytest with the option --update-goldens*",
                                  "*pytest --update-goldens*test_chart.py::test_chart*"])
    assert not goldens_dir.exists()

    written = project.runpytest("--update-goldens")
    written.assert_outcomes(passed=1)
    written.stdout.fnmatch_lines(["pbrlab: wrote 1 golden(s) under *goldens*"])
    assert sorted(p.name for p in goldens_dir.iterdir()) == ["flat.exr", "flat.json", "flat.png"]

    project.runpytest().assert_outcomes(passed=1)
    assert not (project.path / "test-output" / "index.html").exists()


def test_read_only_check_never_writes_even_under_update_goldens(project):
    """The HLSL renders compare with the GLSL goldens and must never replace them."""
    read_only = CHART_TEST.format(level=0.5).replace('srgb8)', 'srgb8, read_only=True)')
    project.makepyfile(test_chart=read_only)
    goldens_dir = project.path / "goldens" / "charts"
    project.runpytest("--update-goldens").assert_outcomes(failed=1)  # missing, and not written
    assert not goldens_dir.exists()

    project.makepyfile(test_chart=CHART_TEST.format(level=0.5))
    project.runpytest("--update-goldens").assert_outcomes(passed=1)
    before = {p.name: p.read_bytes() for p in goldens_dir.iterdir()}
    project.makepyfile(test_chart=read_only.replace("LEVEL = 0.5", "LEVEL = 0.75"))
    project.runpytest("--update-goldens").assert_outcomes(failed=1)  # a mismatch stays one
    assert {p.name: p.read_bytes() for p in goldens_dir.iterdir()} == before


def _assert_failure_page(project):
    output = project.path / "test-output"
    page = (output / "index.html").read_text()
    assert "1 golden failure" in page and "test_chart.py::test_chart" in page
    for image in ("expected", "obtained", "diff"):
        assert f'src="charts/flat/{image}.png"' in page
        assert (output / "charts" / "flat" / f"{image}.png").exists()
    assert "max abs" in page


def test_failure_leaves_artefacts_and_an_index_page(project):
    project.makepyfile(test_chart=CHART_TEST.format(level=0.5))
    project.runpytest("--update-goldens").assert_outcomes(passed=1)
    project.makepyfile(test_chart=CHART_TEST.format(level=0.75))
    result = project.runpytest()
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*linear EXR  FAIL*", "pbrlab: 1 golden failure(s)*index.html"])
    _assert_failure_page(project)

    project.makepyfile(test_chart=CHART_TEST.format(level=0.5))
    project.runpytest().assert_outcomes(passed=1)  # a green run removes the stale page
    assert not (project.path / "test-output" / "index.html").exists()


def test_test_output_holds_only_this_runs_failures(project):
    """Issue 36: a failure's images went away only when the same golden passed again, so a run
    that no longer checks it (another -k, a renamed test) kept the last run's images beside its
    own. A file the user put in test-output/ stays."""
    project.makepyfile(test_chart=CHART_TEST.format(level=0.5))
    project.runpytest("--update-goldens").assert_outcomes(passed=1)
    project.makepyfile(test_chart=CHART_TEST.format(level=0.75))
    project.runpytest().assert_outcomes(failed=1)
    output = project.path / "test-output"
    stale = output / "charts" / "flat"
    assert (stale / "obtained.png").exists()  # control: the failure left its images
    (output / "notes.txt").write_text("mine")

    project.runpytest("-k", "not test_chart").assert_outcomes(deselected=1)
    assert not stale.exists() and not (output / "charts").exists()
    assert sorted(p.name for p in output.iterdir()) == ["notes.txt"]


BROKEN_SHADER_TEST = """
from pathlib import Path
import numpy as np
from pbrlab import evaluate

def test_rim():
    evaluate("my_rim(x)", includes=["rim.glsl"], include_dirs=[Path(__file__).parent], x=np.zeros(1, np.float32))
"""
BROKEN_RIM = "float my_rim(float NdotV) {\n    float x = undefined_thing;\n    return NdotV + y;\n}\n"
# The failure section's lines (between its "___ test_rim ___" header and the next section)
# within which the first error must stand, and its most lines: the error line, the two
# messages of the second line, the what-failed line, a blank, the test's line and its
# statement, the --tb hint.
FIRST_ERROR_WITHIN = 1
SECTION_MOST_LINES = 10


def _failure_section(lines: list[str]) -> list[str]:
    start = next(i for i, line in enumerate(lines) if line.strip("_ ") == "test_rim")
    end = next(i for i in range(start + 1, len(lines)) if lines[i].startswith(("pbrlab:", "====")))
    return lines[start + 1:end]


def test_a_shader_error_in_a_test_shows_the_first_compiler_message_first(project):
    """Issue 36: the compiler's first message came after about 60 lines of the harness's
    traceback and a cascade of follow-on errors."""
    project.makepyfile(test_rim=BROKEN_SHADER_TEST)
    (project.path / "rim.glsl").write_text(BROKEN_RIM)
    section = _failure_section(project.runpytest().outlines)
    rim = project.path / "rim.glsl"
    assert section[FIRST_ERROR_WITHIN - 1].startswith(f"ShaderCompileError: {rim}:2:"), section
    assert "undefined_thing" in section[FIRST_ERROR_WITHIN - 1]
    assert len(section) <= SECTION_MOST_LINES, section
    test_line = next(i for i, line in enumerate(section) if re.match(r"test_rim\.py:\d+: in test_rim$", line))
    assert section[test_line + 1].strip().startswith('evaluate("my_rim(x)"'), section
    assert not any("evaluator.py" in line for line in section), section
    # Control: pytest's own long report (asked for) has the harness's frames and runs longer,
    # so the short section above is the plugin's doing.
    long = _failure_section(project.runpytest("--tb=long").outlines)
    assert any("evaluator.py" in line for line in long) and len(long) > 3 * SECTION_MOST_LINES


def test_index_page_is_written_by_the_controller_under_xdist(project):
    project.makepyfile(test_chart=CHART_TEST.format(level=0.5))
    project.runpytest("--update-goldens").assert_outcomes(passed=1)
    project.makepyfile(test_chart=CHART_TEST.format(level=0.25),
                       test_other="def test_other(gl_context): assert gl_context.version_code >= 330")
    result = project.runpytest("-n", "2")
    result.assert_outcomes(passed=1, failed=1)
    _assert_failure_page(project)
    _assert_names_the_renderer(result.outlines)  # a worker's renderer reaches the controller
