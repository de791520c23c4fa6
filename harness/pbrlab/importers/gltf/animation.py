"""glTF animations (spec 3.11 "Animations", Appendix C "Animation Sampler Interpolation
Modes") sampled at one time: every channel of the chosen animations evaluated at time T
and written over its node's translation, rotation, scale or morph weights. gltf.nodes
builds the node matrices from this pose, gltf.morph the weights.

With t_k <= T < t_(k+1), td = t_(k+1) - t_k and s = (T - t_k) / td (Appendix C):

    STEP         v_k
    LINEAR       (1 - s) v_k + s v_(k+1); a rotation by slerp:
                 a = arccos(|d|), d = v_k . v_(k+1), sign = d / |d|,
                 sin(a (1 - s)) / sin(a) v_k + sign sin(a s) / sin(a) v_(k+1)
                 (the shorter arc; as a -> 0 it tends to the linear form, used below SLERP_LINEAR_BELOW)
    CUBICSPLINE  (2s^3 - 3s^2 + 1) v_k + td (s^3 - 2s^2 + s) b_k
                 + (-2s^3 + 3s^2) v_(k+1) + td (s^3 - s^2) a_(k+1)
                 with a the in-tangent and b the out-tangent of each keyframe (its output
                 holds a_k, v_k, b_k in that order); a rotation is normalised after.

Outside the keyframes' time range a channel holds its first or last keyframe's value
(clamped; T = t_last gives v_last exactly).

Which animations: the first by default, with a warning naming the others when the file has
several; ``--animation N|NAME`` samples one, ``--animation all`` every one at once (a clip
named "all" is chosen by its name first). glTF stores animations as alternatives: the spec
(3.11, Note) "defines only animation storage ... no particular runtime behavior, such as:
order of playing, auto-start", and its Implementation Note recommends that "each animation
is self contained as an action" ("Walk" and "Run"); <model-viewer>, without animation-name,
"always picks the first animation it finds in the model". Sampling every clip together
mixes alternatives into one pose (Fox's Survey, Walk and Run; issue 39).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...foundation.errors import PbrlabError
from .accessors import read_accessor
from .document import Document

INTERPOLATIONS = ("LINEAR", "STEP", "CUBICSPLINE")
PATHS = ("translation", "rotation", "scale", "weights")
USE = {"translation": "ANIMATION_TRANSLATION", "rotation": "ANIMATION_ROTATION",
       "scale": "ANIMATION_SCALE", "weights": "ANIMATION_WEIGHTS"}
# Below this angle between two unit quaternions sin(a) loses its digits (float64: a
# relative error ~ eps / a): the linear form, which slerp tends to, is within a^2/8 of it.
SLERP_LINEAR_BELOW = 1e-6


@dataclass
class Pose:
    """What an animation time overrides: node -> {"translation"|"rotation"|"scale": value}
    and node -> morph weights."""
    trs: dict = field(default_factory=dict)
    weights: dict = field(default_factory=dict)
    time: float | None = None
    animations: tuple = ()


def slerp(a: np.ndarray, b: np.ndarray, s: float) -> np.ndarray:
    """Appendix C's slerp of unit quaternions a, b (x, y, z, w), the shorter arc."""
    d = float(np.dot(a, b))
    angle = math.acos(min(abs(d), 1.0))
    sign = 1.0 if d >= 0 else -1.0
    if angle < SLERP_LINEAR_BELOW:
        out = (1 - s) * a + sign * s * b
    else:
        out = (math.sin(angle * (1 - s)) * a + sign * math.sin(angle * s) * b) / math.sin(angle)
    return out / np.linalg.norm(out)


def hermite(v0, b0, v1, a1, td: float, s: float) -> np.ndarray:
    """Appendix C's cubic Hermite spline between keyframes (v0 with out-tangent b0, v1
    with in-tangent a1), td seconds apart, at s in [0, 1]."""
    s2, s3 = s * s, s * s * s
    return ((2 * s3 - 3 * s2 + 1) * v0 + td * (s3 - 2 * s2 + s) * b0
            + (-2 * s3 + 3 * s2) * v1 + td * (s3 - s2) * a1)


def interpolate(times: np.ndarray, values: np.ndarray, interpolation: str, t: float,
                rotation: bool = False) -> np.ndarray:
    """A sampler's value at time t. ``values``: one row per keyframe (three per keyframe,
    in-tangent, value, out-tangent, for CUBICSPLINE)."""
    n = len(times)
    if interpolation == "CUBICSPLINE":
        a, v, b = values[0::3], values[1::3], values[2::3]
    else:
        v = values
    if t <= times[0] or n == 1:
        out = v[0].copy()
    elif t >= times[-1]:
        out = v[-1].copy()
    else:
        k = int(np.searchsorted(times, t, side="right")) - 1  # t_k <= t < t_(k+1)
        td = float(times[k + 1] - times[k])
        s = (t - float(times[k])) / td
        if interpolation == "STEP":
            out = v[k].copy()
        elif interpolation == "LINEAR":
            out = slerp(v[k], v[k + 1], s) if rotation else (1 - s) * v[k] + s * v[k + 1]
        else:
            out = hermite(v[k], b[k], v[k + 1], a[k + 1], td, s)
    if rotation:
        length = np.linalg.norm(out)
        out = out / length if length > 0 else np.array([0.0, 0.0, 0.0, 1.0])
    return out


