"""`pbrlab eval -o FILE`: large results written to a file (issue 35: the command refused more
than 10,000 rows, so a sweep of 10^6 samples could not be taken from the command line)."""

import subprocess
import sys

import numpy as np
import pytest

from pbrlab.commands.eval import MAX_FILE_ROWS, MAX_ROWS

D_GGX = "pbr_D_GGX(NdotH, 0.5)"


def _eval(*argv, cwd=None):
    return subprocess.run([sys.executable, "-m", "pbrlab.commands.cli", "eval", D_GGX, "--include",
                           "pbr/brdf/d_ggx.glsl", *argv], capture_output=True, text=True, cwd=cwd)


def _d_ggx(n_dot_h, alpha=0.5):
    """GGX's D in float64 (Walter et al. 2007, eq. 33), the function's reference."""
    a2 = alpha * alpha
    return a2 / (np.pi * (n_dot_h * n_dot_h * (a2 - 1.0) + 1.0) ** 2)


def test_a_million_samples_go_to_an_npz_file_with_named_columns(tmp_path):
    run = _eval("--var", "NdotH=0:1:1000000", "-o", str(tmp_path / "d.npz"))
    assert run.returncode == 0, run.stderr
    assert 1_000_000 > MAX_ROWS
    table = np.load(tmp_path / "d.npz")
    assert sorted(table.keys()) == sorted(["NdotH", D_GGX])
    x, d = table["NdotH"], table[D_GGX]
    np.testing.assert_array_equal(x, np.linspace(0, 1, 1_000_000))
    # The reference takes the float32-rounded inputs, so only the float32 arithmetic differs
    # (u = 2^-24): the denominator's base NdotH^2 (a^2 - 1) + 1 lies in [0.25, 1] (a^2 = 0.25), its
    # three roundings (the square, the product, the sum) at most 3u of the larger term 0.75, so
    # 3u / 0.25 = 12u relative; squared 24u + u, the quotient and pi's product 2u more: 27u. The
    # bound 64u leaves the library's own form (|n x h|^2 in place of 1 - NdotH^2) room for its
    # rounding order; a wrong column or alpha is off by percent.
    reference = _d_ggx(x.astype(np.float32).astype(np.float64))
    assert np.max(np.abs(d / reference - 1)) < 64 * 2.0 ** -24


def test_a_csv_file_holds_the_printed_table(tmp_path):
    run = _eval("--var", "NdotH=0,0.5,1", "-o", str(tmp_path / "d.csv"))
    assert run.returncode == 0, run.stderr
    lines = (tmp_path / "d.csv").read_text().splitlines()
    assert lines[0] == f'"NdotH","{D_GGX}"'
    printed = _eval("--var", "NdotH=0,0.5,1").stdout.splitlines()[1:]
    assert [line.split(",") for line in lines[1:]] == [line.split() for line in printed]


@pytest.mark.parametrize("argv,message", [
    (["--var", "NdotH=0:1:20000"], "a printed table is limited to 10000 (write up to"),
    (["--var", "NdotH=0:1:20", "-o", "d.txt"], "-o d.txt: the file must end in .csv or .npz"),
    (["--var", "NdotH=0:1:5000", "--var", "x=0:1:5000", "-o", "d.npz"], f"over the limit of {MAX_FILE_ROWS}"),
], ids=["printed_over_the_limit", "unknown_format", "file_over_the_limit"])
def test_limits_are_named(tmp_path, argv, message):
    run = _eval(*argv, cwd=tmp_path)
    assert run.returncode == 2 and message in run.stderr and "Traceback" not in run.stderr, run.stderr
    assert list(tmp_path.iterdir()) == []
