"""Does a raw stream's line width match the camera's? The background's column pattern must repeat line to line.

A line-scan camera sees the same background on every line, and its pixels'
fixed pattern (gain and offset differences, the scene's texture) repeats
with them. Read with the wrong width ``W`` a stream whose lines are ``P``
samples long shears that pattern by ``P - W`` pixels per line: its column
means over many lines wash out, and a ball's image is slanted (a 2,047-px
stream read with a 2,048-px camera gives plausible balls at 2-3 times their
speeds). :class:`WidthCheck` finds the period at which the samples repeat.

The statistic, for a candidate period ``P``: the samples of clean lines (no
ball within two lines) as one sequence ``s[i]`` (``i`` = line * W + column,
the stream's sample index), its differences ``d[i] = s[i+1] - s[i]``
(an offset per line, a smooth illumination profile and a slow drift
vanish; differences beyond ``CLIP_SIGMA`` robust sigmas are clipped, so a
ball's edge cannot dominate), their mean over the rows of ``i mod P`` gives
a profile ``m_P`` of ``P`` columns from ``n`` rows. Without a pattern of
period ``P`` each of its values is a mean of ``n`` noises, and
``R_P = mean(m_P**2) / (var(d) / n)`` is 1 with a standard deviation of
``sqrt(3 / P)`` (neighbouring differences share a sample: correlation
-1/2); with a pattern repeating at ``P`` the pattern's power adds ``n``
times over. ``z_P = (R_P - 1) / sqrt(3 / P)``.

Verdicts (:class:`WidthVerdict`): ``"confirmed"`` when the camera's width
scores ``z >= Z_DECIDE`` and at least half of the best other candidate's
(a pattern periodic in ``q`` pixels also repeats at ``W +- q``);
``"sheared"`` when another period scores ``z >= Z_DECIDE`` and the camera's
width less than a quarter of it; ``"unknown"`` otherwise (a background
without a pattern: flat, noise-free renders; nothing is claimed). The
candidates are ``W + delta`` for ``delta`` in :data:`START_OFFSETS` and
``2 W`` (lines of twice the width read as two: ``"sheared"`` when ``2 W``
scores over :data:`DOUBLE_RATIO` times ``W``) over the
first ``start_lines`` clean lines (every one), then ``W`` and ``W +- 1,2``
over one block in ``every_blocks``, judged per window of ``window_lines``
sampled lines: with the defaults, a verdict every 524,288 lines (3.7 s of a
140 kHz camera) for about 3 % of the engine's time on a stream without a
ball (``docs/benchmarks.md``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["START_OFFSETS", "RUN_OFFSETS", "DOUBLE_RATIO", "Z_DECIDE", "CLIP_SIGMA", "WidthVerdict", "WidthCheck"]

#: Width errors looked for at the start (pixels per line).
START_OFFSETS = tuple(sorted({d * s for d in (1, 2, 3, 4, 5, 6, 7, 8, 16, 32, 64) for s in (-1, 1)}))
#: Width errors looked for continuously afterwards.
RUN_OFFSETS = (-2, -1, 1, 2)
#: A pattern of period W scores 1/sqrt(2) of its W score at 2 W (half the rows, twice the
#: columns); half lines (a 2 W-px stream read as W px) score 1.4-1.5 times their W score there
#: (tests/test_width.py's streams).
DOUBLE_RATIO = 1.1
#: Score a period needs for a verdict (standard deviations of the no-pattern statistic).
Z_DECIDE = 12.0
#: Differences beyond this many robust sigmas are clipped.
CLIP_SIGMA = 6.0


@dataclass(frozen=True)
class WidthVerdict:
    """What the check says so far.

    Attributes
    ----------
    state : {"unknown", "confirmed", "sheared"}
    period_px : int or None
        The period the samples repeat at (the stream's line length) when
        decided.
    z : float
        Its score.
    z_camera : float
        The camera width's score.
    lines : int
        Lines that went into the verdict.
    """

    state: str
    period_px: int | None
    z: float
    z_camera: float
    lines: int


class _Accumulator:
    """Per-candidate sums of the differences by column (``i mod P``) and their rows."""

    def __init__(self, width: int, offsets: tuple[int, ...], double: bool = False) -> None:
        self.periods = tuple(p for p in (width, *(width + d for d in offsets), *((2 * width,) if double else ())) if p >= 2)
        self.sums = {p: np.zeros(p) for p in self.periods}
        self.rows = dict.fromkeys(self.periods, 0)
        self.sum_sq = 0.0
        self.n_samples = 0
        self.lines = 0

    def add(self, d: np.ndarray, first_index: int, n_lines: int) -> None:
        self.sum_sq += float(np.dot(d, d))
        self.n_samples += d.size
        self.lines += n_lines
        for p in self.periods:
            a = (-first_index) % p
            k = (d.size - a) // p
            if k > 0:
                # summed in float32, the differences' own type: a block's k <= 512 rows
                # round to about 1e-6 of the column sums' noise, far below the score's
                # resolution, at a third of the time of a float64 accumulation (3.3 against
                # 8.3 ms for a stream's first 512 x 2048 block and its 24 candidates)
                self.sums[p] += d[a : a + k * p].reshape(k, p).sum(axis=0)
                self.rows[p] += k

    def scores(self) -> dict[int, float]:
        var = self.sum_sq / max(self.n_samples, 1)
        out = {}
        for p in self.periods:
            n = self.rows[p]
            if n < 2 or var <= 0:
                out[p] = 0.0
                continue
            m = self.sums[p] / n
            r = float(np.mean(m * m)) / (var / n)
            out[p] = (r - 1.0) / math.sqrt(3.0 / p)
        return out


class WidthCheck:
    """Accumulates a stream's clean lines and judges its line width (see the module docstring).

    Parameters
    ----------
    width : int
        The camera's width, pixels (samples per line as read).
    start_lines : int
        Clean lines judged with every candidate at the start.
    every_blocks : int
        Afterwards, one block in this many is sampled.
    block_lines : int
        Lines of a block (the engine's).
    window_lines : int
        Sampled lines per continuous verdict.
    min_lines : int
        Fewest lines for any verdict.
    """

    def __init__(self, width: int, *, start_lines: int = 4096, every_blocks: int = 512, block_lines: int = 512, window_lines: int = 1024, min_lines: int = 128) -> None:
        if width < 2:
            raise ValueError(f"width: must be at least 2, got {width!r}")
        self.width = int(width)
        self.start_lines = int(start_lines)
        self.every_blocks = max(int(every_blocks), 1)
        self.block_lines = max(int(block_lines), 1)
        self.window_lines = int(window_lines)
        self.min_lines = int(min_lines)
        self._start = _Accumulator(self.width, START_OFFSETS, double=True)
        self._window: _Accumulator | None = None
        self.verdict = WidthVerdict("unknown", None, 0.0, 0.0, 0)

    @property
    def sheared(self) -> bool:
        """True once a verdict found the lines sheared (final)."""
        return self.verdict.state == "sheared"

    def wants(self, first_line: int) -> bool:
        """Whether lines from ``first_line`` are analysed (all at the start, then one block in ``every_blocks``)."""
        if self.sheared:
            return False
        if self._window is None and self._start.lines < self.start_lines:
            return True
        return (first_line // self.block_lines) % self.every_blocks == 0

    def add(self, lines: np.ndarray, first_line: int, clean: np.ndarray) -> WidthVerdict:
        """Add consecutive stream lines ``first_line ...`` (``(n, W)``; ``clean[k]``: no ball near line k); return the verdict.

        Runs of clean lines are analysed as contiguous samples; the rest is
        skipped.
        """
        if self.sheared or not self.wants(first_line):
            return self.verdict
        x = np.asarray(lines)
        ok = np.asarray(clean, dtype=bool)
        edges = np.flatnonzero(np.diff(np.concatenate(([0], ok.view(np.int8), [0]))))
        acc = self._start if self._window is None else self._window
        for a, b in zip(edges[::2], edges[1::2]):
            if b - a < 2:
                continue
            s = x[a:b].reshape(-1).astype(np.float32)
            d = np.diff(s)
            sig = 1.4826 * float(np.median(np.abs(d[:: max(d.size // 4096, 1)]))) + 0.5
            np.clip(d, -CLIP_SIGMA * sig, CLIP_SIGMA * sig, out=d)
            acc.add(d, (first_line + int(a)) * self.width, int(b - a))
        self._judge(acc)
        return self.verdict

    def _judge(self, acc: _Accumulator) -> None:
        if acc.lines < self.min_lines:
            return
        z = acc.scores()
        zw = z[self.width]
        z2 = z.pop(2 * self.width, None)
        if z2 is not None and z2 >= Z_DECIDE and z2 > DOUBLE_RATIO * max(zw, 0.0):
            self.verdict = WidthVerdict("sheared", 2 * self.width, z2, zw, acc.lines)
            return
        p_best = max((p for p in z if p != self.width), key=lambda p: z[p], default=self.width)
        zb = z[p_best]
        if zb >= Z_DECIDE and zw < zb / 4:
            self.verdict = WidthVerdict("sheared", p_best, zb, zw, acc.lines)
            return
        if zw >= Z_DECIDE and zw >= zb / 2:
            self.verdict = WidthVerdict("confirmed", self.width, zw, zw, acc.lines)
        elif acc is self._window and acc.lines >= self.window_lines:
            self.verdict = WidthVerdict("unknown", None, zb, zw, acc.lines)
        if acc is self._start and (self.verdict.state == "confirmed" or acc.lines >= self.start_lines):
            self._window = _Accumulator(self.width, RUN_OFFSETS)
        elif acc is self._window and acc.lines >= self.window_lines:
            self._window = _Accumulator(self.width, RUN_OFFSETS)
