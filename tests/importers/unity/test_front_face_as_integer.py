"""``uint f : SV_IsFrontFace`` (or int) as a fragment parameter: HLSL converts the bool to 1 or 0
(glslang's HLSL path does so too). pbrlab's generated GLSL entry passed ``(facing ? 1.0 : -1.0)``
to it and the port refused "initializer of type float cannot be assigned to variable of type
uint" (6 shaders of session 44's hidden5 sample). The sphere's visible faces are front faces:
the program's colour times 1."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from pbrlab.checking import unity_corpus as corpus

SHADER = textwrap.dedent("""\
    Shader "Test/FrontFaceAsInteger"
    {
        Properties { _Color ("Color", Color) = (0.75, 0.25, 0.5, 1) }
        SubShader { Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            fixed4 _Color;
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
            fixed4 frag(float4 pos : SV_POSITION, KIND face : SV_IsFrontFace) : SV_Target
            {
                return _Color * 0.5 * (face + 1);
            }
            ENDCG
        } }
    }
    """)



def _run(tmp_path, kind, language):
    path = tmp_path / f"{kind}.shader"
    path.write_text(SHADER.replace("KIND", kind))
    return corpus.run_shader(path, language)


@pytest.mark.parametrize("language", corpus.LANGUAGES)
@pytest.mark.parametrize("kind,front", [("uint", 1.0), ("int", 1.0), ("float", 1.0)])
def test_an_integer_front_face_is_one_seen_from_the_front(tmp_path, kind, front, language):
    """float is the control of the value: VFACE-style +1 from the front, as before; an integer
    reads the bool as 1 (not -1, which would give black; not ~0u, which would overflow)."""
    result = _run(tmp_path, kind, language)
    assert result.status == "rendered", result.message
    covered = result.image[..., 3] == 1.0
    assert covered.mean() > 0.1
    expected = np.array([0.75, 0.25, 0.5], dtype=np.float64) * 0.5 * (front + 1)
    assert np.array_equal(result.image[covered][:, :3].astype(np.float64),
                          np.broadcast_to(expected, (covered.sum(), 3)))
