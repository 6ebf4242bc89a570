"""The ``ballscan`` command: a thin layer over the library (geometry.md "Command line contract").

Every error the library raises as :class:`~ballscan.errors.BallscanError`
(or a ``ValueError`` from argument checking) is printed as one line on
stderr with exit status 2; nothing prints a traceback.
"""

from __future__ import annotations

import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import Optional

import typer

from ..errors import BallscanError, interrupt_behind

#: The presets and their ball radii (``ballscan.lab.presets.PRESETS``; written here so that ``--help`` loads no renderer).
PRESET_HELP = "tennis-serve (R 0.0335 m), table-tennis (0.020 m), golf-drive (0.02135 m), baseball-pitch (0.0366 m), paper-rail (0.0335 m)"

app = typer.Typer(add_completion=False, no_args_is_help=True, rich_markup_mode=None, help="Ball position and velocity from line-scan images.")


def _print_version(value: bool) -> None:
    if value:
        from .. import __version__

        typer.echo(f"ballscan {__version__}")
        raise typer.Exit()


@app.callback()
def _options(
    version: bool = typer.Option(False, "--version", callback=_print_version, is_eager=True, help="Print the version and exit."),
) -> None:
    """Ball position and velocity from line-scan images."""


def _vec(text: str, name: str) -> tuple[float, float, float]:
    try:
        vals = [float(v) for v in text.split(",")]
    except ValueError:
        raise typer.BadParameter(f"expected three comma-separated numbers, got {text!r}", param_hint=name) from None
    if len(vals) != 3:
        raise typer.BadParameter(f"expected three comma-separated numbers, got {text!r}", param_hint=name)
    return (vals[0], vals[1], vals[2])


