"""Loading the estimator's compiled kernels before its first ball.

Each stage (its ``warm_up``) loads (from numba's on-disk cache) or compiles its
kernels on tiny inputs in its own ``warm_up``; the first call in a process
otherwise carries it (about 0.2 s from the cache, seconds to compile).  A
stream calls :func:`warm_up` before its first ball so that the ball's
latency does not.
"""

from __future__ import annotations

from .. import measure, model, solve


def warm_up() -> None:
    """Load (or compile) every kernel of the estimator now: the forward model's, the measurement's and the fit's."""
    for stage in (model, solve, measure):
        stage.warm_up()
