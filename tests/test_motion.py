"""Ball motion: kinematics, parameter vector round trip, validation."""

from __future__ import annotations

import numpy as np
import pytest

from ballscan.geometry.motion import BallMotion


def test_centre_and_velocity_with_acceleration():
    m = BallMotion(0.03, 0.5, (0, 0.1, 3.0), (10.0, 1.0, -2.0), (0.0, -9.81, 0.0))
    c = m.centre(np.array([0.5, 0.6]))
    np.testing.assert_allclose(c[0], [0, 0.1, 3.0])
    np.testing.assert_allclose(c[1], [1.0, 0.1 + 0.1 - 0.5 * 9.81 * 0.01, 3.0 - 0.2])
    np.testing.assert_allclose(m.velocity_at(np.array([0.6]))[0], [10.0, 1.0 - 0.981, -2.0])


def test_params_round_trip():
    m = BallMotion(0.0335, 0.0017, (0, -0.08, 4.2), (44.5, 3.9, -5.5))
    assert BallMotion.from_params(m.to_params(), m.radius_m) == m
    assert BallMotion.from_dict(m.to_dict()) == m
    assert m.speed_mps == pytest.approx(np.sqrt(44.5**2 + 3.9**2 + 5.5**2))


@pytest.mark.parametrize(
    "kw,match",
    [
        (dict(radius_m=-1.0), "radius_m"),
        (dict(position_m=(0.1, 0, 3)), "x must be 0"),
        (dict(velocity_mps=(1, np.nan, 0)), "finite"),
        (dict(velocity_mps=(1, 0)), "3 values"),
    ],
)
def test_invalid_motion(kw, match):
    base = dict(radius_m=0.03, t_c_s=0.0, position_m=(0, 0, 3), velocity_mps=(10, 0, 0))
    base.update(kw)
    with pytest.raises(ValueError, match=match):
        BallMotion(**base)