# ---------------------------------------------------------------- simulate
@app.command()
def simulate(
    out: Optional[Path] = typer.Option(None, "--out", help="Output name: writes OUT.png, OUT.camera.toml, OUT.truth.json."),
    camera: Optional[Path] = typer.Option(None, "--camera", help="Camera TOML (geometry.md)."),
    preset: Optional[str] = typer.Option(None, "--preset", help=f"Named scene (ball radius): {PRESET_HELP}."),
    radius: Optional[float] = typer.Option(None, "--radius", help="Ball radius R, metres."),
    position: Optional[str] = typer.Option(None, "--position", help="Centre at t_c: X,Y,Z in metres (X = 0)."),
    velocity: Optional[str] = typer.Option(None, "--velocity", help="Velocity VX,VY,VZ in m/s."),
    t_c: Optional[float] = typer.Option(None, "--t-c", help="Crossing time t_c, seconds."),
    lines: Optional[int] = typer.Option(None, "--lines", help="Number of scan lines."),
    noise: str = typer.Option("default", "--noise", help="'default' (8-bit sensor noise) or 'none' (clean 16-bit render)."),
    seed: int = typer.Option(0, "--seed", help="Seed of the sensor noise."),
    bits: Optional[int] = typer.Option(None, "--bits", help="Output bit depth 8, 12 or 16 (default: 8 with noise, 16 without)."),
    texture: str = typer.Option("none", "--texture", help="'none' or 'tennis' (seam band)."),
    ball_level: Optional[float] = typer.Option(None, "--ball-level", help="Ball albedo, linear 0..1."),
    background: float = typer.Option(0.1, "--background", help="Background level, linear 0..1 (above the ball's for a dark ball)."),
    flat: bool = typer.Option(False, "--flat", help="No shading (uniform ball)."),
    extra_ball: list[str] = typer.Option([], "--add-ball", help="Another ball: 'R;X,Y,Z;VX,VY,VZ;T_C' (repeatable)."),
    stream: Optional[Path] = typer.Option(None, "--stream", help="Render a raw line stream instead: writes STREAM, STREAM.camera.toml, STREAM.truth.jsonl (needs --lines and --balls)."),
    balls: int = typer.Option(10, "--balls", help="With --stream: number of balls at random times and positions."),
    force: bool = typer.Option(False, "--force", help="Write through an output that is a symbolic link (refused otherwise)."),
    rig: Optional[str] = typer.Option(None, "--rig", help="Rig TOML or rig preset (lane-90, lane-30, tee): one image per camera of the same ball, OUT.rig.toml and a world-frame OUT.truth.json (--position, --velocity world frame, --t-c rig clock)."),
    rig_only: list[str] = typer.Option([], "--only", help="With --rig: draw the ball in this camera only (repeatable; the others' images are empty)."),
    unknown_clock: list[str] = typer.Option([], "--unknown-clock", help="With --rig: write this camera's clock offset as \"unknown\" (repeatable)."),
    clock_offset: list[str] = typer.Option([], "--clock-offset", help="With --rig: NAME=SECONDS, the camera's true clock offset (repeatable)."),
) -> None:
    """Render a synthetic line-scan image (or, with --stream, a raw line stream; with --rig, one per camera) with its camera file and ground truth."""
    from ..lab.simulate import SimulationRequest, run_simulation

    if rig is not None:
        from .rig import simulate_rig_command

        if out is None:
            raise ValueError("simulate --rig: give --out NAME")
        pos = _vec(position, "--position") if position else None
        vel = _vec(velocity, "--velocity") if velocity else None
        for p in simulate_rig_command(rig, out, radius_m=radius, position_m=pos, velocity_mps=vel, t_c_s=t_c, n_lines=lines, noise=noise, seed=seed,
                                      only=rig_only, unknown=unknown_clock, offsets=clock_offset):
            typer.echo(str(p))
        return

    if stream is not None:
        from ..geometry.camera import load_camera
        from ..stream.sources import simulate_stream

        if camera is None and preset is None:
            raise ValueError("simulate --stream: give --camera CAMERA.toml or --preset NAME")
        if lines is None or lines < 1:
            raise ValueError("simulate --stream: give --lines N (lines in the stream)")
        from ..lab.presets import get_preset

        chosen = get_preset(preset) if preset is not None else None
        cam = load_camera(camera) if camera is not None else chosen.camera
        r_m = radius if radius is not None else (chosen.motion.radius_m if chosen is not None else None)
        if r_m is None:
            raise ValueError("simulate --stream: give --radius R (or a --preset)")
        simulate_stream(stream, cam, lines, balls, seed, radius_m=r_m, force=force)
        for p in (stream, Path(f"{stream}.camera.toml"), Path(f"{stream}.truth.jsonl")):
            typer.echo(str(p))
        return
    if out is None:
        raise ValueError("simulate: give --out NAME (or --stream FILE)")
    req = SimulationRequest(
        out=out,
        camera_path=camera,
        preset=preset,
        radius_m=radius,
        position_m=_vec(position, "--position") if position else None,
        velocity_mps=_vec(velocity, "--velocity") if velocity else None,
        t_c_s=t_c,
        n_lines=lines,
        noise=noise,
        seed=seed,
        bits=bits,
        texture=texture,
        ball_level=ball_level,
        background_level=background,
        shading=not flat,
        extra_balls=tuple(extra_ball),
        force=force,
    )
    written = run_simulation(req)
    for p in written:
        typer.echo(str(p))


