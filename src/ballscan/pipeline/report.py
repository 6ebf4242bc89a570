"""What a person reads: the table of ``ballscan estimate``, its units, the flags in words, and the CSV rows of ``estimate --csv`` and ``batch``."""

from __future__ import annotations

import math

from ..geometry.camera import LineScanCamera
from .results import BallEstimate, EstimateReport

__all__ = ["CSV_COLUMNS", "FLAG_TEXT", "UNITS", "csv_row", "format_ball", "format_table"]

#: Speed units of the table: the factor from m/s.
UNITS = {"m/s": 1.0, "km/h": 3.6, "mph": 3600.0 / 1609.344}

#: Each flag of geometry.md in words.
FLAG_TEXT = {
    "cut_first_line": "already in view at the image's first line (its start is missing)",
    "cut_last_line": "still in view at the image's last line (its end is missing)",
    "cut_sensor_end": "cut by an end of the sensor",
    "overlap": "touches another ball's image",
    "saturated": "clipped pixels on the ball",
    "dropped_lines": "lines missing while it passed",
    "initial_degenerate": "the key-point guess was ill-conditioned",
    "not_converged": "the fit did not converge: do not trust it",
    "degenerate": "some quantities cannot be determined from this image",
    "texture_at_limb": "texture as dark as the background reaches its limb: edges inside the silhouette left out",
    "both_signs": "part of its limb is darker than the backdrop (brighter for a dark ball): edges measured on it (a shadow right beside the ball reads the same)",
    "defocus": "the lens is out of focus at the ball (its blur circle is in the edges' model: defocus_px)",
    "not_a_ball": "its silhouette is not a ball's: do not trust it",
    "implausible_radius": "the radius is outside 1 mm to 0.5 m of any ball (the unit is metres)",
    "implausible_speed": "faster than any sports ball: do not trust it",
    "implausible_range": "farther from the camera than any sports field: check the radius and the camera file",
    "wrong_bit_depth": "the 16-bit values look like pairs of 8-bit samples (8-bit data read as 16-bit?)",
}

#: Flags that make a result unreliable (marked in the table's first line and beside its speed).
UNRELIABLE = ("not_converged", "degenerate", "not_a_ball", "implausible_radius", "implausible_speed", "implausible_range", "wrong_bit_depth")

#: CSV columns: one row per ball (SI units: metres, seconds, m/s, degrees; sigmas are 1-sigma; empty where unknown).
CSV_COLUMNS = (
    "source", "ball", "first_line", "last_line",
    "t_c_s", "x_m", "y_m", "z_m", "vx_mps", "vy_mps", "vz_mps", "speed_mps",
    "t_c_sigma_s", "x_sigma_m", "y_sigma_m", "z_sigma_m", "vx_sigma_mps", "vy_sigma_mps", "vz_sigma_mps", "speed_sigma_mps",
    "flags", "undetermined", "method",
    "speed_transverse_mps", "speed_transverse_sigma_mps", "transverse_axis_y", "transverse_axis_z",
    "psi_y_deg", "psi_y_sigma_deg", "psi_z_deg", "psi_z_sigma_deg",
    "world_x_m", "world_y_m", "world_z_m", "world_vx_mps", "world_vy_mps", "world_vz_mps",
    "world_x_sigma_m", "world_y_sigma_m", "world_z_sigma_m", "world_vx_sigma_mps", "world_vy_sigma_mps", "world_vz_sigma_mps",
    "elevation_deg", "elevation_sigma_deg", "azimuth_deg", "azimuth_sigma_deg",
)  # fmt: skip


def _finite(v) -> bool:
    return v is not None and math.isfinite(float(v))


def _pm(v, s, fmt: str, scale: float = 1.0) -> str:
    if not _finite(v):
        return "undetermined"
    text = format(float(v) * scale, fmt)
    return text + (f" ± {format(float(s) * scale, fmt)}" if _finite(s) else "")


