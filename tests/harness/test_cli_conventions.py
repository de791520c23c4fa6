"""CLI conventions: --version, -q/-v on every command, full-sentence help texts."""

import subprocess
import sys

import pytest

from pbrlab import cli, console

SCENE_ARGS = ["--size", "8x8"]


def _pbrlab(*argv):
    return subprocess.run([sys.executable, "-m", "pbrlab.cli", *argv], capture_output=True, text=True)


@pytest.mark.parametrize("command", cli.COMMANDS)
def test_every_command_has_full_sentence_help_and_takes_q_and_v(command):
    sub = cli.build_parser()._subparsers._group_actions[0]
    parser = sub.choices[command]
    summary = next(a.help for a in sub._choices_actions if a.dest == command)
    assert summary[0].isupper() and summary.endswith("."), summary
    assert parser.description.strip().endswith("."), parser.description
    for flag in ("-q", "--quiet", "-v", "--verbose"):
        assert flag in parser._option_string_actions, (command, flag)


def test_quiet_and_verbose_are_exclusive():
    result = _pbrlab("paths", "-q", "-v")
    assert result.returncode == 2 and "not allowed with argument" in result.stderr


def test_render_says_more_under_v_and_only_errors_under_q(tmp_path):
    from pbrlab.locations import locate
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
