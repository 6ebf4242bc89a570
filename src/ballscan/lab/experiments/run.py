"""Run or resume an experiment: the trials and bounds in parallel, the CSVs, the summary and the figures.

Finished trials are appended to ``trials.csv`` as they complete; a rerun
with the same output folder and configuration (:meth:`ExperimentConfig.fingerprint`)
skips them. Trials and bounds run on one :class:`ballscan.parallel.TaskExecutor`.
"""

from __future__ import annotations

import csv
import json
import math
import os
import time
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, fields, replace
from pathlib import Path

import numpy as np

from ...errors import BallscanError
from ...parallel import TaskExecutor, available_cores
from .config import METHODS, ExperimentConfig, _scene_dict
from .figures import plot_fig7_overlays, plot_sweeps
from .report import summary_markdown
from .trials import BOUND_FIELDS, ROW_FIELDS, BoundRow, BoundSpec, TrialRow, TrialSpec, _fmt, run_bound, run_trial, trial_specs

__all__ = ["PointSummary", "ExperimentResult", "read_rows", "summarise", "run_experiment"]

_CSV = "trials.csv"
_BOUNDS_CSV = "bounds.csv"
_MANIFEST = "experiment.json"


# --------------------------------------------------------------------------- CSV I/O
def read_rows(path: str | Path) -> list[TrialRow]:
    """Rows of a trials CSV; a truncated last line (an interrupted write) is ignored."""
    path = Path(path)
    if not path.exists():
        return []
    rows = []
    with path.open(newline="") as fh:
        reader = csv.DictReader(fh)
        if reader.fieldnames is None:
            return []
        if tuple(reader.fieldnames) != ROW_FIELDS:
            raise BallscanError(f"{path}: not a ballscan trials CSV (columns {reader.fieldnames})")
        for rec in reader:
            try:
                rows.append(TrialRow.from_csv(rec))
            except (TypeError, ValueError, KeyError):
                continue
    return rows


def _complete_trials(rows: Iterable[TrialRow], methods: Sequence[str]) -> dict[tuple, list[TrialRow]]:
    by: dict[tuple, list[TrialRow]] = {}
    for r in rows:
        by.setdefault(r.key, []).append(r)
    need = set(methods)
    return {k: v for k, v in by.items() if {r.method for r in v} == need and len(v) == len(need)}


def _write_csv(path: Path, header: Sequence[str], rows: Iterable[list[str]]) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    with tmp.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerows(rows)
    os.replace(tmp, path)


def _read_bounds(path: Path) -> list[BoundRow]:
    if not path.exists():
        return []
    out = []
    with path.open(newline="") as fh:
        for rec in csv.DictReader(fh):
            try:
                out.append(BoundRow(rec["factor"], *(float(rec[k]) for k in BOUND_FIELDS[1:])))
            except (TypeError, ValueError, KeyError):
                continue
    return out


# --------------------------------------------------------------------------- summary
@dataclass(frozen=True)
class PointSummary:
    """Statistics of one method at one sweep point and texture.

    Attributes
    ----------
    n : int
        Trials.
    n_failed : int
        Trials without a speed estimate (counted as infinite error).
    median_abs_rel : float
        Median ``|relative speed error|`` (dimensionless).
    q25_abs_rel, q75_abs_rel : float
        Inter-quartile range of ``|relative speed error|`` (the error bars).
    median_rel : float
        Median signed relative error (bias), over successful trials.
    median_run_time_s : float
    """

    factor: str
    value: float
    texture: str
    method: str
    n: int
    n_failed: int
    median_abs_rel: float
    q25_abs_rel: float
    q75_abs_rel: float
    median_rel: float
    median_run_time_s: float


def summarise(rows: Sequence[TrialRow]) -> list[PointSummary]:
    """Per (factor, value, texture, method) statistics, sorted."""
    groups: dict[tuple, list[TrialRow]] = {}
    for r in rows:
        groups.setdefault((r.factor, r.value, r.texture, r.method), []).append(r)
    out = []
    for (f, v, t, m), g in sorted(groups.items(), key=lambda kv: (kv[0][0], kv[0][1], kv[0][2], METHODS.index(kv[0][3]))):
        a = np.array([r.abs_rel_error for r in g])
        rel = np.array([r.rel_error for r in g])
        rel = rel[np.isfinite(rel)]
        tt = np.array([r.run_time_s for r in g])
        tt = tt[np.isfinite(tt)]
        q25, med, q75 = np.quantile(a, [0.25, 0.5, 0.75], method="linear") if np.all(np.isfinite(a)) else _inf_quantiles(a)
        out.append(
            PointSummary(
                f, v, t, m, len(g), int(np.sum(~np.isfinite(a))), float(med), float(q25), float(q75),
                float(np.median(rel)) if rel.size else math.nan, float(np.median(tt)) if tt.size else math.nan,
            )
        )
    return out


