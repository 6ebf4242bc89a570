"""Model fit: model and Jacobian checks, recovery of truth, honest sigmas, degeneracy, propagation."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.model.averaged import JacobianMemo, averaged_model, chord_jacobian, hybrid_jacobian, model_jacobian
from ballscan.solve.fit import fit_motion
from ballscan.solve.settings import FitSettings
from ballscan.solve.synthetic import synthetic_edges
from ballscan.solve.uncertainty import param_scale, propagate
from ballscan.geometry.motion import PARAM_NAMES, BallMotion
from ballscan.model.silhouette import silhouette


def _serve():
    cam = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5, k1=-0.05)
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    return cam, m


def test_vectorised_model_equals_silhouette():
    cam, m = _serve()
    t = np.arange(240) / cam.line_rate_hz
    ref = silhouette(cam, m, t, "averaged", n_nodes=16)
    me = averaged_model(cam, m.to_params()[None], m.radius_m, t)
    ok = ref.present
    assert ok.sum() > 100
    assert np.max(np.abs(me.left_px[0, ok] - ref.left_px[ok])) < 1e-5
    assert np.max(np.abs(me.right_px[0, ok] - ref.right_px[ok])) < 1e-5
    assert np.max(np.abs(me.area_px[0] - ref.area_px)) < 1e-5
    assert np.max(np.abs(me.presence[0] - ref.presence)) < 1e-9


def test_jacobian_against_central_differences_of_silhouette():
    cam, m = _serve()
    t = np.arange(240) / cam.line_rate_hz
    th = m.to_params()
    scale = param_scale(cam, m)
    _, dl, dr, da = model_jacobian(cam, th, m.radius_m, t, scale, n_nodes=8)
    ref = silhouette(cam, m, t)
    # interior lines only: at the first/last line presence switches on (kink)
    ok = ref.present & (ref.presence > 0.999)
    for k in range(6):
        h = 1e-2 * scale[k]
        sp = silhouette(cam, BallMotion.from_params(th + h * np.eye(6)[k], m.radius_m), t)
        sm = silhouette(cam, BallMotion.from_params(th - h * np.eye(6)[k], m.radius_m), t)
        for d_fd, d_an in (((sp.left_px - sm.left_px) / (2 * h), dl[:, k]), ((sp.right_px - sm.right_px) / (2 * h), dr[:, k]), ((sp.area_px - sm.area_px) / (2 * h), da[:, k])):
            both = ok & np.isfinite(d_fd)
            err = np.abs(d_fd[both] - d_an[both]) * scale[k]  # pixels per natural step
            assert np.max(err) < 2e-3 * max(1.0, np.max(np.abs(d_an[both]) * scale[k])), PARAM_NAMES[k]


@pytest.mark.parametrize("acc", [(0.0, 0.0, 0.0), (1.0, -9.81, 2.0)])
def test_chord_jacobian_against_central_differences(acc):
    cam, m0 = _serve()
    m = BallMotion(m0.radius_m, m0.t_c_s, m0.position_m, m0.velocity_mps, acc)
    t = np.arange(240) / cam.line_rate_hz
    th = m.to_params()
    scale = param_scale(cam, m)
    left, right, dl, dr = chord_jacobian(cam, th, m.radius_m, t, acc)
    ch = silhouette(cam, m, t, "chord")
    ok = ch.present
    assert ok.sum() > 100 and np.array_equal(np.isfinite(left), ok)
    assert np.max(np.abs(left[ok] - ch.left_px[ok])) < 1e-9 and np.max(np.abs(right[ok] - ch.right_px[ok])) < 1e-9
    for k in range(6):
        h = 1e-3 * scale[k] * np.eye(6)[k]
        sp = silhouette(cam, BallMotion.from_params(th + h, m.radius_m, acc), t, "chord")
        sm = silhouette(cam, BallMotion.from_params(th - h, m.radius_m, acc), t, "chord")
        both = ok & sp.present & sm.present
        for fd, an in (((sp.left_px - sm.left_px) / (2 * h[k]), dl[:, k]), ((sp.right_px - sm.right_px) / (2 * h[k]), dr[:, k])):
            assert np.max(np.abs(fd[both] - an[both])) * scale[k] < 1e-5, PARAM_NAMES[k]


def test_hybrid_jacobian_matches_finite_differences_of_averaged_model():
    cam, m = _serve()
    t = np.arange(240) / cam.line_rate_hz
    th = m.to_params()
    scale = param_scale(cam, m)
    me, fl, fr, fa = model_jacobian(cam, th, m.radius_m, t, scale, n_nodes=8)
    hl, hr, ha = hybrid_jacobian(cam, th, m.radius_m, t, scale, n_nodes=8)
    full = me.presence > 0.999
    big = np.max(np.abs(fl[full]) * scale)
    # pixels per natural step (one line period, one pixel's footprint, 0.1 % of the speed)
    assert np.max(np.abs(hl - fl)[full] * scale) < 1e-3 * big
    assert np.max(np.abs(hr - fr)[full] * scale) < 1e-3 * big
    assert np.max(np.abs(ha - fa) * scale) < 2e-3 * big


def test_fit_recovers_truth_from_noise_free_edges():
    cam, m = _serve()
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=0, add_noise=False)
    init = BallMotion(0.0335, 0.00172, (0, -0.079, 4.3), (43.0, 3.5, -3.0))
    r = fit_motion(cam, e, init)
    assert r.converged and not r.undetermined
    assert abs(r.motion.speed_mps - m.speed_mps) / m.speed_mps < 1e-5
    assert np.allclose(r.motion.to_params(), m.to_params(), rtol=0, atol=[1e-9, 1e-6, 1e-5, 1e-4, 1e-4, 5e-3])
    assert abs(r.edge_bias_px) < 1e-4


def test_fit_with_noise_is_honest_and_solvers_agree():
    cam, m = _serve()
    init = BallMotion(0.0335, 0.00172, (0, -0.079, 4.3), (43.0, 3.5, -3.0))
    z = []
    for seed in range(40):
        e = synthetic_edges(cam, m, 240, edge_sigma_px=0.05, seed=seed, area_sigma_px=1e9)
        r = fit_motion(cam, e, init, FitSettings(fit_edge_bias=False, edge_floor_px=0.0))
        assert r.converged
        z.append((r.motion.to_params() - m.to_params()) / r.sigmas)
    z = np.array(z)
    assert np.all(np.abs(z.mean(axis=0)) < 0.6)
    assert np.all((z.std(axis=0) > 0.6) & (z.std(axis=0) < 1.4))
    assert 0.5 < r.chi2_red < 1.6
    r2 = fit_motion(cam, e, init, FitSettings(fit_edge_bias=False, edge_floor_px=0.0, solver="scipy"))
    assert np.all(np.abs(r2.motion.to_params() - r.motion.to_params()) < 0.02 * r.sigmas)


def test_edge_bias_nuisance_absorbs_a_dilation():
    cam, m = _serve()
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=0, add_noise=False)
    from dataclasses import replace

    e_b = replace(e, left_px=e.left_px + 0.1, right_px=e.right_px - 0.1)  # shaded limbs: both edges move inwards
    r = fit_motion(cam, e_b, m, FitSettings(fit_edge_bias=True))
    assert r.edge_bias_px == pytest.approx(-0.1, abs=0.01)
    assert abs(r.motion.speed_mps - m.speed_mps) / m.speed_mps < 1e-4
    r0 = fit_motion(cam, e_b, m, FitSettings(fit_edge_bias=False))
    assert abs(r0.motion.position_m[2] - m.position_m[2]) > 5 * abs(r.motion.position_m[2] - m.position_m[2])


def test_too_few_lines_is_degenerate_not_a_guess():
    cam, m = _serve()
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.05, seed=0)
    from dataclasses import replace

    keep = np.zeros(e.lines.size, bool)
    keep[e.left_ok.nonzero()[0][:3]] = True
    e3 = replace(e, left_ok=e.left_ok & keep, right_ok=e.right_ok & keep, end_line=np.zeros_like(keep))
    r = fit_motion(cam, e3, m)
    assert r.undetermined == PARAM_NAMES
    assert not r.converged and "degenerate" in r.flags
    assert np.all(np.isnan(r.covariance))


def test_vx_sign_follows_crossing():
    cam, m = _serve()
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.05, seed=1)
    mneg = BallMotion(m.radius_m, m.t_c_s, m.position_m, (-44.0, 3.9, -5.0))
    assert fit_motion(cam, e, mneg).motion.velocity_mps[0] > 0
    from dataclasses import replace

    cam_m = replace(cam, crossing="-x")
    assert fit_motion(cam_m, e, m).motion.velocity_mps[0] < 0


def test_propagate_speed_direction_world():
    cam, m = _serve()
    rng = np.random.default_rng(0)
    A = rng.normal(size=(6, 6)) * np.array([1e-7, 1e-4, 1e-3, 0.05, 0.05, 0.5])
    C = A @ A.T
    u = propagate(cam, m, C)
    V = np.asarray(m.velocity_mps)
    samples = rng.multivariate_normal(m.to_params(), C, size=20000)
    sp = np.linalg.norm(samples[:, 3:], axis=1)
    assert u.speed_raw_mps == pytest.approx(m.speed_mps)
    # the correction removes the norm's upward bias, estimated from the sample
    assert u.speed_correction_mps == pytest.approx(sp.mean() - m.speed_mps, rel=0.3, abs=2e-3)
    assert u.speed_mps == pytest.approx(m.speed_mps - u.speed_correction_mps)
    assert u.speed_sigma_mps == pytest.approx(sp.std(), rel=0.1)
    psi = np.degrees(np.arctan2(samples[:, 4], samples[:, 3]))
    assert u.direction_sigma_deg[0] == pytest.approx(psi.std(), rel=0.05)
    assert u.world_velocity_mps is None
    rot = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    camw = cam.with_pose(rot, [0.1, 0.2, 0.3])
    uw = propagate(camw, m, C)
    assert np.allclose(uw.world_velocity_mps, rot.T @ V)
    assert np.allclose(np.sort(uw.world_velocity_sigma_mps), np.sort(u.velocity_sigma_mps))


@pytest.mark.parametrize("velocity", [(30.0, 0.0, 0.0), (30.0, 3.0, -5.0), (30.0, 0.0, 8.0)])
@pytest.mark.parametrize("sigma_vz", [1.0, 5.0, 10.0])
def test_debiased_speed_monte_carlo(velocity, sigma_vz):
    """Over noisy velocities the corrected speed is less biased and closer than |V|, and its sigma is its RMS error."""
    cam, _ = _serve()
    C = np.zeros((6, 6))
    C[3:, 3:] = np.diag([1e-3, 1e-2, sigma_vz**2])
    C[4, 5] = C[5, 4] = 0.05 * sigma_vz
    truth = float(np.linalg.norm(velocity))
    rng = np.random.default_rng(7)
    est, raw, sig = [], [], []
    for v in rng.multivariate_normal(velocity, C[3:, 3:], size=1500):
        u = propagate(cam, BallMotion(0.0335, 0.0, (0.0, 0.0, 3.0), tuple(v)), C)
        est.append(u.speed_mps)
        raw.append(u.speed_raw_mps)
        sig.append(u.speed_sigma_mps)
    est, raw, sig = np.array(est), np.array(raw), np.array(sig)
    rms = lambda x: float(np.sqrt(np.mean((x - truth) ** 2)))  # noqa: E731
    se = 3.0 * rms(est) / np.sqrt(est.size)  # 3 standard errors of a mean
    # measured: the bias falls to 14-36 % of |V|'s where that is larger than
    # the draws' noise (se covers the case sigma_vz = 1 at vz = 8, where both
    # biases are within it)
    assert abs(est.mean() - truth) <= 0.55 * abs(raw.mean() - truth) + se
    # measured: RMS 0.66-1.00 x |V|'s (1 % for the draws' noise where equal)
    assert rms(est) <= rms(raw) * 1.01
    # sigma is the RMS distance to the speeds the noisy estimate allows, not
    # taken at the truth: measured 1.00-2.00 x the actual RMS (it over-states
    # where the weak direction dominates: vz = 0, sigma_vz 5-10, where the
    # speed leaves out most of a component below its noise and is the more exact);
    # the error is skewed, so 1-sigma coverage is not 68 %
    assert 0.8 < float(np.sqrt(np.mean(sig**2))) / rms(est) < 2.1
    assert np.mean(np.abs(est - truth) < 3 * sig) > 0.97


def test_debiased_speed_sigma_when_the_weak_component_reads_near_zero():
    """A weak V.z of about 2 sigma (a table-tennis scene): the sigma must allow for the truth a sigma out.

    With the sigma taken at the plug-in component alone, draws that read V.z
    near 0 claimed the speed to its linear term: 3-sigma coverage 0.92 here
    (measured; now 0.965).
    """
    cam, _ = _serve()
    C = np.zeros((6, 6))
    C[3:, 3:] = np.diag([1e-3, 1e-2, 0.81])
    C[4, 5] = C[5, 4] = 0.045
    velocity = (11.8, 0.0, 2.08)
    truth = float(np.linalg.norm(velocity))
    rng = np.random.default_rng(7)
    z = []
    for v in rng.multivariate_normal(velocity, C[3:, 3:], size=1500):
        u = propagate(cam, BallMotion(0.02, 0.0, (0.0, 0.0, 1.8), tuple(v)), C)
        z.append(abs(u.speed_mps - truth) / u.speed_sigma_mps)
    assert np.mean(np.array(z) < 3.0) > 0.95


def test_debiased_speed_edge_cases_and_bound_at_truth():
    cam, _ = _serve()
    # the correction removes everything: the sigma stays of the noise's size
    C = np.zeros((6, 6))
    C[3:, 3:] = np.diag([1.0, 2.0, 1.0])
    u = propagate(cam, BallMotion(0.0335, 0.0, (0.0, 0.0, 3.0), (0.5, 0.0, 0.0)), C)
    assert u.speed_mps == 0.0 and 0.5 < u.speed_sigma_mps < 3.0
    # at the truth the sigma is the RMS error of the corrected speed of
    # measurements about |V| (Monte Carlo, 4000 draws: +-3 % on the RMS)
    C = np.zeros((6, 6))
    C[3:, 3:] = np.diag([1e-3, 1e-2, 25.0])
    truth = np.array([30.0, 0.0, 8.0])
    bound = propagate(cam, BallMotion(0.0335, 0.0, (0.0, 0.0, 3.0), tuple(truth)), C, at_truth=True)
    assert bound.speed_mps == pytest.approx(np.linalg.norm(truth))
    rng = np.random.default_rng(3)
    est = [propagate(cam, BallMotion(0.0335, 0.0, (0.0, 0.0, 3.0), tuple(v)), C).speed_mps for v in rng.multivariate_normal(truth, C[3:, 3:], 4000)]
    rms = float(np.sqrt(np.mean((np.array(est) - np.linalg.norm(truth)) ** 2)))
    assert bound.speed_sigma_mps == pytest.approx(rms, rel=0.1)


def _with_levels(e, level: float = 1.0, rel: float = 0.0):
    """Synthetic edges whose lines with signal carry a brightness-model level (areas scaled by it)."""
    from dataclasses import replace

    lev = np.where(e.signal, level, np.nan)
    return replace(
        e, area_px=e.area_px * level, area_sigma_px=e.area_sigma_px * level, area_level=lev, area_level_sigma=np.where(e.signal, rel, np.nan)
    )


def test_levelled_end_areas_sharpen_the_ends_and_stay_honest():
    """With a brightness level, the ends' areas are covered lengths: t_c, vx and vz tighten, sigmas stay honest."""
    cam, m = _serve()
    init = BallMotion(0.0335, 0.00172, (0, -0.079, 4.3), (43.0, 3.5, -3.0))
    st = FitSettings(fit_edge_bias=False, edge_floor_px=0.0, area_level_floor=0.0, area_level_floor_px=0.0)
    z, ratio = [], []
    for seed in range(30):
        e = synthetic_edges(cam, m, 240, edge_sigma_px=0.05, seed=seed, area_sigma_px=0.03)
        plain = fit_motion(cam, e, init, st)
        r = fit_motion(cam, _with_levels(e), init, st)
        assert r.converged and plain.converged
        ratio.append(plain.sigmas / r.sigmas)
        z.append((r.motion.to_params() - m.to_params()) / r.sigmas)
    z, ratio = np.array(z), np.median(ratio, axis=0)
    # measured (synthetic edges only up to 0.3 px of spread, so the ends are
    # all areas): sigma ratios t_c 32, y0 1.6, z0 1.6, vx 15, vy 8.5, vz 9.8
    assert ratio[0] > 10 and ratio[3] > 5 and ratio[5] > 3 and np.all(ratio > 1.2)
    assert np.all(np.abs(z.mean(axis=0)) < 0.6)
    assert np.all((z.std(axis=0) > 0.6) & (z.std(axis=0) < 1.4))
    # the level only scales: a cap half as bright with its level gives the same fit
    e = synthetic_edges(cam, m, 240, edge_sigma_px=0.05, seed=1, area_sigma_px=0.03)
    a, b = fit_motion(cam, _with_levels(e, 1.0), init, st), fit_motion(cam, _with_levels(e, 0.5), init, st)
    # (the partial lines stay loose and unlevelled: their weight changes a little)
    assert np.allclose(a.motion.to_params(), b.motion.to_params(), rtol=0, atol=0.01 * a.sigmas)


