"""Exceptions that carry a one-line, user-facing message.

Every error that reaches the command line is a :class:`BallscanError`; the CLI
prints its message on one line and exits non-zero, never a traceback.
"""

from __future__ import annotations


class BallscanError(Exception):
    """Base class: the message is a complete one-line explanation."""


class InputFileError(BallscanError, ValueError):
    """A file given to ballscan cannot be used: the message is ``"{source}: {problem}"``."""

    def __init__(self, source: str, problem: str):
        super().__init__(f"{source}: {problem}")
        self.source = source
        self.problem = problem


class CameraFileError(InputFileError):
    """A camera TOML file is missing, malformed or physically invalid; ``key`` names the offending key, if one."""

    def __init__(self, source: str, problem: str, key: str | None = None):
        super().__init__(f"{source}: key '{key}'" if key else source, problem)
        self.source = source
        self.key = key


class RecipeFileError(InputFileError):
    """A recipe file (the estimator's settings) is missing, malformed or out of range."""


class ImageFileError(InputFileError):
    """An image file cannot be used as a line-scan image."""


class GeometryError(BallscanError, ValueError):
    """A geometric configuration the model cannot represent (e.g. camera inside the ball)."""


def interrupt_behind(exc: BaseException) -> BaseException | None:
    """The interrupt (a ``BaseException`` that is no ``Exception``) in ``exc``'s chain of causes, if any.

    A signal handler that raises while compiled code runs (a numba kernel)
    surfaces when the kernel returns, as the ``SystemError`` "returned a
    result with an exception set" caused by the handler's exception; the
    error is that interrupt, not a failure of the work.
    """
    seen: set[int] = set()
    inner: BaseException | None = exc
    while inner is not None and id(inner) not in seen:
        if not isinstance(inner, Exception):
            return inner
        seen.add(id(inner))
        inner = inner.__cause__ or inner.__context__
    return None
