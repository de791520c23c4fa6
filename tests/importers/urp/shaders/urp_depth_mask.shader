// A stencil/depth mask as URP projects write them: a Pass with no program, ColorMask 0 (no
// colour), depth written by default, a Stencil block (tests/importers/urp/test_urp_passes.py).
Shader "pbrlab tests/urp depth mask" {
    SubShader {
        Tags { "RenderPipeline" = "UniversalPipeline" "Queue" = "Geometry-1" }
        Pass {
            ColorMask 0
            ZWrite On
            Stencil {
                Ref 2
                Comp Always
                Pass Replace
            }
        }
    }
}
