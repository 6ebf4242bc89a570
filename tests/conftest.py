"""Shared fixtures: cameras and motions used across the test modules."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion

DATA = Path(__file__).parent / "data"


@pytest.fixture
def tennis_camera() -> LineScanCamera:
    return LineScanCamera(width=2048, focal_px=4200.0, principal_px=1023.5, line_rate_hz=70000.0, exposure_s=1.2e-5)


@pytest.fixture
def serve_motion() -> BallMotion:
    return BallMotion(0.0335, 0.0017, (0.0, -0.08, 4.2), (44.5, 3.9, -5.5))


def random_rotation(rng: np.random.Generator) -> np.ndarray:
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    w, x, y, z = q
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )
