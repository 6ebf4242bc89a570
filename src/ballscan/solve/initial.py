"""Key points and the closed-form initial guess (paper Sec. 2.B, Eq. (3)-(7)).

Key points of one ball's image (paper Fig. 1(c)):

``a``, ``b``
    the first and last scanned lines and the ball's (sub-pixel) position
    along the sensor on them;
``o``
    the centre line, midway between ``a`` and ``b`` in time;
``c``, ``d``
    the two tips of the ball's segment on the centre line.

Sign convention
---------------
The paper writes ``y' = -f y / z`` (image plane ``z = -f``); geometry.md
writes ``u = c + f y / z``.  With ``n = y / z`` the undistorted normalised
coordinate of a pixel, ``y' = -f n``.  The paper's ``c`` is then the tip with
the *larger* ``u`` (smaller ``y'``), so that ``phi = arctan(y'_d / f) -
arctan(y'_c / f) > 0``; both ``y`` axes point the same way, so ``y0, z0`` of
Eq. (3)-(4) are directly in the camera frame of geometry.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion

__all__ = ["KeyPoints", "InitialGuess", "SilhouetteEllipse", "find_keypoints", "fit_silhouette_ellipse", "initial_guess", "half_contrast_edges"]

#: an edge within this many pixels of the sensor's first or last pixel centre is the cut, not the ball's limb
_SENSOR_END_PX = 1.5


@dataclass(frozen=True)
class KeyPoints:
    """The paper's key points of one ball (pixels along the sensor, image lines).

    Attributes
    ----------
    line_a, line_b : float
        First and last scanned line (the centre line ``o`` is their mean).
    u_a, u_b : float
        Positions of the ball on lines ``a`` and ``b`` along the sensor, pixels.
    u_a_sigma_px, u_b_sigma_px : float
        Their 1-sigma from the pixel noise (plus a 0.05 px floor).
    line_o : float
        Centre line (may be fractional).
    u_c, u_d : float
        Tips of the segment on the centre line: ``u_c > u_d`` (see the module's
        sign convention).
    t_a_s, t_b_s : float
        Times of lines ``a`` and ``b``.
    cut : str or None
        What cut the ball, where it is cut: ``"first"`` / ``"last"`` /
        ``"both"`` (the image's first / last line: line ``a`` / ``b`` is
        not seen) or
        ``"sensor"`` (an end of the sensor, pixel 0 or W-1, maybe an image
        end too: ``c`` or ``d`` is not seen).  Every key point is then the
        ellipse's fitted to the edges the ball shows
        (:func:`fit_silhouette_ellipse`, :func:`_ellipse_keypoints`).
    """

    line_a: float
    line_b: float
    u_a: float
    u_b: float
    u_a_sigma_px: float
    u_b_sigma_px: float
    line_o: float
    u_c: float
    u_d: float
    t_a_s: float
    t_b_s: float
    cut: str | None = None


@dataclass(frozen=True)
class InitialGuess:
    """The closed-form estimate of Eq. (3)-(7) and what it was built from."""

    motion: BallMotion
    keypoints: KeyPoints
    duration_s: float  #: T of Eq. (7)
    gamma_rad: float
    phi_rad: float
    degenerate: bool  #: Eq. (5)-(6) singular: u_a and u_b agree within their uncertainty
    depth_fallback: bool = False  #: Eq. (5)-(6) ill-conditioned for the depth motion: V.z held at 0
    depth_motion_sigma_m: float = math.nan  #: propagated 1-sigma of z2 - z1 from Eq. (5)-(6)


def _crossing(profile: np.ndarray, level: float, j: int, step: int) -> float:
    """Sub-pixel position where ``profile`` crosses ``level`` between ``j - step`` and ``j``."""
    k = j - step
    if k < 0 or k >= profile.size:
        return float(j)
    p0, p1 = profile[k], profile[j]
    if p1 == p0:
        return float(j)
    return float(k + step * (level - p0) / (p1 - p0))


def half_contrast_edges(profile: np.ndarray, level: float = 0.5, detect: float = 0.25, inner_px: int = 3) -> tuple[float, float]:
    """Outer edges of a ball's segment at half the *local* contrast.

    Each edge is the crossing of ``level`` times the ball's level just
    inside that edge (the largest of the ``inner_px`` pixels inside the
    outermost pixel above ``detect``), linearly interpolated.  The local
    level matters: a shaded limb can be at a third of the ball's contrast,
    and a crossing of half the global contrast then sits pixels inside the
    true edge.

    Parameters
    ----------
    profile : ndarray, shape (n,)
        Background 0, ball about 1 (pixels ``0 .. n-1``).
    level : float
        Fraction of the local ball level at which the edge is taken.
    detect : float
        Level that marks the outermost ball pixels.
    inner_px : int
        Pixels inside the outermost ball pixel used for the local level.

    Returns
    -------
    (left, right) : float
        Sub-pixel positions in the profile's pixel coordinates; NaN when no
        pixel reaches ``detect``.
    """
    above = np.flatnonzero(profile >= detect)
    if above.size == 0:
        return math.nan, math.nan
    j0, j1 = int(above[0]), int(above[-1])
    lvl_left = level * float(profile[j0 : min(j0 + inner_px, j1 + 1)].max())
    lvl_right = level * float(profile[max(j1 - inner_px + 1, j0) : j1 + 1].max())
    # walk inwards from the outermost detected pixel to the local half level
    jl = j0
    while jl < j1 and profile[jl] < lvl_left:
        jl += 1
    jr = j1
    while jr > j0 and profile[jr] < lvl_right:
        jr -= 1
    return _crossing(profile, lvl_left, jl, 1), _crossing(profile, lvl_right, jr, -1)


def _centroid(row: np.ndarray, sigma: np.ndarray) -> tuple[float, float]:
    """Centroid of a non-negative profile and its 1-sigma from per-pixel noise."""
    w = np.maximum(row, 0.0)  # np.clip's values (it calls np.maximum without an upper bound)
    s = w.sum()
    if s <= 0:
        return math.nan, math.inf
    j = np.arange(row.size, dtype=float)
    c = float((w * j).sum() / s)
    var = float(((j - c) ** 2 * sigma**2).sum() / s**2)
    return c, math.sqrt(var)


@dataclass(frozen=True)
class SilhouetteEllipse:
    """A ball's image in (line, pixel) as the sheared ellipse of its limb.

    The limb's pixel on line ``t`` is ``u = u0 + a (t - t0) +- r sqrt(1 -
    ((t - t0) / h)^2)`` (``+`` the larger-``u`` edge): a sphere crossing
    the viewing plane at ``t0`` with its centre's image moving by ``a``
    pixels per line and an image radius ``r`` that changes little while it
    crosses (``vz`` small against the depth) draws this ellipse.

    Attributes
    ----------
    line_o : float
        ``t0``, the centre line (image lines, may be fractional).
    half_lines : float
        ``h``, half the lines the ball spans.
    u_centre_px : float
        ``u0``, the centre's pixel on line ``t0``.
    slope_px_per_line : float
        ``a``.
    radius_px : float
        ``r``.
    rms_px : float
        RMS of the edges about the ellipse.
    n_points : int
        Edges fitted.
    """

    line_o: float
    half_lines: float
    u_centre_px: float
    slope_px_per_line: float
    radius_px: float
    rms_px: float
    n_points: int


def _ellipse_given(lines: np.ndarray, u_px: np.ndarray, side: np.ndarray, t0: float, h: float) -> tuple[np.ndarray, float]:
    """``(u0, a, r)`` by linear least squares at fixed ``t0, h``, and the sum of squared residuals."""
    tau = lines - t0
    q = np.sqrt(np.clip(1.0 - (tau / h) ** 2, 0.0, None))
    A = np.column_stack([np.ones_like(tau), tau, side * q])
    coef, *_ = np.linalg.lstsq(A, u_px, rcond=None)
    res = u_px - A @ coef
    return coef, float(res @ res)


def ellipse_starts(first_line: float, last_line: float, cut_first: bool = False, cut_last: bool = False) -> np.ndarray:
    """Candidate ``(t0, h)`` of :class:`SilhouetteEllipse` for a ball seen from ``first_line`` to ``last_line`` (image lines).

    Both ends seen: ``t0`` within 40 % of the half span of the middle, ``h``
    0.8-2 half spans (the ends may lie beyond the sensor).  One end cut by
    the image's first (last) line: the other end is seen, half a line past
    the last (before the first) line seen, and the ball may be up to five
    times longer than what the image shows of it.  Both ends cut: ``t0``
    anywhere on the lines seen, the ellipse reaching past both.
    """
    span = max(last_line - first_line, 1.0)
    if cut_first and cut_last:
        # both ends beyond the image: the limbs' curvature alone places them
        grid = [(t0, h) for t0 in np.linspace(first_line, last_line, 9) for h in np.linspace(0.5, 5.0, 19) * span]
        return np.array([(t0, h) for t0, h in grid if t0 - h <= first_line and t0 + h >= last_line])
    if cut_first or cut_last:
        h = np.linspace(0.5, 5.0, 46) * span
        t0 = last_line + 0.5 - h if cut_first else first_line - 0.5 + h
        return np.column_stack([t0, h])
    half = 0.5 * span + 0.5
    mid = 0.5 * (first_line + last_line)
    return np.array([(mid + dt * half, hh * half) for dt in np.linspace(-0.4, 0.4, 9) for hh in np.linspace(0.8, 2.0, 13)])


def fit_silhouette_ellipse(lines: np.ndarray, u_px: np.ndarray, side: np.ndarray, starts: np.ndarray) -> SilhouetteEllipse:
    """Fit :class:`SilhouetteEllipse` to limb points, e.g. the edges of a ball cut by the sensor's end or an image end.

    The ellipse is linear in ``u0, a, r`` at fixed ``t0, h``: those are
    solved by least squares inside a search over ``t0, h`` (the best of
    ``starts``, then Nelder-Mead), and the points beyond 4 robust sigmas
    dropped once (a seam or a neighbour's pixels).

    Parameters
    ----------
    lines : ndarray (n,)
        Image line of each point (may be fractional).
    u_px : ndarray (n,)
        Its pixel along the sensor.
    side : ndarray (n,)
        +1 for a larger-``u`` (right) edge, -1 for a left edge.
    starts : ndarray (k, 2)
        Candidate ``(t0, h)``, lines (:func:`ellipse_starts`).

    Raises
    ------
    ValueError
        Fewer than 6 points, no ellipse with a positive radius fits them, or
        the best one is more than twice as long as the longest of ``starts``.
    """
    from scipy.optimize import minimize  # scipy.optimize loads with the first cut ball

    t = np.asarray(lines, dtype=float)
    u = np.asarray(u_px, dtype=float)
    sd = np.asarray(side, dtype=float)
    if t.size < 6:
        raise ValueError(f"fit_silhouette_ellipse: {t.size} limb points, at least 6 needed")
    best = None
    for keep in range(2):
        costs = [_ellipse_given(t, u, sd, float(a), max(float(b), 0.5))[1] for a, b in starts]
        x0 = np.asarray(starts[int(np.argmin(costs))], dtype=float)

        def cost(x: np.ndarray) -> float:
            return _ellipse_given(t, u, sd, float(x[0]), max(float(x[1]), 0.5))[1]

        found = minimize(cost, x0, method="Nelder-Mead", options={"xatol": 1e-3, "fatol": 1e-9, "maxiter": 400})
        t0, h = float(found.x[0]), max(float(found.x[1]), 0.5)
        coef, _ = _ellipse_given(t, u, sd, t0, h)
        tau = t - t0
        res = u - (coef[0] + coef[1] * tau + sd * coef[2] * np.sqrt(np.clip(1.0 - (tau / h) ** 2, 0.0, None)))
        best = (t0, h, coef, res)
        mad = 1.4826 * float(np.median(np.abs(res - np.median(res))))
        ok = np.abs(res) <= 4.0 * max(mad, 0.05)
        if keep or ok.all() or ok.sum() < 6:
            break
        t, u, sd = t[ok], u[ok], sd[ok]
    t0, h, coef, res = best
    if not coef[2] > 0:
        raise ValueError("fit_silhouette_ellipse: the limb points fit no ellipse of positive radius")
    # the starts span every length the ball's lines allow (up to five times
    # the lines seen where an image end cuts it); an ellipse twice longer
    # than the longest is the straight edges of something that is not one
    # ball's limb (a band across the sensor), whose key points would lie
    # millions of lines away
    h_max = float(np.max(starts[:, 1]))
    if not h <= 2.0 * h_max:
        raise ValueError(
            f"fit_silhouette_ellipse: the limb points' ellipse spans {2 * h:.4g} lines, more than twice the {2 * h_max:.4g} "
            "the lines seen allow: they are not one ball's limb"
        )
    return SilhouetteEllipse(t0, h, float(coef[0]), float(coef[1]), float(coef[2]), float(np.sqrt(np.mean(res**2))), int(t.size))


def _line_time(t: np.ndarray, line: float) -> float:
    """Time of a (fractional) image line: per-line timestamps interpolated, or extrapolated with the mean line period."""
    if 0 <= line <= t.size - 1:
        return float(np.interp(line, np.arange(t.size), t))
    period = (t[-1] - t[0]) / max(t.size - 1, 1)
    return float(t[0] + line * period) if line < 0 else float(t[-1] + (line - t.size + 1) * period)


def _ellipse_keypoints(
    box: np.ndarray, rows: np.ndarray, line_offset: int, col_offset: int, t: np.ndarray, sensor_width_px: int | None,
    cut_first: bool, cut_last: bool,
) -> KeyPoints:
    """Key points of a cut ball, from the ellipse through the edges it shows.

    Each line's half-contrast edges (:func:`half_contrast_edges`), less
    those within ``_SENSOR_END_PX`` of the sensor's first or last pixel
    (given ``sensor_width_px``), are limb points;
    :func:`fit_silhouette_ellipse` draws the ball through them, and the key
    points are the ellipse's: ``a``, ``b`` its first and last lines (``t0
    -+ h``, one beyond the image where it is cut by an image end) at the
    centre's pixel there, ``o`` its centre line, ``c``, ``d`` its tips ``u0
    +- r`` (one beyond the sensor where it is cut by a sensor end).
    """
    pts_t, pts_u, pts_s = [], [], []
    lo, hi = (_SENSOR_END_PX, sensor_width_px - 1 - _SENSOR_END_PX) if sensor_width_px is not None else (-math.inf, math.inf)
    for r in range(int(rows[0]), int(rows[-1]) + 1):
        for u, side in zip(half_contrast_edges(box[r]), (-1.0, 1.0)):
            u_abs = u + col_offset
            if math.isfinite(u_abs) and lo < u_abs < hi:
                pts_t.append(r + line_offset)
                pts_u.append(u_abs)
                pts_s.append(side)
    starts = ellipse_starts(float(rows[0] + line_offset), float(rows[-1] + line_offset), cut_first, cut_last)
    e = fit_silhouette_ellipse(np.array(pts_t), np.array(pts_u), np.array(pts_s), starts)
    line_a, line_b = e.line_o - e.half_lines, e.line_o + e.half_lines
    sigma = math.hypot(e.rms_px, 0.05)
    cut = "sensor" if sensor_width_px is not None else ("both" if cut_first and cut_last else ("first" if cut_first else "last"))
    return KeyPoints(
        line_a=line_a,
        line_b=line_b,
        u_a=e.u_centre_px - e.slope_px_per_line * e.half_lines,
        u_b=e.u_centre_px + e.slope_px_per_line * e.half_lines,
        u_a_sigma_px=sigma,
        u_b_sigma_px=sigma,
        line_o=e.line_o,
        u_c=e.u_centre_px + e.radius_px,
        u_d=e.u_centre_px - e.radius_px,
        t_a_s=_line_time(t, line_a),
        t_b_s=_line_time(t, line_b),
        cut=cut,
    )


def find_keypoints(
    box: np.ndarray,
    box_sigma: np.ndarray,
    ball_mask: np.ndarray,
    line_offset: int,
    col_offset: int,
    t_lines_s: np.ndarray,
    cut_first: bool = False,
    cut_last: bool = False,
    sensor_width_px: int | None = None,
) -> KeyPoints:
    """Pick the paper's key points a, b, o, c, d from one ball's image.

    Parameters
    ----------
    box : ndarray, shape (n_lines, n_cols)
        The ball's bounding box normalised so that background is 0 and the
        ball 1 (contrast and polarity removed).
    box_sigma : ndarray, shape (n_cols,) or (n_lines, n_cols)
        Per-pixel noise of ``box`` (same normalisation).
    ball_mask : ndarray of bool, same shape as ``box``
        Pixels detected as ball.
    line_offset, col_offset : int
        Position of the box in the image (line and pixel of ``box[0, 0]``).
    t_lines_s : ndarray
        Time of every line of the whole image, seconds.
    cut_first, cut_last : bool
        The ball is already / still present at the image's first / last line.
    sensor_width_px : int, optional
        The sensor's width W, given when the ball touches its pixel 0 or
        W-1 (flag ``cut_sensor_end``): the key points are then those of the
        ellipse through the edges away from the sensor's ends
        (:func:`fit_silhouette_ellipse`), which also spans lines cut by the
        image's first or last line.
    """
    rows = np.flatnonzero(ball_mask.any(axis=1))
    if rows.size == 0:
        raise ValueError("find_keypoints: the mask holds no ball pixel")
    if cut_first or cut_last or sensor_width_px is not None:
        t = np.asarray(t_lines_s, dtype=float)
        return _ellipse_keypoints(box, rows, line_offset, col_offset, t, sensor_width_px, cut_first, cut_last)
    # one row of sigmas serves every line as it is (np.broadcast_to costs more than a line's centroid)
    box_sigma = np.asarray(box_sigma)
    sig = box_sigma if box_sigma.shape in (box.shape, box.shape[1:]) else np.broadcast_to(box_sigma, box.shape)
    r_a, r_b = int(rows[0]), int(rows[-1])

    def line_centroid(r: int) -> tuple[float, float]:
        cols = np.flatnonzero(ball_mask[r])
        lo, hi = max(cols[0] - 2, 0), min(cols[-1] + 3, box.shape[1])
        s_row = sig[r, lo:hi] if sig.ndim == 2 else sig[lo:hi]
        c, s = _centroid(box[r, lo:hi], s_row)
        if not math.isfinite(c):
            # the line shows the ball only on the background's other side (the
            # shaded or dark-textured end of a bright ball): its centroid is
            # that of the opposite deviation
            c, s = _centroid(-box[r, lo:hi], s_row)
        if not math.isfinite(c):
            # no deviation at all: the detected pixels' middle, to a uniform
            # spread over them
            c, s = 0.5 * (cols[0] + cols[-1]) - lo, (cols[-1] - cols[0] + 1) / math.sqrt(12.0)
        return c + lo, math.hypot(s, 0.05)

    def line_edges(r: int) -> tuple[float, float]:
        return half_contrast_edges(box[r])

    u_a, s_a = line_centroid(r_a)
    u_b, s_b = line_centroid(r_b)
    line_a, line_b = float(r_a), float(r_b)
    r_o = 0.5 * (r_a + r_b)

    # tips c, d on the centre line, interpolated between the neighbouring lines
    r0 = int(math.floor(r_o))
    r1 = min(r0 + 1, box.shape[0] - 1)
    w1 = r_o - r0
    e0 = line_edges(r0)
    e1 = line_edges(r1) if w1 > 0 else e0
    left, right = ((1 - w1) * a + w1 * b for a, b in zip(e0, e1))
    t = np.asarray(t_lines_s, dtype=float)

    def time_of(line: float) -> float:
        return _line_time(t, line + line_offset)

    return KeyPoints(
        line_a=line_a + line_offset,
        line_b=line_b + line_offset,
        u_a=u_a + col_offset,
        u_b=u_b + col_offset,
        u_a_sigma_px=s_a,
        u_b_sigma_px=s_b,
        line_o=r_o + line_offset,
        u_c=float(right) + col_offset,
        u_d=float(left) + col_offset,
        t_a_s=time_of(line_a),
        t_b_s=time_of(line_b),
    )


def _eq5_6(n_a: float, n_b: float, y0: float, z0: float) -> tuple[float, float, float, float]:
    """Solve Eq. (5)-(6) for (z1, y1, y2, z2)."""
    z1 = 2.0 * (y0 - n_b * z0) / (n_a - n_b)
    z2 = 2.0 * z0 - z1
    return z1, n_a * z1, n_b * z2, z2


def _y0_z0(n_c: float, n_d: float, f: float, R: float) -> tuple[float, float, float, float]:
    """Eq. (3)-(4) with the paper's y' = -f n: returns (y0, z0, gamma, phi)."""
    gamma = math.atan(-n_c)  # arctan(y'_c / f)
    phi = math.atan(-n_d) - gamma
    if not phi > 0:
        raise ValueError("initial_guess: the tips c and d do not span a positive angle")
    y0 = -R * math.sin(gamma + 0.5 * phi) / math.sin(0.5 * phi)  # Eq. (3)
    z0 = R * math.cos(gamma + 0.5 * phi) / math.sin(0.5 * phi)  # Eq. (4)
    return y0, z0, gamma, phi


def _depth_motion_sigma(kp: KeyPoints, camera: LineScanCamera, R: float, tip_sigma_px: float) -> float:
    """1-sigma of z2 - z1 from Eq. (3)-(6), propagated by central differences (metres)."""
    u = np.array([kp.u_a, kp.u_b, kp.u_c, kp.u_d], dtype=float)
    sig = np.array([math.hypot(kp.u_a_sigma_px, tip_sigma_px), math.hypot(kp.u_b_sigma_px, tip_sigma_px), tip_sigma_px, tip_sigma_px])

    def dz(uu: np.ndarray) -> float:
        n_a, n_b, n_c, n_d = camera.backproject(uu)
        y0, z0, _, _ = _y0_z0(n_c, n_d, camera.focal_px, R)
        if n_a == n_b:
            return math.inf
        z1, _, _, z2 = _eq5_6(n_a, n_b, y0, z0)
        return z2 - z1

    var = 0.0
    for k in range(4):
        h = np.zeros(4)
        h[k] = 0.01
        try:
            g = (dz(u + h) - dz(u - h)) / 0.02
        except ValueError:
            return math.inf
        var += (g * sig[k]) ** 2
    return math.sqrt(var) if math.isfinite(var) else math.inf


def initial_guess(
    kp: KeyPoints,
    camera: LineScanCamera,
    radius_m: float,
    n_sigma: float = 2.0,
    tip_sigma_px: float = 0.3,
    max_depth_ratio: float = 0.5,
) -> InitialGuess:
    """Position and velocity from the key points, Eq. (3)-(7).

    Parameters
    ----------
    kp : KeyPoints
    camera : LineScanCamera
    radius_m : float
        Known ball radius R, metres.
    n_sigma : float
        ``|u_a - u_b|`` below ``n_sigma`` times its 1-sigma is treated as
        zero (see below).

    Notes
    -----
    * Eq. (3)-(4): ``gamma = arctan(y'_c / f)``, ``phi = arctan(y'_d / f) -
      arctan(y'_c / f)``, ``y0 = -R sin(gamma + phi/2) / sin(phi/2)``,
      ``z0 = R cos(gamma + phi/2) / sin(phi/2)`` with ``y' = -f n``.
    * Eq. (5)-(6): ``y1 = n_a z1``, ``y2 = n_b z2``, ``y1 + y2 = 2 y0``,
      ``z1 + z2 = 2 z0`` give ``z1 = 2 (y0 - n_b z0) / (n_a - n_b)``.  They
      are singular when ``a`` and ``b`` fall at the same sensor position
      (a crossing straight across the line of sight, or along it); when
      ``|u_a - u_b|`` is within ``n_sigma`` of its uncertainty the motion
      along ``y`` and ``z`` is taken as zero and ``degenerate`` is set
      (flag ``initial_degenerate``) instead of dividing by noise.  They
      also amplify key-point errors into the depth motion by about
      ``z0 / |u_a - u_b|``: when the propagated 1-sigma of ``z2 - z1``
      (tips floored at ``tip_sigma_px``) exceeds ``max_depth_ratio`` times
      the ball's diameter (the x-travel over T), ``z`` is held at ``z0``
      (``V.z = 0``), ``V.y`` is taken from ``a`` and ``b`` at that depth,
      and ``depth_fallback`` is set (the guess is then not flagged: the
      depth motion of Eq. (5)-(6) is ill-conditioned for most real
      crossings, and the refinement, not the guess, measures it).
    * Eq. (7): ``T`` is counted as in the paper, from line ``a`` to line
      ``b``: ``T = t_b - t_a`` (``(i_b - i_a) / line_rate`` for uniform
      lines), and ``t_c = (t_a + t_b) / 2``.  A real pixel sees the ball
      over the chord time plus its footprint ``z0 / (f |V.x|)`` plus the
      exposure, less up to one line period lost at each end to line
      sampling, so ``T`` over-estimates ``2R / V.x`` by about
      ``z0 / (f |V.x|) + tau - 1/line_rate`` and ``V.x`` is biased low by
      that fraction of ``T`` (about 1.5 % for the tennis-serve preset).
      The refinement removes this bias.
    """
    n_a, n_b, n_c, n_d = camera.backproject(np.array([kp.u_a, kp.u_b, kp.u_c, kp.u_d]))
    y0, z0, gamma, phi = _y0_z0(n_c, n_d, camera.focal_px, radius_m)
    R = radius_m
    sigma_ab = math.hypot(kp.u_a_sigma_px, kp.u_b_sigma_px)
    # Eq. (5)-(6) divide by n_a - n_b: besides the case the paper's text
    # implies (u_a == u_b within noise), they amplify key-point errors into
    # the depth motion by z0 / |u_a - u_b| (pixels).  The propagated 1-sigma
    # of z2 - z1 is checked too, with the tip error floored at
    # ``tip_sigma_px`` (shaded limbs and seams bias half-contrast tips by
    # tenths of a pixel).
    # (a cut ball's a and b are its fitted ellipse's)
    degenerate = abs(kp.u_a - kp.u_b) <= n_sigma * sigma_ab
    dz_sigma = _depth_motion_sigma(kp, camera, radius_m, tip_sigma_px)
    depth_fallback = not degenerate and not dz_sigma < max_depth_ratio * 2.0 * radius_m
    if degenerate:
        y1 = y2 = y0
        z1 = z2 = z0
    elif depth_fallback:
        # the depth change is not determined: keep z constant (vz = 0) and
        # take the sensor-direction motion from a and b at that depth
        z1 = z2 = z0
        y1, y2 = n_a * z0, n_b * z0
    else:
        z1, y1, y2, z2 = _eq5_6(n_a, n_b, y0, z0)
    T = kp.t_b_s - kp.t_a_s
    if not T > 0:
        raise ValueError("initial_guess: the ball spans no time (first and last line coincide)")
    vx = 2.0 * R / T  # Eq. (7)
    vy = (y2 - y1) / T
    vz = (z2 - z1) / T
    t_c = 0.5 * (kp.t_a_s + kp.t_b_s)
    motion = BallMotion(R, t_c, (0.0, y0, z0), (camera.crossing_sign * vx, vy, vz))
    return InitialGuess(
        motion=motion,
        keypoints=kp,
        duration_s=T,
        gamma_rad=gamma,
        phi_rad=phi,
        degenerate=degenerate,
        depth_fallback=depth_fallback,
        depth_motion_sigma_m=dz_sigma,
    )
