"""Issue 25: the bench figures the README and docs/bench.md quote are those of the committed
docs/bench/accuracy_cost.json (pbrlab.bench.headline generates the block both pages hold)."""

import copy
import json
from pathlib import Path

import pytest

from pbrlab.bench import headline
from pbrlab.foundation.errors import PbrlabError

ROOT = Path(__file__).resolve().parents[2]
JSON = ROOT / "docs" / "bench" / "accuracy_cost.json"
PAGES = (ROOT / "README.md", ROOT / "docs" / "bench.md")


@pytest.fixture(scope="module")
def doc():
    return json.loads(JSON.read_text(encoding="utf-8"))


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_page_bench_figures_are_the_committed_bench_runs(page, doc):
    text = page.read_text(encoding="utf-8")
    assert headline.replace_block(text, headline.block(doc), page.name) == text, (
        f"{page.name}: its bench figures differ from {JSON.name}; run python -m pbrlab.bench.headline "
        f"docs/bench/accuracy_cost.json README.md docs/bench.md")


def test_a_changed_figure_in_the_json_is_caught(doc, tmp_path):
    changed = copy.deepcopy(doc)
    high = next(v for f in changed["families"] if f["name"] == "brdf_tier" for v in f["variants"] if v["name"] == "high")
    high["gpu_isa"]["families"]["rdna3"]["instructions_per_eval"] += 1.0
    (tmp_path / "b.json").write_text(json.dumps(changed))
    page = tmp_path / "page.md"
    page.write_text(PAGES[1].read_text(encoding="utf-8"))
    assert headline.main([str(tmp_path / "b.json"), str(page), "--check"]) == 1
    assert headline.main([str(tmp_path / "b.json"), str(page)]) == 0
    assert headline.main([str(tmp_path / "b.json"), str(page), "--check"]) == 0


def test_a_page_without_the_block_is_a_clear_error(doc):
    with pytest.raises(PbrlabError, match="no bench-figures block"):
        headline.replace_block("# a page\n", headline.block(doc), "page.md")
