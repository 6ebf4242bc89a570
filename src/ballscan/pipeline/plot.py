"""Overlay plots like the paper's Fig. 4 and Fig. 7.

The image is shown with time (scan lines) downwards and the sensor across,
in the sensor's and the stream's own coordinates (a crop is placed by its
offsets); each ball gets the contour of its initial guess (dashed orange)
and of its estimate (solid blue: a pair told apart with any colour vision,
on a grey image), the silhouette of the model at those motions, and the
title says each ball's speed with its 1-sigma and its flags.

The functions draw on a given matplotlib ``Axes`` or make a ``Figure`` of
their own without pyplot: neither changes the backend of a notebook or an
application.
"""

from __future__ import annotations

import numpy as np

from ..outputs import atomic_write_bytes
from ..geometry.camera import LineScanCamera
from ..model.silhouette import silhouette
from .report import UNITS
from .results import EstimateReport

__all__ = ["INITIAL_STYLE", "ESTIMATE_STYLE", "plot_estimates", "save_overlay"]

#: The initial guess's and the estimate's line styles (Okabe-Ito orange and sky blue).
INITIAL_STYLE = {"color": "#E69F00", "linestyle": "--", "linewidth": 1.0}
ESTIMATE_STYLE = {"color": "#56B4E9", "linestyle": "-", "linewidth": 1.2}


def _contour(ax, camera: LineScanCamera, motion, t: np.ndarray, style: dict, label: str | None, offsets: tuple[int, int]) -> tuple[float, float] | None:
    """Draw the model's outline, shifted by ``offsets`` (columns, lines); return its extent along the sensor (pixels)."""
    sil = silhouette(camera, motion, t, model="averaged")
    lines = np.flatnonzero(sil.present)
    if lines.size == 0:
        return None
    # one closed outline: down the left edge, up the right edge
    xs = np.concatenate([sil.left_px[lines], sil.right_px[lines][::-1], sil.left_px[lines[:1]]]) + offsets[0]
    ys = np.concatenate([lines, lines[::-1], lines[:1]]).astype(float) + offsets[1]
    ax.plot(xs, ys, label=label, **style)
    return float(np.min(xs)), float(np.max(xs))


def _title(report: EstimateReport, units: str) -> str:
    """Each ball's speed with its 1-sigma and its flags (the first three balls)."""
    parts = []
    u = UNITS[units]
    for k, b in enumerate(report.balls[:3]):
        if b.speed_mps is None:
            text = f"ball {k}: speed undetermined"
        else:
            sigma = f" ± {b.speed_sigma_mps * u:.2f}" if b.speed_sigma_mps is not None else ""
            text = f"ball {k}: {b.speed_mps * u:.2f}{sigma} {units}"
        if b.flags:
            text += f" [{', '.join(b.flags)}]"
        parts.append(text)
    if len(report.balls) > 3:
        parts.append(f"... {len(report.balls) - 3} more")
    return "\n".join(parts) if parts else "no ball found"


def plot_estimates(
    image: np.ndarray,
    camera: LineScanCamera,
    report: EstimateReport,
    t_lines_s: np.ndarray,
    ax=None,
    margin_px: int = 40,
    *,
    first_column: int = 0,
    first_line: int = 0,
    units: str = "m/s",
    title: bool = True,
):
    """Draw the image and each ball's initial (dashed orange) and estimated (blue) contour.

    Parameters
    ----------
    image : ndarray (n_lines, W)
    camera : LineScanCamera
        The camera of ``image`` (for a crop, the crop's camera).
    report : EstimateReport
    t_lines_s : ndarray
        Line times, seconds.
    ax : matplotlib Axes, optional
        Draw here; otherwise on a new ``matplotlib.figure.Figure``.
    margin_px : int
        Pixels shown around the balls along the sensor (the whole sensor is
        usually too wide to see a ball).
    first_column, first_line : int
        The sensor column and the stream line of ``image[0, 0]`` (a crop's
        offsets), so that the axes read in sensor and stream coordinates.
    units : {"m/s", "km/h", "mph"}
        Of the speeds in the title.
    title : bool
        Title the axes with each ball's speed, 1-sigma and flags.

    Returns
    -------
    matplotlib.figure.Figure
    """
    if ax is None:
        from matplotlib.figure import Figure

        fig = Figure(figsize=(6, 6), dpi=120)
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    n, w = image.shape
    offsets = (int(first_column), int(first_line))
    extent = (offsets[0] - 0.5, offsets[0] + w - 0.5, offsets[1] + n - 0.5, offsets[1] - 0.5)
    ax.imshow(image, cmap="gray", aspect="auto", interpolation="nearest", extent=extent)
    extents = []
    for k, ball in enumerate(report.balls):
        if ball.initial is not None and ball.initial.motion() is not None:
            _contour(ax, camera, ball.initial.motion(), t_lines_s, INITIAL_STYLE, "initial guess" if k == 0 else None, offsets)
        m = ball.motion()
        if m is not None:
            extents.append(_contour(ax, camera, m, t_lines_s, ESTIMATE_STYLE, f"estimate ({ball.method})" if k == 0 else None, offsets))
    extents = [e for e in extents if e is not None]
    if extents:
        lo = min(e[0] for e in extents) - margin_px
        hi = max(e[1] for e in extents) + margin_px
        ax.set_xlim(max(lo, extent[0]), min(hi, extent[1]))
    ax.set_ylim(extent[2], extent[3])
    ax.set_xlabel("sensor pixel")
    ax.set_ylabel("line")
    if title:
        ax.set_title(_title(report, units), fontsize=8)
    if report.balls:
        ax.legend(loc="lower right", fontsize=7)
    return fig


def save_overlay(path, image: np.ndarray, camera: LineScanCamera, report: EstimateReport, t_lines_s: np.ndarray, *, force: bool = False, **options) -> None:
    """Write :func:`plot_estimates` (``options`` are its keywords) to an image file (its format by its suffix, PNG without one).

    The file is written whole or not at all, not through a symbolic link
    unless ``force`` (:func:`ballscan.outputs.atomic_write_bytes`).
    """
    import io
    from pathlib import Path

    fig = plot_estimates(image, camera, report, t_lines_s, **options)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format=Path(path).suffix.lstrip(".").lower() or "png")
    atomic_write_bytes(path, buf.getvalue(), force=force)
