"""Which x86 instructions llvmpipe compiled for each stage of a render, and where the
approximate ones are.

Mesa's release builds print no shader assembly (GALLIVM_DEBUG=asm is compiled out), so this
reads the machine code itself: llvmpipe writes its JIT code into anonymous executable
mappings of the process. A snapshot of those mappings is taken before and after each stage
of ``render_scene`` (environment prefilter, scene draws, display resolve); the bytes that
changed are the code compiled for that stage, and objdump disassembles them.

What it looks for: instructions whose result is not fixed by IEEE 754 but by the CPU model,
so that two x86-64 machines can disagree on the last bits (APPROXIMATE_MNEMONICS): the
reciprocal and reciprocal-square-root estimates (RSQRTPS/SS, RCPPS/SS and their VEX/EVEX
forms). Everything else llvmpipe emits for shading here (mul, add, div, sqrt, min, max,
cvt, round, shuffles) is exactly specified.

Limits, stated: a linear sweep over JIT memory (chunks start at 16-byte boundaries, where
LLVM places functions) can also decode constant pools as instructions; a hit is therefore
reported with its address and neighbours so it can be checked, and the positive controls
(``CONTROLS``: a draw into an sRGB framebuffer, glGenerateMipmap of an sRGB texture) must
find the estimate instructions, or the scan itself is broken.

Run: ``python -m pbrlab.checking.codescan [--json] [GOLDEN ...]`` (each scene shaded in GLSL and in
HLSL, each in a fresh process, so nothing is already compiled). Needs objdump (Debian's
binutils) and Linux's /proc.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import re
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

APPROXIMATE_MNEMONICS = frozenset({
    "rsqrtps", "rsqrtss", "rcpps", "rcpss",                        # SSE: 12-bit estimates
    "vrsqrtps", "vrsqrtss", "vrcpps", "vrcpss",                    # AVX forms of the same
    "vrsqrt14ps", "vrsqrt14ss", "vrcp14ps", "vrcp14ss",            # AVX-512: 14-bit
    "vrsqrt28ps", "vrsqrt28ss", "vrcp28ps", "vrcp28ss",            # AVX-512ER
    "vrsqrtph", "vrsqrtsh", "vrcpph", "vrcpsh",                    # AVX-512 FP16
})
FUNCTION_ALIGNMENT = 16  # LLVM's x86 function alignment
MERGE_GAP = 64           # changed byte ranges closer than this are one chunk


def executable_regions() -> list[tuple[int, int]]:
    """(start, end) of this process's anonymous executable mappings (JIT code)."""
    regions = []
    with open("/proc/self/maps") as maps:
        for line in maps:
            fields = line.split()
            path = fields[5] if len(fields) > 5 else ""
            if "x" in fields[1] and (not path or path.startswith("[anon")):
                start, end = (int(value, 16) for value in fields[0].split("-"))
                regions.append((start, end))
    return regions


def snapshot() -> dict[int, bytes]:
    """The bytes of every JIT mapping, by start address."""
    out = {}
    with open("/proc/self/mem", "rb", buffering=0) as mem:
        for start, end in executable_regions():
            with contextlib.suppress(OSError):
                mem.seek(start)
                out[start] = mem.read(end - start)
    return out


def changed_chunks(before: dict[int, bytes], after: dict[int, bytes]) -> list[tuple[int, bytes]]:
    """(address, bytes) of code written between two snapshots, aligned to function starts."""
    import numpy as np

    chunks = []
    for start, data in after.items():
        new = np.frombuffer(data, np.uint8)
        old = np.frombuffer(before.get(start, b"\0" * len(data))[:len(data)].ljust(len(data), b"\0"), np.uint8)
        changed = np.flatnonzero(new != old)
        if changed.size == 0:
            continue
        breaks = np.flatnonzero(np.diff(changed) > MERGE_GAP)
        firsts = np.concatenate([[changed[0]], changed[breaks + 1]])
        lasts = np.concatenate([changed[breaks], [changed[-1]]])
        for first, last in zip(firsts, lasts):
            first = int(first) - int(first) % FUNCTION_ALIGNMENT
            chunks.append((start + first, bytes(data[first:int(last) + 1])))
    return chunks


_LINE = re.compile(r"^\s*([0-9a-f]+):\s+(?:[0-9a-f]{2} )+\s*([a-z][a-z0-9.]*)\b(.*)$")


def disassemble(chunks: list[tuple[int, bytes]]) -> list[tuple[int, str, str]]:
    """(address, mnemonic, operands) of every instruction objdump decodes in the chunks."""
    objdump = shutil.which("objdump")
    if objdump is None:
        raise RuntimeError("objdump is not installed (Debian package binutils)")
    out = []
    with tempfile.TemporaryDirectory() as folder:
        for address, data in chunks:
            path = Path(folder) / "chunk.bin"
            path.write_bytes(data)
            text = subprocess.run(
                [objdump, "-D", "-b", "binary", "-m", "i386:x86-64", "--no-show-raw-insn",
                 f"--adjust-vma={address:#x}", str(path)],
                check=True, capture_output=True, text=True).stdout
            for line in text.splitlines():
                match = re.match(r"^\s*([0-9a-f]+):\s+([a-z][a-z0-9.]*)\s*(.*)$", line)
                if match:
                    out.append((int(match.group(1), 16), match.group(2), match.group(3).strip()))
    return out