# ---------------------------------------------------------------- estimate
@app.command()
def estimate(
    images: list[Path] = typer.Argument(..., help="Line-scan image (PNG or TIFF, rows = scan lines); with --rig one per camera, in the rig's order."),
    camera: Optional[Path] = typer.Option(None, "--camera", help="Camera TOML (geometry.md)."),
    radius: float = typer.Option(..., "--radius", help="Ball radius R, metres."),
    method: Optional[str] = typer.Option(None, "--method", help="'fit' (sub-pixel least squares, default) or 'paper' (Zhao & Wen)."),
    as_json: bool = typer.Option(False, "--json", help="Print geometry.md's JSON instead of a table."),
    as_csv: bool = typer.Option(False, "--csv", help="Print CSV instead of a table: a header and one row per ball (the columns of batch)."),
    units: str = typer.Option("m/s", "--units", help="Speed unit of the table: m/s, km/h or mph (JSON and CSV stay in m/s)."),
    plot: Optional[Path] = typer.Option(None, "--plot", help="Write an overlay PNG (initial guess dashed orange, estimate blue; of a long recording, the lines around its first ball)."),
    max_pixels: int = typer.Option(2**28, "--max-pixels", help="Refuse images whose header claims more pixels (a guard against forged headers; raise it for long recordings)."),
    timestamps: Optional[Path] = typer.Option(None, "--timestamps", help="Per-line timestamps (text or .npy), seconds."),
    lines_as_columns: bool = typer.Option(False, "--lines-as-columns", help="The image stores time along the columns."),
    saturation: Optional[float] = typer.Option(None, "--saturation", help="Saturation level in DN (default: the type's maximum)."),
    shading: Optional[bool] = typer.Option(None, "--shading/--no-shading", help="The fit's shading-aware second pass (default on; off takes about 40 % less time per ball, V.z less accurate)."),
    pixels: Optional[bool] = typer.Option(
        None, "--pixels/--no-pixels", help="Fit the pixels of the ball's ends (uniform, untextured balls and a continuous exposure: closer to the Cramér–Rao bound, about twice the time; not for textured balls)."
    ),
    matched: Optional[bool] = typer.Option(
        None, "--matched/--no-matched", help="Matched edges on uniform balls of a flat-fielded sensor (default on; extra 'edges' says where they were used)."
    ),
    flat_field: Optional[bool] = typer.Option(
        None, "--flat-field/--no-flat-field", help="On a sensor whose column gains scatter (PRNU): matched edges on the image with the ball's measured gains divided out, on balls of >= 250 lines (default on; extra 'flat_fielded' says where)."
    ),
    recipe_file: Optional[Path] = typer.Option(
        None, "--recipe", help="Recipe file: the estimator's settings that differ from its default (TOML, or a result JSON whose 'recipe' it takes; docs/geometry.md). The flags above override it."
    ),
    force: bool = typer.Option(False, "--force", help="Write --plot through a symbolic link (refused otherwise)."),
    rig: Optional[Path] = typer.Option(None, "--rig", help="Rig TOML (docs/geometry.md): each ball matched across the cameras' images and fitted jointly, world frame."),
    constraint: Optional[str] = typer.Option(None, "--constraint", help="Known constraint, world frame (the camera frame without a pose): 'plane:NX,NY,NZ,D[,SIGMA_M[,SIGMA_DEG]]' (the ball rolls on n.X = D) or 'point:X,Y,Z[,SIGMA_M]'."),
) -> None:
    """Measure every ball in a line-scan image.

    An image longer than 8192 lines (the stream engine's buffer) is measured
    as a stream of its lines: in its stored type, in bounded memory (an
    uncompressed TIFF is memory-mapped), each ball on its own crop.
    """
    from ..geometry.camera import load_camera
    from ..measure.images import load_timestamps, read_stored
    from ..pipeline.report import UNITS, format_table
    from ..stream.recording import measure_stored

    from .options import check_radius_option, recipe_from_options

    radius = check_radius_option(radius)
    recipe = recipe_from_options(recipe_file, method=method, shading=shading, pixels=pixels, matched=matched, flat_field=flat_field)
    if rig is not None or constraint is not None:
        from .rig import estimate_rig_command

        if rig is None and (camera is None or len(images) != 1):
            raise ValueError("estimate --constraint without --rig: give one image and --camera")
        estimate_rig_command(images, rig, camera, radius, constraint, recipe, as_json)
        return
    if camera is None:
        raise ValueError("estimate: give --camera CAMERA.toml (or --rig RIG.toml)")
    if len(images) != 1:
        raise ValueError(f"estimate: one image per command without --rig, got {len(images)}")
    image = images[0]
    if as_json and as_csv:
        raise typer.BadParameter("give one of --json and --csv", param_hint="--csv")
    if units not in UNITS:
        raise typer.BadParameter(f"expected one of {', '.join(UNITS)}, got {units!r}", param_hint="--units")
    if not max_pixels > 0:
        raise typer.BadParameter(f"must be positive, got {max_pixels}", param_hint="--max-pixels")
    cam = load_camera(camera)
    if plot is not None:
        from ..outputs import check_not_symlink

        check_not_symlink(plot, force)  # before the work, not after it
    stored = read_stored(image, lines_as_columns=lines_as_columns, max_pixels=max_pixels)
    ts = load_timestamps(timestamps, stored.n_lines) if timestamps else None
    report = measure_stored(stored, cam, radius, recipe, timestamps_s=ts, saturation_dn=saturation)
    if as_json:
        typer.echo(report.to_json(cam))
    elif as_csv:
        _print_csv(report, cam)
    else:
        typer.echo(format_table(report, cam, units))
    if plot is not None:
        _plot(plot, stored, cam, report, ts, force)


