"""pbrlab against ground truth: the glTF Render Fidelity protocol (model-viewer's
render-fidelity-tools, Khronos' glTF-Render-Fidelity-Generator) with Blender's Cycles as the
path-traced reference and three.js and the Khronos Sample Viewer as peers.

    staging.py     the protocol's scenarios: orbit camera, field of view, environments
    display.py     the protocol's one display transform (linear -> 8-bit RGBA)
    metric.py      the protocol's score: YIQ delta over white, RMS / 35215, in dB
    renderers.py   one view, rendered linear by pbrlab, Cycles, three.js or the Sample Viewer
    benchmark.py   every scene by every renderer, scored against Cycles; the table

``pbrlab fidelity`` (commands/fidelity.py) runs it; docs/fidelity.md shows the table.
"""
