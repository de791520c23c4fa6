"""pytest plugin for projects that test shaders with pbrlab (entry point ``pytest11: pbrlab``).

Options:
    - ``--update-goldens``: write goldens from this run's renders: the only way goldens change
    - ``--pbrlab-output DIR``: failure artefacts and index.html (default: test-output/ in the rootdir)
    - ``--pbrlab-tolerance-profile NAME``: the tolerances goldens are checked with (default: auto,
      by GL renderer)
    - ``--pbrlab-goldens DIR``: the golden root (default: goldens/ in the rootdir)

Fixtures:
    - ``gl_context``: the process's shared moderngl context, made current for each test (under
      pytest-xdist each worker process has its own)
    - ``golden``: ``golden.check(name, linear, srgb8, tolerance)``,
      ``pbrlab.checking.goldens.check_golden`` with this run's renderer info, update flag and folders

The plugin is inert until a test uses one of its fixtures or options: registering it (by
installing pbrlab) opens no GL context, changes no environment variable (llvmpipe's CPU caps
are pinned by ``gl.create_context``, when pbrlab makes a context) and prints nothing. When a
test used ``gl_context`` or ``golden``, the summary names the renderer (GL_RENDERER,
GL_VERSION, Mesa, moderngl and OpenImageIO versions, llvmpipe CPU caps); given a pbrlab
option on the command line, the run header does, before the tests.

At the end of the session the controller (also under ``-n auto``) writes
``test-output/index.html`` with expected / obtained / diff side by side for every golden
failure; each failing check (in whichever process) leaves a small JSON record in
``test-output/.pbrlab-records/`` for it. No failure, no page.
"""

from __future__ import annotations

import html
import json
import os
import shutil
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from ..foundation import golden_names
from ..foundation.errors import PbrlabError, ShaderCompileError

if TYPE_CHECKING:
    from .compare import DiffResult, Tolerance

# Registering the plugin (every pytest run where pbrlab is installed) imports this module and
# nothing heavy: numpy, moderngl, OpenImageIO and the golden store load when a test uses a
# fixture (tests/foundation/test_import_cost.py checks; benchmarks/startup.py measures).

RECORDS_DIR = ".pbrlab-records"
INDEX_NAME = "index.html"
_SETTINGS = pytest.StashKey["_Settings"]()
_SUMMARY = pytest.StashKey[dict]()
_RENDERER = pytest.StashKey[dict]()  # this process's renderer, once a test used a pbrlab context
_HEADER_SHOWN = pytest.StashKey[bool]()
_WORKER_KEY = "pbrlab_renderer"  # xdist: a worker's renderer, sent back in workeroutput


class _Settings:
    def __init__(self, config: pytest.Config):
        self.update = bool(config.getoption("update_goldens"))
        self.output_dir = _folder(config, "pbrlab_output", golden_names.DEFAULT_OUTPUT_DIR)
        self.root = _folder(config, "pbrlab_goldens", golden_names.DEFAULT_ROOT)
        self.records_dir = self.output_dir / RECORDS_DIR
        self.profile = config.getoption("pbrlab_tolerance_profile")


def _folder(config: pytest.Config, option: str, default: str) -> Path:
    """A folder option: relative to where pytest was started; the default is in the rootdir."""
    value = config.getoption(option)
    if value is None:
        return config.rootpath / default
    return Path(config.invocation_params.dir, value).absolute()


def _is_xdist_worker(config: pytest.Config) -> bool:
    return hasattr(config, "workerinput")


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("pbrlab", "pbrlab goldens")
    group.addoption("--update-goldens", action="store_true", default=False,
                    help="write goldens from this run's renders instead of comparing "
                         "(the only way goldens change); review them before committing")
    group.addoption("--pbrlab-output", metavar="DIR", default=None,
                    help="where golden failures leave expected/obtained/diff images and "
                         "index.html (default: test-output in the rootdir)")
    group.addoption("--pbrlab-tolerance-profile", metavar="NAME", default="auto",
                    choices=("auto", *golden_names.TOLERANCE_PROFILE_NAMES),
                    help="tolerances goldens are checked with: llvmpipe (bit-identical "
                         "renders), gpu (measured on a real GPU), or auto (by GL_RENDERER; "
                         "the default)")
    group.addoption("--pbrlab-goldens", metavar="DIR", default=None,
                    help="golden root (default: goldens in the rootdir)")