def test_partial_exposure_lines_levelled_only_when_they_agree():
    """Lines seen during part of the exposure are levelled when they agree with the rest, loose otherwise."""
    from dataclasses import fields, replace

    cam, m = _serve()
    e = _with_levels(synthetic_edges(cam, m, 240, edge_sigma_px=0.05, seed=2, area_sigma_px=0.03))
    me = averaged_model(cam, m.to_params()[None], m.radius_m, e.t_s)
    partial = (me.presence[0] > 0) & (me.presence[0] < 0.999)
    assert np.any(partial & (e.t_s < m.t_c_s)) and np.any(partial & (e.t_s > m.t_c_s))
    st = FitSettings(fit_edge_bias=False, edge_floor_px=0.0)
    loose_st = replace(st, area_partial_check=0.0)
    # consistent lines: levelled, the ends' information sharpens t_c and vx
    fit, loose = fit_motion(cam, e, m, st), fit_motion(cam, e, m, loose_st)
    assert fit.partial_levelled and not loose.partial_levelled
    assert fit.sigmas[0] < 0.8 * loose.sigmas[0] and fit.sigmas[3] < 0.9 * loose.sigmas[3]
    assert np.all(np.abs(fit.motion.to_params() - m.to_params()) < 3 * fit.sigmas)
    # the same lines 50 % too large (a sampled exposure): the loose fit, to the bit
    spoilt = replace(e, area_px=np.where(partial, 1.5 * e.area_px, e.area_px))
    fit_s = fit_motion(cam, spoilt, m, st)
    assert not fit_s.partial_levelled
    assert np.array_equal(fit_s.motion.to_params(), fit_motion(cam, spoilt, m, loose_st).motion.to_params())
    moved = np.abs(fit_s.motion.to_params() - loose.motion.to_params()) / loose.sigmas
    assert fit_s.partial_verdict == "disagree" and fit.partial_verdict == "agree"
    # each test on its own catches lines 10 % too large: the per-line test
    # (the Hausman test made blind) and the Hausman test (the per-line one blind)
    mild = replace(e, area_px=np.where(partial, 1.1 * e.area_px, e.area_px))
    assert fit_motion(cam, mild, m, replace(st, partial_shift_p=1e-300)).partial_verdict == "disagree"
    assert fit_motion(cam, mild, m, replace(st, area_partial_check=1e9)).partial_verdict == "disagree"
    # and neither fires on the consistent lines
    assert fit_motion(cam, e, m, replace(st, partial_shift_p=1e-300)).partial_verdict == "agree"
    assert fit_motion(cam, e, m, replace(st, area_partial_check=1e9)).partial_verdict == "agree"
    # levelling them regardless would move the fit by sigmas
    st_p = replace(st, area_level_partial=True)
    moved_p = np.abs(fit_motion(cam, spoilt, m, st_p).motion.to_params() - fit_motion(cam, e, m, st_p).motion.to_params()) / loose.sigmas
    assert moved.max() < 0.2 and moved_p.max() > 2.0
    # one end only (the lines before t_c dropped: a ball cut by the first line): loose
    keep = e.t_s > m.t_c_s - 0.3 * m.radius_m / m.velocity_mps[0]
    n = e.lines.size
    cut = replace(e, **{f.name: getattr(e, f.name)[keep] for f in fields(e) if isinstance(getattr(e, f.name), np.ndarray) and getattr(e, f.name).shape[:1] == (n,)})
    fit_c = fit_motion(cam, cut, m, st)
    assert fit_c.converged and not fit_c.partial_levelled and fit_c.partial_verdict == "one_end"


