"""Start-up cost of the `pbrlab` command and of the pytest plugin (issue 25): wall clock of
fresh processes, median of N, with a breakdown. A benchmark: it prints figures and asserts
nothing (tests/foundation/test_import_cost.py checks the import structure instead).

    .venv/bin/python benchmarks/startup.py [--runs 9] [--size 512] [--scene scenes/unity_example/scene.json]
        [--empty-cache] [--baseline ../main/harness]

1. ``pbrlab render SCENE -o OUT.png --size 512x512 -q``, N fresh processes after one warm-up
   (which writes the byte-code and the disk cache, as any earlier run would): median, min and
   max of the wall clock, and the processes' CPU time (user + system: steadier than the wall
   clock on a shared machine). ``--empty-cache`` gives every run a new, empty disk cache
   (pbrlab.foundation.disk_cache): what the first render of a scene costs.
2. One process under ``python -X importtime``: import time by top-level package.
3. One process with timers around the stages (parsing the command line, loading the scene,
   the GL context, include expansion, program builds, mesh preparation, the environment,
   the render, writing the PNG): monkeypatched wrappers, nothing in pbrlab changes.
4. The pytest plugin: ``import pbrlab.checking.pytest_plugin`` after ``import pytest`` (importtime,
   cumulative), median of N, and which heavy packages it loaded (none expected).
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HEAVY = ("numpy", "moderngl", "OpenImageIO", "trimesh", "scipy", "PIL", "pyrender", "networkx")

_STAGES = r'''
import sys, time, json
T, C = {}, {}
def timed(module, name, label):
    original = getattr(module, name)
    def wrapper(*args, **kwargs):
        start, cpu = time.perf_counter(), time.process_time()
        try:
            return original(*args, **kwargs)
        finally:
            T[label] = T.get(label, 0.0) + time.perf_counter() - start
            C[label] = C.get(label, 0.0) + time.process_time() - cpu
    setattr(module, name, wrapper)
t0 = time.perf_counter()
from pbrlab.commands import cli
T["import pbrlab.commands.cli"] = time.perf_counter() - t0
C["import pbrlab.commands.cli"] = time.process_time()
t1, c1 = time.perf_counter(), time.process_time()
from pbrlab.foundation import images
from pbrlab.gpu import gl, programs, shaders, source_cache
from pbrlab.render import renderer as render, resource_cache
from pbrlab.scene import meshes
from pbrlab.commands import render as render_command
T["import the render path (render, images, ...)"] = time.perf_counter() - t1
C["import the render path (render, images, ...)"] = time.process_time() - c1
t1 = time.perf_counter()
parser = cli.build_parser(sys.argv[1:])
T["build the parser"] = time.perf_counter() - t1
timed(render_command, "load_any_scene", "load the scene (imports the readers)")
timed(gl, "shared_context", "GL context")
timed(source_cache, "expand", "include expansion (disk cache or expander)")
timed(shaders, "build_program", "program compile + link")
timed(meshes, "_prepared_mesh", "meshes (disk cache or trimesh)")
timed(resource_cache.ContextCache, "environment", "environment (read, SH9, prefilter)")
timed(resource_cache, "_file_texture", "textures")
timed(render, "render_scene", "render_scene (all of it)")
timed(images, "write_png", "write the PNG")
t2 = time.perf_counter()
rc = cli.main(sys.argv[1:])
T["cli.main (all of it)"] = time.perf_counter() - t2
T["process so far"] = time.perf_counter() - t0
C["process so far"] = time.process_time()
heavy = sorted({m.split(".")[0] for m in sys.modules} & set(%r))
print(json.dumps({"stages": T, "cpu": C, "heavy": heavy, "rc": rc}))
''' % (HEAVY,)


def child_env(cache: str | None, harness: Path = ROOT / "harness") -> dict:
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)  # an installed package has its byte-code
    env["PYTHONPATH"] = os.pathsep.join([str(harness), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    if cache is not None:
        env["PBRLAB_CACHE_DIR"] = cache
    return env


def run_timed(command: list[str], env: dict) -> tuple[float, float]:
    """(wall, CPU) seconds of one process."""
    before = os.times()
    start = time.perf_counter()
    subprocess.run(command, env=env, check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = os.times()
    return wall, (after.children_user - before.children_user) + (after.children_system - before.children_system)


def summary(values: list[float]) -> str:
    return f"median {statistics.median(values):.3f} s (min {min(values):.3f}, max {max(values):.3f})"


def import_breakdown(command: list[str], env: dict) -> dict:
    """Self import time (s) by top-level package, from -X importtime."""
    result = subprocess.run([command[0], "-X", "importtime", *command[1:]], env=env, check=True,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    totals: dict = defaultdict(float)
    for line in result.stderr.splitlines():
        m = re.match(r"import time:\s+(\d+) \|\s+\d+ \|\s*([\w.]+)$", line)
        if m:
            totals[m.group(2).split(".")[0]] += int(m.group(1)) * 1e-6
    return dict(sorted(totals.items(), key=lambda item: -item[1]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=9)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--scene", default=str(ROOT / "scenes" / "unity_example" / "scene.json"))
    parser.add_argument("--empty-cache", action="store_true",
                        help="a new, empty disk cache for every run (the first render of a scene)")
    parser.add_argument("--baseline", type=Path, default=None, metavar="HARNESS",
                        help="another checkout's harness/ folder (e.g. main's) rendering the same scene "
                             "in runs interleaved with these: a ratio that holds on a busy machine")
    args = parser.parse_args()
    python = sys.executable
    with tempfile.TemporaryDirectory(prefix="pbrlab-startup-") as scratch:
        out = os.path.join(scratch, "x.png")
        render_args = ["render", args.scene, "-o", out, "--size", f"{args.size}x{args.size}", "-q"]
        command = [python, "-m", "pbrlab.commands.cli", *render_args]
        shared_cache = os.path.join(scratch, "cache")

        def env_for(run: int) -> dict:
            return child_env(os.path.join(scratch, f"cache-{run}") if args.empty_cache else shared_cache)

        subprocess.run(command, env=env_for(-1), check=True, stdout=subprocess.DEVNULL)  # warm-up
        baseline_env = child_env(shared_cache, args.baseline) if args.baseline else None
        if baseline_env:
            subprocess.run(command, env=baseline_env, check=True, stdout=subprocess.DEVNULL)
        walls, cpus, base_walls, base_cpus = [], [], [], []
        for run in range(args.runs):
            wall, cpu = run_timed(command, env_for(run))
            walls.append(wall)
            cpus.append(cpu)
            if baseline_env:
                wall, cpu = run_timed(command, baseline_env)
                base_walls.append(wall)
                base_cpus.append(cpu)
        cache = "an empty disk cache each run" if args.empty_cache else "the disk cache warm"
        print(f"pbrlab render {Path(args.scene).relative_to(ROOT) if Path(args.scene).is_relative_to(ROOT) else args.scene}"
              f" -o x.png --size {args.size}x{args.size}: {args.runs} fresh processes, {cache}")
        print(f"  wall {summary(walls)}")
        print(f"  CPU  {summary(cpus)}  (user + system, all threads)")
        if baseline_env:
            print(f"  baseline {args.baseline}, interleaved: wall {summary(base_walls)}; CPU {summary(base_cpus)}; "
                  f"ratio of medians: wall {statistics.median(walls) / statistics.median(base_walls):.2f}, "
                  f"CPU {statistics.median(cpus) / statistics.median(base_cpus):.2f}")
        print(f"  load average while measuring: {os.getloadavg()[0]:.1f} ({os.cpu_count()} CPUs)")
        print(f"  python -c pass: {summary([run_timed([python, '-c', 'pass'], env_for(0))[0] for _ in range(5)])}")

        print("import time by package (self time, s), one process:")
        for package, seconds in list(import_breakdown(command, env_for(0)).items())[:12]:
            print(f"  {package:24s} {seconds:.3f}")

        result = subprocess.run([python, "-c", _STAGES, *render_args], env=env_for(0), check=True,
                                stdout=subprocess.PIPE, text=True)
        import json
        report = json.loads(result.stdout.strip().splitlines()[-1])
        print("stages, one process (wall s, CPU s of all threads); the stages listed after")
        print("'load the scene' run inside 'render_scene':")
        for label, seconds in report["stages"].items():
            cpu = report["cpu"].get(label)
            print(f"  {label:40s} {seconds:6.3f}" + (f"  {cpu:6.3f}" if cpu is not None else ""))
        print(f"  heavy packages loaded: {', '.join(report['heavy']) or 'none'}")

        plugin = [python, "-c", "import pytest, time; t = time.perf_counter(); import pbrlab.checking.pytest_plugin; "
                                "print(time.perf_counter() - t)"]
        seconds = [float(subprocess.run(plugin, env=env_for(0), check=True, stdout=subprocess.PIPE,
                                        text=True).stdout) for _ in range(args.runs)]
        loaded = subprocess.run([python, "-c", "import sys, pytest; before = set(sys.modules); "
                                 "import pbrlab.checking.pytest_plugin; "
                                 f"print(sorted({{m.split('.')[0] for m in set(sys.modules) - before}} & set({HEAVY!r})))"],
                                env=env_for(0), check=True, stdout=subprocess.PIPE, text=True).stdout.strip()
        print(f"pytest plugin: import pbrlab.checking.pytest_plugin after pytest, {args.runs} processes: {summary(seconds)}; "
              f"heavy packages it loaded: {loaded}")


if __name__ == "__main__":
    main()
