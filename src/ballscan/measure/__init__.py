"""What an image shows: loading, detection of balls against the background, sub-pixel edges (window and matched), the columns' gains, the ball's shading, the lens's blur circle, and the robust statistics they share."""


def warm_up() -> None:
    """Load (or compile) this stage's compiled kernels now (detection, edges, gains, shading and the blur's estimate; see :func:`ballscan.pipeline.warmup.warm_up`)."""
    from . import _defocus_kernels, _detection_kernels, _edge_kernels, _flatfield_kernels, _shading_kernels

    for kernels in (_detection_kernels, _edge_kernels, _flatfield_kernels, _shading_kernels, _defocus_kernels):
        kernels.warm_up()
