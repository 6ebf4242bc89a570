"""Measure every ball of many recordings into one CSV, in parallel and restartably.

Inputs are line-scan images (PNG/TIFF) or raw line streams (``.raw``,
``.bin``, ``.u8``, ``.u16``), or folders of them (not recursive). Each input
needs a camera: ``camera=`` for all of them, or ``NAME.camera.toml`` beside
it (``NAME`` with or without the input's suffix, e.g. ``shot1.camera.toml``
or ``stream.raw.camera.toml``). Per-line timestamps are picked up from
``NAME.timestamps.npy`` / ``NAME.timestamps.txt`` beside the input.

The CSV holds one row per ball (:data:`COLUMNS`). Rows are appended as each
input finishes, so a crash loses at most the inputs in progress; a rerun
skips every input already in the CSV or listed in the sidecar
``OUT.done`` (which also records inputs without any ball).

Work is spread over local processes or a Dask distributed cluster
(``scheduler="tcp://host:port"``) by :class:`ballscan.parallel.TaskExecutor`;
each worker loads the estimator once before its first input.
"""

from __future__ import annotations

import csv
import os
from collections.abc import Sequence
from dataclasses import dataclass
from functools import partial
from pathlib import Path

import numpy as np

from ..errors import BallscanError
from ..parallel import TaskExecutor
from ..pipeline.report import CSV_COLUMNS, csv_row

__all__ = ["COLUMNS", "BatchSummary", "InputResult", "find_inputs", "camera_beside", "measure_input", "run_batch"]

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
    """

    n_inputs: int
    n_skipped: int
    n_done: int
    n_balls: int
    errors: tuple[tuple[str, str], ...]


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


def measure_input(path: str, camera_path: str | None, radius_m: float, method: str = "fit", dtype: str = "uint8", background: str = "engine") -> InputResult:
    """Measure every ball of one input; never raises (a failure is in ``error``).

    Parameters
    ----------
    path : str
        Image or raw stream.
    camera_path : str or None
        Camera TOML; None to look beside the input.
    radius_m : float
        Ball radius, metres.
    method : {"fit", "paper"}
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
                for r in process_stream(source, camera, radius_m, StreamConfig(recipe=Recipe(method=method), background=background), source=src):
                    ests.append(r.estimate)
            except StreamError as exc:
                # A damaged stream (e.g. a truncated last line): keep the balls
                # measured before the fault, and report it.
                rows = tuple(csv_row(src, k, e, camera) for k, e in enumerate(ests))
                return InputResult(src, rows, " ".join(str(exc).split()))
        else:
            from ..measure.images import load_timestamps, read_stored
            from ..pipeline.recipe import Recipe
            from .recording import measure_stored

            stored = read_stored(p)
            ts = load_timestamps(ts_path, stored.n_lines) if ts_path is not None else None
            ests = list(measure_stored(stored, camera, radius_m, Recipe(method=method), timestamps_s=ts).balls)
        return InputResult(src, tuple(csv_row(src, k, e, camera) for k, e in enumerate(ests)))
    except (BallscanError, ValueError, OSError) as exc:
        msg = " ".join(str(exc).split())
        return InputResult(src, (), msg if src in msg else f"{src}: {msg}")


def _done_sources(out_csv: Path) -> set[str]:
    done: set[str] = set()
    if out_csv.is_file() and out_csv.stat().st_size > 0:
        with open(out_csv, newline="") as fh:
            header = next(csv.reader(fh), [])
        if tuple(header) != COLUMNS:
            raise BallscanError(f"{out_csv}: its columns are not this version's ({len(header)} against {len(COLUMNS)}): give a new --out")
        with open(out_csv, newline="") as fh:
            for row in csv.DictReader(fh):
                if row.get("source"):
                    done.add(row["source"])
    side = out_csv.with_name(out_csv.name + ".done")
    if side.is_file():
        done.update(s for s in side.read_text().splitlines() if s)
    return done


def run_batch(
    inputs: Sequence[str | os.PathLike[str]],
    out_csv: str | os.PathLike[str],
    radius_m: float,
    *,
    camera: str | os.PathLike[str] | None = None,
    jobs: int = 1,
    scheduler: str | None = None,
    method: str = "fit",
    dtype: str = "uint8",
    progress: bool = False,
    background: str = "engine",
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
    method, dtype
        As for :func:`measure_input`.
    progress : bool
        Show a rich progress bar on stderr (when it is a terminal).
    background : {"engine", "crop"}
        As for :func:`measure_input` (raw streams only).

    Returns
    -------
    BatchSummary
    """
    if not (np.isfinite(radius_m) and radius_m > 0):
        raise ValueError(f"radius: must be positive, got {radius_m!r}")
    if method not in ("fit", "paper"):
        raise ValueError(f"method: expected 'fit' or 'paper', got {method!r}")
    from .engine import BACKGROUNDS, preload_estimator

    if background not in BACKGROUNDS:
        raise ValueError(f"background: expected one of {BACKGROUNDS}, got {background!r}")
    out = Path(out_csv)
    files = find_inputs(inputs)
    done = _done_sources(out)
    todo = [str(p) for p in files if str(p) not in done]
    cam = None if camera is None else str(camera)
    out.parent.mkdir(parents=True, exist_ok=True)
    new_file = not out.is_file() or out.stat().st_size == 0
    n_done = n_balls = 0
    errors: list[tuple[str, str]] = []
    with open(out, "a", newline="") as fh, open(out.with_name(out.name + ".done"), "a") as side:
        writer = csv.DictWriter(fh, fieldnames=COLUMNS)
        if new_file:
            writer.writeheader()
            fh.flush()
        task = partial(measure_input, camera_path=cam, radius_m=radius_m, method=method, dtype=dtype, background=background)
        with TaskExecutor(jobs, scheduler, warm_up=preload_estimator, progress=progress) as executor:
            for outcome in executor.map(task, todo, label="batch"):
                # measure_input reports the input's own faults; anything else it raised is the item's error
                res = outcome.value if outcome.ok else InputResult(outcome.item, (), f"{outcome.item}: {outcome.error}")
                if res.error is not None:
                    errors.append((res.source, res.error))
                if res.error is None or res.rows:
                    # Rows measured before a fault are kept; the input then
                    # counts as done (rerunning a damaged file changes nothing).
                    writer.writerows(res.rows)
                    fh.flush()
                    side.write(res.source + "\n")
                    side.flush()
                    n_done += 1
                    n_balls += len(res.rows)
    return BatchSummary(len(files), len(files) - len(todo), n_done, n_balls, tuple(errors))