def _with_profile(cam, m, e, noise: float = 0.0, seed: int = 0):
    """Synthetic edges plus the exact averaged coverage of every pixel as their profile (flat ball, level 1)."""
    from dataclasses import replace

    from ballscan.model.averaged import _model_core
    from ballscan.model.pixels import pixel_coverage

    me = _model_core(cam, m.to_params()[None], m.radius_m, e.t_s, m.acceleration_mps2, 16, True)
    lo = int(np.floor(np.nanmin(e.left_px))) - 12
    cols = np.arange(lo, int(np.ceil(np.nanmax(e.right_px))) + 13, dtype=float)
    prof = pixel_coverage(*me.samples, cols)[0]
    prof = prof + noise * np.random.default_rng(seed).standard_normal(prof.shape)
    return replace(e, profile=prof, profile_sigma=np.full(prof.shape, max(noise, 1e-3)), profile_col0=lo)


@pytest.mark.parametrize("groups", ["end", "window"])
def test_pixel_fit_is_exact_on_its_own_model(groups):
    """The pixel residuals vanish at the truth for a profile made by the model; the fit returns there from afar."""
    from ballscan.model.pixels import pixel_residuals
    from ballscan.solve.problem import pixel_windows

    cam, m = _serve()
    e = _with_profile(cam, m, synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=0, add_noise=False))
    st = FitSettings(pixels=True, pixel_groups=groups, pixel_floor=0.0, pixel_nodes=16)
    me = averaged_model(cam, m.to_params()[None], m.radius_m, e.t_s)
    me1 = type(me)(*(getattr(me, k)[0] for k in ("left_px", "right_px", "presence", "area_px", "spread_px", "valid")))
    full = e.signal & me1.valid
    spread = full & (me1.spread_px >= st.pixel_min_spread_px)
    pix = pixel_windows(e, me1, full & ~spread & ~(e.left_ok & e.right_ok), spread, m.t_c_s, st)
    assert pix is not None and pix.n_spread > 10 and pix.n_pixels > 500
    assert pix.n_groups == (2 if groups == "end" else len(np.unique(pix.group[pix.mask])))
    r = pixel_residuals(cam, m.to_params()[None], m.radius_m, pix, m.acceleration_mps2, 16)
    assert np.abs(r).max() < 0.02  # normalised units over sigma 1e-3: coverage exact to 2e-5
    init = BallMotion(0.0335, 0.00172, (0, -0.079, 4.3), (43.0, 3.5, -3.0))
    fit = fit_motion(cam, e, init, st)
    assert fit.converged
    assert np.allclose(fit.motion.to_params(), m.to_params(), rtol=0, atol=[1e-9, 1e-6, 1e-5, 1e-4, 1e-4, 5e-3])


