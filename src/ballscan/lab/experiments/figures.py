"""The paper's experiments (Fig. 5, Fig. 8) and the figures of any experiment (Fig. 5-like sweeps, Fig. 7-like overlays)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ...geometry.camera import LineScanCamera, line_times
from .config import DEFAULT_METHODS, FACTORS, METHODS, TEXTURES, ExperimentConfig, Scene, Sweep, appearance, scene_geometry
from .trials import trial_seed

if TYPE_CHECKING:
    from .run import ExperimentResult

__all__ = ["fig5_config", "fig8_config", "fig5_quick_config", "plot_sweeps", "plot_fig7_overlays"]


# --------------------------------------------------------------------------- built-in experiments
def _fig5_scene() -> Scene:
    # A BASLER spL2048-like sensor behind a 40 mm lens (10 um pixels -> f = 4000 px).
    cam = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=35000.0)
    # 18 m/s rather than a round 20 m/s: at 20 m/s and 35 000 lines/s the chord
    # 2R/|V| of several swept radii is a whole number of lines, where the
    # line-quantised initial guess is exact by coincidence.
    return Scene(camera=cam, radius_m=0.0335, speed_mps=18.0, z_m=3.0, y_m=0.1, direction_deg=0.0)


def fig5_config(trials: int = 16, seed: int = 0, textures: Sequence[str] = TEXTURES, methods: Sequence[str] = DEFAULT_METHODS, points: int = 5) -> ExperimentConfig:
    """The synthetic sweeps of the paper's Fig. 5 (Sec. 3.A).

    Base: tennis ball (R = 33.5 mm) at 18 m/s perpendicular to the viewing
    plane, 3 m from a 2048-px camera (f = 4000 px) at 35 000 lines/s, centre
    0.1 m off the optical axis along the sensor.  Sweeps (``points`` values
    each, log- or linearly spaced):

    - radius 0.02 m (table tennis) to 0.11 m (football);
    - speed 2 m/s (a slow roll) to 60 m/s (a serve);
    - direction 0 deg (perpendicular) to 60 deg towards the sensor y;
    - line rate 2 000 to 140 000 lines/s.
    """
    sweeps = (
        Sweep("radius_m", _spaced(0.02, 0.11, points, log=True, digits=3)),
        Sweep("speed_mps", _spaced(2.0, 60.0, points, log=True, digits=2)),
        Sweep("direction_deg", _spaced(0.0, 60.0, points, log=False, digits=2)),
        Sweep("line_rate_hz", _spaced(2000.0, 140000.0, points, log=True, digits=2)),
    )
    return ExperimentConfig(
        name="fig5",
        scene=_fig5_scene(),
        sweeps=sweeps,
        trials=trials,
        seed=seed,
        textures=tuple(textures),
        methods=tuple(methods),
        description="Synthetic one-factor sweeps after Zhao & Wen, Fig. 5: ball size, speed, direction and line rate.",
        source="fig5",
    )


def fig8_config(trials: int = 16, seed: int = 0, textures: Sequence[str] = TEXTURES, methods: Sequence[str] = DEFAULT_METHODS) -> ExperimentConfig:
    """The laboratory cases of the paper's Fig. 7-8 (Sec. 3.B), simulated.

    A tennis ball (R = 33.5 mm) on a rail at a constant 0.09 m/s, 1 m from a
    BASLER spL2048-70km-like camera (2048 px, f = 2300 px, exposure 2 ms;
    the ``paper-rail`` preset).  Rotating the viewing plane about the optical
    axis by 0, 4 and 10 deg gives the rail motion a component along the
    sensor (``direction_deg``; at 200 lines/s); the scan rate is 100 or 200
    lines/s (at 0 deg).
    """
    from ..presets import get_preset

    p = get_preset("paper-rail")
    m = p.motion
    scene = Scene(
        camera=p.camera,
        radius_m=m.radius_m,
        # 0.09 m/s rather than the preset's 0.1 m/s: at 0.1 m/s the chord
        # 2R/|V| is exactly 134 (67) lines at 200 (100) lines/s, where the
        # line-quantised initial guess is exact by coincidence.
        speed_mps=0.09,
        z_m=m.position_m[2],
        y_m=m.position_m[1],
        ball_level=0.65,
        background_level=0.1,
    )
    return ExperimentConfig(
        name="fig8",
        scene=scene,
        sweeps=(Sweep("direction_deg", (0.0, 4.0, 10.0)), Sweep("line_rate_hz", (100.0, 200.0))),
        trials=trials,
        seed=seed,
        textures=tuple(textures),
        methods=tuple(methods),
        description="The paper's laboratory rail (Sec. 3.B, Fig. 7-8), simulated: viewing-plane rotation 0/4/10 deg and 100/200 lines/s.",
        source="fig8",
    )


def fig5_quick_config(seed: int = 0, textures: Sequence[str] = ("none",), methods: Sequence[str] = ("initial", "fit")) -> ExperimentConfig:
    """``fig5 --quick``: the end points of each factor, 8 trials, untextured.

    By default the paper's Powell refinement (0.3-4 s per ball, about 10x
    the fit) and the textured ball are left out and the slowest corners are
    moved in (speed 4.7 m/s, 5 800 lines/s, both values of the full sweep)
    so that the run takes about half a minute on 2 cores.
    """
    full = fig5_config(trials=8, seed=seed, textures=textures, methods=methods)
    sweeps = (
        Sweep("radius_m", (0.02, 0.11)),
        Sweep("speed_mps", (4.7, 60.0)),
        Sweep("direction_deg", (0.0, 60.0)),
        Sweep("line_rate_hz", (5800.0, 140000.0)),
    )
    return replace(full, sweeps=sweeps, name="fig5-quick")


def _spaced(lo: float, hi: float, n: int, log: bool, digits: int) -> tuple[float, ...]:
    if n < 2:
        return (lo,)
    xs = np.geomspace(lo, hi, n) if log else np.linspace(lo, hi, n)
    return tuple(float(f"{x:.{digits}g}") for x in xs)



# --------------------------------------------------------------------------- figures
_COLOURS = {"initial": "tab:red", "paper": "tab:green", "fit": "tab:blue", "pixels": "tab:purple"}
_LABELS = {
    "initial": "initial guess (Eq. 3-7)",
    "paper": "paper refinement (Powell)",
    "fit": "least-squares fit",
    "pixels": "fit of the ends' pixels",
}


def plot_sweeps(res: ExperimentResult, path: str | Path | None = None, axes=None):
    """Relative speed error against each swept factor, like the paper's Fig. 5.

    One column per sweep, one row per texture; one line per method (median
    ``|relative error|`` over the trials, error bars the inter-quartile
    range) and the Cramér–Rao curve (dashed): the median ``|relative
    error|`` of an efficient estimate's bias-corrected speed, its
    inter-quartile range shaded (:class:`~ballscan.lab.experiments.trials.BoundRow`).

    Parameters
    ----------
    res : ExperimentResult
    path : path, optional
        Write a PNG there (150 dpi).
    axes : array of matplotlib Axes, optional
        ``(n_textures, n_sweeps)`` axes to draw into.

    Returns
    -------
    Path or matplotlib.figure.Figure
        ``path`` when given (the figure is closed), else the figure.
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    import matplotlib.ticker as mticker

    cfg = res.config
    nr, nc = len(cfg.textures), len(cfg.sweeps)
    if axes is None:
        fig, axes = plt.subplots(nr, nc, figsize=(3.6 * nc, 3.2 * nr), squeeze=False, sharey="row")
    else:
        axes = np.asarray(axes).reshape(nr, nc)
        fig = axes[0, 0].figure
    bmap = {b.key: b for b in res.bounds}
    for i, tex in enumerate(cfg.textures):
        for j, sw in enumerate(cfg.sweeps):
            ax = axes[i, j]
            xs = np.array(sorted(sw.values))
            for m in cfg.methods:
                st = [res.stat(sw.factor, x, tex, m) for x in xs]
                med = np.array([s.median_abs_rel for s in st])
                lo = np.array([s.q25_abs_rel for s in st])
                hi = np.array([s.q75_abs_rel for s in st])
                # failed majorities (infinite medians) and exact zeros cannot be drawn on a log axis
                ok = np.isfinite(med) & (med > 0)
                top = np.where(np.isfinite(hi[ok]), hi[ok], med[ok])
                yerr = np.vstack([med[ok] - lo[ok], top - med[ok]])
                ax.errorbar(xs[ok], med[ok], yerr=yerr, color=_COLOURS[m], marker="o", ms=3.5, lw=1.2, capsize=2, label=_LABELS[m])
                for x, s in zip(xs, st):
                    if s.n_failed:
                        # one line per method near the top, so that several methods' notes do not overlap
                        y = 0.97 - 0.07 * METHODS.index(m)
                        ax.annotate(f"{m}: {s.n_failed}/{s.n} failed", (x, y), xycoords=("data", "axes fraction"), fontsize=6,
                                    color=_COLOURS[m], ha="left", va="top")
            if cfg.bound:
                bs = [bmap.get((sw.factor, float(x))) for x in xs]
                yb, b25, b75 = (np.array([getattr(b, k) if b is not None else np.nan for b in bs]) for k in ("median_abs_rel", "q25_abs_rel", "q75_abs_rel"))
                # the same statistics as the methods': an efficient estimate's median and quartiles
                ax.fill_between(xs, b25, b75, color="0.5", alpha=0.15, lw=0)
                ax.plot(xs, yb, "k--", lw=1.0, label="Cramér–Rao: efficient fit's median (band: quartiles)")
            ax.set_yscale("log")
            if FACTORS[sw.factor].log_axis:
                ax.set_xscale("log")
                # plain numbers at 1-2-5 steps read better than powers of ten
                ax.xaxis.set_major_locator(mticker.LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
                ax.xaxis.set_major_formatter(mticker.FuncFormatter(lambda x, _: f"{x / 1000:g}k" if x >= 1000 else f"{x:g}"))
                ax.xaxis.set_minor_formatter(mticker.NullFormatter())
            ax.grid(True, which="both", alpha=0.25)
            ax.set_xlabel(FACTORS[sw.factor].label)
            base = cfg.scene.factor_value(sw.factor)
            ax.axvline(base, color="0.6", lw=0.8, ls=":")
            if j == 0:
                ax.set_ylabel(f"|relative speed error|\n({'untextured' if tex == 'none' else 'tennis texture'})")
    axes[0, 0].legend(fontsize=7, loc="best")
    fig.suptitle(f"{cfg.name}: median |relative speed error| over {cfg.trials} trials (bars: inter-quartile range)", fontsize=10)
    fig.tight_layout()
    if path is None:
        return fig
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return Path(path)


def plot_fig7_overlays(cfg: ExperimentConfig, path: str | Path, texture: str | None = None) -> Path:
    """One rendered image per sweep point with the estimated contours, like Fig. 7.

    Trial 0 of each point is rendered (same seed as in the CSV) and measured
    with the paper's method (top row) and the fit (bottom row); red is the
    initial guess, green the refined estimate
    (:func:`ballscan.pipeline.plot.plot_estimates`).
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    from ...pipeline.estimate import estimate_image
    from ...pipeline.recipe import Recipe
    from ...measure.images import LineImage
    from ...pipeline.plot import plot_estimates
    from ...model.render import render

    tex = texture or cfg.textures[-1]
    points = [(sw.factor, v) for sw in cfg.sweeps for v in sw.values]
    methods = [m for m in ("paper", "fit") if m in cfg.methods] or ["fit"]
    fig, axes = plt.subplots(len(methods), len(points), figsize=(2.6 * len(points), 3.2 * len(methods)), squeeze=False)
    for j, (f, v) in enumerate(points):
        scene = cfg.scene.with_factor(f, v)
        seed = trial_seed(cfg.seed, f, v, tex, 0)
        state = np.random.SeedSequence(seed).generate_state(3, dtype=np.uint32)
        geom = scene_geometry(scene, float(state[1]) / 2.0**32 - 0.5)
        r = render(scene.camera, (geom.motion, appearance(scene, tex, int(state[2]))), geom.n_lines,
                   background_level=scene.background_level, noise=scene.noise, seed=int(state[0]))
        img = LineImage(r.image.astype(float), float(scene.noise.max_dn), scene.noise.bits, "overlay")
        t = line_times(scene.camera, geom.n_lines)
        for i, m in enumerate(methods):
            rep = estimate_image(img, scene.camera, scene.radius_m, recipe=Recipe(method=m))
            ax = axes[i, j]
            plot_estimates(img.data, scene.camera, rep, t, ax=ax, margin_px=15)
            s = rep.balls[0].speed_mps if rep.balls and rep.balls[0].speed_mps is not None else math.nan
            err = (s - geom.motion.speed_mps) / geom.motion.speed_mps
            ax.set_title(f"{f} = {v:g}\n{m}: error {100 * err:+.2f} %", fontsize=8)
            ax.tick_params(labelsize=6)
            ax.xaxis.label.set_size(7)
            ax.yaxis.label.set_size(7)
    fig.suptitle(f"{cfg.name}: trial 0 of each point ({tex} texture); red initial guess, green refined", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return Path(path)
