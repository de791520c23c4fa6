"""The site's pages written from the code (issue 36): the `pbrlab` command's reference from its
argument parser (scripts/mkdocs_cli_reference.py), the Python API reference from the
docstrings (mkdocstrings, docs/api/), and the goldens the front pages show
(scripts/mkdocs_goldens.py). Each check reads the built site (conftest.built_site) against
the code, so a command, an option or a public name added to the code and missing from the
site fails here."""

from __future__ import annotations

import argparse
import html
import importlib.util
import re

import pytest

from site_build import ROOT

HEADING_ID = re.compile(r'<h[1-6] id="([^"]+)"')


def _hook(name: str):
    """A hook module of scripts/, imported as MkDocs loads it."""
    spec = importlib.util.spec_from_file_location(name, ROOT / "scripts" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _page(site, name: str) -> str:
    return html.unescape((site / name / "index.html").read_text(encoding="utf-8"))


def _sections(page: str) -> dict[str, str]:
    """The CLI page split at its subcommand headings (``<h2 id="NAME">``): NAME -> its HTML."""
    parts = re.split(r'<h2 id="([^"]+)"', page)
    return dict(zip(parts[1::2], parts[2::2]))


def _subcommands(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return dict(action.choices)


def _missing_from_cli_page(page: str, parser: argparse.ArgumentParser) -> list[str]:
    """Each subcommand without its section, and each option missing from its section."""
    sections = _sections(page)
    missing = []
    for name, sub in _subcommands(parser).items():
        if name not in sections:
            missing.append(name)
            continue
        missing += [f"{name} {option}" for action in sub._actions for option in action.option_strings
                    if action.help != argparse.SUPPRESS and f"<code>{option}" not in sections[name]]
    return missing


def test_cli_reference_has_every_subcommand_and_option(built_site):
    from pbrlab.commands.cli import COMMANDS, build_parser

    parser = build_parser()
    assert set(_subcommands(parser)) == set(COMMANDS)
    page = _page(built_site, "cli")
    assert not _missing_from_cli_page(page, parser)
    # each command's usage, and its one-line help as the parser holds it
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    for choice in action._choices_actions:
        section = " ".join(re.sub(r"<[^>]+>", "", _sections(page)[choice.dest]).split())
        assert f"usage: pbrlab {choice.dest}" in section
        assert " ".join(choice.help.split()) in section, choice.dest


def test_cli_check_fails_on_a_page_without_a_command(built_site):
    """The check above can fail: the built page with `render`'s section taken out."""
    from pbrlab.commands.cli import build_parser

    page = _page(built_site, "cli")
    sections = _sections(page)
    without_render = page.replace(f'<h2 id="render"{sections["render"]}', "")
    assert _missing_from_cli_page(without_render, build_parser()) == ["render"]


def test_cli_reference_is_written_from_the_parser():
    """A subcommand and an option added to a parser appear in the page written from it: the
    page follows the parser, it is not a copy."""
    from pbrlab.commands.cli import build_parser

    parser = build_parser(["paths"])
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    extra = sub.add_parser("frobnicate", help="Frobnicate the shaders.")
    extra.add_argument("--zap", metavar="N", help="zap N times (default: %(default)s)", default=3)
    text = _hook("mkdocs_cli_reference").cli_reference(parser)
    assert "## `pbrlab frobnicate` {#frobnicate}" in text
    assert "| `--zap N` | zap N times (default: 3) |" in text
    assert "[`paths`](#paths)" in text and "[`render`](#render)" not in text


def test_pytest_plugin_page_has_every_option_and_fixture(built_site):
    from pbrlab.checking import pytest_plugin

    recorder = _hook("mkdocs_cli_reference")._OptionRecorder()
    pytest_plugin.pytest_addoption(recorder)
    options = [name for names, _ in recorder.options for name in names]
    assert "--update-goldens" in options and len(options) == 4
    page = _page(built_site, "api/pytest-plugin")
    assert not [o for o in options if f"<code>{o}" not in page]


def _public_names() -> dict[str, list[str]]:
    """The public fronts by API page, from what the code declares public: ``pbrlab.__all__``,
    the scene front's loader names, the renderer's and the comparison module's public
    functions and classes (neither declares ``__all__``), the plugin's fixtures and its class,
    and ``pbrlab.checking.goldens.__all__``."""
    from _pytest.fixtures import FixtureFunctionDefinition

    import pbrlab
    import pbrlab.scene
    from pbrlab.checking import compare, goldens, pytest_plugin
    from pbrlab.render import renderer

    def defined_in(module):
        return [n for n, o in vars(module).items() if not n.startswith("_")
                and (callable(o) and getattr(o, "__module__", None) == module.__name__)
                and not isinstance(o, FixtureFunctionDefinition) and not n.startswith("pytest_")]

    fixtures = [n for n, o in vars(pytest_plugin).items()
                if isinstance(o, FixtureFunctionDefinition) and not n.startswith("_")]
    return {"api/evaluate": list(pbrlab.__all__),
            "api/scenes": list(pbrlab.scene._FROM_LOADER),
            "api/render": defined_in(renderer),
            "api/pytest-plugin": fixtures + ["GoldenFixture"],
            "api/checking": list(goldens.__all__) + defined_in(compare)}


def _undocumented(page: str, names: list[str]) -> list[str]:
    """The names with no entry of their own (a heading whose id is the object's path)."""
    ids = HEADING_ID.findall(page)
    return [n for n in names if not any(i == n or i.endswith(f".{n}") for i in ids)]


def test_api_reference_documents_every_public_name(built_site):
    names = _public_names()
    assert {"evaluate", "vec3", "PbrlabError", "__version__", "load_scene", "parse_scene",
            "render_scene", "gl_context", "golden", "check_golden", "diff"} <= \
        {n for group in names.values() for n in group}
    missing = {page: _undocumented(_page(built_site, page), group) for page, group in names.items()}
    assert not any(missing.values()), missing


def test_api_check_fails_on_a_page_without_an_entry(built_site):
    """The check above can fail: the render page with render_scene's heading id taken out."""
    page = _page(built_site, "api/render")
    assert 'id="pbrlab.render.renderer.render_scene"' in page
    stripped = page.replace('id="pbrlab.render.renderer.render_scene"', 'id="elsewhere"')
    assert _undocumented(stripped, ["render_scene", "Rendering"]) == ["render_scene"]


@pytest.mark.parametrize("page, golden", [("", "lit_scene_high"), ("getting-started", "chart_metallic"),
                                          ("unity", "lit_scene_high"), ("gltf", "gltf_features_environment")],
                         ids=["home", "getting-started", "unity", "gltf"])
def test_front_pages_show_a_golden(built_site, page, golden):
    """Each front page shows its picture, served from goldens/ as the same bytes."""
    text = (built_site / page / "index.html").read_text(encoding="utf-8")
    up = "../" if page else ""
    assert '<img alt="' in text and f'src="{up}goldens/{golden}.png"' in text
    assert (built_site / "goldens" / f"{golden}.png").read_bytes() == \
        (ROOT / "goldens" / f"{golden}.png").read_bytes()
