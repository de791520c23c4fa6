"""The one OpenGL context factory: headless Mesa through EGL or OSMesa.

``create_context(backend)`` returns a moderngl context (core profile, GL >= 3.3).

* ``egl``: moderngl's standalone EGL backend (glcontext), Mesa's EGL + llvmpipe here,
  NVIDIA's EGL on a GPU machine.
* ``osmesa``: libOSMesa with a core-profile 3.3 context, adopted by moderngl through a
  function loader (``moderngl.init_context(loader=...)``).

Library locations: glcontext's ``GLCONTEXT_LINUX_LIBEGL`` / ``GLCONTEXT_LINUX_LIBGL`` pick
the EGL and GL libraries, ``$PBRLAB_OSMESA_LIBRARY`` picks libOSMesa.

The default backend comes from ``$PBRLAB_GL_BACKEND``; when that is unset, EGL is tried
first and OSMesa second, and when neither loads a single paragraph names the packages.

llvmpipe pinning: llvmpipe compiles shaders for the host CPU's vector extensions, so the
last bits of a result can differ between machines. Unless ``$PBRLAB_LLVMPIPE_CPU_CAPS``
says ``native``, the factory sets ``GALLIUM_OVERRIDE_CPU_CAPS`` (default ``sse4.1``, which
every x86-64 CPU since 2008 has) before the driver loads, so renders are reproducible
across x86-64 hosts. This must happen before the first context of the process.

Mesa's shader disk cache: Mesa 22.3 keys a cached llvmpipe binary by the program's text and
the driver's build, not by ``GALLIUM_OVERRIDE_CPU_CAPS`` or ``LP_NATIVE_VECTOR_WIDTH``, so a
binary compiled on the 256-bit code path was loaded by a later 128-bit process (and the other
way round) and its last bits followed whichever path ran first: the specialised and full
programs of the README's scene then differed by 2 ulp in 352 values, in 1 full run of 3, and
agreed with the cache disabled. Unless the caller names a cache folder
(``MESA_SHADER_CACHE_DIR``, or the older ``MESA_GLSL_CACHE_DIR``) or disables the cache, the
factory gives each code path its own folder (``shader_cache_folder``), set with the CPU pin.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os
import re
import weakref

import moderngl

from ..foundation.errors import GLUnavailableError, PbrlabError

BACKENDS = ("egl", "osmesa")
BACKEND_ENV = "PBRLAB_GL_BACKEND"
CPU_CAPS_ENV = "PBRLAB_LLVMPIPE_CPU_CAPS"
DEFAULT_CPU_CAPS = "sse4.1"
REQUIRED_GL_VERSION = 330

_INSTALL_HINT = (
    "pbrlab renders headless through Mesa, and neither of its OpenGL libraries could be "
    "loaded ({details}). On Debian or Ubuntu install them with "
    "`sudo apt-get install -y libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6` "
    "(in a pbrlab checkout, scripts/setup.sh installs them when run as root), then try again. "
    "To choose one library, set PBRLAB_GL_BACKEND=egl or PBRLAB_GL_BACKEND=osmesa."
)


def shader_cache_folder() -> str:
    """Mesa's shader cache folder for this process's llvmpipe code path (module doc): the
    user's cache folder's mesa_shader_cache/pbrlab-<caps>-<vector width>."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    caps = os.environ.get("GALLIUM_OVERRIDE_CPU_CAPS", "native")
    width = os.environ.get("LP_NATIVE_VECTOR_WIDTH", "default")
    return os.path.join(base, "mesa_shader_cache", f"pbrlab-{re.sub(r'[^A-Za-z0-9.]', '_', caps)}-{width}")


