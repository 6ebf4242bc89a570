"""Continuous line streams: a running background, ball events, estimates as balls leave.

A line-scan camera never stops: lines arrive in chunks of any size, forever.
:class:`StreamEngine` consumes them and returns one :class:`StreamResult`
per ball as soon as the ball has left the viewing plane.

Pipeline per chunk
------------------
1. **Ring buffer.** Lines (and their timestamps) are copied into a ring of
   ``buffer_lines`` lines: memory is fixed however long the stream runs.
2. **Per-line test**, one compiled pass per line in the ring
   (:func:`ballscan.stream._line_kernels.stream_line_test_u8`), over pieces of at most
   ``test_lines`` lines (ending at block boundaries). With the current background
   ``b[j]`` and noise ``s[j]`` (DN) each column has an integer band
   ``[lo, hi] = [floor(b - k s), ceil(b + k s)]``. A pixel is outside the band
   iff ``(x - lo) mod 2**bits > hi - lo`` (one unsigned subtraction and one
   comparison on the stored ``uint8``/``uint16`` data, no float conversion).
   A line holds ball pixels when it has a run of at least ``min_run_px``
   adjacent outside pixels (a single 4-sigma pixel occurs on ~13 % of
   2048-pixel lines by chance; two adjacent ones on ~1e-5 of them).
   Each line's band is first shifted by the line's own offset from the
   background (whole DN, the median of ``x - b`` over 64 columns spread
   over the sensor, clipped to 3 noise sigmas): lamp flicker and other
   illumination changes faster than the block updates stay in the band.
3. **Events.** Hit lines closer than ``margin_lines`` clean lines belong to
   one event (so two balls close in time share one crop and each keeps a
   clean margin). An event ends when ``margin_lines`` clean lines follow its
   last hit line; it is rejected as noise when it is smaller than
   ``min_event_lines`` lines or ``min_event_px`` outside pixels.
4. **Estimate.** The event is cut from the ring with ``margin_lines`` lines
   before and after and the ball's columns plus a margin, and handed to
   :func:`ballscan.pipeline.estimate.estimate_image` with a camera whose principal
   point is shifted by the crop's first column (the same camera frame, so
   positions and velocities need no correction), the lines' timestamps, and
   the engine's background and noise of the crop's columns (a
   :class:`ballscan.measure.detection.ColumnModel`, ``background="engine"``):
   learned on thousands of clean lines, where the crop alone holds a few
   dozen in the ball's columns and its own mode reads high there (limb
   pixels in its window: V.x then read 1.6-3.4 of its sigmas high on
   average on balls of 112-268 lines, ``bench_calibration.py --stream``,
   docs/benchmarks.md), and 0.2 ms less CPU per ball.
   :func:`process_stream` yields the result at once, before the rest of the
   chunk is tested: the latency does not include the lines after the piece
   that ended the event.
5. **Background update.** The model is updated only at fixed absolute block
   boundaries (every ``block_lines`` lines), from every ``sample_step``-th
   line of the block that is at least two lines away from any hit line and
   outside any open event (the model is frozen while a ball passes):
   exponential moving averages of the per-column mean and variance. Because
   the band of a line depends only on the blocks before it, the results do
   not depend on how the stream is cut into chunks.

6. **Width check.** Each tested piece's clean lines (no hit within two
   lines) feed :class:`ballscan.stream.width.WidthCheck`: the background's
   column pattern must repeat at the camera's width. Lines sheared by a
   wrong width (a 2,047-px stream read as 2,048 px) stop the stream with a
   :class:`StreamError` before any ball is measured on them
   (``width_check``).

The model is initialised by :func:`ballscan.measure.detection.detect` on the first
block (robust per-column mode and noise; balls in it do not bias it).
Slow illumination drift is followed by the per-block EMA (the mean of the
per-line offsets goes into the level, their spread is kept out of the
noise); the per-line gain and offset used by the precise estimate are those
:func:`detect` estimates on the crop relative to the engine's columns.
"""

from __future__ import annotations

import math
import time
from collections import deque
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from . import _line_kernels
from .width import WidthCheck
from ..geometry.camera import LineScanCamera, crop_camera
from ..measure.detection import ColumnModel, detect
from ..measure.robust import median
from ..errors import BallscanError
from ..measure.images import LineImage
from ..pipeline.recipe import Recipe
from ..pipeline.results import BallEstimate

__all__ = [
    "BACKGROUNDS",
    "StreamConfig",
    "StreamError",
    "StreamResult",
    "StreamStats",
    "StreamEngine",
    "Chunk",
    "process_stream",
    "estimate_crop",
    "preload_estimator",
]


#: What a crop's estimate is measured on (StreamConfig.background): the
#: engine's running model of its columns, or the crop's own
BACKGROUNDS = ("engine", "crop")


class StreamError(BallscanError):
    """A fault in a line stream (bad data, bad timestamps, stalled or closed source).

    Attributes
    ----------
    results : list of StreamResult
        Balls measured in the call that failed, before the fault (nothing
        measured before a fault is lost).
    """

    def __init__(self, message: str, results: list | None = None):
        super().__init__(message)
        self.results = list(results or [])


