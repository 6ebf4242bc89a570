"""Output files that are whole or absent, one writer per output, and no writes through symlinks.

Every file ballscan writes (an image, a camera file, a truth or result JSON,
a CSV, a saved event) goes through :func:`atomic_path` or
:func:`atomic_write_bytes` / :func:`atomic_write_text`: the content is
written to a temporary name in the destination's folder, flushed to disk and
renamed over the destination, so a reader (or a rerun after a crash or
``kill -9``) sees the old file or the new one, never a part. The new file
keeps an existing file's permission bits, else gets what the umask gives.

A destination that is a symbolic link is refused with a one-line
:class:`OutputFileError` naming it (:func:`check_not_symlink`): a link
planted where an output goes would otherwise redirect the write. With
``force`` the link's target is replaced and the link itself kept.

:class:`OutputLock` holds an exclusive ``fcntl.flock`` on a lock file beside
an output for a run's lifetime, so that a second run on the same output is
refused with a clear message instead of interleaving its writes; the kernel
drops the lock when the process ends, however it ends.

Only the errors module and the standard library are imported here (the base
layer of the package).
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from .errors import BallscanError

__all__ = [
    "TEMP_MARK",
    "OutputFileError",
    "OutputLock",
    "atomic_path",
    "atomic_write_bytes",
    "atomic_write_text",
    "check_not_symlink",
    "remove_stale_temporaries",
]

#: Part of every temporary file's name (``.NAME.TEMP_MARK.XXXX.SUFFIX``): what a crash can leave behind.
TEMP_MARK = "partial"


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
        raise OutputFileError(str(p), f"is a symbolic link (to {os.readlink(p)}); refusing to write through it (remove it, or give --force)")
    return Path(os.path.realpath(p))


def _fsync_dir(folder: Path) -> None:
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _mode_of(target: Path) -> int:
    """The permission bits for the new file: the old file's, else what the umask gives a new file."""
    try:
        return target.stat().st_mode & 0o7777
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str], *, force: bool = False) -> Iterator[Path]:
    """A temporary path beside ``path`` (same suffix) that becomes ``path`` when the block ends without an error.

    Writers that choose the format by the file's extension (images, ``.npz``)
    write to the yielded path; it is synced and renamed over ``path``. On an
    error the temporary file is removed and ``path`` is left as it was.

    Parameters
    ----------
    path : str or path-like
        Destination; its folder must exist.
    force : bool
        Write through a symbolic link to its target.

    Raises
    ------
    OutputFileError
        A symbolic link without ``force``, a missing folder, or an OS error
        (permissions, full disk), naming the path.
    """
    target = check_not_symlink(path, force)
    try:
        fd, tmp_name = tempfile.mkstemp(prefix=f".{target.name}.{TEMP_MARK}.", suffix=target.suffix, dir=target.parent)
    except OSError as exc:
        raise OutputFileError(str(path), f"cannot write ({exc.strerror or type(exc).__name__})") from None
    os.close(fd)
    tmp = Path(tmp_name)
    try:
        yield tmp
        with open(tmp, "rb+") as fh:
            os.fsync(fh.fileno())
        os.chmod(tmp, _mode_of(target))
        os.replace(tmp, target)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            tmp.unlink()
        if isinstance(exc, OSError) and not isinstance(exc, BallscanError):
            raise OutputFileError(str(path), f"cannot write ({exc.strerror or type(exc).__name__})") from None
        raise
    _fsync_dir(target.parent)


def atomic_write_bytes(path: str | os.PathLike[str], data: bytes, *, force: bool = False) -> Path:
    """Write ``data`` to ``path`` whole or not at all (see :func:`atomic_path`); return the file written.

    With ``force`` and ``path`` a symbolic link, the file written is the link's target.
    """
    with atomic_path(path, force=force) as tmp:
        tmp.write_bytes(data)
    return check_not_symlink(path, True)


def atomic_write_text(path: str | os.PathLike[str], text: str, *, force: bool = False) -> Path:
    """Write ``text`` (UTF-8) to ``path`` whole or not at all; return the file written."""
    return atomic_write_bytes(path, text.encode("utf-8"), force=force)


def remove_stale_temporaries(folder: str | os.PathLike[str]) -> list[Path]:
    """Remove the temporary files an interrupted write left in ``folder``; return them."""
    d = Path(folder)
    if not d.is_dir():
        return []
    gone = []
    for q in d.glob(f".*.{TEMP_MARK}.*"):
        if q.is_file() and not q.is_symlink():
            with contextlib.suppress(OSError):
                q.unlink()
                gone.append(q)
    return gone


class OutputLock:
    """An exclusive lock on an output for this process's lifetime (``fcntl.flock`` on ``LOCK_PATH``).

    Parameters
    ----------
    lock_path : path
        The lock file (created if missing, left in place: the lock is the
        kernel's, not the file's existence).
    what : str
        The output named in the refusal.

    Raises
    ------
    BallscanError
        From :meth:`acquire` when another process holds the lock.
    """

    def __init__(self, lock_path: str | os.PathLike[str], what: str) -> None:
        self.path = Path(lock_path)
        self.what = what
        self._fd: int | None = None

    def acquire(self) -> "OutputLock":
        import fcntl

        if self.path.is_symlink():
            raise BallscanError(f"{self.path}: the lock file is a symbolic link; remove it")
        self.path.parent.mkdir(parents=True, exist_ok=True)
        fd = os.open(self.path, os.O_RDWR | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0), 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            holder = os.pread(fd, 32, 0).decode("ascii", "replace").strip() or "?"
            os.close(fd)
            raise BallscanError(f"{self.what}: another ballscan run (pid {holder}) is writing it (lock {self.path}); wait for it or give another output") from None
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
        self._fd = fd
        return self

    def release(self) -> None:
        fd, self._fd = self._fd, None
        if fd is not None:
            os.close(fd)  # closing the descriptor drops the flock

    def __enter__(self) -> "OutputLock":
        return self.acquire()

    def __exit__(self, *exc: object) -> None:
        self.release()
