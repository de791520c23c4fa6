"""The stencil buffer of a render target and the stencil test of one draw (moderngl wraps
neither: the GL entry points come from the context's loader, ``gl.gl_function``).

    buffer = DepthStencilBuffer(ctx, fbo, size, samples)   # fbo's depth: 24-bit depth, 8-bit stencil
    clear(ctx)                                              # every stencil value of the bound target 0
    apply(ctx, StencilState(ref=1, front=StencilFace("always", pass_op="replace"), ...))
    apply(ctx, None)                                        # the test off: GL's initial state

The test and its writes are OpenGL 3.3 core's, section 4.1.5 (Stencil Test): a fragment
passes where ``(ref & read_mask) compare (stencil & read_mask)``; ``fail_op`` updates the
stored value where the test fails, ``depth_fail_op`` where it passes and the depth test fails,
``pass_op`` where both pass, each write limited to the bits of ``write_mask``. Front- and
back-facing triangles have a state each (glStencilFuncSeparate, glStencilOpSeparate); which
face is which follows the context's front_face, as culling does. The names of ``compare`` and
of the operations are GL's, lower case (``lequal``, ``incr_wrap``).

``apply`` keeps the state it last set on each context and calls GL only when it changes: a
render without a stencil state (every scene but a Unity pass's Stencil block) makes no
stencil call at all, and its image is what it was before the buffer existed. The kept state
holds because this module is the only writer of a context's stencil state: moderngl (5.x) has
no stencil call, and no other pbrlab module makes one (grep glStencil, 0x0B90); the key is the
moderngl Context object, one per GL context (gl.create_context), so a context reused across
renders keeps its true state and a released one drops out. Code outside pbrlab that changes
the stencil state of pbrlab's context behind it must call ``forget(ctx)``. The state is kept
only once every call is made: a call that raises leaves it unknown, set in full next time.
The renderer turns the test off after its draws even when one raises (renderer._draw_objects),
so a refused pass does not leave a Stencil block's test on for the next user of the context
(the pyrender cross-check draws into a depth-stencil target without clearing the state).
"""

from __future__ import annotations

import ctypes
import weakref
from dataclasses import dataclass, field, replace

from . import gl
from ..foundation.errors import PbrlabError

# OpenGL 3.3 core enum values (glcorearb.h): StencilFunc and StencilOp (section 4.1.5), renderbuffers (4.4.2)
_COMPARE = {"never": 0x0200, "less": 0x0201, "equal": 0x0202, "lequal": 0x0203, "greater": 0x0204,
            "notequal": 0x0205, "gequal": 0x0206, "always": 0x0207}
_OPERATIONS = {"keep": 0x1E00, "zero": 0x0000, "replace": 0x1E01, "incr": 0x1E02, "decr": 0x1E03,
               "invert": 0x150A, "incr_wrap": 0x8507, "decr_wrap": 0x8508}
_GL_FRONT, _GL_BACK = 0x0404, 0x0405
_GL_STENCIL_TEST = 0x0B90
_GL_STENCIL_BUFFER_BIT = 0x00000400
_GL_FRAMEBUFFER, _GL_RENDERBUFFER = 0x8D40, 0x8D41
_GL_FRAMEBUFFER_BINDING = 0x8CA6
_GL_DEPTH_STENCIL_ATTACHMENT = 0x821A
_GL_DEPTH24_STENCIL8 = 0x88F0
_GL_FRAMEBUFFER_COMPLETE = 0x8CD5
STENCIL_BITS = 8  # GL_DEPTH24_STENCIL8: values 0..255, the masks' width
ALL_BITS = (1 << STENCIL_BITS) - 1


@dataclass(frozen=True)
class StencilFace:
    """The test and the writes of one facing: ``compare`` one of never, less, equal, lequal,
    greater, notequal, gequal, always; each operation one of keep, zero, replace, incr, decr,
    invert, incr_wrap, decr_wrap."""
    compare: str = "always"
    pass_op: str = "keep"
    fail_op: str = "keep"
    depth_fail_op: str = "keep"

    def __post_init__(self):
        if self.compare not in _COMPARE:
            raise PbrlabError(f"stencil compare {self.compare!r}: expected one of {', '.join(_COMPARE)}")
        for op in (self.pass_op, self.fail_op, self.depth_fail_op):
            if op not in _OPERATIONS:
                raise PbrlabError(f"stencil operation {op!r}: expected one of {', '.join(_OPERATIONS)}")


