"""Named simulation scenes: a camera, a ball's motion and how the ball looks.

Each preset is a :class:`Preset` (a named 4-tuple, so
``camera, motion, n_lines, appearance = get_preset("tennis-serve")`` works):
the ball crosses the viewing plane at the middle of ``n_lines`` lines and
its whole image lies inside the image with a margin of at least 10 % of the
visible-line count at both ends and 10 % of the sensor at both ends, so it
can be measured without any "cut" flag.

Presets
-------
tennis-serve
    Tennis ball (R = 33.5 mm) served at 45 m/s, slightly oblique, 4 m from a
    2048-pixel camera at 70 kHz; seam texture spinning at 40 rev/s.
table-tennis
    Table-tennis ball (R = 20 mm) at 12 m/s receding 10 degrees, 1.8 m from
    a 1024-pixel camera at 30 kHz.
golf-drive
    Golf ball (R = 21.35 mm) at 70 m/s with a 12 degree launch angle along
    the sensor, 2.5 m from a 2048-pixel camera at 120 kHz.
baseball-pitch
    Baseball (R = 36.6 mm) at 40 m/s, dropping and receding slightly, 3 m
    from a 2048-pixel camera at 50 kHz; red seam (darker than the leather).
paper-rail
    The paper's laboratory case (Sec. 3.B): a tennis ball on a linear guide
    rail at 0.1 m/s crossing the viewing plane at a right angle, 1 m from a
    BASLER spL2048-70km-like camera (2048 pixels of 10 um, 23 mm lens) at
    200 lines/s.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from ..model.render import Appearance

__all__ = ["Preset", "PRESETS", "get_preset"]


class Preset(NamedTuple):
    """A simulation scene.

    Attributes
    ----------
    camera : LineScanCamera
    motion : BallMotion
        The ball's true motion (camera frame).
    n_lines : int
        Suggested number of scan lines: the ball and a margin fit in.
    appearance : Appearance
    """

    camera: LineScanCamera
    motion: BallMotion
    n_lines: int
    appearance: Appearance


def _velocity(speed_mps: float, along_deg: float, depth_deg: float) -> tuple[float, float, float]:
    """Velocity of ``speed_mps`` tilted ``along_deg`` towards +y and ``depth_deg`` towards +z (degrees)."""
    a, d = math.radians(along_deg), math.radians(depth_deg)
    return (speed_mps * math.cos(a) * math.cos(d), speed_mps * math.sin(a) * math.cos(d), speed_mps * math.sin(d))


def _make(camera: LineScanCamera, radius_m: float, y0_m: float, z0_m: float, velocity_mps, n_lines: int, appearance: Appearance) -> Preset:
    # Centre the crossing in the image so the margins before and after are equal.
    t_c = 0.5 * (n_lines - 1) / camera.line_rate_hz
    motion = BallMotion(radius_m, t_c, (0.0, y0_m, z0_m), velocity_mps)
    return Preset(camera, motion, n_lines, appearance)


def _tennis_serve() -> Preset:
    cam = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=70000.0, exposure_s=12e-6)
    app = Appearance(ball_level=0.65, texture="tennis", seam_level=0.95, spin_axis=(0.2, 0.3, 1.0), spin_rps=40.0, orientation_seed=11)
    return _make(cam, 0.0335, -0.08, 4.0, _velocity(45.0, 5.0, -7.0), 150, app)


def _table_tennis() -> Preset:
    cam = LineScanCamera(width=1024, focal_px=2800.0, principal_px=511.5, line_rate_hz=30000.0)
    app = Appearance(ball_level=0.85, ambient=0.4)
    return _make(cam, 0.020, -0.04, 1.8, _velocity(12.0, 0.0, 10.0), 150, app)


def _golf_drive() -> Preset:
    cam = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=120000.0)
    app = Appearance(ball_level=0.9, ambient=0.3)
    return _make(cam, 0.02135, 0.05, 2.5, _velocity(70.0, -12.0, 0.0), 110, app)


def _baseball_pitch() -> Preset:
    cam = LineScanCamera(width=2048, focal_px=3500.0, principal_px=1023.5, line_rate_hz=50000.0)
    app = Appearance(
        ball_level=0.85, texture="tennis", seam_level=0.45, seam_width_rad=0.12, spin_axis=(0.0, 0.0, 1.0), spin_rps=30.0, orientation_seed=5
    )
    return _make(cam, 0.0366, 0.0, 3.0, _velocity(40.0, 4.0, -3.0), 130, app)


def _paper_rail() -> Preset:
    cam = LineScanCamera(width=2048, focal_px=2300.0, principal_px=1023.5, line_rate_hz=200.0, exposure_s=2e-3)
    app = Appearance(ball_level=0.65, texture="tennis", seam_level=0.95, orientation_seed=2)
    return _make(cam, 0.0335, 0.0, 1.0, (0.1, 0.0, 0.0), 180, app)


#: Every named preset, built once (all fields are immutable).
PRESETS: dict[str, Preset] = {
    "tennis-serve": _tennis_serve(),
    "table-tennis": _table_tennis(),
    "golf-drive": _golf_drive(),
    "baseball-pitch": _baseball_pitch(),
    "paper-rail": _paper_rail(),
}


def get_preset(name: str) -> Preset:
    """The preset called ``name``.

    Raises
    ------
    ValueError
        If there is no such preset; the message lists the names.
    """
    try:
        return PRESETS[name]
    except (KeyError, TypeError):
        raise ValueError(f"unknown preset {name!r}; choose one of: {', '.join(PRESETS)}") from None
