"""`pbrlab features SCENE`: the effects a scene (JSON or glTF 2.0) calls for, per material
and per scene, and how many programs specialisation compiles for it, as JSON. For a glTF
file, "warnings" lists every extension or feature not honoured (as `pbrlab render` warns)."""

from __future__ import annotations

import argparse

import json
from pathlib import Path


def run(args) -> int:
    from ..render.features import features_report
    from ..importers.gltf import is_gltf, load_gltf
    from ..importers.gltf.settings import read_settings
    from .render import load_scene_with_gltf_warnings

    if is_gltf(args.scene):
        environment, render = read_settings(Path(args.scene))
        result = load_gltf(args.scene, environment=environment, render=render, emit_warnings=False)
        report = features_report(result.scene)
        report["warnings"] = result.warnings
    else:
        scene, messages = load_scene_with_gltf_warnings(args.scene)
        report = features_report(scene)
        if messages:  # from glTF files the scene takes in
            report["warnings"] = messages
    print(json.dumps(report, indent=2, default=str))
    return 0


def register(sub, common):
    p = sub.add_parser("features", parents=[common], help="Print, as JSON, the effects a scene calls for and the programs it compiles.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", help="a JSON scene or a glTF 2.0 file (.gltf, .glb)")
    p.set_defaults(run=run)
