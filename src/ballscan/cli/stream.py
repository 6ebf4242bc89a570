"""Command functions for line streams: ``ballscan watch`` and ``ballscan batch``.

The functions take typer ``Annotated`` parameters with real defaults, so
they are both typer commands (``app.command()(watch)``) and plain Python
functions. They hold no logic: :mod:`ballscan.stream.engine`,
:mod:`ballscan.stream.sources` and :mod:`ballscan.stream.batch` do the work. Faults are
raised as :class:`~ballscan.errors.BallscanError` (one-line messages) after
every result measured before them has been printed.
"""

from __future__ import annotations

import math

import json
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Optional

import typer

from ..errors import BallscanError

if TYPE_CHECKING:  # the estimator (numba, scipy) loads only when a command runs
    from ..geometry.camera import LineScanCamera
    from ..stream.engine import StreamResult

__all__ = ["watch", "batch", "format_stream_line", "open_source", "save_event"]


def open_source(
    source: str,
    camera: LineScanCamera,
    *,
    width: int | None = None,
    dtype: str = "uint8",
    chunk_lines: int = 1024,
    timestamps: Path | None = None,
    timeout_s: float | None = None,
    pfs: Path | None = None,
    pixel_format: str | None = None,
    pylon_timestamps: str = "none",
    stop=None,
):
    """The line source named by ``source``.

    ``-`` is standard input (raw lines), a folder is a folder of image
    chunks, ``pylon`` or ``pylon:SERIAL`` a Basler camera (line times at the
    camera file's ``line_rate_hz``), anything else a raw file or named pipe.
    ``pfs``, ``pixel_format`` and ``pylon_timestamps`` are for a camera only.
    ``stop`` (an object with ``is_set()``) ends a raw source after its
    complete lines, also while it waits for data.
    """
    from ..stream.sources import ImageFolderSource, PylonSource, RawLineSource

    if source == "pylon" or source.startswith("pylon:"):
        serial = source.partition(":")[2] or None
        return PylonSource(
            serial, line_rate_hz=camera.line_rate_hz, timeout_s=timeout_s or 5.0,
            timestamps=pylon_timestamps, pixel_format=pixel_format, pfs=pfs,
        )
    given = [name for name, v in (("--pfs", pfs), ("--pixel-format", pixel_format)) if v is not None]
    given += ["--pylon-timestamps"] if pylon_timestamps != "none" else []
    if given:
        raise ValueError(f"{' and '.join(given)}: only for a camera source (pylon or pylon:SERIAL), not {source!r}")
    w = int(width) if width is not None else camera.width
    if source != "-" and Path(source).is_dir():
        return ImageFolderSource(source, w, timestamps=timestamps)
    return RawLineSource(source, w, dtype, chunk_lines=chunk_lines, timeout_s=timeout_s, timestamps=timestamps, stop=stop)


def save_event(folder: Path, result: StreamResult, camera: LineScanCamera, ball_in_event: int) -> list[Path]:
    """Write an event's files into ``folder`` (:meth:`ballscan.stream.events.EventFolder.save`, without the folder's lock and check).

    Returns
    -------
    list of Path
        Files written.
    """
    from ..stream.events import EventFolder

    Path(folder).mkdir(parents=True, exist_ok=True)
    return EventFolder(folder).save(result, camera, ball_in_event)


class _Status:
    """A live status line on stderr (only when it is a terminal)."""

    def __init__(self, enabled: bool) -> None:
        self.enabled = enabled
        self.t0 = time.perf_counter()
        self.last = 0.0
        self.state = (0, 0, 0.0)

    def update(self, lines: int, balls: int, stream_time_s: float, force: bool = False) -> None:
        self.state = (lines, balls, stream_time_s)
        if not self.enabled:
            return
        now = time.perf_counter()
        if not force and now - self.last < 0.25:
            return
        self.last = now
        wall = now - self.t0
        # How far the stream read so far is behind the wall clock: for a
        # real-time source, the reading's delay; a recording read faster than
        # real time is not behind (0).
        behind = max(wall - stream_time_s, 0.0)
        rate = lines / wall if wall > 0 else 0.0
        sys.stderr.write(f"\r{lines:>12,d} lines | {rate / 1e3:8.1f} k lines/s | {balls:5d} balls | behind {behind * 1e3:9.1f} ms \x1b[K")
        sys.stderr.flush()

    def clear(self) -> None:
        """Wipe the status line, so that a result printed on a shared terminal starts on a clean line."""
        if self.enabled:
            sys.stderr.write("\r\x1b[K")
            sys.stderr.flush()
            self.last = 0.0  # redrawn at the next update

    def close(self, balls: int) -> None:
        if self.enabled:
            self.update(self.state[0], balls, self.state[2], force=True)
            sys.stderr.write("\n")
            sys.stderr.flush()


