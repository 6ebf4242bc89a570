"""Measure every ball of many recordings into one CSV, in parallel and restartably.

Inputs are line-scan images (PNG/TIFF) or raw line streams (``.raw``,
``.bin``, ``.u8``, ``.u16``), or folders of them (not recursive). Each input
needs a camera: ``camera=`` for all of them, or ``NAME.camera.toml`` beside
it (``NAME`` with or without the input's suffix, e.g. ``shot1.camera.toml``
or ``stream.raw.camera.toml``). Per-line timestamps are picked up from
``NAME.timestamps.npy`` / ``NAME.timestamps.txt`` beside the input.

The CSV holds one row per ball (:data:`COLUMNS`). Each input's rows are
appended in one write as the input finishes, so a crash loses at most the
inputs in progress. The CSV itself is the restart state: a rerun skips every
input with a row in it. A rerun first checks it: a partial or malformed last
row (a write cut by a crash) is dropped with the rows of its input, which is
measured again, so every ball is in the CSV exactly once. Inputs without any
ball are listed in ``OUT.done``, which is tied to the CSV (it names the CSV's
inode): it counts only while that very CSV exists, and a deleted CSV means
every input is measured again. It also records the recipe the rows were
measured with: a rerun with another recipe is refused rather than mixing
two estimators' rows in one CSV. ``OUT.lock`` (``fcntl.flock``) keeps a second
run from writing the same CSV; an ``OUT`` that is a symbolic link is refused
unless forced.

Work is spread over local processes or a Dask distributed cluster
(``scheduler="tcp://host:port"``) by :class:`ballscan.parallel.TaskExecutor`:
this process loads the estimator, measures the first inputs itself and forks
its local workers from there once the inputs left are worth their start-up
(each starts with the estimator loaded); a Dask worker loads it once before
its first input.
"""

from __future__ import annotations

import csv
import json
import os
from collections.abc import Sequence
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..errors import BallscanError
from ..outputs import OutputLock, check_not_symlink
from ..parallel import TaskExecutor
from ..pipeline.report import CSV_COLUMNS, csv_row

if TYPE_CHECKING:
    from ..pipeline.recipe import Recipe

__all__ = ["COLUMNS", "BatchSummary", "InputResult", "find_inputs", "camera_beside", "load_estimator", "measure_input", "run_batch"]

IMAGE_SUFFIXES = (".png", ".tif", ".tiff")
RAW_SUFFIXES = (".raw", ".bin", ".u8", ".u16")

#: CSV columns: one row per ball (:data:`ballscan.pipeline.report.CSV_COLUMNS`, as ``estimate --csv``).
COLUMNS = CSV_COLUMNS


@dataclass(frozen=True)
class InputResult:
    """What one input gave: its CSV rows and, if it failed, why.

    A raw stream with a fault (e.g. a truncated last line) has both: the
    balls measured before the fault and the message.
    """

    source: str
    rows: tuple[dict, ...]
    error: str | None = None


@dataclass(frozen=True)
class BatchSummary:
    """Outcome of :func:`run_batch`.

    Attributes
    ----------
    n_inputs, n_skipped, n_done, n_balls : int
        Inputs found, skipped (already done), measured now, balls written now.
    errors : tuple of (str, str)
        ``(source, one-line message)`` of each input that failed. An input
        that failed without any ball is not marked done (a rerun tries it
        again); a raw stream with a fault after some balls keeps them.
    repairs : tuple of str
        What was mended in the CSV before the run (a partial last row
        dropped, its input measured again), one line each.
    """

    n_inputs: int
    n_skipped: int
    n_done: int
    n_balls: int
    errors: tuple[tuple[str, str], ...]
    repairs: tuple[str, ...] = ()


def find_inputs(inputs: Sequence[str | os.PathLike[str]]) -> list[Path]:
    """Expand folders into their image and raw files (sorted); keep files as given."""
    out: list[Path] = []
    for item in inputs:
        p = Path(item)
        if p.is_dir():
            out.extend(sorted(q for q in p.iterdir() if q.is_file() and q.suffix.lower() in IMAGE_SUFFIXES + RAW_SUFFIXES))
        else:
            out.append(p)
    return out


