"""Include resolution, #line mapping of compile errors, and amalgamation."""

import re
import subprocess

import pytest

from pbrlab.gpu import shaders
from pbrlab.foundation.errors import PbrlabError, ShaderCompileError

from gl_helpers import fullscreen_program

BROKEN_INCLUDE = """#ifndef BROKEN_GLSL
#define BROKEN_GLSL
float helper_ok(float x) {
    return x * 2.0;
}
float helper_broken(float y) {
    return y + undeclared_identifier;
}
#endif
"""


@pytest.fixture
def include_dir(tmp_path):
    (tmp_path / "user").mkdir()
    (tmp_path / "user" / "broken.glsl").write_text(BROKEN_INCLUDE)
    (tmp_path / "user" / "a.glsl").write_text('#include "user/b.glsl"\n')
    (tmp_path / "user" / "b.glsl").write_text('#include "user/a.glsl"\n')
    return tmp_path


def test_error_in_included_file_names_that_file_and_line(gl_context, include_dir):
    source = ('#version 330 core\n#include "user/broken.glsl"\nout vec4 c;\n'
              'void main() { c = vec4(helper_ok(1.0)); }\n')
    with pytest.raises(ShaderCompileError) as err:
        fullscreen_program(gl_context, source, "entry.frag", include_dirs=[include_dir])
    first = str(err.value).splitlines()[0]  # the first error leads (compile_messages.py)
    assert re.match(r"\S*user/broken\.glsl:7:\d+: error: .*undeclared_identifier", first), str(err.value)


def test_error_in_entry_after_an_include_keeps_entry_line_numbers(gl_context, include_dir):
    source = ('#version 330 core\n#include "user/broken.glsl"\nout vec4 c;\n'
              'void main() { c = vec4(also_undeclared); }\n')
    with pytest.raises(ShaderCompileError, match=r"entry\.frag:4:\d+: error: .*also_undeclared"):
        fullscreen_program(gl_context, source, "entry.frag", include_dirs=[include_dir])


def test_missing_include_names_the_including_file_and_line(include_dir):
    with pytest.raises(PbrlabError, match=r'entry\.frag:2: cannot find include "pbr/nope\.glsl"'):
        shaders.expand('#version 330 core\n#include "pbr/nope.glsl"\n', "entry.frag")


def test_include_cycle_is_an_error(include_dir):
    with pytest.raises(PbrlabError, match="include cycle"):
        shaders.expand('#include "user/a.glsl"\n', "entry", include_dirs=[include_dir])


def test_user_directories_are_searched_before_the_library(tmp_path):
    (tmp_path / "pbr").mkdir()
    (tmp_path / "pbr" / "pbr.glsl").write_text("// user override\n")
    text = shaders.expand('#include "pbr/pbr.glsl"\n', "entry", include_dirs=[tmp_path]).text
    assert "// user override" in text


def test_include_mentioned_in_a_comment_compiles(gl_context):
    source = ('#version 330 core\n// usage: #include "pbr/pbr.glsl"\nout vec4 c;\n'
              'void main() { c = vec4(1.0); }\n')
    assert fullscreen_program(gl_context, source)[0] is not None


def test_library_umbrella_include_compiles(gl_context):
    program, _ = fullscreen_program(
        gl_context, '#version 330 core\n#include "pbr/pbr.glsl"\nout vec4 c;\nvoid main() { c = vec4(PBR_PI); }\n')
    assert program is not None


def test_amalgamation_has_no_includes_and_compiles_with_glslang(tmp_path):
    from pbrlab.commands import cli

    out = tmp_path / "single.glsl"
    assert cli.main(["amalgamate", "pbr/pbr.glsl", "-o", str(out)]) == 0
    text = out.read_text()
    assert "#include" not in re.sub(r"//.*", "", text)
    entry = tmp_path / "check.frag"
    entry.write_text("#version 330 core\n" + text + "\nout vec4 c;\nvoid main() { c = vec4(PBR_PI); }\n")
    result = subprocess.run(["glslangValidator", str(entry)], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr


def test_amalgamate_missing_entry_is_a_clear_error(tmp_path, capsys):
    from pbrlab.commands import cli

    assert cli.main(["amalgamate", str(tmp_path / "nope.glsl"), "-o", str(tmp_path / "x.glsl")]) == 2
    assert "no such file" in capsys.readouterr().err
    assert not (tmp_path / "x.glsl").exists()


def test_guarded_file_is_expanded_once_unless_first_included_conditionally(tmp_path):
    (tmp_path / "g.glsl").write_text("#ifndef G_GLSL\n#define G_GLSL\nfloat g() { return 1.0; }\n#endif\n")
    once = shaders.expand('#include "g.glsl"\n#include "g.glsl"\n', "e", include_dirs=[tmp_path]).text
    assert once.count("float g()") == 1
    # first inclusion inside a conditional that may be false: the later one must stay
    conditional = shaders.expand('#ifdef NEVER\n#include "g.glsl"\n#endif\n#include "g.glsl"\n',
                                 "e", include_dirs=[tmp_path]).text
    assert conditional.count("float g()") == 2


def test_an_include_in_a_comment_or_a_branch_not_taken_is_not_read():
    """Issue 26: the expander resolved every #include line, inside /* */ and under #if 0 too;
    a missing file there stopped the program the compiler would have built."""
    from pbrlab.gpu import shaders
    text = ('#version 330 core\n/* an old include:\n#include "gone.glsl"\n*/\n'
            '#if 0\n#include "missing.glsl"\n#endif\n#include "pbr/common/math.glsl"\n')
    source = shaders.expand(text, "t.glsl")
    assert "gone.glsl" not in "".join(str(p) for p in source.paths)
    assert '#error cannot find include "missing.glsl"' in source.text  # the preprocessor skips it
    with pytest.raises(PbrlabError, match=r'u\.glsl:1: cannot find include "nope\.glsl"'):
        shaders.expand('#include "nope.glsl"\n', "u.glsl")  # outside every #if: an error here


def test_a_missing_include_in_a_branch_taken_is_reported_at_its_line(gl_context):
    from pbrlab.gpu import shaders
    frag = shaders.expand('#version 330 core\n#define X\n#ifdef X\n#include "missing.glsl"\n#endif\n'
                          'out vec4 c;\nvoid main() { c = vec4(1.0); }\n', "frag.glsl")
    vert = shaders.expand('#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n', "vert.glsl")
    with pytest.raises(PbrlabError, match=r'frag\.glsl:4.*cannot find include "missing\.glsl"'):
        shaders.build_program(gl_context, vert, frag)