class _Watched:
    """Chunk iterator that feeds the status line."""

    def __init__(self, src, status: _Status, line_rate_hz: float, stop=None) -> None:
        self._it = iter(src)
        self.stop = stop
        self.status = status
        self.rate = line_rate_hz
        self.lines = 0
        self.balls = 0
        self.interrupted = False
        self._t_first: float | None = None

    def __iter__(self):
        return self

    def __next__(self):
        if self.stop is not None and self.stop.is_set():
            # a stop signal: end the stream here, so the ball in view is measured
            self.interrupted = True
            raise StopIteration
        try:
            ch = next(self._it)
        except KeyboardInterrupt:
            # Ctrl-C while waiting for lines (where a watch spends its time):
            # end the stream normally so the ball in view is still measured.
            self.interrupted = True
            raise StopIteration from None
        self.lines += int(ch.lines.shape[0])
        if ch.timestamps_s is not None and ch.timestamps_s.size:
            if self._t_first is None:
                self._t_first = float(ch.timestamps_s[0])
            span = float(ch.timestamps_s[-1]) - self._t_first
        else:
            span = self.lines / self.rate
        self.status.update(self.lines, self.balls, span)
        return ch


def watch(
    source: Annotated[list[str], typer.Argument(help="Raw lines: a file, a named pipe or '-' (stdin); a folder of PNG/TIFF chunks; or 'pylon[:SERIAL]'. With --rig one per camera, in the rig's order.")],
    camera: Annotated[Optional[Path], typer.Option("--camera", help="Camera TOML (geometry.md); required without --rig.")] = None,
    radius: Annotated[Optional[float], typer.Option("--radius", help="Ball radius R, metres.  [required]")] = None,
    width: Annotated[Optional[int], typer.Option("--width", help="Pixels per raw line (default: the camera's width).")] = None,
    dtype: Annotated[str, typer.Option("--dtype", help="Raw sample type: uint8 or uint16 (little-endian).")] = "uint8",
    chunk_lines: Annotated[int, typer.Option("--chunk-lines", help="Lines read at a time from a raw source.")] = 1024,
    timestamps: Annotated[Optional[Path], typer.Option("--timestamps", help="Per-line timestamps (text or .npy), seconds.")] = None,
    timeout: Annotated[Optional[float], typer.Option("--timeout", help="Give up when a pipe or a camera sends nothing for this many seconds (camera default 5).")] = None,
    pfs: Annotated[Optional[Path], typer.Option("--pfs", help="Camera: a pylon feature file (.pfs, saved by pylon Viewer) loaded first.")] = None,
    pixel_format: Annotated[Optional[str], typer.Option("--pixel-format", help="Camera: set its PixelFormat, Mono8, Mono12 or Mono16 (default: as it is).")] = None,
    pylon_timestamps: Annotated[str, typer.Option("--pylon-timestamps", help="Camera: the frames' times from 'none' (the line count at the camera file's line rate, default), 'grab' (the grab results' timestamps) or 'chunk' (the Timestamp chunk); lost frames (block-ID gaps) flag a ball dropped_lines.")] = "none",
    method: Annotated[Optional[str], typer.Option("--method", help="'fit' (default) or 'paper'.")] = None,
    shading: Annotated[Optional[bool], typer.Option("--shading/--no-shading", help="The fit's shading-aware second pass (default on; off takes about 40 % less time per ball, V.z less accurate).")] = None,
    matched: Annotated[Optional[bool], typer.Option("--matched/--no-matched", help="Matched edges on uniform balls of a flat-fielded sensor (default on).")] = None,
    recipe_file: Annotated[Optional[Path], typer.Option("--recipe", help="Recipe file, as for estimate (docs/geometry.md); the flags above override it.")] = None,
    background: Annotated[str, typer.Option("--background", help="Background a ball's crop is measured on: 'engine' (the stream's running model of its columns, default) or 'crop' (learned on the crop alone, as 'ballscan estimate' on the saved crop).")] = "engine",
    k_sigma: Annotated[float, typer.Option("--k-sigma", help="Ball pixels: beyond k noise sigmas of the background.")] = 4.0,
    margin_lines: Annotated[int, typer.Option("--margin-lines", help="Background lines kept before and after each ball.")] = 16,
    buffer_lines: Annotated[int, typer.Option("--buffer-lines", help="Lines in the ring buffer (longest event).")] = 8192,
    save_events: Annotated[Optional[Path], typer.Option("--save-events", help="Folder for each event's crop and overlay PNGs (and the engine's background of the crop's columns and its lines' times, .columns.npz, with which the crop's estimate is reproduced); whole files only, one watch per folder, damaged files of an earlier run rewritten.")] = None,
    output_format: Annotated[str, typer.Option("--format", help="'json' (one JSON line per ball, default) or 'table' (one readable line per ball).")] = "json",
    units: Annotated[str, typer.Option("--units", help="Speed unit of --format table: m/s, km/h or mph.")] = "m/s",
    progress: Annotated[Optional[bool], typer.Option("--progress/--no-progress", "--status/--no-status", help="Live status line on stderr (default: when stderr is a terminal).")] = None,
    jobs: Annotated[int, typer.Option("--jobs", "-j", "--workers", help="Processes that run the estimates (0: in the reading process, default).")] = 0,
    force: Annotated[bool, typer.Option("--force", help="Write --save-events files through symbolic links (refused otherwise).")] = False,
    serve: Annotated[Optional[str], typer.Option("--serve", metavar="[HOST:]PORT", help="Show the balls live on a web page at http://HOST:PORT/ (host default 127.0.0.1: this machine only; the 'live' extra). After the stream ends the page stays until Ctrl-C.")] = None,
    rig: Annotated[Optional[Path], typer.Option("--rig", help="Rig TOML (docs/geometry.md): one source per camera, each ball paired across them and fitted jointly, as 'ballscan rig watch'.")] = None,
    pair_timeout: Annotated[float, typer.Option("--pair-timeout", help="With --rig: wall seconds a ball waits for the other cameras' balls.")] = 2.0,
    constraint: Annotated[Optional[str], typer.Option("--constraint", help="With --rig: a known constraint as for estimate (world frame).")] = None,
) -> int | None:
    """Measure balls in a continuous line stream, one line per ball as it is measured.

    With --format json each line holds geometry.md's estimate keys plus
    source, first_line and last_line (stream line numbers); with --format
    table a readable line. Results go to stdout, the status line to stderr.
    The end of the stream, or Ctrl-C, SIGTERM or SIGHUP, measures the balls
    that have passed and the ball in view (flagged as cut) and stops; after
    a signal the exit status is 128 + its number (130, 143, 129). A reader
    that goes away (| head) ends the watch quietly. With --rig, the
    streams of a rig's cameras are measured as 'ballscan rig watch' does:
    one joint JSON line per ball.
    """
    sources = [source] if isinstance(source, str) else list(source)
    if radius is None:
        raise ValueError("watch: give --radius R (the ball's radius, metres)")
    if rig is not None:
        _refuse_without_rig(camera=camera, width=width, timestamps=timestamps, pfs=pfs, pixel_format=pixel_format, pylon_timestamps=pylon_timestamps,
                            method=method, shading=shading, matched=matched, recipe_file=recipe_file, background=background, k_sigma=k_sigma, margin_lines=margin_lines,
                            buffer_lines=buffer_lines, save_events=save_events, output_format=output_format, units=units, jobs=jobs, force=force, serve=serve)
        from .rig import watch as rig_watch

        return rig_watch(rig, sources, radius=radius, dtype=dtype, chunk_lines=chunk_lines, timeout=timeout, pair_timeout=pair_timeout, constraint=constraint)
    for name, value, default in (("--pair-timeout", pair_timeout, 2.0), ("--constraint", constraint, None)):
        if value != default:
            raise ValueError(f"watch: {name} needs --rig RIG.toml")
    if len(sources) != 1:
        raise ValueError(f"watch: one source without --rig, got {len(sources)} (several sources: one per camera of a --rig RIG.toml)")
    if camera is None:
        raise ValueError("watch: give --camera CAMERA.toml (or --rig RIG.toml)")
    source = sources[0]
    from ..geometry.camera import load_camera
    from ..pipeline.report import UNITS
    from ..stream.engine import StreamConfig

    from .options import check_radius_option, recipe_from_options

    cam = load_camera(camera)
    radius = check_radius_option(radius)
    if output_format not in ("json", "table"):
        raise typer.BadParameter(f"expected 'json' or 'table', got {output_format!r}", param_hint="--format")
    if units not in UNITS:
        raise typer.BadParameter(f"expected one of {', '.join(UNITS)}, got {units!r}", param_hint="--units")
    if jobs < 0:
        raise typer.BadParameter(f"must be >= 0, got {jobs}", param_hint="--jobs")
    # the settings first: a bad one is reported before a pipe or a camera is opened
    cfg = StreamConfig(k_sigma=k_sigma, margin_lines=margin_lines, buffer_lines=buffer_lines, recipe=recipe_from_options(recipe_file, method=method, shading=shading, matched=matched), background=background, keep_crops=save_events is not None or serve is not None)
    from .signals import ExitStatus, stop_signals

    with stop_signals(graceful=True) as stop, _event_folder(save_events, force) as events:
        src = open_source(
            source, cam, width=width, dtype=dtype, chunk_lines=chunk_lines, timestamps=timestamps, timeout_s=timeout,
            pfs=pfs, pixel_format=pixel_format, pylon_timestamps=pylon_timestamps, stop=stop,
        )
        if src.__class__.__name__ != "PylonSource" and getattr(src, "width", cam.width) != cam.width:
            raise BallscanError(f"--width {src.width} differs from the camera's width = {cam.width} ({camera})")
        if getattr(src, "max_dn", None) is not None and cfg.saturation_dn is None:
            # a camera's 12-bit lines saturate at 4095, not at their type's 65535
            cfg = replace(cfg, saturation_dn=float(src.max_dn))
        show = sys.stderr.isatty() if progress is None else progress
        name = getattr(src, "name", source)
        live = _start_live(serve, cam, src, name) if serve is not None else None
        gen = _Watched(live.hub.chunks(src) if live is not None else src, _Status(bool(show)), cam.line_rate_hz, stop)
        n = _watch_loop(gen, cam, radius, cfg, name, output_format, units, events, jobs, live)
        signum, exit_code = stop.signum, stop.exit_code  # before lingering: a Ctrl-C that ends the page is no stop of the stream
        lost = getattr(src, "dropped_lines", 0)
        if lost:
            print(f"ballscan watch: {lost} lines lost by the camera ({getattr(src, 'gaps', '?')} gaps); balls across them are flagged dropped_lines", file=sys.stderr)
        if signum is not None:
            print(f"ballscan watch: stopped by {stop.name} after {gen.lines} lines, {n} balls (the ball in view measured, flagged if cut)", file=sys.stderr)
        elif gen.interrupted:
            print(f"ballscan watch: interrupted after {gen.lines} lines, {n} balls", file=sys.stderr)
        if live is not None and signum is None and not gen.interrupted:
            print(f"ballscan watch: the stream ended; the live view stays at {live.server.url} until Ctrl-C", file=sys.stderr)
            live.linger(stop)
        elif live is not None:
            live.server.stop()
    if signum is not None:
        raise ExitStatus(exit_code)
    return n


