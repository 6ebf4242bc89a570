"""How the commands end on a signal: SIGINT, SIGTERM and SIGHUP alike, with an exit status that names it.

A service manager or ``docker stop`` sends SIGTERM, a closed terminal
SIGHUP, Ctrl-C SIGINT; each ends a command the same way:

- ``watch`` (:func:`stop_signals` with ``graceful=True``): the signal only
  asks the stream to stop; the source ends after its complete lines, every
  ball that has passed is measured and printed, the ball in view is measured
  flagged as cut, a one-line summary goes to stderr and the exit status is
  ``128 + signum`` (130, 143, 129). A second signal stops at once.
- ``batch``, ``experiment`` and every other command (``graceful=False``,
  :func:`ballscan.cli.app.main` installs it around each command): the
  signal raises :class:`Stopped` in the main thread; the workers
  are killed, the rows already written stay (a rerun does the rest), and the
  exit status is ``128 + signum``.

:class:`ExitStatus` carries a command's exit status and last message to
:func:`ballscan.cli.app.main` (click swallows ``typer.Exit`` codes when it
does not exit the process itself).
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator

__all__ = ["SIGNALS", "ExitStatus", "StopRequest", "Stopped", "stop_signals"]

#: The signals that end a command gracefully.
SIGNALS = tuple(s for s in (getattr(signal, "SIGINT", None), getattr(signal, "SIGTERM", None), getattr(signal, "SIGHUP", None)) if s is not None)


class ExitStatus(Exception):
    """End the command with ``code``, printing ``message`` (if any) on stderr."""

    def __init__(self, code: int, message: str = "") -> None:
        super().__init__(message)
        self.code = int(code)
        self.message = message


class Stopped(BaseException):
    """The command was stopped by signal ``signum`` (exit status ``128 + signum``).

    A ``BaseException`` as ``KeyboardInterrupt`` is, but not one: the CLI
    framework turns a ``KeyboardInterrupt`` into its own exit status (130,
    whatever the signal), and this one must reach
    :func:`ballscan.cli.app.main` with its signal.
    """

    def __init__(self, signum: int) -> None:
        super().__init__(signal.Signals(signum).name)
        self.signum = int(signum)

    @property
    def exit_code(self) -> int:
        return 128 + self.signum


class StopRequest:
    """A stop asked for by a signal: :meth:`is_set` is what sources and loops poll."""

    def __init__(self) -> None:
        self.signum: int | None = None
        self._event = threading.Event()

    def is_set(self) -> bool:
        """True once a stop signal arrived."""
        return self._event.is_set()

    def set(self, signum: int) -> None:
        if self.signum is None:
            self.signum = int(signum)
        self._event.set()

    @property
    def name(self) -> str:
        return "" if self.signum is None else signal.Signals(self.signum).name

    @property
    def exit_code(self) -> int:
        """``128 + signum`` once stopped, else 0."""
        return 0 if self.signum is None else 128 + self.signum


@contextlib.contextmanager
def stop_signals(graceful: bool) -> Iterator[StopRequest]:
    """Handle SIGINT, SIGTERM and SIGHUP while the block runs (the previous handlers restored after).

    Parameters
    ----------
    graceful : bool
        True: the first signal sets the yielded request (the block stops by
        itself), a second raises :class:`Stopped`. False: every signal raises
        :class:`Stopped` at once.

    Outside the main thread (where Python cannot handle signals) nothing is
    installed and the request is never set.
    """
    request = StopRequest()
    if threading.current_thread() is not threading.main_thread():
        yield request
        return

    def handler(signum: int, frame: object) -> None:
        if graceful and not request.is_set():
            request.set(signum)
            return
        request.set(signum)
        raise Stopped(signum)

    previous = {s: signal.signal(s, handler) for s in SIGNALS}
    try:
        yield request
    finally:
        for s, h in previous.items():
            signal.signal(s, h if h is not None else signal.SIG_DFL)
