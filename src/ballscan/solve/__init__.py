"""From measurements to a motion: the closed-form initial guess (Eq. (3)-(7)), the paper's refinement (Eq. (7)-(10)), the least-squares fit and the Cramér-Rao bounds."""


def warm_up() -> None:
    """Load (or compile) this stage's compiled kernels now (the fit's; see :func:`ballscan.pipeline.warmup.warm_up`)."""
    from . import _fit_kernels

    for kernels in (_fit_kernels,):
        kernels.warm_up()