@dataclass(frozen=True)
class StencilState:
    """The stencil test on, with a reference value, masks (0..255) and a state per facing."""
    ref: int = 0
    read_mask: int = ALL_BITS
    write_mask: int = ALL_BITS
    front: StencilFace = field(default_factory=StencilFace)
    back: StencilFace = field(default_factory=StencilFace)

    def __post_init__(self):
        for name in ("ref", "read_mask", "write_mask"):
            if not 0 <= getattr(self, name) <= ALL_BITS:
                raise PbrlabError(f"stencil {name} {getattr(self, name)}: expected 0..{ALL_BITS}")

    def front_on_both_faces(self) -> "StencilState":
        """The front state for every triangle: a surface drawn through its bounding box's back
        faces (a ray-traced sphere) shows its front."""
        return replace(self, back=self.front)


class _ContextStencil:
    """The GL functions of one context and the state last set on it (None: the test off)."""

    def __init__(self, ctx):
        self.ctx, self.functions, self.state = ctx, {}, None

    def __getattr__(self, name):
        if name not in self.functions:
            self.functions[name] = gl.gl_function(self.ctx, name)
        return self.functions[name]


_per_context: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
_UNKNOWN = object()  # a state no StencilState equals: the next apply sets every value


def _of(ctx) -> _ContextStencil:
    if ctx not in _per_context:
        _per_context[ctx] = _ContextStencil(ctx)
    return _per_context[ctx]


def apply(ctx, state: StencilState | None) -> None:
    """The stencil test and writes of the draws that follow (``None``: the test off, GL's initial
    state: function always, reference 0, masks all ones, operations keep)."""
    current = _of(ctx)
    if state == current.state:
        return
    current.state = _UNKNOWN  # until every call below is made (a driver without one raises)
    if state is None:
        ctx.disable_direct(_GL_STENCIL_TEST)
    else:
        ctx.enable_direct(_GL_STENCIL_TEST)
    values = state or StencilState()  # GL's initial values (section 4.1.5, last paragraphs)
    for face, side in ((_GL_FRONT, values.front), (_GL_BACK, values.back)):
        current.glStencilFuncSeparate(face, _COMPARE[side.compare], values.ref, values.read_mask)
        current.glStencilOpSeparate(face, _OPERATIONS[side.fail_op], _OPERATIONS[side.depth_fail_op],
                                    _OPERATIONS[side.pass_op])
    current.glStencilMask(values.write_mask)
    current.state = state


def forget(ctx) -> None:
    """Drop the state kept for ``ctx``: the next ``apply`` sets every value (for code that
    changed the context's stencil state without ``apply``)."""
    _of(ctx).state = _UNKNOWN


def clear(ctx) -> None:
    """Every stencil value of the bound framebuffer 0 (its depth and colour untouched); the
    test off after it."""
    apply(ctx, None)  # the write mask all ones: glClear writes through it
    current = _of(ctx)
    current.glClearStencil(0)
    current.glClear(_GL_STENCIL_BUFFER_BIT)


class DepthStencilBuffer:
    """A GL_DEPTH24_STENCIL8 renderbuffer (``samples`` per pixel, 1 for none) attached as
    ``fbo``'s depth and stencil: the same 24-bit depth as moderngl's depth renderbuffer, and an
    8-bit stencil. The framebuffer bound before is bound again."""

    def __init__(self, ctx, fbo, size, samples: int = 1):
        self.ctx = ctx
        functions = _of(ctx)
        name = ctypes.c_uint(0)
        functions.glGenRenderbuffers(1, ctypes.byref(name))
        self.glo = name.value
        functions.glBindRenderbuffer(_GL_RENDERBUFFER, self.glo)
        # samples 0 is a single-sampled renderbuffer (OpenGL 3.3 core, section 4.4.2)
        functions.glRenderbufferStorageMultisample(_GL_RENDERBUFFER, samples if samples > 1 else 0,
                                                   _GL_DEPTH24_STENCIL8, int(size[0]), int(size[1]))
        functions.glBindRenderbuffer(_GL_RENDERBUFFER, 0)
        bound = ctypes.c_int(0)
        functions.glGetIntegerv(_GL_FRAMEBUFFER_BINDING, ctypes.byref(bound))
        functions.glBindFramebuffer(_GL_FRAMEBUFFER, fbo.glo)
        functions.glFramebufferRenderbuffer(_GL_FRAMEBUFFER, _GL_DEPTH_STENCIL_ATTACHMENT, _GL_RENDERBUFFER,
                                            self.glo)
        status = functions.glCheckFramebufferStatus(_GL_FRAMEBUFFER)
        functions.glBindFramebuffer(_GL_FRAMEBUFFER, bound.value)
        if status != _GL_FRAMEBUFFER_COMPLETE:
            self.release()
            raise PbrlabError(f"a {size[0]}x{size[1]} depth-stencil buffer with {samples} sample(s) per pixel "
                              f"leaves the framebuffer incomplete (status 0x{status:04X})")

    def release(self) -> None:
        if self.glo:
            _of(self.ctx).glDeleteRenderbuffers(1, ctypes.byref(ctypes.c_uint(self.glo)))
            self.glo = 0
