"""Loading the estimator's compiled kernels before its first ball.

Each kernel module loads (from numba's on-disk cache) or compiles its
kernels on tiny inputs in its own ``warm_up``; the first call in a process
otherwise carries it (about 0.2 s from the cache, seconds to compile).  A
stream calls :func:`warm_up` before its first ball so that the ball's
latency does not.
"""

from __future__ import annotations

from ..measure import _detection_kernels, _edge_kernels, _flatfield_kernels, _shading_kernels
from ..model import _forward_kernels
from ..solve import _fit_kernels


def warm_up() -> None:
    """Load (or compile) every kernel of the estimator now: the forward model's, the measurement's and the fit's."""
    for kernels in (_forward_kernels, _fit_kernels, _detection_kernels, _edge_kernels, _shading_kernels, _flatfield_kernels):
        kernels.warm_up()