def _pm_vec(v, s, fmt: str, scale: float = 1.0) -> str:
    if v is None:
        return "undetermined"
    sig = s if s is not None else (None,) * len(v)
    return "(" + ", ".join(_pm(a, b, fmt, scale) for a, b in zip(v, sig)) + ")"


def format_ball(k: int, b: BallEstimate, camera: LineScanCamera | None = None, units: str = "m/s") -> str:
    """A few lines describing one ball (1-sigma after ±), in the world frame too when ``camera`` has a pose.

    Parameters
    ----------
    k : int
        The ball's index in its image.
    b : BallEstimate
    camera : LineScanCamera, optional
        Gives the world frame (its pose) and the direction angles.
    units : {"m/s", "km/h", "mph"}
        Of speeds and velocities.
    """
    if units not in UNITS:
        raise ValueError(f"units: expected one of {', '.join(UNITS)}, got {units!r}")
    u = UNITS[units]
    unreliable = [f for f in b.flags if f in UNRELIABLE]
    warn = f"  UNRELIABLE ({', '.join(unreliable)})" if unreliable else ""
    lines = [f"ball {k}: method {b.method}, lines {b.first_line}-{b.last_line}, {b.run_time_s * 1e3:.1f} ms{warn}"]
    mark = "  (UNRELIABLE)" if unreliable and b.speed_mps is not None else ""
    lines.append(f"  speed        {_pm(b.speed_mps, b.speed_sigma_mps, '.4f', u)} {units}{mark}")
    der = b.derived(camera)
    has_sigma = b.covariance is not None
    if der is not None:
        sigma = der.speed_transverse_sigma_mps if has_sigma else None
        if b.transverse is None:
            lines.append(f"  across axis  {_pm(der.speed_transverse_mps, sigma, '.4f', u)} {units}  (|(vx, vy)|, the well-measured part)")
        else:
            axis = ", ".join(f"{c:.3f}" for c in b.transverse.axis)
            lines.append(f"  across sight {_pm(der.speed_transverse_mps, sigma, '.4f', u)} {units}  (|(vx, v along ({axis}))|, the well-measured part; the speed is at least this)")
    lines.append(f"  velocity     {_pm_vec(b.velocity_mps, b.velocity_sigma_mps, '.4f', u)} {units}")
    lines.append(f"  position     {_pm_vec(b.position_m, b.position_sigma_m, '.5f')} m")
    lines.append(f"  t_c          {_pm(b.t_c_s, b.t_c_sigma_s, '.7f')} s")
    if der is not None:
        sd = der.direction_sigma_deg if has_sigma else (None, None)
        psi = [_pm(der.direction_deg[k], sd[k], ".2f") + (" deg" if _finite(der.direction_deg[k]) else "") for k in (0, 1)]
        lines.append(f"  direction    psi_y {psi[0]}, psi_z {psi[1]}  (towards +y, towards +z)")
    if der is not None and der.world_velocity_mps is not None:
        ws = (lambda v: v) if has_sigma else (lambda v: None)
        lines.append(f"  world pos    {_pm_vec(der.world_position_m, ws(der.world_position_sigma_m), '.5f')} m")
        lines.append(f"  world vel    {_pm_vec(der.world_velocity_mps, ws(der.world_velocity_sigma_mps), '.4f', u)} {units}")
        lines.append(
            f"  launch       elevation {_pm(der.elevation_deg, ws(der.elevation_sigma_deg), '.2f')} deg, "
            f"azimuth {_pm(der.azimuth_deg, ws(der.azimuth_sigma_deg), '.2f')} deg"
        )
    if b.initial is not None:
        lines.append(f"  initial      speed {_pm(b.initial.speed_mps, None, '.4f', u)} {units}")
    if b.extra.get("defocus_used"):
        src = "the camera file's" if b.extra["defocus_source"] == "camera" else "measured on its edges"
        lines.append(f"  blur circle  {_pm(b.extra['defocus_px'], b.extra['defocus_sigma_px'], '.2f')} px  ({src})")
    for flag in b.flags:
        lines.append(f"  flag         {flag}: {FLAG_TEXT[flag]}")
    if b.undetermined:
        lines.append(f"  undetermined {', '.join(b.undetermined)}")
    for key in ("chi2_red", "residual_rms_px", "energy", "evaluations"):
        if key in b.extra and b.extra[key] is not None:
            lines.append(f"  {key:12s} {b.extra[key]:.4g}" if _finite(b.extra[key]) else f"  {key:12s} undetermined")
    return "\n".join(lines)


