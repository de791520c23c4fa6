"""The documentation: README.md is a short front page, docs/ a MkDocs site that builds with
--strict (a broken internal link or anchor, or a page missing from the nav, fails), and every
snippet marked as runnable (doc_snippets.py: ``<!-- runs: PATH -->`` / ``<!-- runs -->``) runs
as pasted, in a fresh project, with the interpreter running these tests."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from doc_snippets import parse
from site_build import ROOT, copy_site_sources, mkdocs_build, run

README = ROOT / "README.md"
README_MAX_LINES = 200  # issue 27: what it is, a picture, the two commands, one example, links
DOCUMENTS = [README, *sorted((ROOT / "docs").rglob("*.md"))]
RUNNABLE = [doc for doc in DOCUMENTS if parse(doc).files or parse(doc).shell]
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def test_readme_is_a_short_front_page():
    lines = README.read_text(encoding="utf-8").splitlines()
    assert len(lines) <= README_MAX_LINES, f"README.md has {len(lines)} lines; move detail to docs/"


def test_readme_keeps_the_two_commands():
    """.ci/run and the Makefile point new users at these two lines."""
    text = README.read_text(encoding="utf-8")
    assert "make demo   # set everything up, render the material charts and the lit example to out/" in text
    assert "make test   # set everything up, run the whole test suite" in text


def test_readme_links_point_at_files_that_exist():
    """README.md is read on the forge, outside the site: its relative links are paths."""
    text = README.read_text(encoding="utf-8")
    targets = [t for t in LINK.findall(text) if not re.match(r"[a-z]+:", t) and not t.startswith("#")]
    assert targets, "README.md links to no page"
    missing = [t for t in targets if not (ROOT / t.split("#")[0]).exists()]
    assert not missing, missing


def test_site_builds_with_strict(built_site):
    site = built_site
    # The included files arrived: glsl/README.md's function table, the README's example,
    # the example scene.
    assert "Functions, sources and measured worst-case error" in (site / "library" / "index.html").read_text(encoding="utf-8")
    assert "my_rim" in (site / "getting-started" / "index.html").read_text(encoding="utf-8")
    scenes_page = (site / "scenes" / "index.html").read_text(encoding="utf-8")
    assert "red_plastic" in scenes_page
    # The scene-file reference's tables, rendered from the JSON Schema: every field of every
    # object, and the parser's own checks.
    from pbrlab.scene.schema import PARSER_ONLY_RULES, scene_schema
    schema = scene_schema()
    fields = [key for node in schema["$defs"].values() for key in node.get("properties", {})]
    missing = [key for key in fields if f"<code>{key}</code></td>" not in scenes_page]
    assert not missing, missing
    assert "&lt;!-- scene-schema --&gt;" not in scenes_page and "<!-- scene-schema -->" not in scenes_page
    assert "What the parser checks beyond the schema" in scenes_page
    assert "not parallel to the view direction" in PARSER_ONLY_RULES[2] and PARSER_ONLY_RULES[2].split("`")[-1] in scenes_page
    # The generated page: every GLSL file of the library, with its Provides line.
    files_page = (site / "library-files" / "index.html").read_text(encoding="utf-8")
    glsl = ROOT / "glsl"
    missing = [p.relative_to(glsl).as_posix() for p in glsl.rglob("*.glsl")
               if f"<code>{p.relative_to(glsl).as_posix()}</code>" not in files_page]
    assert not missing, missing
    assert files_page.count("Provides:") == len(list(glsl.rglob("*.glsl")))


@pytest.mark.parametrize("link", ["[nowhere](no-such-page.md)",
                                  "![a golden the site does not serve](goldens/chart_f0.png)"],
                         ids=["page", "golden-not-served"])
def test_strict_build_fails_on_a_broken_link(site_tools, tmp_path, link):
    """The check above can fail: a link to a page that does not exist stops the build, and so
    does a picture of goldens/ that scripts/mkdocs_goldens.py does not serve (chart_f0.png is
    in goldens/, but no page shows it)."""
    copy_site_sources(tmp_path)
    page = tmp_path / "docs" / "conventions.md"
    page.write_text(page.read_text(encoding="utf-8") + f"\nSee {link}.\n", encoding="utf-8")
    result = mkdocs_build(tmp_path / "mkdocs.yml", tmp_path / "site")
    assert result.returncode != 0
    target = LINK.search(link).group(1)
    assert target in result.stdout + result.stderr


def test_readme_has_a_runnable_example():
    project = parse(README)
    assert [s.path for s in project.files] == ["shaders/my/rim.glsl", "shaders/rim_surface.glsl",
                                               "test_my_shader.py"]
    assert project.commands()


@pytest.mark.parametrize("document", RUNNABLE, ids=[str(d.relative_to(ROOT)) for d in RUNNABLE])
def test_runnable_snippets_run_as_pasted(document, tmp_path):
    """The document's files, written into an empty folder; then its shell blocks' commands,
    in order: every one must succeed."""
    project = parse(document)
    assert project.shell, f"{document.name}: runnable files, but no <!-- runs --> block runs them"
    project.write(tmp_path)
    for command in project.commands():
        result = run(command, tmp_path)
        assert result.returncode == 0, f"{' '.join(command)}\n{result.stdout}\n{result.stderr}"


def test_readme_example_first_run_names_the_missing_golden(tmp_path):
    """What the README says of the first run: it fails, and says how to create the golden."""
    parse(README).write(tmp_path)
    result = run(["python", "-m", "pytest"], tmp_path)
    assert result.returncode == 1, result.stdout + result.stderr
    assert "golden 'rim_sphere' is missing" in result.stdout
    assert "--update-goldens" in result.stdout
    assert "1 failed, 1 passed" in result.stdout


@pytest.mark.parametrize("text, message", [
    ("<!-- runs: a.py -->\n\n```python\nx = 1\n```\n", "must be followed by a fenced code block"),
    ("<!-- runs: a.py -->\n```python\nx = 1\n", "not closed"),
    ('<!-- runs: a.py -->\n```python title="b.py"\nx = 1\n```\n', "is not the file its marker writes"),
    ("<!-- runs: ../a.py -->\n```python\nx = 1\n```\n", "must be a path inside the project"),
], ids=["no-block", "unclosed", "title-mismatch", "outside"])
def test_a_malformed_marker_is_an_error_not_a_skipped_snippet(tmp_path, text, message):
    page = tmp_path / "page.md"
    page.write_text(text, encoding="utf-8")
    with pytest.raises(ValueError, match=message):
        parse(page)
