"""The compiled helpers (ballscan.compiled) and the one compiled signature of every kernel the package calls."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.compiled import pairwise_sum
from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.measure import _detection_kernels, _edge_kernels, _flatfield_kernels, _shading_kernels
from ballscan.model import _forward_kernels as F
from ballscan.solve import _fit_kernels
from ballscan.stream import _line_kernels

KERNEL_MODULES = (F, _fit_kernels, _detection_kernels, _edge_kernels, _shading_kernels, _flatfield_kernels, _line_kernels)


def test_pairwise_sum_equals_numpy():
    rng = np.random.default_rng(0)
    for n in list(range(0, 40)) + [127, 128, 129, 255, 256, 257, 799, 800, 1000, 4099]:
        a = rng.standard_normal(n) * 10.0 ** rng.uniform(-8, 8, n)
        assert pairwise_sum(a) == np.sum(a), n


@pytest.mark.slow
def test_every_kernel_compiles_one_signature_only():
    # a second signature (a read-only or strided argument) is compiled when
    # first seen: 0.5 s inside a stream's ball
    from ballscan.measure.detection import ColumnModel, detect
    from ballscan.pipeline.estimate import estimate_image
    from ballscan.pipeline.recipe import Recipe
    from ballscan.measure.images import LineImage
    from ballscan.model.render import Appearance, SensorNoise, render
    from ballscan.stream.engine import preload_estimator

    preload_estimator()
    cam = LineScanCamera(240, 3000.0, 119.5, 50000.0, None)
    m = BallMotion(0.0335, 0.002, (0.0, 0.001, 3.0), (30.0, 0.0, 0.0))
    for prnu in (0.0, 0.008):
        noise = SensorNoise(bits=16, white_dn=1000.0, black_dn=0.0, read_dn=5.0, full_well_e=None, prnu_sigma=prnu)
        r = render(cam, (m, Appearance.flat(0.8)), 200, background_level=0.1, noise=noise, seed=4)
        img = LineImage(r.image.astype(float), float(noise.max_dn), 16, "k")
        for pixels in (False, True):
            estimate_image(img, cam, 0.0335, recipe=Recipe(pixels=pixels))
        # and on known columns (the stream's engine background: read-only arrays)
        own = detect(img)
        estimate_image(img, cam, 0.0335, columns=ColumnModel(own.background_dn, own.noise_dn))
    for kernel in (F.averaged_samples, F.averaged_edges_jacobian, F.pixel_residuals, F.pixel_residuals_jacobian, F.coverage_grid, F.chord_edges, F.hybrid_rows,
                   _shading_kernels.limb_values, _detection_kernels.mode_seek, _edge_kernels.running_medians, _edge_kernels.walk_edges,
                   _edge_kernels.inner_differences, _edge_kernels.edge_windows, _shading_kernels.limb_levels, _shading_kernels.shading_fit,
                   _shading_kernels.line_level_sums, _shading_kernels.level_scatter, _shading_kernels.interior_normals,
                   _edge_kernels.rough_edges, _edge_kernels.shot_noise, _edge_kernels.level_gradients, _edge_kernels.shaded_sides,
                   _edge_kernels.window_edges, _edge_kernels.line_coverage, _edge_kernels.finished_edges, _edge_kernels.finite_rows,
                   _edge_kernels.limb_pixels, _fit_kernels.fit_residuals, _fit_kernels.fit_jacobian, _fit_kernels.area_tables,
                   _fit_kernels.select_lines, _fit_kernels.block_ratio, _fit_kernels.equilibrated,
                   _fit_kernels.damped, _fit_kernels.on_both_sides, _fit_kernels.loose_rows, _shading_kernels.chord_rows,
                   _shading_kernels.unique_lines, _shading_kernels.level_spans):
        assert len(kernel.signatures) == 1, (kernel.__name__, kernel.signatures)
    # and no kernel of the modules the package calls, listed or not, holds a
    # second one (the private helpers are compiled inside the kernels that
    # call them, once per caller's types, with no dispatch at run time)
    dispatchers = [
        v for module in KERNEL_MODULES for k, v in vars(module).items()
        if not k.startswith("_") and hasattr(v, "signatures") and hasattr(v, "py_func") and v.py_func.__module__ == module.__name__
    ]
    assert len(dispatchers) > 50
    assert [d.__name__ for d in dispatchers if len(d.signatures) > 1] == []