def _beside(path: Path, suffix: str) -> Path | None:
    for stem in (path.with_suffix("").name, path.name):
        q = path.with_name(stem + suffix)
        if q.is_file():
            return q
    return None


def camera_beside(path: Path) -> Path | None:
    """``NAME.camera.toml`` beside ``path`` (``NAME`` with or without its suffix), or None."""
    return _beside(path, ".camera.toml")


def _timestamps_beside(path: Path) -> Path | None:
    return _beside(path, ".timestamps.npy") or _beside(path, ".timestamps.txt")


def measure_input(path: str, camera_path: str | None, radius_m: float, recipe: "Recipe | None" = None, dtype: str = "uint8", background: str = "engine") -> InputResult:
    """Measure every ball of one input; never raises (a failure is in ``error``).

    Parameters
    ----------
    path : str
        Image or raw stream.
    camera_path : str or None
        Camera TOML; None to look beside the input.
    radius_m : float
        Ball radius, metres.
    recipe : Recipe or None
        The estimator's settings (:class:`ballscan.pipeline.recipe.Recipe`;
        None: the default).
    dtype : {"uint8", "uint16"}
        Sample type of a raw stream.
    background : {"engine", "crop"}
        What a raw stream's balls are measured on (``StreamConfig.background``:
        the engine's running model of the crop's columns, or the crop's own).
    """
    src = str(path)
    try:
        p = Path(src)
        cam_path = Path(camera_path) if camera_path is not None else camera_beside(p)
        if cam_path is None:
            raise BallscanError(f"{src}: no camera file (give --camera or put {p.with_suffix('').name}.camera.toml beside it)")
        from ..geometry.camera import load_camera

        camera = load_camera(cam_path)
        ts_path = _timestamps_beside(p)
        if p.suffix.lower() in RAW_SUFFIXES:
            from .sources import RawLineSource
            from ..pipeline.recipe import Recipe
            from .engine import StreamConfig, process_stream

            from .engine import StreamError

            source = RawLineSource(p, camera.width, dtype, timestamps=ts_path, name=src)
            ests = []
            try:
                for r in process_stream(source, camera, radius_m, StreamConfig(recipe=recipe or Recipe(), background=background), source=src):
                    ests.append(r.estimate)
            except StreamError as exc:
                # A damaged stream (e.g. a truncated last line): keep the balls
                # measured before the fault, and report it.
                rows = tuple(csv_row(src, k, e, camera) for k, e in enumerate(ests))
                return InputResult(src, rows, " ".join(str(exc).split()))
        else:
            from ..measure.images import load_timestamps, read_stored
            from ..pipeline.recipe import Recipe
            from .prefetch import decoded
            from .recording import measure_stored

            stored = decoded(src)  # decoded ahead on another core, or None
            if stored is None:
                stored = read_stored(p)
            ts = load_timestamps(ts_path, stored.n_lines) if ts_path is not None else None
            ests = list(measure_stored(stored, camera, radius_m, recipe or Recipe(), timestamps_s=ts).balls)
        return InputResult(src, tuple(csv_row(src, k, e, camera) for k, e in enumerate(ests)))
    except (BallscanError, ValueError, OSError) as exc:
        msg = " ".join(str(exc).split())
        return InputResult(src, (), msg if src in msg else f"{src}: {msg}")


@dataclass(frozen=True)
class _CsvState:
    """What a CSV on disk holds: its valid length (bytes), the sources with rows, and what was dropped."""

    size: int
    sources: frozenset[str]
    dropped: tuple[str, ...]


