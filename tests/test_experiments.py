"""Tests of ballscan.lab.experiments: the paper's trends on --quick, determinism, resume, configs, Dask."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from ballscan.lab import experiments as ex
from ballscan.geometry.camera import LineScanCamera
from ballscan.errors import BallscanError
from ballscan.cli.experiment import experiment_app


# --------------------------------------------------------------------------- a tiny, fast experiment
def _tiny(trials: int = 2, methods=("initial", "fit"), textures=("none",), seed: int = 3) -> ex.ExperimentConfig:
    cam = LineScanCamera(width=512, focal_px=1500.0, principal_px=255.5, line_rate_hz=20000.0)
    scene = ex.Scene(camera=cam, radius_m=0.03, speed_mps=17.0, z_m=2.0, y_m=0.05)
    return ex.ExperimentConfig(
        name="tiny",
        scene=scene,
        sweeps=(ex.Sweep("speed_mps", (12.0, 23.0)),),
        trials=trials,
        textures=textures,
        methods=methods,
        seed=seed,
        bound=False,
        source="tiny",
    )


def _run(cfg, out, **kw):
    kw.setdefault("progress", False)
    kw.setdefault("plots", False)
    return ex.run_experiment(cfg, out, **kw)


def _comparable(res) -> list[tuple]:
    return sorted(r.comparable() for r in res.rows)


# --------------------------------------------------------------------------- --quick: the paper's trends
@pytest.fixture(scope="module")
def quick(tmp_path_factory):
    """``fig5 --quick`` run once through the library (about 30 s on 2 cores)."""
    cfg = ex.fig5_quick_config()
    return ex.run_experiment(cfg, tmp_path_factory.mktemp("fig5q"), jobs=2, progress=False, quick=True)


def _median(res, factor, value, method, texture="none") -> float:
    return res.stat(factor, value, texture, method).median_abs_rel


@pytest.mark.slow
def test_quick_mode_is_small_and_says_so(quick):
    cfg = quick.config
    assert cfg.trials >= 8
    assert all(len(s.values) == 2 for s in cfg.sweeps)
    text = (quick.out_dir / "summary.md").read_text()
    assert "Quick mode" in text and "8 trials per point" in text
    assert len(quick.rows) == 4 * 2 * cfg.trials * len(cfg.methods)
    for p in quick.files:
        assert p.exists(), p


@pytest.mark.slow
def test_quick_error_falls_with_ball_size_and_line_rate(quick):
    # The paper's Sec. 3.A: larger balls and faster scanning give more contour.
    # Margin: the fit's median at the large end must be at least 2x smaller
    # (the measured ratios are ~0.025-0.09).
    for m in ("fit",):
        assert _median(quick, "radius_m", 0.11, m) < 0.5 * _median(quick, "radius_m", 0.02, m)
        assert _median(quick, "line_rate_hz", 140000.0, m) < 0.5 * _median(quick, "line_rate_hz", 5800.0, m)
    # the initial guess, quantised to whole lines, improves too (no margin: 8 trials)
    assert _median(quick, "radius_m", 0.11, "initial") < _median(quick, "radius_m", 0.02, "initial")
    assert _median(quick, "line_rate_hz", 140000.0, "initial") < _median(quick, "line_rate_hz", 5800.0, "initial")


def _points(res):
    return [(s.factor, v) for s in res.config.sweeps for v in s.values]


# Passes since the speed is corrected for the upward bias of a noisy
# velocity's norm (before, the fit lost to the line-quantised initial guess
# where the ball spans few lines: 6.2 % vs 1.9 % at 5 800 lines/s).
@pytest.mark.slow
def test_quick_fit_beats_initial_guess_everywhere(quick):
    # Margin: the fit's median |error| below the initial guess's (factor 1.0).
    worse = []
    for f, v in _points(quick):
        fit, ini = _median(quick, f, v, "fit"), _median(quick, f, v, "initial")
        if not fit < 1.0 * ini:
            worse.append(f"{f}={v:g}: fit {100 * fit:.3g} % vs initial {100 * ini:.3g} %")
    if worse:
        pytest.fail("fit not better than the initial guess at: " + "; ".join(worse))


# Known shortfall of the fit (reported, not hidden).  With the two-pass fit
# of commit d88b6a6 (runs/fig5-quick-s2) the fit's median |error| was 2.2x-3.8x
# the bound at six of the eight points.  Since the end lines' areas are
# levelled by the shading model (session 3) it is 1.8x-5.0x at six points
# (1.80x at R = 0.11 m, 1.87x at 5 800 lines/s, 2.04x at 60 m/s, 2.74x at
# 4.7 m/s, 2.84x at 60 deg, 4.96x at 140 000 lines/s; 8 trials per point,
# so the medians scatter by tens of per cent) and within it at two (0.85x at
# the base direction, 0.30x at R = 0.02 m).  Since the renderer samples the
# balls' first and last lines finely (session 4: their coverage was up to
# 0.066 px off the continuous exposure) and the limb texture test has a
# tolerance, 1.6x-4.1x at six points.  Since the shading pass measures the
# windows with whole pixels' exact coverage (session 4: on noise-free
# renders V.x had been 2e-5 low, the size of the bound at 140 000 lines/s)
# 1.8x-5.6x at four points (1.78x at 60 deg, 3.62x at 140 000 lines/s,
# 4.38x at 4.7 m/s, 5.56x at R = 0.11 m, where every trial moved by
# +0.002 %: the removed bias had offset part of the noisy images' error) and
# within the bound's 1.5x at the other four (1.48x at 5 800 lines/s, 1.44x
# at 60 m/s, 0.67x at 0 deg, 0.30x at R = 0.02 m).  Since the lines of the
# ball's partial exposure are levelled when they agree with the rest
# (session 5, FitSettings.area_partial_check): 1.5x-4.1x at four points
# (1.52x at 60 deg, 2.43x at 4.7 m/s, 2.48x at 140 000 lines/s, 4.05x at
# R = 0.11 m) and 0.15x-0.98x at the others (0.69x at 5 800 lines/s, 0.41x
# at 60 m/s, 0.98x at 0 deg, 0.15x at R = 0.02 m).  Since the bound is that
# of the scene's sensor model (session 6, precision.sensor_crlb: each
# pixel's own shot noise, and the columns' gains, PRNU 0.8 %, unknown; the
# bound moves by -4 % to +3.5 %), 2.4x-4.1x at three points (2.44x at
# 4.7 m/s, 2.49x at 140 000 lines/s, 4.07x at R = 0.11 m) and 0.15x-1.48x at
# the others (1.48x at 60 deg, where the bound widened by 3.5 %).  PRNU
# costs the bound under 4 % but the fit about 2x at 4.7 m/s (with the
# columns' true gains divided out of the image: 2.4x -> 1.8x over 24
# trials): the estimator's loss, not the bound's.  The matched edges of
# session 6 (edges.matched_edges) took 140 000 lines/s to 1.18x and 4.7 m/s
# to 2.04x here, but they are used only on a flat-fielded sensor (this
# scene's PRNU 0.8 % left their position sigmas 2x too small), so these
# numbers are the window edges' again.  Session 7, measured on the three
# points (8 trials each): at R = 0.11 m the bound's relative sigma is 6e-6
# and the renderer's default sampling (4 x 8 per edge pixel) is half of the
# fit's error: rendered with 16 x 64, 4.07x -> 1.86x; at 4.7 m/s and
# 140 000 lines/s 16 x 64 and 32 x 256 change nothing (2.4x-3.1x), and at
# R = 0.11 m neither PRNU 0 (1.4e-5 median error against 1.7e-5) nor a
# 16-bit sensor does: the loss there is the window edges' on ~500 lines.
# Session 8: the matched edges (and the spread lines' pixels) on PRNU
# sensors too, measured on the crop with the ball's measured column gains
# divided out (pipeline.estimate: balls of >= 64 measured
# columns), the background of its columns measured away from it (the
# detector's level there was 0.1 noise sigma high at R = 0.11 m, in
# proportion to the noise: +1.1e-5 on the speed, 1.8 sigma of the bound)
# and each matched edge's sigma carrying the gain error that remains
# (flatfield's gain_sigma, the smooth trend's share included); and the
# shading fit no longer keeps a light that does not lower the interior's
# robust scale by 1 % (flat balls had 19-117 DN of light "behind" the
# ball and were refused as not uniform, falling back to the windows) nor
# takes lines the ball only partly crossed for plateau lines on long balls
# (shading._level_margin).  Then 1.56x at 140 000 lines/s, 1.70x at
# R = 0.11 m, within 1.5x at the other six (0.12x R = 0.02 m, 0.70x
# 4.7 m/s, 0.26x 60 m/s, 0.47x 0 deg, 1.31x 60 deg, 0.48x 5 800 lines/s).
# Merged with the flat-fielded path only on balls of >= 250 lines with both
# edges (Recipe.long_ball_min_lines: on the stream bench's 109-line
# balls its speed sigma was 1.45x small) and the fit's exact Jacobians:
# 1.7x at both (0.000705 % vs 0.00041 %, 0.00272 % vs 0.00157 %).
# Session 9, measured on 32 seeds of each point (the test's 8 first):
# each pixel's shot-noise sigma had followed its own noisy value, which
# gave the pixels reading high less weight (_edge_kernels.shot_noise):
# mean speed error +0.36 -> +0.13 sigma of the bound at R = 0.11 m,
# +0.57 -> +0.48 at 140 000 lines/s (paired shifts -0.23 +- 0.015 and
# -0.08 +- 0.006).  Ratios here 1.72x -> 1.54x at R = 0.11 m, 1.73x ->
# 1.74x at 140 000 lines/s; the others 0.12x (R = 0.02 m), 0.69x
# (4.7 m/s), 0.44x (60 m/s), 1.01x (0 deg), 1.37x (60 deg), 0.40x
# (5 800 lines/s) (were 0.12, 0.68, 0.40, 1.08, 1.32, 0.38).  Not the
# cause: the speed-norm correction (R = 0.11 m: 0.02 sigma; at 140 000
# lines/s its positive part leaves +0.26 sigma at vz = 0, but that is the
# lowest-RMSE and lowest-median choice of raw / positive part / unbiased
# and the bound's sigma is that estimator's RMS), the bound (its V.x sigma
# within 1-3 % of a brute-force Fisher information from finely sampled
# renders), the gains (the true ones: RMSE 1.27x -> 1.18x at R = 0.11 m,
# none at 140 000 lines/s), the background (the true one: no change),
# the shading level's 800 pixels, one brightness for both ends.
# What remains: V.x scatters 1.28x (R = 0.11 m) and 1.34x (140 000
# lines/s) its bound (speed RMSE 1.27x and 1.16x, 32 seeds; medians over
# 32 seeds 1.53x and 1.35x), with no significant bias left beyond the
# norm correction's (+0.13 +- 0.23, +0.48 +- 0.19), and these 8 seeds
# fall high (the 32 seeds' medians of the other 24 are lower).
# Session 10 (benchmarks/bench_efficiency.py, benchmarks/efficiency/):
# the spread-pixel fit's model took 8 Gauss-Legendre nodes per piece of the
# exposure, a staircase in the parameters (a pixel's coverage kinks where a
# node's chord end crosses a pixel border): from 8 to 32 nodes V.x moved
# by 0.53 / 0.31 / 0.33 sigma of the bound RMS at R = 0.11 m / 4.7 m/s /
# 140 000 lines/s (32 seeds), from 32 to 64 by 0.07-0.10.  Now 32.  Against
# the linearised efficient estimator on each trial's own noise draw (128
# seeds) the fit's excess variance went 0.47 -> 0.27 / 0.65 -> 0.58 /
# 0.55 -> 0.44 sigma^2, what is left being its information (its own V.x
# sigma 1.10x / 1.15x the bound at R = 0.11 m / 140 000 lines/s: a free
# brightness per end fitted on the windows' pixels costs 4-7 %) and the
# renderer's 4 x 8 sampling (V.x +0.28 / +0.38 sigma against 16 x 64 on
# the same noise).  The detector split the 140 000 lines/s ball at a ragged
# widest column in 2 of 128 renders (V.x 6 and 43 sigma off; fixed, none
# of the test's 8).  Here, same trials: 1.62x at R = 0.11 m (1.54x),
# 1.98x at 140 000 lines/s (1.74x), 0.92x at 4.7 m/s (0.69x), the others
# unchanged (0.12x, 0.44x, 1.01x, 1.37x, 0.40x); over 32 seeds R = 0.11 m's
# V.x RMSE 1.27x -> 1.14x, its median 1.53x -> 1.26x, 140 000 lines/s
# 1.35x -> 1.31x, 4.7 m/s 1.07x -> 1.28x (128 seeds: 1.32x -> 1.19x,
# 1.10x -> 1.17x, 0.99x -> 1.14x).  An 8-trial median is a coarse
# statistic: an efficient estimator's exceeds 1.5x with probability 0.12,
# one at 1.15x / 1.3x the bound with 0.23 / 0.35.
# Then the spread lines' pixel windows reach 20 px beyond half the edge
# spread, not 3 (Recipe.spread_fit: each end's free brightness is
# measured on the ball's interior, not on the ramps' inner pixels; fit
# minus the efficient estimator, 128 seeds: mean +0.19 / +0.51 / +0.51 ->
# +0.14 / +0.19 / +0.21 sigma, RMS 0.55 / 0.91 / 0.83 -> 0.46 / 0.62 /
# 0.67; V.x RMSE 1.27x / 1.45x / 1.31x -> 1.18x / 1.27x / 1.20x the bound
# at R = 0.11 m / 4.7 m/s / 140 000 lines/s, speed medians 1.19x / 1.14x /
# 1.17x -> 1.21x / 1.07x / 0.88x).  Passes: here 1.21x at R = 0.11 m,
# 1.25x at 140 000 lines/s, 0.78x at 4.7 m/s, the others unchanged (0.12x
# R = 0.02 m, 0.44x 60 m/s, 1.01x 0 deg, 1.37x 60 deg, 0.40x 5 800
# lines/s); the 32 seeds' medians 1.33x, 1.16x, 0.89x (1.53x, 1.35x, 1.07x
# before session 10).
@pytest.mark.slow
def test_quick_fit_within_1p5_of_cramer_rao(quick):
    # Margin 1.5x the median |error| of an efficient unbiased estimator
    # (0.6745 sigma_CRLB), untextured flat ball.
    far = []
    for f, v in _points(quick):
        fit = _median(quick, f, v, "fit")
        bound = quick.bound(f, v).median_abs_rel
        if not fit <= 1.5 * bound:
            far.append(f"{f}={v:g}: fit {100 * fit:.3g} % vs CRLB {100 * bound:.3g} % ({fit / bound:.1f}x)")
    if far:
        pytest.fail("fit above 1.5x the Cramér–Rao bound at: " + "; ".join(far))


# --------------------------------------------------------------------------- determinism and scaling
def test_trial_seed_depends_on_identity_only():
    a = ex.trial_seed(0, "radius_m", 0.02, "none", 3)
    assert a == ex.trial_seed(0, "radius_m", 0.02, "none", 3)
    others = {
        ex.trial_seed(1, "radius_m", 0.02, "none", 3),
        ex.trial_seed(0, "speed_mps", 0.02, "none", 3),
        ex.trial_seed(0, "radius_m", 0.021, "none", 3),
        ex.trial_seed(0, "radius_m", 0.02, "tennis", 3),
        ex.trial_seed(0, "radius_m", 0.02, "none", 4),
    }
    assert a not in others and len(others) == 5


def test_same_results_with_one_and_two_jobs(tmp_path):
    cfg = _tiny()
    r1 = _run(cfg, tmp_path / "j1", jobs=1)
    r2 = _run(cfg, tmp_path / "j2", jobs=2)
    assert len(r1.rows) == 2 * 2 * 2
    assert _comparable(r1) == _comparable(r2)
    # and the estimates are real numbers, not failures
    assert all(math.isfinite(r.est_speed_mps) for r in r1.rows)


def test_resume_skips_finished_trials(tmp_path):
    cfg = _tiny(trials=3)
    out = tmp_path / "run"
    full = _run(cfg, out, jobs=1)
    assert full.n_new_trials == 6 and full.n_reused_trials == 0
    # simulate an interruption: keep two finished trials and half of a third
    # (its "initial" row only) plus a line cut mid-write
    path = out / "trials.csv"
    with path.open(newline="") as fh:
        lines = fh.read().splitlines()
    kept = lines[: 1 + 2 * 2 + 1]
    path.write_text("\n".join(kept) + "\n" + lines[6][:25])
    again = _run(cfg, out, jobs=2)
    assert again.n_reused_trials == 2 and again.n_new_trials == 4
    assert _comparable(again) == _comparable(full)
    rows = ex.read_rows(path)
    assert len(rows) == len(full.rows)  # no duplicates, no half trial
    # nothing left to do
    third = _run(cfg, out, jobs=2)
    assert third.n_new_trials == 0 and third.n_reused_trials == 6
    # more trials later: only the new ones run
    more = _run(ex.replace_trials(cfg, 4), out, jobs=1)
    assert more.n_new_trials == 2 and more.n_reused_trials == 6


def test_other_configuration_in_the_same_folder_is_refused(tmp_path):
    _run(_tiny(trials=1), tmp_path, jobs=1)
    with pytest.raises(BallscanError, match="different experiment configuration"):
        _run(_tiny(trials=1, seed=4), tmp_path, jobs=1)
    res = _run(_tiny(trials=1, seed=4), tmp_path, jobs=1, fresh=True)
    assert res.n_new_trials == 2


def test_csv_is_tidy(tmp_path):
    res = _run(_tiny(trials=1), tmp_path, jobs=1)
    with (tmp_path / "trials.csv").open(newline="") as fh:
        recs = list(csv.DictReader(fh))
    assert tuple(recs[0]) == ex.ROW_FIELDS
    assert {r["method"] for r in recs} == {"initial", "fit"}
    for r in recs:
        rel = float(r["rel_error"])
        assert math.isclose(rel, (float(r["est_speed_mps"]) - float(r["true_speed_mps"])) / float(r["true_speed_mps"]), rel_tol=1e-9)
        assert float(r["run_time_s"]) >= 0
    assert len(recs) == len(res.rows)


# --------------------------------------------------------------------------- configs
_GOOD = """
name = "t"
trials = 1
methods = ["initial", "fit"]
textures = ["none"]
bound = false
[camera]
width = 512
focal_px = 1500.0
principal_px = 255.5
line_rate_hz = 20000.0
[ball]
radius_m = 0.03
speed_mps = 17.0
z_m = 2.0
y_m = 0.05
[[sweep]]
factor = "speed_mps"
values = [12.0, 23.0]
"""


def _write(tmp_path: Path, text: str) -> Path:
    p = tmp_path / "exp.toml"
    p.write_text(text)
    return p


@pytest.mark.parametrize(
    "edit, key, words",
    [
        (('factor = "speed_mps"', 'factor = "spin_rps"'), "sweep[0].factor", "unknown factor"),
        (("values = [12.0, 23.0]", "values = []"), "sweep[0].values", "empty range"),
        (("radius_m = 0.03", "radius_m = -0.03"), "ball.radius_m", "positive"),
        (("bound = false", "bound = false\ncolour = 3"), "colour", "unknown key"),
        (("z_m = 2.0", "z_m = 2.0\nmass_kg = 0.05"), "ball.mass_kg", "unknown key"),
        (("values = [12.0, 23.0]", "start = 1.0\nstop = 2.0\nnum = 0"), "sweep[0].num", "empty range"),
        (("values = [12.0, 23.0]", "values = [12.0, 0.05]"), "sweep[0].values", "lines"),
        (("focal_px = 1500.0", "focal_px = -1500.0"), "camera", "focal_px"),
        (('methods = ["initial", "fit"]', 'methods = ["initial", "magic"]'), "methods", "methods"),
        (("trials = 1", "trials = 0"), "trials", "positive"),
        (("y_m = 0.05", "y_m = 0.5"), "ball", "outside the sensor"),
    ],
)
def test_bad_configs_give_one_line_errors_before_any_work(tmp_path, edit, key, words):
    text = _GOOD.replace(*edit)
    assert text != _GOOD
    path = _write(tmp_path, text)
    out = tmp_path / "out"
    res = CliRunner().invoke(experiment_app, ["custom", "--config", str(path), "--out", str(out), "--no-progress"])
    exc = res.exception
    assert isinstance(exc, BallscanError) and isinstance(exc, ValueError), res.output
    msg = str(exc)
    assert "\n" not in msg
    assert str(path) in msg and f"'{key}" in msg and words in msg, msg
    assert not out.exists()  # nothing was started


def test_missing_and_unparsable_config(tmp_path):
    with pytest.raises(ex.ExperimentConfigError, match="no such file"):
        ex.load_config(tmp_path / "nope.toml")
    with pytest.raises(ex.ExperimentConfigError, match="not valid TOML"):
        ex.load_config(_write(tmp_path, "name = "))


def test_camera_from_a_path_and_log_range(tmp_path):
    (tmp_path / "cam.toml").write_text("width = 512\nfocal_px = 1500.0\nprincipal_px = 255.5\nline_rate_hz = 20000.0\n")
    text = _GOOD.split("[camera]")[0] + 'camera = "cam.toml"\n[ball]' + _GOOD.split("[ball]")[1]
    text = text.replace("values = [12.0, 23.0]", "start = 10.0\nstop = 40.0\nnum = 3\nlog = true")
    cfg = ex.load_config(_write(tmp_path, text))
    assert cfg.scene.camera.width == 512
    assert cfg.sweeps[0].values == (10.0, 20.0, 40.0)


def test_example_config_is_valid():
    cfg = ex.load_config(Path(__file__).parents[1] / "examples" / "custom_experiment.toml")
    assert {s.factor for s in cfg.sweeps} == {"direction_z_deg", "z_m", "read_dn"}
    q = ex.quick_config(cfg)
    assert q.trials == 8 and all(len(s.values) <= 2 for s in q.sweeps)


def test_custom_cli_end_to_end(tmp_path):
    path = _write(tmp_path, _GOOD.replace("bound = false", "bound = true"))
    out = tmp_path / "out"
    res = CliRunner().invoke(experiment_app, ["custom", "--config", str(path), "--out", str(out), "--jobs", "1", "--no-progress"])
    assert res.exit_code == 0, res.output
    for name in ("trials.csv", "bounds.csv", "summary.csv", "t.png", "summary.md"):
        assert (out / name).exists(), name
    md = (out / "summary.md").read_text()
    assert "ballscan experiment custom --config" in md and "| speed_mps | 12 | none |" in md


def test_factor_application():
    cfg = ex.fig5_config()
    s = cfg.scene
    assert s.with_factor("line_rate_hz", 2000.0).camera.line_rate_hz == 2000.0
    assert s.with_factor("read_dn", 5.0).noise.read_dn == 5.0
    v = s.with_factor("direction_deg", 60.0).velocity_mps
    assert np.allclose(v, (s.speed_mps * 0.5, s.speed_mps * math.sqrt(3) / 2, 0.0))
    # a fixed exposure longer than the new line period is clipped to the period
    rail = ex.fig8_config().scene
    assert rail.camera.exposure_s == pytest.approx(2e-3)
    assert rail.with_factor("line_rate_hz", 1000.0).camera.exposure == pytest.approx(1e-3)
    noise, contrast = ex.crlb_noise_dn(s)
    assert noise > s.noise.read_dn and contrast == pytest.approx(0.6 * s.noise.white_dn)


# --------------------------------------------------------------------------- Dask
@pytest.mark.slow
@pytest.mark.parametrize("processes", [False, True], ids=["threads", "processes"])
def test_dask_local_cluster_equals_local_run(tmp_path, processes):
    distributed = pytest.importorskip("distributed")
    cfg = _tiny()
    local = _run(cfg, tmp_path / "local", jobs=1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=processes, dashboard_address=None) as cluster:
        remote = _run(cfg, tmp_path / "dask", scheduler=cluster.scheduler_address)
    assert remote.n_new_trials == local.n_new_trials
    assert _comparable(remote) == _comparable(local)


def test_missing_dask_is_a_clear_error(tmp_path, monkeypatch):
    import builtins

    real = builtins.__import__

    def no_distributed(name, *a, **kw):
        if name == "distributed" or name.startswith("distributed."):
            raise ImportError("no distributed")
        return real(name, *a, **kw)

    monkeypatch.setattr(builtins, "__import__", no_distributed)
    with pytest.raises(BallscanError, match=r"pip install 'ballscan\[dask\]'"):
        _run(_tiny(trials=1), tmp_path, scheduler="tcp://127.0.0.1:1")


@pytest.mark.slow
def test_fig5_and_fig8_commands(tmp_path):
    runner = CliRunner()
    res = runner.invoke(experiment_app, ["fig5", "--quick", "--trials", "1", "--out", str(tmp_path / "f5"), "--jobs", "2", "--no-progress"])
    assert res.exit_code == 0, res.output
    assert res.output.startswith("quick mode: 1 trials per point, 8 points")
    assert (tmp_path / "f5" / "fig5-quick.png").exists()
    res = runner.invoke(
        experiment_app,
        ["fig8", "--trials", "1", "--textures", "none", "--methods", "initial,fit", "--out", str(tmp_path / "f8"), "--jobs", "1", "--no-progress"],
    )
    assert res.exit_code == 0, res.output
    for name in ("fig8.png", "fig8-overlays.png", "summary.md", "trials.csv"):
        assert (tmp_path / "f8" / name).exists(), name
    assert len(ex.read_rows(tmp_path / "f8" / "trials.csv")) == 5 * 2
    bad = runner.invoke(experiment_app, ["fig8", "--methods", "initial,magic", "--out", str(tmp_path / "f8b")])
    assert bad.exit_code != 0 and "--methods" in bad.output


def test_pixels_method_on_request(tmp_path):
    """'pixels' is an estimator one can ask for; it is not in the default set and says when it fell back."""
    assert "pixels" in ex.METHODS and "pixels" not in ex.DEFAULT_METHODS
    assert ex.fig5_config().methods == ex.DEFAULT_METHODS
    res = _run(_tiny(methods=("initial", "fit", "pixels")), tmp_path / "px", jobs=1)
    pix = [r for r in res.rows if r.method == "pixels"]
    fit = [r for r in res.rows if r.method == "fit"]
    assert len(pix) == len(fit) > 0
    for r in pix:
        assert r.est_speed_mps is not None and np.isfinite(r.est_speed_mps)
        words = [w for w in r.flags.split(";") if w.startswith("pixels_")] if r.flags else []
        assert all(w in ex.EXTRA_FLAGS for w in words)
