"""Monte-Carlo reproduction of the paper's experiments (Sec. 3, Fig. 5 and Fig. 8).

An *experiment* is a base scene (camera, ball, sensor) and one-factor sweeps
of it ("control variety method", Sec. 3.A): for every swept value, every
texture and every trial a line-scan image is rendered with fresh sensor noise
and measured by each method:

``"initial"``
    the paper's key-point initial guess, Eq. (3)-(7);
``"paper"``
    the paper's gradient-image matching refinement with Powell (Eq. (9)-(10));
``"fit"``
    ballscan's sub-pixel edge least-squares fit;
``"pixels"`` (on request, not in the default set)
    the same fit with the ball's ends fitted pixel by pixel
    (``Recipe(pixels=True)``: uniform balls and a continuous
    exposure; where it refuses a ball the row is the plain fit's, with the
    reason in ``flags`` as ``pixels_<reason>``).

The Cramér–Rao bound of the pixel intensities under the scene's sensor model
(:func:`ballscan.solve.precision.sensor_crlb`: each pixel's shot noise, the
columns' unknown gains) is added as a fourth curve.  Results are one tidy
CSV row per trial and method, a figure like Fig. 5 and a Markdown summary.

Trials are independent tasks: they run on local cores or on a Dask cluster
(:class:`ballscan.parallel.TaskExecutor`), each with a seed derived from
``(seed, factor, value, texture, trial)`` only, so results do not depend on
the number of workers.  Finished trials are appended to the CSV as they
complete; a rerun with the same output folder skips them.

The modules, lower to higher:

:mod:`~ballscan.lab.experiments.config`
    the scene, the sweeps and the configuration, validated at construction,
    and custom experiments from TOML;
:mod:`~ballscan.lab.experiments.trials`
    one trial (render and measure) and one point's Cramér–Rao bound;
:mod:`~ballscan.lab.experiments.figures`
    the paper's Fig. 5 and Fig. 8 experiments and the plots;
:mod:`~ballscan.lab.experiments.report`
    the Markdown summary and the paper's trends checked;
:mod:`~ballscan.lab.experiments.run`
    the runner: parallel trials and bounds, CSVs, resume.

The names below are the package's interface.
"""

from __future__ import annotations

from . import config, figures, report, run, trials
from .config import (
    DEFAULT_METHODS,
    FACTORS,
    MAX_LINES,
    METHODS,
    Method,
    TEXTURES,
    ExperimentConfig,
    ExperimentConfigError,
    FactorSpec,
    Scene,
    Sweep,
    Texture,
    TrialGeometry,
    appearance,
    config_from_dict,
    crlb_noise_dn,
    load_config,
    quick_config,
    replace_trials,
    scene_geometry,
    validate_config,
)
from .figures import fig5_config, fig5_quick_config, fig8_config, plot_fig7_overlays, plot_sweeps
from .report import summary_markdown, trend_checks
from .run import ExperimentResult, PointSummary, read_rows, run_experiment, summarise
from .trials import (
    BOUND_FIELDS,
    EXTRA_FLAGS,
    MEDIAN_ABS_NORMAL,
    ROW_FIELDS,
    BoundRow,
    BoundSpec,
    TrialRow,
    TrialSpec,
    pick_estimate,
    run_bound,
    run_trial,
    trial_seed,
    trial_specs,
)

__all__ = [*config.__all__, *trials.__all__, *run.__all__, *figures.__all__, *report.__all__]
