"""Anti-aliasing (render.antialias, issue 38): multisampled targets resolved in linear radiance,
spheres covering their samples analytically (templates/scene_geometry.inc,
pbrlab_sphere_coverage). Checked against float64 geometry computed here: which of each pixel's
samples a half-plane's edge or a sphere's silhouette covers (the sample positions are the GL's
own, glGetMultisamplefv), the area of the half-plane in each pixel, the sphere's disc area;
that fully covered pixels keep the single-sampled render's values bit for bit; that the
resolve averages linear radiance (not sRGB codes); GLSL against HLSL; and that a sample count
this GL does not take is refused by name."""

import copy
import math
import warnings

import numpy as np
import pytest

from pbrlab.foundation.errors import SceneError
from pbrlab.gpu import targets
from pbrlab.gpu.programs import LANGUAGES
from pbrlab.maths import srgb8
from pbrlab.render.renderer import render_scene, scene_frame
from pbrlab.scene import parse_scene

SAMPLES = 4  # the count llvmpipe takes besides 1 (GL_MAX_SAMPLES = 4); the tests skip where it is not taken
SIZE = 64
# An unlit white emitter (specular workflow, albedo and specular 0: no reflection; no light, no
# environment): its radiance is exactly (1, 1, 1), so a pixel k of whose 4 samples it covers
# resolves to k / 4 exactly (sums of k ones and 4 - k zeros, then / 4: exact in float32).
WHITE = {"workflow": "specular", "albedo": [0, 0, 0], "specular": [0, 0, 0], "smoothness": 0.0,
         "emission": [1.0, 1.0, 1.0]}
LIT = {"albedo": [0.8, 0.4, 0.2], "metallic": 0.3, "smoothness": 0.6}
# A sample whose position lies nearer the true edge than this (pixels) may fall on either side:
# the GPU's window coordinates are float32 and a rasterised edge's vertices are snapped to
# 2^-GL_SUBPIXEL_BITS of a pixel (llvmpipe: 8 bits, 1/256; each vertex coordinate moves by at
# most half of that, so the edge by at most 2^-8 / sqrt(2) * 2 < 2^-8). The sphere's ray test
# is float32 arithmetic on window coordinates below 64 (ulp 2^-18) through a handful of
# operations: far below the same 2^-8, used for both.
AMBIGUOUS_PX = 2.0 ** -8


def _data(material, objects, samples, size=SIZE, lights=()):
    return {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40, "size": [size, size]},
            "lights": copy.deepcopy(list(lights)), "environment": None,
            "materials": {"m": dict(material)}, "objects": copy.deepcopy(objects),
            "render": {"antialias": samples}}


def _render(data, gl_context, language="glsl"):
    scene = parse_scene(data)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return scene, render_scene(scene, gl_context, language=language)


def _offsets(gl_context, samples=SAMPLES):
    """The GL's sample positions in a pixel, as offsets from its centre (pixels)."""
    with targets.Target(gl_context, (4, 4), "f32", samples=samples) as target:
        return np.array(target.sample_offsets(), np.float64)


def _taken(gl_context):
    from pbrlab.gpu import gl_limits
    if SAMPLES not in gl_limits.sample_counts(gl_context, "f32"):
        pytest.skip(f"this GL takes no {SAMPLES}-sample float target")


def _window_samples(size, offsets):
    """Window coordinates (GL's: lower-left origin) of every sample, top row first: HxWxSx2."""
    w, h = size
    x = np.arange(w) + 0.5
    y = (np.arange(h) + 0.5)[::-1]
    grid = np.stack(np.broadcast_arrays(x[None, :], y[:, None]), axis=-1)
    return grid[:, :, None, :] + offsets[None, None, :, :]


# --- a half-plane: the edge of a large flat quad, tilted ------------------------------------

EDGE_DEG = 17.0  # the quad's rotation about the view axis: its edge is neither row nor column
EDGE_OFFSET = 0.13  # scene units from the view axis to the edge


