"""Between the measurement loop and the page: a bounded ring of balls and the stream's health.

The measurement loop (``ballscan watch``) calls :meth:`LiveHub.chunk` for
each chunk of lines it reads, :meth:`LiveHub.ball` for each measured ball and
:meth:`LiveHub.end` when the source ends. None of these waits for the
server: each appends to a bounded queue (the oldest item is dropped when the
server falls behind) or updates a few numbers, and copies at most a few
lines; the crop's display pixels, its outline and every message are made on
the server's thread (:meth:`LiveHub.drain`). Memory is bounded: the last
``capacity`` balls, the crops of the last ``crop_capacity`` of them, a few
sampled lines for the background strip.

A viewer reads the ring with a cursor (:meth:`LiveHub.balls_after`): a
viewer that falls more than ``capacity`` balls behind skips the oldest ones
(and is told how many); no viewer holds anything of its own.
"""

from __future__ import annotations

import threading
import time
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..geometry.camera import LineScanCamera
from .balls import BallFilter, CropView, LiveBall, ball_from_record, crop_view

__all__ = ["LiveConfig", "Health", "LiveHub"]

#: Most columns of the background strip (bins of whole columns).
STRIP_BINS = 256


@dataclass(frozen=True)
class LiveConfig:
    """Settings of a live view.

    Parameters
    ----------
    capacity : int
        Balls kept for the page's table and charts (the ring).
    crop_capacity : int
        Of those, the most recent ones whose crop is kept.
    pending : int
        Balls and chunks waiting for the server's thread; beyond, the
        oldest are dropped (the measurement never waits).
    stall_after_s : float
        Seconds without a new line after which the page says the source stalled.
    sample_every_s : float
        Seconds between the lines sampled for the background strip.
    sample_lines : int
        Lines kept for the strip's per-column median.
    """

    capacity: int = 1000
    crop_capacity: int = 32
    pending: int = 256
    stall_after_s: float = 1.0
    sample_every_s: float = 0.5
    sample_lines: int = 32

    def __post_init__(self) -> None:
        for name in ("capacity", "crop_capacity", "pending", "sample_lines"):
            v = getattr(self, name)
            if isinstance(v, bool) or not isinstance(v, int) or v < 1:
                raise ValueError(f"{name}: must be an integer >= 1, got {v!r}")
        for name in ("stall_after_s", "sample_every_s"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and v > 0 and np.isfinite(v)):
                raise ValueError(f"{name}: must be a positive number of seconds, got {v!r}")


