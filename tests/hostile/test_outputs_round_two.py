"""Issue 26 (round two), nothing lost: the bench's report (JSON, markdown tables, Pareto
plots), the demo's contact sheets and index, and the other figure and file writers go
through the all-or-nothing output layer (pbrlab.foundation.outputs). A disk that fills up part-way
through a write (simulated: files opened for writing in the folder share a byte budget, and
the write that passes it writes what fits and raises ENOSPC, as a full disk does) leaves
every previous good file as it was, names the file it could not write, and leaves no
temporary. A bench run takes minutes: the writers are tested directly with small data."""

import builtins
import errno
import io
import os
import json
from pathlib import Path

import numpy as np
import pytest

from pbrlab.commands import cli
from pbrlab.checking import contact_sheets
from pbrlab.foundation import outputs
from pbrlab.bench import report
from pbrlab.foundation.errors import PbrlabError

OLD = b"the previous good file"


class _FillingFile:
    """A file object whose writes draw on the disk's remaining bytes."""

    def __init__(self, real, disk):
        self._real, self._disk = real, disk

    def write(self, data):
        size = len(data)
        if size <= self._disk.free:
            self._disk.free -= size
            return self._real.write(data)
        fits, self._disk.free = self._disk.free, 0
        self._real.write(data[:fits])
        self._real.flush()
        raise OSError(errno.ENOSPC, "No space left on device")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return self._real.__exit__(*exc)

    def __iter__(self):
        return iter(self._real)

    def __getattr__(self, name):
        return getattr(self._real, name)


class _FullDisk:
    """Every file opened for writing inside ``folder`` (through open, io.open, Path.write_*,
    matplotlib and Pillow alike) shares ``free`` bytes."""

    def __init__(self, folder: Path, free: int, monkeypatch):
        self.folder, self.free = folder.resolve(), free
        real_open = builtins.open

        def filling_open(file, mode="r", *args, **kwargs):
            handle = real_open(file, mode, *args, **kwargs)
            writing = any(flag in mode for flag in "wax+")
            inside = isinstance(file, (str, Path)) and Path(file).resolve().parent == self.folder
            return _FillingFile(handle, self) if writing and inside else handle
        monkeypatch.setattr(builtins, "open", filling_open)
        monkeypatch.setattr(io, "open", filling_open)


def _ours(folder: Path):
    return sorted(p.name for p in folder.iterdir() if ".tmp" in p.name)


def _family(name="fresnel"):
    variants = [{"name": n, "error": {"max_rel": err}, "instructions": {"per_eval": cost},
                 "gpu_isa": None} for n, err, cost in (("exact", 1e-7, 40.0), ("schlick", 3e-3, 12.0))]
    return {"name": name, "title": f"{name} (test)", "exact": "exact", "variants": variants}


def _doc():
    return {"schema": report.SCHEMA_ID, "quick": True, "families": [_family("fresnel"), _family("ggx")],
            "gpu_isa": {"available": False, "reason": "not measured in this test"},
            "padding": "x" * 4000}


def _markdown(doc):
    return "# Accuracy versus cost (test)\n\n" + "\n".join(f"## {f['name']}" for f in doc["families"]) + "\n"


def test_a_full_disk_keeps_the_previous_accuracy_cost_json(tmp_path, monkeypatch, census):
    """The reported fault: `bench --out DIR` on a nearly full disk left cut-off JSON."""
    target = tmp_path / "accuracy_cost.json"
    target.write_bytes(OLD)
    _FullDisk(tmp_path, 1000, monkeypatch)  # the document is over 4000 bytes
    with pytest.raises(PbrlabError, match=f"cannot write {target}: No space left on device"):
        report.write_json(_doc(), target)
    assert target.read_bytes() == OLD and _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


def test_a_full_disk_keeps_the_previous_pareto_plot(tmp_path, monkeypatch, census):
    plot = tmp_path / "fresnel.png"
    plot.write_bytes(OLD)
    _FullDisk(tmp_path, 2000, monkeypatch)  # a plot is tens of kilobytes
    with pytest.raises(PbrlabError, match=f"cannot write {plot}: No space left on device"):
        report.pareto_plot(_family(), plot, quick=True)
    assert plot.read_bytes() == OLD and _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