def pytest_configure(config: pytest.Config) -> None:
    settings = _Settings(config)
    config.stash[_SETTINGS] = settings
    # A failure page of an earlier pbrlab run goes, with the records it was built from; a
    # project that never used pbrlab has no records folder, and nothing of its is touched.
    # Workers start after this, so they never lose a record of this run.
    # So are the images its failures left (each record lists them): test-output/ holds only
    # this run's, even where this run does not check those goldens again.
    if not _is_xdist_worker(config) and settings.records_dir.is_dir():
        _remove_recorded_artefacts(settings.output_dir, _load_records(settings.records_dir))
        shutil.rmtree(settings.records_dir, ignore_errors=True)
        (settings.output_dir / INDEX_NAME).unlink(missing_ok=True)
        try:
            settings.output_dir.rmdir()  # only when nothing else is in it
        except OSError:
            pass


def _remove_recorded_artefacts(output_dir: Path, records: list[dict]) -> None:
    """Delete the artefact files the records name, then each folder they leave empty, up to
    ``output_dir`` (a file pbrlab did not write keeps its folder)."""
    output_dir = output_dir.resolve()
    for record in records:
        for relative in (record.get("artefacts") or {}).values():
            path = (output_dir / relative).resolve()
            if output_dir not in path.parents:
                continue  # a record names only files under the output folder; never follow one out
            path.unlink(missing_ok=True)
            for folder in path.parents:
                if folder == output_dir:
                    break
                try:
                    folder.rmdir()
                except OSError:  # absent, or holds files of this run or of the user: leave it
                    break


def _options_given(config: pytest.Config) -> bool:
    """True when the command line names one of the plugin's options."""
    return bool(config.getoption("update_goldens")
                or config.getoption("pbrlab_output") is not None
                or config.getoption("pbrlab_goldens") is not None
                or config.getoption("pbrlab_tolerance_profile") != "auto")


def _renderer_lines(info: dict) -> list[str]:
    return [
        f"pbrlab: GL_RENDERER {info['GL_RENDERER']}; GL_VERSION {info['GL_VERSION']}",
        f"pbrlab: Mesa {info['mesa']}, moderngl {info['moderngl']}, "
        f"OpenImageIO {info['openimageio']}, backend {info['backend']}, "
        f"llvmpipe CPU caps {info['llvmpipe_cpu_caps']}",
    ]


def pytest_report_header(config: pytest.Config) -> list[str]:
    if not _options_given(config):
        return []  # inert: no context, no line (the summary names the renderer if a test used one)
    config.stash[_HEADER_SHOWN] = True
    try:
        from ..gpu import gl
        info = gl.context_info(gl.shared_context())
    except PbrlabError as exc:  # no GL library: say so instead of failing collection
        return [f"pbrlab: {exc}"]
    return _renderer_lines(info)


def _shared_context_for(config: pytest.Config):
    """The shared context for a test, noting its renderer for the summary."""
    from ..gpu import gl
    try:
        context = gl.shared_context()
    except PbrlabError as exc:
        pytest.fail(str(exc), pytrace=False)
    if _RENDERER not in config.stash:
        config.stash[_RENDERER] = gl.context_info(context)
    return context


@pytest.fixture
def gl_context(request):
    """The process's shared moderngl context (``pbrlab.gpu.gl.shared_context()``), made
    current for this test (another test may have made an OSMesa context current)."""
    return _shared_context_for(request.config)


