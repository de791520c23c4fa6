"""Whole-program cost per glTF material class (issue 35): pbrlab's specialised scene program
(the production program and the checking program, as `pbrlab render` builds them) beside the
fragment programs three.js and the Khronos glTF Sample Viewer generate for the same glTF file,
all compiled by Mesa RADV/ACO for RDNA3 / RDNA2 / GCN5 on the null device (pbrlab.gpu.isa;
pbrlab.bench.gpu's ACO_NOTE says what the figures are).

The files: pbrlab.bench.peer_gltf (one generated sphere per class, the same textures, mesh
and lights in each). The peers' programs are captured from their real shader sources in
headless Chromium (tools/threejs_gltf/render.mjs and tools/sample_viewer/render.mjs with the
spec key ``capturePrograms``: tools/chromium/program_capture.mjs records every linked
program's sources and the draws made with it) and committed (benchmarks/peer_programs/), so
the bench runs without Chromium.

Which captured program is the model's (``select``): of the programs the page drew with,
three.js's is the one whose ``#define SHADER_NAME`` is the glTF material's name (three.js
names a material's program after the material; its PMREM passes are named
PMREMEquirectangularToCubemap, PMREMGGXConvolution, ...), and the Sample Viewer's is the one
whose fragment defines its material switch ``MATERIAL_*`` (its pbr.frag; the panorama,
prefilter and environment passes define none). Where more than one distinct program matches
(none did in the committed capture), the largest text is kept and the count recorded.

Rewrite for compiling (``vulkan_glsl``), two edits and nothing else: WebGL's ``#version 300 es``
becomes ``#version 450`` (glslang compiles ES only from 310 and, under ``-R``, loose uniforms
gathered into a block as for pbrlab's own programs, in an ES profile declares a built-in
``average`` that three.js's own ``average(vec3)`` then clashes with; desktop GLSL does not),
and the identifier ``sampler`` (a parameter name in three.js's transmission chunk,
``textureBicubic(sampler2D sampler, ...)``) becomes ``pbrlab_sampler``: ``sampler`` is a type
keyword of GLSL for Vulkan (GL_KHR_vulkan_glsl), not of WebGL's GLSL ES 3.00.
Precision is kept as written: both peers declare ``precision highp float`` (and highp
int/samplers) and no ``mediump``/``lowp`` occurs in any captured program (``precision_note``
checks it), so every float is 32-bit either way, as in desktop GLSL.
"""

from __future__ import annotations

import hashlib
import json
import re
import shutil
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from ..foundation.errors import PbrlabError
from ..gpu.isa import compile as gpu_isa
from ..gpu.isa import spirv
from . import gpu, peer_gltf