def _refuse_without_rig(**given) -> None:
    """``watch --rig``: refuse the one-camera options (the rig file gives the cameras; 'ballscan rig watch' takes the rest)."""
    import inspect

    defaults = inspect.signature(watch).parameters
    for name, value in given.items():
        if value != defaults[name].default:
            flag = {"output_format": "--format", "recipe_file": "--recipe"}.get(name, "--" + name.replace("_", "-"))
            raise ValueError(f"watch --rig: {flag} does not apply (the rig file gives the cameras; with --rig: --radius, --dtype, --chunk-lines, --timeout, --pair-timeout, --constraint)")


def _event_folder(folder: Path | None, force: bool):
    """The locked, checked event folder of ``--save-events`` (a context manager), or a null context without one."""
    import contextlib

    if folder is None:
        return contextlib.nullcontext(None)
    from ..stream.events import EventFolder

    @contextlib.contextmanager
    def opened():
        with EventFolder(folder, force=force) as events:
            if events.removed:
                print(f"ballscan watch: {folder}: removed {len(events.removed)} partial or damaged files (their events are written again)", file=sys.stderr)
            yield events

    return opened()


def _watch_loop(gen: _Watched, cam: LineScanCamera, radius: float, cfg, name: str, output_format: str, units: str, events, jobs: int, live=None) -> int:
    """Run the engine over ``gen``, print each ball (save its event, show it on the live page); return the balls printed."""
    from ..stream.engine import preload_estimator, process_stream

    executor = None
    if jobs:
        # Estimates (tens of ms each) in other processes: reading and the
        # per-line test keep up with the camera while balls are measured;
        # the workers end with this process, however it ends.
        from concurrent.futures import ProcessPoolExecutor

        from ..parallel import worker_start

        executor = ProcessPoolExecutor(jobs, initializer=worker_start, initargs=(preload_estimator,))
    else:
        preload_estimator()  # the kernels' loading is no ball's latency
    n = 0
    per_event: dict[int, int] = {}
    try:
        for res in process_stream(gen, cam, radius, cfg, source=name, dtype=None, executor=executor):
            text = json.dumps(res.to_dict(cam), allow_nan=False) if output_format == "json" else format_stream_line(res, cam, units)
            try:
                gen.status.clear()
                sys.stdout.write(text + "\n")
                sys.stdout.flush()
            except BrokenPipeError:
                # The reader went away (e.g. `| head`): stop quietly.
                return n
            n += 1
            if live is not None:
                live.hub.ball(res)
            if events is not None:
                k = per_event.get(res.event_index, 0)
                per_event[res.event_index] = k + 1
                events.save(res, cam, k)
            gen.balls = n
    except KeyboardInterrupt:
        gen.interrupted = True
    finally:
        if live is not None:
            live.end(sys.exc_info()[1] or (KeyboardInterrupt() if gen.interrupted else None))
        gen.status.close(n)
        if executor is not None:
            executor.shutdown(wait=False, cancel_futures=True)
    return n


