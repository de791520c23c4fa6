"""The hardware sRGB path (lecture: "let the GPU magically handle it"), measured
against the exact IEC 61966-2-1 curves of the float64 reference."""

import numpy as np

from pbrlab.gpu import targets
from pbrlab.maths.reference.color import linear_to_srgb, srgb_to_linear

from gl_helpers import COPY_TEXELS, fullscreen_program


def _draw_texels(ctx, texture, kind, size):
    program, vao = fullscreen_program(ctx, COPY_TEXELS)
    with targets.Target(ctx, size, kind, depth=False) as target:
        target.use()
        texture.use(0)
        vao.render(vertices=3)
        return target.read()


def test_framebuffer_encode_lands_on_a_code_adjacent_to_the_exact_curve(gl_context):
    # 65536 linear values across [0, 1], written through GL_FRAMEBUFFER_SRGB.
    linear = np.linspace(0.0, 1.0, 256 * 256)
    image = np.repeat(linear.astype(np.float32)[:, None], 4, axis=1).reshape(256, 256, 4)
    texture = targets.upload_texture(gl_context, image, srgb=False)
    got = _draw_texels(gl_context, texture, "srgb8", (256, 256))[..., :3].astype(np.float64)
    exact = linear_to_srgb(image[..., :3].astype(np.float64)) * 255.0
    # Tolerance: the hardware encode need not round to nearest (llvmpipe approximates
    # the curve: Mesa gallivm lp_bld_format_srgb.c). It must pick one of the two codes
    # that bracket the exact value, i.e. |code - exact| < 1 LSB. Measured on Mesa 22.3
    # llvmpipe: max 0.65 LSB, 6.8 % of values not rounded to nearest.
    assert np.all(np.abs(got - exact) < 1.0), np.abs(got - exact).max()
    assert np.all((got == np.floor(exact)) | (got == np.ceil(exact)))


def test_texture_decode_of_all_256_codes_round_trips(gl_context):
    codes = np.arange(256, dtype=np.uint8)
    image = np.repeat(codes[:, None], 4, axis=1).reshape(16, 16, 4)
    texture = targets.upload_texture(gl_context, image, srgb=True)
    decoded = _draw_texels(gl_context, texture, "f32", (16, 16))[..., :3].astype(np.float64)
    exact = srgb_to_linear(image[..., :3] / 255.0)
    # llvmpipe decodes sRGB with a polynomial, not a table (Mesa gallivm
    # lp_bld_format_srgb.c): measured relative error up to 2.5 % (code 1). What must hold
    # is that the decoded value re-encodes to its own code (< 0.5 code away from it):
    # measured max 0.34 code. A decode that skipped the sRGB curve would be off by ~50 codes.
    reencoded = linear_to_srgb(np.maximum(decoded, 0.0)) * 255.0
    assert np.abs(reencoded - image[..., :3]).max() < 0.5
    assert np.abs(decoded - exact).max() < 2e-3
    assert decoded[..., 0].ravel()[0] == 0.0 and decoded[..., 0].ravel()[-1] == 1.0


def test_alpha_is_never_srgb_encoded(gl_context):
    image = np.zeros((1, 1, 4), np.float32)
    image[..., 3] = 0.5
    texture = targets.upload_texture(gl_context, image, srgb=False)
    out = _draw_texels(gl_context, texture, "srgb8", (1, 1))
    assert out[0, 0, 3] in (127, 128)  # linear 0.5 -> 127.5, not the sRGB 188


def test_hdr_targets_read_back_values_above_one(gl_context):
    image = np.full((2, 2, 4), 1000.5, np.float32)
    texture = targets.upload_texture(gl_context, image, srgb=False)
    assert np.all(_draw_texels(gl_context, texture, "f32", (2, 2)) == 1000.5)
    assert np.all(_draw_texels(gl_context, texture, "f16", (2, 2)) == 1000.5)  # exact in half
