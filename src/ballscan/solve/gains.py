"""The sensor's column gains as nuisance parameters of the fitted pixels, with their prior, eliminated at every point.

A sensor that is not flat-fielded reads, in column ``j``, the ball's signal
above the column's background times its gain ``g_j = 1 + delta_j``
(photo-response non-uniformity, PRNU; the background, gain included, is
what the column reads without the ball).  The fitted pixels' whitened
residuals of :func:`ballscan.model.pixels.pixel_residuals`,
``r_p = w_p (B_g s_p cov_p - v_p)`` (the refinement's pixels, Zhao & Wen
Eq. (7)-(10)), become ``w_p (B_g (1 + delta_j(p)) s_p cov_p - v_p)``: to
first order ``r + M delta``, where column ``j`` of ``M`` is the whitened
ball signal ``m_p = w_p B_g s_p cov_p = r_p + w_p v_p`` of the pixels of
sensor column ``j``, less its projection on each brightness group's signal
(the group's brightness ``B_g`` is fitted again: variable projection, the
derivative of Kaufman's form).  The gains are alike on every line of a
column, so this error does not average out over the lines a slow edge
spends in one column.

Each gain's prior is the columns' scatter ``N(0, sigma^2)``
(:attr:`ballscan.measure.flatfield.ColumnGains.prnu_sigma`) combined with
what the ball's interior pixels of that column say
(:func:`interior_levels`: pixels the ball covers whole, beyond the fitted
windows, whose level is the column's gain times the ball's brightness):
``N(mu_j, sigma_j^2)``.  The gains are eliminated at every point:
``delta = (M^T M + S^-2)^-1 (S^-2 mu - M^T r)`` with ``S = diag(sigma_j)``;
the pixel rows become ``r + M delta`` and each column gives one prior row
``(delta_j - mu_j) / sigma_j``.  Their sum of squares is ``(r + M mu)^T (I
+ M S^2 M^T)^-1 (r + M mu)``: the chi-square of the pixels under the
covariance of white noise plus the columns' unknown gains, the model of the
pixels' Cramér-Rao bound (:func:`ballscan.solve.precision.sensor_crlb`,
which takes every pixel of the ball), so the fit's covariance carries the
gains' share.  The Jacobian rows are projected the same way (``M`` held at
the point).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..measure.edges import EdgeMeasurements
from ..model.pixels import PixelWindows

__all__ = ["GainColumns", "GainElimination", "InteriorLevels", "gain_columns", "interior_levels"]


@dataclass(frozen=True)
class GainColumns:
    """The fitted pixels' sensor columns and the prior of their gains.

    Attributes
    ----------
    column : ndarray of int64 (n_pixels,)
        Each fitted pixel's gain, ``0 .. n_columns - 1`` (the pixels in the
        row-major order of :attr:`PixelWindows.mask`, as the residuals).
    group : ndarray of int64 (n_pixels,)
        Each pixel's brightness group.
    weighted_values : ndarray (n_pixels,)
        ``w_p v_p``: a pixel's whitened value (its residual plus this is its
        whitened model).
    n_columns : int
        Distinct sensor columns (gains).
    n_groups : int
        Brightness groups.
    mean, sigma : ndarray (n_columns,)
        Prior mean and 1-sigma of each column's relative gain less 1.
    """

    column: np.ndarray
    group: np.ndarray
    weighted_values: np.ndarray
    n_columns: int
    n_groups: int
    mean: np.ndarray
    sigma: np.ndarray


def gain_columns(pix: PixelWindows, sigma: float, interior: InteriorLevels | None = None) -> GainColumns:
    """The columns of the fitted pixels ``pix`` (pixel centres rounded to the sensor's columns) and their gains' prior.

    Parameters
    ----------
    pix : PixelWindows
    sigma : float
        The columns' gain scatter (relative 1-sigma): every gain's prior.
    interior : InteriorLevels, optional
        The ball's interior levels by column (:func:`interior_levels`),
        relative to their weighted mean: each measured column's prior is
        combined with its level's (product of the two normal densities).

    Raises
    ------
    ValueError
        If ``sigma`` is not a positive finite number.
    """
    if not (np.isfinite(sigma) and sigma > 0):
        raise ValueError(f"gain_columns: sigma must be a positive relative gain, got {sigma!r}")
    cols = np.rint(pix.cols_px[pix.mask]).astype(np.int64)
    uniq, column = np.unique(cols, return_inverse=True)
    wv = (pix.weights * pix.values)[pix.mask]
    prec = np.full(uniq.size, 1.0 / sigma**2)
    num = np.zeros(uniq.size)
    if interior is not None and interior.columns.size:
        w = 1.0 / interior.sigma**2
        ref = float(np.sum(w * interior.level) / np.sum(w))
        k = np.searchsorted(interior.columns, uniq)
        k = np.clip(k, 0, interior.columns.size - 1)
        hit = interior.columns[k] == uniq
        # the level relative to the columns' mean: the gain less 1, with its sigma
        d, sd = interior.level[k] / ref - 1.0, interior.sigma[k] / ref
        prec = prec + np.where(hit, 1.0 / sd**2, 0.0)
        num = np.where(hit, d / sd**2, 0.0)
    return GainColumns(
        column.astype(np.int64), pix.group[pix.mask].astype(np.int64), wv, int(uniq.size), int(pix.n_groups), num / prec, 1.0 / np.sqrt(prec)
    )


@dataclass(frozen=True)
class InteriorLevels:
    """The ball's level in each sensor column, measured on the pixels it covers whole (:func:`interior_levels`).

    Attributes
    ----------
    columns : ndarray of int64 (n,)
        Sensor columns, ascending.
    level, sigma : ndarray (n,)
        Each column's mean of ``value / shade`` (normalised units) and its 1-sigma.
    """

    columns: np.ndarray
    level: np.ndarray
    sigma: np.ndarray


def interior_levels(edges: EdgeMeasurements, left_px, right_px, reach_px, lines: np.ndarray, floor: float) -> InteriorLevels:
    """Each column's level on the ball's interior: the pixels of ``lines`` whose whole width lies more than ``reach_px`` inside both edges.

    Those pixels are covered whole at any motion near the model's
    (``left_px``, ``right_px``: its edges on every line, pixels; ``reach_px``
    per line: half the edge spread and the fitted window beyond it), so
    their values are ``B g_j s_p`` plus noise: the column's gain times the
    ball's brightness ``B`` and relative surface brightness ``s_p``
    (``edges.profile_shade``).  Each column's weighted mean of ``v / s``
    (weights ``(s / sigma)^2``, ``sigma`` the pixel's noise and ``floor`` in
    quadrature) and its 1-sigma.  They are not among the fitted pixels
    (:func:`ballscan.solve.problem.pixel_windows` takes the windows within
    ``reach_px`` of an edge), so their evidence on the gains is their own.
    """
    idx = np.flatnonzero(lines)
    if edges.profile is None or idx.size == 0:
        return InteriorLevels(np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0))
    prof, psig = edges.profile[idx], edges.profile_sigma[idx]
    cols = edges.profile_col0 + np.arange(prof.shape[1], dtype=float)
    lo = (np.asarray(left_px)[idx] + np.asarray(reach_px)[idx])[:, None]
    hi = (np.asarray(right_px)[idx] - np.asarray(reach_px)[idx])[:, None]
    shade = np.ones(prof.shape) if edges.profile_shade is None else edges.profile_shade[idx]
    shade = np.where(np.isfinite(shade) & (shade > 0), shade, 1.0)
    use = (cols[None, :] - 0.5 >= lo) & (cols[None, :] + 0.5 <= hi) & np.isfinite(prof) & (psig > 0)
    if not use.any():
        return InteriorLevels(np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0))
    w = np.where(use, shade**2 / (np.where(psig > 0, psig, 1.0) ** 2 + floor**2), 0.0)
    y = np.where(use, prof / shade, 0.0)
    sw = w.sum(axis=0)
    have = sw > 0
    level = (w * y).sum(axis=0)[have] / sw[have]
    return InteriorLevels(cols[have].astype(np.int64), level, 1.0 / np.sqrt(sw[have]))


class GainElimination:
    """The gains of :class:`GainColumns` eliminated at one point, whose raw pixel residuals are ``raw``.

    Attributes
    ----------
    raw : ndarray (n_pixels,)
        The pixel residuals without gains (whitened).
    delta : ndarray (n_columns,)
        The gains' estimate at the point, ``g_j - 1``.
    residuals : ndarray (n_pixels + n_columns,)
        The pixel rows ``raw + M delta``, then the prior rows ``(delta - mean) / sigma``.
    """

    def __init__(self, gc: GainColumns, raw: np.ndarray):
        self.gc = gc
        self.raw = np.asarray(raw, dtype=float)
        m = self.raw + gc.weighted_values
        self.m = np.where(np.isfinite(m), m, 0.0)
        nc, ng = gc.n_columns, gc.n_groups
        m2 = self.m * self.m
        mm = np.bincount(gc.group, m2, minlength=ng)
        self.inv = np.divide(1.0, mm, out=np.zeros(ng), where=mm > 0)
        # S = U^T E: the group's signal in each column (U: a group's signal, E: a column's)
        self.S = np.bincount(gc.group * nc + gc.column, m2, minlength=ng * nc).reshape(ng, nc)
        ee = np.bincount(gc.column, m2, minlength=nc)
        prec = 1.0 / gc.sigma**2
        K = np.diag(ee + prec) - self.S.T @ (self.inv[:, None] * self.S)
        # positive definite (a projection's Gram matrix plus the prior's); a few hundred columns at most
        self.K = K
        self.delta = np.linalg.solve(K, prec * gc.mean - self._mt(self.raw[:, None])[:, 0])
        self.residuals = np.concatenate([self.raw + self._m(self.delta[:, None])[:, 0], (self.delta - gc.mean) / gc.sigma])

    def _mt(self, A: np.ndarray) -> np.ndarray:
        """``M^T A`` for ``A`` (n_pixels, k): ``E^T A - S^T diag(1/mm) U^T A``."""
        gc, k = self.gc, A.shape[1]
        mA = self.m[:, None] * A
        EtA = np.stack([np.bincount(gc.column, mA[:, i], minlength=gc.n_columns) for i in range(k)], axis=1)
        UtA = np.stack([np.bincount(gc.group, mA[:, i], minlength=gc.n_groups) for i in range(k)], axis=1)
        return EtA - self.S.T @ (self.inv[:, None] * UtA)

    def _m(self, Z: np.ndarray) -> np.ndarray:
        """``M Z`` for ``Z`` (n_columns, k): each pixel's signal times its column's ``Z`` less its group's projection."""
        gc = self.gc
        return self.m[:, None] * (Z[gc.column] - (self.inv[:, None] * (self.S @ Z))[gc.group])

    def jacobian(self, J: np.ndarray) -> np.ndarray:
        """The rows of :attr:`residuals` from the raw pixel residuals' Jacobian ``J`` (n_pixels, p): ``(n_pixels + n_columns, p)``.

        Each pixel's row scaled by its column's estimated gain (the model's
        signal is), then projected as the residuals (the gains' estimate
        held: variable projection).
        """
        # the pixels' model scaled by their columns' estimated gains moves with theta as much
        J = np.asarray(J, dtype=float) * (1.0 + self.delta[self.gc.column])[:, None]
        Z = -np.linalg.solve(self.K, self._mt(J))
        return np.vstack([J + self._m(Z), Z / self.gc.sigma[:, None]])
