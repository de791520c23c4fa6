"""scripts/setup.sh: without root, missing system packages are named in one exact
apt-get line and the script stops before touching the virtualenv."""

import os
import re
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


def _current_tree(tmp_path, naga: bool = True) -> Path:
    """A copy of the script in a scratch tree whose .venv stamp matches its requirements, whose npm
    tools match their lock files and (``naga``) whose tools/naga holds the pinned naga-cli: the
    real .venv and tools are never touched by the test suite."""
    import hashlib
    import re
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
    if naga:
        version = re.search(r"^NAGA_VERSION=(\S+)$", (ROOT / "scripts" / "setup.sh").read_text(), re.M).group(1)
        (tree / "tools" / "naga" / "bin").mkdir(parents=True)
        (tree / "tools" / "naga" / "bin" / "naga").write_text("#!/bin/sh\nexit 0\n")
        (tree / "tools" / "naga" / "bin" / "naga").chmod(0o755)
        (tree / "tools" / "naga" / ".pbrlab-installed").write_text(version + "\n")
    return tree


def test_everything_installed_and_venv_current_is_a_quick_no_op(tmp_path):
    tree = _current_tree(tmp_path)
    env = dict(os.environ, PATH=f"{_fake_bin(tmp_path, '1000', installed=True)}:{os.environ['PATH']}")
    out = subprocess.run(["bash", str(tree / "scripts" / "setup.sh")], capture_output=True,
                         text=True, env=env, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout == "" and out.stderr == ""


def test_naga_without_cargo_is_a_clear_error(tmp_path):
    """naga-cli is missing (in tools/naga and in the machine's cache) and cargo is neither on PATH
    nor in ~/.cargo/bin: exit 1 with a line naming cargo (the control of the no-op above: the same
    tree with tools/naga stops here)."""
    tree = _current_tree(tmp_path, naga=False)
    env = dict(os.environ, PATH=f"{_fake_bin(tmp_path, '1000', installed=True)}:/usr/bin:/bin",
               HOME=str(tmp_path / "home"), PBRLAB_TOOL_CACHE=str(tmp_path / "cache"))
    out = subprocess.run(["bash", str(tree / "scripts" / "setup.sh")], capture_output=True,
                         text=True, env=env, timeout=60)
    assert out.returncode == 1
    assert "naga-cli" in out.stderr and "needs cargo" in out.stderr, out.stderr


def test_naga_built_once_per_machine_is_copied_into_a_fresh_tree(tmp_path):
    """A fresh clone on a machine whose cache holds the pinned naga-cli: copied into tools/naga with
    its stamp, no cargo needed (the same environment as the test above, plus the cache)."""
    tree = _current_tree(tmp_path, naga=False)
    version = re.search(r"^NAGA_VERSION=(\S+)$", (tree / "scripts" / "setup.sh").read_text(), re.M).group(1)
    cached = tmp_path / "cache" / f"naga-cli-{version}" / "bin"
    cached.mkdir(parents=True)
    (cached / "naga").write_text("#!/bin/sh\necho cached naga\n")
    (cached / "naga").chmod(0o755)
    env = dict(os.environ, PATH=f"{_fake_bin(tmp_path, '1000', installed=True)}:/usr/bin:/bin",
               HOME=str(tmp_path / "home"), PBRLAB_TOOL_CACHE=str(tmp_path / "cache"))
    out = subprocess.run(["bash", str(tree / "scripts" / "setup.sh")], capture_output=True,
                         text=True, env=env, timeout=60)
    assert out.returncode == 0, out.stderr
    assert (tree / "tools" / "naga" / "bin" / "naga").read_text() == "#!/bin/sh\necho cached naga\n"
    assert (tree / "tools" / "naga" / ".pbrlab-installed").read_text().strip() == version
