"""HLSL as written, for glslang: a vector argument wider than the parameter of the program's own
function it is passed to, truncated explicitly (``.x``, ``.xyz``), as FXC does implicitly.

    text = truncated_arguments(hlsl_text)

FXC, Unity's compiler for Direct3D, converts an argument to its parameter's type with a
warning, not an error, where it drops components ("X3206: implicit truncation of vector type";
Microsoft's HLSL reference, "Casting and conversion": a vector to a smaller vector or a scalar
keeps its first components). TextMesh Pro's shaders rely on it: ``UnpackUV(float uv)`` called
with a ``float2``. glslang's HLSL front end finds no overload and refuses the program. The GLSL
port spells the same truncation in its type pass (cg_types, which this module reuses to type
the arguments); here only that edit is applied, to the program's own functions (an include's
functions and Unity's are compiled from their files), and only where the parameter and the
argument are a scalar or a vector and the call has one candidate overload. An argument of a
type the type pass cannot infer is left as written.
"""

from __future__ import annotations

import functools

from . import cg_types


class _ArgumentReader(cg_types._Parser):
    """The Cg type pass, recording which of its edits are argument truncations."""

    def __init__(self, text: str, symbols: cg_types.Symbols, own: frozenset, srp: bool):
        super().__init__(text, symbols, srp=srp)
        self.own = own
        self.truncations: list[int] = []   # ids of self.edits' items

    def overload(self, sigs, args):
        sig = super().overload(sigs, args)
        if sig is None or self.decl_only or not any(s is sig for name in self.own for s in self.sym.functions.get(name, ())):
            return sig
        for a, p in zip(args, sig.params):
            t, want = a.t, p.type
            if p.qual != "in" or t is None or not (t.numeric and want.numeric) or t.cols or want.cols:
                continue
            if t.dim > want.dim:
                mark = self.edits.mark()
                self.truncate(a, want.dim)
                self.truncations += range(mark + 1, self.edits.mark() + 1)
        return sig


@functools.lru_cache(maxsize=64)  # each stage of a program asks for the same text
def truncated_arguments(text: str, srp: bool = False) -> str:
    """``text`` (a Cg/HLSL program) with each vector argument to one of its own functions that
    is wider than the parameter cut to the parameter's size; anything the type pass cannot read
    is left as written."""
    library = cg_types.library()
    declared = cg_types.library().copy()
    try:
        cg_types._Parser(text, declared, declarations_only=True, srp=srp).program()
        own = frozenset(name for name in declared.functions if name not in library.functions)
        if not own:
            return text
        reader = _ArgumentReader(text, library.copy(), own, srp)
    except cg_types.CgSyntaxError:
        return text
    reader.program()
    kept = cg_types.Edits()
    kept.items = {k: v for k, v in reader.edits.items.items() if k in set(reader.truncations)}
    return kept.apply(text) if kept.items else text
