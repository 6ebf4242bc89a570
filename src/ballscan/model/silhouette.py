"""Analytic silhouette of a moving sphere on a line-scan image.

For every scan line the sphere's section by the viewing plane is a circle of
radius ``rho = sqrt(R^2 - x_c^2)`` around ``(y_c, z_c)``; its two tangent rays
from the projection centre give the ball's two edges on the sensor.  This is
the geometric content of the paper's dynamic sphere model (first Eq. (8))
seen through the projection of Eq. (2).

Two models are provided:

``"chord"``
    The zero-thickness viewing plane ``x = 0`` at the line's centre time
    ``t_i``.
``"averaged"``
    What a real pixel integrates: the slab ``|x| <= z / (2 f)`` of a pixel's
    height across the line and the exposure window
    ``[t_i - tau/2, t_i + tau/2]``.  The returned edges are the means of the
    instantaneous edges over the (slab x exposure) samples in which the ball
    is present, which is exactly what an area-based edge measurement (the sum
    of partial pixel coverage) recovers; ``presence`` is the fraction of
    samples in which some of the ball is seen and ``area_px`` the expected
    summed coverage of the line.

Both are exact up to the quadrature described in :func:`silhouette`; neither
renders pixels.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import IntEnum

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion

__all__ = ["LineStatus", "Silhouette", "silhouette", "tangent_normalised", "visible_line_count"]


class LineStatus(IntEnum):
    """Per-line status of the analytic silhouette."""

    OK = 0
    ABSENT = 1  #: the ball does not meet the viewing plane (or slab) on this line
    BEHIND = 2  #: the section reaches the plane z <= rho: an edge ray would point backwards
    INSIDE = 3  #: the projection centre is inside the ball


@dataclass(frozen=True)
class Silhouette:
    """Edges of a ball's image, one entry per scan line.

    Attributes
    ----------
    left_px, right_px : ndarray
        Edge positions along the sensor in pixels (``left < right``); NaN
        where the line's status is not OK.  They may lie outside
        ``[0, width-1]``: clipping to the sensor is the caller's business.
    presence : ndarray
        Fraction (0..1) of the line's slab-and-exposure samples in which the
        ball is seen; 0 or 1 for the chord model.
    area_px : ndarray
        Expected summed pixel coverage of the line, ``E[(right - left) * present]``.
    status : ndarray of LineStatus
    """

    left_px: np.ndarray
    right_px: np.ndarray
    presence: np.ndarray
    area_px: np.ndarray
    status: np.ndarray

    @property
    def present(self) -> np.ndarray:
        """Lines on which the ball is seen and measured."""
        return self.status == LineStatus.OK

    @property
    def degenerate(self) -> bool:
        """True when any line is BEHIND or INSIDE (the model cannot give numbers)."""
        return bool(np.any(self.status >= LineStatus.BEHIND))

    @property
    def first_line(self) -> int | None:
        idx = np.flatnonzero(self.present)
        return int(idx[0]) if idx.size else None

    @property
    def last_line(self) -> int | None:
        idx = np.flatnonzero(self.present)
        return int(idx[-1]) if idx.size else None


def tangent_normalised(y: np.ndarray, w: np.ndarray, rho: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Normalised coordinates ``n = y / z`` of the two tangents to a circle.

    The circle has centre ``(y, w)`` (along the sensor, along the optical
    axis) and radius ``rho``; tangents from the origin are the lines
    ``y = n z`` with

        n_pm = (y w +- rho sqrt(y^2 + w^2 - rho^2)) / (w^2 - rho^2).

    Returns ``(n_minus, n_plus, valid)``; ``valid`` is False where the circle
    reaches ``w <= rho`` (a tangent would point backwards or sideways) or
    contains the origin.
    """
    y = np.asarray(y, dtype=float)
    w = np.asarray(w, dtype=float)
    rho = np.asarray(rho, dtype=float)
    den = w * w - rho * rho
    disc = y * y + den
    valid = (w > rho) & (disc > 0)
    root = np.sqrt(np.where(valid, disc, 1.0))
    den_safe = np.where(valid, den, 1.0)
    n_minus = (y * w - rho * root) / den_safe
    n_plus = (y * w + rho * root) / den_safe
    return np.where(valid, n_minus, np.nan), np.where(valid, n_plus, np.nan), valid


_GAUSS_CACHE: dict[int, tuple[np.ndarray, np.ndarray]] = {}


