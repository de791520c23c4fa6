"""Issue 39 (round three), outputs that destroyed what they replaced. An output was written
to a temporary and renamed over its name: as root that replaced a device node (``schema -o
/dev/null``) or the link ``/dev/stdout`` with a regular file, and a rename over a link replaced
the link. Now (pbrlab.foundation.output_targets, docs/faults.md): devices that take any bytes,
this process's streams and FIFOs with a reader are written through and stay what they were;
other devices, sockets and FIFOs without a reader are refused; a link to a regular file in its
folder has its target replaced and stays a link, one leading out of the folder is refused. An
input is never an output: ``pbrlab demo --out goldens`` and a Unity material's texture
property named as ``-o`` are refused with every file intact.

Device nodes are made with mknod in the test's own folder (root only), never the machine's
/dev; a guard on ``os.replace`` fails a test, rather than damaging the machine, if anything
would rename over a path under /dev or the checkout's goldens (so the suite can be run against
an implementation without these rules)."""

import json
import os
import shutil
import socket
import stat
import threading
from pathlib import Path

import numpy as np
import pytest

from hostile_common import UNITY_TEXTURE, base_scene
from pbrlab.commands import cli
from pbrlab.foundation import images
from pbrlab.foundation.locations import checkout_folder

ROOT = os.geteuid() == 0
needs_root = pytest.mark.skipif(not ROOT, reason="mknod (device nodes) needs root")


@pytest.fixture(autouse=True)
def no_rename_over_devices_or_goldens(monkeypatch):
    """Fail, never damage: a rename onto /dev or into the checkout's goldens is an error here."""
    real_replace = os.replace
    goldens = checkout_folder("goldens")
    guarded = [os.path.realpath("/dev")] + ([os.path.realpath(goldens)] if goldens else [])

    def replace(src, dst, **kw):
        where = os.path.realpath(os.path.dirname(os.path.abspath(dst)))
        for folder in guarded:
            if where == folder or where.startswith(folder + os.sep):
                raise AssertionError(f"would rename a file over {dst}")
        return real_replace(src, dst, **kw)
    monkeypatch.setattr(os, "replace", replace)


def _node(path: Path, kind: int, major: int, minor: int) -> os.stat_result:
    os.mknod(path, kind | 0o666, os.makedev(major, minor))
    return os.lstat(path)


def _same_node(path: Path, before: os.stat_result) -> bool:
    after = os.lstat(path)
    return (stat.S_IFMT(after.st_mode), after.st_rdev, after.st_ino) == \
        (stat.S_IFMT(before.st_mode), before.st_rdev, before.st_ino)


def _schema(capsys, target) -> tuple[int, str, str]:
    status = cli.main(["schema", "-o", str(target)])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def _schema_text() -> str:
    from pbrlab.scene.schema import scene_schema
    return json.dumps(scene_schema(), indent=2) + "\n"


def _leftovers(folder: Path) -> list:
    return sorted(p.name for p in folder.iterdir() if ".tmp" in p.name)


@needs_root
@pytest.mark.parametrize("through_link", [False, True], ids=["the node", "a link to it"])
def test_a_null_device_is_written_through_and_stays_a_device(tmp_path, capsys, through_link, census):
    null = tmp_path / "null"
    before = _node(null, stat.S_IFCHR, 1, 3)
    target = null
    if through_link:
        target = tmp_path / "schema.json"
        target.symlink_to(null)
    status, _, err = _schema(capsys, target)
    assert status == 0, err
    assert _same_node(null, before), "the device node was replaced"
    assert not through_link or os.readlink(target) == str(null)
    assert _leftovers(tmp_path) == []
    census["output not a regular file", "handled"] += 1


def test_dev_stdout_is_written_through_and_stays_a_link(capfd, census):
    """The machine's own /dev/stdout (a link, never renamed over: the guard above)."""
    before = os.lstat("/dev/stdout")
    status = cli.main(["schema", "-o", "/dev/stdout"])
    out, err = capfd.readouterr()
    assert status == 0, err
    assert out == _schema_text()
    assert _same_node(Path("/dev/stdout"), before)
    census["output not a regular file", "handled"] += 1


@needs_root
def test_a_full_device_is_refused_with_its_reason_and_stays(tmp_path, capsys, census):
    full = tmp_path / "full"
    before = _node(full, stat.S_IFCHR, 1, 7)
    status, _, err = _schema(capsys, full)
    assert status == 2 and "No space left on device" in err and "Traceback" not in err, err
    assert _same_node(full, before) and _leftovers(tmp_path) == []
    census["output not a regular file", "refused cleanly"] += 1


@needs_root
@pytest.mark.parametrize("kind, major, minor, says", [
    (stat.S_IFBLK, 7, 0, "block device"),       # a loop disk
    (stat.S_IFCHR, 1, 1, "character device"),   # /dev/mem
    (stat.S_IFCHR, 1, 8, "character device"),   # /dev/random
], ids=["block device", "memory device", "random device"])
def test_other_devices_are_refused_before_any_work(tmp_path, capsys, kind, major, minor, says, census):
    node = tmp_path / "dev"
    before = _node(node, kind, major, minor)
    status, _, err = _schema(capsys, node)
    assert status == 2 and says in err and str(node) in err and "Traceback" not in err, err
    assert _same_node(node, before) and _leftovers(tmp_path) == []
    census["output not a regular file", "refused cleanly"] += 1


def test_a_socket_is_refused(tmp_path, capsys, census):
    path = tmp_path / "s.sock"
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as server:
        server.bind(str(path))
        before = os.lstat(path)
        status, _, err = _schema(capsys, path)
        assert status == 2 and "socket" in err and "Traceback" not in err, err
        assert _same_node(path, before)
    census["output not a regular file", "refused cleanly"] += 1


