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

With the prior ``delta_j ~ N(0, sigma^2)`` (the column gains' scatter,
:attr:`ballscan.measure.flatfield.ColumnGains.prnu_sigma`) the gains are
eliminated at every point: ``delta = -(M^T M + I / sigma^2)^-1 M^T r``; the
pixel rows become ``r + M delta`` and each column gives one prior row
``delta_j / sigma``.  Their sum of squares is ``r^T (I + sigma^2 M
M^T)^-1 r``: the chi-square of the pixels under the covariance of white
noise plus the columns' unknown gains, the model of the pixels'
Cramér-Rao bound (:func:`ballscan.solve.precision.sensor_crlb`), so the
fit's covariance carries the gains' share.  The Jacobian rows are projected
the same way (``M`` held at the point).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..model.pixels import PixelWindows

__all__ = ["GainColumns", "GainElimination", "gain_columns"]


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
    sigma : float
        Prior 1-sigma of a column's relative gain.
    """

    column: np.ndarray
    group: np.ndarray
    weighted_values: np.ndarray
    n_columns: int
    n_groups: int
    sigma: float


def gain_columns(pix: PixelWindows, sigma: float) -> GainColumns:
    """The columns of the fitted pixels ``pix`` (pixel centres rounded to the sensor's columns) and the prior 1-sigma ``sigma`` (relative gain).

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
    return GainColumns(column.astype(np.int64), pix.group[pix.mask].astype(np.int64), wv, int(uniq.size), int(pix.n_groups), float(sigma))


class GainElimination:
    """The gains of :class:`GainColumns` eliminated at one point, whose raw pixel residuals are ``raw``.

    Attributes
    ----------
    raw : ndarray (n_pixels,)
        The pixel residuals without gains (whitened).
    delta : ndarray (n_columns,)
        The gains' estimate at the point, ``g_j - 1``.
    residuals : ndarray (n_pixels + n_columns,)
        The pixel rows ``raw + M delta``, then the prior rows ``delta / sigma``.
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
        K = np.diag(ee + 1.0 / gc.sigma**2) - self.S.T @ (self.inv[:, None] * self.S)
        # positive definite (a projection's Gram matrix plus the prior's); a few hundred columns at most
        self.K = K
        self.delta = -np.linalg.solve(K, self._mt(self.raw[:, None]))[:, 0]
        self.residuals = np.concatenate([self.raw + self._m(self.delta[:, None])[:, 0], self.delta / gc.sigma])

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
        return np.vstack([J + self._m(Z), Z / self.gc.sigma])