def _plot(path: Path, stored, camera, report, timestamps_s, force: bool = False) -> None:
    """The overlay of the whole image, or of a long recording's lines around its first ball (in its own line numbers)."""
    import numpy as np

    from ..geometry.camera import line_times
    from ..pipeline.plot import save_overlay
    from ..stream.recording import is_recording

    t = line_times(camera, stored.n_lines, timestamps_s)
    lo, hi = 0, stored.n_lines
    if is_recording(stored) and report.balls:
        first = report.balls[0]
        lo = max((first.first_line or 0) - 64, 0)
        hi = min((first.last_line or 0) + 65, stored.n_lines)
        report = replace(report, balls=(first,))
    data = np.asarray(stored.data[lo:hi], dtype=float)
    if data.ndim == 3:
        data = data[:, :, :3] @ np.array([0.299, 0.587, 0.114])
    save_overlay(path, data, camera, report, t[lo:hi], first_line=lo, force=force)


def _print_csv(report, camera) -> None:
    import csv

    from ..pipeline.report import CSV_COLUMNS, csv_row

    writer = csv.DictWriter(sys.stdout, fieldnames=CSV_COLUMNS, lineterminator="\n")
    writer.writeheader()
    for k, ball in enumerate(report.balls):
        writer.writerow(csv_row(report.image, k, ball, camera))