def format_table(report: EstimateReport, camera: LineScanCamera | None = None, units: str = "m/s") -> str:
    """All balls of a report (see :func:`format_ball`), or a one-line note when none was found."""
    if not report.balls:
        return f"{report.image}: no ball found"
    frame = " (world frame from the camera's pose)" if camera is not None and camera.has_pose else ""
    head = f"{report.image}: {len(report.balls)} ball(s){frame}"
    return head + "\n" + "\n".join(format_ball(k, b, camera, units) for k, b in enumerate(report.balls))


def _num(v) -> str:
    return repr(float(v)) if _finite(v) else ""


def _three(prefix: str, suffix: str, v, names=("x", "y", "z")) -> dict:
    return {f"{prefix}{n}{suffix}": ("" if v is None else _num(v[i])) for i, n in enumerate(names)}


def csv_row(source: str, k: int, b: BallEstimate, camera: LineScanCamera | None = None) -> dict:
    """One ball as a row of :data:`CSV_COLUMNS` (world and launch columns empty without a pose)."""
    der = b.derived(camera)
    sig = b.covariance is not None and der is not None
    row = {
        "source": source, "ball": k,
        "first_line": "" if b.first_line is None else int(b.first_line),
        "last_line": "" if b.last_line is None else int(b.last_line),
        "t_c_s": _num(b.t_c_s), **_three("", "_m", b.position_m), **_three("v", "_mps", b.velocity_mps),
        "speed_mps": _num(b.speed_mps), "t_c_sigma_s": _num(b.t_c_sigma_s),
        **_three("", "_sigma_m", b.position_sigma_m), **_three("v", "_sigma_mps", b.velocity_sigma_mps),
        "speed_sigma_mps": _num(b.speed_sigma_mps),
        "flags": " ".join(b.flags), "undetermined": " ".join(b.undetermined), "method": b.method,
    }  # fmt: skip
    row.update({c: "" for c in CSV_COLUMNS if c not in row})
    if der is None:
        return row
    row["speed_transverse_mps"] = _num(der.speed_transverse_mps)
    if b.transverse is not None:
        row["transverse_axis_y"], row["transverse_axis_z"] = _num(b.transverse.axis[1]), _num(b.transverse.axis[2])
    row["psi_y_deg"], row["psi_z_deg"] = _num(der.direction_deg[0]), _num(der.direction_deg[1])
    if sig:
        row["speed_transverse_sigma_mps"] = _num(der.speed_transverse_sigma_mps)
        row["psi_y_sigma_deg"], row["psi_z_sigma_deg"] = _num(der.direction_sigma_deg[0]), _num(der.direction_sigma_deg[1])
    if der.world_velocity_mps is not None:
        row.update(_three("world_", "_m", der.world_position_m))
        row.update(_three("world_v", "_mps", der.world_velocity_mps))
        row["elevation_deg"], row["azimuth_deg"] = _num(der.elevation_deg), _num(der.azimuth_deg)
        if sig:
            row.update(_three("world_", "_sigma_m", der.world_position_sigma_m))
            row.update(_three("world_v", "_sigma_mps", der.world_velocity_sigma_mps))
            row["elevation_sigma_deg"], row["azimuth_sigma_deg"] = _num(der.elevation_sigma_deg), _num(der.azimuth_sigma_deg)
    return row
