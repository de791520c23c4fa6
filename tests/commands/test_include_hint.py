"""An include that is not found says how to add its folder: -I on the command line,
include_dirs from Python (issue 36); following the hint makes the same call work."""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab import evaluate
from pbrlab.commands import cli
from pbrlab.foundation.errors import PbrlabError

RIM = "float my_rim(float NdotV) { return 1.0 - NdotV; }\n"


@pytest.fixture
def own_shaders(tmp_path):
    (tmp_path / "my").mkdir()
    (tmp_path / "my" / "rim.glsl").write_text(RIM)
    return tmp_path


def test_pbrlab_eval_suggests_dash_i_and_then_works(own_shaders, capsys):
    args = ["eval", "my_rim(NdotV)", "--include", "my/rim.glsl", "--var", "NdotV=0:1:3"]
    assert cli.main(args) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert 'cannot find include "my/rim.glsl"' in err and "-I DIR" in err and "include_dirs=[DIR]" in err
    assert cli.main(args + ["-I", str(own_shaders)]) == 0  # as the hint says
    assert "0.5" in capsys.readouterr().out


def test_evaluate_suggests_include_dirs_and_then_works(own_shaders):
    with pytest.raises(PbrlabError, match=r'cannot find include "my/rim\.glsl".*include_dirs=\[DIR\]'):
        evaluate("my_rim(NdotV)", includes=["my/rim.glsl"], NdotV=np.zeros(1, np.float32))
    got = evaluate("my_rim(NdotV)", includes=["my/rim.glsl"], include_dirs=[own_shaders],
                   NdotV=np.zeros(1, np.float32))
    assert got[0] == 1.0
