"""An include by a project path (issue 34): ``#include "Assets/..."`` resolves from the Unity
project's root, the folder that holds Assets/, wherever below it the shader lies; a shader
outside any project (no folder above it holds Assets/), or a project without the file, is
refused naming the shader's file and line and why.
"""

from __future__ import annotations

import numpy as np
import pytest

from pbrlab.foundation.errors import PbrlabError
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene
from test_urp_library_round2 import LANGUAGES, render_constant, urp_pass

INCLUDE = '#include "Assets/Shaders/Library/Constant.hlsl"'
LIBRARY = "float3 pbrlab_test_constant() { return float3(0.25, 0.5, 0.75); }\n"
EXPECTED = np.array([0.25, 0.5, 0.75])
# exact: constants float32 holds, written to a float target unchanged
BOUND = 0.0


def _project_shader(root, with_library: bool):
    shader_folder = root / "Assets" / "Materials" / "Deep"
    shader_folder.mkdir(parents=True)
    if with_library:
        (root / "Assets" / "Shaders" / "Library").mkdir(parents=True)
        (root / "Assets" / "Shaders" / "Library" / "Constant.hlsl").write_text(LIBRARY)
    return shader_folder


@pytest.mark.parametrize("language", LANGUAGES)
def test_assets_include_resolves_from_the_project_root(tmp_path, language):
    """A shader two folders below Assets/ includes Assets/Shaders/Library/Constant.hlsl: the
    pixel is the included function's constant."""
    folder = _project_shader(tmp_path / "Project", with_library=True)
    pixels, _ = render_constant(folder, urp_pass("project include", "return float4(pbrlab_test_constant(), 1.0);",
                                                 INCLUDE), language, environment=False)
    assert (np.abs(pixels[:, :3] - EXPECTED).max(axis=1) > BOUND).mean() == 0.0


@pytest.mark.parametrize("with_project", (False, True))
def test_assets_include_without_the_file_is_refused_naming_the_line(tmp_path, with_project):
    """Control: the same shader outside any project (no Assets/ above it), or in a project
    without the file, is refused at the include's line, saying which."""
    folder = _project_shader(tmp_path / "Project", with_library=False) if with_project else tmp_path
    shader = folder / "t.shader"
    text = urp_pass("project include", "return float4(pbrlab_test_constant(), 1.0);", INCLUDE)
    shader.write_text(text)
    line = text.splitlines().index(next(ln for ln in text.splitlines() if "Assets/Shaders" in ln)) + 1
    data = {"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40, "size": [8, 8]},
            "materials": {"m": {"surface": str(shader)}},
            "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}]}
    with pytest.raises(PbrlabError) as info:
        render_scene(parse_scene(data, origin="project include test", base=tmp_path), language="glsl")
    message = str(info.value)
    assert f"t.shader:{line}:" in message and "Assets/Shaders/Library/Constant.hlsl" in message
    if with_project:
        assert f"here {tmp_path / 'Project'}, which has no" in message
    else:
        assert "no folder at or above" in message and "holds an Assets/ folder" in message
