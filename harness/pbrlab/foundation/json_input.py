"""The one gate every JSON-like input passes before a parser reads its fields.

``read_json_file(path)`` reads a file as strict JSON; ``normalize(data, origin)`` checks a
parsed (or hand-built) document and returns a fresh copy in plain Python types. Both raise
SceneError naming the file and the field path, e.g.
``scene.json: lights[2].intensity: 1e400 is not a finite number``. What they refuse:

* a key given twice in one object (JSON allows it; the last one would win in silence);
* non-finite numbers anywhere: the literals ``NaN``, ``Infinity``, ``-Infinity`` and
  numbers that overflow a double (``1e400``);
* finite numbers beyond the float32 range (|x| > 3.4028235e38): the GPU holds float32;
* nesting deeper than ``MAX_DEPTH`` (a scene needs 6 levels) and non-string keys;
* files that are not UTF-8, unreadable (permissions, a symlink loop) or not JSON.

What they accept besides JSON's own types, so the Python API takes what numpy code holds:
numpy scalars (``np.float32(0.5)``, ``np.int64(3)``, ``np.bool_``), numpy arrays (as
nested lists) and tuples (as lists). Booleans stay booleans: a parser must not take 0 or
"yes" for one (``scene._Reader.choice`` compares types).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from .errors import SceneError

MAX_DEPTH = 32
FLOAT32_MAX = float(np.finfo(np.float32).max)


class _Pairs(dict):
    """An object as parsed, remembering keys that appeared more than once."""
    duplicates: tuple = ()


def pairs_hook(pairs):
    obj = _Pairs()
    seen = []
    for key, value in pairs:
        if key in obj:
            seen.append(key)
        obj[key] = value
    obj.duplicates = tuple(seen)
    return obj


def parse_constant(name):
    return {"NaN": math.nan, "Infinity": math.inf, "-Infinity": -math.inf}[name]


def read_json_file(path) -> object:
    """Parse ``path`` as JSON (duplicate keys and non-finite numbers are caught by
    ``normalize``, which the caller runs on the result)."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except IsADirectoryError:
        raise SceneError(f"{path}: is a directory, not a scene file") from None
    except FileNotFoundError:
        raise SceneError(f"{path}: no such scene file") from None
    except OSError as exc:
        raise SceneError(f"{path}: cannot read: {exc.strerror or exc}") from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SceneError(f"{path}: not a UTF-8 text file (byte 0x{data[exc.start]:02x} at "
                         f"offset {exc.start})") from None
    try:
        return json.loads(text, object_pairs_hook=pairs_hook, parse_constant=parse_constant)
    except json.JSONDecodeError as exc:
        raise SceneError(f"{path}:{exc.lineno}:{exc.colno}: invalid JSON: {exc.msg}") from None
    except RecursionError:
        raise SceneError(f"{path}: JSON nested too deeply (a scene needs a few levels; "
                         f"at most {MAX_DEPTH} are read)") from None


def _where(path: str) -> str:
    return path.lstrip(".") or "(top level)"


def _number(value: float, origin: str, path: str):
    if math.isnan(value):
        raise SceneError(f"{origin}: {_where(path)}: is NaN; every number must be finite")
    if math.isinf(value):
        raise SceneError(f"{origin}: {_where(path)}: is infinite ({'-' if value < 0 else ''}Infinity, "
                         "or a number beyond 1.8e308 such as 1e400); every number must be finite")
    if abs(value) > FLOAT32_MAX:
        raise SceneError(f"{origin}: {_where(path)}: {value:g} is beyond the float32 range "
                         f"(|x| <= {FLOAT32_MAX:.8g}) the GPU computes in")
    return value


def normalize(data, origin: str = "<scene>", path: str = "", depth: int = 0):
    """A checked copy of ``data`` in plain JSON types (module doc); never mutates ``data``."""
    if depth > MAX_DEPTH:
        raise SceneError(f"{origin}: {_where(path)}: nested more than {MAX_DEPTH} levels deep")
    if isinstance(data, np.ndarray):
        data = data.tolist()
    elif isinstance(data, np.generic):
        data = data.item()
    if data is None or isinstance(data, (bool, str)):
        return data
    if isinstance(data, int):
        if abs(data) > FLOAT32_MAX:
            raise SceneError(f"{origin}: {_where(path)}: {data} is beyond the float32 range")
        return data
    if isinstance(data, float):
        return _number(data, origin, path)
    if isinstance(data, dict):
        duplicates = getattr(data, "duplicates", ())
        if duplicates:
            raise SceneError(f"{origin}: {_where(path)}: key {json.dumps(duplicates[0])} is given "
                             "more than once (JSON would keep only the last one)")
        out = {}
        for key, value in data.items():
            if not isinstance(key, str):
                raise SceneError(f"{origin}: {_where(path)}: keys must be strings, got {key!r}")
            out[key] = normalize(value, origin, f"{path}.{key}", depth + 1)
        return out
    if isinstance(data, (list, tuple)):
        return [normalize(v, origin, f"{path}[{i}]", depth + 1) for i, v in enumerate(data)]
    raise SceneError(f"{origin}: {_where(path)}: expected a JSON value, got a "
                     f"{type(data).__name__} ({_short(data)})")


def _short(value) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."
