"""The keywords a material's property drawers enable (Unity's MaterialPropertyDrawer, Scripting
API): Unity's material inspector sets them from the property's value when a material is made
or the value changes, so a material of the shader drawn with its defaults has them on.

- ``[Toggle]`` / ``[Toggle(KEYWORD)]`` on a number: KEYWORD (by default the property's name in
  upper case with ``_ON``) where the value is not 0;
- ``[ToggleOff]`` / ``[ToggleOff(KEYWORD)]``: KEYWORD (by default the name with ``_OFF``) where
  the value is 0;
- ``[KeywordEnum(A, B, C)]``: the property's name, ``_``, and the value-th name, in upper case
  with spaces as ``_`` (``[KeywordEnum(None, High Quality)] _SunDisk = 1``: ``_SUNDISK_HIGH_QUALITY``).

Only the keywords some pass declares matter (a program sees no other); unity/material.py
enables them where the material's own ``keywords`` enable none of their set.

    words = drawer_keywords(shader.properties, values)   # values: properties.resolve's
"""

from __future__ import annotations

import re

_DRAWER = re.compile(r"^(Toggle|ToggleOff|KeywordEnum)\s*(?:\((.*)\))?$")


def drawer_keywords(properties: dict, values: dict) -> tuple:
    """The keywords the properties' drawers enable at ``values`` (module docstring)."""
    out = []
    for name, prop in properties.items():
        value = values.get(name)
        if not isinstance(value, (int, float)):
            continue
        for attribute in prop.attributes:
            m = _DRAWER.match(attribute.strip())
            if m is None:
                continue
            kind, argument = m.group(1), (m.group(2) or "").strip()
            if kind == "Toggle" and value != 0:
                out.append(argument or f"{name.upper()}_ON")
            elif kind == "ToggleOff" and value == 0:
                out.append(argument or f"{name.upper()}_OFF")
            elif kind == "KeywordEnum":
                names = [n.strip() for n in argument.split(",")]
                index = int(value)
                if argument and 0 <= index < len(names) and index == value:
                    out.append(f"{name}_{names[index]}".upper().replace(" ", "_"))
    return tuple(dict.fromkeys(out))
