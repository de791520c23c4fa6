"""pbrlab.maths.srgb8.encode, the exact display encode (and the mip chains' colour encode): the
fast table-and-correction form gives exactly the codes of a plain search of the code
edges (round to nearest on the IEC 61966-2-1 curve), also at and next to every edge."""

import numpy as np

from pbrlab.maths import srgb8
from pbrlab.maths.reference.color import linear_to_srgb


def _search(x):
    return np.searchsorted(srgb8.ENCODE_EDGES, np.nan_to_num(x, nan=0.0), side="right").astype(np.uint8)


def test_encode_equals_the_edge_search_at_and_around_every_edge():
    edges = srgb8.ENCODE_EDGES
    f32 = lambda a: a.astype(np.float32).astype(np.float64)  # noqa: E731
    x = np.concatenate([edges, np.nextafter(edges, 0), np.nextafter(edges, 1), f32(edges),
                        f32(np.nextafter(edges.astype(np.float32), np.float32(0))),
                        f32(np.nextafter(edges.astype(np.float32), np.float32(1))),
                        [0.0, 1.0, -1.0, 2.0, np.nan, np.inf, -np.inf, 1e-30, 5e-324, 1 - 1e-12]])
    assert np.array_equal(srgb8.encode(x), _search(x))


def test_encode_equals_the_edge_search_over_float32_and_float64_values():
    every_997th_float32 = np.arange(0, 0x3F800001, 997, dtype=np.uint32).view(np.float32)
    assert np.array_equal(srgb8.encode(every_997th_float32), _search(every_997th_float32.astype(np.float64)))
    rng = np.random.default_rng(5)
    x = np.concatenate([rng.random(200_000), rng.random(200_000) ** 8])
    assert np.array_equal(srgb8.encode(x), _search(x))


def test_encode_rounds_to_the_nearest_code_of_the_exact_curve():
    x = np.random.default_rng(6).random(100_000)
    assert np.array_equal(srgb8.encode(x), np.rint(255 * linear_to_srgb(x)).astype(np.uint8))
