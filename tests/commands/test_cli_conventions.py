"""CLI conventions: --version, -q/-v on every command, full-sentence help texts."""

import subprocess
import sys
from pathlib import Path

import pytest

from pbrlab.commands import cli
from pbrlab.foundation import console

SCENE_ARGS = ["--size", "8x8"]


def _pbrlab(*argv):
    return subprocess.run([sys.executable, "-m", "pbrlab.commands.cli", *argv], capture_output=True, text=True)


@pytest.mark.parametrize("command", cli.COMMANDS)
def test_every_command_has_full_sentence_help_and_takes_q_and_v(command):
    sub = cli.build_parser()._subparsers._group_actions[0]
    parser = sub.choices[command]
    summary = next(a.help for a in sub._choices_actions if a.dest == command)
    assert summary[0].isupper() and summary.endswith("."), summary
    assert parser.description.strip().endswith("."), parser.description
    for flag in ("-q", "--quiet", "-v", "--verbose"):
        assert flag in parser._option_string_actions, (command, flag)


@pytest.mark.parametrize("command", cli.COMMANDS)
def test_only_commands_that_open_a_gl_context_take_backend(command):
    """--backend on a command that opens no GL context would be accepted and ignored."""
    sub = cli.build_parser()._subparsers._group_actions[0]
    opens_gl = command in ("demo", "render", "eval", "hardcases", "bench", "fidelity")
    assert ("--backend" in sub.choices[command]._option_string_actions) == opens_gl, command
    for name in ("amalgamate", "diff", "features", "port_unity", "paths"):  # none of them opens one
        source = Path(cli.__file__).with_name(f"{name}.py").read_text()
        assert "args.backend" not in source and "gl_context" not in source and "import evaluator" not in source \
            and "evaluator import" not in source, name


def test_quiet_and_verbose_are_exclusive():
    result = _pbrlab("paths", "-q", "-v")
    assert result.returncode == 2 and "not allowed with argument" in result.stderr


def test_render_says_more_under_v_and_only_errors_under_q(tmp_path):
    from pbrlab.foundation.locations import locate
    scene = str(locate("scenes") / "example.json")
    out = str(tmp_path / "x.png")
    normal = _pbrlab("render", scene, "-o", out, *SCENE_ARGS)
    quiet = _pbrlab("render", scene, "-o", out, "-q", *SCENE_ARGS)
    verbose = _pbrlab("render", scene, "-o", out, "-v", *SCENE_ARGS)
    assert normal.returncode == quiet.returncode == verbose.returncode == 0, normal.stderr
    assert normal.stdout == f"2 specialised program(s)\nwrote {out}\n"
    assert quiet.stdout == ""
    assert verbose.stdout.startswith("renderer: ") and verbose.stdout.endswith(normal.stdout)


def test_console_levels():
    try:
        console.set_level(console.QUIET)
        assert console.level() == console.QUIET
    finally:
        console.set_level(console.NORMAL)
