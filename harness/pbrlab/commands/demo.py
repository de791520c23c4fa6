"""`pbrlab demo [--out DIR] [--language hlsl]`: render the default material charts and the lit
example scene (the Unity-style surface API), check them against the goldens, and say where
the images are. ``--language hlsl`` shades with the HLSL twins against the same goldens.

Per image it writes NAME.png (sRGB) and NAME.exr (linear radiance), the raw renders, and
NAME_sheet.png, a contact sheet with the chart's title, row and column values, term names
and golden verdict; OUT/index.html shows every sheet with its caption and golden status.

The goldens are the checkout's goldens/ folder (or --goldens DIR). An installed wheel ships
none: the demo then renders, says once that there is no golden to compare, and exits 0."""

from __future__ import annotations

import argparse

from pathlib import Path

from .render import add_language_option


def run(args) -> int:
    from ..foundation import console, images, outputs, progress
    from ..checking import contact_sheets, goldens
    from ..gpu import gl
    from ..foundation.errors import PbrlabError
    from ..checking.charts import CHARTS
    from ..checking.golden_scenes import GOLDEN_SCENES
    from ..foundation.locations import checkout_folder
    from ..render.renderer import render_scene
    from .render import check_finite

    out = Path(args.out)
    golden_root = Path(args.goldens) if args.goldens is not None else checkout_folder("goldens")
    refuse_golden_folder(out, golden_root)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise PbrlabError(f"--out {out}: exists and is not a directory") from None
    except OSError as exc:
        raise PbrlabError(f"--out {out}: cannot create the folder: {exc.strerror or exc}") from None
    ctx = gl.shared_context(args.backend)
    info = gl.context_info(ctx)
    console.note(f"pbrlab demo on {info['GL_RENDERER']} ({info['GL_VERSION']}, {info['backend']}), "
          f"shading in {args.language.upper()}")
    if golden_root is None:
        print(f"{NO_GOLDEN}: the goldens are in pbrlab's source checkout, not in the installed "
              "package (pass --goldens DIR to compare with a folder of them)")
    failures = 0
    entries = []
    names = [*CHARTS, "lit_scene_high"]
    for name in names:
        with progress.stage(f"rendering {name}"):  # a live line on a terminal past 2 s
            rendering = render_scene(GOLDEN_SCENES[name](), ctx, language=args.language)
        check_finite(rendering.linear, name)
        png, exr = out / f"{name}.png", out / f"{name}.exr"
        goldens_of_name = [] if golden_root is None else [(p, f"the golden {name}") for p in
                                                          goldens.golden_paths(golden_root, name).all()]
        with outputs.transaction([png, exr], goldens_of_name) as tx:  # the pair, or neither; never a golden
            images.write_png(png, rendering.srgb8, tx=tx)
            images.write_exr(exr, rendering.linear, metadata=rendering.info, tx=tx)
        if golden_root is None:
            status = NO_GOLDEN
            print(f"  {png}  {exr}")
        else:
            status, failed = _check(name, rendering, info, golden_root, out, args.tolerance_profile)
            failures += failed
        sheet = out / f"{name}_sheet.png"
        contact_sheets.write_sheet(sheet, name, rendering.srgb8, status)
        entries.append({"name": name, "status": status, "sheet": sheet.name, "png": png.name, "exr": exr.name})
    index = out / "index.html"
    contact_sheets.write_index(index, entries)
    print(f"{len(names)} images in {out}/" + (f"; {failures} differ from their goldens" if failures else "")
          + f"; labelled sheets and captions in {index}")
    return 1 if failures else 0


NO_GOLDEN = "rendered, no golden to compare"


def refuse_golden_folder(out: Path, golden_root: Path | None) -> None:
    """Refuse an ``--out`` that is the goldens' folder or inside it, before any work: the demo's
    images carry the goldens' names (chart_f0.png, ...), so they would replace the very files
    they are checked against (``pbrlab demo --out goldens`` in the checkout did)."""
    import os

    from ..foundation.errors import PbrlabError
    from ..foundation.safe_paths import is_within

    if golden_root is not None and is_within(os.path.realpath(out), os.path.realpath(golden_root)):
        raise PbrlabError(f"--out {out}: is the goldens' folder {golden_root} or inside it, and the demo's "
                          "images have the goldens' names; choose another folder (default: out)")


def _check(name, rendering, info, golden_root: Path, out: Path, profile: str) -> tuple[str, int]:
    """The golden verdict of one image, printed: (its status line, 1 if it differs else 0)."""
    from ..checking import goldens

    png, exr = out / f"{name}.png", out / f"{name}.exr"
    try:
        result = goldens.check_golden(name, rendering.linear, rendering.srgb8, info=info,
                                      update=False, root=golden_root,
                                      output_dir=out / "golden-diffs", profile=profile)
    except goldens.GoldenFailure as failure:
        print(f"  {png}  {exr}  DIFFERS from goldens/{name}")
        print("\n".join("      " + line for line in failure.figures.splitlines()))
        return f"DIFFERS from goldens/{name}: " + " ".join(failure.figures.split()), 1
    status = f"matches goldens/{name} (max abs {result.max_abs:.2g})"
    print(f"  {png}  {exr}  {status}")
    return status, 0


def register(sub, common):
    p = sub.add_parser("demo", parents=[common], help="Render the material charts and the lit example, and check them against the goldens.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", default="out", help="output folder (default: out)")
    p.add_argument("--goldens", default=None,
                   help="golden folder (default: the checkout's goldens/; an installed wheel has none)")
    p.add_argument("--tolerance-profile", default="auto", choices=("auto", "llvmpipe", "gpu"),
                   help="tolerances to check the goldens with: auto picks llvmpipe or gpu "
                        "from the GL renderer (default: auto)")
    add_language_option(p)
    p.set_defaults(run=run)