PEERS = ("threejs", "sample_viewer")
PEER_TITLES = {"threejs": "three.js", "sample_viewer": "Sample Viewer"}
COLUMNS = ("pbrlab production", "pbrlab checking", "three.js", "Sample Viewer")
TOOLS = {"threejs": "tools/threejs_gltf/render.mjs", "sample_viewer": "tools/sample_viewer/render.mjs"}
ENVIRONMENT = "sunrise"   # the fidelity benchmark's HDR environment (staging.ENVIRONMENTS_DIR)
CAPTURE_SIZE = (16, 16)   # the frame's size does not enter a program
CAMERA = {"eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "yfov_deg": 45, "znear": 0.1, "zfar": 10}
WEBGL_VERSION = "#version 300 es\n"
VULKAN_VERSION = "#version 450\n"

# What each peer's program defines when it honours the class (its own switches, read from its
# shader chunks: three.js's WebGLProgram defines, the Sample Viewer's pbr.frag MATERIAL_*).
# A program without its class's markers (None: no define could say it) is of a material the peer
# does not implement: it is reported, and not counted as the class's cheapest.
CLASS_MARKERS = {
    # three.js r187's GLTFLoader has no KHR_materials_pbrSpecularGlossiness (none in
    # examples/jsm/loaders/GLTFLoader.js): it draws the file's core metallic-roughness material
    "threejs": {"metallic-roughness": ("#define STANDARD",), "specular-glossiness": None,
                "clear-coat": ("#define USE_CLEARCOAT",), "sheen": ("#define USE_SHEEN",),
                "transmission": ("#define USE_TRANSMISSION",), "iridescence": ("#define USE_IRIDESCENCE",),
                "anisotropy": ("#define USE_ANISOTROPY",), "unlit": ("#define SHADER_TYPE MeshBasicMaterial",)},
    "sample_viewer": {"metallic-roughness": ("#define MATERIAL_METALLICROUGHNESS",),
                      "specular-glossiness": ("#define MATERIAL_SPECULARGLOSSINESS",),
                      "clear-coat": ("#define MATERIAL_CLEARCOAT",), "sheen": ("#define MATERIAL_SHEEN",),
                      "transmission": ("#define MATERIAL_TRANSMISSION", "#define MATERIAL_VOLUME"),
                      "iridescence": ("#define MATERIAL_IRIDESCENCE",),
                      "anisotropy": ("#define MATERIAL_ANISOTROPY",), "unlit": ("#define MATERIAL_UNLIT",)},
}


@dataclass(frozen=True)
class Case:
    """One comparison: a material class, its directional-light count, with or without the HDR
    environment."""
    material_class: str
    lights: int
    environment: bool = True

    @property
    def key(self) -> str:
        return f"{self.material_class}-{self.lights}light-{'env' if self.environment else 'noenv'}"

    @property
    def gltf_name(self) -> str:
        return peer_gltf.file_name(self.material_class, self.lights)


def cases(material_classes=tuple(peer_gltf.CLASSES), extras: bool = True) -> list:
    """Per class: one light with the environment (issue 35's done-when row), then with
    ``extras`` 0 and 4 lights with it and one light without it."""
    out = []
    for material_class in material_classes:
        out.append(Case(material_class, 1, True))
        if extras:
            out += [Case(material_class, 0, True), Case(material_class, 4, True), Case(material_class, 1, False)]
    return out


# ---- capture (Chromium) ------------------------------------------------------------------------

def select(peer: str, programs: list, material_name: str) -> tuple[str, int]:
    """(fragment text, how many distinct drawn programs matched) of the model's program among a
    page's captured ``programs`` (the module docstring gives the rule)."""
    def matches(fragment: str) -> bool:
        if peer == "threejs":
            return re.search(rf"^#define SHADER_NAME {re.escape(material_name)}$", fragment, re.M) is not None
        return re.search(r"^#define MATERIAL_[A-Z_]+ 1$", fragment, re.M) is not None

    found = sorted({p["fragment"] for p in programs if p["draws"] > 0 and p["fragment"] and matches(p["fragment"])},
                   key=len)
    if not found:
        raise PbrlabError(f"{PEER_TITLES[peer]}: none of the {len(programs)} captured programs drew the "
                          f"material {material_name!r}")
    return found[-1], len(found)


def _versions(root: Path) -> dict:
    def package(path):
        return json.loads((root / path).read_text())["version"]
    chromium = subprocess.run(["/usr/bin/chromium", "--version"], capture_output=True, text=True).stdout.strip()
    return {"three": package("tools/threejs_gltf/node_modules/three/package.json"),
            "gltf-viewer": package("tools/sample_viewer/node_modules/@khronosgroup/gltf-viewer/package.json"),
            "chromium": chromium, "webgl": "WebGL2 on ANGLE/SwiftShader (tools/chromium/launch.mjs)"}


def _capture_one(root: Path, peer: str, case: Case, gltf: Path, environment: dict | None, tmp: Path) -> dict:
    spec = {"gltf": str(gltf), "size": list(CAPTURE_SIZE), "camera": CAMERA, "capturePrograms": True}
    if peer == "threejs":
        spec.update(environment=environment["environment"] if environment else None, msaa=0)
    else:
        spec.update(environment=environment["environment_hdr"] if environment else None)
    out = tmp / f"{peer}-{case.key}"
    spec_path = out.with_suffix(".spec.json")
    spec_path.write_text(json.dumps(spec))
    node = shutil.which("node")
    if node is None:
        raise PbrlabError("node is not installed (in a pbrlab checkout, `bash scripts/setup.sh` installs it)")
    result = subprocess.run([node, str(root / TOOLS[peer]), str(spec_path), str(out)], capture_output=True, text=True)
    if result.returncode != 0:
        raise PbrlabError(f"{TOOLS[peer]} {case.key}: {(result.stderr.strip().splitlines() or ['failed'])[-1]}")
    return json.loads(Path(f"{out}.programs.json").read_text())


def capture(root: Path, folder: Path, selected_cases, jobs: int = 2, log=print) -> dict:
    """Renders every case's file with both peers (headless Chromium), writes the model's
    fragment program of each to ``folder/<peer>/<case>.frag`` and ``folder/manifest.json``
    (versions, each file's sha256, how many programs each page linked and matched)."""
    from ..checking.fidelity import staging

    folder = Path(folder)
    manifest_path = folder / "manifest.json"
    manifest = json.loads(manifest_path.read_text()) if manifest_path.exists() else {"cases": {}}
    with tempfile.TemporaryDirectory(prefix="pbrlab-peer-programs-") as tmp:
        tmp = Path(tmp)
        environment = staging.prepare_environment(ENVIRONMENT, tmp)
        files = {}
        for case in selected_cases:
            if case.gltf_name not in files:
                files[case.gltf_name] = peer_gltf.write(tmp, case.material_class, case.lights)
        work = [(peer, case) for case in selected_cases for peer in PEERS]

        def run(item):
            peer, case = item
            path, _ = files[case.gltf_name]
            programs = _capture_one(root, peer, case, path, environment if case.environment else None, tmp)
            fragment, matched = select(peer, programs, case.material_class)
            log(f"captured {PEER_TITLES[peer]:13s} {case.key}: {len(programs)} programs linked, {matched} matched")
            return peer, case, fragment, len(programs), matched

        with ThreadPoolExecutor(max_workers=jobs) as pool:
            results = list(pool.map(run, work))
    for peer, case, fragment, linked, matched in results:
        (folder / peer).mkdir(parents=True, exist_ok=True)
        (folder / peer / f"{case.key}.frag").write_text(fragment)
        entry = manifest["cases"].setdefault(case.key, {})
        entry.update(gltf=case.gltf_name, gltf_sha256=files[case.gltf_name][1])
        entry[peer] = {"file": f"{peer}/{case.key}.frag", "programs_linked": linked, "programs_matched": matched}
    manifest["versions"] = _versions(root)
    manifest["environment"] = ENVIRONMENT
    manifest_path.write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n")
    return manifest


# ---- compiling ---------------------------------------------------------------------------------

def vulkan_glsl(webgl_fragment: str, where: str) -> str:
    """The captured WebGL2 fragment as glslang compiles it (module docstring: the version line
    and the identifier ``sampler``)."""
    if not webgl_fragment.startswith(WEBGL_VERSION):
        raise PbrlabError(f"{where}: not a WebGL2 program (its first line is not '{WEBGL_VERSION.strip()}')")
    if re.search(r"\b(mediump|lowp)\b", webgl_fragment):
        raise PbrlabError(f"{where}: declares mediump/lowp, which #version 450 would compile at 32 bits: "
                          "the rewrite no longer keeps precision as written")
    return VULKAN_VERSION + re.sub(r"\bsampler\b", "pbrlab_sampler", webgl_fragment[len(WEBGL_VERSION):])


def honours(peer: str, material_class: str, fragment: str) -> bool:
    """Whether ``peer``'s captured ``fragment`` carries the class's markers (CLASS_MARKERS)."""
    markers = CLASS_MARKERS[peer][material_class]
    return markers is not None and all(re.search(rf"^{re.escape(m)}\b", fragment, re.M) for m in markers)


def gltf_sha256(case: Case) -> str:
    return hashlib.sha256(peer_gltf.gltf_bytes(case.material_class, case.lights)).hexdigest()


def peer_fragment(folder: Path, peer: str, case: Case, manifest: dict) -> str:
    """The committed capture of ``peer`` for ``case``, checked against the file it was captured
    from (a missing capture, or one of a file the generator no longer writes, is an error naming
    the file and `--capture`)."""
    path = Path(folder) / peer / f"{case.key}.frag"
    if not path.is_file():
        raise PbrlabError(f"{path}: no captured {PEER_TITLES[peer]} program for {case.key} "
                          "(run benchmarks/whole_program_cost.py --capture)")
    recorded = manifest.get("cases", {}).get(case.key, {}).get("gltf_sha256")
    if recorded != gltf_sha256(case):
        raise PbrlabError(f"{path}: captured from another {case.gltf_name} than pbrlab.bench.peer_gltf writes now "
                          "(run benchmarks/whole_program_cost.py --capture)")
    return path.read_text()


def pbrlab_jobs(case: Case, folder: Path, checking: bool) -> list:
    """The jobs of pbrlab's specialised programs for ``case``'s file (``pbrlab render``'s, via
    bench.gpu.scene_programs)."""
    from ..checking.fidelity import staging
    from ..importers.gltf import load_gltf
    from ..scene.model import Environment

    path, _ = peer_gltf.write(folder, case.material_class, case.lights)
    environment = Environment(path=staging.ENVIRONMENTS_DIR / f"{ENVIRONMENT}.exr") if case.environment else None
    scene = load_gltf(path, environment=environment, size=(64, 64), emit_warnings=False).scene
    return [program.job("glsl") for program in gpu.scene_programs(scene, "specialised", checking=checking)]


def _compile_named(jobs: dict, sources: dict, families) -> dict:
    """gpu._compile, with a program that does not compile reported by its file (``sources``:
    key -> where it came from)."""
    try:
        return gpu._compile(jobs, families)
    except PbrlabError:
        for key, job in jobs.items():  # which one: each alone through glslang
            try:
                spirv.compile_glsl(job.fragment, "fragment")
            except PbrlabError as exc:
                raise PbrlabError(f"{sources[key]}: does not compile: {exc}") from None
        raise


def measure(folder: Path, selected_cases, families=gpu.GPU_FAMILIES) -> dict:
    """``{case key: {column: {"families": {family: {"instructions", "vgprs", "waves"}},
    "honoured": bool, "source": str}}}`` for COLUMNS. A program's figures are of its
    largest program where a column has several (pbrlab: one object, one program)."""
    folder = Path(folder)
    manifest = json.loads((folder / "manifest.json").read_text()) if (folder / "manifest.json").is_file() else {}
    jobs, sources, layout = {}, {}, {}
    with tempfile.TemporaryDirectory(prefix="pbrlab-peer-gltf-") as tmp:
        for case in selected_cases:
            layout[case.key] = {}
            for column, checking in (("pbrlab production", False), ("pbrlab checking", True)):
                keys = []
                for index, job in enumerate(pbrlab_jobs(case, Path(tmp), checking)):
                    key = f"{case.key}|{column}|{index}"
                    jobs[key], sources[key] = job, f"pbrlab {column[7:]} program of {case.gltf_name}"
                    keys.append(key)
                layout[case.key][column] = (keys, True, f"pbrlab.bench.peer_gltf {case.gltf_name}")
            for peer in PEERS:
                column = PEER_TITLES[peer]
                fragment = peer_fragment(folder, peer, case, manifest)
                where = str(folder / peer / f"{case.key}.frag")
                key = f"{case.key}|{column}"
                jobs[key], sources[key] = gpu_isa.Job(key, vulkan_glsl(fragment, where)), where
                honoured = honours(peer, case.material_class, fragment)
                layout[case.key][column] = ([key], honoured, where)
    compiled = _compile_named(jobs, sources, families)
    out = {}
    for case_key, columns in layout.items():
        out[case_key] = {}
        for column, (keys, honoured, source) in columns.items():
            per_family = {}
            for family in families:
                best = max((compiled[family][k] for k in keys), key=lambda s: s["Instructions"])
                per_family[family] = {"instructions": best["Instructions"], "vgprs": best["VGPRs"],
                                      "waves": best["Subgroups per SIMD"]}
            out[case_key][column] = {"families": per_family, "honoured": honoured, "source": source}
    return out


def cheapest(row: dict, family: str = "rdna3") -> str:
    """The column with the fewest instructions on ``family`` among pbrlab's production program
    and the peers that honour the class (pbrlab's checking program is a test build)."""
    candidates = [c for c in COLUMNS if c != "pbrlab checking" and row[c]["honoured"]]
    return min(candidates, key=lambda c: (row[c]["families"][family]["instructions"], c != "pbrlab production"))


def markdown_table(case_key: str, row: dict, families=gpu.GPU_FAMILIES) -> str:
    """One case as a Markdown table: a row per column of COLUMNS, instructions / VGPRs / waves
    per family, the cheapest (RDNA3 instructions) in bold."""
    best = cheapest(row)
    header = "| program | " + " | ".join(f"{gpu.TITLES[f]} instr / VGPRs / waves" for f in families) + " |"
    lines = [f"**{case_key}**", "", header, "|---|" + "---|" * len(families)]
    for column in COLUMNS:
        entry = row[column]
        cells = [f"{entry['families'][f]['instructions']} / {entry['families'][f]['vgprs']} / "
                 f"{entry['families'][f]['waves']}" for f in families]
        name = column if entry["honoured"] else f"{column} (does not implement the class)"
        if column == best:
            cells[0] = f"**{cells[0]}**"
            name = f"**{name}**"
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines)