ALL = "all"  # --animation all: every animation sampled together


def listed_animations(doc: Document) -> str:
    """The file's animations as "0 'Survey', 1 'Walk'" (an unnamed one by its index)."""
    names = [a.data.get("name") for a in doc.items("animations")]
    return ", ".join(f"{i} {n!r}" if isinstance(n, str) else str(i) for i, n in enumerate(names)) or "none"


def chosen_animations(doc: Document, animation: str | int | None, warn=None) -> list[int]:
    """The animations sampled (module doc): the first, the one ``--animation`` names (an
    index or a name), or all of them for "all"; refused with the file's list when it names
    none. ``warn(message)`` hears which one was taken when the file has several and the
    user named none."""
    animations = doc.items("animations")
    names = [a.data.get("name") for a in animations]
    if animation is None:
        if len(animations) > 1 and warn is not None:
            warn(f"animation 0 sampled, the first of {len(animations)} ({listed_animations(doc)}); glTF "
                 f"animations are alternatives: --animation NAME|INDEX picks another, --animation all samples "
                 f"them together")
        return [0]
    if animation in names:
        return [names.index(animation)]
    text = str(animation)
    if text == ALL:
        return list(range(len(animations)))
    if text.isdigit() and int(text) < len(animations):
        return [int(text)]
    doc.fail("animations", f"--animation {animation}: no animation has that index or name "
                           f"(the file's animations: {listed_animations(doc)}; or all)")


def check_time(time: float) -> float:
    if not math.isfinite(time):
        raise PbrlabError(f"--time {time}: expected a finite number of seconds")
    return float(time)


def sample(doc: Document, time: float | None, animation: str | None, warn=None) -> Pose:
    """The pose at ``time`` (None with no animation chosen: no pose, the nodes as written;
    an animation without a time: its first keyframes, t = 0). ``warn``: chosen_animations'."""
    if time is None and animation is None:
        return Pose()
    if not doc.items("animations"):
        doc.fail("animations", f"{'--time' if time is not None else '--animation'}: the file has no animations")
    time = 0.0 if time is None else check_time(time)
    chosen = chosen_animations(doc, animation, warn)
    pose = Pose(time=time, animations=tuple(chosen))
    nodes = doc.items("nodes")
    for index in chosen:
        anim = doc.items("animations")[index]
        samplers = anim.objects("samplers", min_items=1)
        for c, channel in enumerate(anim.objects("channels", min_items=1)):
            target = channel.object("target")
            node_index = target.index("node", "nodes")
            path = target.enum("path", PATHS)
            if node_index is None:
                continue  # spec 5.6: without a node the channel "should be ignored" (an extension may target)
            sampler = samplers[channel.integer("sampler", None, lo=0, hi=len(samplers) - 1)]
            value = _sampled(doc, sampler, path, nodes[node_index], time)
            if path == "weights":
                pose.weights[node_index] = tuple(float(w) for w in value)
            else:
                if nodes[node_index].has("matrix"):
                    channel.fail(f"animates {path} of node {node_index}, which has a matrix "
                                 "(spec 3.11: an animated node must use translation, rotation and scale)")
                pose.trs.setdefault(node_index, {})[path] = value
    return pose


def _sampled(doc: Document, sampler, path: str, node, time: float) -> np.ndarray:
    interpolation = sampler.enum("interpolation", INTERPOLATIONS, "LINEAR")
    times = read_accessor(doc, sampler.index("input", "accessors", required=True),
                          f"{sampler.path}.input", "ANIMATION_INPUT")[:, 0]
    if np.any(np.diff(times) <= 0):
        sampler.fail("input: keyframe times must increase strictly (spec 3.11)")
    per_key = 3 if interpolation == "CUBICSPLINE" else 1
    if interpolation == "CUBICSPLINE" and len(times) < 2:
        sampler.fail("input: CUBICSPLINE needs at least two keyframes (spec 3.11)")
    values = read_accessor(doc, sampler.index("output", "accessors", required=True),
                           f"{sampler.path}.output", USE[path])
    if path == "weights":
        rows = len(values)
        if rows % (len(times) * per_key):
            sampler.fail(f"output: {rows} weights are not a multiple of {len(times) * per_key} "
                         f"({len(times)} keyframes{' x 3' if per_key == 3 else ''})")
        values = values.reshape(len(times) * per_key, -1)
    elif len(values) != len(times) * per_key:
        sampler.fail(f"output: {len(values)} values for {len(times)} keyframes "
                     f"(expected {len(times) * per_key}{' (in-tangent, value, out-tangent each)' if per_key == 3 else ''})")
    return interpolate(times, values, interpolation, time, rotation=path == "rotation")
