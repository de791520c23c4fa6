"""The folder rule for files a model names: resolve the name, every symbolic link on the way
included, and read it only where the model lies, unless the user allowed reading outside.

    real = safe_paths.inside(folder, "textures/albedo.png", referrer="model.gltf: images[0]")

Every reader of a file that another file names goes through ``inside`` (glTF buffers and images,
a JSON scene's textures, meshes, environments, surfaces and glTF files, Unity texture properties,
the ``#include`` files of surfaces and Unity shaders). Models arrive as archives, and archives
carry symbolic links: a check of the written path alone (no ``..``, not absolute) passes
``albedo.png -> ../secret/albedo.png``. So the check is on the resolved path
(``os.path.realpath``): it must lie inside the resolved folder.

The folder (``region``):

* ``climb=False`` (glTF): the referring file's folder, whatever the written path says; a written
  ``..`` or absolute path is refused by the glTF reader itself before it gets here.
* ``climb=True`` (a JSON scene, a shader's ``#include``): a person wrote the path, and ``..`` in
  it is a visible choice: the folder widens to where the written path climbs
  (``../assets/sky.exr`` from ``scenes/a/`` gives ``scenes/``; an absolute path names its file,
  so the folder is the file system's root). Symbolic links on the way must still stay in it.

``allow=True`` (``--allow-outside``; the default is ``allowing_outside``'s setting, off) reads
the file wherever the links lead. A refusal is an ``OutsideFolderError`` naming the file that
referred to it, the link, where the link leads, and the flag.
"""

from __future__ import annotations

import contextlib
import contextvars
import os
from pathlib import Path
from typing import Iterator

from .errors import PbrlabError

FLAG = "--allow-outside"
_ALLOWED = contextvars.ContextVar("pbrlab_allow_outside", default=False)


class OutsideFolderError(PbrlabError):
    """A named file resolves (through a symbolic link) outside the folder it may be read from.
    ``reason`` is the message without the referrer, for readers that prefix their own."""

    def __init__(self, referrer: str, reason: str):
        super().__init__(f"{referrer}: {reason}" if referrer else reason)
        self.reason = reason


@contextlib.contextmanager
def allowing_outside(allow: bool = True) -> Iterator[None]:
    """Within the block, ``inside`` reads files outside their folder when ``allow`` (the CLI's
    ``--allow-outside``, for readers deep below the command that take no flag of their own)."""
    token = _ALLOWED.set(bool(allow))
    try:
        yield
    finally:
        _ALLOWED.reset(token)


def outside_allowed() -> bool:
    return _ALLOWED.get()


_OWN_LINK_FOLDERS: list[str] = []


def trust_links_in(folder: str | Path) -> None:
    """Follow every link in ``folder``, a folder of pbrlab's own whose links pbrlab made
    (gpu.programs: a plain-named link to a surface whose name an ``#include`` cannot carry)."""
    _OWN_LINK_FOLDERS.append(os.path.abspath(folder))


def reading_rules() -> tuple:
    """What ``inside`` answers by besides the file system (whether reading outside is allowed,
    the folders whose links are followed): part of the key of a cached answer of it."""
    return outside_allowed(), tuple(_OWN_LINK_FOLDERS)


def is_within(path: str | Path, folder: str | Path) -> bool:
    """Whether ``path`` is ``folder`` or lies below it (both already resolved)."""
    path, folder = os.fspath(path), os.fspath(folder)
    try:
        return os.path.commonpath([path, folder]) == folder
    except ValueError:  # a relative and an absolute path, or two drives
        return False


def region(base: Path, written: str, climb: bool) -> Path:
    """The folder, as written (not resolved), that ``written`` (relative to ``base``) may be read
    from: ``base``, or with ``climb`` the folder its leading ``..`` reach (the root for an
    absolute path)."""
    base = Path(os.path.abspath(base))
    if not climb:
        return base
    lexical = Path(os.path.normpath(base / written))
    return Path(os.path.commonpath([base, lexical.parent]))


def _first_link_out(folder: Path, lexical: Path, real_folder: str) -> tuple[Path, str] | None:
    """The first component of ``lexical`` below ``folder`` that is a symbolic link resolving
    outside ``real_folder``, with what it says (its readlink text); None when there is none."""
    try:
        parts = lexical.relative_to(folder).parts
    except ValueError:
        return None
    current = folder
    for part in parts:
        current = current / part
        if os.path.islink(current) and not is_within(os.path.realpath(current), real_folder):
            try:
                return current, os.readlink(current)
            except OSError:
                return current, "?"
    return None


def inside(base: str | Path, written: str | os.PathLike, referrer: str = "", *, climb: bool = False,
           allow: bool | None = None) -> Path:
    """The resolved path of ``written`` (relative to ``base``, or absolute), refused with an
    ``OutsideFolderError`` when it lies outside its folder (``region``) and reading outside is not
    allowed (``allow``; None: as ``allowing_outside`` says). A file that does not exist is returned
    resolved as far as it goes: the caller says it is missing."""
    allow = outside_allowed() if allow is None else allow
    base = Path(base)
    lexical = Path(os.path.abspath(os.path.normpath(base / written)))
    real = Path(os.path.realpath(base / written))
    if allow or any(is_within(os.path.abspath(base), own) for own in _OWN_LINK_FOLDERS):
        return real
    folder = region(base, os.fspath(written), climb)
    real_folder = os.path.realpath(folder)
    if is_within(real, real_folder):
        return real

    def shown(p) -> str:  # as the user named things: relative when the base was given relative
        return os.fspath(p) if base.is_absolute() else os.path.relpath(p)

    link = _first_link_out(folder, lexical, real_folder)
    if link is None:  # the written path itself leaves the folder (a reader without a written-path check)
        reason = f"{written} lies outside {shown(folder)} (it resolves to {real})"
    else:
        prefix = "" if link[0] == lexical else f"{written}: "  # the named file itself is the link
        reason = (f"{prefix}{shown(link[0])} is a symbolic link to {link[1]}, which leads outside "
                  f"{shown(folder)} (to {real})")
    raise OutsideFolderError(referrer, f"{reason}; files are read only inside the model's folder "
                                       f"(pass {FLAG} to read it)")


def named_file(path: str | Path, allow: bool | None = None) -> Path:
    """A model file named on the command line (a scene, a glTF file), checked like the files it
    names: when it is a symbolic link, its target must lie in the folder the link is in (a
    ``scene.gltf`` link in an unpacked archive that points at another folder is refused).
    Returns ``path`` as given: the files it names resolve against the folder it was named in."""
    path = Path(path)
    inside(path.parent, path.name, allow=allow)
    return path