class GoldenFixture:
    """``check(name, linear, srgb8, tolerance)`` against the golden store of this run."""

    def __init__(self, settings: _Settings, info: dict, nodeid: str):
        self.settings = settings
        self.info = info
        self.nodeid = nodeid
        self.update = settings.update
        self.root = settings.root
        self.output_dir = settings.output_dir

    def check(self, name: str, linear, srgb8, tolerance: Tolerance | None = None, *,
              srgb_tolerance: Tolerance | None = None, read_only: bool = False) -> DiffResult:
        """``read_only``: a render that must match a golden another path made (the HLSL twin
        of a GLSL render) compares, and never writes, even under --update-goldens.
        Tolerances not given come from ``--pbrlab-tolerance-profile``."""
        __tracebackhide__ = True
        from . import goldens
        update = self.update and not read_only
        try:
            result = goldens.check_golden(
                name, linear, srgb8, tolerance, self.info, update=update, root=self.root,
                output_dir=self.output_dir, srgb_tolerance=srgb_tolerance, nodeid=self.nodeid,
                profile=self.settings.profile)
        except goldens.GoldenFailure as failure:
            self._record(failure.kind, name, message=str(failure), linear=failure.linear,
                         srgb=failure.srgb, artefacts=failure.artefacts)
            raise
        if update:
            self._record("updated", name)
        return result

    def _record(self, kind, name, *, message="", linear=None, srgb=None, artefacts=None):
        import secrets

        from . import goldens
        from ..foundation import outputs
        record = {
            "kind": kind, "name": name, "nodeid": self.nodeid, "message": message,
            "linear": linear.to_dict() if linear else None,
            "srgb": srgb.to_dict() if srgb else None,
            "artefacts": {label: os.path.relpath(path, self.output_dir)
                          for label, path in (artefacts or {}).items()},
            "golden": str(goldens.golden_paths(self.root, name).exr),
        }
        records = self.settings.records_dir
        records.mkdir(parents=True, exist_ok=True)
        outputs.write_file(records / f"{secrets.token_hex(8)}.json",
                           json.dumps(record, indent=1, default=str))


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo):
    """A shader that fails to compile is reported as the compiler's messages (the first error
    at its file and line first, compile_messages.py) and the test's own line, instead of the
    harness's frames above them; ``--tb`` given on the command line keeps pytest's report."""
    report = yield
    if (report.failed and call.excinfo is not None and call.excinfo.errisinstance(ShaderCompileError)
            and item.config.getoption("tbstyle", "auto") == "auto"):
        report.longrepr = _shader_failure(item, call.excinfo)
    return report


def _shader_failure(item: pytest.Item, excinfo: pytest.ExceptionInfo) -> str:
    lines = [f"{type(excinfo.value).__name__}: {excinfo.value}", ""]
    in_test = [entry for entry in excinfo.traceback if Path(entry.path) == Path(item.path)]
    if in_test:
        entry = in_test[-1]
        where = os.path.relpath(entry.path, item.config.rootpath)
        lines += [f"{where}:{entry.lineno + 1}: in {entry.name}", f"    {entry.statement.lines[0].strip()}"]
    lines.append("(pbrlab's pytest plugin left out the harness's frames; --tb=long shows them)")
    return "\n".join(lines)


@pytest.fixture(scope="session")
def _pbrlab_renderer_info(request) -> dict:
    from ..gpu import gl
    return gl.context_info(_shared_context_for(request.config))


@pytest.fixture
def golden(request, _pbrlab_renderer_info) -> GoldenFixture:
    """Compare renders against goldens (writes them under ``--update-goldens``)."""
    return GoldenFixture(request.config.stash[_SETTINGS], _pbrlab_renderer_info,
                         request.node.nodeid)


