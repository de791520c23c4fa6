"""MkDocs hook of the pbrlab site (mkdocs.yml, ``hooks:``): the command-line references, written
at every build from the code that parses the command line, never edited by hand.

``cli.md``: the ``pbrlab`` command, from its argument parser
(``pbrlab.commands.cli.build_parser``): every subcommand with its one-line help, its usage,
its description and every option with its help, choices and default.

``<!-- pytest-options -->`` in a page (api/pytest-plugin.md): the table of the pytest
plugin's options, from its ``pytest_addoption``.

argparse has no public way to walk a parser, so this reads the attributes every argparse
documentation tool reads (``_actions``, ``_SubParsersAction.choices`` and
``_choices_actions``, ``HelpFormatter._expand_help``): stable since Python 3.2.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from mkdocs.structure.files import File

PAGE = "cli.md"
USAGE_WIDTH = 100  # the usage lines' width: fixed, so the page does not follow the terminal's


def _subcommands(parser: argparse.ArgumentParser):
    """(name, one-line help, subparser) of each subcommand, in the order they were added."""
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    helps = {choice.dest: choice.help for choice in action._choices_actions}
    return [(name, helps.get(name) or "", sub) for name, sub in action.choices.items()]


def _usage(parser: argparse.ArgumentParser) -> str:
    formatter = argparse.HelpFormatter(parser.prog, width=USAGE_WIDTH)
    formatter.add_usage(parser.usage, parser._actions, parser._mutually_exclusive_groups)
    return formatter.format_help().strip()


def _cell(text: str) -> str:
    return " ".join(text.split()).replace("|", "\\|")


def _argument(action: argparse.Action) -> str:
    """How the argument is written: ``-o OUTPUT``, ``--backend {egl,osmesa}``, ``scene``."""
    if not action.option_strings:
        return f"`{action.metavar or action.dest}`"
    if action.nargs == 0:
        value = ""
    elif action.metavar is not None:
        value = f" {action.metavar if isinstance(action.metavar, str) else ' '.join(action.metavar)}"
    elif action.choices is not None:
        value = " {" + ",".join(map(str, action.choices)) + "}"
    else:
        value = f" {action.dest.upper()}"
    return ", ".join(f"`{option}{value}`" for option in action.option_strings)


def _meaning(parser: argparse.ArgumentParser, action: argparse.Action) -> str:
    text = parser._get_formatter()._expand_help(action) if action.help else ""
    extra = []
    if action.choices is not None and action.metavar is not None:
        extra.append("one of " + ", ".join(f"`{c}`" for c in action.choices))
    shown_default = action.default not in (None, False, argparse.SUPPRESS) and action.nargs != 0
    if shown_default and "default" not in text:
        extra.append(f"default `{action.default}`")
    return _cell(text + (f" ({'; '.join(extra)})" if extra else ""))


def _arguments_table(parser: argparse.ArgumentParser) -> list[str]:
    rows = [f"| {_argument(a)} | {_meaning(parser, a)} |" for a in parser._actions
            if a.help != argparse.SUPPRESS]
    return ["| argument | meaning |", "|---|---|", *rows] if rows else []


def _description(text: str | None, raw: bool) -> list[str]:
    """A description as the terminal shows it: verbatim when the parser keeps its layout."""
    if not text:
        return []
    return ["```text", text.strip("\n"), "```", ""] if raw else [" ".join(text.split()), ""]


def cli_reference(parser: argparse.ArgumentParser) -> str:
    commands = _subcommands(parser)
    out = ["# The `pbrlab` command",
           "",
           "Every subcommand of `pbrlab` (also `python -m pbrlab`) with its options, written from the",
           "command's argument parser (`pbrlab.commands.cli.build_parser`) at each build by",
           "`scripts/mkdocs_cli_reference.py`: what `pbrlab COMMAND --help` prints. How the commands fit",
           "together: [The harness](harness.md).",
           "",
           "```text", _usage(parser), "```", "",
           *_description(parser.description, False),
           *_arguments_table(parser), "",
           "| command | what it does |", "|---|---|",
           *[f"| [`{name}`](#{name}) | {_cell(help_)} |" for name, help_, _ in commands], ""]
    for name, help_, sub in commands:
        raw = issubclass(sub.formatter_class, argparse.RawDescriptionHelpFormatter)
        out += [f"## `pbrlab {name}` {{#{name}}}", "", _cell(help_), "",
                "```text", _usage(sub), "```", "",
                *_description(sub.description, raw),
                *_arguments_table(sub), "",
                *_description(sub.epilog, raw)]
    return "\n".join(out)


class _OptionRecorder:
    """Stands for pytest's parser and its option group: records each ``addoption`` call."""

    def __init__(self):
        self.options = []

    def getgroup(self, *args, **kwargs):
        return self

    def addoption(self, *names, **settings):
        self.options.append((names, settings))


def pytest_options_table(pytest_addoption) -> str:
    recorder = _OptionRecorder()
    pytest_addoption(recorder)
    rows = []
    for names, settings in recorder.options:
        value = "" if settings.get("action") == "store_true" else f" {settings.get('metavar', 'VALUE')}"
        meaning = settings.get("help", "")
        if settings.get("choices"):
            meaning += f" (one of {', '.join(f'`{c}`' for c in settings['choices'])})"
        rows.append(f"| {', '.join(f'`{n}{value}`' for n in names)} | {_cell(meaning)} |")
    return "\n".join(["| option | meaning |", "|---|---|", *rows])


def _import_pbrlab_from(config) -> None:
    root = Path(config["config_file_path"]).parent
    if (root / "harness" / "pbrlab").is_dir():  # this checkout's package, not an installed one
        sys.path.insert(0, str(root / "harness"))


def on_files(files, config):
    _import_pbrlab_from(config)
    from pbrlab.commands.cli import build_parser

    files.append(File.generated(config, PAGE, content=cli_reference(build_parser())))
    return files


PYTEST_OPTIONS_MARKER = "<!-- pytest-options -->"


def on_page_markdown(markdown, page, config, files):
    if PYTEST_OPTIONS_MARKER not in markdown:
        return markdown
    _import_pbrlab_from(config)
    from pbrlab.checking.pytest_plugin import pytest_addoption

    return markdown.replace(PYTEST_OPTIONS_MARKER, pytest_options_table(pytest_addoption))
