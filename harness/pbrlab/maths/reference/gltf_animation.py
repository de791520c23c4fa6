"""Float64 reference of glTF 2.0's animation samplers (spec Appendix C "Animation Sampler
Interpolation Modes"), written from the specification in a different form from the
importer's (gltf.animation), so the tests compare two derivations:

- STEP: the keyframe at or before t (Appendix C: "the value of the first keyframe
  of the interval").
- LINEAR: the straight line between the two keyframes; a rotation as the geodesic
  on the unit quaternion sphere, here q_k (q_k^-1 q_(k+1))^s through the axis-angle
  power of the relative rotation (the shorter arc: q_(k+1) negated when q_k . q_(k+1) < 0),
  which equals Appendix C's sin-weighted slerp.
- CUBICSPLINE: the Hermite basis as a matrix, p(s) = [s^3 s^2 s 1] H [v_k, td b_k, v_(k+1), td a_(k+1)]^T,
  H = [[2, 1, -2, 1], [-3, -2, 3, -1], [0, 1, 0, 0], [1, 0, 0, 0]]; a quaternion normalised.
- Outside the time range: the first or last keyframe's value.
"""

from __future__ import annotations

import math

import numpy as np

HERMITE = np.array([[2.0, 1.0, -2.0, 1.0], [-3.0, -2.0, 3.0, -1.0], [0.0, 1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]])


def quat_multiply(a, b) -> np.ndarray:
    """Hamilton product of (x, y, z, w) quaternions."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz])


def quat_power(q, s: float) -> np.ndarray:
    """q^s of a unit quaternion: the same axis, s times the angle."""
    w = min(max(q[3], -1.0), 1.0)
    half = math.acos(w)
    axis = np.asarray(q[:3], np.float64)
    n = np.linalg.norm(axis)
    if n == 0.0:
        return np.array([0.0, 0.0, 0.0, 1.0])
    return np.concatenate([axis / n * math.sin(half * s), [math.cos(half * s)]])


def geodesic(q0, q1, s: float) -> np.ndarray:
    q0, q1 = np.asarray(q0, np.float64), np.asarray(q1, np.float64)
    if np.dot(q0, q1) < 0:
        q1 = -q1
    conjugate = np.array([-q0[0], -q0[1], -q0[2], q0[3]])
    return quat_multiply(q0, quat_power(quat_multiply(conjugate, q1), s))


def sample(times, values, interpolation: str, t: float, rotation: bool = False) -> np.ndarray:
    times = [float(x) for x in times]
    values = np.asarray(values, np.float64)
    keys = values.reshape(len(times), 3, -1) if interpolation == "CUBICSPLINE" else values.reshape(len(times), 1, -1)
    value = keys[:, 1] if interpolation == "CUBICSPLINE" else keys[:, 0]
    if t <= times[0]:
        out = value[0]
    elif t >= times[-1]:
        out = value[-1]
    else:
        k = max(i for i in range(len(times)) if times[i] <= t)
        td = times[k + 1] - times[k]
        s = (t - times[k]) / td
        if interpolation == "STEP":
            out = value[k]
        elif interpolation == "LINEAR" and rotation:
            out = geodesic(value[k], value[k + 1], s)
        elif interpolation == "LINEAR":
            out = value[k] + s * (value[k + 1] - value[k])
        else:
            basis = np.array([s ** 3, s ** 2, s, 1.0]) @ HERMITE
            out = basis @ np.stack([value[k], td * keys[k, 2], value[k + 1], td * keys[k + 1, 0]])
    out = np.array(out, np.float64)
    return out / np.linalg.norm(out) if rotation else out
