"""Shader Graph output for URP (issue 34): a generated pass (Attributes, Varyings,
PackedVaryings and their pack and unpack functions, the graph's SurfaceDescriptionFunction
and VertexDescriptionFunction, ``ZERO_INITIALIZE``, ``UnityTexture2D``) drawn by pbrlab's
stand-ins for URP's Shader Graph includes (``Editor/ShaderGraph/Includes/Varyings.hlsl``,
``UnlitPass.hlsl``, ``PBRForwardPass.hlsl``, ``ShaderPass.hlsl``; Core RP's ``Texture.hlsl``,
``TextureStack.hlsl``; URP's ``ShaderGraphFunctions.hlsl``, ``DBuffer.hlsl``). Each test shader
(tests/importers/urp/shaders/shader_graph/, written for pbrlab in the generated code's form)
is compared with a hand-written URP pass computing the same; both are refused on the main
branch before this (no stand-ins). Content: the texture's texels show, tiled and offset."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from pbrlab.foundation.locations import locate

from test_urp_front_end import SHADERS, _render

GRAPHS = SHADERS / "shader_graph"
BRICKS = str(locate("scenes") / "assets" / "bricks_albedo.png")
# The graph and the reference sample the same texel at the same UV and apply the same
# operations (a product; URP's PBR model on the same inputs), so they agree to the last bit
# (measured: 0.0 in both languages, unlit and lit); 1e-6 is the bound the other URP
# front-end tests use for renders computed the same way (float32 ulps of values <= 1).
BOUND = 1e-6


def _texture(tiling=(1.0, 1.0), offset=(0.0, 0.0)) -> dict:
    return {"_BaseMap": {"path": BRICKS, "srgb": True, "tiling": list(tiling), "offset": list(offset)}}


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
@pytest.mark.parametrize("graph, reference", [("sg_unlit_texture", "sg_reference_unlit"),
                                              ("sg_lit_texture", "sg_reference_lit")])
def test_a_shader_graph_pass_draws_what_its_graph_computes(graph, reference, language):
    props = _texture(tiling=(2.0, 2.0), offset=(0.25, 0.0))
    got = _render(GRAPHS / f"{graph}.shader", language, props)
    want = _render(GRAPHS / f"{reference}.shader", language, props)
    assert (got[..., 3] > 0).all()
    assert np.mean(np.abs(got - want) > BOUND) == 0.0, np.abs(got - want).max()


@pytest.mark.parametrize("language", ["glsl", "hlsl"])
def test_the_graph_s_texture_shows_its_texels_tiled_and_offset(language):
    """Colour, not alpha: the bricks' texels vary across the image (the texture, not a flat
    colour); the base colour (1, 0.5, 0.25) scales each channel of the white-tinted render
    (powers of two: exact, so the bound is float32's relative 1e-6); the tiling and offset move
    the texels (the tiled image differs from the untiled one over most pixels)."""
    graph = GRAPHS / "sg_unlit_texture.shader"
    plain = _render(graph, language, _texture())
    white = _render(graph, language, {**_texture(), "_BaseColor": [1.0, 1.0, 1.0, 1.0]})
    tiled = _render(graph, language, _texture(tiling=(2.0, 2.0), offset=(0.25, 0.0)))
    assert plain[..., :3].std(axis=(0, 1)).min() > 0.01          # texels, not one colour
    np.testing.assert_allclose(plain[..., :3], white[..., :3] * [1.0, 0.5, 0.25], rtol=1e-6, atol=1e-7)
    assert np.mean(np.abs(tiled[..., :3] - plain[..., :3]) > 0.01) > 0.5  # the tiling is applied