def _half_plane_objects():
    """A 20-unit square facing the camera, turned EDGE_DEG about the view axis and moved so that
    one edge crosses the image near its centre; every other edge is far outside the view."""
    theta = math.radians(EDGE_DEG)
    shift = 10.0 - EDGE_OFFSET  # the square's right edge EDGE_OFFSET units along its own x from the view axis
    return [{"mesh": {"primitive": "plane", "size": 20}, "material": "m",
             "transform": {"rotate_deg": [90, 0, EDGE_DEG],
                           "translate": [-shift * math.cos(theta), -shift * math.sin(theta), 0.0]}}]


def _project(frame, point):
    """A world point's window coordinates (lower-left origin), float64."""
    clip = frame.view_proj @ np.append(point, 1.0)
    ndc = clip[:2] / clip[3]
    return (ndc * 0.5 + 0.5) * np.asarray(frame.size, np.float64)


def _edge_line(frame):
    """The edge in window coordinates: a unit normal n pointing out of the quad and c, inside
    where n . p < c."""
    theta = math.radians(EDGE_DEG)
    along = np.array([-math.sin(theta), math.cos(theta), 0.0])
    out = np.array([math.cos(theta), math.sin(theta), 0.0])
    centre = EDGE_OFFSET * out  # the edge's point nearest the view axis (the plane z = 0)
    a, b = _project(frame, centre - along), _project(frame, centre + along)
    tangent = (b - a) / np.linalg.norm(b - a)
    n = np.array([tangent[1], -tangent[0]])
    if n @ (_project(frame, centre + out) - a) < 0:
        n = -n
    return n, float(n @ a)


def _clipped_area(n, c, x0, y0):
    """Area of {p : n . p <= c} inside the unit pixel [x0, x0 + 1] x [y0, y0 + 1] (polygon
    clipping, Sutherland and Hodgman 1974, then the shoelace formula)."""
    square = [(x0, y0), (x0 + 1, y0), (x0 + 1, y0 + 1), (x0, y0 + 1)]
    kept = []
    for i, p in enumerate(square):
        q = square[(i + 1) % 4]
        fp, fq = n @ p - c, n @ q - c
        if fp <= 0:
            kept.append(p)
        if fp * fq < 0:
            t = fp / (fp - fq)
            kept.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
    if len(kept) < 3:
        return 0.0
    xs, ys = np.array(kept).T
    return 0.5 * abs(float(xs @ np.roll(ys, -1) - ys @ np.roll(xs, -1)))


def pattern_error(n, offsets):
    """The worst |covered samples / S - covered area| of the pattern over every position of a
    straight edge with normal n across a pixel: the sampling error of the pattern itself.
    The area is continuous in the edge's offset and the count steps where the edge crosses a
    sample, so the worst is at those crossings, on one side or the other."""
    centred = offsets + 0.5  # positions in the pixel [0, 1]^2
    worst = 0.0
    for s in centred:
        c = float(n @ s)
        area = _clipped_area(n, c, 0.0, 0.0)
        below = int(np.sum(centred @ n < c))
        at_or_below = int(np.sum(centred @ n <= c))
        worst = max(worst, abs(below / len(offsets) - area), abs(at_or_below / len(offsets) - area))
    return worst


