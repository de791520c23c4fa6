"""pbrlab.foundation.locations: one function decides where glsl/, hlsl_ports/ and scenes/ are; the CLI reports it.

The wheel side (package data found through importlib.resources, outside any checkout) is
proven by scripts/check_wheel.sh, which CI runs after the suite.
"""

import subprocess
import sys
from pathlib import Path

import pytest

import pbrlab
from pbrlab.gpu import hlsl, shaders
from pbrlab.foundation import locations
from pbrlab.foundation.errors import PbrlabError

REPO = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("tree", sorted(locations.TREES))
def test_a_checkout_finds_its_own_trees(tree, monkeypatch):
    monkeypatch.delenv(locations.TREES[tree], raising=False)
    assert locations.locate(tree) == REPO / tree
    assert locations.origin(tree) == "checkout"


@pytest.mark.parametrize("tree", sorted(locations.TREES))
def test_the_environment_variable_overrides(tree, tmp_path, monkeypatch):
    monkeypatch.setenv(locations.TREES[tree], str(tmp_path))
    assert locations.locate(tree) == tmp_path
    assert locations.origin(tree) == f"${locations.TREES[tree]}"


def test_the_modules_use_the_located_trees():
    assert shaders.GLSL_ROOT == locations.locate("glsl")
    assert hlsl.HLSL_ROOT == locations.locate("hlsl_ports")


def test_an_unknown_tree_is_a_programming_error():
    with pytest.raises(ValueError, match="unknown tree 'goldens'"):
        locations.locate("goldens")


def test_a_missing_tree_names_its_environment_variable(monkeypatch, tmp_path):
    monkeypatch.delenv("PBRLAB_SCENES_ROOT", raising=False)
    monkeypatch.setattr(locations, "__file__", str(tmp_path / "a" / "b" / "locations.py"))
    with pytest.raises(PbrlabError, match=r"PBRLAB_SCENES_ROOT"):
        locations.locate("scenes")


def test_version_and_paths_print_every_tree():
    for argv in (["--version"], ["paths"]):
        out = subprocess.run([sys.executable, "-m", "pbrlab.commands.cli", *argv], capture_output=True,
                             text=True, check=True).stdout
        for tree in locations.TREES:
            assert f"{tree}: {REPO / tree} (checkout)" in out, (argv, out)
    version = subprocess.run([sys.executable, "-m", "pbrlab.commands.cli", "--version"], capture_output=True,
                             text=True, check=True).stdout
    assert version.startswith(f"pbrlab {pbrlab.__version__}\n")
