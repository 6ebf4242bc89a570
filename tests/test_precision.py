"""Cramér–Rao bounds: against the fit's empirical spread, scaling, text table."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.solve.fit import fit_motion
from ballscan.solve.settings import FitSettings
from ballscan.solve.synthetic import synthetic_edges
from ballscan.geometry.motion import BallMotion
from ballscan.solve.precision import PrecisionBound, _pixel_fisher, _pixel_model, edge_crlb, pixel_crlb, sensor_crlb
from ballscan.model.render import SensorNoise


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


def _dense_fisher(G, var, signal, prnu):
    """Brute force: every column's full covariance inverted."""
    F = np.zeros((G.shape[0], G.shape[0]))
    for c in range(G.shape[2]):
        S = np.diag(var[:, c]) + prnu**2 * np.outer(signal[:, c], signal[:, c])
        Gc = G[:, :, c]
        F += Gc @ np.linalg.solve(S, Gc.T)
    return F


def test_prnu_fisher_matches_the_dense_covariance():
    cam, m = _serve()
    cov, dcov = _pixel_model(cam, m, 8)
    rng = np.random.default_rng(3)
    var = rng.uniform(3.0, 9.0, cov.shape)  # each pixel its own noise
    G, sig = 150.0 * dcov, 150.0 * cov
    for prnu in (0.0, 0.008, 0.05):
        F = _pixel_fisher(G, var, sig, prnu)
        Fd = _dense_fisher(G, var, sig, prnu)
        assert np.allclose(F, Fd, rtol=1e-9, atol=1e-12 * np.abs(Fd).max())


def test_prnu_bound_reduces_to_white_noise_and_only_widens():
    cam, m = _serve()
    p0 = pixel_crlb(cam, m, 2.0, 150.0)
    assert np.array_equal(pixel_crlb(cam, m, 2.0, 150.0, prnu_sigma=0.0).sigmas, p0.sigmas)
    p1 = pixel_crlb(cam, m, 2.0, 150.0, prnu_sigma=0.02)
    assert np.all(p1.sigmas >= p0.sigmas) and np.any(p1.sigmas > 1.001 * p0.sigmas)
    assert "PRNU 0.02" in p1.noise
    # the sensor model with read noise only and no gain spread is white
    # Gaussian noise of sqrt(read^2 + 1/12) on a contrast of white x (ball - bg)
    ns = SensorNoise(bits=12, white_dn=1000.0, black_dn=0.0, read_dn=2.0, full_well_e=None, prnu_sigma=0.0)
    s0 = sensor_crlb(cam, m, ns, 0.7, 0.1)
    ref = pixel_crlb(cam, m, float(np.sqrt(4.0 + 1.0 / 12.0)), 600.0)
    assert np.allclose(s0.sigmas, ref.sigmas, rtol=1e-12)
    # shot noise and unknown gains widen it; a flat-fielded camera pays nothing for PRNU
    ns2 = SensorNoise(bits=12, white_dn=1000.0, black_dn=0.0, read_dn=2.0, full_well_e=20000.0, prnu_sigma=0.01)
    shot = sensor_crlb(cam, m, ns2, 0.7, 0.1, flat_field=True)
    both = sensor_crlb(cam, m, ns2, 0.7, 0.1)
    assert np.all(shot.sigmas > s0.sigmas) and np.all(both.sigmas >= shot.sigmas)
    noprnu = sensor_crlb(cam, m, SensorNoise(bits=12, white_dn=1000.0, black_dn=0.0, read_dn=2.0, full_well_e=20000.0, prnu_sigma=0.0), 0.7, 0.1)
    assert np.array_equal(shot.sigmas, noprnu.sigmas)
    # a darker ball on a brighter background is bounded too (the signal's sign does not matter)
    assert np.isfinite(sensor_crlb(cam, m, ns2, 0.1, 0.7).speed_sigma_mps)
    with pytest.raises(ValueError, match="prnu_sigma"):
        pixel_crlb(cam, m, 2.0, 150.0, prnu_sigma=-0.1)
    with pytest.raises(ValueError, match="ball_level"):
        sensor_crlb(cam, m, ns2, 0.5, 0.5)