def pin_llvmpipe_cpu_caps() -> str:
    """Pin llvmpipe's code generation to one CPU feature level, and keep Mesa's shader cache
    apart per code path (module doc); returns the level used."""
    caps = os.environ.get(CPU_CAPS_ENV, DEFAULT_CPU_CAPS)
    if caps != "native":
        os.environ.setdefault("GALLIUM_OVERRIDE_CPU_CAPS", caps)
    if not any(os.environ.get(name) for name in ("MESA_SHADER_CACHE_DIR", "MESA_GLSL_CACHE_DIR")):
        folder = shader_cache_folder()
        # Mesa makes only the last folder of the path: on a fresh machine without ~/.cache it
        # printed "Failed to create ... for shader cache" and ran every process uncached.
        try:
            os.makedirs(folder, exist_ok=True)
        except OSError:
            pass  # unwritable home: Mesa says so and runs uncached, as it would anyway
        os.environ["MESA_SHADER_CACHE_DIR"] = folder
    return os.environ.get("GALLIUM_OVERRIDE_CPU_CAPS", "native")


def default_backend() -> str | None:
    """The backend named by $PBRLAB_GL_BACKEND, or None for 'EGL, then OSMesa'."""
    name = os.environ.get(BACKEND_ENV, "").strip().lower()
    if name and name not in BACKENDS:
        raise PbrlabError(
            f"{BACKEND_ENV}={name!r} is not a backend; use one of {', '.join(BACKENDS)}."
        )
    return name or None


def create_context(backend: str | None = None) -> moderngl.Context:
    """A new headless moderngl context on ``backend`` ('egl', 'osmesa' or None = default)."""
    if backend is None:
        backend = default_backend()
    if backend is not None and backend not in BACKENDS:
        raise PbrlabError(f"unknown GL backend {backend!r}; use one of {', '.join(BACKENDS)}.")
    pin_llvmpipe_cpu_caps()
    candidates = [backend] if backend else list(BACKENDS)
    failures = []
    for name in candidates:
        try:
            ctx = _CREATE[name]()
        except _BackendUnavailable as exc:
            failures.append(f"{name}: {exc}")
            continue
        ctx.extra = dict(ctx.extra or {}, backend=name)
        return make_current(ctx)
    raise GLUnavailableError(_INSTALL_HINT.format(details="; ".join(failures)))


class _BackendUnavailable(Exception):
    pass


def _create_egl() -> moderngl.Context:
    try:
        return moderngl.create_context(standalone=True, backend="egl", require=REQUIRED_GL_VERSION)
    except Exception as exc:  # glcontext reports a missing libEGL as a generic Exception
        raise _BackendUnavailable(str(exc).strip().splitlines()[0] if str(exc) else type(exc).__name__)


# OSMesa constants, from Mesa's include/GL/osmesa.h.
_OSMESA_FORMAT = 0x22
_OSMESA_RGBA = 0x1908
_OSMESA_DEPTH_BITS = 0x30
_OSMESA_STENCIL_BITS = 0x31
_OSMESA_ACCUM_BITS = 0x32
_OSMESA_PROFILE = 0x33
_OSMESA_CORE_PROFILE = 0x34
_OSMESA_CONTEXT_MAJOR_VERSION = 0x36
_OSMESA_CONTEXT_MINOR_VERSION = 0x37
_GL_UNSIGNED_BYTE = 0x1401


class _OSMesaLoader:
    """Owns one OSMesa context and hands moderngl its GL entry points."""

    def __init__(self, lib: ctypes.CDLL):
        self.lib = lib
        lib.OSMesaCreateContextAttribs.restype = ctypes.c_void_p
        lib.OSMesaCreateContextAttribs.argtypes = [ctypes.POINTER(ctypes.c_int), ctypes.c_void_p]
        lib.OSMesaMakeCurrent.restype = ctypes.c_ubyte
        lib.OSMesaMakeCurrent.argtypes = [
            ctypes.c_void_p, ctypes.c_void_p, ctypes.c_uint, ctypes.c_int, ctypes.c_int]
        lib.OSMesaGetProcAddress.restype = ctypes.c_void_p
        lib.OSMesaGetProcAddress.argtypes = [ctypes.c_char_p]
        lib.OSMesaDestroyContext.argtypes = [ctypes.c_void_p]
        attribs = [
            _OSMESA_FORMAT, _OSMESA_RGBA,
            _OSMESA_DEPTH_BITS, 24, _OSMESA_STENCIL_BITS, 8, _OSMESA_ACCUM_BITS, 0,
            _OSMESA_PROFILE, _OSMESA_CORE_PROFILE,
            _OSMESA_CONTEXT_MAJOR_VERSION, 3, _OSMESA_CONTEXT_MINOR_VERSION, 3,
            0,
        ]
        self.handle = lib.OSMesaCreateContextAttribs((ctypes.c_int * len(attribs))(*attribs), None)
        if not self.handle:
            raise _BackendUnavailable("OSMesaCreateContextAttribs refused a core 3.3 context")
        # OSMesa needs a bound colour buffer to make the context current; pbrlab renders
        # into framebuffer objects, so a 1x1 buffer is enough.
        self._buffer = (ctypes.c_ubyte * 4)()
        if not lib.OSMesaMakeCurrent(self.handle, self._buffer, _GL_UNSIGNED_BYTE, 1, 1):
            raise _BackendUnavailable("OSMesaMakeCurrent failed")

    def load_opengl_function(self, name: str) -> int:
        return self.lib.OSMesaGetProcAddress(name.encode("ascii")) or 0

    def release(self) -> None:
        if self.handle:
            self.lib.OSMesaDestroyContext(self.handle)
            self.handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc_info):
        return None