def _inf_quantiles(a: np.ndarray) -> tuple[float, float, float]:
    # np.quantile interpolates inf - finite to nan; order statistics keep inf
    s = np.sort(a)
    n = len(s)
    return tuple(float(s[min(n - 1, int(math.floor(q * (n - 1) + 0.5)))]) for q in (0.25, 0.5, 0.75))  # type: ignore[return-value]


# --------------------------------------------------------------------------- runner
@dataclass(frozen=True)
class ExperimentResult:
    """What :func:`run_experiment` produced.

    Attributes
    ----------
    config : ExperimentConfig
    out_dir : Path
    rows : tuple of TrialRow
        Every row of the config's trials (previous runs included), sorted by key.
    bounds : tuple of BoundRow
    summary : tuple of PointSummary
    n_new_trials, n_reused_trials : int
        Trials run now and trials taken from an earlier run's CSV.
    wall_time_s : float
        Wall-clock seconds of this call.
    files : tuple of Path
        CSV, bounds CSV, summary CSV, figure(s) and Markdown summary written.
    """

    config: ExperimentConfig
    out_dir: Path
    rows: tuple[TrialRow, ...]
    bounds: tuple[BoundRow, ...]
    summary: tuple[PointSummary, ...]
    n_new_trials: int
    n_reused_trials: int
    wall_time_s: float
    files: tuple[Path, ...]

    def stat(self, factor: str, value: float, texture: str, method: str) -> PointSummary:
        """The summary of one point (``KeyError`` if absent)."""
        for s in self.summary:
            if (s.factor, s.value, s.texture, s.method) == (factor, float(value), texture, method):
                return s
        raise KeyError((factor, value, texture, method))

    def bound(self, factor: str, value: float) -> BoundRow:
        for b in self.bounds:
            if b.key == (factor, float(value)):
                return b
        raise KeyError((factor, value))


def run_experiment(
    cfg: ExperimentConfig,
    out_dir: str | Path,
    *,
    jobs: int | None = None,
    scheduler: str | None = None,
    progress: bool = True,
    fresh: bool = False,
    plots: bool = True,
    command: str | None = None,
    overlays: bool = False,
    quick: bool = False,
) -> ExperimentResult:
    """Run (or resume) an experiment and write its CSV, figure and summary.

    Parameters
    ----------
    cfg : ExperimentConfig
    out_dir : path
        Output folder; created if needed.  If it holds a run of the same
        configuration (same :meth:`ExperimentConfig.fingerprint`) its
        finished trials are kept and skipped.
    jobs : int, optional
        Local worker processes (default: every core available); ignored with
        ``scheduler``.
    scheduler : str, optional
        Address of a Dask scheduler (``tcp://host:8786``) to run the trials on.
    progress : bool
        Show rich progress bars.
    fresh : bool
        Discard any earlier results in ``out_dir``.
    plots : bool
        Write the figure (matplotlib) besides the CSVs and the summary.
    command : str, optional
        The command line, quoted in the summary.
    overlays : bool
        Also render Fig. 7-like overlays (one image per sweep point).
    quick : bool
        Say in the summary that this is the reduced ``--quick`` run.

    Returns
    -------
    ExperimentResult

    Raises
    ------
    BallscanError
        If ``out_dir`` holds a different experiment, Dask is needed but
        missing, or a trial raised (after every other trial is saved).
    """
    from ...stream.engine import preload_estimator

    t_start = time.perf_counter()
    if jobs is None:
        jobs = available_cores()
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise ValueError(f"jobs: must be a positive integer, got {jobs!r}")
    out = Path(out_dir)
    csv_path, bounds_path = _open_out_dir(cfg, out, fresh)
    specs = trial_specs(cfg)
    wanted = {s.key for s in specs}
    kept = _keep_complete_trials(csv_path, cfg.methods)
    done = {r.key for r in kept}
    todo = [s for s in specs if s.key not in done]
    n_reused = len(wanted & done)

    bounds: list[BoundRow] = []
    with TaskExecutor(jobs, scheduler, warm_up=preload_estimator, progress=progress) as executor:
        new_rows, failed = _run_trials(executor, cfg, todo, csv_path)
        if cfg.bound:
            bounds, failed_bounds = _run_bounds(executor, cfg, bounds_path)
            failed += failed_bounds
    if failed:
        raise BallscanError(f"{out}: {len(failed)} task(s) failed, the others are saved (a rerun resumes); first: {failed[0]}")

    all_rows = [r for r in kept if r.key in wanted] + new_rows
    all_rows.sort(key=lambda r: (r.key, METHODS.index(r.method)))
    result = ExperimentResult(cfg, out, tuple(all_rows), tuple(bounds), tuple(summarise(all_rows)), len(todo), n_reused, 0.0, ())
    return _write_outputs(result, t_start, plots=plots, overlays=overlays, command=command, quick=quick)


