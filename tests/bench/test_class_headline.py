"""Issue 35: the README's whole-pixel table per material class is generated from the committed
run of benchmarks/whole_program_cost.py (docs/bench/whole_program_cost.json) by
pbrlab.bench.class_headline, so the README quotes the bench's figures; the same figures are
docs/bench.md's RDNA3 column (its table per family, written from the same run)."""

from __future__ import annotations

import copy
import json
import re
from pathlib import Path

import pytest

from pbrlab.bench import class_headline
from pbrlab.foundation.errors import PbrlabError

ROOT = Path(__file__).resolve().parents[2]
JSON = ROOT / "docs" / "bench" / "whole_program_cost.json"
README = ROOT / "README.md"


@pytest.fixture(scope="module")
def doc():
    return json.loads(JSON.read_text(encoding="utf-8"))


def test_the_readme_table_is_the_committed_bench_run(doc):
    text = README.read_text(encoding="utf-8")
    assert class_headline.replace_block(text, class_headline.block(doc), "README.md") == text, (
        "README.md: its class-cost figures differ from docs/bench/whole_program_cost.json; run "
        "python -m pbrlab.bench.class_headline docs/bench/whole_program_cost.json README.md")


def test_a_changed_figure_is_caught(doc):
    """Control: one instruction more in one peer's figure changes the block."""
    changed = copy.deepcopy(doc)
    changed["results"]["sheen-1light-env"]["three.js"]["families"]["rdna3"]["instructions"] += 1
    assert class_headline.block(changed) != class_headline.block(doc)


def test_docs_bench_quotes_the_same_rdna3_figures(doc):
    """docs/bench.md's per-family table agrees with the JSON on every RDNA3 instruction / VGPR pair."""
    text = (ROOT / "docs" / "bench.md").read_text(encoding="utf-8")
    section = text[text.index("## The whole program per glTF material class"):]
    quoted, current = {}, None
    for m in re.finditer(r"^\| ([a-z-]*) \| \**(pbrlab production|three\.js|Sample Viewer)[^|]*\| \**(\d+) / (\d+) /",
                         section, re.M):
        current = m.group(1) or current
        quoted[(current, m.group(2))] = (int(m.group(3)), int(m.group(4)))
    for key, row in doc["results"].items():
        if not key.endswith("-1light-env"):
            continue
        material_class = key[:-len("-1light-env")]
        for column in ("pbrlab production", "three.js", "Sample Viewer"):
            f = row[column]["families"]["rdna3"]
            assert quoted[(material_class, column)] == (f["instructions"], f["vgprs"]), (material_class, column)


def test_a_document_without_the_done_when_case_is_refused(doc):
    empty = dict(doc, results={k: v for k, v in doc["results"].items() if not k.endswith("-1light-env")})
    with pytest.raises(PbrlabError, match="no one-light, environment case"):
        class_headline.block(empty)
