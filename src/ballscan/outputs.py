"""Writing output files safely: never through a symlink (unless forced), always whole.

Every file ballscan writes (an image, a camera file, a truth or result JSON,
a CSV) goes through :func:`atomic_write_bytes` or :func:`atomic_write_text`:
the content is written to a temporary file in the same folder, flushed to
disk and renamed over the destination, so a reader (or a rerun after a
crash) sees the old file or the new one, never half of one.

A destination that is a symbolic link is refused with a one-line
:class:`OutputFileError` naming it: a link planted where an output goes
(a truth file linked to another file, a CSV linked to a log) would
otherwise redirect the write.  ``force=True`` writes through the link: the
link's target is replaced (atomically), the link itself is kept.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .errors import BallscanError

__all__ = ["OutputFileError", "atomic_write_bytes", "atomic_write_text", "check_not_symlink"]


class OutputFileError(BallscanError, OSError):
    """An output file cannot (or must not) be written; the message names it."""

    def __init__(self, path: str, problem: str):
        super().__init__(f"{path}: {problem}")
        self.path = path
        self.problem = problem


def check_not_symlink(path: str | os.PathLike[str], force: bool = False) -> Path:
    """The path to write for ``path``: refused if it is a symbolic link, unless ``force``.

    Parameters
    ----------
    path : str or path-like
        The destination as the user named it.
    force : bool
        Write through a link: the returned path is the link's final target
        (a dangling link's target is created).

    Returns
    -------
    pathlib.Path
        ``path`` itself, or with ``force`` the resolved target of a link.

    Raises
    ------
    OutputFileError
        ``path`` is a symbolic link and ``force`` is false.
    """
    p = Path(os.fspath(path))
    if not p.is_symlink():
        return p
    if not force:
        raise OutputFileError(str(p), "is a symbolic link; refusing to write through it (remove it, or give --force)")
    return Path(os.path.realpath(p))


def atomic_write_bytes(path: str | os.PathLike[str], data: bytes, *, force: bool = False) -> Path:
    """Write ``data`` to ``path`` whole or not at all (a temporary file renamed over it).

    Parameters
    ----------
    path : str or path-like
        Destination; its folder must exist.  A symbolic link is refused
        unless ``force`` (see :func:`check_not_symlink`).
    data : bytes
        The file's complete content.
    force : bool
        Write through a symbolic link to its target.

    Returns
    -------
    pathlib.Path
        The file written (the link's target with ``force``).

    Raises
    ------
    OutputFileError
        A symbolic link without ``force``, a missing folder, or an OS error
        (permissions, full disk), naming the path.
    """
    target = check_not_symlink(path, force)
    folder = target.parent
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".part", dir=folder)
    except OSError as exc:
        raise OutputFileError(str(path), f"cannot write ({exc.strerror or type(exc).__name__})") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        mode = _mode_of(target)
        os.chmod(tmp, mode)
        os.replace(tmp, target)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        if isinstance(exc, OSError):
            raise OutputFileError(str(path), f"cannot write ({exc.strerror or type(exc).__name__})") from None
        raise
    return target


def atomic_write_text(path: str | os.PathLike[str], text: str, *, force: bool = False) -> Path:
    """Write ``text`` (UTF-8) to ``path`` as :func:`atomic_write_bytes` does."""
    return atomic_write_bytes(path, text.encode("utf-8"), force=force)


def _mode_of(target: Path) -> int:
    """The permission bits for the new file: the old file's, else what the umask gives a new file."""
    try:
        return target.stat().st_mode & 0o7777
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask
