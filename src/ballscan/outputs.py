"""Output files that are whole or absent, one writer per output, and no writes through symlinks.

A file is written to a temporary name in its own folder, flushed to disk and
renamed over the target (:func:`atomic_write_bytes`, :func:`atomic_path`): a
crash or ``kill -9`` leaves either the old file or the new one, never a
part. A rename replaces a symbolic link itself, never its target; an output
that is a symbolic link is refused unless forced (:func:`check_not_symlink`).
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
    "OutputLock",
    "atomic_path",
    "atomic_write_bytes",
    "atomic_write_text",
    "check_not_symlink",
    "remove_stale_temporaries",
]

#: Part of every temporary file's name (``.NAME.TEMP_MARK.XXXX.SUFFIX``): what a crash can leave behind.
TEMP_MARK = "partial"


def check_not_symlink(path: str | os.PathLike[str], force: bool = False) -> None:
    """Refuse an output path that is a symbolic link (unless ``force``).

    Raises
    ------
    BallscanError
        Naming the path and its target.
    """
    p = Path(path)
    if not force and p.is_symlink():
        raise BallscanError(f"{p}: is a symbolic link (to {os.readlink(p)}); refusing to write through it (give --force to write to its target)")


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


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str], *, force: bool = False) -> Iterator[Path]:
    """A temporary path beside ``path`` (same suffix) that becomes ``path`` when the block ends without an error.

    Writers that choose the format by the file's extension (images, ``.npz``)
    write to the yielded path; it is synced and renamed over ``path``. On an
    error the temporary file is removed and ``path`` is left as it was.
    With ``force`` and ``path`` a symbolic link, its target is replaced.
    """
    p = Path(path)
    check_not_symlink(p, force)
    if force and p.is_symlink():
        p = p.resolve()
    p.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{p.name}.{TEMP_MARK}.", suffix=p.suffix, dir=p.parent)
    os.close(fd)
    tmp = Path(tmp_name)
    try:
        yield tmp
        with open(tmp, "rb+") as fh:
            os.fsync(fh.fileno())
        os.replace(tmp, p)
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink()
        raise
    _fsync_dir(p.parent)


def atomic_write_bytes(path: str | os.PathLike[str], data: bytes, *, force: bool = False) -> None:
    """Write ``data`` to ``path`` whole or not at all (temporary file, fsync, rename)."""
    with atomic_path(path, force=force) as tmp:
        tmp.write_bytes(data)


def atomic_write_text(path: str | os.PathLike[str], text: str, *, force: bool = False) -> None:
    """Write ``text`` (UTF-8) to ``path`` whole or not at all."""
    atomic_write_bytes(path, text.encode("utf-8"), force=force)


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
