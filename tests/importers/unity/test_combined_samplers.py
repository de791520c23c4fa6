"""combined_samplers.spelled: a sampler state that Cg's tex2D samples is declared a sampler2D
(FXC's compatibility mode takes it as a combined sampler); one used with a texture object's
methods is left a sampler state. The rendered check is tests/importers/urp/
test_urp_scene_textures.py::test_own_color_target_sampler_reads_the_frame_so_far."""

from pbrlab.importers.unity.combined_samplers import spelled

PROGRAM = """SAMPLER(_CameraColorTexture);
SamplerState _Grab;
SAMPLER(sampler_MainTex);
float4 f(float2 uv) {
    return tex2D(_CameraColorTexture, uv) + tex2Dlod(_Grab, float4(uv, 0, 0)) + _MainTex.Sample(sampler_MainTex, uv);
}
"""


def test_sampled_sampler_states_become_sampler2d_and_others_stay():
    out = spelled(PROGRAM).splitlines()
    assert out[0] == "sampler2D _CameraColorTexture;"
    assert out[1] == "sampler2D _Grab;"
    assert out[2] == "SAMPLER(sampler_MainTex);"  # control: a texture object's sampler state
    assert len(out) == len(PROGRAM.splitlines())


def test_program_without_cg_sampling_is_unchanged():
    text = PROGRAM.replace("tex2D(_CameraColorTexture, uv)", "0").replace("tex2Dlod(_Grab, float4(uv, 0, 0))", "0")
    assert spelled(text) == text
