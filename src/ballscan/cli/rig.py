"""Command functions for rigs of several cameras: ``ballscan rig check`` and the ``--rig`` forms of simulate, estimate and precision.

They parse and print; :mod:`ballscan.geometry.rig`, :mod:`ballscan.lab.rig`,
:mod:`ballscan.pipeline.rig` and :mod:`ballscan.solve.rig_precision` do the work.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Optional

import typer

__all__ = ["estimate_rig_command", "precision_rig_command", "rig_app", "simulate_rig_command"]

rig_app = typer.Typer(add_completion=False, no_args_is_help=True, rich_markup_mode=None, help="Rigs of several cameras (docs/geometry.md, 'Rig file').")


@rig_app.command("check")
def check(rig: Path = typer.Argument(..., help="Rig TOML (docs/geometry.md), or a rig preset: lane-90, lane-30, tee.")) -> None:
    """Print each camera's viewing plane in the world frame and where the planes cross."""
    from ..lab.rig import rig_scene
    from ..pipeline.rig import check_lines

    r, _ = rig_scene(str(rig))
    for line in check_lines(r):
        typer.echo(line)


def _offsets(specs: list[str]) -> dict[str, float]:
    out = {}
    for s in specs:
        name, _, v = s.partition("=")
        try:
            out[name] = float(v)
        except ValueError:
            raise typer.BadParameter(f"expected NAME=SECONDS, got {s!r}", param_hint="--clock-offset") from None
    return out


def simulate_rig_command(
    rig: str, out: Path, *, radius_m, position_m, velocity_mps, t_c_s, n_lines, noise: str, seed: int, only: list[str], unknown: list[str], offsets: list[str]
) -> list[Path]:
    """``ballscan simulate --rig``: one image per camera of the same ball, a rig file and a world-frame truth."""
    from dataclasses import replace

    from ..lab.rig import reference_crossing_motion, rig_scene, simulate_rig, write_rig_simulation
    from ..model.render import Appearance, SensorNoise

    r, preset = rig_scene(rig)
    if preset is not None:
        m = preset.motion
        motion = replace(
            m,
            radius_m=radius_m if radius_m is not None else m.radius_m,
            position_m=position_m if position_m is not None else m.position_m,
            velocity_mps=velocity_mps if velocity_mps is not None else m.velocity_mps,
            t_ref_s=t_c_s if t_c_s is not None else m.t_ref_s,
        )
        lines, app = n_lines or preset.n_lines, preset.appearance
    else:
        missing = [n for n, v in (("--radius", radius_m), ("--position", position_m), ("--velocity", velocity_mps), ("--lines", n_lines)) if v is None]
        if missing:
            raise ValueError("simulate --rig RIG.toml: these are required: " + ", ".join(missing))
        cam0 = r.cameras[r.reference].camera
        t_c = t_c_s if t_c_s is not None else 0.5 * (n_lines - 1) / cam0.line_rate_hz
        motion = reference_crossing_motion(r, radius_m, position_m, velocity_mps, t_c)
        lines, app = n_lines, Appearance()
    if noise == "none":
        sn = SensorNoise.none(16)
    elif noise == "default":
        sn = SensorNoise()
    else:
        raise ValueError(f"--noise: expected 'default' or 'none', got {noise!r}")
    for name in [*only, *unknown, *_offsets(offsets)]:
        if name not in r.names:
            raise ValueError(f"simulate --rig: no camera {name!r} in the rig (cameras: {', '.join(r.names)})")
    sim = simulate_rig(r, motion, lines, app, clock_offsets_s=_offsets(offsets), noise=sn, seed=seed, cameras=tuple(only) or None)
    return write_rig_simulation(sim, out, unknown_clocks=tuple(unknown), seed=seed)


def estimate_rig_command(images: list[Path], rig: Optional[Path], camera: Optional[Path], radius_m: float, constraint: Optional[str], recipe, as_json: bool) -> None:
    """``ballscan estimate --rig RIG.toml A.png B.png`` (or one image with ``--camera`` and ``--constraint``)."""
    from ..geometry.camera import load_camera
    from ..geometry.rig import load_rig
    from ..pipeline.rig import estimate_rig, single_camera_rig
    from ..solve.constraint import parse_constraint

    con = parse_constraint(constraint) if constraint else None
    r = load_rig(rig) if rig is not None else single_camera_rig(load_camera(camera))
    report = estimate_rig([str(p) for p in images], r, radius_m, recipe=recipe, constraint=con)
    if as_json:
        typer.echo(report.to_json())
        return
    typer.echo(f"{'ball':>4} {'cameras':<16} {'t_c [s]':>12} {'speed [m/s]':>20} {'elevation [deg]':>18} {'azimuth [deg]':>18}  flags")
    for k, b in enumerate(report.balls):
        if b.motion is None:
            typer.echo(f"{k:>4} {'+'.join(b.cameras):<16} {'undetermined':>12}  {' '.join(b.flags)}")
            continue
        t_c = f"{b.t_c_s:12.6f}" if b.t_c_determined else f"{'undetermined':>12}"
        unknown = f" ({', '.join(b.undetermined)})" if b.undetermined else ""
        if b.velocity_determined:
            sp, sp_s = b.speed()
            el, el_s, az, az_s = b.direction()
            typer.echo(f"{k:>4} {'+'.join(b.cameras):<16} {t_c} {sp:10.3f} +- {sp_s:<7.3g} {el:8.3f} +- {el_s:<6.3g} {az:8.3f} +- {az_s:<6.3g}  {' '.join(b.flags)}{unknown}")
        else:
            typer.echo(f"{k:>4} {'+'.join(b.cameras):<16} {t_c} {'undetermined':>20} {'undetermined':>18} {'undetermined':>18}  {' '.join(b.flags)}{unknown}")
        if b.joint is not None:
            for c in b.joint.cameras:
                clock = f", clock offset {c.clock_offset_s:+.4g} +- {c.clock_offset_sigma_s:.2g} s" if c.clock_offset_sigma_s else ""
                verdict = "consistent" if c.consistent else "INCONSISTENT"
                typer.echo(f"       {c.name}: chi2_red {c.chi2_red:.3g} (alone {c.chi2_red_own:.3g}), delta_chi2 {c.delta_chi2:.3g}: {verdict}{clock}")
            if b.joint.constraint is not None:
                typer.echo(f"       constraint {b.joint.constraint.kind}: residuals {', '.join(f'{v:+.2f}' for v in b.joint.constraint_residuals)} sigma")


