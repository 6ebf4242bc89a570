"""Run one task function over many items: in this process, on local processes or on a Dask cluster.

:class:`TaskExecutor` is the one executor of the package (batches of
recordings, Monte-Carlo experiments). Its :meth:`~TaskExecutor.map` yields a
:class:`TaskResult` per item as the items finish (in completion order), with
one error policy everywhere:

- an ``Exception`` raised by the task becomes a failed result carrying the
  item and a one-line message; the other items still run and the caller
  decides what a failure means;
- ``KeyboardInterrupt`` (or any exception in the caller's loop) stops
  everything: the items not started are dropped and the workers stop as
  soon as their running task ends (a Ctrl-C in a terminal reaches them too).

Where the tasks run:

``scheduler="tcp://host:port"``
    a Dask distributed cluster (``pip install "dask[distributed]"``, imported
    only then), connected to within :data:`DASK_CONNECT_TIMEOUT_S`;
``jobs == 1`` (or a first map of a single item)
    this process, one item after the other;
``jobs > 1`` (or ``-1``: every core available)
    up to that many local processes (no more than the items left), each
    limited to one thread of BLAS/OpenMP/numba: the parallelism is across
    items. The first map of a block runs its items here, one after the other
    (after ``warm_up``), until the items left would take longer serially than
    with the workers plus their start-up (:data:`FORK_START_S` or
    :data:`SPAWN_START_S` per worker, against the mean time of the items run
    so far): too little work never pays for a process. The workers are then
    forked from this warm process (POSIX, when no other Python thread runs
    here), so they start with its imports and loaded kernels and the warm-up
    runs once in all; elsewhere they are fresh loky processes (bundled with
    joblib) that each run ``warm_up`` first. :attr:`TaskExecutor.start_method`
    tells which.

The worker processes serve every later map of a ``with TaskExecutor(...)``
block; leaving the block normally lets them finish and shuts them down,
leaving it on an error or an interrupt (Ctrl-C, or SIGTERM/SIGHUP turned into
one) kills them at once, so no worker outlives the block. A local worker also
watches its parent (:func:`worker_start`): when the parent dies without
shutting them down (``kill -9``), the workers end within :data:`PARENT_POLL_S`
seconds instead of finishing their queue. The ``warm_up`` callable (e.g.
loading compiled kernels) runs before the first task in this process, in each
fresh (loky) worker, and on every worker connected at the first map for Dask;
it only saves time, a task must not depend on it for its result. A worker
moves what it holds once warm out of the garbage collector's reach
(``gc.freeze``): its collections never walk the loaded modules and kernels
again, nor copy the pages a forked worker shares with its parent by touching
them.

Only the errors module and third-party libraries are imported here (the
base layer of the package).
"""

from __future__ import annotations

import contextlib
import gc
import os
import signal
import threading
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import as_completed
from dataclasses import dataclass
from typing import Any, Generic, TypeVar

from .errors import BallscanError, interrupt_behind

__all__ = ["DASK_CONNECT_TIMEOUT_S", "FORK_START_S", "PARENT_POLL_S", "SPAWN_START_S", "TaskResult", "TaskExecutor", "run_tasks", "available_cores", "can_fork", "collector_paused", "reuse_freed_memory", "start_forked", "worker_start"]

T = TypeVar("T")
R = TypeVar("R")

#: Seconds to wait for a Dask scheduler to answer before giving up.
DASK_CONNECT_TIMEOUT_S = 20.0

#: Seconds between a local worker's checks that its parent process is alive.
PARENT_POLL_S = 0.2

#: Seconds a worker forked from a warm process costs before its first task
#: (the fork of a process holding the estimator's loaded kernels, the thread
#: limits and the parent watch), rounded up from its measured cost
#: (docs/benchmarks.md).
FORK_START_S = 0.05

#: Seconds a fresh worker costs before its first task: importing the package
#: and loading its compiled kernels, rounded up from their measured cost.
SPAWN_START_S = 1.5