@dataclass(frozen=True)
class Chunk:
    """A block of consecutive lines from a source.

    Attributes
    ----------
    lines : numpy.ndarray
        ``uint8`` or ``uint16``, shape ``(n, W)``. May be a view of the
        source's reusable buffer: consume it before asking for the next chunk.
    timestamps_s : numpy.ndarray or None
        float64, shape ``(n,)``: centre time of each line (s), or None for
        ``line / line_rate_hz``.
    """

    lines: np.ndarray
    timestamps_s: np.ndarray | None = None


@dataclass(frozen=True)
class StreamConfig:
    """Settings of the stream engine.

    Parameters
    ----------
    k_sigma : float
        Band half-width in noise sigmas of the per-line test.
    min_run_px : int
        Adjacent outside pixels a line needs to count as a ball line.
    min_event_lines : int
        Smallest event (lines from first to last hit line); smaller ones are
        noise.
    min_event_px : int
        Smallest event (outside pixels in runs); smaller ones are noise.
    margin_lines : int
        Clean lines that end an event, and lines of background kept before
        and after it in the crop.
    margin_px : int
        Smallest column margin each side of the ball in the crop; the margin
        is at least the ball's width too, so the crop's background estimate
        has more background than ball columns.
    block_lines : int
        Lines between background updates (and of the initial model).
    test_lines : int
        Most lines tested at a time (pieces also end at block boundaries). A
        ball's result comes out as soon as the piece that ends its event is
        tested, before the rest of the chunk: fewer lines give a lower
        latency for a little more per-piece overhead. Results do not depend
        on it.
    sample_step : int
        Every ``sample_step``-th clean line of a block feeds the update.
    ema_alpha : float
        Weight of a block in the moving averages (0 < alpha <= 1); the
        model's memory is about ``block_lines / ema_alpha`` lines.
    buffer_lines : int
        Lines in the ring buffer; an event with its margins longer than this
        is reported cut.
    noise_floor_dn : float
        Smallest noise sigma (DN) used for the band.
    recipe : Recipe
        The estimator's strategy (:class:`ballscan.pipeline.recipe.Recipe`);
        its ``shading`` pass is about half of a ball's estimation time, off
        trades V.z accuracy for latency.
    saturation_dn : float or None
        Clipping level (DN); default the dtype's maximum.
    keep_crops : bool
        Attach each event's crop to its results (for ``--save-events``).
    line_offset : bool
        Shift each line's band by the line's own offset from the background
        (whole DN): the median of ``x - b`` over ``offset_columns`` columns
        spread over the sensor. Follows illumination changes faster than the
        block updates (lamp flicker) at about 1.5 ms per 1024 x 2048 chunk.
    offset_columns : int
        Columns sampled for the per-line offset.
    max_line_offset_sigma : float
        The per-line offset is clipped to this many typical noise sigmas, so
        that a ball covering most of the sampled columns cannot move the
        band onto itself.
    background : {"engine", "crop"}
        The background the estimate measures a crop on: the engine's
        running model of its columns (level and noise; the per-line drift is
        still measured on the crop), or the one :func:`detect` learns on the
        crop alone, as ``ballscan estimate`` would on the crop's image.
    width_check : bool
        Check that the lines are the camera's width from the background's
        column pattern (:mod:`ballscan.stream.width`), at the start and
        continuously; lines found sheared stop the stream with a
        :class:`StreamError` before any ball measured on them.
    """

    k_sigma: float = 4.0
    min_run_px: int = 2
    min_event_lines: int = 2
    min_event_px: int = 12
    margin_lines: int = 16
    margin_px: int = 48
    block_lines: int = 512
    test_lines: int = 256
    sample_step: int = 8
    ema_alpha: float = 0.25
    buffer_lines: int = 8192
    noise_floor_dn: float = 0.5
    recipe: Recipe = Recipe()
    saturation_dn: float | None = None
    keep_crops: bool = False
    line_offset: bool = True
    offset_columns: int = 64
    max_line_offset_sigma: float = 3.0
    background: str = "engine"
    width_check: bool = True

    def __post_init__(self) -> None:
        def need(ok: bool, name: str, why: str) -> None:
            if not ok:
                raise ValueError(f"{name}: {why}, got {getattr(self, name)!r}")

        def real(name: str) -> bool:
            v = getattr(self, name)
            return isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(v, bool) and math.isfinite(v)

        def integer(name: str) -> bool:
            v = getattr(self, name)
            return isinstance(v, (int, np.integer)) and not isinstance(v, bool)

        need(real("k_sigma") and self.k_sigma > 0, "k_sigma", "must be positive")
        for name in ("min_run_px", "min_event_lines", "min_event_px", "margin_lines", "block_lines", "test_lines", "sample_step"):
            need(integer(name) and getattr(self, name) >= 1, name, "must be an integer >= 1")
        need(integer("margin_px") and self.margin_px >= 0, "margin_px", "must be an integer >= 0")
        need(real("ema_alpha") and 0 < self.ema_alpha <= 1, "ema_alpha", "must be in (0, 1]")
        need(self.block_lines >= 8, "block_lines", "must be at least 8")
        need(
            isinstance(self.buffer_lines, (int, np.integer)) and self.buffer_lines >= 2 * self.block_lines + 4 * self.margin_lines,
            "buffer_lines",
            "must be at least 2 * block_lines + 4 * margin_lines",
        )
        need(real("noise_floor_dn") and self.noise_floor_dn > 0, "noise_floor_dn", "must be positive")
        need(isinstance(self.recipe, Recipe), "recipe", "must be a Recipe")
        need(self.saturation_dn is None or (real("saturation_dn") and self.saturation_dn > 0), "saturation_dn", "must be None or positive")
        for name in ("keep_crops", "line_offset", "width_check"):
            need(isinstance(getattr(self, name), bool), name, "must be True or False")
        need(integer("offset_columns") and self.offset_columns >= 8, "offset_columns", "must be an integer >= 8")
        need(real("max_line_offset_sigma") and self.max_line_offset_sigma >= 0, "max_line_offset_sigma", "must be >= 0")
        need(self.background in BACKGROUNDS, "background", "must be 'engine' or 'crop'")