@pytest.mark.parametrize("free_after", ["json", "markdown", "first plot"])
def test_the_bench_report_is_written_whole_or_not_at_all(tmp_path, monkeypatch, free_after, census):
    """JSON, tables and plots are one set: the disk filling at any of them keeps every
    previous file, so the tables never describe a different run from the JSON."""
    monkeypatch.setattr(report, "markdown", _markdown)
    doc = _doc()
    paths = report.report_paths(doc, tmp_path)
    for path in paths:
        path.write_bytes(OLD)
    json_size = len(json.dumps(doc, indent=1)) + 1
    free = {"json": json_size // 2, "markdown": json_size + 10, "first plot": json_size + 200}[free_after]
    failing = {"json": paths[0], "markdown": paths[1], "first plot": paths[2]}[free_after]
    _FullDisk(tmp_path, free, monkeypatch)
    with pytest.raises(PbrlabError, match=f"cannot write {failing}: No space left on device"):
        report.write_report(doc, tmp_path)
    assert [p.read_bytes() for p in paths] == [OLD] * len(paths)
    assert _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


def test_the_bench_report_replaces_every_file_when_there_is_room(tmp_path, monkeypatch, census):
    monkeypatch.setattr(report, "markdown", _markdown)
    doc = _doc()
    for path in report.report_paths(doc, tmp_path):
        path.write_bytes(OLD)
    written = report.write_report(doc, tmp_path)
    assert [p.name for p in written] == ["accuracy_cost.json", "accuracy_cost.md", "fresnel.png", "ggx.png"]
    assert json.loads(written[0].read_text()) == doc
    assert written[1].read_text().startswith("# Accuracy versus cost (test)")
    for plot in written[2:]:
        assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert plot.read_bytes().endswith(outputs.PNG_TRAILER)
    assert _ours(tmp_path) == []
    census["output fault", "handled"] += 1


def test_bench_out_that_is_a_file_is_refused_before_measuring(tmp_path, capsys, census):
    not_a_folder = tmp_path / "report"
    not_a_folder.write_bytes(OLD)
    assert cli.main(["bench", "--quick", "--family", "fresnel", "--out", str(not_a_folder)]) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and f"--out {not_a_folder}: exists and is not a directory" in err, err
    assert not_a_folder.read_bytes() == OLD
    census["output fault", "refused cleanly"] += 1


def test_a_full_disk_keeps_the_previous_demo_sheet_and_index(tmp_path, monkeypatch, census):
    sheet, index = tmp_path / "lit_scene_high_sheet.png", tmp_path / "index.html"
    sheet.write_bytes(OLD)
    index.write_bytes(OLD)
    _FullDisk(tmp_path, 1500, monkeypatch)
    pixels = np.full((24, 32, 4), 128, np.uint8)
    with pytest.raises(PbrlabError, match=f"cannot write {sheet}: No space left on device"):
        contact_sheets.write_sheet(sheet, "lit_scene_high", pixels, "matches goldens/lit_scene_high")
    entries = [{"name": "lit_scene_high", "status": "matches " + "x" * 2000, "sheet": sheet.name,
                "png": "lit_scene_high.png", "exr": "lit_scene_high.exr"}]
    with pytest.raises(PbrlabError, match=f"cannot write {index}: No space left on device"):
        contact_sheets.write_index(index, entries)
    assert sheet.read_bytes() == OLD and index.read_bytes() == OLD and _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


def test_a_full_disk_keeps_the_previous_radiance_hdr(tmp_path, monkeypatch, census):
    from pbrlab.checking import sample_viewer
    hdr = tmp_path / "sky.hdr"
    hdr.write_bytes(OLD)
    _FullDisk(tmp_path, 100, monkeypatch)
    with pytest.raises(PbrlabError, match=f"cannot write {hdr}: No space left on device"):
        sample_viewer.write_radiance_hdr(hdr, np.ones((8, 16, 3), np.float32))
    assert hdr.read_bytes() == OLD and _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


def test_a_figure_cut_short_without_an_error_is_caught_by_its_end_marker(tmp_path, census):
    """A writer that returns without complaint but leaves a truncated PNG (a device that
    loses the tail) is refused before the rename."""
    class ShortFigure:
        def savefig(self, path, format=None):
            Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + b"\0" * 64)
    target = tmp_path / "plot.png"
    target.write_bytes(OLD)
    with pytest.raises(PbrlabError, match=f"cannot write {target}: the file written is cut short"):
        outputs.write_figure(target, ShortFigure())
    assert target.read_bytes() == OLD and _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


def test_a_real_full_disk_keeps_the_previous_bench_report(tmp_path, monkeypatch, census):
    """The reported fault on a real file system: a 64 KiB tmpfs (root only), the previous
    report on it, then filled to within a few kilobytes of full."""
    import subprocess
    disk = tmp_path / "tiny"
    disk.mkdir()
    if os.geteuid() != 0 or subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(disk)],
                                           capture_output=True).returncode != 0:
        pytest.skip("mounting a 64 KiB tmpfs needs root (the simulated full disk tests cover this)")
    try:
        monkeypatch.setattr(report, "markdown", _markdown)
        doc = _doc()
        paths = report.report_paths(doc, disk)
        for path in paths:
            path.write_bytes(OLD)
        (disk / "filler").write_bytes(b"\0" * (64 * 1024 - 4 * 4096 - 6000))
        with pytest.raises(PbrlabError, match=f"cannot write {disk}/.*: No space left on device"):
            report.write_report(doc, disk)
        assert [p.read_bytes() for p in paths] == [OLD] * len(paths)
        assert _ours(disk) == []
        census["output fault", "refused cleanly"] += 1
    finally:
        subprocess.run(["umount", str(disk)], check=False)