OSMESA_LIBRARY_ENV = "PBRLAB_OSMESA_LIBRARY"  # a libOSMesa path, to use another Mesa build


def _create_osmesa() -> moderngl.Context:
    path = (os.environ.get(OSMESA_LIBRARY_ENV)
            or ctypes.util.find_library("OSMesa") or "libOSMesa.so.8")
    try:
        lib = ctypes.CDLL(path)
    except OSError as exc:
        raise _BackendUnavailable(f"cannot load libOSMesa ({exc})")
    loader = _OSMesaLoader(lib)
    moderngl.init_context(loader=loader)
    ctx = moderngl.get_context()
    if ctx.version_code < REQUIRED_GL_VERSION:
        raise _BackendUnavailable(f"OSMesa gave GL {ctx.version_code}, pbrlab needs {REQUIRED_GL_VERSION}")
    ctx.extra = {"osmesa_loader": loader}  # keeps the OSMesa context and buffer alive
    return ctx


_CREATE = {"egl": _create_egl, "osmesa": _create_osmesa}

_shared: dict[str | None, moderngl.Context] = {}


def make_current(ctx: moderngl.Context) -> moderngl.Context:
    """Make ``ctx`` the thread's current GL context and return it.

    moderngl issues GL calls on whatever context is current; with EGL and OSMesa
    contexts in one process, each entry point (evaluator, renderer) calls this first.
    OSMesaMakeCurrent sets Mesa's shared GL dispatch without EGL knowing, so an EGL context
    that EGL still records as current would not be bound again (eglMakeCurrent of the current
    context does nothing) and its calls went to the OSMesa context: an EGL render after an
    OSMesa one read another context's textures (max difference 1.0; the Sample Renderer
    tests failed after the OSMesa pyrender tests in one pytest worker). After an OSMesa
    context, EGL's current context is released first, so binding it again is real.
    """
    global _last_current
    if _last_current is not None and _last_current() is not ctx \
            and (_last_current() is None or (_last_current().extra or {}).get("backend") == "osmesa") \
            and (ctx.extra or {}).get("backend") != "osmesa":
        _release_egl_context()
    ctx.mglo.__enter__()
    _last_current = weakref.ref(ctx)
    return ctx


_last_current = None  # a weak reference to the context make_current bound last


def _release_egl_context() -> None:
    """eglMakeCurrent(current display, no surfaces, no context), where EGL has a current context."""
    egl = ctypes.CDLL(os.environ.get("GLCONTEXT_LINUX_LIBEGL", "libEGL.so.1"))
    egl.eglGetCurrentDisplay.restype = ctypes.c_void_p
    display = egl.eglGetCurrentDisplay()
    if display:
        egl.eglMakeCurrent.restype = ctypes.c_uint
        egl.eglMakeCurrent.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
        egl.eglMakeCurrent(display, None, None, None)


def shared_context(backend: str | None = None) -> moderngl.Context:
    """One context per backend per process, created on first use (for the evaluator,
    the renderer, the CLI), made current on every call."""
    key = backend or default_backend()
    if key not in _shared:
        _shared[key] = create_context(key)
    return make_current(_shared[key])


