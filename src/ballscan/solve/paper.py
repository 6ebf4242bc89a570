"""The paper's model-based refinement (Sec. 2.C, second Eq. (7)-(10)).

The dynamic sphere model is rendered with the same camera and lines as the
real image, gradient images are taken along the sensor direction only,

    G(i, j) = |I(i, j+1) - I(i, j)|                 (second Eq. (7), (8))

and the energy

    eps = sum_ij [G'(i, j) - G(i, j)]^2             (Eq. (9))

is minimised over ``(t_c, y0, z0, V.x, V.y, V.z)`` with Powell's method
(Eq. (10)) from the key-point initial guess.

Normalisation: the real and simulated images differ in brightness, so the
real image is first mapped to ``(I - background) / contrast`` (background 0,
ball 1, using the detector's per-column background and the region's robust
ball/background contrast, sign included) and the model is rendered as pixel
coverage (background 0, ball 1).  The energy then compares the shapes of the
two contours, not their brightness.

Rendering the model: every candidate motion is rendered over the region
around the ball only, as the pixel coverage of the slab-and-exposure-averaged
analytic silhouette (:func:`ballscan.model.silhouette.silhouette`), i.e. a
noise-free, untextured, flat image of the sphere.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from ..model.silhouette import silhouette

__all__ = ["PaperResult", "render_coverage", "gradient_image", "refine_paper", "POWELL_OPTIONS"]

#: Powell's tolerances, on the scaled parameters (one unit = one line period
#: for t_c, one pixel footprint at the ball's depth for y0 and z0 (z0: ten),
#: 1 % of the initial speed for each velocity component) and on the energy.
POWELL_OPTIONS = {"xtol": 1e-3, "ftol": 1e-7, "maxfev": 4000}


@dataclass(frozen=True)
class PaperResult:
    """Outcome of the paper's refinement.

    Attributes
    ----------
    motion : BallMotion
        The refined motion.
    energy : float
        Final value of Eq. (9) (normalised units: contrast = 1).
    initial_energy : float
        Eq. (9) at the initial guess.
    n_evaluations : int
        Energy evaluations (each one renders the model).
    n_iterations : int
        Powell iterations.
    converged : bool
    message : str
    run_time_s : float
    """

    motion: BallMotion
    energy: float
    initial_energy: float
    n_evaluations: int
    n_iterations: int
    converged: bool
    message: str
    run_time_s: float


def render_coverage(
    camera: LineScanCamera, motion: BallMotion, t_lines_s: np.ndarray, cols: np.ndarray
) -> np.ndarray:
    """Noise-free image of the dynamic sphere model (Sec. 2.C.b): pixel coverage in [0, 1].

    Parameters
    ----------
    camera : LineScanCamera
    motion : BallMotion
    t_lines_s : ndarray, shape (n_lines,)
        Times of the lines to render, seconds.
    cols : ndarray, shape (n_cols,)
        Pixel indices to render.

    Returns
    -------
    ndarray, shape (n_lines, n_cols)
        Fraction of each pixel covered by the ball (presence-weighted overlap
        of the pixel ``[j - 1/2, j + 1/2]`` with the mean edges of the line).
    """
    sil = silhouette(camera, motion, t_lines_s, model="averaged")
    ok = sil.present
    left = np.where(ok, sil.left_px, 0.0)[:, None]
    right = np.where(ok, sil.right_px, 0.0)[:, None]
    j = np.asarray(cols, dtype=float)[None, :]
    overlap = np.clip(np.minimum(right, j + 0.5) - np.maximum(left, j - 0.5), 0.0, 1.0)
    return np.where(ok[:, None], overlap * sil.presence[:, None], 0.0)


def gradient_image(image: np.ndarray) -> np.ndarray:
    """Absolute difference along the sensor, second Eq. (7)/(8): ``|I(i, j+1) - I(i, j)|``."""
    return np.abs(np.diff(image, axis=1))


def refine_paper(
    camera: LineScanCamera,
    initial: BallMotion,
    box: np.ndarray,
    line_offset: int,
    col_offset: int,
    t_lines_s: np.ndarray,
    options: dict | None = None,
) -> PaperResult:
    """Minimise the gradient-image energy of Eq. (9)-(10) with Powell's method.

    Parameters
    ----------
    camera : LineScanCamera
    initial : BallMotion
        The key-point initial guess (Eq. (3)-(7)).
    box : ndarray, shape (n_lines, n_cols)
        The region around the ball, normalised to background 0, ball 1.
    line_offset, col_offset : int
        Image line and pixel of ``box[0, 0]``.
    t_lines_s : ndarray
        Times of all lines of the image, seconds.
    options : dict, optional
        Overrides of :data:`POWELL_OPTIONS`.
    """
    start = time.perf_counter()
    n_lines, n_cols = box.shape
    t_box = np.asarray(t_lines_s, dtype=float)[line_offset : line_offset + n_lines]
    cols = np.arange(col_offset, col_offset + n_cols)
    g_real = gradient_image(box)
    theta0 = initial.to_params()
    z0 = max(initial.position_m[2], 1e-6)
    period = float(np.median(np.diff(t_box))) if t_box.size > 1 else 1.0 / camera.line_rate_hz
    speed = max(initial.speed_mps, 1e-9)
    scale = np.array([period, z0 / camera.focal_px, 10 * z0 / camera.focal_px, 0.01 * speed, 0.01 * speed, 0.01 * speed])
    accel = initial.acceleration_mps2
    R = initial.radius_m
    n_eval = 0

    def energy(xs: np.ndarray) -> float:
        nonlocal n_eval
        n_eval += 1
        theta = theta0 + xs * scale
        if not (theta[2] > R and theta[3] != 0.0):
            return math.inf
        try:
            m = BallMotion.from_params(theta, R, accel)
        except ValueError:
            return math.inf
        model = render_coverage(camera, m, t_box, cols)
        return float(np.sum((gradient_image(model) - g_real) ** 2))  # Eq. (9)

    e0 = energy(np.zeros(6))
    opts = dict(POWELL_OPTIONS)
    if options:
        opts.update(options)
    from scipy.optimize import minimize  # the paper method only: scipy.optimize loads then

    res = minimize(energy, np.zeros(6), method="Powell", options=opts)
    theta = theta0 + res.x * scale
    motion = BallMotion.from_params(theta, R, accel)
    return PaperResult(
        motion=motion,
        energy=float(res.fun),
        initial_energy=e0,
        n_evaluations=n_eval,
        n_iterations=int(res.nit),
        converged=bool(res.success),
        message=str(res.message),
        run_time_s=time.perf_counter() - start,
    )
