"""Fault injection on every output path: writers that fail mid-way, a full disk (a 64 KiB
tmpfs when this runs as root, a simulated ENOSPC otherwise), files that land truncated,
SIGTERM, SIGINT and SIGKILL during a write. After each, every target holds its old bytes
or its complete new content, all outputs of one command or none, and no temporary file
of ours is left (a killed process's ones go on the next write to that folder)."""

import errno
import json
import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from hostile_common import base_scene
from pbrlab.commands import cli
from pbrlab.checking import goldens
from pbrlab.foundation import images, outputs
from pbrlab.foundation.errors import PbrlabError

OLD = b"the previous good file"


def _ours(folder: Path):
    return sorted(p.name for p in folder.iterdir() if ".tmp" in p.name)


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(base_scene()))
    return path


def _fail_on(suffix, how):
    """An _encode that misbehaves for targets ending in ``suffix``."""
    real = images._encode

    def encode(tmp, spec, pixels, target):
        if not str(target).endswith(suffix):
            return real(tmp, spec, pixels, target)
        if how == "raise midway":
            real(tmp, spec, pixels, target)
            with open(tmp, "r+b") as f:
                f.truncate(os.path.getsize(tmp) // 2)
            raise OSError(errno.ENOSPC, "No space left on device")
        if how == "truncate silently":
            real(tmp, spec, pixels, target)
            with open(tmp, "r+b") as f:
                f.truncate(os.path.getsize(tmp) - 7)
        elif how == "write nothing":
            pass
        elif how == "zero bytes":
            open(tmp, "wb").close()
    return encode


@pytest.mark.parametrize("how", ["raise midway", "truncate silently", "write nothing", "zero bytes"])
@pytest.mark.parametrize("failing", [".png", ".exr"])
def test_render_outputs_are_all_or_nothing_under_a_failing_writer(scene_file, tmp_path, monkeypatch,
                                                                  capsys, how, failing, census):
    png, exr = tmp_path / "out.png", tmp_path / "out.exr"
    png.write_bytes(OLD)
    exr.write_bytes(OLD)
    monkeypatch.setattr(images, "_encode", _fail_on(failing, how))
    assert cli.main(["render", str(scene_file), "-o", str(png), "--hdr", str(exr)]) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and f"cannot write {tmp_path / ('out' + failing)}" in err, err
    assert png.read_bytes() == OLD and exr.read_bytes() == OLD
    assert _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


def test_a_failing_fsync_is_a_full_disk_not_a_good_file(tmp_path, monkeypatch, census):
    target = tmp_path / "x.exr"
    target.write_bytes(OLD)

    def no_space(fd):
        raise OSError(errno.ENOSPC, "No space left on device")
    monkeypatch.setattr(outputs.os, "fsync", no_space)
    with pytest.raises(PbrlabError, match="cannot write .*x.exr: No space left on device"):
        images.write_exr(target, np.ones((4, 4, 3), np.float32))
    assert target.read_bytes() == OLD and _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


def test_update_goldens_writes_all_three_files_or_none(tmp_path, monkeypatch, census):
    linear = np.full((4, 4, 4), 0.5, np.float32)
    srgb = np.full((4, 4, 4), 188, np.uint8)
    goldens.check_golden("g", linear, srgb, update=True, root=tmp_path, output_dir=tmp_path / "out")
    paths = goldens.golden_paths(tmp_path, "g").all()
    before = [p.read_bytes() for p in paths]

    def broken(self, target, text):
        raise PbrlabError(f"cannot write {target}: No space left on device")
    monkeypatch.setattr(outputs.Transaction, "write_text", broken)
    with pytest.raises(PbrlabError, match="g.json: No space"):
        goldens.check_golden("g", linear * 2, srgb // 2, update=True, root=tmp_path,
                             output_dir=tmp_path / "out")
    assert [p.read_bytes() for p in paths] == before
    assert _ours(tmp_path) == []
    census["output fault", "refused cleanly"] += 1


def _tiny_tmpfs(path: Path) -> bool:
    if os.geteuid() != 0:
        return False
    path.mkdir()
    proc = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(path)],
                          capture_output=True)
    return proc.returncode == 0


def test_a_full_disk_keeps_the_good_file(scene_file, tmp_path, capsys, census):
    disk = tmp_path / "tiny"
    if not _tiny_tmpfs(disk):
        pytest.skip("mounting a 64 KiB tmpfs needs root (the simulated ENOSPC tests cover this)")
    try:
        good = disk / "out.png"
        assert cli.main(["render", str(scene_file), "-o", str(good)]) == 0
        kept = good.read_bytes()
        (disk / "filler").write_bytes(b"\0" * (64 * 1024 - len(kept) - 8192))
        assert cli.main(["render", str(scene_file), "-o", str(good), "--size", "300x300"]) == 2
        err = capsys.readouterr().err
        assert "Traceback" not in err and "cannot write" in err and str(good) in err
        assert good.read_bytes() == kept and _ours(disk) == []
        census["output fault", "refused cleanly"] += 1
    finally:
        subprocess.run(["umount", str(disk)], check=False)


