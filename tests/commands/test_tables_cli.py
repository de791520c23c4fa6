"""`pbrlab tables --out DIR` writes every file its help names (issue 36: the help named
examples/engine/ files that a wheel user does not have; the wheel now ships them and the
command copies them beside the tables)."""

from __future__ import annotations

import re

import pytest

from pbrlab.commands import cli, tables
from pbrlab.foundation.locations import engine_snippets

# "DIR/pbrlab_dfg.exr and .png": a file the help promises in DIR, and its sibling suffixes.
PROMISE = re.compile(r"DIR/(?P<stem>[\w.]+?)\.(?P<ext>\w+)(?P<more>(?: and \.\w+)*)")


def promised_files(help_text: str) -> set[str]:
    names = set()
    for match in PROMISE.finditer(" ".join(help_text.split())):
        for ext in [match["ext"], *re.findall(r"\.(\w+)", match["more"])]:
            names.add(f"{match['stem']}.{ext}")
    return names


def test_the_promise_reader_reads_a_help_line():
    """Control: the reader finds every name of such a sentence (a name it missed would go unchecked)."""
    assert promised_files("DIR/a.exr and .png: x; DIR/b.glsl and .hlsl: y") == {"a.exr", "a.png", "b.glsl", "b.hlsl"}


def test_tables_writes_every_file_its_help_names(tmp_path, capsys):
    with pytest.raises(SystemExit):
        cli.main(["tables", "--help"])
    help_text = capsys.readouterr().out
    assert "examples/" not in help_text, "the help names a checkout folder a wheel user does not have"
    promised = promised_files(help_text)
    assert {"pbrlab_dfg.exr", "pbrlab_sheen_albedo.png", "pbrlab_tables.glsl", "pbrlab_tables.hlsl"} <= promised
    assert cli.main(["tables", "--out", str(tmp_path)]) == 0
    assert promised <= {p.name for p in tmp_path.iterdir()}
    for name in tables.SNIPPETS:
        assert (tmp_path / name).read_bytes() == (engine_snippets() / name).read_bytes()