def _check_csv(out_csv: Path) -> _CsvState:
    """Read ``out_csv``; find the prefix of whole, well-formed rows and the inputs of a damaged end.

    A damaged end (a last row without its newline or with the wrong number of
    fields) is dropped with every row of the last input before it (that
    input's rows may be incomplete): both inputs are measured again.
    """
    if not out_csv.is_file() or out_csv.stat().st_size == 0:
        return _CsvState(0, frozenset(), ())
    data = out_csv.read_bytes()
    if (",".join(COLUMNS) + "\r\n").encode().startswith(data):
        return _CsvState(0, frozenset(), ())  # a header cut short: nothing in it yet
    lines = data.splitlines(keepends=True)
    header = next(csv.reader([lines[0].decode("utf-8", "replace")]), [])
    if tuple(header) != COLUMNS or not lines[0].endswith(b"\n"):
        raise BallscanError(f"{out_csv}: its columns are not this version's ({len(header)} against {len(COLUMNS)}): give a new --out")
    size = len(lines[0])
    starts: list[tuple[int, str]] = []  # (offset, source) of each whole row
    bad = None
    for raw in lines[1:]:
        fields = next(csv.reader([raw.decode("utf-8", "replace")]), [])
        if not raw.endswith(b"\n") or len(fields) != len(COLUMNS) or not fields[0]:
            bad = fields[0] if fields else ""
            break
        starts.append((size, fields[0]))
        size += len(raw)
    if bad is None:
        return _CsvState(size, frozenset(src for _, src in starts), ())
    dropped = [bad] if bad else []
    if starts:
        last = starts[-1][1]
        while starts and starts[-1][1] == last:
            size = starts.pop()[0]
        dropped.append(last)
    return _CsvState(size, frozenset(src for _, src in starts), tuple(dict.fromkeys(dropped)))


def _sidecar(side: Path, out_csv: Path) -> tuple[set[str], str | None]:
    """The inputs without balls that ``side`` lists and the recipe it records (its changes as sorted JSON; None where it has none).

    Empty and None unless ``side`` belongs to this very CSV (its first line
    names the CSV's inode).
    """
    if not side.is_file() or not out_csv.is_file():
        return set(), None
    lines = side.read_text(errors="replace").splitlines()
    if not lines or lines[0] != f"# csv inode {out_csv.stat().st_ino}":
        return set(), None
    recipe = next((s[len("# recipe "):] for s in lines[1:] if s.startswith("# recipe ")), None)
    return {s for s in lines[1:] if s and not s.startswith("# ")}, recipe


def _append(fd: int, data: bytes) -> None:
    """Write all of ``data`` at the end of ``fd`` and sync it."""
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view) :]
    os.fsync(fd)


def _csv_bytes(rows: Sequence[dict]) -> bytes:
    import io

    buf = io.StringIO()
    csv.DictWriter(buf, fieldnames=COLUMNS).writerows(rows)
    return buf.getvalue().encode("utf-8")


def run_batch(
    inputs: Sequence[str | os.PathLike[str]],
    out_csv: str | os.PathLike[str],
    radius_m: float,
    *,
    camera: str | os.PathLike[str] | None = None,
    jobs: int = 1,
    scheduler: str | None = None,
    recipe: "Recipe | None" = None,
    dtype: str = "uint8",
    progress: bool = False,
    background: str = "engine",
    force: bool = False,
) -> BatchSummary:
    """Measure all inputs into ``out_csv`` (see the module docstring).

    Parameters
    ----------
    inputs : sequence of path
        Files and folders.
    out_csv : path
        Appended to; created with a header if missing.
    radius_m : float
        Ball radius, metres.
    camera : path or None
        Camera TOML for all inputs.
    jobs : int
        Local processes (-1 = all cores; 1 = this process).
    scheduler : str or None
        Dask distributed scheduler address; overrides ``jobs``.
    recipe, dtype
        As for :func:`measure_input`.
    progress : bool
        Show a rich progress bar on stderr (when it is a terminal).
    background : {"engine", "crop"}
        As for :func:`measure_input` (raw streams only).
    force : bool
        Write through an ``out_csv`` that is a symbolic link (to its target).

    Returns
    -------
    BatchSummary

    Raises
    ------
    BallscanError
        If another run holds the CSV's lock, the CSV is a symbolic link
        (without ``force``), has other columns, or its rows were measured
        with another recipe (``OUT.done`` records it).
    """
    if not (np.isfinite(radius_m) and radius_m > 0):
        raise ValueError(f"radius: must be positive, got {radius_m!r}")
    from ..pipeline.recipe import Recipe

    if recipe is not None and not isinstance(recipe, Recipe):
        raise ValueError(f"recipe: expected a Recipe, got {recipe!r}")
    from .engine import BACKGROUNDS

    if background not in BACKGROUNDS:
        raise ValueError(f"background: expected one of {BACKGROUNDS}, got {background!r}")
    out = Path(out_csv)
    check_not_symlink(out, force)
    if force and out.is_symlink():
        out = out.resolve()
    files = find_inputs(inputs)
    cam = None if camera is None else str(camera)
    out.parent.mkdir(parents=True, exist_ok=True)
    side = out.with_name(out.name + ".done")
    check_not_symlink(side)
    recipe = recipe or Recipe()
    used = json.dumps(recipe.changes(), sort_keys=True)
    with OutputLock(out.with_name(out.name + ".lock"), str(out)):
        state = _check_csv(out)
        no_ball_sources, earlier = _sidecar(side, out)
        if earlier is not None and earlier != used and (state.sources or no_ball_sources):
            # a restart with other settings would mix two estimators' rows in one CSV
            raise BallscanError(f"{out}: measured with the recipe {earlier}, not {used}: give that recipe, or another --out")
        repairs = []
        if state.size and state.size < out.stat().st_size:
            with open(out, "r+b") as fh:
                fh.truncate(state.size)
                os.fsync(fh.fileno())
            repairs.append(f"{out}: dropped a partial last row; measuring again: {', '.join(state.dropped) or 'its input'}")
        done = set(state.sources) | no_ball_sources
        todo = [str(p) for p in files if str(p) not in done]
        fd = os.open(out, os.O_WRONLY | os.O_APPEND | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0), 0o644)
        try:
            if state.size == 0:
                os.ftruncate(fd, 0)
                _append(fd, ",".join(COLUMNS).encode() + b"\r\n")
            no_balls = sorted(done - set(state.sources))
            # the sidecar names this CSV's inode: it counts only with this very file
            from ..outputs import atomic_write_text

            atomic_write_text(side, "".join(f"{x}\n" for x in [f"# csv inode {os.fstat(fd).st_ino}", f"# recipe {used}", *no_balls]))
            n_done, n_balls, errors = _run(todo, fd, side, camera=cam, radius_m=radius_m, jobs=jobs, scheduler=scheduler, recipe=recipe, dtype=dtype, progress=progress, background=background)
        finally:
            os.close(fd)
    return BatchSummary(len(files), len(files) - len(todo), n_done, n_balls, tuple(errors), tuple(repairs))