@dataclass(frozen=True)
class StreamResult:
    """One measured ball of a stream.

    Attributes
    ----------
    estimate : BallEstimate
        Its ``first_line`` / ``last_line`` are stream line numbers.
    source : str
        Name of the stream.
    event_index : int
        0-based index of the event (crop) the ball was found in.
    crop_lines, crop_cols : tuple of int
        ``[start, stop)`` of the crop in stream lines and sensor pixels.
    latency_s : float
        Seconds from the arrival of the chunk that completed the event to
        this result.
    handoff_s : float
        Seconds from the arrival of that chunk to the crop being handed to
        the estimator (the engine's own share of the latency).
    crop : numpy.ndarray or None
        The crop's stored values (only with ``keep_crops``).
    crop_times_s : numpy.ndarray or None
        The crop's line times, seconds (only with ``keep_crops``).
    crop_columns : ColumnModel or None
        The engine's background and noise of the crop's columns that the
        estimate used (None with ``background="crop"`` and for an event that
        was not estimated): ``estimate_crop(crop, crop_times_s, ...,
        columns=crop_columns)`` gives the same estimate again.
    """

    estimate: BallEstimate
    source: str
    event_index: int
    crop_lines: tuple[int, int]
    crop_cols: tuple[int, int]
    latency_s: float = 0.0
    crop: np.ndarray | None = field(default=None, repr=False, compare=False)
    crop_times_s: np.ndarray | None = field(default=None, repr=False, compare=False)
    handoff_s: float = 0.0
    crop_columns: ColumnModel | None = field(default=None, repr=False, compare=False)

    def to_dict(self, camera: LineScanCamera | None = None) -> dict[str, Any]:
        """geometry.md estimate keys plus ``source``, ``first_line``, ``last_line`` (stream lines)."""
        d = self.estimate.to_dict(camera)
        d["source"] = self.source
        d["first_line"] = self.estimate.first_line
        d["last_line"] = self.estimate.last_line
        d["event"] = self.event_index
        d["latency_s"] = self.latency_s
        return d


@dataclass(frozen=True)
class StreamStats:
    """Counters of a stream engine (a snapshot).

    Attributes
    ----------
    lines : int
        Lines received.
    events : int
        Events cut and estimated (noise events not counted).
    balls : int
        Results returned.
    rejected : int
        Events rejected as too small.
    busy_s : float
        Seconds spent inside :meth:`StreamEngine.push`.
    stream_time_s : float
        Time of the last line received minus that of the first (s).
    """

    lines: int
    events: int
    balls: int
    rejected: int
    busy_s: float
    stream_time_s: float

    @property
    def lines_per_s(self) -> float:
        """Processing rate (lines per second of engine time)."""
        return self.lines / self.busy_s if self.busy_s > 0 else float("inf")


@dataclass
class _Event:
    start: int
    last_hit: int
    col_min: int
    col_max: int
    n_px: int
    overflowed: bool = False
    relearned_at: int = 0