@dataclass(frozen=True)
class Health:
    """The stream's health as the page shows it.

    Attributes
    ----------
    state : {"waiting", "running", "stalled", "ended", "failed", "replay"}
    message : str
        Words for the banner (empty while running).
    lines : int
        Lines read.
    lines_per_s : float
        Lines read per second over the last second or so.
    behind_s : float
        How far the reading is behind the wall clock (a real-time source's
        delay; 0 for a recording read faster than real time), seconds.
    since_last_line_s : float or None
        Seconds since the last chunk was read.
    last_lag_s : float or None
        The last ball's lag (its last line read to its publication), seconds.
    dropped_lines : int
        Lines the source lost (a camera's block-ID gaps).
    balls : int
        Balls measured.
    skipped : int
        Balls dropped before the server's thread saw them (it fell behind).
    strip_dn : tuple of float
        Background level (DN) in bins of columns across the sensor: the
        per-column median of recently sampled lines, averaged per bin.
    width : int
        Sensor pixels the strip spans.
    """

    state: str
    message: str
    lines: int
    lines_per_s: float
    behind_s: float
    since_last_line_s: float | None
    last_lag_s: float | None
    dropped_lines: int
    balls: int
    skipped: int
    strip_dn: tuple[float, ...]
    width: int

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready form."""
        d = dict(self.__dict__)
        d["strip_dn"] = [round(v, 1) for v in self.strip_dn]
        return d


class LiveHub:
    """Balls and health of one live run (see the module docstring).

    Parameters
    ----------
    camera : LineScanCamera
        The stream's camera (the balls' outlines; the line rate).
    config : LiveConfig, optional
    dropped_lines : callable, optional
        Returns the source's lost lines so far (read on the server's thread).
    """

    mode = "live"

    def __init__(self, camera: LineScanCamera, config: LiveConfig | None = None, *, dropped_lines: Callable[[], int] | None = None) -> None:
        self.camera = camera
        self.config = config or LiveConfig()
        self._dropped = dropped_lines
        self._inbox: deque = deque(maxlen=self.config.pending)  # (result, lag_s) from the measurement loop
        self._taken = 0  # balls handed in by the measurement loop
        self._lock = threading.Lock()
        self._ring: deque[LiveBall] = deque(maxlen=self.config.capacity)
        self._crops: dict[int, CropView] = {}
        self._next = 0  # index of the next ball
        # health, written by the measurement loop (plain numbers: no lock needed to read)
        self._t0: float | None = None
        self._first_t: float | None = None
        self._lines = 0
        self._last_read: float | None = None
        self._span_s = 0.0
        self._reads: deque[tuple[int, float]] = deque(maxlen=512)  # (lines after the chunk, wall time read)
        self._samples: deque[np.ndarray] = deque(maxlen=self.config.sample_lines)
        self._last_sample = -np.inf
        self._sampled = 0  # times lines were sampled (the strip is recomputed only after a new sample)
        self._strip_cache: tuple[int, tuple[float, ...]] = (0, ())
        self._rate = (0.0, 0, 0.0)  # (time, lines, rate) of the last rate update
        self._last_lag: float | None = None
        self._end: tuple[str, str] | None = None
        self._wake: Callable[[], Any] | None = None

    def set_wake(self, wake: Callable[[], Any] | None) -> None:
        """Call ``wake`` (from the measurement loop's thread, so it must not wait) whenever a ball is handed over."""
        self._wake = wake

    # ---------------------------------------------------- the measurement loop
    def chunks(self, source: Iterable[Any]) -> Iterator[Any]:
        """Pass the source's chunks through, noting each one (:meth:`chunk`)."""
        for ch in source:
            self.chunk(ch)
            yield ch

    def chunk(self, chunk: Any) -> None:
        """Note a chunk just read: its lines, its time, now and then a few lines for the strip.

        ``chunk`` is a :class:`ballscan.stream.engine.Chunk` or an array of lines.
        """
        now = time.perf_counter()
        lines = getattr(chunk, "lines", chunk)
        n = int(lines.shape[0])
        if self._t0 is None:
            self._t0 = now
        ts = getattr(chunk, "timestamps_s", None)
        self._lines += n
        if ts is not None and len(ts):
            if self._first_t is None:
                self._first_t = float(ts[0])
            self._span_s = float(ts[-1]) - self._first_t
        else:
            self._span_s = self._lines / self.camera.line_rate_hz
        self._reads.append((self._lines, now))
        self._last_read = now
        if n and now - self._last_sample >= self.config.sample_every_s:
            self._last_sample = now
            pick = np.linspace(0, n - 1, min(n, 4)).round().astype(int)
            for k in pick:
                self._samples.append(np.array(lines[k]))
            self._sampled += 1

    def ball(self, result: Any) -> None:
        """Hand over a measured ball (a :class:`ballscan.stream.engine.StreamResult`); never waits."""
        now = time.perf_counter()
        lag = None
        last = result.estimate.last_line
        if last is not None:
            # the chunk that held the ball's last line: the first whose end is past it
            for end, t in reversed(self._reads):
                if end <= last:
                    break
                lag = now - t
        self._taken += 1
        self._inbox.append((result, lag))
        self._notify()

    def end(self, message: str, failed: bool = False) -> None:
        """The source ended (``failed``: with a fault); ``message`` is the banner's text."""
        self._end = ("failed" if failed else "ended", message)
        self._notify()

    def _notify(self) -> None:
        wake = self._wake
        if wake is not None:
            try:
                wake()
            except RuntimeError:  # the server's loop has closed: nobody to wake
                self._wake = None

    # ---------------------------------------------------- the server's thread
    def drain(self) -> int:
        """Turn the balls handed over since the last call into the ring's entries; return how many."""
        made = 0
        while True:
            try:
                result, lag = self._inbox.popleft()
            except IndexError:
                return made
            self._add(self._make(result, lag))
            made += 1

    def _make(self, result: Any, lag: float | None) -> LiveBall:
        est = result.estimate
        crop = None
        if result.crop is not None:
            crop = crop_view(
                result.crop, result.crop_lines[0], result.crop_cols[0],
                camera=self.camera, motion=est.motion(), times_s=result.crop_times_s,
            )  # fmt: skip
        with self._lock:
            index = self._next
            self._next += 1
        return ball_from_record(result.to_dict(self.camera), index, source=result.source, lag_s=lag, crop=crop)

    def _add(self, ball: LiveBall) -> None:
        with self._lock:
            self._ring.append(ball)
            if ball.crop is not None:
                self._crops[ball.index] = ball.crop
                for k in sorted(self._crops)[: max(len(self._crops) - self.config.crop_capacity, 0)]:
                    del self._crops[k]
            if ball.lag_s is not None:
                self._last_lag = ball.lag_s

    @property
    def newest(self) -> int:
        """Index of the newest ball in the ring (-1 before the first)."""
        with self._lock:
            return self._ring[-1].index if self._ring else -1

    def balls_after(self, index: int) -> tuple[list[LiveBall], int]:
        """Balls newer than ``index`` (with their crops) and how many newer ones already left the ring."""
        with self._lock:
            newer = [b for b in self._ring if b.index > index]
            skipped = (newer[0].index - index - 1) if newer else 0
            return [self._with_crop(b) for b in newer], max(skipped, 0)

    def _with_crop(self, ball: LiveBall) -> LiveBall:
        crop = self._crops.get(ball.index)
        if crop is ball.crop:
            return ball
        return LiveBall(**{**ball.__dict__, "crop": crop})

    def balls(self, selection: BallFilter | None = None) -> list[LiveBall]:
        """The ring's balls that pass ``selection``, oldest first (crops only where kept)."""
        sel = selection or BallFilter()
        with self._lock:
            return [self._with_crop(b) for b in self._ring if sel.accepts(b)]

    def ball_detail(self, index: int) -> LiveBall | None:
        """One ball of the ring with its crop if it is still kept, else None."""
        with self._lock:
            for b in self._ring:
                if b.index == index:
                    return self._with_crop(b)
        return None

    def health(self) -> Health:
        """The stream's health now."""
        now = time.perf_counter()
        lines = self._lines
        t_rate, n_rate, rate = self._rate
        if now - t_rate >= 1.0:
            rate = (lines - n_rate) / (now - t_rate) if t_rate else 0.0
            self._rate = (now, lines, rate)
        since = None if self._last_read is None else now - self._last_read
        # at the last read: a recording read faster than real time is not behind, a camera's delay shows
        behind = 0.0 if self._t0 is None or self._last_read is None else max((self._last_read - self._t0) - self._span_s, 0.0)
        if self._end is not None:
            state, message = self._end
        elif self._t0 is None:
            state, message = "waiting", "waiting for the first lines"
        elif since is not None and since > self.config.stall_after_s:
            state, message = "stalled", f"the source stalled: no lines for {since:.1f} s"
        else:
            state, message = "running", ""
        with self._lock:
            balls = self._next
        return Health(
            state, message, lines, rate, behind, since, self._last_lag,
            int(self._dropped()) if self._dropped is not None else 0,
            balls + len(self._inbox), self._taken - balls - len(self._inbox), self._strip(), int(self.camera.width),
        )  # fmt: skip

    def _strip(self) -> tuple[float, ...]:
        """The background per bin of columns: the median over the sampled lines of each column, averaged per bin."""
        sampled, strip = self._strip_cache
        if sampled == self._sampled:
            return strip
        sampled = self._sampled
        try:
            samples = list(self._samples)
        except RuntimeError:  # appended to while copied: the next health has it
            return ()
        if not samples:
            return ()
        med = np.median(np.stack(samples).astype(np.float64), axis=0)
        bins = min(STRIP_BINS, med.size)
        edges = np.linspace(0, med.size, bins + 1).round().astype(int)
        strip = tuple(float(v) for v in np.add.reduceat(med, edges[:-1]) / np.diff(edges))
        self._strip_cache = (sampled, strip)
        return strip