#: Thread-count variables of the numerical libraries, set to 1 in local workers
#: (several processes on one machine: one thread each, no oversubscription).
_ONE_THREAD_ENV = {
    name: "1"
    for name in (
        "OMP_NUM_THREADS",
        "OPENBLAS_NUM_THREADS",
        "MKL_NUM_THREADS",
        "BLIS_NUM_THREADS",
        "VECLIB_MAXIMUM_THREADS",
        "NUMEXPR_NUM_THREADS",
        "NUMBA_NUM_THREADS",
    )
}


@dataclass(frozen=True)
class TaskResult(Generic[T, R]):
    """The outcome of one item.

    Attributes
    ----------
    item
        The item the task was called with.
    value
        What the task returned; None when it failed.
    error : str or None
        ``"ExceptionType: message"`` on one line when the task raised, else None.
    """

    item: T
    value: R | None = None
    error: str | None = None

    @property
    def ok(self) -> bool:
        """True when the task returned."""
        return self.error is None


def available_cores() -> int:
    """CPU cores this process may run on (at least 1)."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return max(1, os.cpu_count() or 1)


def _watch_parent(parent_pid: int) -> None:
    """End this process (status 1) as soon as its parent is no longer ``parent_pid``."""
    while os.getppid() == parent_pid:
        time.sleep(PARENT_POLL_S)
    os._exit(1)


@contextlib.contextmanager
def collector_paused() -> Iterator[None]:
    """The cyclic garbage collector off within the block (its state before restored after).

    Loading compiled kernels makes many objects that live as long as the
    process; each collection that runs meanwhile walks all those made so
    far, for nothing.  Garbage without cycles is freed at once all the same.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


#: glibc's ``mallopt`` parameters (malloc.h): M_TRIM_THRESHOLD, M_MMAP_THRESHOLD.
_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3


def reuse_freed_memory(mmap_threshold_bytes: int = 16 << 20, trim_threshold_bytes: int = 64 << 20) -> bool:
    """Let this process's large temporary arrays reuse freed memory instead of fresh pages (glibc's allocator; elsewhere nothing).

    By default glibc maps a block above 128 KiB to 32 MiB (the threshold
    grows with the blocks freed) straight from the kernel and returns it on
    ``free``, and gives the top of its heap back beyond twice that: each
    of an image's working arrays (a 300 x 2048 float64 array is 4.9 MB) is
    then new memory, which the kernel zero-fills page by page on first touch
    (docs/benchmarks.md has the page faults and time it costs a batch).
    Blocks below ``mmap_threshold_bytes`` come from the heap, and up to
    ``trim_threshold_bytes`` of freed heap is kept: the next image's arrays
    reuse it.  The process's peak memory is unchanged; what it holds after a
    peak stays mapped up to ``trim_threshold_bytes``.  A process-wide
    setting: taken by the ``ballscan`` program's own process
    (:func:`ballscan.cli.app.run`) and by every local worker
    (:func:`worker_start`), never by a library caller's process.  True where
    the allocator took both settings.
    """
    import ctypes

    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):  # not glibc (macOS, Windows)
        return False
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    return bool(mallopt(_M_MMAP_THRESHOLD, int(mmap_threshold_bytes))) and bool(mallopt(_M_TRIM_THRESHOLD, int(trim_threshold_bytes)))


def worker_start(warm_up: Callable[[], Any] | None = None) -> None:
    """The initializer of a local worker process: watch the parent, then run ``warm_up``.

    A daemon thread polls the parent's pid every :data:`PARENT_POLL_S`
    seconds; when the parent has died (the worker was re-parented) the worker
    exits at once, whatever task it is running (Linux's ``PR_SET_PDEATHSIG``
    is not used: it fires when the *thread* that started the worker ends,
    which for a pool's own threads is not the parent's death).
    """
    parent = os.getppid()
    if parent == 1:
        os._exit(1)  # the parent died before this worker started
    reuse_freed_memory()  # a worker measures item after item
    threading.Thread(target=_watch_parent, args=(parent,), name="ballscan-parent-watch", daemon=True).start()
    if warm_up is not None:
        warm_up()
        gc.freeze()  # what this worker loaded is never walked again by its collections


