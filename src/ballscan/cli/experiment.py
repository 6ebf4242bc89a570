"""``ballscan experiment``: the paper's experiments (Fig. 5, Fig. 8) and custom sweeps.

A thin layer over :mod:`ballscan.lab.experiments`; register with
``app.add_typer(experiment_app, name="experiment")``. SIGINT, SIGTERM and
SIGHUP stop a run with status 128 + the signal's number; its workers are
killed, the trials written stay and a rerun resumes.  Library errors
(:class:`~ballscan.errors.BallscanError`, ``ValueError``) propagate to the
main CLI, which prints them on one line.
"""

from __future__ import annotations

import shlex
from pathlib import Path
from typing import TYPE_CHECKING, Optional

import typer

from .signals import stop_signals

if TYPE_CHECKING:  # the experiments (numba, scipy, matplotlib) load only when one runs
    from ..lab import experiments as ex

experiment_app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    rich_markup_mode=None,
    help="Reproduce the paper's experiments (Monte-Carlo sweeps, parallel, resumable).",
)

_JOBS = typer.Option(-1, "--jobs", "-j", help="Processes on this machine (1: this process; -1: all cores).")
_SCHED = typer.Option(None, "--scheduler", help="Dask scheduler address (tcp://host:8786): run the trials there (needs ballscan[dask]).")
_FRESH = typer.Option(False, "--fresh", help="Discard earlier results in --out instead of resuming.")
_PROGRESS = typer.Option(True, "--progress/--no-progress", help="Progress bars on stderr (shown only when it is a terminal).")
_SEED = typer.Option(0, "--seed", help="Base seed; each trial's seed derives from it and the trial's identity.")


def _words(text: Optional[str], allowed: tuple[str, ...], name: str) -> Optional[tuple[str, ...]]:
    if text is None:
        return None
    words = tuple(w.strip() for w in text.split(",") if w.strip())
    bad = [w for w in words if w not in allowed]
    if not words or bad:
        raise typer.BadParameter(f"expected a comma-separated subset of {','.join(allowed)}, got {text!r}", param_hint=name)
    return words


def _command(*parts: str) -> str:
    return " ".join(["ballscan", "experiment", *[shlex.quote(p) for p in parts if p]])


def _choices(textures: Optional[str], methods: Optional[str]) -> tuple[Optional[tuple[str, ...]], Optional[tuple[str, ...]]]:
    """The words of ``--textures`` and ``--methods``, checked (None where an option is not given)."""
    from ..lab import experiments as ex

    return _words(textures, ex.TEXTURES, "--textures"), _words(methods, ex.METHODS, "--methods")


def _run(cfg: ex.ExperimentConfig, out: Path, cmd: str, *, jobs: int, scheduler: Optional[str], progress: bool, fresh: bool, quick: bool, overlays: bool = False) -> None:
    """Run the experiment ``cfg`` into ``out`` (a stop signal ends it; ``jobs`` -1: all cores) and print its report."""
    from ..lab import experiments as ex

    with stop_signals(graceful=False):
        res = ex.run_experiment(
            cfg, out, jobs=None if jobs == -1 else jobs, scheduler=scheduler, progress=progress, fresh=fresh, command=cmd, overlays=overlays, quick=quick
        )
    _report(res, quick)


def _report(res: ex.ExperimentResult, quick: bool) -> None:
    from ..lab import experiments as ex

    cfg = res.config
    n_pts = sum(len(s.values) for s in cfg.sweeps)
    if quick:
        typer.echo(f"quick mode: {cfg.trials} trials per point, {n_pts} points, textures {','.join(cfg.textures)}, methods {','.join(cfg.methods)}")
    typer.echo(f"{cfg.name}: {res.n_new_trials} trials run, {res.n_reused_trials} reused, {res.wall_time_s:.1f} s")
    for line in ex.trend_checks(res):
        typer.echo("  " + line)
    for p in res.files:
        typer.echo(str(p))