# The child handles SIGINT as a process started from a terminal does (KeyboardInterrupt): one
# started by a runner that ignores SIGINT (a non-interactive shell's background job) inherits
# SIG_IGN, and Python then installs no handler (the test waited 60 s on a clean-clone CI run).
_SLOW_WRITER = textwrap.dedent("""
    import signal, sys, time
    signal.signal(signal.SIGINT, signal.default_int_handler)
    from pbrlab.commands import cli
    from pbrlab.foundation import images
    real = images._encode
    def slow(tmp, spec, pixels, target):
        real(tmp, spec, pixels, target)
        print("WRITING", flush=True)
        for _ in range(1200):  # 0.1 s steps: a process-directed signal may land on one of
            time.sleep(0.1)    # llvmpipe's threads, and Python runs its handler only when the
                               # main thread returns to the interpreter (one 120 s sleep: a CI timeout)
    images._encode = slow
    sys.exit(cli.main(sys.argv[1:]))
""")


@pytest.mark.parametrize("signum, status", [(signal.SIGTERM, 128 + signal.SIGTERM),
                                            (signal.SIGINT, 130), (signal.SIGKILL, -signal.SIGKILL)])
def test_a_signal_during_a_large_write_leaves_the_target_and_no_temporary(scene_file, tmp_path,
                                                                          signum, status, census):
    exr = tmp_path / "big.exr"
    exr.write_bytes(OLD)
    proc = subprocess.Popen([sys.executable, "-c", _SLOW_WRITER, "render", str(scene_file),
                             "--hdr", str(exr), "--size", "1024x1024"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        for line in proc.stdout:
            if line.startswith("WRITING"):
                break
        assert len(_ours(tmp_path)) == 1  # the large EXR, complete in its temporary file
        proc.send_signal(signum)
        assert proc.wait(timeout=60) == status
    finally:
        proc.kill()
        proc.wait()
    assert "Traceback" not in proc.stderr.read()
    assert exr.read_bytes() == OLD
    if signum == signal.SIGKILL:  # nothing can run on SIGKILL: the next write cleans up
        assert len(_ours(tmp_path)) == 1
        images.write_png(tmp_path / "next.png", np.zeros((2, 2, 3), np.uint8))
    assert _ours(tmp_path) == []
    census["output fault", "handled"] += 1


def test_stale_temporaries_of_live_processes_are_left_alone(tmp_path, census):
    live = tmp_path / f".a.png.{os.getppid()}-0123abcd.tmp.png"
    done = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True)
    dead = tmp_path / f".b.png.{int(done.stdout)}-0123abcd.tmp.png"
    foreign = tmp_path / ".c.png.tmp"  # not our pattern: never touched
    for p in (live, dead, foreign):
        p.write_bytes(b"x")
    images.write_png(tmp_path / "new.png", np.zeros((2, 2, 3), np.uint8))
    assert live.exists() and foreign.exists() and not dead.exists()
    census["output fault", "handled"] += 1


def _texture_scene(tmp_path):
    images.write_png(tmp_path / "tex.png", np.full((4, 4, 3), 99, np.uint8))
    data = base_scene()
    data["materials"]["m"]["textures"] = {"albedo": "tex.png"}
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    return path


@pytest.mark.parametrize("args, what", [
    (lambda d: ["render", str(d / "scene.json"), "-o", str(d / "tex.png")], "albedo texture"),
    (lambda d: ["render", str(d / "scene.json"), "-o", str(d / "link.png")], "albedo texture"),
    (lambda d: ["render", str(d / "scene.json"), "--hdr", str(d / "a.exr"), "-o",
                str(d / "sub" / ".." / "tex.png")], "albedo texture"),
    (lambda d: ["diff", str(d / "tex.png"), str(d / "copy.png"), "--heatmap", str(d / "tex.png")],
     "expected image"),
    (lambda d: ["diff", str(d / "tex.png"), str(d / "copy.png"), "--heatmap", str(d / "copy.png")],
     "obtained image"),
    (lambda d: ["amalgamate", str(d / "main.glsl"), "-o", str(d / "main.glsl")], "amalgamates"),
    (lambda d: ["amalgamate", str(d / "main.glsl"), "-o", str(d / "inc.glsl")], "amalgamates"),
])
def test_an_output_that_is_an_input_is_refused_before_any_work(tmp_path, capsys, args, what, census):
    _texture_scene(tmp_path)
    (tmp_path / "sub").mkdir()
    os.link(tmp_path / "tex.png", tmp_path / "link.png")
    (tmp_path / "copy.png").write_bytes((tmp_path / "tex.png").read_bytes())
    (tmp_path / "inc.glsl").write_text("float f() { return 1.0; }\n")
    (tmp_path / "main.glsl").write_text('#include "inc.glsl"\nvoid main() {}\n')
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()}
    assert cli.main(args(tmp_path)) == 2
    err = capsys.readouterr().err
    assert "refusing to write" in err and what in err and "Traceback" not in err, err
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()} == before
    census["output = input", "refused cleanly"] += 1
