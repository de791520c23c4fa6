"""Unity surface-shader program memory over many distinct shaders: the process's resident set
size (RSS, from /proc/self/status) while one GL context renders N distinct generated ``.shader``
files, one after another. Unity programs live in the context's scene-program cache
(programs.program_cache: programs.PROGRAMS_PER_CONTEXT, least recently used released), so RSS
must level off once it is full; before, unity/program.py kept every program in a dict (300
shaders took RSS from 165 MB to 1,245 MB). A measurement, not a test: it prints figures and
asserts nothing.

    .venv/bin/python benchmarks/unity_program_cache_rss.py [--shaders 1000] [--every 100]
        [--language glsl|hlsl]

Each shader is a Lambert surface with its own emission constant (distinct program text, so
never a cache hit), rendered on a 16 x 16 sphere.

Prints RSS after the first render (compiler and context warm) and every --every shaders, the
growth from the point where the cache first filled to the end, and the cache size.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

from pbrlab.gpu import gl, programs
from pbrlab.render import renderer as render
from pbrlab.scene import model as scene

SHADER = """Shader "Benchmark/Distinct{k}" {{
    Properties {{ _Color ("Color", Color) = (1, 1, 1, 1) }}
    SubShader {{
        CGPROGRAM
        #pragma surface surf Lambert
        fixed4 _Color;
        struct Input {{ float4 color : COLOR; }};
        void surf (Input IN, inout SurfaceOutput o) {{
            o.Albedo = _Color.rgb * 0.5;
            o.Emission = float3({k}.0 / 100000.0, 0.0, 0.0);
        }}
        ENDCG
    }}
}}
"""


def rss_mib() -> float:
    with open("/proc/self/status", encoding="ascii") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    raise RuntimeError("no VmRSS in /proc/self/status (Linux only)")


def _scene(folder: Path, name: str):
    data = {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40, "size": [16, 16]},
            "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 1.0}],
            "environment": None,
            "materials": {"m": {"surface": name}},
            "objects": [{"sphere": {"center": [0, 0, 0], "radius": 1}, "material": "m"}]}
    return scene.parse_scene(data, "<benchmark>", folder)


def _cached(ctx) -> int | None:
    cache = getattr(programs, "program_cache", None)
    return len(cache(ctx)) if cache is not None else None


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shaders", type=int, default=1000)
    parser.add_argument("--every", type=int, default=100)
    parser.add_argument("--language", choices=programs.LANGUAGES, default="glsl")
    args = parser.parse_args()
    ctx = gl.shared_context()
    limit = getattr(programs, "PROGRAMS_PER_CONTEXT", None)
    print(f"cache size (programs.PROGRAMS_PER_CONTEXT): {limit} programs per context "
          "(the Unity shaders' and the scene templates' together)")
    print(f"{'shaders':>8}  {'RSS MiB':>8}  {'programs cached':>15}  {'s':>7}")
    start = time.perf_counter()
    full_at = None
    with tempfile.TemporaryDirectory(prefix="pbrlab-unity-rss-") as tmp:
        folder = Path(tmp)
        for k in range(args.shaders):
            name = f"distinct_{k}.shader"
            (folder / name).write_text(SHADER.format(k=k), encoding="utf-8")
            render.render_scene(_scene(folder, name), ctx, language=args.language)
            cached = _cached(ctx)
            if full_at is None and limit is not None and cached is not None and cached >= limit:
                full_at = (k + 1, rss_mib())
            if k == 0 or (k + 1) % args.every == 0:
                print(f"{k + 1:>8}  {rss_mib():>8.1f}  {cached if cached is not None else '-':>15}  "
                      f"{time.perf_counter() - start:>7.1f}", flush=True)
    end = rss_mib()
    if full_at:
        print(f"RSS when the cache filled (after {full_at[0]} shaders): {full_at[1]:.1f} MiB; "
              f"at the end: {end:.1f} MiB; growth since: {end - full_at[1]:+.1f} MiB")


if __name__ == "__main__":
    main()
