"""Generate wgsl/pbrlab.wgsl from glsl/: the shader library as naga translates it, for WebGPU
(wgpu, Bevy, browsers).

    python -m pbrlab.gpu.port_wgsl            # rewrite wgsl/pbrlab.wgsl from glsl/
    python -m pbrlab.gpu.port_wgsl --check    # exit 1 if wgsl/pbrlab.wgsl is stale

The file is generated, never edited: tests/library/test_wgsl_amalgamation.py fails when
regenerating would change it. The recipe is the whole port:

  1. ``pbrlab amalgamate pbr/pbr.glsl`` (the core umbrella; the Unity layer, an opt-in room of
     its own, is not in it), under ``#version 450``, with an empty ``void main() {}``: naga's
     GLSL front end needs an entry point, and keeps every function, called or not.
  2. naga (NAGA_VERSION, pbrlab.gpu.naga) translates and validates it.
  3. The stub entry point (``fn main_1`` and ``@fragment fn main``) is cut out; a header
     states the configuration and every name naga changed (below).

WGSL has no preprocessor, so the file is one configuration: every selector at its default
(glsl/README.md), no hooks. Without PBR_DFG_LUT_LOOKUP the environment BRDF is the analytic fit
(pbr_env_brdf_approx); a WebGPU engine that wants the DFG table translates the GLSL itself with
the hook defined, as examples/wgpu does. naga's names: a function that overloads an earlier one
gets ``_1``, ``_2`` in declaration order; a name (function, parameter or struct member) that
ends in a digit gets a trailing ``_`` (``pbr_pow5_``, ``f0_``); parameters and locals get
numeric suffixes where names repeat across the module.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from ..foundation.errors import PbrlabError
from ..foundation.locations import locate
from . import naga, shaders

WGSL_ROOT = locate("wgsl")
WGSL_FILE = "pbrlab.wgsl"
UMBRELLA = "pbr/pbr.glsl"
GENERATOR = "harness/pbrlab/gpu/port_wgsl.py"
_STUB_ENTRY = "void main() {}\n"
# What naga writes for the stub: the GLSL main as main_1 and the WGSL entry point calling it.
_STUB_WGSL = re.compile(r"\nfn main_1\(\) \{\n    return;\n\}\n\n@fragment ?\nfn main\(\) \{\n    main_1\(\);\n"
                        r"    return;\n\}\n")
_WGSL_FN = re.compile(r"^fn (\w+)\((.*?)\)( -> [^{]+?)? \{$", re.M)
_GLSL_NAME = re.compile(r"\b([A-Za-z_]\w*)\s*\(")


def _glsl_source(glsl_root: Path) -> str:
    return "#version 450\n" + shaders.amalgamate(glsl_root / UMBRELLA) + "\n" + _STUB_ENTRY


def _renamed(glsl: str, wgsl: str) -> list[str]:
    """'wgsl_name(params) -> type   GLSL name' for each function naga renamed."""
    glsl_names = set(_GLSL_NAME.findall(glsl))
    lines = []
    for m in _WGSL_FN.finditer(wgsl):
        name = m.group(1)
        if name in glsl_names:
            continue
        base = re.sub(r"_\d+$", "", name) if re.search(r"_\d+$", name) and re.sub(r"_\d+$", "", name) in glsl_names \
            else name
        if base == name and name.endswith("_") and name[:-1] in glsl_names:
            base = name[:-1]
        why = "overload" if base != name and not name.endswith("_") else "ends in a digit"
        if base not in glsl_names:
            raise PbrlabError(f"{GENERATOR}: naga's function {name} matches no GLSL function; "
                              "its renaming rule changed: update this generator")
        types = ", ".join(param.split(": ", 1)[1] for param in m.group(2).split(", ") if param)
        lines.append(f"{name}({types}){m.group(3) or ''}   <- GLSL {base} ({why})")
    return lines


def generate(glsl_root: Path = shaders.GLSL_ROOT) -> str:
    """The text of wgsl/pbrlab.wgsl."""
    glsl = _glsl_source(glsl_root)
    wgsl = naga.glsl_to_wgsl(glsl, "frag", UMBRELLA)
    stub = list(_STUB_WGSL.finditer(wgsl))
    if len(stub) != 1:
        raise PbrlabError(f"{GENERATOR}: naga {naga.NAGA_VERSION}'s stub entry point is not where it was "
                          "(fn main_1 / @fragment fn main): update this generator")
    body = wgsl[:stub[0].start()] + "\n" + wgsl[stub[0].end():]
    header = [
        "// pbrlab.wgsl: the pbrlab shading library (glsl/pbr/pbr.glsl, every public file) in WGSL, for",
        "// WebGPU: wgpu, Bevy, browsers. Paste it above your own WGSL or load it as a module source.",
        f"// Generated from glsl/ by {GENERATOR} with naga {naga.NAGA_VERSION} (the translator of wgpu):",
        "// do not edit; edit the GLSL, then run python -m pbrlab.gpu.port_wgsl. docs/wgsl.md explains it.",
        "//",
        "// One configuration (WGSL has no preprocessor): every selector at its default (glsl/README.md),",
        "// no hooks, so the environment BRDF is the analytic fit (pbr_env_brdf_approx), not the DFG table.",
        "// Names: the library's (glsl/README.md), except where naga changed them: an overload gets _1, _2",
        "// in declaration order; a name ending in a digit gets a trailing _ (functions, parameters and",
        "// struct members alike: pbr_PreparedSurface.f0_ and .f90_); parameters and locals get numeric",
        "// suffixes where names repeat. The library's #define constants are inlined as numbers.",
        "// Renamed functions (WGSL name and parameter types <- GLSL name):",
        *[f"//   {line}" for line in _renamed(glsl, body)],
        "// SPDX-License-Identifier: MIT. Part of pbrlab (https://spdx.org/licenses/MIT); full text in its LICENSE file.",
        "",
    ]
    return "\n".join(header) + body.rstrip("\n") + "\n"


def is_stale(glsl_root: Path = shaders.GLSL_ROOT, wgsl_root: Path = WGSL_ROOT) -> bool:
    path = wgsl_root / WGSL_FILE
    return not path.is_file() or path.read_text(encoding="utf-8") != generate(glsl_root)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pbrlab.gpu.port_wgsl", description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="report a stale wgsl/pbrlab.wgsl, write nothing")
    parser.add_argument("--glsl-root", type=Path, default=shaders.GLSL_ROOT)
    parser.add_argument("--wgsl-root", type=Path, default=WGSL_ROOT)
    args = parser.parse_args(argv)
    try:
        if args.check:
            if is_stale(args.glsl_root, args.wgsl_root):
                print(f"{WGSL_FILE}: differs from the generated text", file=sys.stderr)
                print("regenerate with: python -m pbrlab.gpu.port_wgsl", file=sys.stderr)
                return 1
            return 0
        text = generate(args.glsl_root)
        path = args.wgsl_root / WGSL_FILE
        if not path.is_file() or path.read_text(encoding="utf-8") != text:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
            print(f"wrote {path}")
        return 0
    except PbrlabError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