def _forked_worker_start() -> None:
    """The initializer of a worker forked from a warm process: default signal handling, one thread, parent watch.

    The fork inherits the parent's signal handlers (a command's stop
    handlers) and its thread pools' sizes; a worker gets Python's defaults
    (SIGINT raises ``KeyboardInterrupt``, SIGTERM/SIGHUP end it) and one
    thread per native library (``threadpoolctl``), as a fresh worker does
    through its environment.
    """
    signal.signal(signal.SIGINT, signal.default_int_handler)
    for sig in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, _STOP_SIGNALS)  # blocked by the parent around the fork
    # what the parent loaded is kept out of this worker's collections: they
    # would walk it, and copy every page of it they touch (the fork shares them)
    gc.freeze()
    from threadpoolctl import threadpool_limits

    threadpool_limits(1)
    worker_start(None)


#: The signals that stop a command, held back while workers are forked.
_STOP_SIGNALS = {signal.SIGINT, signal.SIGTERM, signal.SIGHUP}


def can_fork() -> bool:
    """Whether workers may be forked from this process: a POSIX fork and no other Python thread running here.

    A thread of this process could hold a lock at the fork that the child
    then never sees released; native threads of the numerical libraries
    (OpenBLAS) take care of the fork themselves.
    """
    import multiprocessing

    return "fork" in multiprocessing.get_all_start_methods() and threading.active_count() == 1


@contextlib.contextmanager
def _forking() -> Iterator[None]:
    """The block in which this process forks: the stop signals held back, the fork's warning silenced.

    A stop signal's handler raising inside the fork's own hooks would be
    dropped (and the children would inherit it pending); it is delivered
    when the block ends.  Python >= 3.12 warns of a fork beside the
    numerical libraries' native threads (no other Python thread runs:
    :func:`can_fork`).
    """
    import warnings

    mask = signal.pthread_sigmask(signal.SIG_BLOCK, _STOP_SIGNALS)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)


def _forked_main(target: Callable[..., Any], args: tuple) -> None:
    _forked_worker_start()
    target(*args)


def start_forked(target: Callable[..., Any], *args: Any, name: str = "ballscan-forked"):
    """Start ``target(*args)`` in a process forked from this one (only where :func:`can_fork`), set up as a forked worker.

    The child handles signals Python's default way, runs one thread per
    numerical library and ends when this process dies (as the executor's
    forked workers); the stop signals are held back during the fork.  The
    caller joins (or kills and joins) the returned
    ``multiprocessing.Process``; it is a daemon, ended at the latest when
    this interpreter exits.
    """
    import multiprocessing

    proc = multiprocessing.get_context("fork").Process(target=_forked_main, args=(target, args), name=name, daemon=True)
    with _forking():
        proc.start()
    return proc


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split())
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def _call(func: Callable[[Any], Any], item: Any) -> tuple[Any, str | None]:
    """Run one task where it is scheduled; an ``Exception`` becomes its one-line message.

    An ``Exception`` caused by an interrupt (see
    :func:`ballscan.errors.interrupt_behind`) is that interrupt: it stops the run as the interrupt itself would.
    """
    try:
        return func(item), None
    except Exception as exc:  # the error policy: a failed item is a result, not the end of the run
        interrupt = interrupt_behind(exc)
        if interrupt is not None:
            raise interrupt from None
        return None, _one_line(exc)


class _Bar:
    """A rich progress bar on stderr, shown only when asked and stderr is a terminal."""

    def __init__(self, enabled: bool, label: str, total: int) -> None:
        self._p = None
        if not (enabled and total):
            return
        from rich.console import Console

        console = Console(stderr=True)
        if not console.is_terminal:
            return
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

        self._p = Progress(
            TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TimeRemainingColumn(),
            console=console, auto_refresh=False,
        )  # fmt: skip
        self._task = self._p.add_task(label, total=total)
        self._p.start()

    def advance(self) -> None:
        # refreshed here, not by a thread of its own: workers may be forked from this process
        if self._p is not None:
            self._p.advance(self._task)
            self._p.refresh()

    def stop(self) -> None:
        if self._p is not None:
            self._p.stop()
            self._p = None