@pytest.mark.parametrize("language", LANGUAGES)
def test_half_plane_edge_coverage_is_its_samples_and_near_its_area(gl_context, language):
    """Each pixel's alpha is the share of its samples inside the quad's edge (float64 here;
    samples within AMBIGUOUS_PX of the edge may go either way), and within the pattern's own
    sampling error (pattern_error, at the edge's slope) plus the vertex snapping's area
    (2^-8 px along at most sqrt(2) px of edge) of the half-plane's exact area in the pixel."""
    _taken(gl_context)
    offsets = _offsets(gl_context)
    scene, got = _render(_data(WHITE, _half_plane_objects(), SAMPLES), gl_context, language)
    alpha = got.linear[..., 3].astype(np.float64)
    n, c = _edge_line(scene_frame(scene))
    distance = _window_samples((SIZE, SIZE), offsets) @ n - c  # HxWxS, < 0 inside
    inside = (distance < 0).sum(axis=-1) / SAMPLES
    ambiguous = (np.abs(distance) < AMBIGUOUS_PX).sum(axis=-1) / SAMPLES
    assert np.all(np.abs(alpha - inside) <= ambiguous), np.argwhere(np.abs(alpha - inside) > ambiguous)[:5]
    assert 0 < ((alpha > 0) & (alpha < 1)).sum(), "no fractional coverage: not antialiased"
    area = np.array([[_clipped_area(n, c, x, SIZE - 1 - y) for x in range(SIZE)] for y in range(SIZE)])
    bound = pattern_error(n, offsets) + math.sqrt(2) * AMBIGUOUS_PX
    assert pattern_error(n, offsets) < 0.5  # four samples do better than one (0.5 at any slope)
    assert np.abs(alpha - area).max() <= bound, (np.abs(alpha - area).max(), bound)


@pytest.mark.parametrize("language", LANGUAGES)
def test_resolve_averages_linear_radiance(gl_context, language):
    """White over black: an edge pixel k of whose 4 samples are white resolves to exactly k / 4 in
    linear radiance (colour = alpha = k / 4), and its PNG code is the sRGB encode of k / 4
    (0.5 -> 188), not the average of the codes 0 and 255 (128: averaging after the encode)."""
    _taken(gl_context)
    _, got = _render(_data(WHITE, _half_plane_objects(), SAMPLES), gl_context, language)
    linear = got.linear
    assert set(np.unique(linear[..., 3])) <= {0.0, 0.25, 0.5, 0.75, 1.0}
    assert np.array_equal(linear[..., :3], np.repeat(linear[..., 3:], 3, axis=-1))
    half = linear[..., 3] == 0.5
    assert half.any()
    assert np.all(got.srgb8[half][:, :3] == srgb8.encode(np.float32([0.5]))[0]) and srgb8.encode(np.float32([0.5]))[0] == 188


@pytest.mark.parametrize("language", LANGUAGES)
def test_flat_quad_interior_is_unchanged(gl_context, language):
    """Where the quad covers every sample its radiance is the single-sampled render's, bit for
    bit (the same shading at the pixel centre; equal samples average to themselves)."""
    _taken(gl_context)
    _, one = _render(_data(WHITE, _half_plane_objects(), 1), gl_context, language)
    _, four = _render(_data(WHITE, _half_plane_objects(), SAMPLES), gl_context, language)
    full = four.linear[..., 3] == 1.0
    assert full.sum() > SIZE * SIZE // 4
    assert np.array_equal(four.linear[full], one.linear[full])


# --- a sphere: ray-traced, covering its samples itself -------------------------------------

SPHERE_RADIUS = 1.0


def _sphere_data(material, samples, lights=()):
    return _data(material, [{"sphere": {"center": [0, 0, 0], "radius": SPHERE_RADIUS}, "material": "m"}],
                 samples, lights=lights)


def _sphere_sample_hits(frame, offsets):
    """Whether each sample's camera ray hits the sphere (float64), and whether it passes within
    AMBIGUOUS_PX of the silhouette: HxWxS each."""
    w, h = frame.size
    window = _window_samples((w, h), offsets)
    ndc = window / np.array([w, h], np.float64) * 2 - 1
    rays = (frame.forward + ndc[..., :1] * frame.right + ndc[..., 1:] * frame.up)
    oc = frame.position  # the sphere's centre is the origin
    q = np.linalg.norm(np.cross(oc, rays), axis=-1) / np.linalg.norm(rays, axis=-1)  # the ray's distance
    pixel = np.linalg.norm(oc) * 2 * np.linalg.norm(frame.up) / h  # world size of a pixel at the centre's distance
    return q <= SPHERE_RADIUS, np.abs(q - SPHERE_RADIUS) < AMBIGUOUS_PX * pixel


