"""Forward models of the ball's image: the analytic silhouette per line and the independent supersampled renderer."""


def warm_up() -> None:
    """Load (or compile) this stage's compiled kernels now (the averaged silhouette's; see :func:`ballscan.pipeline.warmup.warm_up`)."""
    from . import _forward_kernels

    for kernels in (_forward_kernels,):
        kernels.warm_up()
