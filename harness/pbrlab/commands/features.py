"""`pbrlab features SCENE`: the effects a scene (JSON or glTF 2.0) calls for, per material
and per scene, and how many programs specialisation compiles for it, as JSON."""

from __future__ import annotations

import argparse

import json
from pathlib import Path


def run(args) -> int:
    from ..features import features_report, gltf_features
    from ..scene import load_scene

    path = Path(args.scene)
    if path.suffix.lower() in (".gltf", ".glb"):
        report = gltf_features(path)
    else:
        report = features_report(load_scene(path))
    print(json.dumps(report, indent=2, default=str))
    return 0


def register(sub, common):
    p = sub.add_parser("features", parents=[common], help="Print, as JSON, the effects a scene calls for and the programs it compiles.",
                       description=__doc__,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", help="a JSON scene or a glTF 2.0 file (.gltf, .glb)")
    p.set_defaults(run=run)
