"""A pass drawn as the corpus draws it: the corpus scene's sphere (its camera, lights and
environment) in one language, the linear rgba32f image; and the pixels the sphere covers whole."""

from __future__ import annotations

from pbrlab.checking import unity_corpus as corpus
from pbrlab.importers.loader import parse_scene
from pbrlab.render.renderer import render_scene


def render_on_corpus_sphere(tmp_path, shader, language, keywords=None):
    """``keywords``: the material's enabled keywords (None: the corpus scene's)."""
    scene = corpus.scene_for(shader)
    if keywords is not None:
        scene["materials"]["m"]["keywords"] = keywords
    return render_scene(parse_scene(scene, "t", tmp_path), language=language).linear


def covered_pixels(image):
    """The mask of pixels the sphere covers whole (alpha 1); the sphere fills a third at least."""
    covered = image[..., 3] == 1.0
    assert covered.mean() > 0.3
    return covered
