"""HLSL -> WGSL with Slang, the compiler whose library the PyPI package slangpy ships.

    wgsl = hlsl_to_wgsl(hlsl_text, name="sphere.frag.hlsl", include_dirs=[HLSL_ROOT])

slangpy ships Slang's compiler library (libslang-compiler.so) but no ``slangc``, and its Python
API compiles only for the device it opens (WGSL needs Dawn, which it does not carry). The
library's C entry points take slangc's own command line (spProcessCommandLineArguments), so
this module calls them through ctypes: ``-target wgsl -stage fragment -entry main -I DIR FILE``.
The legacy C API is the one Slang documents as stable for C callers (slang.h, "C API").
"""

from __future__ import annotations

import ctypes
import tempfile
from pathlib import Path

from ..foundation.errors import PbrlabError, ShaderCompileError

_SLANG_OK = 0  # SLANG_OK


def _library() -> ctypes.CDLL:
    try:
        import slangpy
    except ImportError:
        raise PbrlabError("slangpy is not installed: it carries the Slang compiler; pip install slangpy==0.43.1 "
                          "(in a pbrlab checkout, scripts/setup.sh does)") from None
    found = sorted(Path(slangpy.__file__).parent.glob("libslang-compiler.so*"))
    if not found:
        raise PbrlabError(f"slangpy {slangpy.__version__} has no libslang-compiler.so beside it")
    lib = ctypes.CDLL(str(found[0]))
    lib.spCreateSession.restype = ctypes.c_void_p
    lib.spCreateSession.argtypes = [ctypes.c_char_p]
    lib.spDestroySession.argtypes = [ctypes.c_void_p]
    lib.spCreateCompileRequest.restype = ctypes.c_void_p
    lib.spCreateCompileRequest.argtypes = [ctypes.c_void_p]
    lib.spDestroyCompileRequest.argtypes = [ctypes.c_void_p]
    lib.spProcessCommandLineArguments.restype = ctypes.c_int32
    lib.spProcessCommandLineArguments.argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_char_p), ctypes.c_int]
    lib.spCompile.restype = ctypes.c_int32
    lib.spCompile.argtypes = [ctypes.c_void_p]
    lib.spGetDiagnosticOutput.restype = ctypes.c_char_p
    lib.spGetDiagnosticOutput.argtypes = [ctypes.c_void_p]
    lib.spGetEntryPointCode.restype = ctypes.c_void_p
    lib.spGetEntryPointCode.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.POINTER(ctypes.c_size_t)]
    return lib


def hlsl_to_wgsl(hlsl: str, name: str = "<hlsl>", include_dirs=(), stage: str = "fragment",
                 entry: str = "main") -> str:
    """Slang's WGSL for one HLSL entry point; a refusal is a ShaderCompileError with Slang's
    diagnostics, naming ``name``."""
    lib = _library()
    with tempfile.TemporaryDirectory(prefix="pbrlab-slang-") as tmp:
        source = Path(tmp) / Path(name).name
        source.write_text(hlsl, encoding="utf-8")
        args = ["-target", "wgsl", "-stage", stage, "-entry", entry]
        for directory in include_dirs:
            args += ["-I", str(directory)]
        args.append(str(source))
        session = lib.spCreateSession(None)
        request = lib.spCreateCompileRequest(session)
        try:
            argv = (ctypes.c_char_p * len(args))(*(a.encode() for a in args))
            rc = lib.spProcessCommandLineArguments(request, argv, len(args))
            if rc == _SLANG_OK:
                rc = lib.spCompile(request)
            diagnostics = (lib.spGetDiagnosticOutput(request) or b"").decode(errors="replace")
            size = ctypes.c_size_t()
            code = lib.spGetEntryPointCode(request, 0, ctypes.byref(size)) if rc == _SLANG_OK else None
            if rc != _SLANG_OK or not code:
                message = diagnostics.replace(str(source), name).strip()
                raise ShaderCompileError(f"{name}: Slang could not compile it to WGSL (result {rc}):\n{message}")
            return ctypes.string_at(code, size.value).decode("utf-8")
        finally:
            lib.spDestroyCompileRequest(request)
            lib.spDestroySession(session)
