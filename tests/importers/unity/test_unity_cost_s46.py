"""The caches that keep a many-pass shader's per-pass work once a process (session 46: a
256-pass Amplify preview took over 20 minutes) give the answers the uncached code gives, and
read a file again once it changed: an include file edited, created in a folder searched
first, or a piece of text whose scan depends on the piece before it.

Each test asks twice with no change (the second answer comes from the cache: the cache's
build count stays put, the control that the cache is consulted at all), then changes a file
and asks again: the answer must be the new file's.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from pbrlab.foundation import file_identity
from pbrlab.gpu import hlsl, shaders, source_limits
from pbrlab.importers.unity import user_definitions


def _rewrite(path: Path, text: str) -> None:
    """``text`` into ``path`` with a later modification time (a file system whose clock ticks
    coarsely would otherwise leave it as it was: the size differs anyway)."""
    before = path.stat().st_mtime_ns if path.exists() else 0
    path.write_text(text, encoding="utf-8")
    os.utime(path, ns=(before + 10**9, before + 10**9))


def test_text_defines_rereads_a_changed_include(tmp_path):
    """user_definitions.text_defines: an include that #defines PI gives the stand-in's
    PBRLAB_USER_DEFINES_PI; the include edited without it, the define is gone."""
    include = tmp_path / "Mine.hlsl"
    _rewrite(include, "#define PI 3.14159265358979323846\n")
    program = '#include "Mine.hlsl"\nfloat4 frag() : SV_Target { return PI; }\n'
    assert user_definitions.text_defines(program, tmp_path) == {"PBRLAB_USER_DEFINES_PI": 1}
    builds = user_definitions._TEXT_DEFINES.builds
    assert user_definitions.text_defines(program, tmp_path) == {"PBRLAB_USER_DEFINES_PI": 1}
    assert user_definitions._TEXT_DEFINES.builds == builds  # kept: the control that it is cached
    _rewrite(include, "#define TAU 6.28\n")
    assert user_definitions.text_defines(program, tmp_path) == {}
    # a file the program names created where it was not before (a nested include)
    _rewrite(include, '#include "More.hlsl"\n')
    assert user_definitions.text_defines(program, tmp_path) == {}
    _rewrite(tmp_path / "More.hlsl", "struct LightingData { float x; };\n")
    assert user_definitions.text_defines(program, tmp_path) == {"PBRLAB_USER_DEFINES_LightingData": 1}


def test_text_defines_keeps_no_answer_for_a_legacy_code_page(tmp_path):
    """A file read byte for byte (not UTF-8) warns at every read, as it did before the cache:
    its answer is not kept, so each call reads (and notes) it again."""
    (tmp_path / "Old.cginc").write_bytes(b"// caf\xe9\n#define PI 3.14\n")
    program = '#include "Old.cginc"\n'
    for _ in range(2):
        with pytest.warns(UserWarning, match="not UTF-8"):
            assert user_definitions.text_defines(program, tmp_path) == {"PBRLAB_USER_DEFINES_PI": 1}


def test_include_closure_follows_edits_and_new_files(tmp_path):
    """file_identity.include_closure: an include edited to include another reaches it; a file
    created in a folder searched before the one that held it is the one found."""
    first, second = tmp_path / "first", tmp_path / "second"
    first.mkdir()
    second.mkdir()
    _rewrite(second / "a.h", "// a\n")
    _rewrite(second / "b.h", "// b\n")
    text = '#include "a.h"\n'
    assert file_identity.include_closure(text, [first, second]) == [(second / "a.h").resolve()]
    builds = file_identity._FILE_INCLUDES.builds
    assert file_identity.include_closure(text, [first, second]) == [(second / "a.h").resolve()]
    assert file_identity._FILE_INCLUDES.builds == builds  # kept
    _rewrite(second / "a.h", '#include "b.h"\n')
    assert file_identity.include_closure(text, [first, second]) == [(second / "a.h").resolve(),
                                                                    (second / "b.h").resolve()]
    _rewrite(first / "a.h", "// a, found first\n")
    assert file_identity.include_closure(text, [first, second]) == [(first / "a.h").resolve()]


def test_hlsl_limits_read_a_changed_include(tmp_path):
    """hlsl.check_limits: an include within the limits passes twice (the second from the
    cache); edited to declare an array over MAX_ARRAY_ELEMENTS, the same program is refused
    at the include's line."""
    include = tmp_path / "big.hlsl"
    _rewrite(include, "static float small[4];\n")
    text = '#include "big.hlsl"\nfloat4 main() : SV_Target { return 0; }\n'
    hlsl.check_limits(text, "entry", [tmp_path])
    builds = hlsl._INCLUDED_FILES.builds
    hlsl.check_limits(text, "entry", [tmp_path])
    assert hlsl._INCLUDED_FILES.builds == builds  # kept
    _rewrite(include, "// grown\nstatic float big[20000];\n")
    with pytest.raises(source_limits.ShaderLimitError, match=r"big\.hlsl:2: an array of 20000"):
        hlsl.check_limits(text, "entry", [tmp_path])


def test_expand_finds_a_file_created_in_an_earlier_folder(tmp_path):
    """shaders.expand: an include resolved from the second folder is resolved from the first
    once a file of its name is created there (and the places looked at are reported)."""
    first, second = tmp_path / "first", tmp_path / "second"
    first.mkdir()
    second.mkdir()
    _rewrite(second / "x.glsl", "float second_x;\n")
    source = shaders.expand('#include "x.glsl"\n', include_dirs=[first, second])
    assert "second_x" in source.text and first / "x.glsl" in source.probed
    assert "second_x" in shaders.expand('#include "x.glsl"\n', include_dirs=[first, second]).text
    _rewrite(first / "x.glsl", "float first_x;\n")
    source = shaders.expand('#include "x.glsl"\n', include_dirs=[first, second])
    assert "first_x" in source.text and "second_x" not in source.text


# Texts whose scan in pieces must read what the joined text reads: a comment or a backslash
# line that runs from one piece into the next, brackets opened in one and closed in another,
# and a macro defined in one piece and expanded in another.
_PIECES = [
    (["/* (", "int a[20000]; */"], None),
    (["#define BIG \\", "x"], None),
    (["float f(", "int a[20000]);"], "an array of 20000"),
    (["(" * 200, "(" * 57 + ")" * 257], "brackets nested over 256"),
    (["#define D(x) x x x x", "D(D(D(D(D(D(D(D(D(D(D(D(y))))))))))))"], "macros expand the program"),
]


@pytest.mark.parametrize("pieces, refusal", _PIECES)
def test_pieces_read_as_the_joined_text(pieces, refusal):
    """source_limits.check_pieces gives check_text's answer on the joined text; the control:
    the first two texts, each piece checked alone, would be refused (the array sits inside a
    comment, or a #define's continued line, only when the pieces are joined)."""
    def answer(check, *args):
        try:
            check(*args, str)
        except source_limits.ShaderLimitError as exc:
            return str(exc)
        return None

    joined = answer(source_limits.check_text, "\n".join(pieces))
    assert (joined is None) == (refusal is None) and (refusal is None or refusal in joined)
    assert answer(source_limits.check_pieces, pieces) == joined
    if refusal is None and "20000" in pieces[-1]:  # the control: alone, the last piece is refused
        assert answer(source_limits.check_text, pieces[-1]) is not None