def _load_records(records_dir: Path) -> list[dict]:
    if not records_dir.is_dir():
        return []
    records = [json.loads(p.read_text(encoding="utf-8"))
               for p in records_dir.glob("*.json") if not p.name.startswith(".")]
    return sorted(records, key=lambda r: (r["nodeid"], r["name"]))


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node, error) -> None:
    """xdist controller: keep the renderer a worker used (the first one reported)."""
    info = getattr(node, "workeroutput", {}).get(_WORKER_KEY)
    if info and _RENDERER not in node.config.stash:
        node.config.stash[_RENDERER] = info


@pytest.hookimpl(tryfirst=True)  # before xdist sends workeroutput to the controller
def pytest_sessionfinish(session: pytest.Session, exitstatus) -> None:
    config = session.config
    if _is_xdist_worker(config):
        if _RENDERER in config.stash:
            config.workeroutput[_WORKER_KEY] = config.stash[_RENDERER]
        return
    if _SETTINGS not in config.stash:
        return
    settings = config.stash[_SETTINGS]
    records = _load_records(settings.records_dir)
    failures = [r for r in records if r["kind"] != "updated"]
    updated = sorted({r["name"] for r in records if r["kind"] == "updated"})
    index = None
    if failures:
        index = settings.output_dir / INDEX_NAME
        write_index(index, failures)
    config.stash[_SUMMARY] = {"failures": len(failures), "index": index, "updated": updated,
                              "root": settings.root}


def pytest_terminal_summary(terminalreporter, exitstatus, config: pytest.Config) -> None:
    if _RENDERER in config.stash and not config.stash.get(_HEADER_SHOWN, False):
        for line in _renderer_lines(config.stash[_RENDERER]):
            terminalreporter.write_line(line)
    summary = config.stash.get(_SUMMARY, None)
    if not summary:
        return
    if summary["updated"]:
        terminalreporter.write_line(
            f"pbrlab: wrote {len(summary['updated'])} golden(s) under {summary['root']}; "
            f"look at them (git status, git diff --stat) before committing")
    if summary["failures"]:
        terminalreporter.write_line(
            f"pbrlab: {summary['failures']} golden failure(s): expected / obtained / diff "
            f"side by side in {summary['index']}", red=True)


def _cell_image(record: dict, label: str) -> str:
    path = record["artefacts"].get(label)
    if not path:
        return '<td class="none">no golden yet</td>' if label == "expected" else "<td>-</td>"
    src = html.escape(Path(path).as_posix(), quote=True)
    return f'<td><a href="{src}"><img src="{src}" alt="{label}"></a></td>'


def _metrics(record: dict) -> str:
    lines = []
    for key, title in (("linear", "linear EXR"), ("srgb", "sRGB PNG")):
        result = record.get(key)
        if result:
            verdict = "ok" if result["passed"] else "FAIL"
            lines.append(f"<li><b>{title}: {verdict}</b> {html.escape(result['summary'])}<br>"
                         f"<small>tolerance: {html.escape(result['tolerance']['reason'])}</small></li>")
    return "<ul>" + "".join(lines) + "</ul>" if lines else ""


def write_index(path: Path, failures: list[dict]) -> None:
    """The HTML summary of golden failures: one row each, images side by side."""
    from importlib import resources
    from string import Template

    from ..foundation import outputs
    rows = []
    for record in failures:
        rows.append(
            "<tr>"
            f'<td class="what"><h2>{html.escape(record["name"])}</h2>'
            f'<p class="kind">{html.escape(record["kind"])}</p>'
            f'<p><code>{html.escape(record["nodeid"])}</code></p>'
            f'{_metrics(record)}<details><summary>message</summary>'
            f'<pre>{html.escape(record["message"])}</pre></details></td>'
            f'{_cell_image(record, "expected")}{_cell_image(record, "obtained")}'
            f'{_cell_image(record, "diff")}'
            "</tr>")
    template = Template(resources.files("pbrlab").joinpath("templates", "report.html")
                        .read_text(encoding="utf-8"))
    page = template.substitute(count=len(failures), rows="\n".join(rows))
    path.parent.mkdir(parents=True, exist_ok=True)
    outputs.write_file(path, page)