@pytest.mark.parametrize("groups, distorted, deg", [("end", False, 30.0), ("window", False, 0.0), ("end", True, 60.0)])
def test_pixel_jacobian_equals_central_differences(groups, distorted, deg):
    """The compiled forward-mode Jacobian of the pixel residuals against central differences of the residuals.

    Central differences with a step of 1e-5 of the parameter scale (1e-3
    for vz) agree with
    the exact derivative to O(h^2) except where a step moves a sample end
    across a pixel border (the coverage's kinks): measured 1e-9 to 1.1e-7
    relative per column on these balls, tolerance 2e-6 (a y0 / vy
    derivative that took the lower end's sign for the upper end was 3e-5
    off).  The forward differences the fit used before (step 1e-3) were 4 %
    off in the t_c column at 30 degrees.
    """
    from ballscan.model.pixels import pixel_residuals, pixel_residuals_jacobian
    from ballscan.solve.problem import pixel_windows

    a = np.radians(deg)
    cam = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None, k1=-0.05 if distorted else 0.0, k2=0.01 if distorted else 0.0)
    m = BallMotion(0.0335, 0.002, (0.0, 0.01, 3.0), (30.0 * np.cos(a), 1.5, 30.0 * np.sin(a)))
    e = _with_profile(cam, m, synthetic_edges(cam, m, 200, edge_sigma_px=0.02, seed=1, add_noise=False), noise=0.01, seed=2)
    st = FitSettings(pixels=True, pixel_groups=groups, pixel_min_spread_px=0.0)
    me = averaged_model(cam, m.to_params()[None], m.radius_m, e.t_s)
    me1 = type(me)(*(getattr(me, k)[0] for k in ("left_px", "right_px", "presence", "area_px", "spread_px", "valid")))
    full = e.signal & me1.valid
    spread = full & (me1.spread_px >= 0.0) & (e.left_ok | e.right_ok)
    pix = pixel_windows(e, me1, full & ~spread, spread, m.t_c_s, st)
    assert pix is not None and pix.n_pixels > 300
    # a little off the truth, where the residuals are not the profile's noise alone
    th = m.to_params() + 0.3 * param_scale(cam, m) * np.array([1.0, -1.0, 0.5, 0.7, -0.4, 0.9])
    J = pixel_residuals_jacobian(cam, th, m.radius_m, pix, 3)
    # vz, the weak axis, moves the residuals so little that a small step is round-off
    h = np.array([1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-3]) * param_scale(cam, m)
    Jc = np.empty_like(J)
    for j in range(6):
        d = np.zeros(6)
        d[j] = h[j]
        rp = pixel_residuals(cam, (th + d)[None], m.radius_m, pix, (0.0, 0.0, 0.0), 3)[0]
        rm = pixel_residuals(cam, (th - d)[None], m.radius_m, pix, (0.0, 0.0, 0.0), 3)[0]
        Jc[:, j] = (rp - rm) / (2 * h[j])
    err = np.linalg.norm(J - Jc, axis=0) / np.linalg.norm(Jc, axis=0)
    assert np.all(err < 2e-6), err