def _gauss(n: int) -> tuple[np.ndarray, np.ndarray]:
    if n not in _GAUSS_CACHE:
        _GAUSS_CACHE[n] = np.polynomial.legendre.leggauss(n)
    return _GAUSS_CACHE[n]


def silhouette(
    camera: LineScanCamera,
    motion: BallMotion,
    t_lines_s: np.ndarray,
    model: str = "averaged",
    n_nodes: int = 8,
) -> Silhouette:
    """Edges of the ball's image on every scan line.

    Parameters
    ----------
    camera : LineScanCamera
        Intrinsics (focal length, principal point, distortion, exposure).
    motion : BallMotion
        The ball (camera frame).
    t_lines_s : array_like, shape (n_lines,)
        Centre time of each line, seconds (see :func:`ballscan.geometry.camera.line_times`).
    model : {"averaged", "chord"}
        See the module docstring.
    n_nodes : int
        Gauss-Legendre nodes per piece of the averaged model's quadrature.

    Notes
    -----
    The averaged model uses that a sample at time ``t`` in the exposure and
    at tilt ``s`` within the pixel's height (the plane ``x = s z``,
    ``|s| <= 1/(2f)``) cuts the sphere at signed distance
    ``d = x_c(t) - s z_c`` from its centre, where ``x_c(t)`` is linear over the
    exposure.  ``d`` is the sum of two independent uniform variables and has a
    trapezoidal density; the edge is a smooth function of ``d`` after the
    substitution ``d = R sin(theta)``, so it is integrated in ``theta`` with
    Gauss-Legendre on the (up to three) pieces between the trapezoid's kinks.
    Given ``d``, the centre's ``y, z`` are taken at the conditional mean time
    (they vary linearly over the exposure).  Terms of order ``s^2 ~ 1e-8``
    are dropped (below 1e-6 px).
    """
    t = np.asarray(t_lines_s, dtype=float).reshape(-1)
    R = motion.radius_m
    if model == "chord":
        return _chord(camera, motion, t)
    if model != "averaged":
        raise ValueError(f"model: expected 'averaged' or 'chord', got {model!r}")

    c0 = motion.centre(t)  # (N, 3) at line centre times
    v0 = motion.velocity_at(t)
    a1 = v0[:, 0]  # dx_c/dt over the exposure
    A = np.abs(a1) * camera.exposure / 2.0  # half-width of the exposure term
    B = c0[:, 2] / (2.0 * camera.focal_px)  # half-width of the slab term (z_c > 0 where it matters)
    B = np.where(c0[:, 2] > 0, B, 0.0)
    x0 = c0[:, 0]

    # Trapezoid support and kinks of the density of d, then clip to [-R, R].
    lo = x0 - A - B
    k1 = x0 - np.abs(A - B)
    k2 = x0 + np.abs(A - B)
    hi = x0 + A + B
    edges = np.stack([lo, k1, k2, hi], axis=1)  # (N, 4)
    edges_c = np.clip(edges, -R, R)
    theta_e = np.arcsin(edges_c / R)  # (N, 4)

    g, gw = _gauss(n_nodes)
    th_a = theta_e[:, :-1, None]
    th_b = theta_e[:, 1:, None]
    half = (th_b - th_a) / 2.0
    theta = th_a + half * (1.0 + g)  # (N, 3, n)
    d = R * np.sin(theta)
    jac = R * np.cos(theta) * half * gw  # dd = R cos(theta) dtheta, times the piece's weight

    # density of d: trapezoid with total mass 1
    x0b, Ab, Bb = x0[:, None, None], A[:, None, None], B[:, None, None]
    width_total = 2.0 * (Ab + Bb)
    plateau = 1.0 / np.maximum(2.0 * np.maximum(Ab, Bb), 1e-300)
    slope_zone = np.abs(d - x0b) > np.abs(Ab - Bb)
    ramp = np.maximum(width_total / 2.0 - np.abs(d - x0b), 0.0) / np.maximum(4.0 * Ab * Bb, 1e-300)
    dens = np.where(slope_zone, ramp, plateau)
    dens = np.where(width_total > 0, dens, 0.0)
    wgt = dens * jac  # (N, 3, n) weight of each sample in the line's mass

    # conditional mean of U1 = a1 (t - t_i) given d: U1 uniform on [-A, A] intersected
    # with [d - x0 - B, d - x0 + B]
    u_lo = np.maximum(-Ab, d - x0b - Bb)
    u_hi = np.minimum(Ab, d - x0b + Bb)
    u_mean = 0.5 * (u_lo + u_hi)
    a1b = a1[:, None, None]
    dt = np.where(np.abs(a1b) > 0, u_mean / np.where(a1b == 0, 1.0, a1b), 0.0)
    tt = t[:, None, None] + dt
    cc = motion.centre(tt)  # (N, 3, n, 3)
    yc, zc, xc = cc[..., 1], cc[..., 2], cc[..., 0]
    # plane x = s z through the sample: s = (x_c - d) / z_c, in-plane depth z_c + s x_c
    s = (xc - d) / np.where(zc > 0, zc, 1.0)
    w = zc + s * xc
    rho = R * np.cos(theta)
    n_lo, n_hi, ok = tangent_normalised(yc, w, rho)

    mass = wgt.sum(axis=(1, 2))
    has_mass = mass > 0
    inside = _camera_inside(motion, t, R, camera.exposure)
    bad_sample = (~ok) & (wgt > 0)
    behind = np.any(bad_sample, axis=(1, 2))

    u_lo = camera.project_normalised(np.where(ok, n_lo, 0.0))
    u_hi = camera.project_normalised(np.where(ok, n_hi, 0.0))
    m = np.where(has_mass, mass, 1.0)
    left = (wgt * u_lo).sum(axis=(1, 2)) / m
    right = (wgt * u_hi).sum(axis=(1, 2)) / m
    area = (wgt * (u_hi - u_lo)).sum(axis=(1, 2))

    status = np.full(t.shape, LineStatus.ABSENT, dtype=np.int8)
    status[has_mass] = LineStatus.OK
    status[has_mass & behind] = LineStatus.BEHIND
    status[inside] = LineStatus.INSIDE
    okline = status == LineStatus.OK
    return Silhouette(
        left_px=np.where(okline, left, np.nan),
        right_px=np.where(okline, right, np.nan),
        presence=np.where(status == LineStatus.ABSENT, 0.0, np.clip(mass, 0.0, 1.0)),
        area_px=np.where(okline, area, np.where(status == LineStatus.ABSENT, 0.0, np.nan)),
        status=status,
    )