class TaskExecutor:
    """Where tasks run (see the module docstring); use as a context manager.

    Parameters
    ----------
    jobs : int
        Local processes; 1 runs the tasks in this process, -1 uses every
        available core. Ignored with ``scheduler``.
    scheduler : str or None
        Dask distributed scheduler address (``tcp://host:8786``).
    warm_up : callable or None
        Called without arguments once in each worker before its first task.
    progress : bool
        Show a progress bar per map on stderr (never when stderr is not a terminal).
    before_workers : callable or None
        Called without arguments in this process just before its local
        workers start (e.g. to end a helper process whose work they inherit).

    Raises
    ------
    ValueError
        If ``jobs`` is not a positive integer or -1.
    """

    def __init__(self, jobs: int = 1, scheduler: str | None = None, *, warm_up: Callable[[], Any] | None = None, progress: bool = False, before_workers: Callable[[], Any] | None = None) -> None:
        if isinstance(jobs, bool) or not isinstance(jobs, int) or not (jobs >= 1 or jobs == -1):
            raise ValueError(f"jobs: must be a positive integer or -1 (every core), got {jobs!r}")
        self.jobs = available_cores() if jobs == -1 else jobs
        self.scheduler = scheduler
        self.warm_up = warm_up
        self.progress = progress
        self.before_workers = before_workers
        self._pool = None  # a concurrent.futures or loky ProcessPoolExecutor
        self._start_method: str | None = None
        self._client = None  # distributed.Client
        self._warmed = False

    @property
    def start_method(self) -> str | None:
        """How the local workers started: ``"fork"`` (from this warm process), ``"loky"`` (fresh processes), or None while none runs."""
        return self._start_method if self._pool is not None else None

    # ------------------------------------------------------------------ lifetime
    def __enter__(self) -> "TaskExecutor":
        return self

    def __exit__(self, exc_type, exc, tb) -> None:
        self.close(kill=exc_type is not None)

    def close(self, kill: bool = False) -> None:
        """Stop the workers and disconnect from Dask.

        Parameters
        ----------
        kill : bool
            Kill local workers at once (their running tasks are lost); else
            they finish the tasks they are running first.
        """
        pool, self._pool = self._pool, None
        self._start_method = None
        if pool is not None:
            if kill:
                # SIGKILL each worker; the pool then fails its pending futures
                # and its shutdown returns at once (loky's own kill_workers
                # breaks on futures already cancelled; both pools keep their
                # processes by pid in _processes)
                for proc in list(getattr(pool, "_processes", {}).values()):
                    if proc.pid is not None and proc.is_alive():
                        with contextlib.suppress(OSError):
                            os.kill(proc.pid, signal.SIGKILL)
            pool.shutdown(wait=True)
        client, self._client = self._client, None
        if client is not None:
            client.close()
        self._warmed = False

    # ------------------------------------------------------------------ work
    def map(self, func: Callable[[T], R], items: Iterable[T], label: str = "tasks") -> Iterator[TaskResult[T, R]]:
        """Yield a :class:`TaskResult` for each item as it finishes (any order).

        ``func`` and the items must be picklable for local processes and Dask
        (module-level functions, plain data).
        """
        todo = list(items)
        if not todo:
            return
        if self.scheduler is not None:
            results = self._map_dask(func, todo)
        elif self._pool is not None:
            results = self._map_pool(func, todo)
        elif min(self.jobs, len(todo)) == 1:
            # one worker would do: no process to start
            results = self._map_here(func, todo)
        else:
            results = self._map_local(func, todo)
        bar = _Bar(self.progress, label, len(todo))
        try:
            for res in results:
                bar.advance()
                yield res
        except BaseException:
            # an interrupt or an error in the caller's loop: drop the pending
            # items now and stop the workers
            # (the workers first: the generator's close cancels the pending
            # futures, which a pool that loses its workers fails itself)
            self.close(kill=True)
            results.close()
            raise
        finally:
            bar.stop()

    def _warm_here(self) -> None:
        if self.warm_up is not None and not self._warmed:
            self.warm_up()
            self._warmed = True

    def _map_here(self, func: Callable[[T], R], todo: Sequence[T]) -> Iterator[TaskResult[T, R]]:
        self._warm_here()
        for item in todo:
            value, error = _call(func, item)
            yield TaskResult(item, value, error)

    def _worth_workers(self, n_left: int, item_s: float) -> bool:
        """Whether ``n_left`` items of ``item_s`` seconds each finish sooner on workers, their start-up included."""
        n = min(self.jobs, n_left)
        start_s = (FORK_START_S if can_fork() else SPAWN_START_S) * n
        return n > 1 and n_left * item_s * (1.0 - 1.0 / n) > start_s

    def _map_local(self, func: Callable[[T], R], todo: Sequence[T]) -> Iterator[TaskResult[T, R]]:
        """The items here, timed, until the rest is worth the workers' start-up; the rest on the workers."""
        self._warm_here()
        spent = 0.0
        for k, item in enumerate(todo):
            if k and self._worth_workers(len(todo) - k, spent / k):
                yield from self._map_pool(func, todo[k:])
                return
            t0 = time.perf_counter()
            value, error = _call(func, item)
            spent += time.perf_counter() - t0
            yield TaskResult(item, value, error)

    def _start_pool(self, n_workers: int) -> None:
        if self.before_workers is not None:
            self.before_workers()
        if can_fork():
            import multiprocessing
            from concurrent.futures import ProcessPoolExecutor

            pool = ProcessPoolExecutor(n_workers, mp_context=multiprocessing.get_context("fork"), initializer=_forked_worker_start)
            self._pool, self._start_method = pool, "fork"  # close() stops it whatever happens below
            with _forking():
                pool.submit(int).result()  # the pool forks every worker at its first submit
        else:
            from joblib.externals.loky.process_executor import ProcessPoolExecutor

            self._pool = ProcessPoolExecutor(n_workers, initializer=worker_start, initargs=(self.warm_up,), env=dict(_ONE_THREAD_ENV))
            self._start_method = "loky"

    def _map_pool(self, func: Callable[[T], R], todo: Sequence[T]) -> Iterator[TaskResult[T, R]]:
        if self._pool is None:
            self._start_pool(min(self.jobs, len(todo)))
        pending = {self._pool.submit(_call, func, item): item for item in todo}
        try:
            # as_completed waits on all the futures with one waiter (a wait()
            # per result would install and remove one on every pending future)
            for fut in as_completed(list(pending)):
                item = pending.pop(fut)
                value, error = fut.result()
                yield TaskResult(item, value, error)
        except GeneratorExit:
            # the caller stopped early: items not started yet are dropped
            # (after an error or an interrupt the caller kills the workers,
            # which fails the pending futures itself)
            for fut in pending:
                fut.cancel()
            raise

    def _map_dask(self, func: Callable[[T], R], todo: Sequence[T]) -> Iterator[TaskResult[T, R]]:
        client = self._connect()
        from distributed import as_completed

        # pure=False: equal items are still separate tasks, and hashing them is wasted work
        futures = client.map(_call, [func] * len(todo), todo, pure=False)
        item_of = {fut.key: item for fut, item in zip(futures, todo)}
        try:
            with client.as_current():
                for fut in as_completed(futures):
                    value, error = fut.result()
                    yield TaskResult(item_of[fut.key], value, error)
        finally:
            client.cancel([f for f in futures if not f.done()])

    def _connect(self):
        if self._client is not None:
            return self._client
        try:
            from distributed import Client
        except ImportError:
            raise BallscanError('--scheduler needs Dask distributed: pip install "dask[distributed]" (or pip install \'ballscan[dask]\')') from None
        try:
            client = Client(self.scheduler, timeout=f"{DASK_CONNECT_TIMEOUT_S:g}s", set_as_default=False)
        except (OSError, TimeoutError) as exc:
            raise BallscanError(f"--scheduler {self.scheduler}: cannot connect ({' '.join(str(exc).split())[:160]})") from None
        self._client = client
        if self.warm_up is not None:
            client.run(self.warm_up)
        return client


def run_tasks(
    func: Callable[[T], R],
    items: Iterable[T],
    *,
    jobs: int = 1,
    scheduler: str | None = None,
    warm_up: Callable[[], Any] | None = None,
    progress: bool = False,
    label: str = "tasks",
) -> Iterator[TaskResult[T, R]]:
    """One :meth:`TaskExecutor.map` in its own executor (workers stopped when the iteration ends)."""
    with TaskExecutor(jobs, scheduler, warm_up=warm_up, progress=progress) as ex:
        yield from ex.map(func, items, label)
