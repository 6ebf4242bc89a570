"""Where the final fit's V.x error comes from, band by band (run on demand, not a test).

    python benchmarks/efficiency/decompose.py [--point radius_m=0.11] [--seeds 32] [--variant default|noprnu|truegain]

For each trial of a quick-sweep point (the renders of ``bench_efficiency.py``)
the final ``fit_motion`` call of the estimator is recorded (its selection,
whitened residuals ``r`` and Jacobian ``J`` at the solution).  The errors
of the data at the truth follow linearly, ``r0 = r + J (theta_true -
theta_hat)``, and the V.x error is ``sum_b g_b^T r0_b`` with ``g = J (J^T
J)^-1 e_vx`` split by data band ``b`` (matched edges, window / wide edges,
levelled areas, end pixels, spread-line pixels; and by the line's
position ``|u| = |V.x (t - t_c)| / R`` within the ball).  Per band it
prints the fit's predicted variance of that share ``|g_b|^2`` and the
measured one over the trials (their ratio: how far the band's errors
exceed their stated sigmas in the direction that matters), and the
shares' cross-correlations' part of the total.  Also the bound's V.x
information by the same line bands (``precision`` pixel Fisher
information per line, the column gains known) against the fit's own
``a^T F_b a`` in the bound's efficient direction ``a = C e_vx``.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import sys  # noqa: E402
from dataclasses import replace  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

U_BANDS = (0.0, 0.5, 0.8, 0.9, 0.95, 0.98, 0.995, 1.0, 9.0)


def _install_recorder(log: list) -> None:
    from ballscan.solve import fit as F
    from ballscan.solve.problem import BlockState

    if getattr(F, "_recorder_installed", None) is not None:
        return F._recorder_installed
    orig_lm, orig_select = F.levenberg_marquardt, BlockState.select

    def select(self, *a, **k):
        out = orig_select(self, *a, **k)
        log.append(("sel", self.block.edges, out))
        return out

    def lm(*a, **k):
        out = orig_lm(*a, **k)
        log.append(("lm", out))
        return out

    F.levenberg_marquardt, BlockState.select = lm, select
    F._recorder_installed = log
    return log


def run_one(args):
    from ballscan.lab import experiments as ex
    from ballscan.pipeline.estimate import estimate_image
    from ballscan.measure.images import LineImage
    from ballscan.model.render import render
    from bench_efficiency import trial_scene

    factor, value, trial, variant = args
    truebg = variant.endswith("+truebg")
    variant = variant.replace("+truebg", "")
    log = _install_recorder([])
    spec, state, geom, app = trial_scene(factor, value, trial)
    truth = geom.motion
    cam = spec.scene.camera
    noise = spec.scene.noise
    nz = replace(noise, prnu_sigma=0.0) if variant == "noprnu" else noise
    rd = render(cam, (truth, app), geom.n_lines, background_level=spec.scene.background_level, noise=nz, seed=int(state[0]))
    data = rd.image.astype(float)
    if variant == "truegain":
        data = (data - noise.black_dn) / rd.column_gain[None, :] + noise.black_dn
    log.clear()
    import ballscan.pipeline.stages as S

    if truebg:
        # the background's expectation (DN) in place of the detector's / refined one
        level = noise.black_dn + noise.white_dn * spec.scene.background_level * (rd.column_gain if variant == "default" else 1.0)
        S.full_background = lambda det: np.broadcast_to(level, det.shape).astype(float)
    rep = estimate_image(LineImage(data, float(noise.max_dn), noise.bits, "t"), cam, spec.scene.radius_m)
    b, _ = ex.pick_estimate(rep, truth.t_c_s)
    # the last solve and the selection it solved
    i_lm = max(i for i, e in enumerate(log) if e[0] == "lm")
    i_sel = max(i for i, e in enumerate(log[:i_lm]) if e[0] == "sel")
    sol = log[i_lm][1]
    x, r, J = sol.x, sol.residuals, sol.jacobian
    _, edges, sel = log[i_sel]
    use_l, use_r, use_a, pix = sel.use_left, sel.use_right, sel.use_area, sel.pixels
    t = edges.t_s
    # row -> (time, kind)
    kinds, times = [], []
    ml = edges.left_matched if edges.left_matched is not None else np.zeros(t.size, bool)
    mr = edges.right_matched if edges.right_matched is not None else np.zeros(t.size, bool)
    for use, m in ((use_l, ml), (use_r, mr)):
        idx = np.flatnonzero(use)
        times.append(t[idx])
        kinds.append(np.where(m[idx], "matched", "window"))
    idx = np.flatnonzero(use_a)
    times.append(t[idx])
    kinds.append(np.full(idx.size, "area"))
    if pix is not None:
        rows = np.nonzero(pix.mask)[0]
        times.append(pix.t_s[rows])
        # the spread lines are those with an edge pair in the selection before the pixels took them
        # (edge pairs measured: the spread lines; the end lines have none)
        n_sp = np.isin(pix.t_s, t[edges.left_ok & edges.right_ok])
        kinds.append(np.where(n_sp[rows], "px_spread", "px_end"))
    times = np.concatenate(times)
    kinds = np.concatenate(kinds)
    assert times.size == r.size == J.shape[0], (times.size, r.size, J.shape)
    th_true = truth.to_params()
    dth = th_true - x[:6]
    r0 = r + J[:, :6] @ dth
    u = np.abs(truth.velocity_mps[0] * (times - truth.t_c_s)) / truth.radius_m
    return {"J": J[:, :6], "r0": r0, "kind": kinds, "u": u, "err": x[:6] - th_true, "rep_sig": b.velocity_sigma_mps[0] if b else np.nan}


def nominal_pixel_model(factor, value, nodes):
    """The bound's pixel model of the point's nominal motion (gains known), on the lines it keeps (presence > 0).

    Returns a dict: ``scene``, ``motion``, ``cov`` and ``dcov`` (the pixels'
    coverage and its derivatives, ``precision._pixel_model`` with ``nodes``),
    ``me`` (the averaged model, 8 nodes) and ``keep`` (its lines kept),
    ``t`` (their times, s), ``var`` (the pixels' noise variance, DN^2) and
    ``G`` (the DN derivatives, (6, lines, columns)).
    """
    from ballscan.lab import experiments as ex
    from ballscan.model.averaged import averaged_model
    from ballscan.solve.precision import _n_lines_for, _pixel_model
    from bench_efficiency import _spec

    sc = _spec(factor, value, 0).scene
    m = ex.scene_geometry(sc, 0.0).motion
    cam, nse = sc.camera, sc.noise
    cov, dcov = _pixel_model(cam, m, nodes)
    tt = np.arange(_n_lines_for(cam, m)) / cam.line_rate_hz
    me = averaged_model(cam, m.to_params()[None], m.radius_m, tt, m.acceleration_mps2, 8)
    keep = me.presence[0] > 0
    dy = sc.ball_level - sc.background_level
    y = sc.background_level + dy * cov
    var = nse.read_dn**2 + 1 / 12 + y * nse.white_dn**2 / nse.full_well_e
    return dict(scene=sc, motion=m, cov=cov, dcov=dcov, me=me, keep=keep, t=tt[keep], var=var, G=nse.white_dn * dy * dcov)


def pixel_fisher_by_line(factor, value):
    """Per-line pixel Fisher information of the point's nominal motion (gains known) and the line's |u|."""
    pm = nominal_pixel_model(factor, value, 8)
    m, G = pm["motion"], pm["G"]
    Fi = np.einsum("pnc,qnc->npq", G / pm["var"], G)
    u = np.abs(m.velocity_mps[0] * (pm["t"] - m.t_c_s)) / m.radius_m
    return Fi, u


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--point", default="radius_m=0.11")
    ap.add_argument("--seeds", type=int, default=32)
    ap.add_argument("--variant", default="default")
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    from joblib import Parallel, delayed

    f, v = a.point.split("=")
    v = float(v)
    res = Parallel(n_jobs=a.jobs)(delayed(run_one)((f, v, k, a.variant)) for k in range(a.seeds))
    Fi, u_pix = pixel_fisher_by_line(f, v)
    Fb = Fi.sum(0)
    Cb = np.linalg.inv(Fb)
    e = np.zeros(6)
    e[3] = 1.0
    aeff = Cb @ e
    sig_b = math.sqrt(Cb[3, 3])
    print(f"{a.point} variant {a.variant}, {len(res)} trials; bound (gains known) sigma_vx {sig_b:.3g}")
    errs = np.array([r["err"][3] for r in res])
    print(f"V.x RMSE {math.sqrt(np.mean(errs**2)):.3g} = {math.sqrt(np.mean(errs**2)) / sig_b:.3f}x; fit's own (J^T J)^-1 sigma (median) "
          f"{np.median([math.sqrt(np.linalg.inv(r['J'].T @ r['J'])[3, 3]) for r in res]) / sig_b:.3f}x; reported {np.median([r['rep_sig'] for r in res]) / sig_b:.3f}x")
    # linearised error check
    lin = []
    for r in res:
        C = np.linalg.inv(r["J"].T @ r["J"])
        g = r["J"] @ C[:, 3]
        lin.append(-(g @ r["r0"]))
    lin = np.array(lin)
    print(f"linearised V.x error vs actual: corr {np.corrcoef(lin, errs)[0, 1]:.4f}, RMS ratio {math.sqrt(np.mean(lin**2) / np.mean(errs**2)):.3f}")

    def report(label, keyfun, keys):
        print(f"\n-- by {label}: share of the V.x error variance (units sigma_bound^2)")
        print(f"{'band':<16} {'rows':>7} {'pred':>8} {'meas':>8} {'ratio':>6} {'a^TF_fit a':>11} {'a^TF_pix a':>11}")
        contrib = {k: [] for k in keys}
        pred = {k: [] for k in keys}
        ffit = {k: [] for k in keys}
        nrow = {k: [] for k in keys}
        for r in res:
            C = np.linalg.inv(r["J"].T @ r["J"])
            g = r["J"] @ C[:, 3]
            kk = keyfun(r)
            for k in keys:
                s = kk == k
                contrib[k].append(g[s] @ r["r0"][s])
                pred[k].append(g[s] @ g[s])
                Jb = r["J"][s]
                ffit[k].append(aeff @ (Jb.T @ Jb) @ aeff)
                nrow[k].append(s.sum())
        tot = np.zeros(len(res))
        for k in keys:
            c = np.array(contrib[k])
            tot += c
            pk = ""
            if label == "|u| band":
                lo, hi = (float(q) for q in k.split("-"))
                s = (u_pix >= lo) & (u_pix < hi)
                pk = f"{aeff @ Fi[s].sum(0) @ aeff / sig_b**2:11.4f}"
            print(f"{str(k):<16} {np.mean(nrow[k]):7.0f} {np.mean(pred[k]) / sig_b**2:8.4f} {np.mean(c**2) / sig_b**2:8.4f} "
                  f"{np.mean(c**2) / max(np.mean(pred[k]), 1e-300):6.2f} {np.mean(ffit[k]) / sig_b**2:11.4f} {pk:>11}")
        M = np.array([contrib[k] for k in keys])
        Cm = M @ M.T / M.shape[1] / sig_b**2
        print("   share covariance (sigma_bound^2): " + "; ".join(
            f"{keys[i]}x{keys[j]} {2 * Cm[i, j]:+.3f}" for i in range(len(keys)) for j in range(i + 1, len(keys)) if abs(2 * Cm[i, j]) > 0.03))
        sumvar = sum(np.mean(np.array(contrib[k]) ** 2) for k in keys)
        print(f"{'total':<16} {'':>7} {np.mean([sum(pred[k][i] for k in keys) for i in range(len(res))]) / sig_b**2:8.4f} "
              f"{np.mean(tot**2) / sig_b**2:8.4f}   (sum of bands' {sumvar / sig_b**2:.4f}: cross terms {(np.mean(tot**2) - sumvar) / sig_b**2:+.4f})")

    kinds = sorted({k for r in res for k in np.unique(r["kind"])})
    report("data kind", lambda r: r["kind"], kinds)
    bands = list(zip(U_BANDS[:-1], U_BANDS[1:]))

    labels = [f"{lo:g}-{hi:g}" for lo, hi in bands]

    def ub(r):
        out = np.full(r["u"].size, "", dtype=object)
        for (lo, hi), lab in zip(bands, labels):
            out[(r["u"] >= lo) & (r["u"] < hi)] = lab
        return out

    report("|u| band", ub, labels)


if __name__ == "__main__":
    main()