# ---------------------------------------------------------------- precision
@app.command()
def precision(
    camera: Optional[Path] = typer.Option(None, "--camera", help="Camera TOML (geometry.md)."),
    radius: float = typer.Option(..., "--radius", help="Ball radius R, metres."),
    velocity: str = typer.Option(..., "--velocity", help="Velocity VX,VY,VZ in m/s (camera frame; world frame with --rig or --constraint)."),
    position: str = typer.Option(..., "--position", help="Centre at the crossing, X,Y,Z in metres (X = 0)."),
    edge_noise: Optional[float] = typer.Option(None, "--edge-noise", help="1-sigma of one edge measurement, pixels."),
    pixel_noise: Optional[float] = typer.Option(None, "--pixel-noise", help="Pixel noise 1-sigma in DN (with --contrast): bound for any estimator on the image."),
    contrast: Optional[float] = typer.Option(None, "--contrast", help="Ball/background contrast in DN (with --pixel-noise)."),
    prnu: float = typer.Option(0.0, "--prnu", help="Relative 1-sigma of the columns' gains (PRNU) not flat-fielded, e.g. 0.008 (with --pixel-noise)."),
    as_json: bool = typer.Option(False, "--json", help="Print JSON (one object per bound, under \"bounds\") instead of tables."),
    rig: Optional[Path] = typer.Option(None, "--rig", help="Rig TOML or rig preset (lane-90, lane-30, tee): the joint bound, world frame (--position is the centre at the reference camera's crossing; --edge-noise, default 0.1 px)."),
    constraint: Optional[str] = typer.Option(None, "--constraint", help="Known constraint as for estimate: 'plane:NX,NY,NZ,D[,SIGMA_M[,SIGMA_DEG]]' or 'point:X,Y,Z[,SIGMA_M]'."),
    sweep: Optional[str] = typer.Option(None, "--sweep", help="With --rig: START:STOP:STEP degrees, the second camera turned about the ball's path; prints sigma(direction) per angle."),
    sweep_plot: Optional[Path] = typer.Option(None, "--plot", help="With --sweep: write the sweep's plot (PNG)."),
) -> None:
    """Print the Cramér–Rao bound (1-sigma) on position, velocity and speed for a camera or a rig."""
    from ..geometry.camera import load_camera
    from ..geometry.motion import BallMotion
    from ..solve.precision import edge_crlb, pixel_crlb

    if not radius > 0:
        raise typer.BadParameter(f"must be positive, got {radius}", param_hint="--radius")
    if rig is not None or constraint is not None or sweep is not None:
        from .rig import precision_rig_command

        if rig is None and camera is None:
            raise ValueError("precision: give --camera CAMERA.toml or --rig RIG.toml")
        if sweep is not None and rig is None:
            raise ValueError("precision --sweep: give --rig RIG.toml (the sweep turns its second camera)")
        precision_rig_command(rig, camera, radius, _vec(position, "--position"), _vec(velocity, "--velocity"), edge_noise if edge_noise is not None else 0.1,
                              constraint, sweep, sweep_plot, as_json)
        return
    if camera is None:
        raise ValueError("precision: give --camera CAMERA.toml (or --rig RIG.toml)")
    cam = load_camera(camera)
    pos = _vec(position, "--position")
    vel = _vec(velocity, "--velocity")
    if vel[0] == 0:
        raise typer.BadParameter("VX must be non-zero (the ball must cross the viewing plane)", param_hint="--velocity")
    # the bound assumes an image starting at line 0 that holds the whole ball:
    # put the crossing after half the ball's visible duration plus a margin
    from ..model.silhouette import visible_line_count

    probe = BallMotion(radius, 0.0, pos, vel)
    t_c = (0.6 * visible_line_count(cam, probe) + 5.0) / cam.line_rate_hz
    motion = BallMotion(radius, t_c, pos, vel)
    if edge_noise is None and pixel_noise is None:
        raise ValueError("precision: give --edge-noise PX, or --pixel-noise DN with --contrast DN")
    if prnu and pixel_noise is None:
        raise ValueError("precision: --prnu is a property of the pixels: give it with --pixel-noise DN and --contrast DN")
    bounds = []
    if edge_noise is not None:
        if not edge_noise > 0:
            raise typer.BadParameter(f"must be positive, got {edge_noise}", param_hint="--edge-noise")
        bounds.append(edge_crlb(cam, motion, edge_noise))
    if pixel_noise is not None:
        if contrast is None or not contrast != 0 or not pixel_noise > 0:
            raise ValueError("precision: --pixel-noise needs a positive noise and a non-zero --contrast")
        if not 0 <= prnu < 1:
            raise typer.BadParameter(f"must be in [0, 1), got {prnu}", param_hint="--prnu")
        bounds.append(pixel_crlb(cam, motion, pixel_noise, abs(contrast), prnu_sigma=prnu))
    if as_json:
        import json

        typer.echo(json.dumps({"bounds": [b.to_dict() for b in bounds]}, indent=2, allow_nan=False))
    else:
        for b in bounds:
            typer.echo(b.to_text())


# ---------------------------------------------------------------- demo
@app.command()
def demo(
    out: Path = typer.Option(Path("demo_out"), "--out", help="Folder for the example files."),
    preset: str = typer.Option("tennis-serve", "--preset", help=f"Scene to render (ball radius): {PRESET_HELP}."),
) -> None:
    """Render an example, estimate it with both methods and plot the result."""
    from ..lab.demo import run_demo

    for line in run_demo(out, preset):
        typer.echo(line)


@app.command("warm-up")
def warm_up_command() -> None:
    """Compile (or load) every numerical kernel now, with progress: the first measurement after an install then starts at once.

    The compiled code is cached on disk (beside the package's sources, or
    in NUMBA_CACHE_DIR when that is set: point it at a shared folder for a
    cluster's workers).
    """
    from ..pipeline.warmup import KERNEL_MODULES, warm_up

    done = warm_up((*KERNEL_MODULES, "ballscan.stream._line_kernels"), show=None)
    typer.echo(f"{done.kernels} kernels ready ({done.compiled} compiled now) in {done.time_s:.1f} s; cache: {done.cache_dir or 'none (memory only)'}")