@pytest.mark.parametrize("language", LANGUAGES)
def test_sphere_coverage_is_its_samples_rays(gl_context, language):
    """A ray-traced sphere's alpha is the share of the pixel's samples whose own rays hit it
    (float64 here; rays within AMBIGUOUS_PX of the silhouette may go either way): the sample
    mask the sphere program writes, not the proxy cube's coverage."""
    _taken(gl_context)
    offsets = _offsets(gl_context)
    scene, got = _render(_sphere_data(WHITE, SAMPLES), gl_context, language)
    hits, ambiguous = _sphere_sample_hits(scene_frame(scene), offsets)
    alpha = got.linear[..., 3].astype(np.float64)
    expected = hits.sum(axis=-1) / SAMPLES
    slack = ambiguous.sum(axis=-1) / SAMPLES
    assert np.all(np.abs(alpha - expected) <= slack), np.argwhere(np.abs(alpha - expected) > slack)[:5]
    assert ((alpha > 0) & (alpha < 1)).sum() > 0


def test_sphere_disc_alpha_sums_to_its_area(gl_context):
    """The summed alpha is the disc's area, pi rho^2 pixels (rho = f tan(asin(R / D)), the
    silhouette of a sphere centred on the view axis, f = (H / 2) / tan(fov / 2)), within the
    lattice-point bound of each sample's shifted pixel grid: the unit squares about the grid
    points inside the disc lie in the disc of radius rho + sqrt(2) / 2 and cover the one of
    rho - sqrt(2) / 2, so each grid's count is within sqrt(2) pi rho + pi / 2 of pi rho^2 (Gauss's
    circle problem, the elementary bound), and so is their average, the summed alpha. A cube's
    coverage (no sample mask) would exceed it by about (4 / pi - 1) pi rho^2."""
    _taken(gl_context)
    scene, got = _render(_sphere_data(WHITE, SAMPLES), gl_context)
    f = (SIZE / 2) / math.tan(math.radians(40) / 2)
    rho = f * math.tan(math.asin(SPHERE_RADIUS / 4.0))
    bound = math.sqrt(2) * math.pi * rho + math.pi / 2
    total = float(got.linear[..., 3].astype(np.float64).sum())
    assert abs(total - math.pi * rho ** 2) <= bound, (total, math.pi * rho ** 2, bound)


@pytest.mark.parametrize("language", LANGUAGES)
def test_sphere_interior_is_the_single_sampled_render(gl_context, language):
    """A lit sphere: where it covers every sample the pixel is shaded at its centre, as without
    antialiasing, bit for bit; and the two languages give the same antialiased image within
    the GLSL/HLSL bound of tests/gpu/hlsl (here: equal, as their single-sampled renders are)."""
    _taken(gl_context)
    lights = [{"type": "directional", "direction": [-0.4, -0.5, -1.0], "intensity": 2.0}]
    _, one = _render(_sphere_data(LIT, 1, lights), gl_context, language)
    _, four = _render(_sphere_data(LIT, SAMPLES, lights), gl_context, language)
    full = four.linear[..., 3] == 1.0
    assert full.sum() > 100
    assert np.array_equal(four.linear[full], one.linear[full])
    edge = (four.linear[..., 3] > 0) & (four.linear[..., 3] < 1)
    assert edge.sum() > 0 and set(np.unique(one.linear[..., 3])) <= {0.0, 1.0}


def test_glsl_and_hlsl_antialias_alike(gl_context):
    """The HLSL twins (SV_Coverage through spirv-cross's GLSL 400) cover the same samples as the
    GLSL programs (gl_SampleMask): the same alpha everywhere, on a sphere and on a quad's edge."""
    _taken(gl_context)
    for data in (_sphere_data(WHITE, SAMPLES), _data(WHITE, _half_plane_objects(), SAMPLES)):
        _, glsl = _render(data, gl_context, "glsl")
        _, hlsl = _render(data, gl_context, "hlsl")
        assert np.array_equal(glsl.linear[..., 3], hlsl.linear[..., 3])


