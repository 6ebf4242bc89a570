"""Overlay plots like the paper's Fig. 4 and Fig. 7.

The image is shown with time (scan lines) downwards and the sensor across;
each ball gets the contour of its initial guess in red and of its refined
estimate in green (the silhouette of the model at those motions).
"""

from __future__ import annotations

import numpy as np

from ..geometry.camera import LineScanCamera
from .results import EstimateReport
from ..model.silhouette import silhouette

__all__ = ["plot_estimates", "save_overlay"]


def _contour(ax, camera: LineScanCamera, motion, t: np.ndarray, colour: str, label: str | None) -> tuple[float, float] | None:
    """Draw the model's outline; return its extent along the sensor (pixels)."""
    sil = silhouette(camera, motion, t, model="averaged")
    lines = np.flatnonzero(sil.present)
    if lines.size == 0:
        return None
    # one closed outline: down the left edge, up the right edge
    xs = np.concatenate([sil.left_px[lines], sil.right_px[lines][::-1], sil.left_px[lines[:1]]])
    ys = np.concatenate([lines, lines[::-1], lines[:1]]).astype(float)
    ax.plot(xs, ys, color=colour, lw=1.0, label=label)
    return float(np.min(xs)), float(np.max(xs))


def plot_estimates(image: np.ndarray, camera: LineScanCamera, report: EstimateReport, t_lines_s: np.ndarray, ax=None, margin_px: int = 40):
    """Draw the image and each ball's initial (red) and refined (green) contour.

    Parameters
    ----------
    image : ndarray (n_lines, W)
    camera : LineScanCamera
    report : EstimateReport
    t_lines_s : ndarray
        Line times, seconds.
    ax : matplotlib Axes, optional
    margin_px : int
        Pixels shown around the balls along the sensor (the whole sensor is
        usually too wide to see a ball).

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=(6, 6), dpi=120)
    else:
        fig = ax.figure
    ax.imshow(image, cmap="gray", aspect="auto", interpolation="nearest")
    extents = []
    for k, ball in enumerate(report.balls):
        if ball.initial is not None and ball.initial.motion() is not None:
            _contour(ax, camera, ball.initial.motion(), t_lines_s, "red", "initial guess" if k == 0 else None)
        m = ball.motion()
        if m is not None:
            extents.append(_contour(ax, camera, m, t_lines_s, "lime", f"refined ({ball.method})" if k == 0 else None))
    extents = [e for e in extents if e is not None]
    if extents:
        lo = min(e[0] for e in extents) - margin_px
        hi = max(e[1] for e in extents) + margin_px
        ax.set_xlim(max(lo, -0.5), min(hi, image.shape[1] - 0.5))
    ax.set_ylim(image.shape[0] - 0.5, -0.5)
    ax.set_xlabel("sensor pixel u")
    ax.set_ylabel("scan line")
    if report.balls:
        ax.legend(loc="lower right", fontsize=7)
    return fig


def save_overlay(path, image: np.ndarray, camera: LineScanCamera, report: EstimateReport, t_lines_s: np.ndarray) -> None:
    """Write :func:`plot_estimates` to a PNG file."""
    import matplotlib.pyplot as plt

    fig = plot_estimates(image, camera, report, t_lines_s)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