def _write_outputs(result: ExperimentResult, t_start: float, *, plots: bool, overlays: bool, command: str | None, quick: bool) -> ExperimentResult:
    """Write the summary CSV, the figures and the Markdown summary; ``result`` with its files and wall time."""
    cfg, out = result.config, result.out_dir
    files = [out / _CSV] + ([out / _BOUNDS_CSV] if cfg.bound else [])
    files.append(_write_summary_csv(result))
    if plots:
        files.append(plot_sweeps(result, out / f"{cfg.name}.png"))
        if overlays:
            files.append(plot_fig7_overlays(cfg, out / f"{cfg.name}-overlays.png"))
    result = replace(result, wall_time_s=time.perf_counter() - t_start, files=tuple(files))
    md = out / "summary.md"
    md.write_text(summary_markdown(result, command=command, quick=quick))
    return replace(result, files=tuple(files) + (md,))


def _open_out_dir(cfg: ExperimentConfig, out: Path, fresh: bool) -> tuple[Path, Path]:
    """Create ``out`` and its manifest; refuse a folder holding another configuration's results.

    Returns
    -------
    trials_csv, bounds_csv : Path
    """
    out.mkdir(parents=True, exist_ok=True)
    csv_path, bounds_path, manifest = out / _CSV, out / _BOUNDS_CSV, out / _MANIFEST
    fp = cfg.fingerprint()
    if fresh:
        for p in (csv_path, bounds_path, manifest):
            p.unlink(missing_ok=True)
    if manifest.exists():
        try:
            old = json.loads(manifest.read_text()).get("fingerprint")
        except (json.JSONDecodeError, AttributeError):
            old = None
        if old != fp:
            raise BallscanError(f"{out}: holds results of a different experiment configuration; use another --out or --fresh")
    manifest.write_text(json.dumps({"fingerprint": fp, "name": cfg.name, "scene": _scene_dict(cfg.scene), "methods": list(cfg.methods), "seed": cfg.seed}, indent=2))
    return csv_path, bounds_path


def _keep_complete_trials(csv_path: Path, methods: Sequence[str]) -> list[TrialRow]:
    """The rows of the trials finished with every method; the CSV is rewritten with them only.

    A trial cut short by an interruption has some of its rows and is redone whole.
    """
    done = _complete_trials(read_rows(csv_path), methods)
    kept = [r for k in sorted(done) for r in sorted(done[k], key=lambda r: METHODS.index(r.method))]
    _write_csv(csv_path, ROW_FIELDS, (r.to_csv() for r in kept))
    return kept


def _run_trials(executor: TaskExecutor, cfg: ExperimentConfig, todo: Sequence[TrialSpec], csv_path: Path) -> tuple[list[TrialRow], list[str]]:
    """Run the trials, appending each one's rows to the CSV as it finishes.

    Returns
    -------
    rows : list of TrialRow
    failed : list of str
        One line per trial whose task raised.
    """
    rows: list[TrialRow] = []
    failed: list[str] = []
    with csv_path.open("a", newline="") as fh:
        writer = csv.writer(fh)
        for res in executor.map(run_trial, todo, f"{cfg.name}: trials"):
            if not res.ok:
                failed.append(f"trial {res.item.key}: {res.error}")
                continue
            # one write per trial, flushed, so an interruption loses at most the trials in flight
            writer.writerows(r.to_csv() for r in res.value)
            fh.flush()
            rows.extend(res.value)
    return rows, failed


def _run_bounds(executor: TaskExecutor, cfg: ExperimentConfig, bounds_path: Path) -> tuple[list[BoundRow], list[str]]:
    """The bound of every sweep point (those in ``bounds_path`` reused), in sweep order, and the failures."""
    have = {b.key: b for b in _read_bounds(bounds_path)}
    points = [(sw.factor, float(v)) for sw in cfg.sweeps for v in sw.values]
    todo = [BoundSpec(f, v, cfg.scene.with_factor(f, v)) for f, v in points if (f, v) not in have]
    failed: list[str] = []
    for res in executor.map(run_bound, todo, f"{cfg.name}: Cramér–Rao bounds"):
        if res.ok:
            have[res.value.key] = res.value
        else:
            failed.append(f"bound at {res.item.factor} = {res.item.value:g}: {res.error}")
    _write_csv(bounds_path, BOUND_FIELDS, ([_fmt(getattr(b, k)) for k in BOUND_FIELDS] for b in sorted(have.values(), key=lambda b: b.key)))
    return [have[p] for p in points if p in have], failed


def _write_summary_csv(res: ExperimentResult) -> Path:
    path = res.out_dir / "summary.csv"
    names = [f.name for f in fields(PointSummary)]
    _write_csv(path, names, ([_fmt(getattr(s, n)) for n in names] for s in res.summary))
    return path
