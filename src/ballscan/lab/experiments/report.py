"""The Markdown summary of an experiment and the paper's trends (Sec. 3.A) checked on it."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from .run import ExperimentResult

__all__ = ["trend_checks", "summary_markdown"]


# --------------------------------------------------------------------------- reporting
def _pct(x: float) -> str:
    if not math.isfinite(x):
        return "fail"
    return f"{100 * x:.3g}"


def trend_checks(res: ExperimentResult) -> list[str]:
    """The paper's claims (Sec. 3.A) checked on these results, one sentence each."""
    out = []
    cfg = res.config
    ms = [m for m in ("paper", "fit") if m in cfg.methods]
    for tex in cfg.textures:
        if "initial" in cfg.methods:
            for m in ms:
                pts = [(s, res.stat(s.factor, s.value, tex, "initial")) for s in res.summary if s.texture == tex and s.method == m]
                better = sum(1 for a, b in pts if a.median_abs_rel < b.median_abs_rel)
                out.append(f"[{tex}] {m} better than the initial guess (median |error|) at {better} of {len(pts)} sweep points.")
        for sw in cfg.sweeps:
            if len(sw.values) < 2:
                continue
            lo, hi = min(sw.values), max(sw.values)
            for m in ms:
                a = res.stat(sw.factor, lo, tex, m).median_abs_rel
                b = res.stat(sw.factor, hi, tex, m).median_abs_rel
                ratio = b / a if a > 0 and math.isfinite(a) and math.isfinite(b) else math.nan
                out.append(f"[{tex}] {m}: median |error| at {sw.factor} = {hi:g} is {ratio:.3g} x that at {lo:g}.")
    return out


def summary_markdown(res: ExperimentResult, command: str | None = None, quick: bool = False) -> str:
    """A short Markdown report: settings, table of median errors, the paper's trends checked."""
    cfg = res.config
    sc = cfg.scene
    lines = [f"# Experiment `{cfg.name}`", ""]
    if quick:
        lines += [f"**Quick mode**: {cfg.trials} trials per point, {sum(len(s.values) for s in cfg.sweeps)} points, methods {', '.join(cfg.methods)}. Numbers are indicative only.", ""]
    if cfg.description:
        lines += [cfg.description, ""]
    if command:
        lines += ["Command:", "", f"    {command}", ""]
    v = sc.velocity_mps
    lines += [
        "## Base scene",
        "",
        f"- camera: {sc.camera.width} px, f = {sc.camera.focal_px:g} px, c = {sc.camera.principal_px:g} px, "
        f"{sc.camera.line_rate_hz:g} lines/s, exposure {sc.camera.exposure * 1e6:.4g} us",
        f"- ball: R = {sc.radius_m:g} m, |V| = {sc.speed_mps:g} m/s, direction {sc.direction_deg:g} deg towards y and "
        f"{sc.direction_z_deg:g} deg towards z (V = {v[0]:.4g}, {v[1]:.4g}, {v[2]:.4g} m/s), centre (0, {sc.y_m:g}, {sc.z_m:g}) m",
        f"- levels: ball {sc.ball_level:g}, background {sc.background_level:g} (linear), shading {'on' if sc.shading else 'off'}",
        f"- sensor: {sc.noise.bits} bit, white {sc.noise.white_dn:g} DN, read noise {sc.noise.read_dn:g} DN, full well "
        f"{sc.noise.full_well_e} e-, PRNU {sc.noise.prnu_sigma:g}",
        "- sweeps: " + "; ".join(f"{s.factor} in {list(s.values)}" for s in cfg.sweeps),
        f"- {cfg.trials} trials per point and texture ({', '.join(cfg.textures)}), seed {cfg.seed}; methods {', '.join(cfg.methods)}"
        + ("; Cramér–Rao bound of the pixels" if cfg.bound else ""),
        "",
        f"Run: {res.n_new_trials} trials now, {res.n_reused_trials} reused from an earlier run, {res.wall_time_s:.1f} s wall "
        f"this call; median run time per ball: "
        + ", ".join(f"{m} {1e3 * _median([s.median_run_time_s for s in res.summary if s.method == m]):.0f} ms" for m in cfg.methods)
        + ".",
        "",
        "## Median |relative speed error| (%)",
        "",
        "Median over the trials; in brackets the inter-quartile range; `fail` = more than half the trials gave no speed. "
        "CRLB = the median |error| of an efficient estimate of the untextured flat ball's speed (bias-corrected as the fit's) "
        "with the pixel Cramér–Rao covariance, under the sensor's read, shot and quantisation noise and its columns' unknown gains; "
        "in brackets its RMS (the 1-sigma bound), which a weak depth velocity makes far larger than the median.",
        "",
    ]
    head = ["factor", "value", "texture"] + list(cfg.methods) + (["CRLB"] if cfg.bound else []) + ["failed"]
    lines.append("| " + " | ".join(head) + " |")
    lines.append("|" + "---|" * len(head))
    bmap = {b.key: b for b in res.bounds}
    for sw in cfg.sweeps:
        for val in sw.values:
            for tex in cfg.textures:
                cells = [sw.factor, f"{val:g}", tex]
                failed = []
                for m in cfg.methods:
                    s = res.stat(sw.factor, val, tex, m)
                    cells.append(f"{_pct(s.median_abs_rel)} [{_pct(s.q25_abs_rel)}–{_pct(s.q75_abs_rel)}]")
                    if s.n_failed:
                        failed.append(f"{m} {s.n_failed}/{s.n}")
                if cfg.bound:
                    b = bmap.get((sw.factor, float(val)))
                    cells.append(f"{_pct(b.median_abs_rel)} [{_pct(b.rel_sigma)}]" if b else "-")
                cells.append(", ".join(failed) or "0")
                lines.append("| " + " | ".join(cells) + " |")
    lines += ["", "## The paper's trends, checked", ""]
    lines += [f"- {t}" for t in trend_checks(res)]
    lines.append("")
    return "\n".join(lines)


def _median(xs: Sequence[float]) -> float:
    a = np.array([x for x in xs if math.isfinite(x)])
    return float(np.median(a)) if a.size else math.nan
