"""The small text files a user hands ballscan (camera, rig and recipe files), read bounded and decoded, with one-line errors."""

from __future__ import annotations

from pathlib import Path
from typing import Callable

__all__ = ["read_small_text"]


def read_small_text(path: Path, max_bytes: int, kind: str, error: Callable[[str, str], Exception]) -> str:
    """The UTF-8 text of ``path``, reading at most ``max_bytes + 1`` bytes (a FIFO or ``/dev/zero`` too).

    Parameters
    ----------
    path : Path
        The file.
    max_bytes : int
        The largest file accepted, bytes.
    kind : str
        What the file should be (``"camera"``, ``"rig"``, ``"recipe"``), for the messages.
    error : callable
        ``error(source, problem)``: the exception raised (its message names the file).

    Raises
    ------
    Exception
        ``error``'s: not found, unreadable (a folder too), over ``max_bytes``, or not UTF-8 text.
    """
    try:
        with open(path, "rb") as fh:
            data = fh.read(max_bytes + 1)
    except FileNotFoundError:
        raise error(str(path), "file not found") from None
    except OSError as exc:
        raise error(str(path), f"cannot read ({exc.strerror or exc.__class__.__name__})") from None
    if len(data) > max_bytes:
        raise error(str(path), f"over {max_bytes} bytes: not a {kind} file")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise error(str(path), f"not a {kind} file (not UTF-8 text)") from None