# --- refusals ------------------------------------------------------------------------------

def test_antialias_beyond_this_gl_is_refused_by_name(gl_context):
    """32 samples (a value the scene format admits, beyond llvmpipe's GL_MAX_SAMPLES = 4) is
    refused before rendering, naming the scene, the field, the value and what the GL takes."""
    from pbrlab.gpu import gl_limits
    counts = gl_limits.sample_counts(gl_context, "f32")
    assert counts[0] == 1
    if 32 in counts:
        pytest.skip("this GL takes 32 samples per pixel")
    scene = parse_scene(_sphere_data(WHITE, 32), origin="aa.json")
    with pytest.raises(SceneError, match=r"aa\.json: render\.antialias: 32 samples per pixel; this GL's "
                                         r"rgba32f target with depth takes 1"):
        render_scene(scene, gl_context)


@pytest.mark.parametrize("value", [3, 0, 4.0, True, "4", 64])
def test_antialias_not_a_sample_count_is_refused_by_the_parser(value):
    data = _sphere_data(WHITE, 1)
    data["render"]["antialias"] = value
    with pytest.raises(SceneError, match=r"x\.json: render\.antialias: expected one of 1, 2, 4, 8, 16, 32"):
        parse_scene(data, origin="x.json")


# --- what reads the target: a grab pass, the transmission copy -------------------------------

WALL = {"workflow": "specular", "albedo": [0, 0, 0], "specular": [0, 0, 0], "smoothness": 0.0,
        "emission": [1.0, 0.5, 0.25]}
BACKDROP = [{"mesh": {"primitive": "plane", "size": 40}, "material": "wall",
             "transform": {"translate": [0, 0, -3], "rotate_deg": [90, 0, 0]}}]


@pytest.mark.parametrize("language", LANGUAGES)
def test_grab_pass_and_transmission_copy_read_the_resolved_target(gl_context, language, tmp_path):
    """Behind the sphere an emitter fills the view, so what a grab pass or the transmission copy
    holds is one radiance at every pixel, antialiased or not. A GrabPass shader drawing half
    of what it grabbed, and a thin glass sphere seeing the copy, give at 4 samples the
    single-sampled values bit for bit where they cover every sample; an unresolved
    multisampled grab or copy would read as black."""
    _taken(gl_context)
    shader = tmp_path / "grab.shader"
    shader.write_text("""Shader "t/Grab" { SubShader { Tags { "Queue" = "Transparent" }
GrabPass { "_BehindTex" }
Pass { CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#include "UnityCG.cginc"
sampler2D _BehindTex;
struct v2f { float4 pos : SV_POSITION; float4 grab : TEXCOORD0; };
v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.grab = ComputeGrabScreenPos(o.pos); return o; }
half4 frag(v2f i) : SV_Target { return tex2Dproj(_BehindTex, UNITY_PROJ_COORD(i.grab)) * 0.5; }
ENDCG } } }""", encoding="utf-8")
    glass = {"albedo": [1, 1, 1], "smoothness": 1.0, "transmission": 1.0}
    for front in ({"surface": str(shader)}, glass):
        renders = {}
        for samples in (1, SAMPLES):
            data = _sphere_data(front, samples)
            data["materials"]["wall"] = WALL
            data["objects"] = BACKDROP + data["objects"]
            scene = parse_scene(data, "<test>", tmp_path)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                renders[samples] = render_scene(scene, gl_context, language=language).linear
        sphere = np.zeros((SIZE, SIZE), bool)
        sphere[SIZE // 2 - 4:SIZE // 2 + 4, SIZE // 2 - 4:SIZE // 2 + 4] = True
        assert np.array_equal(renders[SAMPLES][sphere], renders[1][sphere])
        assert renders[1][sphere][:, 0].min() > 0.25  # it saw the wall (red 1, halved at most)
