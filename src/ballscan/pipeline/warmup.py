"""Loading the estimator's compiled kernels before its first ball.

Each stage's ``warm_up`` loads (from numba's on-disk cache) or compiles its
kernels on tiny inputs; the first call in a process otherwise carries it
(about 0.2 s from the cache, a minute or more of CPU to compile after an
install).  :func:`ensure_warm` does it once per process before any ball is
timed, so that no ball's ``run_time_s`` (and no stream ball's latency)
includes it; when kernels must be compiled it says so on stderr, with
progress, since the wait is otherwise silent.
"""

from __future__ import annotations

import contextlib
import gc
import importlib
import sys
import time
from dataclasses import dataclass

from .. import compiled
from ..parallel import collector_paused

__all__ = ["KERNEL_MODULES", "WarmUp", "ensure_warm", "warm_up"]

#: The estimator's kernel modules, in the order they are loaded.
KERNEL_MODULES = (
    "ballscan.model._forward_kernels",
    "ballscan.solve._fit_kernels",
    "ballscan.measure._detection_kernels",
    "ballscan.measure._edge_kernels",
    "ballscan.measure._shading_kernels",
    "ballscan.measure._flatfield_kernels",
    "ballscan.measure._defocus_kernels",
)

_warm = False


@dataclass(frozen=True)
class WarmUp:
    """What :func:`warm_up` did.

    Attributes
    ----------
    kernels : int
        Compiled kernels of the modules loaded.
    compiled : int
        Of those, the ones that had no code in the disk cache (compiled now).
    time_s : float
        Wall time of the warm-up, seconds.
    cache_dir : str or None
        Where the compiled code is kept (:func:`ballscan.compiled.cache_dir`).
    """

    kernels: int
    compiled: int
    time_s: float
    cache_dir: str | None


def _to_compile(names: tuple[str, ...]) -> int:
    """Kernels of ``names`` without code in the disk cache (imports the modules)."""
    mods = [importlib.import_module(n) for n in names]
    return sum(compiled.is_cached(k) is False for m in mods for k in compiled.KERNELS.get(m.__name__, ()))


def warm_up(modules: tuple[str, ...] = KERNEL_MODULES, *, show: bool | None = None) -> WarmUp:
    """Load (or compile) every kernel of ``modules`` now (default: the estimator's).

    Parameters
    ----------
    modules : tuple of str
        Kernel modules, each with a ``warm_up()``.
    show : bool or None
        Report the compilation on stderr (a message and, on a terminal, a
        progress bar).  None: only when some kernel must be compiled.
    """
    t0 = time.perf_counter()
    missing = _to_compile(modules)
    show = missing > 0 if show is None else show
    bar = _Progress(len(modules), missing, compiled.cache_dir(modules)) if show else None
    # Loading from the cache makes objects that live as long as the process:
    # collections meanwhile would walk them for nothing (about 50 ms for the
    # estimator).  A compilation makes much cyclic garbage (numba's
    # intermediate code): the collector runs then, and once more at the end.
    with collector_paused() if missing == 0 else contextlib.nullcontext():
        for name in modules:
            if bar is not None:
                bar.step(name)
            importlib.import_module(name).warm_up()
    if missing:
        gc.collect()
    if bar is not None:
        bar.close()
    global _warm
    _warm = _warm or set(KERNEL_MODULES) <= set(modules)
    n = sum(len(compiled.KERNELS.get(m, ())) for m in modules)
    return WarmUp(n, missing, time.perf_counter() - t0, compiled.cache_dir(modules))


def ensure_warm() -> None:
    """:func:`warm_up` once per process (nothing after the first call)."""
    if not _warm:
        warm_up()


class _Progress:
    """The compile message on stderr: a rich bar on a terminal, a line per module elsewhere."""

    def __init__(self, total: int, missing: int, cache: str | None) -> None:
        print(
            f"ballscan: compiling {missing} numerical kernels (first run after an install only; "
            f"about a minute of CPU, cached in {cache or 'memory only'}) ...",
            file=sys.stderr,
            flush=True,
        )
        self._n = 0
        self._total = total
        self._t0 = time.perf_counter()
        self._bar = None
        from rich.console import Console

        console = Console(stderr=True)
        if console.is_terminal:
            from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

            self._bar = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), console=console, transient=True)
            self._task = self._bar.add_task("compiling", total=total)
            self._bar.start()

    def step(self, name: str) -> None:
        short = name.removeprefix("ballscan.")
        if self._bar is not None:
            self._bar.update(self._task, completed=self._n, description=f"compiling {short}")
        else:
            print(f"  [{self._n + 1}/{self._total}] {short}", file=sys.stderr, flush=True)
        self._n += 1

    def close(self) -> None:
        if self._bar is not None:
            self._bar.update(self._task, completed=self._total)
            self._bar.stop()
        print(f"ballscan: kernels ready ({time.perf_counter() - self._t0:.0f} s)", file=sys.stderr, flush=True)