def _start_live(address: str, camera: LineScanCamera, src, name: str):
    """The live view of a watch (``--serve``), serving before the first line is read."""
    from ..live.server import LiveWatch

    try:
        live = LiveWatch(camera, address, dropped_lines=lambda: getattr(src, "dropped_lines", 0), title=f"ballscan watch {name}")
    except ValueError as exc:
        raise typer.BadParameter(str(exc).removeprefix("--serve: "), param_hint="--serve") from None
    url = live.start()
    print(f"ballscan watch: live view at {url}", file=sys.stderr, flush=True)
    return live


def format_stream_line(result: StreamResult, camera: LineScanCamera, units: str = "m/s") -> str:
    """One readable line of a stream's ball: lines, speed ± sigma, the speed across the axis, direction, flags, latency."""
    from ..pipeline.report import FLAG_TEXT, UNITS, UNRELIABLE

    b, u = result.estimate, UNITS[units]
    parts = [f"ball {result.event_index}", f"lines {b.first_line}-{b.last_line}"]
    unreliable = [f for f in b.flags if f in UNRELIABLE]
    if b.speed_mps is None:
        parts.append("speed undetermined")
    else:
        sig = f" ± {b.speed_sigma_mps * u:.2f}" if b.speed_sigma_mps is not None else ""
        mark = " (UNRELIABLE)" if unreliable else ""
        parts.append(f"{b.speed_mps * u:.2f}{sig} {units}{mark}")
    # (with the velocity along the line of sight undetermined, what the velocity across it gives)
    der = b.derived(camera)
    if der is not None and b.covariance is not None:
        across = "across axis" if b.transverse is None else "across sight"
        parts.append(f"{across} {der.speed_transverse_mps * u:.2f} ± {der.speed_transverse_sigma_mps * u:.2f}")
        psi, psi_sigma = der.direction_deg[0], der.direction_sigma_deg[0]
        parts.append(f"psi_y {psi:.1f} ± {psi_sigma:.1f} deg" if math.isfinite(psi) else "psi_y undetermined")
        if der.elevation_deg is not None:
            parts.append(f"elevation {der.elevation_deg:.1f} ± {der.elevation_sigma_deg:.1f} deg")
    if b.flags:
        parts.append("; ".join(FLAG_TEXT[f] for f in b.flags))
    parts.append(f"{result.latency_s * 1e3:.1f} ms")
    return " | ".join(parts)