def load_estimator() -> None:
    """Import the estimator and load its compiled kernels (the executor's warm-up for a batch).

    The stream engine's own kernels are not loaded here: an input measured
    as a stream (a raw file, a recording longer than the engine's ring)
    loads them when its engine starts.
    """
    from .engine import preload_estimator

    preload_estimator(stream_kernels=False)


def _run(todo: list[str], fd: int, side: Path, *, camera: str | None, radius_m: float, jobs: int, scheduler: str | None, recipe: "Recipe", dtype: str, progress: bool, background: str) -> tuple[int, int, list[tuple[str, str]]]:
    """Measure ``todo`` on the executor, appending each input's rows to the CSV's ``fd`` in one write.

    With local workers allowed (``jobs`` other than 1, no ``scheduler``),
    the PNGs are decoded on another core while this process loads the
    estimator and measures the first inputs, until the workers start
    (:func:`ballscan.stream.prefetch.decoding_ahead`).
    """
    from .prefetch import decoding_ahead, stop_decoding

    n_done = n_balls = 0
    errors: list[tuple[str, str]] = []
    task = partial(measure_input, camera_path=camera, radius_m=radius_m, recipe=recipe, dtype=dtype, background=background)
    executor = TaskExecutor(jobs, scheduler, warm_up=load_estimator, progress=progress, before_workers=stop_decoding)  # no process yet
    ahead = executor.scheduler is None and executor.jobs > 1 and len(todo) > 1
    with decoding_ahead(todo if ahead else []), open(side, "a") as side_fh, executor:
        for outcome in executor.map(task, todo, label="batch"):
            # measure_input reports the input's own faults; anything else it raised is the item's error
            res = outcome.value if outcome.ok else InputResult(outcome.item, (), f"{outcome.item}: {outcome.error}")
            if res.error is not None:
                errors.append((res.source, res.error))
            if res.error is None or res.rows:
                # Rows measured before a fault are kept; the input then
                # counts as done (rerunning a damaged file changes nothing).
                if res.rows:
                    _append(fd, _csv_bytes(res.rows))
                else:
                    side_fh.write(res.source + "\n")
                    side_fh.flush()
                n_done += 1
                n_balls += len(res.rows)
    return n_done, n_balls, errors