def _sweep(text: str) -> list[float]:
    try:
        a, b, step = (float(v) for v in text.split(":"))
    except ValueError:
        raise typer.BadParameter(f"expected START:STOP:STEP in degrees, got {text!r}", param_hint="--sweep") from None
    if not step > 0 or b < a:
        raise typer.BadParameter(f"expected START <= STOP and STEP > 0, got {text!r}", param_hint="--sweep")
    n = int(math.floor((b - a) / step + 1e-9)) + 1
    return [a + i * step for i in range(n)]


def precision_rig_command(
    rig: Optional[Path], camera: Optional[Path], radius_m: float, position_m, velocity_mps, edge_noise_px: float, constraint: Optional[str],
    sweep: Optional[str], plot: Optional[Path], as_json: bool,
) -> None:
    """``ballscan precision --rig RIG.toml`` (world frame), ``--sweep`` over the second camera's angle, ``--constraint``."""
    from ..geometry.camera import load_camera
    from ..geometry.rig import WorldMotion
    from ..lab.rig import rig_scene
    from ..pipeline.rig import single_camera_rig
    from ..solve.constraint import parse_constraint
    from ..solve.rig_precision import rig_crlb, sweep_second_camera

    if rig is not None:
        r, _ = rig_scene(str(rig))
    else:
        r = single_camera_rig(load_camera(camera))
    con = parse_constraint(constraint) if constraint else None
    motion = WorldMotion(radius_m, 0.0, position_m, velocity_mps, tuple(r.gravity_vector()))
    if not edge_noise_px > 0:
        raise typer.BadParameter(f"must be positive, got {edge_noise_px}", param_hint="--edge-noise")
    if sweep is None:
        b = rig_crlb(r, motion, edge_noise_px=edge_noise_px, constraint=con)
        typer.echo(json.dumps(b.to_dict(), indent=2) if as_json else b.to_text())
        return
    rows = sweep_second_camera(r, motion, _sweep(sweep), edge_noise_px=edge_noise_px, constraint=con)
    if as_json:
        typer.echo(json.dumps({"sweep": [{"angle_deg": a, **b.to_dict()} for a, b in rows]}, indent=2))
    else:
        typer.echo(f"{'angle [deg]':>11} {'direction':>11} {'elevation':>11} {'azimuth':>11} {'speed [m/s]':>12}   (1-sigma bounds, degrees)")
        for a, b in rows:
            typer.echo(f"{a:11.1f} {b.direction_sigma_deg:11.4g} {b.elevation_sigma_deg:11.4g} {b.azimuth_sigma_deg:11.4g} {b.speed_sigma_mps:12.4g}")
    if plot is not None:
        from ..lab.rig import plot_sweep

        plot_sweep(rows, plot)
        typer.echo(str(plot))



@rig_app.command("watch")
def watch(
    rig: Path = typer.Argument(..., help="Rig TOML (docs/geometry.md)."),
    sources: list[str] = typer.Argument(..., help="One line source per camera, in the rig's order (as for 'ballscan watch': a raw file, a named pipe, '-', a folder of image chunks, pylon[:SERIAL])."),
    radius: float = typer.Option(..., "--radius", help="Ball radius R, metres."),
    dtype: str = typer.Option("uint8", "--dtype", help="Sample type of raw sources: uint8 or uint16."),
    chunk_lines: int = typer.Option(1024, "--chunk-lines", help="Lines read at a time from each source."),
    timeout: Optional[float] = typer.Option(None, "--timeout", help="Give up when a pipe or a camera sends nothing for this many seconds."),
    pair_timeout: float = typer.Option(2.0, "--pair-timeout", help="Wall seconds a ball waits for the other cameras' balls before it is measured with what came."),
    constraint: Optional[str] = typer.Option(None, "--constraint", help="Known constraint as for estimate (world frame)."),
) -> None:
    """Measure a rig's line streams as they arrive: one joint JSON line per ball (world frame), paired across the cameras by time."""
    from ..geometry.rig import load_rig
    from ..solve.constraint import parse_constraint
    from ..stream.rig import pair_streams
    from .options import check_radius_option
    from .stream import open_source

    radius = check_radius_option(radius)
    if not pair_timeout > 0:
        raise typer.BadParameter(f"must be positive, got {pair_timeout}", param_hint="--pair-timeout")
    r = load_rig(rig)
    con = parse_constraint(constraint) if constraint else None
    if len(sources) != len(r.cameras):
        raise ValueError(f"rig watch: {len(sources)} sources for {len(r.cameras)} cameras ({', '.join(r.names)}); give one per camera in the rig's order")
    srcs = [open_source(s, rc.camera, dtype=dtype, chunk_lines=chunk_lines, timeout_s=timeout) for s, rc in zip(sources, r.cameras)]
    for ball in pair_streams(srcs, r, radius, constraint=con, pair_timeout_s=pair_timeout):
        typer.echo(ball.to_json(own=False))
