"""The output struct of a layered lighting model (``model.LAYERED_MODELS``) as code, written
from the model's field table (``model.OUTPUT_FIELDS``): the harness declares it before the
program, so the port's type pass (``port.port_program``) knows it and the generated programs
(``generate``) carry it. It lies between the model and the port: it reads only the model.
"""

from __future__ import annotations

from . import model as M


def vector_type(n: int) -> str:
    """The float vector type of ``n`` components as the generated code spells it."""
    return "float" if n == 1 else f"vec{n}"


def layered_struct(shader) -> list[str]:
    """The output struct of a layered model (model.LAYERED_MODELS), written from its field
    table before the program that fills it; none for the other models."""
    if getattr(shader, "kind", None) != "surface" or shader.pragma.model not in M.LAYERED_MODELS:
        return []
    name = M.BUILTIN_MODELS[shader.pragma.model]
    fields = [f"    {vector_type(n)} {field};" for field, n in M.OUTPUT_FIELDS[name].items()]
    return [f"// {name}: {M.LAYERED_MODELS[shader.pragma.model]}'s fields, then SurfaceOutputStandardLayers'",
            f"struct {name} {{", *fields, "};"]