@experiment_app.command()
def fig5(
    out: Path = typer.Option(..., "--out", help="Output folder (trials.csv, bounds.csv, summary.csv, fig5.png, summary.md)."),
    quick: bool = typer.Option(False, "--quick", help="2 points per factor, 8 trials, untextured, initial guess and fit (about 30 s on 2 cores)."),
    trials: Optional[int] = typer.Option(None, "--trials", help="Trials per point and texture (default 16; 8 with --quick)."),
    points: int = typer.Option(5, "--points", help="Values per factor (full mode)."),
    textures: Optional[str] = typer.Option(None, "--textures", help="Comma list of none,tennis (default both; none with --quick)."),
    methods: Optional[str] = typer.Option(None, "--methods", help="Comma list of initial,paper,fit,pixels (default initial,paper,fit; initial,fit with --quick)."),
    seed: int = _SEED,
    jobs: int = _JOBS,
    scheduler: Optional[str] = _SCHED,
    fresh: bool = _FRESH,
    progress: bool = _PROGRESS,
) -> None:
    """Synthetic sweeps of ball size, speed, direction and line rate (paper Fig. 5)."""
    from ..lab import experiments as ex

    tex, meth = _choices(textures, methods)
    if quick:
        cfg = ex.fig5_quick_config(seed=seed, textures=tex or ("none",), methods=meth or ("initial", "fit"))
    else:
        cfg = ex.fig5_config(seed=seed, points=points, textures=tex or ex.TEXTURES, methods=meth or ex.DEFAULT_METHODS)
    if trials is not None:
        cfg = ex.replace_trials(cfg, trials)
    cmd = _command("fig5", "--out", str(out), "--quick" if quick else "", *(["--trials", str(trials)] if trials else []),
                   *(["--textures", textures] if textures else []), *(["--methods", methods] if methods else []),
                   *(["--points", str(points)] if points != 5 else []), *(["--seed", str(seed)] if seed else []))
    _run(cfg, out, cmd, jobs=jobs, scheduler=scheduler, progress=progress, fresh=fresh, quick=quick)


@experiment_app.command()
def fig8(
    out: Path = typer.Option(..., "--out", help="Output folder (CSV, fig8.png, fig8-overlays.png, summary.md)."),
    quick: bool = typer.Option(False, "--quick", help="8 trials per point."),
    trials: Optional[int] = typer.Option(None, "--trials", help="Trials per point and texture (default 16; 8 with --quick)."),
    textures: Optional[str] = typer.Option(None, "--textures", help="Comma list of none,tennis (default both)."),
    methods: Optional[str] = typer.Option(None, "--methods", help="Comma list of initial,paper,fit,pixels (default initial,paper,fit)."),
    overlays: bool = typer.Option(True, "--overlays/--no-overlays", help="Also draw Fig. 7-like overlay images."),
    seed: int = _SEED,
    jobs: int = _JOBS,
    scheduler: Optional[str] = _SCHED,
    fresh: bool = _FRESH,
    progress: bool = _PROGRESS,
) -> None:
    """The laboratory rail: viewing-plane rotation 0/4/10 deg, 100/200 lines/s (paper Fig. 7-8)."""
    from ..lab import experiments as ex

    tex, meth = _choices(textures, methods)
    cfg = ex.fig8_config(seed=seed, textures=tex or ex.TEXTURES, methods=meth or ex.DEFAULT_METHODS)
    if quick:
        cfg = ex.replace_trials(cfg, 8)
    if trials is not None:
        cfg = ex.replace_trials(cfg, trials)
    cmd = _command("fig8", "--out", str(out), "--quick" if quick else "", *(["--trials", str(trials)] if trials else []))
    _run(cfg, out, cmd, jobs=jobs, scheduler=scheduler, progress=progress, fresh=fresh, quick=quick, overlays=overlays)


@experiment_app.command()
def custom(
    config: Path = typer.Option(..., "--config", help="Experiment TOML (see examples/custom_experiment.toml)."),
    out: Path = typer.Option(..., "--out", help="Output folder."),
    quick: bool = typer.Option(False, "--quick", help="End points of each sweep, 8 trials."),
    trials: Optional[int] = typer.Option(None, "--trials", help="Override the config's trials per point."),
    overlays: bool = typer.Option(False, "--overlays/--no-overlays", help="Also draw Fig. 7-like overlays (one image per point)."),
    jobs: int = _JOBS,
    scheduler: Optional[str] = _SCHED,
    fresh: bool = _FRESH,
    progress: bool = _PROGRESS,
) -> None:
    """Sweeps of any factor on your own camera and ball (TOML config)."""
    from ..lab import experiments as ex

    cfg = ex.load_config(config)
    if quick:
        cfg = ex.quick_config(cfg)
    if trials is not None:
        cfg = ex.replace_trials(cfg, trials)
    cmd = _command("custom", "--config", str(config), "--out", str(out), "--quick" if quick else "")
    _run(cfg, out, cmd, jobs=jobs, scheduler=scheduler, progress=progress, fresh=fresh, quick=quick, overlays=overlays)