@pytest.mark.parametrize("grid", ["shared", "compacted", "descending_fractional", "wide"])
def test_pixel_coverage_histogram_equals_the_direct_sum(grid):
    """The cumulative-histogram coverage (unit-step grids) against the direct sum over samples and pixels."""
    from ballscan.model.averaged import _model_core
    from ballscan.model.pixels import _pixel_coverage_direct, pixel_coverage

    cam = LineScanCamera(2048, 3000.0, 1023.5, 50000.0, None)
    m = BallMotion(0.0335, 0.002, (0.0, 0.01, 3.0), (26.0, 0.0, 15.0))
    t = 0.002 + np.linspace(-1.2e-3, 1.2e-3, 40)  # the ends and beyond included
    rng = np.random.default_rng(5)
    thetas = m.to_params()[None] + rng.normal(size=(3, 6)) * param_scale(cam, m)
    lo, hi, w = _model_core(cam, thetas, m.radius_m, t, (0.0, 0.0, 0.0), 8, True).samples
    lo[1, 7, 0, 0] = np.nan  # a non-finite sample: that line's pixels are NaN
    if grid == "shared":
        cols = np.arange(985.0, 1062.0)
    elif grid == "compacted":
        cols = np.stack([np.sort(rng.choice(np.arange(985.0, 1062.0), 16, replace=False)) for _ in t])
    elif grid == "descending_fractional":
        cols = 1040.37 - np.arange(30.0)[None, :] + rng.integers(-20, 20, size=(t.size, 1))
    else:
        cols = np.arange(700.0, 1400.0)
    new = pixel_coverage(lo, hi, w, cols)
    ref = _pixel_coverage_direct(lo, hi, w, cols)
    assert new.shape == ref.shape == (3, t.size, cols.shape[-1])
    assert np.array_equal(np.isnan(new), np.isnan(ref)) and np.isnan(new[1, 7]).all()
    assert np.nanmax(np.abs(new - ref)) < 1e-12
    assert np.nanmax(ref) > 0.99  # fully covered pixels are in the test


