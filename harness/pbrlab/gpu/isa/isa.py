"""What a disassembly says beyond RADV's statistics: how much of the arithmetic is 16-bit,
and how much of that is packed (two halves per instruction, ``v_pk_*``)."""

from __future__ import annotations

import re

_INSTRUCTION = re.compile(r"^\s+([a-z]\w*)\b")
# ACO folds a run of identical instructions into one line and this note (aco_print_asm)
_REPEATED = re.compile(r"^\s*\(then repeated (\d+) times\)")
_TRANSCENDENTAL = re.compile(r"v_(exp|log|rcp|rsq|sqrt|sin|cos)_")


def instructions(disassembly: str) -> list:
    """Mnemonics in program order, with ACO's folded repeats expanded."""
    names = []
    for line in disassembly.splitlines():
        if (m := _REPEATED.match(line)) and names:
            names += [names[-1]] * int(m.group(1))
        elif (m := _INSTRUCTION.match(line)) and not line.strip().endswith(":"):
            names.append(m.group(1))
    return names


def summary(disassembly: str) -> dict:
    """Counts of vector ALU instructions by precision in an ACO disassembly."""
    valu = [n for n in instructions(disassembly) if n.startswith("v_")]
    return {"valu": len(valu),
            "valu_f16": sum(1 for n in valu if "f16" in n or "16" in n.split("_")[-1]),
            "valu_packed": sum(1 for n in valu if n.startswith("v_pk_")),
            "transcendental": sum(1 for n in valu if _TRANSCENDENTAL.match(n))}
