"""Issue 26 (round two), resource limits: a Unity shader whose Properties block has
thousands of Float properties. Reading the block counted each property's line from the
start of the block (quadratic: 6.3 s of 7 for 20,000 properties, 0.45 s for 5,000); it
now counts each newline once. The shader renders as the same shader with its one used
property alone.

What remains grows with the program, not the properties (llvmpipe, Mesa 22.3, shader cache
off, one sphere, GLSL): reading 1,000 / 2,000 / 4,000 properties in 1,000 / 2,000 / 4,000
statements compiles in 2.2 / 10.7 / 29.5 s at the first draw, and 4,000 statements reading
one property take 38 s: the driver's compile time, which no property limit would bound."""

import numpy as np

from hostile_common import base_scene
from pbrlab.render.renderer import render_scene
from pbrlab.scene import parse_scene
from pbrlab.importers.unity import UnityShaderError, load_shader, parse


def _shader(count: int, used: int, broken_at: int | None = None) -> str:
    lines = [f'        _P{i} ("P{i}", Float) = {0.25 if i == used else 0.5}' for i in range(count)]
    if broken_at is not None:
        lines[broken_at] = f'        _P{broken_at} ("P{broken_at}", Float) = 1 junk'
    props = "\n".join(lines)
    return f'''Shader "Test/Many" {{
    Properties {{
{props}
    }}
    SubShader {{
        CGPROGRAM
        #pragma surface surf Standard
        float _P{used};
        struct Input {{ float2 uv_MainTex; }};
        void surf (Input IN, inout SurfaceOutputStandard o) {{
            o.Albedo = float3(_P{used}, 0.5, 0.5);
        }}
        ENDCG
    }}
}}
'''


class _CountingText(str):
    """A str that adds up the characters its count() scans (the line counting's work)."""

    scanned = 0

    def count(self, sub, start=0, end=None):
        stop = len(self) if end is None else min(end, len(self))
        _CountingText.scanned += max(0, stop - start)
        return str.count(self, sub, start, end)


def test_reading_many_properties_counts_each_line_once(tmp_path, census):
    text = _shader(5000, used=4999)
    start, end = text.index("Properties {") + len("Properties {"), text.index("\n    }\n")
    block = _CountingText(text[start:end])
    _CountingText.scanned = 0
    props = parse._properties_in(block, 2, tmp_path / "many.shader", [])
    assert len(props) == 5000
    assert _CountingText.scanned <= 2 * len(block), (
        f"{_CountingText.scanned} characters scanned for a {len(block)}-character block")
    census["unity properties", "handled"] += 1


def test_a_bad_property_among_thousands_is_named_at_its_line(tmp_path, census):
    path = tmp_path / "many.shader"
    path.write_text(_shader(5000, used=0, broken_at=4321))
    try:
        load_shader(path)
    except UnityShaderError as exc:
        assert str(exc).startswith(f"{path}:{3 + 4321}: cannot read this Properties text: 'junk'"), exc
    else:
        raise AssertionError("a property with trailing junk was read")
    census["unity properties", "refused cleanly"] += 1


def test_five_thousand_properties_render_as_the_one_they_use(tmp_path, gl_context, census):
    (tmp_path / "many.shader").write_text(_shader(5000, used=4999))
    (tmp_path / "one.shader").write_text(_shader(1, used=0).replace("_P0", "_P4999"))
    assert len(load_shader(tmp_path / "many.shader").properties) == 5000
    images = []
    for name in ("many", "one"):
        scene = base_scene()
        scene["camera"]["size"] = [16, 12]
        scene["materials"]["m"] = {"surface": str(tmp_path / f"{name}.shader")}
        images.append(render_scene(parse_scene(scene, base=tmp_path), gl_context).linear)
    assert images[0][..., 3].max() > 0
    np.testing.assert_array_equal(images[0], images[1])
    census["unity properties", "handled"] += 1
