"""The one exception type for user mistakes and missing system pieces.

Anything raised as a ``PbrlabError`` is a message for a person: the CLI prints it
without a traceback and exits non-zero. Everything else is a bug in pbrlab and keeps
its traceback.
"""


class PbrlabError(Exception):
    """A problem the user can fix: bad input, a missing file or package, a shader error."""


class GLUnavailableError(PbrlabError):
    """No OpenGL implementation could be loaded."""


class ShaderCompileError(PbrlabError):
    """GLSL failed to compile or link; the message names the original file and line."""


class SceneError(PbrlabError):
    """A scene file is malformed; the message names the offending field."""


class InconsistentCountError(PbrlabError):
    """The bench's instruction counts failed their own check (a negative count, two counts
    of one kernel that disagree, or a draw with no instructions); the message lists each."""


class LoopLimitWarning(UserWarning):
    """A shader loop asks for more iterations than the renderer runs (llvmpipe stops every
    loop after 65535 iterations and carries on with the partial result)."""
