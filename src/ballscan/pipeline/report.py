"""Human-readable tables of estimates (the default output of ``ballscan estimate``)."""

from __future__ import annotations

from .results import BallEstimate, EstimateReport

__all__ = ["format_table", "format_ball"]


def _num(v, fmt: str) -> str:
    return "undetermined" if v is None else format(v, fmt)


def _vec(v, fmt: str) -> str:
    return "undetermined" if v is None else "(" + ", ".join(format(x, fmt) for x in v) + ")"


def _pm(v, s, fmt: str) -> str:
    if v is None:
        return "undetermined"
    return format(v, fmt) + (f" ± {format(s, fmt)}" if s is not None else "")


def _pm_vec(v, s, fmt: str) -> str:
    if v is None:
        return "undetermined"
    if s is None:
        return _vec(v, fmt)
    return "(" + ", ".join(f"{format(a, fmt)} ± {format(b, fmt)}" for a, b in zip(v, s)) + ")"


def format_ball(k: int, b: BallEstimate) -> str:
    """A few lines describing one ball (1-sigma after ±)."""
    lines = [
        f"ball {k}: method {b.method}, lines {b.first_line}-{b.last_line}, {b.run_time_s * 1e3:.1f} ms",
        f"  speed        {_pm(b.speed_mps, b.speed_sigma_mps, '.4f')} m/s",
        f"  velocity     {_pm_vec(b.velocity_mps, b.velocity_sigma_mps, '.4f')} m/s",
        f"  position     {_pm_vec(b.position_m, b.position_sigma_m, '.5f')} m",
        f"  t_c          {_num(b.t_c_s, '.7f')} s",
    ]
    if b.initial is not None:
        lines.append(f"  initial      speed {_num(b.initial.speed_mps, '.4f')} m/s, velocity {_vec(b.initial.velocity_mps, '.4f')} m/s")
    if b.flags:
        lines.append(f"  flags        {', '.join(b.flags)}")
    for key in ("chi2_red", "residual_rms_px", "energy", "evaluations"):
        if key in b.extra:
            lines.append(f"  {key:12s} {b.extra[key]:.4g}")
    return "\n".join(lines)


def format_table(report: EstimateReport) -> str:
    """All balls of a report, or a one-line note when none was found."""
    if not report.balls:
        return f"{report.image}: no ball found"
    return f"{report.image}: {len(report.balls)} ball(s)\n" + "\n".join(format_ball(k, b) for k, b in enumerate(report.balls))
