"""The `pbrlab` command. Each subcommand lives in pbrlab/commands/<name>.py and exposes
``register(subparsers, common)``, where ``common`` is the parent parser carrying the
options every command takes (``--backend``).

User mistakes arrive as PbrlabError and are printed as one message, exit status 2,
without a traceback. So are the machine's own refusals that name a file (an OSError such
as a full disk or a permission denied while reading: "path: No space left on device")
and running out of memory. A command's own "no" (e.g. images over tolerance) is exit 1.
SIGTERM and SIGHUP unwind like Ctrl-C (outputs.signal_cleanup): temporary output
files are removed and the exit status is 128 + the signal number.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from ..foundation.version import __version__
from ..foundation import console, outputs
from ..foundation.errors import PbrlabError
from ..gpu.gl import BACKENDS
from ..gpu import driver_time_limit


class _VersionAction(argparse.Action):
    """``--version``: the package version and where its shaders are (``pbrlab paths``)."""

    def __init__(self, option_strings, dest, **kwargs):
        super().__init__(option_strings, dest, nargs=0, default=argparse.SUPPRESS,
                         help="print the version and where the shaders are, then exit")

    def __call__(self, parser, namespace, values, option_string=None):
        from . import paths
        print(f"pbrlab {__version__}")
        for line in paths.lines():
            print(f"  {line}")
        parser.exit()

COMMANDS = ("demo", "render", "eval", "amalgamate", "diff", "features", "hardcases", "bench", "fidelity", "port-unity",
            "paths", "schema", "tables")


# The commands that open an OpenGL context themselves, and so take --backend (the others
# would accept it and ignore it).
GL_COMMANDS = ("demo", "render", "eval", "hardcases", "bench", "fidelity")


def _named_command(argv) -> str | None:
    """The command ``argv`` names (its first word not starting with '-'), if it is one."""
    for word in argv:
        if not word.startswith("-"):
            return word if word in COMMANDS else None
    return None


def build_parser(argv=None) -> argparse.ArgumentParser:
    """The parser of every command; given ``argv`` naming a command, of that command only:
    each command module imports what it needs when registered (``pbrlab bench`` its
    reference tables), so a render starts without loading the others (issue 25).
    """
    common = argparse.ArgumentParser(add_help=False)
    loudness = common.add_mutually_exclusive_group()
    loudness.add_argument("-q", "--quiet", dest="verbosity", action="store_const", const=console.QUIET,
                          default=console.NORMAL,
                          help="Print results and errors only: no progress and no 'wrote ...' lines.")
    loudness.add_argument("-v", "--verbose", dest="verbosity", action="store_const", const=console.VERBOSE,
                          help="Also print details, such as the renderer a command runs on.")
    parser = argparse.ArgumentParser(
        prog="pbrlab", description="Render, evaluate and verify the pbrlab shading library. "
                                   "Run 'pbrlab COMMAND --help' for the options of a command.")
    parser.add_argument("--version", action=_VersionAction)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    gl = argparse.ArgumentParser(add_help=False, parents=[common])
    gl.add_argument(
        "--backend", choices=BACKENDS, default=None,
        help="The OpenGL backend to render with (default: $PBRLAB_GL_BACKEND, else EGL, then OSMesa).")
    named = _named_command(argv or [])
    for name in (named,) if named else COMMANDS:
        importlib.import_module(f"pbrlab.commands.{name.replace('-', '_')}").register(
            sub, gl if name in GL_COMMANDS else common)
    return parser


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser(argv)
    args = parser.parse_args(argv)
    console.set_level(getattr(args, "verbosity", console.NORMAL))
    try:
        # a compile that would run for hours ends with a message (gpu.driver_time_limit)
        with outputs.signal_cleanup(), driver_time_limit.enabled():
            return int(args.run(args) or 0)
    except PbrlabError as exc:
        print(f"pbrlab {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. `pbrlab features x.json | head`: the reader left
        sys.stderr.close()
        return 0
    except OSError as exc:
        if exc.filename is None and exc.errno is None:
            raise  # not the system's word about a file: a bug, keep the traceback
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"pbrlab {args.command}: error: {where}{exc.strerror or exc}", file=sys.stderr)
        return 2
    except MemoryError:
        print(f"pbrlab {args.command}: error: out of memory (try a smaller --size or fewer "
              "samples)", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        outputs.remove_live_temps()
        return 130
    except outputs.Terminated as exc:
        outputs.remove_live_temps()
        return 128 + exc.signum


if __name__ == "__main__":
    sys.exit(main())
