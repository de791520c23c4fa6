"""Every shader file an engine copies carries the licence notice (README: Licence): the GLSL
library, its generated HLSL twins (the generator copies the GLSL header) and the hand-written
shim, and so does an amalgamated single file."""

import pytest

from pbrlab.gpu import hlsl, shaders

NOTICE = "// SPDX-License-Identifier: MIT. Part of pbrlab"
FILES = {f"{root.name}/{path.relative_to(root).as_posix()}": path
         for root, suffix in ((shaders.GLSL_ROOT, "*.glsl"), (hlsl.HLSL_ROOT, "*.hlsl"))
         for path in sorted((root / "pbr").rglob(suffix))}


@pytest.mark.parametrize("name", sorted(FILES))
def test_shader_file_carries_the_licence_notice_in_its_header(name):
    """The notice closes the header comment, on the line before the include guard."""
    lines = FILES[name].read_text(encoding="utf-8").splitlines()
    guard = next(i for i, line in enumerate(lines) if line.startswith("#ifndef PBR_"))
    assert lines[guard - 1].startswith(NOTICE), f"{name}: the line before the guard is {lines[guard - 1]!r}"


def test_amalgamated_library_carries_the_notice():
    text = shaders.expand('#include "pbr/pbr.glsl"\n', line_directives=False).text
    assert NOTICE in text