def batch(
    inputs: Annotated[list[Path], typer.Argument(help="Images (PNG/TIFF), raw streams (.raw/.bin) or folders of them.")],
    out_csv: Annotated[Path, typer.Option("--out", help="CSV file: one row per ball; inputs already in it are skipped.")],
    radius: Annotated[float, typer.Option("--radius", help="Ball radius R, metres.")],
    camera: Annotated[Optional[Path], typer.Option("--camera", help="Camera TOML for all inputs (default: NAME.camera.toml beside each).")] = None,
    jobs: Annotated[int, typer.Option("--jobs", "-j", help="Processes on this machine (1: this process, default; -1: all cores).")] = 1,
    scheduler: Annotated[Optional[str], typer.Option("--scheduler", help="Dask distributed scheduler address (tcp://HOST:PORT).")] = None,
    method: Annotated[Optional[str], typer.Option("--method", help="'fit' (default) or 'paper'.")] = None,
    recipe_file: Annotated[Optional[Path], typer.Option("--recipe", help="Recipe file for every input, as for estimate (docs/geometry.md); --method overrides it.")] = None,
    dtype: Annotated[str, typer.Option("--dtype", help="Sample type of raw streams: uint8 or uint16.")] = "uint8",
    progress: Annotated[Optional[bool], typer.Option("--progress/--no-progress", help="Progress bar on stderr (default: when it is a terminal).")] = None,
    background: Annotated[str, typer.Option("--background", help="Raw streams: 'engine' (the stream's running background of a crop's columns, default, as watch) or 'crop' (learned on the crop alone).")] = "engine",
    force: Annotated[bool, typer.Option("--force", help="Write through an --out that is a symbolic link (refused otherwise).")] = False,
) -> int:
    """Measure every ball of many recorded images or raw streams into one CSV (restartable).

    Inputs already in the CSV are skipped; a partial last row (a run killed
    while writing) is dropped and its input measured again. One run at a
    time writes a CSV (OUT.lock). Each input that fails is printed as one
    line on stderr and the command exits with status 1; the others are in
    the CSV. SIGINT, SIGTERM or SIGHUP stop it with status 128 + the
    signal's number (the rows written stay; a rerun does the rest).
    """
    from ..stream.batch import run_batch
    from .options import check_radius_option, recipe_from_options
    from .signals import ExitStatus, stop_signals

    radius = check_radius_option(radius)
    recipe = recipe_from_options(recipe_file, method=method)
    with stop_signals(graceful=False):
        summary = run_batch(
            inputs, out_csv, radius, camera=camera, jobs=jobs, scheduler=scheduler, recipe=recipe, dtype=dtype,
            progress=sys.stderr.isatty() if progress is None else progress, background=background, force=force,
        )
    for note in summary.repairs:
        print(f"ballscan batch: {note}", file=sys.stderr)
    for src, msg in summary.errors:
        print(f"ballscan: error: {msg}", file=sys.stderr)
    print(
        f"{summary.n_done} inputs measured ({summary.n_balls} balls), {summary.n_skipped} skipped (already in {out_csv}), {len(summary.errors)} failed",
        file=sys.stderr,
    )
    if summary.errors:
        raise ExitStatus(1)
    return summary.n_balls
