"""A surface program that writes a material uniform (issue 34: Unity's EffectExamples Dissolve and
Respawn write ``_cutoff`` in surf()): FXC's compatibility mode, how Unity compiles, lets a program
write a global; the value lasts the invocation and starts as the property's. pbrlab reads and
writes a static copy set from the uniform at each entry (written_globals.py), in the vertex: stage
and the pixel alike. Both languages: GLSL through the port, HLSL as written.

Scene: no light, no environment, Albedo 0, so the pixel is the Emission the program writes.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene

LANGUAGES = ("glsl", "hlsl")
# The pixel's own value (below 2, two float32 operations at 2^-24 relative each): 2 * 2 * 2^-24.
EXACT = 1e-6
# The vertex's value reaches the pixel interpolated: each barycentric weight is a plane equation
# evaluated in float32 at window coordinates up to the image's width (corpus.SIZE, 64 pixels), so
# the weights' sum is 1 within 64 * 2^-24, on a value below 2: 2 * 64 * 2^-24 = 7.6e-6.
INTERPOLATED = 2 * corpus.SIZE[0] * 2.0 ** -24

SHADER = """
Shader "t/surface written" {
    Properties { _Gain ("gain", Float) = 0.25 }
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert vertex:vert
        half _Gain;
        struct Input { float fromVertex; };
        void vert(inout appdata_full v, out Input o) {
            UNITY_INITIALIZE_OUTPUT(Input, o);
            _Gain += 1.0;
            o.fromVertex = _Gain;
        }
        void surf(Input IN, inout SurfaceOutput o) {
            _Gain = _Gain * 2.0 + 0.1;
            o.Albedo = 0;
            o.Emission = float3(_Gain, IN.fromVertex, 0);
        }
        ENDCG
    }
}
"""


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("gain", [0.25, 0.4])
def test_surface_program_writes_a_copy_of_its_uniform_per_stage(tmp_path, language, gain):
    """Each stage's copy starts as the property: the pixel's 2 g + 0.1, the vertex's g + 1 (the
    vertex's write does not reach surf's _Gain). Control: the unwritten uniform (g, g)."""
    shader = tmp_path / "written.shader"
    shader.write_text(textwrap.dedent(SHADER))
    data = corpus.scene_for(shader)
    data.pop("environment", None)
    data["lights"] = []
    data["materials"]["m"]["properties"] = {"_Gain": gain}
    image = render_scene(parse_scene(data, "t", tmp_path), language=language).linear.astype(np.float64)
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    expected = np.array([2 * gain + 0.1, gain + 1.0, 0.0])
    err = np.abs(image[covered, :3] - expected)
    assert err[:, 0].max() <= EXACT and err[:, 1].max() <= INTERPOLATED and err[:, 2].max() == 0.0, image[covered][0]
    unwritten = np.array([gain, gain, 0.0])
    assert (np.abs(image[covered, :3] - unwritten).max(axis=1) > 100 * INTERPOLATED).all()
