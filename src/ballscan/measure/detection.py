"""Finding balls in a line-scan image: background model, threshold, regions, flags.

Background model
----------------
A stationary line-scan camera sees the same scene line after line, so the
background of pixel ``(i, j)`` is modelled as

    B[i, j] = line_gain[i] * background_dn[j] + line_offset_dn[i]

* ``background_dn[j]`` is a per-column level: the *mode* of the column,
  found by mode seeking (a median restricted to a window of +-4.5 noise
  sigmas, iterated) started from the backdrop's level on the lines no ball
  crosses (:mod:`ballscan.measure.clear_lines`: the largest set of lines
  that match one another pixel by pixel after one scale each), or, where
  fewer than three such lines are found, from the level of the neighbouring
  columns (a wide running median of the column medians). This stays on the
  background where a ball covers most of a column's lines (a plain median
  fails there once the ball covers more than half of them) and where the
  backdrop's level changes across the sensor (the neighbours' level is then
  another level), and, because the window is re-centred on the column's own
  values, follows hot/cold columns, PRNU and vignetting. Where a column has
  almost no values near its start (a strongly defective column) its level on
  the ball-free lines (else its own median) is used.
* Slow illumination drift and a lamp's flicker along time are one factor
  per line, estimated as a median over the background pixels of the line
  (pixels of a first-pass ball mask excluded), so a ball never biases it.
  The first pass is centred on the lines' medians, or, on a line where
  fewer than half the pixels lie on that level (a ball covering most of
  the line), on the scale that puts the most pixels on the ball-free
  lines' profile (:func:`ballscan.measure.clear_lines.line_levels`). The
  drift is a gain (``line_gain``, multiplicative: illumination) when the
  background is well above its noise (measured on consecutive lines
  levelled by their medians, so that a flickering lamp is not read as
  noise), and an offset (``line_offset_dn``) when the background is near
  zero, where a ratio would be unstable. The other one is then 1 / 0.
* Pixels at the saturation level where the backdrop itself reaches it (a
  bright backdrop on a flickering lamp's brightest lines) are background.
* ``noise_dn[j]`` is a per-column noise sigma (DN): the standard deviation
  of the column's values in the mode seeking's last window, floored at
  ``noise_floor_dn`` (default 0.5 DN, the quantisation of integer data) and
  at a quarter of the image's median column noise.
* A caller that already knows the columns' level and noise (the stream
  engine's running model, learned on thousands of lines before the ball)
  passes them as a :class:`ColumnModel`: the per-column mode seeking is
  skipped, and only the per-line drift is estimated from the image.

Regions
-------
Pixels whose residual ``|X - B|`` exceeds ``k_sigma * noise_dn[j]`` are
labelled (8-connected); pieces closer than ``merge_gap_px`` are grouped (a
textured ball's seam or shaded limb can match the background and cut its
silhouette into pieces); a group smaller than ``min_area_px`` is rejected
(noise and hot pixels give single pixels at this threshold). A region's mask
is the group's pixels with holes filled along each line and each column
(between the first and last ball pixel of a line, or of a column, is ball).
A group whose lines or columns contain two separate runs of ball pixels (on
two or more neighbouring lines or columns: one alone is a ragged edge) is
two merged balls: it is split at the gap when the two parts are cleanly
apart along one axis, and flagged ``"overlap"`` either way.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..compiled import as_arg
from ._detection_kernels import (
    fill_lines_and_cols,
    first_pass_lines,
    group_mask,
    integer_median_mad,
    kept_median,
    label_hits,
    mode_seek,
    multi_runs,
    reflect_median_filter,
    region_values,
    second_level,
)
from .clear_lines import ClearLines, clear_line_levels, column_noise, line_levels
from .images import LineImage
from .robust import MAD_TO_SIGMA, median

__all__ = [
    "BallRegion",
    "ColumnModel",
    "Detection",
    "detect",
    "background_at",
    "region_background",
    "FLAG_WORDS",
]

#: Flags a region can carry (geometry.md vocabulary).
FLAG_WORDS = ("cut_first_line", "cut_last_line", "cut_sensor_end", "overlap", "saturated")

_BIG = 1e300  # stand-in for "excluded" in masked medians (finite: no inf-inf NaNs)


@dataclass(frozen=True)
class BallRegion:
    """One ball's image region.

    Attributes
    ----------
    index : int
        Position in :attr:`Detection.regions` (0-based).
    line_start, line_stop : int
        Scan lines ``[line_start, line_stop)`` holding ball pixels.
    col_start, col_stop : int
        Sensor pixels ``[col_start, col_stop)`` holding ball pixels.
    mask : numpy.ndarray
        bool, shape ``(line_stop - line_start, col_stop - col_start)``: ball
        pixels of the box, holes filled along lines and columns. Partially
        covered limb pixels below the threshold are not in it: the edge
        extractor should look one or two pixels beyond the mask.
    polarity : int
        +1 if the ball is brighter than the background, -1 if darker.
    contrast_dn : float
        Robust (median) ball-minus-background level over the mask, DN,
        signed (same sign as ``polarity``).
    flags : tuple of str
        Words from :data:`FLAG_WORDS` (geometry.md).
    n_pixels : int
        Number of pixels above threshold (before hole filling).
    both_signs : bool
        More than :data:`OTHER_SIGN_SHARE` of the mask's pixels lie on the
        other side of the backdrop (a bright ball's side in shadow darker
        than the backdrop): ``contrast_dn`` is that of the larger side, and
        the edges may lie on a limb of either sign
        (:func:`ballscan.measure.edges.measure_edges`).
    """

    index: int
    line_start: int
    line_stop: int
    col_start: int
    col_stop: int
    mask: np.ndarray
    polarity: int
    contrast_dn: float
    flags: tuple[str, ...]
    n_pixels: int = 0
    both_signs: bool = False

    def __post_init__(self) -> None:
        if not (0 <= self.line_start < self.line_stop and 0 <= self.col_start < self.col_stop):
            raise ValueError(
                f"BallRegion: the box must be non-empty and non-negative, got lines [{self.line_start}, {self.line_stop}) "
                f"and columns [{self.col_start}, {self.col_stop})"
            )
        box = (self.line_stop - self.line_start, self.col_stop - self.col_start)
        if np.shape(self.mask) != box:
            raise ValueError(f"BallRegion.mask: must have the box's shape {box}, got {np.shape(self.mask)}")
        if self.polarity not in (1, -1):
            raise ValueError(f"BallRegion.polarity: must be +1 or -1, got {self.polarity!r}")
        if not all(f in FLAG_WORDS for f in self.flags):
            raise ValueError(f"BallRegion.flags: must be words of FLAG_WORDS {FLAG_WORDS}, got {self.flags!r}")

    @property
    def lines(self) -> slice:
        """Slice of the box along the scan lines (rows)."""
        return slice(self.line_start, self.line_stop)

    @property
    def cols(self) -> slice:
        """Slice of the box along the sensor (columns)."""
        return slice(self.col_start, self.col_stop)


@dataclass(frozen=True, eq=False)
class ColumnModel:
    """A known per-column background (the stream engine's running model).

    Attributes
    ----------
    background_dn : numpy.ndarray
        float64, shape ``(W,)``: per-column background level, DN, at the
        line gain (or offset) of the lines the model was learned on.
    noise_dn : numpy.ndarray
        float64, shape ``(W,)``: per-column noise sigma, DN.

    Both are stored as read-only float64 copies; models compare by identity
    (arrays have no single truth value).
    """

    background_dn: np.ndarray
    noise_dn: np.ndarray

    def __post_init__(self) -> None:
        b = np.array(self.background_dn, dtype=np.float64)
        s = np.array(self.noise_dn, dtype=np.float64)
        for name, a in (("background_dn", b), ("noise_dn", s)):
            a.setflags(write=False)
            object.__setattr__(self, name, a)
        if b.ndim != 1 or s.shape != b.shape or b.size < 2:
            raise ValueError(f"ColumnModel: background_dn and noise_dn must be 1-D of one length >= 2, got {b.shape} and {s.shape}")
        if not (np.all(np.isfinite(b)) and np.all(np.isfinite(s)) and np.all(s >= 0)):
            raise ValueError("ColumnModel: levels must be finite and noise sigmas finite and >= 0")


@dataclass(frozen=True)
class Detection:
    """Background model and ball regions of one image.

    Attributes
    ----------
    background_dn : numpy.ndarray
        float64, shape ``(W,)``: per-column background level (DN) at a line
        gain of 1. The background of line ``i`` is
        ``line_gain[i] * background_dn + line_offset_dn[i]``; use
        :func:`background_at` for the 2-D value.
    noise_dn : numpy.ndarray
        float64, shape ``(W,)``: per-column noise sigma (DN), floored.
    regions : tuple of BallRegion
        Ordered by first line, then by mid line (~ t_c), then first column.
    saturation_dn : float
        Level (DN) at or above which pixels are clipped.
    line_gain : numpy.ndarray
        float64, shape ``(n_lines,)``: multiplicative drift per line.
    line_offset_dn : numpy.ndarray
        float64, shape ``(n_lines,)``: additive drift per line (DN).
    drift_model : str
        ``"gain"`` or ``"offset"``: which of the two is estimated.
    threshold_sigma : float
        The ``k_sigma`` used.
    """

    background_dn: np.ndarray
    noise_dn: np.ndarray
    regions: tuple[BallRegion, ...]
    saturation_dn: float
    line_gain: np.ndarray
    line_offset_dn: np.ndarray
    drift_model: str = "gain"
    threshold_sigma: float = 4.0

    @property
    def shape(self) -> tuple[int, int]:
        """``(n_lines, W)`` of the image."""
        return (int(self.line_gain.shape[0]), int(self.background_dn.shape[0]))


def background_at(detection: Detection, lines, cols) -> np.ndarray:
    """Background level (DN) on the grid ``lines x cols``.

    Parameters
    ----------
    detection : Detection
    lines, cols : slice, int array or int
        Scan lines and sensor pixels (anything that indexes a 1-D array).

    Returns
    -------
    numpy.ndarray
        float64, shape ``(len(lines), len(cols))``.
    """
    g = np.atleast_1d(detection.line_gain[lines])
    o = np.atleast_1d(detection.line_offset_dn[lines])
    b = np.atleast_1d(detection.background_dn[cols])
    return g[:, None] * b[None, :] + o[:, None]


def region_background(
    detection: Detection, region: BallRegion, margin: int = 0
) -> tuple[np.ndarray, np.ndarray, tuple[slice, slice]]:
    """Background and noise around one region, for the edge extractor.

    Parameters
    ----------
    detection : Detection
    region : BallRegion
    margin : int, optional
        Pixels added on every side of the region's box (clipped to the image).

    Returns
    -------
    background : numpy.ndarray
        float64, shape of the (padded) box: background level (DN).
    noise : numpy.ndarray
        float64, one value per column of the box: noise sigma (DN).
    box : tuple of slice
        ``(lines, cols)`` of the padded box in image coordinates.
    """
    n, w = detection.shape
    m = max(int(margin), 0)
    ls = slice(max(region.line_start - m, 0), min(region.line_stop + m, n))
    cs = slice(max(region.col_start - m, 0), min(region.col_stop + m, w))
    return background_at(detection, ls, cs), detection.noise_dn[cs].copy(), (ls, cs)


# --------------------------------------------------------------------------
# Robust statistics helpers (vectorised)
# --------------------------------------------------------------------------
def _row_median(a: np.ndarray) -> np.ndarray:
    """``np.median(a, axis=1)`` of a 2-D array with at least one column, by sorting the rows."""
    s = np.sort(a, axis=1)
    h = s.shape[1] // 2
    return s[:, h] if s.shape[1] % 2 else (s[:, h - 1] + s[:, h]) / 2


def _masked_median(s: np.ndarray, excluded: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Median of the non-excluded values of each row and their count.

    ``s`` holds the rows with their excluded values set to +inf (sorted here,
    in place) and ``excluded`` the number of them per row.  The median is
    defined as that of the row with its excluded values replaced by
    alternately +BIG and -BIG (in the order they occur), so that they cancel
    in pairs: the median of the kept values, to half a rank when the number
    excluded is odd. Computed without building that row: the middle ranks of
    the virtual row ``[-BIG] * (e // 2) + kept + [+BIG] * ((e + 1) // 2)``
    are looked up among the sorted kept values. Rows with no kept value
    give 0; check the count.
    """
    s.sort(axis=1)
    # the look-up, compiled (_detection_kernels.kept_median)
    return kept_median(s, as_arg(excluded, np.int64), _BIG)


def _mode_seek(
    s: np.ndarray, start: np.ndarray, sigma: np.ndarray, floor: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mode and noise of each row of the row-sorted ``s`` by mode seeking.

    Each iteration takes the values within +-4.5 sigma of the current centre
    and moves the centre to their median (the final level is their mean). After two iterations sigma becomes
    the standard deviation of the window's values (a +-4.5 sigma window keeps
    99.9993 % of Gaussian noise, so that is the noise sigma; an IQR would be
    coarse on integer data), and two more iterations follow with it. Ball
    values far from the background never enter the window.

    Because the rows are sorted, a window is an index range, found by a
    binary search in O(log n) per row (``s`` is float32: the window test and
    the offsets from the centre are in float32, the sums in float64).

    Returns
    -------
    centre, sigma, count : numpy.ndarray
        Per row: the mode, the noise sigma and the number of values in the
        final window.
    """
    # compiled (_detection_kernels.mode_seek): the rounds per row, without the numpy
    # form's whole-array temporaries
    return mode_seek(as_arg(s, np.float32), as_arg(start), as_arg(sigma), float(floor))


def _global_noise(x: np.ndarray) -> float:
    """Noise sigma (DN) from differences of consecutive lines (balls are rare outliers); ``x`` float32."""
    if x.shape[0] < 2:
        return 0.0
    d = np.diff(x, axis=0).ravel()
    # ~100k differences pin sigma to well under 1 %: no need for more.
    d = d[:: max(1, d.size // 100_000)]
    if d.size == 0:
        return 0.0
    # Integer data (the usual case): both medians by counting, exact and
    # cheaper than two selections.
    ok, _, mad = integer_median_mad(as_arg(d, np.float32))
    mad = np.float32(mad) if ok else median(np.abs(d - median(d)))
    return float(MAD_TO_SIGMA * mad / np.sqrt(2.0))


# --------------------------------------------------------------------------
# Background model
# --------------------------------------------------------------------------
#: Most lines the per-column background mode and noise are measured on (:func:`_column_modes`).
_MODE_LINES = 2048
#: A column's lines off its mode are taken for a ball's unless this share of them lies at one level.
_TAIL_SHARE = 0.5
#: The lines' medians hold where at most this share of each line's pixels lie off its median's level.
_LINE_OFF_SHARE = 0.5


@dataclass(frozen=True)
class _ColumnStart:
    """Per-column level and noise sigma (DN, not floored) and the first per-line drift.

    The drift is a gain (``use_gain``; ``line_offset_dn`` 0) or an offset
    (``line_gain`` 1), from the lines' medians.
    """

    background_dn: np.ndarray
    noise_dn: np.ndarray
    line_gain: np.ndarray
    line_offset_dn: np.ndarray
    use_gain: bool


@dataclass(frozen=True)
class _Background:
    """The image's background model (the fields of :class:`Detection` of the same names)."""

    background_dn: np.ndarray
    noise_dn: np.ndarray
    line_gain: np.ndarray
    line_offset_dn: np.ndarray
    drift_model: str


def _background(
    x: np.ndarray, noise_floor_dn: float, first_pass_k: float, known: ColumnModel | None = None, saturation_dn: float = np.inf
) -> _Background:
    """The background model of the float32 image ``x`` (see the module docstring), with the columns of ``known`` where given.

    The columns' modes and the lines' medians are tried first (one sort of
    the sampled columns, one pass over the subsampled lines). They hold
    where no column's lines off its mode hold another level that the
    image's first or last line shows (a backdrop under an even ball's
    middle, see :func:`_column_modes`), no column is defective and every
    line has at most ``_LINE_OFF_SHARE`` of its pixels off its median's
    level. Only an image that fails a check pays for the search of its
    ball-free lines (:mod:`ballscan.measure.clear_lines`).
    """
    n, w = x.shape
    # Column subsample for per-line statistics: a few hundred columns give a
    # per-line level to a small fraction of the noise, at a fraction of the cost.
    step = max(1, w // 512)
    xs = x[:, ::step]
    # Per-line level from the line medians: balls cover a minority of a line.
    level = _row_median(xs)
    if known is not None:
        # a writeable copy: the kernels below take writeable arrays (a
        # read-only one would compile a second signature on a stream ball)
        b = known.background_dn.copy()
        sig = np.maximum(known.noise_dn, noise_floor_dn)
        # the known levels hold the drift of the lines they were learned on:
        # this image's lines are measured relative to them
        ref = float(median(b[::step]))
        use_gain = ref > 10.0 * max(float(median(sig)), noise_floor_dn) and float(level.min()) > 0.0
        gain0 = level / ref if use_gain else np.ones(n)
        offset0 = np.zeros(n) if use_gain else level - ref
        start = _ColumnStart(background_dn=b, noise_dn=sig, line_gain=gain0, line_offset_dn=offset0, use_gain=use_gain)
        return _line_drift(xs, step, start, noise_floor_dn, first_pass_k)[0]
    ref = float(median(level))
    sigma0, use_gain = _drift_noise(xs, level, noise_floor_dn)
    first = level / ref if use_gain else level - ref
    start, held = _column_modes(x, first, use_gain, sigma0, noise_floor_dn)
    bg, off_share = _line_drift(xs, step, start, noise_floor_dn, first_pass_k)
    if held and off_share <= _LINE_OFF_SHARE:
        return bg
    clear, col_noise, first = _clear_start(x, level, ref, use_gain, noise_floor_dn, first, sigma0, saturation_dn)
    if clear is None:
        # no backdrop seen alone often enough: the modes and medians stand
        return bg
    start, _ = _column_modes(x, first, use_gain, sigma0, noise_floor_dn, clear, col_noise)
    return _line_drift(xs, step, start, noise_floor_dn, first_pass_k)[0]


def _drift_noise(xs: np.ndarray, level: np.ndarray, noise_floor_dn: float) -> tuple[float, bool]:
    """The image's noise sigma (DN) and whether its drift is a gain, from the subsampled ``xs``.

    The noise is measured on the differences of consecutive lines. Where
    the lines' levels change from line to line by more than a quarter of
    that (a flickering lamp), the differences read the change as noise (and
    the offset model would be chosen on a bright backdrop): the noise is
    then also measured on the lines levelled both ways (scaled and shifted
    to the reference level, :func:`ballscan.measure.clear_lines.column_noise`)
    and the least is taken.
    """
    ref = float(median(level))
    positive = float(level.min()) > 0.0
    sigma0 = max(_global_noise(xs[:, ::2]), noise_floor_dn)
    k = -(-xs.shape[0] // _MODE_LINES)
    # some 128 columns decide the model
    sub, lev = xs[::k, :: max(1, xs.shape[1] // 128)], level[::k]
    if sub.shape[0] >= 8:
        dl = np.diff(lev)
        spread = MAD_TO_SIGMA * float(median(np.abs(dl - median(dl))))
        if spread > 0.25 * sigma0:
            per = [column_noise(sub, lev, ref, g) for g in ((True, False) if positive else (False,))]
            sigma0 = max(min([sigma0] + [float(median(v)) for v in per]), noise_floor_dn)
    return sigma0, ref > 10.0 * sigma0 and positive


def _clear_start(
    x: np.ndarray, level_full: np.ndarray, ref: float, use_gain: bool, noise_floor_dn: float, first: np.ndarray, sigma0: float, saturation_dn: float
) -> tuple[ClearLines | None, np.ndarray, np.ndarray]:
    """The ball-free lines' profile (:mod:`ballscan.measure.clear_lines`), the columns' noise and the lines' first scale (offset) on it."""
    k = -(-x.shape[0] // _MODE_LINES)
    sub = x[::k]
    if sub.shape[0] >= 8:
        cols = column_noise(sub, level_full[::k], ref, use_gain)
        cols = np.maximum(cols, max(noise_floor_dn, 0.25 * float(median(cols))))
    else:
        cols = np.full(x.shape[1], sigma0)
    clear = clear_line_levels(x, level_full, ref, cols, use_gain, saturation_dn) if x.shape[0] >= 8 else None
    if clear is None:
        return None, cols, first
    return clear, cols, line_levels(x, clear.level_dn, cols, first, clear.scale_range, use_gain, saturation_dn=saturation_dn)


def _column_modes(
    x: np.ndarray,
    first: np.ndarray,
    use_gain: bool,
    sigma0: float,
    noise_floor_dn: float,
    clear: ClearLines | None = None,
    col_noise: np.ndarray | None = None,
) -> tuple[_ColumnStart, bool]:
    """Per-column background mode and noise (see the module docstring), with the lines' first drift ``first``.

    Started from the neighbouring columns' level, or from the ball-free
    lines' profile ``clear`` (their noise ``col_noise``) where given.
    Returns the start and whether the modes hold on their own: no
    ``clear`` given, no defective column, and no column whose lines off
    its mode hold, for at least ``_TAIL_SHARE`` of them, one level within
    the noise that its first or last line lies off the mode (that level
    may be the backdrop's and the mode an even ball's over most of the
    column's lines).
    """
    gain0 = first if use_gain else np.ones(first.size)
    offset0 = np.zeros(first.size) if use_gain else first
    # The columns' statistics from at most _MODE_LINES evenly spaced lines:
    # their level is then known to a few hundredths of the noise, and the
    # cost of the sorts below does not grow with the image's length.
    k = -(-x.shape[0] // _MODE_LINES)
    x, g, o = x[::k], gain0[::k], offset0[::k]
    n, w = x.shape
    # Per-column mode, started from the neighbours' level, on the columns with
    # the per-line level removed: s is (W, n), each column sorted. It is
    # written transposed and sorted in place (sorting a transposed view
    # copies every row first).
    s = np.empty((w, n), dtype=x.dtype)
    if use_gain:
        np.divide(x.T, g.astype(x.dtype)[None, :], out=s)
    else:
        np.subtract(x.T, o.astype(x.dtype)[None, :], out=s)
    s.sort(axis=1)
    col_med = (s[:, n // 2] if n % 2 else 0.5 * (s[:, n // 2 - 1] + s[:, n // 2])).astype(np.float64)
    if clear is not None:
        # the ball-free lines' level: the backdrop's own, where a ball covers
        # most of a column's lines or the backdrop changes across the sensor
        neighbours = clear.level_dn
    else:
        neighbours = _neighbour_level(col_med)
    sig_start = np.full(w, sigma0)
    b, sig, cnt = _mode_seek(s, neighbours, sig_start, noise_floor_dn)
    min_support = max(3, int(np.ceil(0.03 * n)))
    weak = cnt < min_support
    if np.any(weak) and clear is not None:
        b[weak] = clear.level_dn[weak]
        sig[weak] = col_noise[weak]
    elif np.any(weak):
        # A column whose values are nowhere near its neighbours' level is a
        # defective (hot/cold) column, not a ball: use its own mode.
        b2, sig2, _ = _mode_seek(s[weak], col_med[weak], sig_start[weak], noise_floor_dn)
        b[weak] = b2
        sig[weak] = sig2
    held = clear is None and not np.any(weak)
    if held:
        # The lines off a column's mode are a ball's, unless most of them
        # hold one level within the noise and the first or last line is
        # among them: then they may be the backdrop's (seen at an end of
        # the image, where a ball is only if it is cut there), and the mode
        # an even ball's over most of the column's lines.
        half = 4.5 * np.maximum(sig, noise_floor_dn)
        tail, dense = second_level(s, b, half)
        ends = (np.abs(_levelled_line(x, g, o, use_gain, 0) - b) > half) | (np.abs(_levelled_line(x, g, o, use_gain, n - 1) - b) > half)
        held = not np.any((dense >= min_support) & (dense >= _TAIL_SHARE * tail) & ends)
    return _ColumnStart(background_dn=b, noise_dn=sig, line_gain=gain0, line_offset_dn=offset0, use_gain=use_gain), held


def _levelled_line(x: np.ndarray, g: np.ndarray, o: np.ndarray, use_gain: bool, i: int) -> np.ndarray:
    """Line ``i`` of ``x`` brought to the reference level as the sorted columns are (divided by its gain, or its offset removed)."""
    return x[i] / g[i] if use_gain else x[i] - o[i]


def _neighbour_level(col_med: np.ndarray) -> np.ndarray:
    """The level of each column's neighbours: a wide running median of the columns' medians."""
    w = col_med.size
    # Wide enough to out-vote a run of up to ~127 ball-dominated columns (a
    # median filter leaves monotone profiles such as vignetting unchanged).
    win = max(w // 4, 255) | 1
    # "reflect", not "nearest": at a sensor end "nearest" repeats the end column
    # half a window long, and a ball covering that end would out-vote the background.
    size = min(win, 2 * w - 1)
    if np.isnan(col_med).any():
        from scipy.ndimage import median_filter  # only here: scipy.ndimage takes a quarter second to import

        return median_filter(col_med, size=size, mode="reflect")
    # compiled (_detection_kernels.reflect_median_filter): ndi.median_filter's values
    return reflect_median_filter(col_med, size)


def _line_drift(
    xs: np.ndarray, step: int, start: _ColumnStart, noise_floor_dn: float, first_pass_k: float
) -> tuple[_Background, float]:
    """Per-line gain or offset from the background pixels of the subsampled columns ``xs`` (every ``step``-th), and the floored noise.

    Also returns the largest share of a line's pixels off its first level
    (beyond ``first_pass_k`` noise): above one half, that level is a ball's.
    """
    n = xs.shape[0]
    b, sig, gain0, offset0, use_gain = start.background_dn, start.noise_dn, start.line_gain, start.line_offset_dn, start.use_gain
    # First-pass ball mask on the subsampled columns, then per-line drift from
    # background pixels only.
    bs = b[::step]
    thr = first_pass_k * np.maximum(sig[::step], noise_floor_dn)
    # the residual, the exclusion and the samples in one compiled pass
    # (_detection_kernels.first_pass_lines)
    samples, n_excluded = first_pass_lines(
        as_arg(xs, np.float32), as_arg(gain0), as_arg(offset0), as_arg(bs), as_arg(thr), use_gain
    )
    off_share = float(n_excluded.max()) / xs.shape[1] if n else 0.0
    v, c = _masked_median(samples, n_excluded)
    good = c >= max(3, xs.shape[1] // 10)
    if use_gain:
        gain = _fill_bad(v, good, gain0)
        offset = np.zeros(n)
    else:
        offset = _fill_bad(v, good, offset0)
        gain = np.ones(n)

    # Noise floor: the quantisation floor, and not less than a quarter of the
    # typical column noise (a column with too few background values to
    # measure must not get a tiny sigma and flood the mask).
    typical = float(median(sig)) if sig.size else noise_floor_dn
    noise = np.maximum(sig, max(noise_floor_dn, 0.25 * typical))
    bg = _Background(background_dn=b, noise_dn=noise, line_gain=gain, line_offset_dn=offset, drift_model="gain" if use_gain else "offset")
    return bg, off_share


def _fill_bad(values: np.ndarray, good: np.ndarray, fallback: np.ndarray) -> np.ndarray:
    """Replace values of lines without enough background by interpolation (or the fallback)."""
    if np.all(good):
        return values
    if not np.any(good):
        return fallback.astype(np.float64)
    idx = np.arange(values.size)
    return np.interp(idx, idx[good], values[good])


# --------------------------------------------------------------------------
# Regions
# --------------------------------------------------------------------------
# the closing that tells a ragged edge from a notch between two balls (pixels)
_NOTCH_CLOSE_PX = 2


def _merged_runs(m: np.ndarray, closed: np.ndarray, axis: int) -> np.ndarray:
    """Lines (``axis=1``) or columns (``axis=0``) of ``closed`` (the closed ``m``) in two or more runs, less a ragged edge.

    A line (column) in two runs counts where its neighbour is in two runs
    too, in ``closed`` or, with ``m`` closed by only ``_NOTCH_CLOSE_PX``
    pixels, there: a notch between two touching balls shows on several
    neighbouring lines of the lightly closed mask even where the full
    closing leaves it on one line at each end of their overlap (a small
    ball beside a large one, which would otherwise pass as one clean ball).
    One such line alone in both is a ragged edge: on a long ball the column
    at its widest point is covered by a fraction of a pixel for hundreds of
    lines, its pixels cross the threshold only now and then, and gaps longer
    than the closing's leave it in two runs (a fast ball of Fig. 5 would
    otherwise be split at such a column into two "overlapping" balls).
    """
    # compiled (_detection_kernels.multi_runs)
    out, lone = multi_runs(as_arg(closed, np.bool_), axis)
    if np.any(lone):
        light, _ = multi_runs(as_arg(_close(m, _NOTCH_CLOSE_PX), np.bool_), axis)
        out |= lone & light
    return out


def _valid_run(f: np.ndarray, k: int, op: np.ufunc, axis: int) -> np.ndarray:
    """``op`` (logical or / and) over every window of ``k`` entries along ``axis`` (0 or 1), windows inside ``f`` only.

    Entry ``i`` of the result combines ``f[i : i + k]`` along ``axis`` (the
    result is ``k - 1`` shorter). Built by doubling: windows of 1, 2, 4, ...
    entries, then two overlapping windows of the largest such length (or and
    and are idempotent, so the overlap does not matter): a few whole-array
    boolean operations instead of a per-pixel running filter.
    """

    def head(g: np.ndarray, d: int) -> np.ndarray:
        return g[:-d] if axis == 0 else g[:, :-d]

    def tail(g: np.ndarray, d: int) -> np.ndarray:
        return g[d:] if axis == 0 else g[:, d:]

    g = f
    length = 1
    while 2 * length <= k:
        g = op(head(g, length), tail(g, length))
        length *= 2
    if length < k:
        g = op(head(g, k - length), tail(g, k - length))
    return g


def _close(m: np.ndarray, r: int) -> np.ndarray:
    """Binary closing by a (2r+1)^2 square, as if the mask were surrounded by background (no edge effects).

    A square is the sum of a horizontal and a vertical segment, so the
    dilation and the erosion are each two 1-D window operations. The mask is
    padded by ``2 r`` background pixels and only windows inside the padded
    array are formed: the dilation then sees all the background it would see
    in an unbounded plane, and the erosion of the ``r``-wide dilated border
    never needs a pixel beyond it (this runs on every stream event's crop).
    """
    if r <= 0:
        return m
    k = 2 * r + 1
    p = np.zeros((m.shape[0] + 4 * r, m.shape[1] + 4 * r), dtype=bool)
    p[2 * r : -2 * r, 2 * r : -2 * r] = m
    d = _valid_run(_valid_run(p, k, np.logical_or, 0), k, np.logical_or, 1)
    return _valid_run(_valid_run(d, k, np.logical_and, 0), k, np.logical_and, 1)


def _split(m: np.ndarray, r: int, min_area: int) -> list[_RawRegion] | None:
    """Try to split a merged mask into two parts cleanly apart along one axis.

    Returns the two parts (their first line and column relative to the
    box's, ``merged`` True); an empty list where the only cuts found leave a
    cap of one ball (:func:`_is_cap`: the mask is one ball with an inner
    gap); None otherwise.
    """
    capped = False
    closed = _close(m, r)
    for axis in (1, 0):  # first apart along the sensor (same time), then in time
        multi = _merged_runs(m, closed, axis)
        if not np.any(multi):
            continue
        # Gap centres along the other axis, on the lines (or columns) with two runs.
        sub = closed[multi, :] if axis == 1 else closed[:, multi].T
        centres = []
        for row in sub:
            idx = np.flatnonzero(row)
            gaps = np.flatnonzero(np.diff(idx) > 1)
            if gaps.size:
                g = gaps[0]
                centres.append(0.5 * (idx[g] + idx[g + 1]))
        if not centres:
            continue
        cut = int(np.floor(np.median(centres))) + 1
        if axis == 1:
            a, b = m[:, :cut], m[:, cut:]
            offs = ((0, 0), (0, cut))
        else:
            a, b = m[:cut, :], m[cut:, :]
            offs = ((0, 0), (cut, 0))
        if a.sum() < min_area or b.sum() < min_area:
            continue
        if _is_cap(a, axis, at_end=True) or _is_cap(b, axis, at_end=False):
            capped = True  # one ball whose inner gap (texture, a shaded side) reaches the cut
            continue
        parts = []
        for (dl, dc), part in zip(offs, (a, b)):
            rows = np.flatnonzero(part.any(axis=1))
            cols = np.flatnonzero(part.any(axis=0))
            crop = part[rows[0] : rows[-1] + 1, cols[0] : cols[-1] + 1]
            cc = _close(crop, r)
            if np.any(_merged_runs(crop, cc, 1)) or np.any(_merged_runs(crop, cc, 0)):
                parts = None
                break
            parts.append(_RawRegion(int(dl + rows[0]), int(dc + cols[0]), crop, True))
        if parts:
            return parts
    return [] if capped else None


#: A split part whose widest chord lies within this share of its length from the cut is a cap of a
#: ball that goes on beyond the cut, not a ball of its own (:func:`_is_cap`).
_CAP_SHARE = 0.2


def _is_cap(part: np.ndarray, axis: int, at_end: bool) -> bool:
    """Whether a part of a split mask widens towards the cut: a cap of one ball, not a second ball.

    Two touching balls meet at a notch, and each part is widest about its
    ball's middle, away from the cut (for two equal balls overlapping by
    less than three quarters of a diameter, more than a fifth of the part's
    length from it); a ball cut through an inner gap (a seam, a dark patch
    or a shaded side that reaches its outline) leaves a part that is widest
    at the cut or just beyond the gap.  ``axis`` is the split's (0: in time,
    the part's chords per line; 1: along the sensor, per column),
    ``at_end`` whether the cut lies after the part's last line (column)
    rather than before its first.
    """
    lines = part if axis == 0 else part.T
    rows = np.flatnonzero(lines.any(axis=1))
    if rows.size < 2:
        return False
    width = np.array([np.ptp(np.flatnonzero(lines[i])) + 1 for i in rows])
    # the widest chord nearest the cut, as a share of the part's length from the cut
    widest = rows[np.flatnonzero(width == width.max())[-1 if at_end else 0]]
    from_cut = (rows[-1] - widest) if at_end else (widest - rows[0])
    return bool(from_cut <= _CAP_SHARE * (rows[-1] - rows[0]))


def _group_components(
    lab: np.ndarray, boxes: np.ndarray, sizes: np.ndarray, gap: int, min_piece: int
) -> list[list[int]]:
    """Group labelled pieces closer than ``gap`` pixels (union-find on boxes, checked on pixels).

    ``boxes[k]`` is ``(line_start, line_stop, col_start, col_stop)`` and
    ``sizes[k]`` the pixel count of label ``k + 1``.
    """
    ids = np.flatnonzero(sizes >= min_piece).tolist()
    if not ids:
        return []
    box = boxes[ids]
    parent = list(range(len(ids)))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    if len(ids) > 1:
        l0, l1, c0, c1 = (box[:, q] for q in range(4))
        from scipy.ndimage import binary_dilation  # pieces near each other only

        st = np.ones((2 * gap + 1, 2 * gap + 1), dtype=bool)
        for i, j in _near_pairs(box, gap):
            if find(i) == find(j):
                continue
            # Pixel-level check where a pixel of one can lie within gap of the
            # other: both boxes widened by gap, intersected (a small piece beside
            # a large one costs its own box, not the large one's)
            ls = slice(max(l0[i], l0[j]) - gap, min(l1[i], l1[j]) + gap)
            cs = slice(max(c0[i], c0[j]) - gap, min(c1[i], c1[j]) + gap)
            ls = slice(max(ls.start, 0), ls.stop)
            cs = slice(max(cs.start, 0), cs.stop)
            sub = lab[ls, cs]
            mi = binary_dilation(sub == ids[i] + 1, st)
            if np.any(mi & (sub == ids[j] + 1)):
                parent[find(i)] = find(j)
    groups: dict[int, list[int]] = {}
    for i in range(len(ids)):
        groups.setdefault(find(i), []).append(ids[i])
    return list(groups.values())


def _near_pairs(box: np.ndarray, gap: int, block: int = 1024):
    """Index pairs ``(i, j)``, ``i < j``, of boxes ``(line_start, line_stop, col_start, col_stop)`` closer than ``gap``, in row order.

    Compared a block of rows at a time: memory grows with the number of
    boxes, not with its square.
    """
    l0, l1, c0, c1 = (box[:, q] for q in range(4))
    n = len(box)
    for a in range(0, n, block):
        b = min(a + block, n)
        near = (
            (l0[a:b, None] - gap < l1[None, :])
            & (l0[None, :] - gap < l1[a:b, None])
            & (c0[a:b, None] - gap < c1[None, :])
            & (c0[None, :] - gap < c1[a:b, None])
        )
        ii, jj = np.nonzero(near)
        keep = jj > ii + a
        yield from zip((ii[keep] + a).tolist(), jj[keep].tolist())


@dataclass(frozen=True)
class _RawRegion:
    """A ball's mask before hole filling: its box's first line and column, its pixels, and whether it was merged with another ball."""

    line_start: int
    col_start: int
    mask: np.ndarray
    merged: bool


def _check_detect_settings(k_sigma: float, min_area_px: int, merge_gap_px: int, noise_floor_dn: float) -> None:
    """One precise ``ValueError`` for a setting of :func:`detect` out of its range."""
    if not (isinstance(k_sigma, (int, float, np.integer, np.floating)) and np.isfinite(k_sigma) and k_sigma > 0):
        raise ValueError(f"k_sigma must be a positive number, got {k_sigma}")
    if not (isinstance(min_area_px, (int, np.integer)) and not isinstance(min_area_px, bool) and min_area_px >= 1):
        raise ValueError(f"min_area_px must be an integer >= 1, got {min_area_px!r}")
    if not (isinstance(merge_gap_px, (int, np.integer)) and not isinstance(merge_gap_px, bool) and merge_gap_px >= 0):
        raise ValueError(f"merge_gap_px must be an integer >= 0, got {merge_gap_px!r}")
    if not (isinstance(noise_floor_dn, (int, float, np.integer, np.floating)) and np.isfinite(noise_floor_dn) and noise_floor_dn >= 0):
        raise ValueError(f"noise_floor_dn must be a finite number >= 0, got {noise_floor_dn!r}")


def _raw_regions(lab: np.ndarray, boxes: np.ndarray, sizes: np.ndarray, gap: int, min_area_px: int) -> list[_RawRegion]:
    """The groups of labelled pieces large enough to be balls, two merged balls split where they are cleanly apart."""
    out: list[_RawRegion] = []
    nlab = sizes.size
    for grp in _group_components(lab, boxes, sizes, gap, min_piece=2):
        area = int(sizes[grp].sum())
        if area < min_area_px:
            continue
        first, stop = boxes[grp].min(axis=0), boxes[grp].max(axis=0)
        l0, l1, c0, c1 = int(first[0]), int(stop[1]), int(first[2]), int(stop[3])
        if l1 - l0 < 2 or c1 - c0 < 2:
            continue  # a hot pixel run along one line or one column
        in_group = np.zeros(nlab + 1, dtype=bool)
        in_group[np.asarray(grp) + 1] = True
        # in_group[lab[l0:l1, c0:c1]], compiled
        m = group_mask(lab, l0, l1, c0, c1, in_group)
        closed = _close(m, gap)
        merged = bool(np.any(_merged_runs(m, closed, 1)) or np.any(_merged_runs(m, closed, 0)))
        if merged:
            parts = _split(m, gap, min_area_px)
            if parts:
                out.extend(_RawRegion(l0 + q.line_start, c0 + q.col_start, q.mask, True) for q in parts)
                continue
            merged = parts is None  # [] : one ball, its inner gap reaching its outline
        out.append(_RawRegion(l0, c0, m, merged))
    return out


def _mid_line(raw: _RawRegion) -> float:
    """The middle line of a region (~ t_c): a mask's box is its pixels' box, its first and last lines hold pixels."""
    return raw.line_start + 0.5 * (raw.mask.shape[0] - 1)


#: share of a region's pixels on the other side of the backdrop from its
#: median beyond which the region is a ball of both signs (a bright ball's
#: side in shadow darker than the backdrop): noise alone puts 0.2-0.3 % of
#: the pixels of a ball at the detection limit there
OTHER_SIGN_SHARE = 0.1


def _region_contrast(vals: np.ndarray) -> tuple[float, bool]:
    """A region's contrast (DN, signed), the median of its pixels' levels over the backdrop, and whether it is of both signs.

    Where more than :data:`OTHER_SIGN_SHARE` of them lie on the median's
    other side of the backdrop, the median of those on its side: the median
    of all would mix the two signs' levels towards 0, and the contrast is
    the unit of every normalised profile of the ball.
    """
    if vals.size == 0:
        return 0.0, False
    contrast = float(median(vals))
    other = vals < 0.0 if contrast >= 0 else vals > 0.0
    if np.count_nonzero(other) > OTHER_SIGN_SHARE * vals.size:
        return float(median(vals[~other])), True
    return contrast, False


def _ball_region(index: int, raw: _RawRegion, x64: np.ndarray, bg: _Background, sat: float) -> BallRegion:
    """The region of a raw mask: its holes filled, its contrast, polarity and flags."""
    n, w = x64.shape
    l0, c0 = raw.line_start, raw.col_start
    # compiled (_detection_kernels.fill_lines_and_cols, _detection_kernels.region_values)
    filled = fill_lines_and_cols(as_arg(raw.mask, np.bool_))
    h, wd = filled.shape
    vals, saturated = region_values(x64, bg.line_gain, bg.background_dn, bg.line_offset_dn, l0, c0, filled, sat)
    contrast, both_signs = _region_contrast(vals)
    flags = []
    if l0 == 0:
        flags.append("cut_first_line")
    if l0 + h >= n:
        flags.append("cut_last_line")
    if c0 == 0 or c0 + wd >= w:
        flags.append("cut_sensor_end")
    if raw.merged:
        flags.append("overlap")
    if saturated:
        flags.append("saturated")
    filled.setflags(write=False)
    return BallRegion(
        index=index,
        line_start=int(l0),
        line_stop=int(l0 + h),
        col_start=int(c0),
        col_stop=int(c0 + wd),
        mask=filled,
        polarity=1 if contrast >= 0 else -1,
        contrast_dn=contrast,
        flags=tuple(flags),
        n_pixels=int(raw.mask.sum()),
        both_signs=both_signs,
    )


def _unclip_backdrop(x32: np.ndarray, bg: _Background, sat: float, k_sigma: float) -> np.ndarray:
    """``x32`` with its pixels at the saturation level (within ``k_sigma`` noise) where the backdrop itself reaches it set to the background.

    A bright backdrop under a flickering lamp clips on its brightest lines:
    there it reads the saturation level, less than the model's ``gain *
    level``, and would pass for a dark ball across the whole line.
    """
    # a level beyond the pixels' float range is never reached (and would overflow the cast)
    if not np.isfinite(sat) or sat > float(np.finfo(x32.dtype).max) or not np.any(x32 >= sat):
        return x32
    pred = bg.line_gain[:, None] * bg.background_dn[None, :] + bg.line_offset_dn[:, None]
    near = sat - k_sigma * bg.noise_dn[None, :]
    # the clipped backdrop's values lie within the noise below the level
    clip = (x32 >= near) & (pred >= near)
    return np.where(clip, pred, x32).astype(np.float32) if np.any(clip) else x32


def detect(
    image: LineImage,
    *,
    k_sigma: float = 4.0,
    min_area_px: int = 12,
    merge_gap_px: int = 6,
    noise_floor_dn: float = 0.5,
    columns: ColumnModel | None = None,
) -> Detection:
    """Find the balls in a line-scan image.

    Parameters
    ----------
    image : LineImage
        The image (rows = scan lines).
    k_sigma : float, optional
        Threshold on ``|X - background|`` in units of the column's noise sigma.
    min_area_px : int, optional
        Smallest region (pixels above threshold) kept as a ball; smaller blobs
        are noise, hot pixels or debris.
    merge_gap_px : int, optional
        Pieces closer than this (pixels) are one ball (seams or shaded limbs
        at background level cut a textured ball into pieces).
    noise_floor_dn : float, optional
        Smallest noise sigma (DN) used for thresholds: keeps a noise-free or
        flat image from dividing by zero.
    columns : ColumnModel, optional
        The columns' background level and noise when they are known (the
        stream engine's model of a crop's columns): used as they are (the
        noise floored as the detector's own), and only the per-line drift is
        estimated from the image.

    Returns
    -------
    Detection
        Background model and regions; no regions for an empty, flat or fully
        saturated image.

    Raises
    ------
    ValueError
        If a setting is out of its range (``k_sigma > 0``, ``min_area_px >=
        1``, ``merge_gap_px >= 0``, ``noise_floor_dn >= 0``; the message names
        it), the image has fewer than 2 lines or columns, or ``columns`` is
        a model of another width.
    """
    _check_detect_settings(k_sigma, min_area_px, merge_gap_px, noise_floor_dn)
    x = np.asarray(image.data, dtype=np.float64)
    if x.ndim != 2 or x.shape[0] < 2 or x.shape[1] < 2:
        raise ValueError(f"image must be 2-D with at least 2 lines and 2 columns, got shape {x.shape}")
    n, w = x.shape
    if columns is not None and np.shape(columns.background_dn) != (w,):
        raise ValueError(f"columns: a model of {np.shape(columns.background_dn)[0]} columns for an image of {w}")
    sat = float(image.saturation_dn)
    floor = max(float(noise_floor_dn), 1e-12)

    # float32 for the whole-image passes: exact for 16-bit integers, and the
    # statistics are accumulated in float64.
    x32 = x.astype(np.float32)
    bg = _background(x32, floor, first_pass_k=3.0, known=columns, saturation_dn=sat)
    x32 = _unclip_backdrop(x32, bg, sat, k_sigma)
    # The pixels with |x - background| > k_sigma noise (in float32), labelled
    # 8-connected, with their sizes and boxes (compiled).  The offset is 0
    # in the gain model: adding it there changes no residual.
    lab, sizes, boxes = label_hits(
        as_arg(x32, np.float32),
        bg.line_gain.astype(np.float32),
        bg.background_dn.astype(np.float32),
        bg.line_offset_dn.astype(np.float32),
        (k_sigma * bg.noise_dn).astype(np.float32),
    )
    raw = _raw_regions(lab, boxes, sizes, max(int(merge_gap_px), 0), min_area_px) if sizes.size else []
    raw.sort(key=lambda q: (q.line_start, _mid_line(q), q.col_start))
    x64 = as_arg(x)
    regions = tuple(_ball_region(i, q, x64, bg, sat) for i, q in enumerate(raw))
    for arr in (bg.background_dn, bg.noise_dn, bg.line_gain, bg.line_offset_dn):
        arr.setflags(write=False)
    return Detection(
        background_dn=bg.background_dn,
        noise_dn=bg.noise_dn,
        regions=regions,
        saturation_dn=sat,
        line_gain=bg.line_gain,
        line_offset_dn=bg.line_offset_dn,
        drift_model=bg.drift_model,
        threshold_sigma=float(k_sigma),
    )
