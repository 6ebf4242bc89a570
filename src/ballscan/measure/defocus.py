"""Defocus: the blur circle of a lens focused at another distance than the ball's, measured on the ball's edges.

A real aperture images each point of a ball it is not focused on as a
uniform disc, the blur circle, of diameter ``b`` pixels.  Along the sensor
its marginal is the semicircle density of radius ``b / 2`` (variance
``b^2 / 16``): a sharp limb becomes a ramp some ``b`` pixels wide.  The
edges' windows and level runs (:mod:`ballscan.measure.edges`) are a pixel
or two wide, so the blur moves their limb level and the edge outwards by
tenths of a pixel (half a pixel on a 26-pixel ball with a 3.8-pixel blur
circle), the more the smaller the ball: a pattern the depth velocity
absorbs.  :class:`ballscan.measure.shading.LimbProfile` carries the blur
into the edges' profile model once it is known (its camera's ``defocus_px``).

The camera file may give it (``defocus_px``, docs/geometry.md); otherwise
:func:`estimate_defocus` measures it on the ball's own edges: on the lines
where the exposure hardly spreads the edge, each edge's pixels are compared
with the brightness model's profile (the shading law, the pixel's width and
the exposure: :class:`ballscan.measure.shading.LimbProfile` without blur)
blurred by circles of a range of diameters, each edge with its own level
and position, and the diameter of least weighted squares over all of them
is taken.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

import numpy as np

from ..compiled import as_arg
from ._defocus_kernels import edge_squares
from .edges import EdgeMeasurements

if TYPE_CHECKING:  # the shading module imports this one's kernel
    from .shading import LimbProfile

__all__ = ["Defocus", "DefocusSettings", "MAX_LEAN", "SYSTEMATIC", "blur_kernel", "estimate_defocus"]

#: Relative 1-sigma of a measured blur circle beyond its noise: the lens's disc is not quite
#: uniform, nor the shading law exact at the limb (ballscan's renders of a uniform disc read
#: 1-6 % long, the POV-Ray set's focal blur 6-13 % short in median, docs/benchmarks.md).
SYSTEMATIC = 0.1

#: Steepest edge measured (its change along the sensor per pixel across it, :func:`_steep`): the
#: blur circle's width across it is then within 4 % of its marginal along the sensor.
MAX_LEAN = 0.3


@dataclass(frozen=True)
class DefocusSettings:
    """Tuning of :func:`estimate_defocus` (pixels).

    Attributes
    ----------
    max_spread_px : float
        Edges of the lines whose model edge spread over the exposure is below
        this: there the edge's width is the blur's and the pixel's.
    half_window_px : int
        Pixels compared on either side of each edge.
    max_edges : int
        Edges used at most (evenly spaced over the passage and both sides).
    min_edges : int
        Fewest edges for an estimate.
    max_diameter_px : float
        Largest blur circle tried.
    step_px : float
        Spacing of the diameters tried (refined between them by a parabola).
    samples_per_px : int
        Model samples per pixel (the blur's and the pixel's quadrature).
    max_shift_px : float
        Each edge's position may move this far from its measured value (the
        window edges of a blurred limb lie up to half a pixel out).
    """

    max_spread_px: float = 0.2
    half_window_px: int = 5
    max_edges: int = 48
    min_edges: int = 12
    max_diameter_px: float = 8.0
    step_px: float = 0.5
    samples_per_px: int = 10
    max_shift_px: float = 1.0

    def __post_init__(self) -> None:
        for name in ("max_spread_px", "max_diameter_px", "step_px", "max_shift_px"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v > 0):
                raise ValueError(f"DefocusSettings.{name}: expected a finite number > 0, got {v!r}")
        for name, low in (("half_window_px", 2), ("max_edges", 1), ("min_edges", 1), ("samples_per_px", 2)):
            v = getattr(self, name)
            if not (isinstance(v, int) and not isinstance(v, bool) and v >= low):
                raise ValueError(f"DefocusSettings.{name}: expected an integer >= {low}, got {v!r}")


@dataclass(frozen=True)
class Defocus:
    """The blur circle a ball's edges are measured with.

    Attributes
    ----------
    diameter_px : float
        Diameter of the blur circle on the sensor, pixels (0: in focus).
    sigma_px : float
        Its 1-sigma, pixels (0 where the camera file gives it).
    noise_px : float
        The part of ``sigma_px`` the edges' scatter shows (without the
        :data:`SYSTEMATIC` part), pixels.
    n_edges : int
        Edges it was measured on (0: from the camera file).
    source : {"camera", "image"}
    used : bool
        Whether the edges' model carries it: always from the camera file; a
        measured one where it stands out of its noise (see
        :func:`ballscan.pipeline.stages.ball_defocus`).
    """

    diameter_px: float
    sigma_px: float
    n_edges: int
    source: Literal["camera", "image"]
    used: bool = True
    noise_px: float = 0.0


def blur_kernel(diameter_px: float, step_px: float) -> np.ndarray:
    """The blur circle's marginal along the sensor on cells of ``step_px`` pixels centred on 0: each cell's exact share (sums to 1).

    The semicircle density ``2 sqrt(a^2 - x^2) / (pi a^2)``, ``a`` the
    radius, integrated over each cell; ``[1.0]`` for a blur below half a cell.
    """
    a = 0.5 * float(diameter_px)
    if a < 0.5 * step_px:
        return np.ones(1)
    n = int(math.ceil(a / step_px - 0.5))
    x = np.arange(-n, n + 1) * step_px

    def primitive(u: np.ndarray) -> np.ndarray:
        u = np.clip(u, -a, a)
        return u * np.sqrt(a * a - u * u) + a * a * np.arcsin(u / a)

    w = primitive(x + 0.5 * step_px) - primitive(x - 0.5 * step_px)
    return w / w.sum()


def _steep(limb: "LimbProfile", edge_px: np.ndarray) -> np.ndarray:
    """Whether each line's model edge leans, in the image, more than :data:`MAX_LEAN` from square to the sensor.

    The blur circle is round: across a leaning edge it is wider than its
    marginal along the sensor (by ``sqrt(1 + k^2)``, ``k`` the edge's
    change along the sensor per pixel of the image's other axis), which
    the estimate takes for the whole blur.  That axis advances by the
    ball's image speed, ``f |vx| / (z line_rate)`` pixels a line.  The
    edge's change per line holds the image's own motion along the sensor
    too, so an oblique ball's edges count as leaning and it gets no
    estimate: measured on the image's edge alone (that motion taken off),
    those balls got one, and their fits came out worse on the POV-Ray set
    (docs/benchmarks.md, "POV-Ray set: defocus").
    """
    cam, m = limb.camera, limb.motion
    per_line = cam.focal_px * abs(m.velocity_mps[0]) / (max(m.position_m[2], 1e-9) * cam.line_rate_hz)
    with np.errstate(invalid="ignore"):
        lean = np.abs(np.gradient(edge_px)) / max(per_line, 1e-300) if edge_px.size > 1 else np.zeros(edge_px.size)
    return ~(lean <= MAX_LEAN)


def _selected_edges(edges: EdgeMeasurements, limb: "LimbProfile", s: DefocusSettings) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rows of ``edges`` (line index), sides (+1 left, -1 right) and measured edges (px) of the sharp lines' usable edges, at most ``s.max_edges``.

    Sharp: the exposure spreads the model's edge by less than
    ``s.max_spread_px`` and the edge does not lean (:func:`_steep`).
    """
    rows, sides, at = [], [], []
    sharp = limb.spread_px[edges.lines] < s.max_spread_px
    for sg, e, ok, model in ((1.0, edges.left_px, edges.left_ok, limb.left_px), (-1.0, edges.right_px, edges.right_ok, limb.right_px)):
        i = np.flatnonzero(ok & np.isfinite(e) & sharp & ~_steep(limb, model[edges.lines]))
        rows.append(i)
        sides.append(np.full(i.size, sg))
        at.append(e[i])
    r, sg, e = (np.concatenate(a) for a in (rows, sides, at))
    if r.size > s.max_edges:
        pick = np.linspace(0, r.size - 1, s.max_edges).astype(int)
        r, sg, e = r[pick], sg[pick], e[pick]
    return r, sg, e


def _edge_pixels(edges: EdgeMeasurements, rows: np.ndarray, sides: np.ndarray, at: np.ndarray, half: int) -> tuple[np.ndarray, ...]:
    """Each edge's pixels: offsets inwards from its measured edge (px), normalised values and their weights (0: unusable)."""
    k = np.arange(-half, half + 1)
    cols = np.rint(at)[:, None] + sides[:, None] * k[None, :]
    j = cols.astype(int) - int(edges.profile_col0)
    inside = (j >= 0) & (j < edges.profile.shape[1])
    jc = np.clip(j, 0, edges.profile.shape[1] - 1)
    y = edges.profile[rows[:, None], jc]
    sy = edges.profile_sigma[rows[:, None], jc] if edges.profile_sigma is not None else np.ones_like(y)
    w = np.where(inside & np.isfinite(y) & np.isfinite(sy) & (sy > 0), 1.0 / np.where(sy > 0, sy, 1.0) ** 2, 0.0)
    offsets = sides[:, None] * (cols - at[:, None])
    return offsets, np.where(w > 0, y, 0.0), w


@dataclass(frozen=True)
class _Lookup:
    """Where each edge's pixels fall on the model's fine grid at each shift: the sample below (its index in the edge's row) and the fraction towards the next (E, S, K)."""

    below: np.ndarray
    fraction: np.ndarray


def _lookup(n_grid: int, grid0: float, step: float, offsets: np.ndarray, shifts: np.ndarray) -> _Lookup:
    """The data's pixel at offset ``o`` (inwards from the measured edge) is compared with the model at ``o + shift`` (grid ``grid0 + step * f``)."""
    x = (offsets[:, None, :] + shifts[None, :, None] - grid0) / step
    i0 = np.clip(np.floor(x).astype(np.int64), 0, n_grid - 2)
    return _Lookup(i0, np.clip(x - i0, 0.0, 1.0))


def _parabola_min(d: np.ndarray, f: np.ndarray) -> float:
    """The diameter of least ``f`` over the grid ``d``, refined by the parabola in ``d^2`` through the least and its neighbours (kept within them).

    The squares depend on the blur through its variance (``d^2 / 16``):
    a parabola in ``d`` itself would pull a minimum between grid points
    towards the smaller one.
    """
    i = int(np.argmin(f))
    if i == 0 or i == d.size - 1:
        return float(d[i])
    (v0, v1, v2), (f0, f1, f2) = d[i - 1:i + 2] ** 2, f[i - 1:i + 2]
    # the parabola through the three points: its second and first divided differences
    s01, s12 = (f1 - f0) / (v1 - v0), (f2 - f1) / (v2 - v1)
    a = (s12 - s01) / (v2 - v0)
    if not a > 0:
        return float(d[i])
    vertex = 0.5 * (v0 + v1) - s01 / (2.0 * a)
    return float(math.sqrt(min(max(vertex, v0), v2)))


def estimate_defocus(limb: "LimbProfile", edges: EdgeMeasurements, settings: DefocusSettings = DefocusSettings()) -> Defocus | None:
    """The blur circle's diameter measured on the ball's sharp edges (see the module's notes).

    Parameters
    ----------
    limb : LimbProfile
        The ball's brightness model (its shading law, edge spread and mean
        edges at a rough motion), without a blur along the sensor (its
        camera's, if any, is left out of the profile).
    edges : EdgeMeasurements
        The ball's edges, with their normalised ``profile``.
    settings : DefocusSettings

    Returns
    -------
    Defocus or None
        ``source="image"``.  Its sigma is the spread of the estimates from
        the four quarters of the edges (each side, each half of the
        passage), which holds the texture's and the shading law's errors
        as well as the noise's, and at least the noise's alone (the
        curvature of the weighted squares), with :data:`SYSTEMATIC` of the
        diameter added.  None where fewer than
        ``settings.min_edges`` sharp edges, or no profile, are available,
        or where the best diameter lies at the end of the range tried.
    """
    s = settings
    if edges.profile is None:
        return None
    rows, sides, at = _selected_edges(edges, limb, s)
    if rows.size < s.min_edges:
        return None
    lines = edges.lines[rows]
    offsets, y, w = _edge_pixels(edges, rows, sides, at, s.half_window_px)
    # the model's point profile, inwards from its own mean edge, on a fine grid
    # wide enough for the pixels, their shifts and the largest blur
    step = 1.0 / s.samples_per_px
    reach = s.half_window_px + 1.0 + s.max_shift_px + 0.5 * s.max_diameter_px + 1.0
    grid = np.arange(-reach, reach + 0.5 * step, step)
    point, _ = limb.sharp()(lines, sides, np.broadcast_to(grid, (lines.size, grid.size)))
    point = np.nan_to_num(point)
    # the data's edge against the model's: the model is compared at the data's offsets moved by this
    model_edge = np.where(sides > 0, limb.left_px[lines], limb.right_px[lines])
    base = sides * (at - model_edge)
    ok = np.isfinite(base)
    if ok.sum() < s.min_edges:
        return None
    offsets, y, w, point, sides, lines, base = offsets[ok], y[ok], w[ok], point[ok], sides[ok], lines[ok], base[ok]
    offsets = offsets + base[:, None]
    at_grid = _lookup(grid.size, grid[0], step, offsets, np.arange(-s.max_shift_px, s.max_shift_px + 1e-9, 0.1))
    diameters = np.arange(0.0, s.max_diameter_px + 1e-9, s.step_px)
    pixel = np.ones(s.samples_per_px) / s.samples_per_px
    point, y, w = as_arg(point), as_arg(y), as_arg(w)
    per_edge, total = [], []
    for d in diameters:
        # the model blurred by the circle and averaged over the pixel's width
        per_edge.append(edge_squares(point, np.convolve(blur_kernel(d, step), pixel), at_grid.below, at_grid.fraction, y, w))
        total.append(per_edge[-1].sum())
        if len(total) >= 3 and total[-1] > total[-2] > min(total):
            # past the minimum (the squares rise on both of its sides): the larger blurs fit worse still
            break
    sse = np.array(per_edge)
    diameters = diameters[: sse.shape[0]]
    diameter = max(_parabola_min(diameters, sse.sum(axis=1)), 0.0)
    if diameter >= s.max_diameter_px - s.step_px:
        # at the end of the range tried: no blur circle describes these edges
        return None
    # the quarters: each side, each half of the passage
    early = lines < np.median(lines)
    quarters = [(sides == sg) & (early == e) for sg in (1.0, -1.0) for e in (True, False)]
    parts = [max(_parabola_min(diameters, sse[:, q].sum(axis=1)), 0.0) for q in quarters if q.sum() >= 2]
    spread = float(np.std(parts, ddof=1) / math.sqrt(len(parts))) if len(parts) >= 2 else math.nan
    # the residuals' degrees of freedom: a level and a shift per edge, one diameter
    noise = _noise_sigma(diameters, sse.sum(axis=1), int((w > 0).sum()) - 2 * lines.size - 1)
    scatter = float(np.fmax(spread, noise))
    return Defocus(
        diameter_px=float(diameter), sigma_px=math.hypot(scatter, SYSTEMATIC * diameter), n_edges=int(lines.size), source="image",
        noise_px=scatter,
    )


def _noise_sigma(x: np.ndarray, f: np.ndarray, dof: int) -> float:
    """The 1-sigma of the minimum of the weighted squares ``f`` over the grid ``x`` from their curvature there (the residuals' variance from ``dof``)."""
    i = min(max(int(np.argmin(f)), 1), x.size - 2)
    scale = f.min() / max(dof, 1)
    curvature = (f[i - 1] - 2.0 * f[i] + f[i + 1]) / (x[1] - x[0]) ** 2 / max(scale, 1e-300)
    return float(math.sqrt(2.0 / curvature)) if curvature > 0 else math.nan
