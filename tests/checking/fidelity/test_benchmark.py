"""pbrlab against the path tracer, as CI can check it: every committed scene of the fidelity
benchmark (benchmarks/fidelity: the Cycles references, the peers' images, a second Cycles
seed) re-rendered by pbrlab here and scored with the protocol's metric.

Each row's bound comes from the peers and the reference, never from pbrlab's own output
(benchmark.Row.bound_db): not worse than the worst of three.js and the Sample Viewer,
widened by the reference's noise (ratios add in squares). The committed reference is good
enough to score with when its noise (seed 1 against seed 0) moves no renderer's score by
more than 0.5 dB: noise ratio <= sqrt(10^0.1 - 1) = 0.35 of the smallest ratio scored."""

import math

import pytest

from pbrlab.checking.fidelity import benchmark, renderers, staging

SCENARIOS = staging.read_scenarios()
COMMITTED = [s for s in SCENARIOS if benchmark.reference_path(s.key, "cycles").is_file()]
NOISE_SHARE = math.sqrt(10 ** 0.1 - 1)  # a 0.5 dB move of a score by noise adding in squares


def test_every_scene_has_its_committed_references():
    assert COMMITTED == SCENARIOS, [s.key for s in SCENARIOS if s not in COMMITTED]
    for s in SCENARIOS:
        for name in ("cycles", benchmark.NOISE, *renderers.PEERS):
            assert benchmark.reference_path(s.key, name).is_file(), (s.key, name)


@pytest.fixture(scope="module")
def rows():
    return {r.key: r for r in benchmark.run(COMMITTED, log=lambda line: None)}


@pytest.mark.parametrize("key", [s.key for s in COMMITTED])
def test_pbrlab_is_within_its_bound(rows, key):
    row = rows[key]
    assert row.bound_db() is not None, key
    assert row.scores["pbrlab"] <= row.bound_db(), (
        f"{key}: pbrlab {row.scores['pbrlab']:.2f} dB, bound {row.bound_db():.2f} dB "
        f"(peers {', '.join(f'{p} {row.scores[p]:.2f}' for p in renderers.PEERS)}, noise {row.noise_db:.2f})")


@pytest.mark.parametrize("key", [s.key for s in COMMITTED])
def test_the_references_noise_moves_no_score_by_half_a_decibel(rows, key):
    row = rows[key]
    smallest = min(10 ** (v / 10) for v in row.scores.values())
    assert 10 ** (row.noise_db / 10) <= NOISE_SHARE * smallest, (key, row.noise_db, row.scores)