@app.command()
def view(
    results: Path = typer.Argument(..., help="A saved run: a 'watch --save-events' folder, a 'batch' CSV or JSON lines ('watch' output)."),
    serve: str = typer.Option("8000", "--serve", metavar="[HOST:]PORT", help="Where to serve the page (host default 127.0.0.1: this machine only)."),
    camera: Optional[Path] = typer.Option(None, "--camera", help="The run's camera TOML: a saved event's crop then shows its fitted outline."),
) -> None:
    """Serve the live page over a saved run: every ball, filters by flag and speed range, the table as CSV (until Ctrl-C)."""
    from ..geometry.camera import load_camera
    from ..live.replay import load_run
    from ..live.server import LiveServer, parse_address

    try:
        host, port = parse_address(serve)
    except ValueError as exc:
        raise typer.BadParameter(str(exc).removeprefix("--serve: "), param_hint="--serve") from None
    run = load_run(results, load_camera(camera) if camera is not None else None)
    server = LiveServer(run, host, port, title=f"ballscan view {results}")
    url = server.start()
    print(f"ballscan view: {len(run.all_balls)} balls of {results} at {url} (Ctrl-C stops)", file=sys.stderr, flush=True)
    try:
        while server.serving:
            time.sleep(0.2)
    except KeyboardInterrupt:
        pass
    finally:
        server.stop()


def _register_subcommands() -> None:
    """Experiments and line streams live in their own modules; the commands are theirs."""
    from .experiment import experiment_app
    from .rig import rig_app
    from .stream import batch, watch

    app.add_typer(experiment_app, name="experiment")
    app.add_typer(rig_app, name="rig")
    app.command()(watch)
    app.command()(batch)


_register_subcommands()


def main(argv: list[str] | None = None) -> int:
    """Entry point: run the CLI, turning library errors into one-line messages."""
    args = sys.argv[1:] if argv is None else list(argv)
    if not args:
        args = ["--help"]  # bare `ballscan`: the overview, and success
    from .signals import ExitStatus, Stopped, stop_signals

    try:
        with stop_signals(graceful=False):  # watch asks for a graceful stop within
            app(args=args, prog_name="ballscan", standalone_mode=False)
    except ExitStatus as exc:
        if exc.message:
            print(f"ballscan: {exc.message}", file=sys.stderr)
        return exc.code
    except Stopped as exc:
        print(f"ballscan: stopped by {exc}", file=sys.stderr)
        return exc.exit_code
    except BallscanError as exc:
        print(f"ballscan: error: {exc}", file=sys.stderr)
        return 2
    except (ValueError, OSError) as exc:
        print(f"ballscan: error: {exc}", file=sys.stderr)
        return 2
    except typer.Exit as exc:
        return exc.exit_code
    except typer.Abort:
        print("ballscan: aborted", file=sys.stderr)
        return 1
    except Exception as exc:
        stop = interrupt_behind(exc)
        if isinstance(stop, Stopped):  # a stop signal surfacing through a compiled kernel's return
            print(f"ballscan: stopped by {stop}", file=sys.stderr)
            return stop.exit_code
        # usage errors of the (vendored) click parser: show them the click way
        if hasattr(exc, "show") and hasattr(exc, "exit_code"):
            exc.show()
            return int(exc.exit_code)
        raise
    return 0


def run() -> None:
    """The ``ballscan`` program (its console script and ``python -m ballscan``): :func:`main`, then exit with its status.

    The process is the program's own: its large working arrays reuse freed
    memory (:func:`ballscan.parallel.reuse_freed_memory`).  Before the
    interpreter's teardown, every object is moved out of the garbage
    collector's reach (``gc.freeze``): the teardown's collections then free
    the loaded modules and compiled kernels without walking them again and
    again.  Only here, where the process ends next: frozen objects are never
    collected.
    """
    from ..parallel import reuse_freed_memory

    reuse_freed_memory()
    code = main()
    import gc

    gc.freeze()
    sys.exit(code)


if __name__ == "__main__":  # pragma: no cover
    run()