def _camera_inside(motion: BallMotion, t: np.ndarray, R: float, exposure: float) -> np.ndarray:
    """Lines whose exposure window finds the projection centre inside the ball.

    The distance from the origin to the centre is convex in time for uniform
    motion, so checking the window's ends and middle misses only grazing
    contacts shorter than the window (where the centre passes within R of the
    origin between the samples); the window is sampled at 5 points.
    """
    offsets = np.linspace(-0.5, 0.5, 5) * exposure if exposure > 0 else np.zeros(1)
    c = motion.centre(t[:, None] + offsets[None, :])
    return np.any(np.linalg.norm(c, axis=-1) <= R, axis=1)


def _chord(camera: LineScanCamera, motion: BallMotion, t: np.ndarray) -> Silhouette:
    R = motion.radius_m
    c = motion.centre(t)
    xc, yc, zc = c[:, 0], c[:, 1], c[:, 2]
    present = np.abs(xc) < R
    rho = np.sqrt(np.where(present, R * R - xc * xc, 0.0))
    n_lo, n_hi, ok = tangent_normalised(yc, zc, rho)
    status = np.full(t.shape, LineStatus.ABSENT, dtype=np.int8)
    status[present & ok] = LineStatus.OK
    status[present & ~ok] = LineStatus.BEHIND
    status[_camera_inside(motion, t, R, 0.0)] = LineStatus.INSIDE
    okline = status == LineStatus.OK
    left = np.where(okline, camera.project_normalised(np.where(ok, n_lo, 0.0)), np.nan)
    right = np.where(okline, camera.project_normalised(np.where(ok, n_hi, 0.0)), np.nan)
    return Silhouette(
        left_px=left,
        right_px=right,
        presence=okline.astype(float),
        area_px=np.where(okline, right - left, 0.0),
        status=status,
    )


def visible_line_count(camera: LineScanCamera, motion: BallMotion) -> float:
    """geometry.md's estimate of the number of lines a ball appears in.

    ``line_rate * ((2R + z0/f) / |V.x| + tau)``: the chord time plus one
    pixel footprint and one exposure.
    """
    vx = abs(motion.velocity_mps[0])
    if vx == 0:
        return float("inf")
    z0 = motion.position_m[2]
    return camera.line_rate_hz * ((2 * motion.radius_m + z0 / camera.focal_px) / vx + camera.exposure)