def test_a_fifo_with_a_reader_gets_every_byte_and_stays_a_fifo(tmp_path, capsys, census):
    """The reader's end is open before the command runs (a non-blocking open for reading needs
    no writer); the schema (34 KB) fits the pipe's buffer (64 KiB on Linux, pipe(7)), so the
    write completes before the test reads it back."""
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    before = os.lstat(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
    try:
        status, _, err = _schema(capsys, fifo)
        os.set_blocking(reader, True)
        chunks = []
        while status == 0 and (chunk := os.read(reader, 1 << 16)):
            chunks.append(chunk)
    finally:
        os.close(reader)
    assert status == 0, err
    assert b"".join(chunks) == _schema_text().encode()
    assert _same_node(fifo, before) and _leftovers(tmp_path) == []
    census["output not a regular file", "handled"] += 1


def test_a_fifo_nobody_reads_is_refused_at_once(tmp_path, capsys, census):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    before = os.lstat(fifo)
    result = []
    worker = threading.Thread(target=lambda: result.append(_schema(capsys, fifo)), daemon=True)
    worker.start()
    worker.join(timeout=20)
    assert result, "writing to a FIFO with no reader hung"
    status, _, err = result[0]
    assert status == 2 and "no process reads" in err, err
    assert _same_node(fifo, before)
    census["output not a regular file", "refused cleanly"] += 1


def test_a_link_to_a_file_in_its_folder_replaces_the_file_and_stays_a_link(tmp_path, capsys, census):
    (tmp_path / "real").mkdir()
    real = tmp_path / "real" / "schema.json"
    real.write_text("old")
    link = tmp_path / "out.json"
    link.symlink_to("real/schema.json")
    status, _, err = _schema(capsys, link)
    assert status == 0, err
    assert link.is_symlink() and os.readlink(link) == "real/schema.json"
    assert real.read_text() == _schema_text()
    assert _leftovers(tmp_path) == [] and _leftovers(tmp_path / "real") == []
    census["output through a link", "handled"] += 1


@pytest.mark.parametrize("dangling", [False, True], ids=["to a file", "to no file yet"])
def test_a_link_out_of_the_output_folder_is_refused(tmp_path, capsys, dangling, census):
    """An unpacked archive's ``out.json -> ../elsewhere/precious``: refused, both ends intact."""
    (tmp_path / "outdir").mkdir()
    (tmp_path / "elsewhere").mkdir()
    precious = tmp_path / "elsewhere" / "precious"
    if not dangling:
        precious.write_text("precious")
    link = tmp_path / "outdir" / "out.json"
    link.symlink_to("../elsewhere/precious")
    status, _, err = _schema(capsys, link)
    assert status == 2 and "symbolic link" in err and "outside" in err and "Traceback" not in err, err
    assert link.is_symlink()
    assert (precious.read_text() == "precious") if not dangling else not precious.exists()
    census["output through a link", "refused cleanly"] += 1


def test_a_dangling_link_inside_the_folder_creates_its_file(tmp_path, capsys, census):
    link = tmp_path / "out.json"
    link.symlink_to("made.json")
    status, _, err = _schema(capsys, link)
    assert status == 0, err
    assert link.is_symlink() and (tmp_path / "made.json").read_text() == _schema_text()
    census["output through a link", "handled"] += 1


def test_demo_never_writes_into_the_goldens(tmp_path, capsys, census):
    """``pbrlab demo --out goldens`` in the checkout, and ``--out``/``--goldens`` naming one
    folder anywhere: refused before any render, every golden byte for byte as it was."""
    goldens = checkout_folder("goldens")
    assert goldens is not None, "run from the checkout: the goldens are in its goldens/ folder"
    copy = tmp_path / "goldens"
    copy.mkdir()
    for name in ("chart_f0.png", "chart_f0.exr", "chart_f0.json"):
        shutil.copy(goldens / name, copy / name)
    before = {p: p.read_bytes() for p in copy.iterdir()}
    cwd = os.getcwd()
    os.chdir(goldens.parent)
    try:
        status = cli.main(["demo", "--out", "goldens"])
    finally:
        os.chdir(cwd)
    err = capsys.readouterr().err
    assert status == 2 and "goldens" in err and "Traceback" not in err, err
    for out in (copy, copy / "sub"):
        status = cli.main(["demo", "--out", str(out), "--goldens", str(copy)])
        err = capsys.readouterr().err
        assert status == 2 and "goldens" in err, err
    assert {p: p.read_bytes() for p in copy.iterdir()} == before
    census["output = input", "refused cleanly"] += 1




@pytest.mark.parametrize("named", ["as written", "through a link"])
def test_a_unity_texture_property_is_never_the_output(tmp_path, capsys, named, census):
    images.write_png(tmp_path / "tex.png", np.full((4, 4, 4), 200, np.uint8))
    before = (tmp_path / "tex.png").read_bytes()
    (tmp_path / "tex.shader").write_text(UNITY_TEXTURE)
    scene = base_scene()
    scene["materials"]["m"] = {"surface": "tex.shader", "properties": {"_MainTex": {"path": "tex.png"}}}
    (tmp_path / "scene.json").write_text(json.dumps(scene))
    out = tmp_path / "tex.png"
    if named == "through a link":
        out = tmp_path / "out.png"
        out.symlink_to("tex.png")
    status = cli.main(["render", str(tmp_path / "scene.json"), "-o", str(out)])
    err = capsys.readouterr().err
    assert status == 2 and "_MainTex texture property" in err and "Traceback" not in err, err
    assert (tmp_path / "tex.png").read_bytes() == before
    census["output = input", "refused cleanly"] += 1
