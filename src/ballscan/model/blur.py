"""The lens's blur circle as quadrature nodes: the marginal of a uniform disc along either axis of the sensor.

A lens focused at another distance than the ball's images each point as a
uniform disc (the blur circle) of diameter ``b`` pixels
(:attr:`ballscan.geometry.camera.LineScanCamera.defocus_px`).  Along either
axis of the image its marginal is the semicircle density of radius
``b / 2`` (variance ``b^2 / 16``).  The averaged silhouette integrates it
across the sensor (:mod:`ballscan.model.averaged`), the limb profile along
it (:class:`ballscan.measure.shading.LimbProfile`), each as a weighted sum
over these nodes.
"""

from __future__ import annotations

import numpy as np

from ..geometry.camera import LineScanCamera

__all__ = ["ACROSS_NODES", "ALONG_NODES", "MIN_BLUR_PX", "blur_diameter", "semicircle_nodes"]

#: Blur circles below this diameter (pixels) are taken as in focus: their
#: effect on an edge (``b^2 / 16`` of variance beside the pixel's ``1 / 12``)
#: is below a thousandth of a pixel.
MIN_BLUR_PX = 0.05
#: Nodes of the marginal across the sensor, where the averaged silhouette integrates each
#: offset's pixel height in closed form (:func:`ballscan.model.averaged.blur_offsets`).
ACROSS_NODES = 8
#: Nodes of the marginal along the sensor, where the coverage of a pixel by a shifted chord is
#: piecewise linear in the shift: 12 hold a blurred edge's pixel coverage within 2e-3 of its
#: exact convolution (tests/test_defocus.py).
ALONG_NODES = 12


def blur_diameter(camera: LineScanCamera) -> float:
    """The camera's blur-circle diameter that the model carries, pixels: ``defocus_px``, 0 where not set or below :data:`MIN_BLUR_PX`."""
    d = camera.defocus_px
    return float(d) if d is not None and d >= MIN_BLUR_PX else 0.0


def semicircle_nodes(diameter_px: float, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Offsets (pixels) and weights of the blur circle's marginal: Gauss-Chebyshev nodes of the second kind.

    ``sum w_j f(s_j)`` integrates ``f`` against the semicircle density of
    radius ``diameter_px / 2`` exactly for polynomials of degree below
    ``2 n`` (tests/test_defocus.py).  In focus (a diameter of 0) one offset
    0 of weight 1.
    """
    if not diameter_px > 0:
        return np.zeros(1), np.ones(1)
    j = np.arange(1, n + 1)
    s = np.cos(j * np.pi / (n + 1))
    w = np.sin(j * np.pi / (n + 1)) ** 2
    return 0.5 * float(diameter_px) * s, w / w.sum()