class StageScanner:
    """Attributes the JIT code written during each named stage to that stage; stages nest,
    and code written while an inner stage runs belongs to the inner one only."""

    def __init__(self):
        self.code: dict[str, list] = {}
        self._stack: list[str] = []
        self._last = None

    def _checkpoint(self) -> None:
        now = snapshot()
        if self._stack:
            self.code.setdefault(self._stack[-1], []).extend(changed_chunks(self._last, now))
        self._last = now

    @contextlib.contextmanager
    def stage(self, name: str):
        self._checkpoint()
        self._stack.append(name)
        try:
            yield
        finally:
            self._checkpoint()
            self._stack.pop()

    def wrap(self, owner, attribute: str, name: str):
        original = getattr(owner, attribute)

        def wrapped(*args, **kwargs):
            with self.stage(name):
                return original(*args, **kwargs)
        setattr(owner, attribute, wrapped)

    def report(self) -> dict:
        stages = {}
        for name, chunks in self.code.items():
            instructions = disassemble(chunks)
            counts = Counter(mnemonic for _, mnemonic, _ in instructions)
            hits = [(a, m, ops) for a, m, ops in instructions if m in APPROXIMATE_MNEMONICS]
            stages[name] = {
                "code_bytes": sum(len(data) for _, data in chunks),
                "instructions": len(instructions),
                "approximate": dict(Counter(m for _, m, _ in hits)),
                "approximate_at": [f"{a:#x} {m} {ops}" for a, m, ops in hits[:8]],
                "exact_roots_and_divides": {m: counts[m] for m in sorted(counts)
                                            if re.match(r"v?(sqrt|div)[ps][sd]$", m)},
            }
        return stages


def scan_golden_scene(name: str, language: str = "glsl") -> dict:
    """Render golden scene ``name`` once in ``language``, in this process, recording each
    stage's code."""
    from . import golden_scenes
    from ..gpu import gl, ibl
    from ..render import renderer as render

    gl.shared_context()
    scanner = StageScanner()
    scanner.wrap(ibl, "prefiltered_environment", "environment prefilter")
    scanner.wrap(render, "_draw_sphere", "scene draws (float target)")
    scanner.wrap(render, "_draw_mesh", "scene draws (float target)")
    scanner.wrap(render, "_resolve", "display resolve (float target, CPU encode)")
    with scanner.stage("texture upload and the rest of the render"):
        render.render_scene(golden_scenes.GOLDEN_SCENES[name](), language=language)
    return scanner.report()


def scan_controls() -> dict:
    """Positive controls: the two llvmpipe paths known to use RSQRTPS (module docstring)."""
    import numpy as np

    from ..gpu import gl, targets
    from . import golden_scenes
    from ..render import renderer as render

    ctx = gl.shared_context()
    scanner = StageScanner()
    with scanner.stage("control: glGenerateMipmap of an sRGB8_ALPHA8 texture"):
        texture = ctx.texture((64, 64), 4, np.arange(64 * 64 * 4, dtype=np.uint8).tobytes(),
                              internal_format=targets.GL_SRGB8_ALPHA8)
        texture.build_mipmaps()
        ctx.finish()
    with scanner.stage("control: display resolve into an sRGB framebuffer"):
        render.render_scene(golden_scenes.GOLDEN_SCENES["chart_metallic"](), ctx, transfer="HARDWARE")
    return scanner.report()


def run_in_fresh_process(job: str) -> dict:
    """Scan one job ('controls', a golden name, or NAME:hlsl) in a new interpreter: an
    empty JIT."""
    result = subprocess.run([sys.executable, "-m", "pbrlab.checking.codescan", "--one", job],
                            check=True, capture_output=True, text=True)
    return json.loads(result.stdout)


def main(argv=None) -> int:
    from .golden_scenes import GOLDEN_SCENES

    parser = argparse.ArgumentParser(
        prog="python -m pbrlab.checking.codescan",
        description="Disassemble llvmpipe's JIT code per render stage of each golden scene and "
                    "list the CPU-dependent (estimate) instructions.")
    parser.add_argument("names", nargs="*", help="golden scenes (default: all)")
    parser.add_argument("--json", action="store_true", help="print the report as JSON")
    parser.add_argument("--one", help=argparse.SUPPRESS)  # internal: scan in this process
    args = parser.parse_args(argv)
    if args.one:
        name, _, language = args.one.partition(":")
        report = scan_controls() if name == "controls" else scan_golden_scene(name, language or "glsl")
        print(json.dumps(report))
        return 0
    unknown = sorted(set(args.names) - set(GOLDEN_SCENES))
    if unknown:
        parser.error(f"no golden scene named {', '.join(unknown)}")
    names = args.names or list(GOLDEN_SCENES)
    jobs = ["controls", *names, *(f"{name}:hlsl" for name in names)]
    reports = {job: run_in_fresh_process(job) for job in jobs}
    if args.json:
        print(json.dumps(reports, indent=2))
        return 0
    for job, stages in reports.items():
        print(job)
        for stage, data in stages.items():
            approx = ", ".join(f"{m} x{n}" for m, n in sorted(data["approximate"].items())) or "none"
            print(f"  {stage:48s} {data['instructions']:7d} instructions; estimates: {approx}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