def test_pixel_fit_widens_its_covariance_by_its_pixels_correlated_model_error():
    """An unmodelled pattern over neighbouring pixels (a texture) inflates the covariance as correlated edges do; white noise does not.

    The pixel residuals enter the covariance scale's correlation terms
    (``Selection.correlated_runs``): a ball whose profile carries a smooth
    stripe pattern of 6 noise sigmas, 8 pixels long, that no motion
    explains, gets an inflation above 2; the same ball with only white
    noise keeps an inflation of 1 (its scale is the reduced chi-square's).
    """
    from dataclasses import replace

    cam, m = _serve()
    st = FitSettings(pixels=True, pixel_groups="end", pixel_nodes=16)
    init = BallMotion(0.0335, 0.00172, (0, -0.079, 4.3), (43.0, 3.5, -3.0))
    base = synthetic_edges(cam, m, 240, edge_sigma_px=0.02, seed=0, add_noise=False)
    white = _with_profile(cam, m, base, noise=0.01, seed=3)
    cols = white.profile_col0 + np.arange(white.profile.shape[1])
    stripes = 0.06 * np.sin(2 * np.pi * cols / 16.0)[None, :] * (white.profile > 0.05)
    textured = replace(white, profile=white.profile + stripes)
    fit_white = fit_motion(cam, white, init, st)
    fit_textured = fit_motion(cam, textured, init, st)
    assert fit_white.converged and fit_textured.converged
    assert fit_white.inflation == 1.0
    assert fit_textured.inflation > 2.0
    # the sigmas grow with it: sqrt(inflation) on top of the reduced chi-square's scale
    assert np.sqrt(fit_textured.covariance[3, 3]) > 1.4 * np.sqrt(fit_white.covariance[3, 3] * fit_textured.chi2_red / fit_white.chi2_red)
