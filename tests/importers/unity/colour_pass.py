"""A minimal vertex/fragment shader with one include of its own beside UnityCG.cginc, a _Color
property of short binary fractions (0.75, 0.25, 0.5, 1) and a fragment that returns one
expression: the shader several front-end tests write in two variants and compare."""

from __future__ import annotations

import textwrap

COLOR = (0.75, 0.25, 0.5, 1.0)


def colour_pass(name: str, include: str, returned: str) -> str:
    """The .shader text: ``#include "<include>"`` and ``return <returned>;`` in its fragment."""
    return textwrap.dedent(f"""\
        Shader "Test/{name}"
        {{
            Properties {{ _Color ("Color", Color) = (0.75, 0.25, 0.5, 1) }}
            SubShader
            {{
                Pass
                {{
                    CGPROGRAM
                    #pragma vertex vert
                    #pragma fragment frag
                    #include "UnityCG.cginc"
                    #include "{include}"
                    fixed4 _Color;
                    float4 vert(float4 p : POSITION) : SV_POSITION {{ return UnityObjectToClipPos(p); }}
                    fixed4 frag() : SV_Target {{ return {returned}; }}
                    ENDCG
                }}
            }}
        }}
        """)
