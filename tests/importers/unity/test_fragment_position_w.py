"""A fragment's SV_Position.w is the clip-space w, the eye depth, as in Direct3D (Unity's default
API; importers/unity/generate_pass.py's _CLIP_W). GLSL's gl_FragCoord.w, and glslang's
SV_Position taken from it, is 1 / w: a fragment reading ``i.pos.w`` (``ComputeScreenPos(i.pos)``
in the fragment, a depth fade's own eye depth) read 0.45 where Unity reads 2.2.

The shader returns (i.pos.w, i.pos.z, 0, 1) on the corpus sphere. Reference, float64: the eye
depth of the fragment's window depth z, e = 1 / (zp.z z + zp.w) with Unity's _ZBufferParams for a
GL depth range, zp = (1 - f/n, f/n, (1 - f/n) / f, 1/n) (UnityShaderVariables; the corpus frame's
near n and far f). Both come from the rasteriser's interpolation of the same plane (z and 1/w are
affine in screen space), so they agree to the float32 rounding of z: sphere_depth.depth_bound.
Control: 1 / w (the old value) fails the same bound; and the depths lie on the unit sphere seen
from 3.2 units (2.2 <= e <= 3.2)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.depth_range import scene_frame

from sphere_depth import depth_bound

SHADER = """\
Shader "Test/FragmentPositionW" {
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #include "UnityCG.cginc"
        struct v2f { float4 pos : SV_POSITION; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); return o; }
        float4 frag(v2f i) : SV_Target { return float4(i.pos.w, i.pos.z, 0.0, 1.0); }
        ENDCG
    } }
}
"""
CAMERA_DISTANCE = 3.2  # unity_corpus.scene_for's camera, at (0, 0, 3.2) looking at the unit sphere


@pytest.mark.parametrize("language", corpus.LANGUAGES)
def test_a_fragments_position_w_is_the_eye_depth(tmp_path, language):
    path = tmp_path / "position_w.shader"
    path.write_text(textwrap.dedent(SHADER))
    outcome = corpus.run_shader(path, language)
    assert outcome.status == "rendered", outcome.message
    frame = scene_frame(parse_scene(corpus.scene_for(Path(path)), origin="position w test", base=tmp_path))
    image = np.asarray(outcome.image, np.float64)
    # pixels whose four neighbours are drawn too: the silhouette's partly covered pixels mix
    # samples of the background into the value
    drawn = image[..., 1] > 0
    interior = drawn & np.roll(drawn, 1, 0) & np.roll(drawn, -1, 0) & np.roll(drawn, 1, 1) & np.roll(drawn, -1, 1)
    assert interior.sum() > 2000
    n, f = frame.near, frame.far
    zp = (1 - f / n, f / n, (1 - f / n) / f, 1 / n)
    eye = 1.0 / (zp[2] * image[..., 1] + zp[3])
    bound = depth_bound(eye, frame)
    w = image[..., 0]
    over = np.abs(w - eye) > bound
    assert over[interior].mean() == 0.0, (np.abs(w - eye) / bound)[interior].max()
    assert (eye[interior] >= CAMERA_DISTANCE - 1.0 - 1e-3).all() and (eye[interior] <= CAMERA_DISTANCE).all()
    # control: GLSL's gl_FragCoord.w, 1 / w, the value read before
    assert (np.abs(1.0 / w[interior] - eye[interior]) > bound[interior]).all()