_GL_FUNCTION_TYPES = {
    # name: (restype, argtypes), from the OpenGL 3.3 core specification
    "glTexImage2D": (None, [ctypes.c_uint, ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_int,
                            ctypes.c_int, ctypes.c_uint, ctypes.c_uint, ctypes.c_void_p]),
    "glPixelStorei": (None, [ctypes.c_uint, ctypes.c_int]),
    "glTexParameteri": (None, [ctypes.c_uint, ctypes.c_uint, ctypes.c_int]),
    "glGetMultisamplefv": (None, [ctypes.c_uint, ctypes.c_uint, ctypes.POINTER(ctypes.c_float)]),
    # the stencil buffer and its test (stencil_state.py)
    "glGenRenderbuffers": (None, [ctypes.c_int, ctypes.POINTER(ctypes.c_uint)]),
    "glDeleteRenderbuffers": (None, [ctypes.c_int, ctypes.POINTER(ctypes.c_uint)]),
    "glBindRenderbuffer": (None, [ctypes.c_uint, ctypes.c_uint]),
    "glRenderbufferStorageMultisample": (None, [ctypes.c_uint, ctypes.c_int, ctypes.c_uint, ctypes.c_int,
                                                ctypes.c_int]),
    "glBindFramebuffer": (None, [ctypes.c_uint, ctypes.c_uint]),
    "glFramebufferRenderbuffer": (None, [ctypes.c_uint, ctypes.c_uint, ctypes.c_uint, ctypes.c_uint]),
    "glCheckFramebufferStatus": (ctypes.c_uint, [ctypes.c_uint]),
    "glGetIntegerv": (None, [ctypes.c_uint, ctypes.POINTER(ctypes.c_int)]),
    "glStencilFuncSeparate": (None, [ctypes.c_uint, ctypes.c_uint, ctypes.c_int, ctypes.c_uint]),
    "glStencilOpSeparate": (None, [ctypes.c_uint, ctypes.c_uint, ctypes.c_uint, ctypes.c_uint]),
    "glStencilMask": (None, [ctypes.c_uint]),
    "glClearStencil": (None, [ctypes.c_int]),
    "glClear": (None, [ctypes.c_uint]),
    # OpenGL 4.2 core (ARB_internalformat_query): optional, gl_limits.sample_counts falls back
    "glGetInternalformativ": (None, [ctypes.c_uint, ctypes.c_uint, ctypes.c_uint, ctypes.c_int,
                                     ctypes.POINTER(ctypes.c_int)]),
}


def gl_function(ctx: moderngl.Context, name: str):
    """A GL entry point moderngl does not wrap, for ``ctx`` (which must be current), as a
    ctypes function: OSMesaGetProcAddress for OSMesa, eglGetProcAddress otherwise."""
    restype, argtypes = _GL_FUNCTION_TYPES[name]
    loader = (ctx.extra or {}).get("osmesa_loader")
    if loader is not None:
        address = loader.load_opengl_function(name)
    else:
        egl = ctypes.CDLL(os.environ.get("GLCONTEXT_LINUX_LIBEGL", "libEGL.so.1"))
        egl.eglGetProcAddress.restype = ctypes.c_void_p
        egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
        address = egl.eglGetProcAddress(name.encode("ascii"))
    if not address:
        raise PbrlabError(f"the GL driver does not provide {name}")
    return ctypes.CFUNCTYPE(restype, *argtypes)(address)


def context_info(ctx: moderngl.Context) -> dict:
    """Renderer facts for report headers and golden sidecars."""
    import OpenImageIO

    version = ctx.info["GL_VERSION"]
    mesa = re.search(r"Mesa ([0-9][0-9.\w-]*)", version)
    return {
        "backend": (ctx.extra or {}).get("backend", "unknown"),
        "GL_RENDERER": ctx.info["GL_RENDERER"],
        "GL_VERSION": version,
        "mesa": mesa.group(1) if mesa else None,
        "moderngl": moderngl.__version__,
        "openimageio": OpenImageIO.__version__,
        "llvmpipe_cpu_caps": os.environ.get("GALLIUM_OVERRIDE_CPU_CAPS", "native"),
    }
