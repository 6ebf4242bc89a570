"""Cramér–Rao bounds: against the fit's empirical spread, scaling, text table."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.camera import LineScanCamera
from ballscan.fit import FitSettings, fit_motion, synthetic_edges
from ballscan.motion import BallMotion
from ballscan.precision import PrecisionBound, edge_crlb, pixel_crlb


def _serve():
    cam = LineScanCamera(2048, 4200.0, 1023.5, 70000.0, 1.2e-5)
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    return cam, m


def test_edge_crlb_matches_empirical_spread():
    cam, m = _serve()
    st = FitSettings(fit_edge_bias=False, edge_floor_px=0.0)
    bound = edge_crlb(cam, m, 0.05, settings=st)
    errs = []
    for seed in range(200):
        e = synthetic_edges(cam, m, 240, edge_sigma_px=0.05, seed=1000 + seed, area_sigma_px=1e9)
        r = fit_motion(cam, e, m, st)
        errs.append(r.motion.to_params() - m.to_params())
    errs = np.array(errs)
    ratio = errs.std(axis=0) / bound.sigmas
    # 200 samples: the std itself is known to +-5 % (1 sigma)
    assert np.all((ratio > 0.85) & (ratio < 1.15)), ratio
    # (|V| itself is not compared: with sigma_vz ~ 13 m/s at this noise the
    # speed is far from linear in vz, see MotionUncertainty.speed_correction_mps)


def test_bounds_scale_and_table():
    cam, m = _serve()
    b1 = edge_crlb(cam, m, 0.05)
    b2 = edge_crlb(cam, m, 0.10)
    assert isinstance(b1, PrecisionBound)
    assert np.allclose(b2.sigmas, 2 * b1.sigmas, rtol=1e-6)
    # the depth velocity is the weak axis
    assert b1.velocity_sigma_mps[2] > 10 * b1.velocity_sigma_mps[0]
    txt = b1.to_text()
    for word in ("t_c", "speed", "vz", "psi_y", "1-sigma"):
        assert word in txt
    p1 = pixel_crlb(cam, m, 2.0, 150.0)
    p2 = pixel_crlb(cam, m, 4.0, 150.0)
    assert np.allclose(p2.sigmas, 2 * p1.sigmas, rtol=1e-6)
    # a single edge from ~3 pixels of noise 2/150 carries ~0.02 px: the pixel bound
    # must be comparable to the edge bound at that noise
    be = edge_crlb(cam, m, 2.0 / 150.0 * 1.5)
    assert 0.05 < p1.velocity_sigma_mps[0] / be.velocity_sigma_mps[0] < 3.0
    with pytest.raises(ValueError):
        edge_crlb(cam, m, 0.0)
    with pytest.raises(ValueError):
        pixel_crlb(cam, m, 1.0, 0.0)
