"""Typed reads from one glTF JSON object: the one place the importer checks a field's type
and range before using it (the glTF 2.0 specification's JSON schema, section 5).

    node = FieldReader(data, "nodes[3]", doc)
    node.numbers("translation", 3, default=[0, 0, 0])    # np.ndarray, finite
    mesh = node.index("mesh", "meshes")                  # an int in range, or None

Messages follow the importer's two forms, both naming the file and the field path:
a bad value is refused at its object, ``x.gltf: materials[0].pbrMetallicRoughness:
metallicFactor must be a number in [0, 1], got "a"``; a bad container (an array or object
that is something else) at its own path, ``x.gltf: materials: expected an array of
objects, got "gold"``. Values reach this module through pbrlab.foundation.json_input, so numbers
are already finite and within float32; types are checked strictly (1.0 is no index,
0 is no boolean).
"""

from __future__ import annotations

import json
import math

import numpy as np

from ...foundation.errors import SceneError


def shown(value) -> str:
    """A value as JSON, cut short for a message."""
    text = json.dumps(value)
    return text if len(text) <= 40 else text[:37] + "..."


def join(path: str, key) -> str:
    if isinstance(key, int):
        return f"{path}[{key}]"
    return f"{path}.{key}" if path else key


def _is_int(value) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _option(option, names: dict | None) -> str:
    if names and option in names:
        return f"{option} ({names[option]})"  # a GL enum with its name: 33071 (CLAMP_TO_EDGE)
    return option if isinstance(option, str) else json.dumps(option)


def _interval(lo, hi, lo_open=False) -> str:
    return f"{'(' if lo_open else '['}{lo:g}, {hi:g}]"


class FieldReader:
    """One JSON object of a glTF document at ``path``; ``doc`` (a document.Document)
    resolves indices into the top-level arrays and names the file in messages."""

    def __init__(self, data, path: str, doc=None):
        self.path, self.doc = path, doc
        if not isinstance(data, dict):
            self.fail_at(path, f"expected an object, got {shown(data)}")
        self.data = data

    # --- failing ----------------------------------------------------------------------
    def fail_at(self, where: str, message: str):
        origin = self.doc.path if self.doc is not None else "<glTF>"
        raise SceneError(f"{origin}: {where or '(top level)'}: {message}")

    def fail(self, message: str):
        self.fail_at(self.path, message)

    def _bad(self, key, what: str, value):
        self.fail(f"{key} must be {what}, got {shown(value)}")

    # --- presence ---------------------------------------------------------------------
    def has(self, key) -> bool:
        return key in self.data

    def _value(self, key, default, what: str):
        if key in self.data:
            return self.data[key]
        if default is None:
            self.fail(f"{key} is required ({what})")
        return default

    # --- containers -------------------------------------------------------------------
    def object(self, key) -> FieldReader:
        """The object at ``key`` (an empty one when absent)."""
        return FieldReader(self.data.get(key, {}), join(self.path, key), self.doc)

    def array(self, key, min_items: int = 0) -> list:
        value = self.data.get(key, [])
        where = join(self.path, key)
        if not isinstance(value, list):
            self.fail_at(where, f"expected an array, got {shown(value)}")
        if len(value) < min_items:
            self.fail_at(where, f"expected an array of at least {min_items} item{'s' if min_items > 1 else ''}, "
                                f"got {shown(value)}")
        return value

    def objects(self, key, min_items: int = 0) -> list[FieldReader]:
        """The array of objects at ``key`` (empty when absent)."""
        items, where = self.array(key, min_items), join(self.path, key)
        for i, v in enumerate(items):
            if not isinstance(v, dict):
                self.fail_at(f"{where}[{i}]", f"expected an object, got {shown(v)}")
        return [FieldReader(v, f"{where}[{i}]", self.doc) for i, v in enumerate(items)]

    def strings(self, key) -> list[str]:
        values = self.array(key)
        for i, v in enumerate(values):
            if not isinstance(v, str):
                self.fail_at(f"{join(self.path, key)}[{i}]", f"expected a string, got {shown(v)}")
        return values

    def extensions(self) -> list[tuple[str, FieldReader]]:
        """(name, object) of each extension the object carries (spec 3.12: objects)."""
        ext = self.object("extensions")
        return [(name, ext.object(name)) for name in ext.data]

    # --- scalars ----------------------------------------------------------------------
    def integer(self, key, default=None, lo: int = 0, hi: int | None = None) -> int:
        what = (f"an integer in [{lo}, {hi}]" if hi is not None else
                "a non-negative integer" if lo == 0 else "a positive integer" if lo == 1 else f"an integer >= {lo}")
        value = self._value(key, default, what)
        if not _is_int(value) or value < lo or (hi is not None and value > hi):
            self._bad(key, what, value)
        return value

    def number(self, key, default=None, lo=-math.inf, hi=math.inf, lo_open=False) -> float:
        what = "a number" if (lo, hi) == (-math.inf, math.inf) else f"a number in {_interval(lo, hi, lo_open)}"
        value = self._value(key, default, what)
        if not _is_number(value) or not (lo < value if lo_open else lo <= value) or value > hi:
            self._bad(key, what, value)
        return float(value)

    def numbers(self, key, n: int, default=None, lo=-math.inf, hi=math.inf) -> np.ndarray:
        what = f"{n} numbers" + ("" if (lo, hi) == (-math.inf, math.inf) else f" in {_interval(lo, hi)}")
        value = self._value(key, default, what)
        if (not isinstance(value, list) or len(value) != n
                or not all(_is_number(v) and lo <= v <= hi for v in value)):
            self._bad(key, what, value)
        return np.array(value, np.float64)

    def string(self, key, default=None) -> str:
        value = self._value(key, default, "a string")
        if not isinstance(value, str):
            self._bad(key, "a string", value)
        return value

    def boolean(self, key, default=None) -> bool:
        value = self._value(key, default, "true or false")
        if not isinstance(value, bool):
            self._bad(key, "true or false", value)
        return value

    def enum(self, key, options, default=None, names: dict | None = None):
        """One of ``options``, same type and value (4.0 is not the mode 4)."""
        shown_options = ", ".join(_option(o, names) for o in options)
        value = self._value(key, default, f"one of {shown_options}")
        if not any(type(value) is type(o) and value == o for o in options):
            self._bad(key, f"one of {shown_options}", value)
        return value

    # --- references -------------------------------------------------------------------
    def index(self, key, collection: str, required: bool = False) -> int | None:
        """An index into the document's top-level array ``collection`` (None when absent
        and not required)."""
        if key not in self.data:
            if required:
                self.fail(f"{key} is required (an index into {collection})")
            return None
        return self.doc.check_index(collection, self.data[key], join(self.path, key))

    def indices(self, key, collection: str) -> list[int]:
        """An array of indices into ``collection``, each given once."""
        values = self.array(key)
        where = join(self.path, key)
        out = [self.doc.check_index(collection, v, f"{where}[{i}]") for i, v in enumerate(values)]
        if len(set(out)) != len(out):
            self.fail_at(where, f"names an index twice: {shown(values)}")
        return out
