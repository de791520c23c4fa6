"""Run a corpus of real Unity shaders (files nobody on this project wrote) through the
harness as a new user would: each ``.shader`` as a scene material, rendered in HLSL (as
written) and GLSL (its port), and report what happened to each.

    python -m pbrlab.checking.unity_corpus corpus/unity --out report.json     # every shader, both languages
    outcome = run_shader(path, "hlsl")                               # one of them

An outcome is ``rendered`` (every pixel finite), ``non-finite`` (rendered, but a pixel is NaN
or Inf: a defect), ``refused`` (a ``PbrlabError`` naming what is missing: the documented
answer to a Unity feature the harness cannot run) or ``traceback`` (any other exception: a
defect). The report adds GLSL/HLSL agreement for shaders rendered in both, and counts apart
those rendered in both that draw black (``draws_black``): each must be black by its own
defaults, as Unity would draw it, and listed with the reason (corpus/urp/black_by_defaults.md,
the pinned corpora's BLANK_BY_DEFAULT), or it is a defect.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
import tempfile
import traceback
import warnings
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from ..foundation.errors import PbrlabError
from ..foundation.locations import locate

LANGUAGES = ("glsl", "hlsl")
SIZE = (64, 64)
# A render no display tells from black: every RGB value rounds to sRGB code 0, i.e. lies below
# half of code 1 in linear (1/255 / 12.92 = 3.04e-4 on the sRGB curve's linear segment, IEC
# 61966-2-1; the corpus scene's tone map is the identity that low).
BLACK_LEVEL = 0.5 / 255 / 12.92


@dataclass
class Outcome:
    path: str
    language: str
    status: str                 # rendered, non-finite, refused, traceback
    message: str = ""
    warnings: list = field(default_factory=list)
    image: object = None        # HxWx4 float32 linear radiance when rendered

    def summary(self) -> dict:
        d = asdict(self)
        d.pop("image")
        return d


def corpus_shaders(root: Path) -> list[Path]:
    """Every ``.shader`` file below ``root``, sorted."""
    return sorted(p for p in Path(root).rglob("*.shader") if p.is_file())


# The corpus scene's supplied lightmap (importers/unity/lightmaps.py; scenes/assets/make_assets.py),
# for a shader whose drawn vertex/fragment program reads one: the sphere's lightmap UVs (its one UV
# set) scaled by a half and offset by a quarter, into the middle of the image.
LIGHTMAP = {"path": str(locate("scenes") / "assets" / "lightmap_rgbm.png"), "encoding": "rgbm",
            "scale_offset": [0.5, 0.5, 0.25, 0.25]}


# Its supplied realtime GI lightmap (importers/unity/dynamic_lightmaps.py; scenes/assets/make_assets.py),
# for a shader whose drawn vertex/fragment program reads one: the sphere's realtime lightmap UVs
# (TEXCOORD2: its one UV set) scaled by 0.6 and offset by 0.3 and 0.1, into another part of the image.
DYNAMIC_LIGHTMAP = {"path": str(locate("scenes") / "assets" / "realtime_lightmap.exr"),
                    "scale_offset": [0.6, 0.6, 0.3, 0.1]}


def scene_for(shader: Path) -> dict:
    """A small scene that shows a shader: a UV sphere (mesh: UVs, tangents, vertices a
    vertex function can move) under a directional and a point light and the sky; a lightmapped
    sphere (LIGHTMAP) where the shader's drawn vertex/fragment program reads Unity's lightmap,
    which it cannot run without, and a realtime GI lightmap (DYNAMIC_LIGHTMAP) where it reads
    Unity's realtime lightmap (every other shader sees the sphere as it always has). A
    full-screen shader (importers/unity/fullscreen_pass.py: drawn over the whole view, reading
    the camera's colour) is shown over the same sphere in a pbrlab material (BACKDROP), the scene
    its pass reads."""
    material = {"surface": str(shader)}
    read = _read(shader)
    if _reads_lightmap(read):
        material["lightmap"] = dict(LIGHTMAP)
    if _reads_lightmap(read, realtime=True):
        material["dynamic_lightmap"] = dict(DYNAMIC_LIGHTMAP)
    backdrop = _draws_fullscreen(read)
    return {
        "camera": {"position": [0.0, 0.0, 3.2], "target": [0.0, 0.0, 0.0], "fov_y_deg": 40,
                   "size": list(SIZE)},
        "lights": [
            {"type": "directional", "direction": [-0.4, -0.6, -0.7], "color": [1, 1, 1], "intensity": 1.0},
            {"type": "point", "position": [1.5, 1.0, 2.0], "color": [1, 1, 1], "intensity": 2.0, "range": 10},
        ],
        "environment": {"path": str(locate("scenes") / "assets" / "sky.exr"), "intensity": 0.5},
        "materials": {"m": material, **({"backdrop": dict(BACKDROP)} if backdrop else {})},
        "objects": [{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "m"}]
                   + ([{"mesh": {"primitive": "uv_sphere", "radius": 1.0}, "material": "backdrop"}] if backdrop else []),
        "render": {"quality": "high", "tonemap": "khronos_neutral"},
    }


# The sphere a full-screen shader's pass is shown over: a lit pbrlab material.
BACKDROP = {"albedo": [0.8, 0.5, 0.3], "smoothness": 0.5}


def _read(shader: Path):
    """(``shader`` as the reader reads it in its pipeline, whether that is URP), or None for
    a file that is no ``.shader`` or one the reader refuses (its render says why). Read once
    for the questions scene_for asks: a read parses every pass, seconds for hundreds of them."""
    from ..importers.unity import BUILTIN, URP, read_shader
    from ..importers.urp import material as urp
    if Path(shader).suffix != ".shader":
        return None
    srp = urp.reads(Path(shader))
    try:
        return read_shader(Path(shader), URP if srp else BUILTIN), srp
    except PbrlabError:
        return None


def _draws_fullscreen(read) -> bool:
    """Whether a shader (``_read``'s answer) draws a full-screen pass."""
    from ..importers.unity.fullscreen_pass import is_fullscreen
    return read is not None and any(is_fullscreen(p) for p in read[0].passes)


def _reads_lightmap(read, realtime: bool = False) -> bool:
    """Whether a shader (``_read``'s answer: a Unity .shader read without a lightmap) draws a
    vertex/fragment program that reads the object's lightmap (with ``realtime``, its realtime
    GI lightmap); False for anything else, and for a shader the reader refuses (its render says
    why). A URP shader's lightmap is read the same way (lightmaps.first_read with urp); it has
    no realtime one here."""
    from ..importers.unity.dynamic_lightmaps import needs_dynamic_lightmap
    from ..importers.unity.lightmaps import needs_lightmap
    if read is None or (read[1] and realtime):
        return False
    if realtime:
        return needs_dynamic_lightmap(read[0])
    return needs_lightmap(read[0], urp=read[1])


def _messages(caught) -> list:
    """The warnings' texts, each cut to 300 characters after its place (``path:line: ``, whose
    length varies with the folders), so that what it says survives (no_colour_reason reads it)."""
    out = []
    for w in caught:
        text = str(w.message)
        place = re.match(r"^.*?\.\w+(?::\d+)*: ", text)
        out.append(text[:(place.end() if place else 0) + 300])
    return out


def run_shader(shader: Path, language: str) -> Outcome:
    from ..render.renderer import render_scene
    from ..importers.loader import parse_scene

    shader = Path(shader).resolve()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            scene = parse_scene(scene_for(shader), origin="corpus scene", base=shader.parent)
            image = render_scene(scene, language=language).linear
        except PbrlabError as exc:
            return Outcome(str(shader), language, "refused", str(exc)[:3000],
                           _messages(caught))
        except Exception as exc:  # a defect: the report names it
            tb = traceback.format_exception(type(exc), exc, exc.__traceback__)
            return Outcome(str(shader), language, "traceback", "".join(tb[-3:])[-600:],
                           _messages(caught))
    finite = np.isfinite(image).all(axis=-1)
    if finite.all():
        return Outcome(str(shader), language, "rendered", "", _messages(caught), image)
    # which pixels, so a report says where the shader's own arithmetic (or pbrlab's) broke down
    rows, cols = np.nonzero(~finite)
    where = (f"{int((~finite).sum())} of {finite.size} pixels are NaN or infinite (rows "
             f"{rows.min()}..{rows.max()}, columns {cols.min()}..{cols.max()})")
    return Outcome(str(shader), language, "non-finite", where, _messages(caught), image)


# What a compiler says (glslang, Mesa's GLSL compiler): a shader the front end let through and
# the compiler refused is a defect of the front end, not a refusal naming a Unity feature.
_COMPILER = ("failed to compile", "HLSL failed", "error: ", "cannot find include")


def is_compiler_error(message: str) -> bool:
    """Whether a refusal's first line is a compiler's (a named refusal puts its reason first)."""
    first = message.splitlines()[0] if message else ""
    return any(word in first for word in _COMPILER)


def without_folders(text: str) -> str:
    """``text`` with every path cut to its file name (a key that holds on any checkout)."""
    return re.sub(r"(?:/[^\s/:()\"']+)+/", "", text)


def refusal_key(message: str) -> str:
    """The part of a refusal that names the missing feature (without the file's path and line)."""
    first = message.splitlines()[0] if message else ""
    first = re.sub(r"^.*?\.(?:shader|cginc|glsl|json)(?::\d+)*: (?:materials\.\w+\.surface: )?(?:.*?\.shader:\d+: )?", "",
                   first)
    return without_folders(first)[:90]


def no_colour_reason(outcomes: dict) -> str | None:
    """Why a shader rendered in every language draws no colour by its own ColorMask (a
    program-less ``ColorMask 0`` pass: a depth/stencil mask, drawn as written), by a fragment
    function that writes no SV_Target (a depth-only pass), or, drawn alone, by
    its Stencil test (it draws over another object's mask), read from its note; None for any other
    shader. The report lists these, not as silently empty images."""
    from ..importers.unity.parse import NO_COLOUR_BY_COLOR_MASK, NO_COLOUR_BY_FRAGMENT, NO_COLOUR_BY_STENCIL
    reasons = (NO_COLOUR_BY_COLOR_MASK, NO_COLOUR_BY_FRAGMENT, NO_COLOUR_BY_STENCIL)
    notes = [next((w for w in o.warnings if any(r in w for r in reasons)), None)
             for o in outcomes.values()]
    if not outcomes or any(o.status != "rendered" for o in outcomes.values()) or None in notes:
        return None
    return without_folders(notes[0]).split(": ", 1)[-1]   # the note, which says it, without its place


def agreement(a: np.ndarray, b: np.ndarray) -> float:
    """Largest relative difference of the GLSL and HLSL renders (1e-3 floor)."""
    return float(np.max(np.abs(a - b) / np.maximum(np.maximum(np.abs(a), np.abs(b)), 1e-3)))


def draws_black(image) -> bool:
    """Whether a rendered image shows no colour: every RGB value within BLACK_LEVEL of 0 (alpha
    alone is no picture; a NaN is not black: the non-finite outcome reports it)."""
    return bool(np.all(np.abs(np.asarray(image, np.float64)[..., :3]) <= BLACK_LEVEL))


def run_corpus(root: Path, progress=None) -> dict:
    rows = []
    for shader in corpus_shaders(root):
        outcomes = {lang: run_shader(shader, lang) for lang in LANGUAGES}
        row = {"path": str(shader.relative_to(root)),
               **{lang: outcomes[lang].summary() for lang in LANGUAGES}}
        for o in row["glsl"], row["hlsl"]:
            o.pop("path")
            o.pop("language")
        if all(o.status == "rendered" for o in outcomes.values()):
            row["glsl_hlsl_max_rel"] = agreement(outcomes["glsl"].image, outcomes["hlsl"].image)
            row["black"] = all(draws_black(o.image) for o in outcomes.values())
        if no_colour_reason(outcomes):
            row["no_colour"] = no_colour_reason(outcomes)
        rows.append(row)
        if progress:
            progress(row)
    counts = {lang: {} for lang in LANGUAGES}
    for row in rows:
        for lang in LANGUAGES:
            s = row[lang]["status"]
            counts[lang][s] = counts[lang].get(s, 0) + 1
    both = sum(all(row[lang]["status"] == "rendered" for lang in LANGUAGES) for row in rows)
    black = [row["path"] for row in rows if row.get("black") and "no_colour" not in row]
    no_colour = [row["path"] for row in rows if "no_colour" in row]
    return {"shaders": len(rows), "rendered_in_both": both, "black_in_both": len(black), "black": black,
            "draws_no_colour_by_its_color_mask": no_colour, "counts": counts, "rows": rows}


def outcome_problems(expected: str, outcomes: dict, blank_reason: str | None = None,
                     agreement_bound: float = 1e-4) -> list[str]:
    """What is wrong with one shader's ``outcomes`` (language -> Outcome) against its pinned
    ``expected`` outcome (expected_outcomes' vocabulary); empty when they match. A rendered
    pair must agree to ``agreement_bound`` (the GLSL port against the HLSL as written) and
    draw colour (an RGB value other than 0: alpha alone is no picture), unless ``blank_reason``
    says why its defaults draw none, or the shader writes no colour by its ColorMask
    (no_colour_reason): then it must be black. A refusal must name what is missing, not be a
    compiler's error, unless pinned as a defect; a traceback is always wrong."""
    problems = []
    blank_reason = blank_reason or no_colour_reason(outcomes)  # a mask: black, listed by its reason
    for lang, o in outcomes.items():
        if o.status not in ("rendered", "refused"):
            problems.append(f"{lang}: {o.status}: {o.message[:300]}")
        elif o.status == "refused" and not expected.startswith("defect: ") and is_compiler_error(o.message):
            problems.append(f"{lang}: a compiler error, not a refusal: {o.message[:300]}")
    if problems:
        return problems
    if expected.startswith("defect: "):  # a known front-end defect, pinned until it is mended
        if not any(o.status == "refused" for o in outcomes.values()):
            return ["renders now: pin it as rendered"]
        if not any(expected[len("defect: "):] in without_folders(o.message) for o in outcomes.values()):
            return [f"the pinned defect changed: {[o.message[:300] for o in outcomes.values()]}"]
        return []
    if expected == "rendered":
        if not all(o.status == "rendered" for o in outcomes.values()):
            return [f"{lang}: {o.message[:300]}" for lang, o in outcomes.items() if o.status != "rendered"]
        images = [o.image for o in outcomes.values()]
        if agreement(images[0], images[-1]) > agreement_bound:
            problems.append(f"GLSL and HLSL differ by {agreement(images[0], images[-1]):.3g} > {agreement_bound}")
        drew = [bool((image[..., :3] != 0).any()) for image in images]  # colour, not alpha
        if drew != [blank_reason is None] * len(drew):
            problems.append(blank_reason or "drew nothing")
        return problems
    if not all(o.status == "refused" for o in outcomes.values()):
        return [f"{lang}: {o.status}" for lang, o in outcomes.items() if o.status != "refused"]
    if expected not in {refusal_key(o.message) for o in outcomes.values()}:
        return [f"refused for another reason: {[o.message[:300] for o in outcomes.values()]}"]
    return []


def expected_outcomes(report: dict) -> dict:
    """{shader: "rendered", what its refusal names, or "defect: " and a compiler's error}."""
    expected = {}
    for row in report["rows"]:
        statuses = {row[lang]["status"] for lang in LANGUAGES}
        if statuses == {"rendered"}:
            expected[row["path"]] = "rendered"
            continue
        refusing = [row[lang] for lang in LANGUAGES if row[lang]["status"] != "rendered"]
        bad = next((o for o in refusing if o["status"] == "refused" and is_compiler_error(o["message"])),
                   refusing[0])
        key = refusal_key(bad["message"]) if bad["status"] == "refused" else bad["status"]
        if bad["status"] == "refused" and is_compiler_error(bad["message"]):
            errors = [e for e in bad["message"].splitlines() if "error" in e.lower()]
            key = "defect: " + without_folders(re.sub(r"^.*?error:?\s*", "", errors[0] if errors else key))[:80]
        elif "rendered" in statuses:  # one language renders, the other refuses: a defect too
            key = "defect: " + key
        expected[row["path"]] = key
    return expected


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m pbrlab.checking.unity_corpus", description=__doc__.split("\n\n")[0])
    parser.add_argument("root", type=Path, help="a folder of .shader files (searched recursively)")
    parser.add_argument("--out", type=Path, help="write the report as JSON here")
    parser.add_argument("--expect", type=Path, help="write the outcomes as tests/importers/unity/test_corpus.py "
                        "expects them: {shader: \"rendered\" or what its refusal names}")
    args = parser.parse_args(argv)

    def progress(row):
        marks = " ".join(f"{lang}:{row[lang]['status']}" for lang in LANGUAGES) + (" BLACK" if row.get("black") else "")
        first = next((row[lang]["message"] for lang in LANGUAGES if row[lang]["message"]), "")
        print(f"{row['path']}: {marks} {first[:160]}", flush=True)

    report = run_corpus(args.root, progress)
    from ..importers.unity.parse import NO_COLOUR_BY_COLOR_MASK as NO_COLOUR
    print(f"rendered in both languages: {report['rendered_in_both']} of {report['shaders']} "
          f"({report['black_in_both']} of them black besides the ColorMask 0 masks: each black by its own "
          f"defaults, listed with the reason, or a defect); {json.dumps(report['counts'])}")
    for path in report["black"]:
        print(f"  black: {path}")
    for path in report["draws_no_colour_by_its_color_mask"]:
        print(f"rendered, {NO_COLOUR}: {path}")
    from ..foundation import outputs
    if args.out:
        with outputs.transaction([args.out]) as tx:
            tx.write_text(args.out, json.dumps(report, indent=1) + "\n")
    if args.expect:
        expected = expected_outcomes(report)
        with outputs.transaction([args.expect]) as tx:
            tx.write_text(args.expect, json.dumps(expected, indent=1, sort_keys=True) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