class StreamEngine:
    """Measure balls in an endless stream of lines (see the module docstring).

    Parameters
    ----------
    camera : LineScanCamera
        Its ``width`` must match the lines.
    radius_m : float
        Known ball radius, metres.
    config : StreamConfig, optional
    source : str, optional
        Name used in results and messages.
    dtype : numpy dtype, optional
        ``uint8`` or ``uint16``: the stored type of the lines.
    executor : concurrent.futures.Executor, optional
        Run the estimates there (e.g. a one-process pool on a second core)
        instead of inside :meth:`push`; results still come out of
        :meth:`push` / :meth:`poll` / :meth:`finish` in event order.

    Notes
    -----
    Use :meth:`push` for each chunk and :meth:`finish` at the end of the
    stream. Both return the results completed by that call.
    """

    def __init__(
        self,
        camera: LineScanCamera,
        radius_m: float,
        config: StreamConfig | None = None,
        *,
        source: str = "<stream>",
        dtype: Any = np.uint8,
        executor: Any = None,
    ) -> None:
        if not isinstance(camera, LineScanCamera):
            raise ValueError(f"camera: expected a LineScanCamera, got {type(camera).__name__}")
        if not (isinstance(radius_m, (int, float, np.floating)) and math.isfinite(radius_m) and radius_m > 0):
            raise ValueError(f"radius: must be positive, got {radius_m!r}")
        dt = np.dtype(dtype)
        if dt not in (np.dtype(np.uint8), np.dtype(np.uint16)):
            raise ValueError(f"dtype: lines must be uint8 or uint16, got {dt}")
        self.camera = camera
        self.radius_m = float(radius_m)
        self.config = config or StreamConfig()
        self.source = source
        self.dtype = dt
        self._max_dn = int(np.iinfo(dt).max)
        self.width = int(camera.width)
        cap = int(self.config.buffer_lines)
        self._ring = np.zeros((cap, self.width), dtype=dt)
        self._times = np.zeros(cap, dtype=np.float64)
        self._hit = np.zeros(cap, dtype=bool)  # per-line hit flags of the ring
        self._off = np.zeros(cap, dtype=np.int32)  # per-line offsets (DN) of the ring
        m = min(int(self.config.offset_columns), self.width)
        self._ocols = np.unique(np.linspace(0, self.width - 1, m).round().astype(np.intp))
        self._cap = cap
        self._n = 0  # lines received
        self._has_timestamps: bool | None = None
        self._last_t: float | None = None
        self._first_t: float | None = None
        # background model
        self._bg: np.ndarray | None = None  # float64 (W,)
        self._var: np.ndarray | None = None
        self._lo: np.ndarray | None = None
        self._span: np.ndarray | None = None
        self._event: _Event | None = None
        self._n_events = 0
        self._n_balls = 0
        self._n_rejected = 0
        self._busy = 0.0
        self._finished = False
        self._chunk_arrival = 0.0
        self._executor = executor
        self._pending: deque[_Job] = deque()
        self._width_check = WidthCheck(self.width, block_lines=self.config.block_lines) if self.config.width_check else None
        if executor is None:
            # Import the estimator now, not when the first ball leaves.
            preload_estimator()
        else:
            # the engine's own kernels (the estimator's load in the workers)
            _line_kernels.warm_up()

    # ------------------------------------------------------------------ public
    @property
    def lines_received(self) -> int:
        """Lines received so far."""
        return self._n

    @property
    def background_dn(self) -> np.ndarray | None:
        """Current per-column background (DN), or None before the first block."""
        return None if self._bg is None else self._bg.copy()

    @property
    def noise_dn(self) -> np.ndarray | None:
        """Current per-column noise sigma (DN), or None before the first block."""
        return None if self._var is None else np.sqrt(self._var)

    def stats(self) -> StreamStats:
        """Counters so far."""
        span = 0.0 if self._first_t is None or self._last_t is None else self._last_t - self._first_t
        return StreamStats(self._n, self._n_events, self._n_balls, self._n_rejected, self._busy, span)

    def push(self, lines: np.ndarray, timestamps_s: np.ndarray | None = None) -> list[StreamResult]:
        """Feed consecutive lines; return the balls completed by them.

        Parameters
        ----------
        lines : numpy.ndarray
            Shape ``(n, W)`` (or ``(W,)`` for one line), the engine's dtype.
        timestamps_s : numpy.ndarray, optional
            Centre time (s) of each line, strictly increasing across chunks.
            Give them for every chunk or for none.

        Returns
        -------
        list of StreamResult

        Raises
        ------
        StreamError
            On a width, dtype or timestamp fault. The lines before the fault
            are processed and the results they completed are in the
            exception's ``results``.
        """
        out: list[StreamResult] = []
        try:
            for r in self._push_iter(lines, timestamps_s):
                out.append(r)
        except StreamError as exc:
            exc.results[:0] = out
            raise
        return out

    def _push_iter(self, lines: np.ndarray, timestamps_s: np.ndarray | None = None) -> Iterator[StreamResult]:
        """:meth:`push` as a generator: each result as soon as it is measured.

        The lines are tested ``test_lines`` at a time; a ball's result is
        yielded as soon as the piece that completes its event is tested,
        before the rest of the lines are tested and before the background
        update that follows it. Engine time (``busy_s``) excludes the time
        the consumer holds a result. A fault raises after every result before
        it was yielded (the exception's ``results`` is empty). Exhaust it
        before feeding more lines.
        """
        arrival = time.perf_counter()
        self._chunk_arrival = arrival
        if self._finished:
            raise StreamError(f"{self.source}: push() after finish()")
        x = np.asarray(lines)
        if x.ndim == 1:
            x = x[None, :]
        if x.ndim != 2 or x.shape[1] != self.width:
            raise StreamError(
                f"{self.source}: lines of {x.shape[-1] if x.ndim else 0} pixels after line {self._n}, "
                f"but the camera has width = {self.width}"
            )
        if x.dtype != self.dtype:
            raise StreamError(f"{self.source}: lines of type {x.dtype} after line {self._n}, expected {self.dtype}")
        fault: str | None = None
        ts = None
        if timestamps_s is not None:
            ts = np.asarray(timestamps_s, dtype=np.float64).reshape(-1)
            if ts.size != x.shape[0]:
                raise StreamError(f"{self.source}: {ts.size} timestamps for a chunk of {x.shape[0]} lines (after line {self._n})")
        if self._has_timestamps is None and x.shape[0]:
            self._has_timestamps = ts is not None
        elif x.shape[0] and self._has_timestamps != (ts is not None):
            raise StreamError(f"{self.source}: timestamps given for some chunks but not others (at line {self._n})")
        if ts is not None and ts.size:
            # step[k] = ts[k] - (time of the line before it), across chunks too
            before = np.concatenate(([self._last_t if self._last_t is not None else -np.inf], ts[:-1]))
            bad = np.flatnonzero(~np.isfinite(ts) | ~(ts > before))
            if bad.size:
                k = int(bad[0])
                prev = "" if not np.isfinite(before[k]) else f" after {before[k]!r} s"
                fault = (
                    f"{self.source}: timestamp of line {self._n + k} is {ts[k]!r} s{prev}: timestamps must be finite "
                    f"and strictly increasing; the {self._n + k} lines before it were processed"
                )
                x, ts = x[:k], ts[:k]
        out: list[StreamResult] = []
        t: float | None = arrival  # start of the current stretch of engine time
        try:
            if x.shape[0]:
                for done in self._ingest(x, ts):
                    self._busy += time.perf_counter() - t
                    t = None
                    yield from done
                    t = time.perf_counter()
            if self._executor is not None:
                self._collect(out, wait=False)
        finally:
            if t is not None:
                self._busy += time.perf_counter() - t
        yield from out
        if fault is not None:
            raise StreamError(fault)

    def poll(self) -> list[StreamResult]:
        """Results whose estimates finished in the executor since the last call (no new lines)."""
        out: list[StreamResult] = []
        self._collect(out, wait=False)
        return out

    def finish(self) -> list[StreamResult]:
        """End of stream: measure the event still open (flagged ``cut_last_line`` if the ball is)."""
        if self._finished:
            return []
        if self._width_check is not None and self._width_check.sheared:
            self._finished = True  # nothing is measured on sheared lines
            self._collect([], wait=True)
            return []
        t0 = time.perf_counter()
        self._chunk_arrival = t0
        out: list[StreamResult] = []
        if self._bg is None and self._n >= 2:
            self._init_model(self._n)
            self._test(0, self._n, out)
        if self._event is not None:
            ev, self._event = self._event, None
            self._close(ev, out)
        self._collect(out, wait=True)
        self._finished = True
        self._busy += time.perf_counter() - t0
        return out

    # ---------------------------------------------------------------- internals
    def _ingest(self, x: np.ndarray, ts: np.ndarray | None) -> Iterator[list[StreamResult]]:
        """Store and test ``x`` piece by piece; yield the results of each piece that completes any."""
        n_in = x.shape[0]
        pos = 0
        block = self.config.block_lines
        while pos < n_in:
            # Pieces end at block boundaries so that model updates fall on
            # fixed absolute lines (results independent of the chunking), and
            # hold at most test_lines lines so that a ball's result comes out
            # soon after its event ends, not after the whole chunk is tested.
            to_boundary = block - (self._n % block)
            k = min(n_in - pos, to_boundary, self.config.test_lines)
            piece = x[pos : pos + k]
            tpiece = ts[pos : pos + k] if ts is not None else (np.arange(self._n, self._n + k, dtype=np.float64) / self.camera.line_rate_hz)
            out: list[StreamResult] = []
            update = self._store(piece, tpiece, out)
            if out:
                yield out
            if update:
                self._update_model(self._n - block, self._n)
            pos += k

    def _store(self, piece: np.ndarray, tpiece: np.ndarray, out: list[StreamResult]) -> bool:
        """Copy a piece into the ring and test it; True when it completes a block (the model update is due)."""
        k = piece.shape[0]
        start = self._n
        self._check_overflow(start + k, out)
        i0 = start % self._cap
        i1 = i0 + k
        if i1 <= self._cap:
            self._ring[i0:i1] = piece
            self._times[i0:i1] = tpiece
        else:
            s = self._cap - i0
            self._ring[i0:] = piece[:s]
            self._ring[: k - s] = piece[s:]
            self._times[i0:] = tpiece[:s]
            self._times[: k - s] = tpiece[s:]
        if self._first_t is None:
            self._first_t = float(tpiece[0])
        self._last_t = float(tpiece[-1])
        self._n = start + k
        block = self.config.block_lines
        if self._bg is None:
            if self._n >= block:
                self._init_model(block)
                self._test(0, self._n, out)
            return False
        self._test(start, self._n, out)
        return self._n % block == 0

    def _check_overflow(self, new_n: int, out: list[StreamResult]) -> None:
        ev = self._event
        if ev is None:
            return
        if not ev.overflowed:
            first_needed = max(ev.start - self.config.margin_lines, 0)
            if new_n - first_needed <= self._cap:
                return
            # The event no longer fits the ring: report it cut and relearn the
            # background (a long "event" is usually a step in illumination).
            self._emit_cut(ev, out, f"event longer than the {self._cap}-line buffer")
            ev.overflowed = True
        elif new_n - ev.relearned_at <= 4 * self.config.block_lines:
            return
        # Relearn from the last block, and again every 4 blocks while the
        # event lasts: a model learnt while a (very slow) ball was still in
        # view must not keep the event open after it has gone.
        hi = self._n
        lo = max(hi - self.config.block_lines, 0)
        self._init_model_from(self._read(lo, hi))
        ev.relearned_at = hi

    def _read(self, lo: int, hi: int) -> np.ndarray:
        """Lines ``[lo, hi)`` of the stream from the ring (a copy)."""
        idx = np.arange(lo, hi) % self._cap
        return self._ring[idx]

    def _read_times(self, lo: int, hi: int) -> np.ndarray:
        return self._times[np.arange(lo, hi) % self._cap]

    def _init_model(self, n_lines: int) -> None:
        self._init_model_from(self._read(0, n_lines))

    def _init_model_from(self, data: np.ndarray) -> None:
        if data.shape[0] >= 2:
            sat = self.config.saturation_dn if self.config.saturation_dn is not None else float(self._max_dn)
            det = detect(LineImage(data.astype(np.float64), sat, 8 * self.dtype.itemsize, self.source), noise_floor_dn=self.config.noise_floor_dn)
            g = float(np.median(det.line_gain))
            o = float(np.median(det.line_offset_dn))
            bg = det.background_dn * g + o
            sig = np.asarray(det.noise_dn, dtype=np.float64)
        else:
            bg = data.astype(np.float64).mean(axis=0)
            sig = np.full(self.width, 2.0)
        self._bg = np.asarray(bg, dtype=np.float64).copy()
        self._var = np.maximum(sig, self.config.noise_floor_dn) ** 2
        self._set_band()

    def _set_band(self) -> None:
        sig = np.maximum(np.sqrt(self._var), self.config.noise_floor_dn)
        half = self.config.k_sigma * sig
        lo = np.maximum(np.floor(self._bg - half), 0.0)
        hi = np.minimum(np.ceil(self._bg + half), float(self._max_dn))
        lo = np.minimum(lo, hi)
        self._lo = lo.astype(self.dtype)
        self._span = (hi - lo).astype(self.dtype)
        self._bg_ocols16 = np.rint(16.0 * self._bg[self._ocols]).astype(np.int64)
        self._max_off = int(np.ceil(self.config.max_line_offset_sigma * float(median(sig))))

    def _update_model(self, lo: int, hi: int) -> None:
        cfg = self.config
        hit = self._hit[np.arange(lo, hi) % self._cap]
        # Exclude lines within 2 of a hit (faint limb lines below the band)
        # and every line of an open event: the model is frozen under a ball.
        near = hit.copy()
        for s in (1, 2):
            near[s:] |= hit[:-s]
            near[:-s] |= hit[s:]
        if self._event is not None:
            near[max(self._event.start - lo, 0) :] = True
        rows = np.arange(0, hi - lo, cfg.sample_step)
        rows = rows[~near[rows]]
        if rows.size < 2:
            return
        # The per-column sums of x - offset and its square over the sampled
        # lines, in one compiled pass: exact integers (the float64 sums of
        # the same integers, bit for bit), without the
        # (lines, W) float copy. Fast per-line offsets (flicker) are not
        # noise: they are removed before the variance, their mean kept in the
        # level (slow drift).
        idx = (lo + rows) % self._cap
        sums = _line_kernels.stream_block_sums_u8 if self.dtype.itemsize == 1 else _line_kernels.stream_block_sums_u16
        total, total2 = sums(self._ring, self._off, idx)
        off = self._off[idx].astype(np.float64)
        n = rows.size
        mean = total / n
        var = np.maximum(total2 - n * mean * mean, 0.0) / (n - 1)
        mean += off.mean()
        a = cfg.ema_alpha
        self._bg += a * (mean - self._bg)
        self._var += a * (var - self._var)
        self._set_band()

    def _test(self, lo: int, hi: int, out: list[StreamResult]) -> None:
        """Test stored lines ``[lo, hi)`` with the current band, in place in the ring, and record their hits."""
        hit_lines, counts, cmin, cmax = self._line_test(lo, hi - lo)
        self._check_width(lo, hi)
        self._record(lo, hi - lo, hit_lines, counts, cmin, cmax, out)

    def _check_width(self, lo: int, hi: int) -> None:
        """Feed the tested lines ``[lo, hi)`` with their clean flags (no hit within 2 lines) to the width check."""
        wc = self._width_check
        if wc is None or hi - lo < 2 or not wc.wants(lo):
            return
        a = max(lo - 2, 0)
        hit = self._hit[np.arange(a, hi) % self._cap]
        near = hit.copy()
        for s in (1, 2):
            near[s:] |= hit[:-s]
            near[:-s] |= hit[s:]
        # (the last two lines' successors are not tested yet: counted clean)
        wc.add(self._read(lo, hi), lo, ~near[lo - a :])

    def _require_width(self) -> None:
        """Raise the width check's refusal (before a ball is measured on sheared lines)."""
        wc = self._width_check
        if wc is None or not wc.sheared:
            return
        v = wc.verdict
        how = "half a line per line read" if v.period_px == 2 * self.width else f"each line sheared by {v.period_px - self.width:+d} px against the last"
        raise StreamError(
            f"{self.source}: the lines are not {self.width} px wide: the background's column pattern repeats every "
            f"{v.period_px} samples (score {v.z:.0f}, {self.width} px: {v.z_camera:.0f}), {how}; "
            f"a {v.period_px}-px stream read as {self.width} px? (check the camera file's width and --width); "
            f"stopped after {self._n} lines"
        )

    def _line_test(self, start: int, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Stream lines ``[start, start + n)`` (in the ring) holding ball pixels: indices (from ``start``), counts, first and last column.

        One compiled pass per line (:func:`ballscan.stream._line_kernels.stream_line_test_u8`):
        the line's offset (stored in the ring's ``_off``), the band test
        ``(x - lo - offset) mod 2**bits > hi - lo`` and the run rule; the hit
        flags go to the ring's ``_hit``. Counts are the positions starting
        ``min_run_px`` adjacent outside pixels; the last column is the last
        such position plus ``min_run_px - 1``.
        """
        cfg = self.config
        kernel = _line_kernels.stream_line_test_u8 if self.dtype.itemsize == 1 else _line_kernels.stream_line_test_u16
        return kernel(
            self._ring, start % self._cap, n, self._lo, self._span, self._ocols, self._bg_ocols16, self._max_off,
            int(cfg.min_run_px), bool(cfg.line_offset), self._off, self._hit,
        )

    def _record(self, start: int, n: int, idx: np.ndarray, counts: np.ndarray, cmin: np.ndarray, cmax: np.ndarray, out: list[StreamResult]) -> None:
        # (the ring's hit flags of these lines are set by the line test)
        m = self.config.margin_lines
        for i, c, a, b in zip(idx.tolist(), counts.tolist(), cmin.tolist(), cmax.tolist()):
            line = start + i
            ev = self._event
            if ev is not None and line - ev.last_hit - 1 >= m:
                self._event = None
                self._close(ev, out)
                ev = None
            if ev is None:
                self._event = _Event(line, line, a, b, c)
            else:
                ev.last_hit = line
                ev.col_min = min(ev.col_min, a)
                ev.col_max = max(ev.col_max, b)
                ev.n_px += c
        ev = self._event
        if ev is not None and (start + n) - ev.last_hit - 1 >= m:
            self._event = None
            self._close(ev, out)

    def _emit_cut(self, ev: _Event, out: list[StreamResult], why: str) -> None:
        self._require_width()
        est = BallEstimate(
            method=self.config.recipe.method,
            radius_m=self.radius_m,
            t_c_s=None,
            position_m=None,
            velocity_mps=None,
            speed_mps=None,
            flags=("cut_first_line", "cut_last_line", "degenerate"),
            undetermined=("t_c_s", "position_m", "velocity_mps", "speed_mps"),
            extra={"reason": why},
        )
        job = _Job(self._n_events, ev.start, ev.last_hit + 1, ev.col_min, ev.col_max + 1, None, None, self._chunk_arrival, 0.0, ev.start, ev.last_hit)
        job.balls = (est,)
        self._n_events += 1
        self._pending.append(job)
        self._collect(out, wait=False)

    def _close(self, ev: _Event, out: list[StreamResult]) -> None:
        self._require_width()
        cfg = self.config
        if ev.overflowed:
            return
        if ev.last_hit - ev.start + 1 < cfg.min_event_lines or ev.n_px < cfg.min_event_px:
            self._n_rejected += 1
            return
        m = cfg.margin_lines
        l0 = max(ev.start - m, 0, self._n - self._cap)
        l1 = min(ev.last_hit + 1 + m, self._n)
        if l1 - l0 < 2:
            self._n_rejected += 1
            return
        ball_w = ev.col_max - ev.col_min + 1
        cm = max(cfg.margin_px, ball_w)
        c0 = max(ev.col_min - cm, 0)
        c1 = min(ev.col_max + 1 + cm, self.width)
        crop = self._ring[np.arange(l0, l1) % self._cap, c0:c1]
        times = self._read_times(l0, l1)
        sat = cfg.saturation_dn if cfg.saturation_dn is not None else float(self._max_dn)
        exposure = None
        if not self._has_timestamps and self.camera.exposure_s is None:
            # estimate_image sets the exposure to the median line period when
            # timestamps are given; without a timestamps file the exact period is known.
            exposure = 1.0 / self.camera.line_rate_hz
        camera = crop_camera(self.camera, c0, c1, exposure_s=exposure)
        # the model learns nothing from the event's lines: these are its columns
        # from the clean lines before the ball
        columns = ColumnModel(self._bg[c0:c1], np.sqrt(self._var[c0:c1])) if cfg.background == "engine" else None
        args = (
            crop, times, camera, self.radius_m, cfg.recipe, sat, 8 * self.dtype.itemsize, f"{self.source}[{l0}:{l1}, {c0}:{c1}]", columns,
        )
        handoff = time.perf_counter() - self._chunk_arrival
        job = _Job(self._n_events, l0, l1, c0, c1, crop, times, self._chunk_arrival, handoff, ev.start, ev.last_hit, columns=columns)
        self._n_events += 1
        if self._executor is None:
            job.balls = estimate_crop(*args)
        else:
            job.future = self._executor.submit(estimate_crop, *args)
        self._pending.append(job)
        self._collect(out, wait=False)

    def _collect(self, out: list[StreamResult], wait: bool) -> None:
        """Move finished estimates to ``out``, in event order."""
        cfg = self.config
        while self._pending:
            job = self._pending[0]
            if job.future is not None:
                if not wait and not job.future.done():
                    return
                job.balls = job.future.result()
            self._pending.popleft()
            done = time.perf_counter()
            for b in job.balls:
                # Crop lines -> stream lines; an estimate without lines (it
                # failed) gets the event's first and last ball line.
                est = replace(
                    b,
                    first_line=job.first_hit if b.first_line is None else int(b.first_line) + job.l0,
                    last_line=job.last_hit if b.last_line is None else int(b.last_line) + job.l0,
                )
                self._n_balls += 1
                out.append(
                    StreamResult(
                        est,
                        self.source,
                        job.index,
                        (job.l0, job.l1),
                        (job.c0, job.c1),
                        done - job.arrival,
                        job.crop.copy() if cfg.keep_crops and job.crop is not None else None,
                        job.times.copy() if cfg.keep_crops and job.times is not None else None,
                        job.handoff,
                        job.columns,
                    )
                )


@dataclass
class _Job:
    index: int
    l0: int
    l1: int
    c0: int
    c1: int
    crop: np.ndarray | None
    times: np.ndarray | None
    arrival: float
    handoff: float
    first_hit: int
    last_hit: int
    balls: tuple = ()
    future: Any = None
    columns: ColumnModel | None = None


def estimate_crop(
    crop: np.ndarray,
    times_s: np.ndarray,
    camera: LineScanCamera,
    radius_m: float,
    recipe: Recipe,
    saturation_dn: float,
    bits: int,
    name: str,
    columns: ColumnModel | None = None,
) -> tuple[BallEstimate, ...]:
    """Estimate the balls of one event crop (a top-level function: runs in worker processes too).

    Parameters
    ----------
    crop : numpy.ndarray
        Stored values of the crop, ``(n_lines, n_cols)``.
    times_s : numpy.ndarray
        Centre time of each crop line, seconds.
    camera : LineScanCamera
        The crop's camera (:func:`crop_camera`).
    radius_m : float
    recipe : Recipe
        The estimator's strategy.
    saturation_dn : float
    bits : int
    name : str
    columns : ColumnModel, optional
        The crop columns' background and noise (the engine's model), else
        learned on the crop.

    Returns
    -------
    tuple of BallEstimate
        Lines relative to the crop, in the order of ``t_c``. If the
        estimator fails on the crop, one undetermined estimate (flag
        ``"degenerate"``, ``extra["reason"]``) without lines: a stream must
        not stop on one bad ball.
    """
    from ..pipeline.estimate import estimate_image

    image = LineImage(crop.astype(np.float64), saturation_dn, bits, name)
    try:
        return estimate_image(image, camera, radius_m, recipe=recipe, timestamps_s=times_s, columns=columns).balls
    except (BallscanError, ValueError, ArithmeticError, np.linalg.LinAlgError) as exc:
        return (BallEstimate.undetermined_estimate(recipe.method, radius_m, f"estimate failed: {str(exc)[:200]}"),)


def preload_estimator(*, stream_kernels: bool = True) -> None:
    """Import the estimator's modules and load its compiled kernels (an ``initializer`` for worker processes).

    The first estimate in a fresh process otherwise carries the imports and
    the loading of the kernels (:func:`ballscan.pipeline.warmup.warm_up`).
    ``stream_kernels``: the engine's own line kernels and the fit's lazily
    imported ``scipy.special`` too (a process that measures stored images
    only loads them when an engine starts, or at its first partial end).  The
    modules are imported with the garbage collector paused: they live as
    long as the process.
    """
    from ..parallel import collector_paused
    from ..pipeline.warmup import ensure_warm

    with collector_paused():
        from ..measure import edges  # noqa: F401
        from ..pipeline import estimate  # noqa: F401
        from ..solve import fit  # noqa: F401
        from .recording import measure_stored  # noqa: F401
    ensure_warm()
    if stream_kernels:
        _line_kernels.warm_up()
        with collector_paused():
            # the fit's test of a ball's partial end lines loads it at the
            # first such ball: not in a stream ball's latency (about 0.1 s)
            import scipy.special  # noqa: F401


def process_stream(
    chunks: Iterable[Chunk | np.ndarray],
    camera: LineScanCamera,
    radius_m: float,
    config: StreamConfig | None = None,
    *,
    source: str = "<stream>",
    dtype: Any = None,
    executor: Any = None,
) -> Iterator[StreamResult]:
    """Run a :class:`StreamEngine` over chunks; yield results as they are measured.

    Parameters
    ----------
    chunks : iterable of Chunk or numpy.ndarray
        Consecutive lines; arrays are chunks without timestamps.
    camera, radius_m, config, source
        As for :class:`StreamEngine`.
    dtype : numpy dtype, optional
        Stored type; default that of the first chunk.
    executor : concurrent.futures.Executor, optional
        Where to run the estimates (see :class:`StreamEngine`).

    Yields
    ------
    StreamResult
        Each as soon as it is measured: after the piece of ``test_lines``
        lines that ends its event, before the rest of that chunk is tested.

    Raises
    ------
    StreamError
        On a fault of the stream or its source, after yielding every result
        measured before it (an event open at the fault is measured and
        yielded first, flagged as cut where its ball is).
    """
    engine: StreamEngine | None = None
    it = iter(chunks)
    while True:
        try:
            ch = next(it)
        except StopIteration:
            break
        except BallscanError as exc:
            # A source fault (truncated, stalled, closed): keep what was measured.
            if engine is not None:
                yield from engine.finish()
            raise exc if isinstance(exc, StreamError) else StreamError(str(exc)) from None
        if not isinstance(ch, Chunk):
            ch = Chunk(np.asarray(ch))
        if engine is None:
            engine = StreamEngine(camera, radius_m, config, source=source, dtype=dtype or ch.lines.dtype, executor=executor)
        try:
            # each ball as soon as it is measured, not after the whole chunk
            yield from engine._push_iter(ch.lines, ch.timestamps_s)
        except StreamError:
            yield from engine.finish()
            raise
    if engine is not None:
        yield from engine.finish()
