"""scripts/setup.sh: without root, missing system packages are named in one exact
apt-get line and the script stops before touching the virtualenv."""

import os
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _fake_bin(tmp_path, uid: str, installed: bool) -> Path:
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    (bin_dir / "id").write_text(f"#!/bin/sh\necho {uid}\n")
    status = "install ok installed" if installed else "unknown ok not-installed"
    (bin_dir / "dpkg-query").write_text(f"#!/bin/sh\nprintf '{status}'\n")
    for tool in bin_dir.iterdir():
        tool.chmod(0o755)
    return bin_dir


def test_non_root_user_gets_the_exact_install_line_and_exit_1(tmp_path):
    env = dict(os.environ, PATH=f"{_fake_bin(tmp_path, '1000', installed=False)}:{os.environ['PATH']}")
    out = subprocess.run(["bash", str(ROOT / "scripts" / "setup.sh")], capture_output=True,
                         text=True, env=env, cwd=tmp_path)
    assert out.returncode == 1
    assert ("sudo apt-get install -y binutils chromium g++ glslang-tools libegl-mesa0 libegl1 libgl1-mesa-dri "
            "libosmesa6 libvulkan1 mesa-vulkan-drivers nodejs spirv-cross") in out.stderr
    assert "setup: creating the virtualenv" not in out.stdout


def test_everything_installed_and_venv_current_is_a_quick_no_op(tmp_path):
    # A copy of the script in a scratch tree whose .venv stamp matches its requirements:
    # the real .venv is never touched by the test suite.
    import hashlib
    import shutil

    tree = tmp_path / "tree"
    (tree / "scripts").mkdir(parents=True)
    shutil.copy(ROOT / "scripts" / "setup.sh", tree / "scripts")
    for name in ("requirements.txt", "pyproject.toml"):
        shutil.copy(ROOT / name, tree)
    (tree / ".venv" / "bin").mkdir(parents=True)
    (tree / ".venv" / "bin" / "python").write_text("#!/bin/sh\nexit 0\n")
    (tree / ".venv" / "bin" / "python").chmod(0o755)
    digest = hashlib.sha256((tree / "requirements.txt").read_bytes() + (tree / "pyproject.toml").read_bytes())
    (tree / ".venv" / ".pbrlab-installed").write_text(digest.hexdigest()[:16] + "\n")
    for name in ("sample_viewer", "gltf_validator", "threejs", "threejs_gltf", "babylonjs"):  # the npm tools' packages, current too
        tool = tree / "tools" / name
        (tool / "node_modules").mkdir(parents=True)
        shutil.copy(ROOT / "tools" / name / "package-lock.json", tool)
        lock = hashlib.sha256((tool / "package-lock.json").read_bytes()).hexdigest()[:16]
        (tool / "node_modules" / ".pbrlab-installed").write_text(lock + "\n")
    env = dict(os.environ, PATH=f"{_fake_bin(tmp_path, '1000', installed=True)}:{os.environ['PATH']}")
    out = subprocess.run(["bash", str(tree / "scripts" / "setup.sh")], capture_output=True,
                         text=True, env=env, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout == "" and out.stderr == ""
