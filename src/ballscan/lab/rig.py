"""Rigs of several line-scan cameras: named presets and ``ballscan simulate --rig``.

A rig preset is two posed cameras (:class:`ballscan.geometry.rig.Rig`), the
ball's motion in the world frame (:class:`ballscan.geometry.rig.WorldMotion`,
with gravity) and the image length.  The world frame: ``X`` along the lane
(the flight direction), ``Z`` up (gravity ``-Z``), ``Y`` across.

Presets
-------
lane-90
    A tennis ball at 45 m/s down a lane; camera ``side`` 4 m beside it
    looking across (its sensor vertical), camera ``top`` 4 m above looking
    down (its sensor across the lane): the second camera turned 90 degrees
    about the flight direction, so that each one's depth axis lies along
    the other's sensor.  Both viewing planes are the lane's cross-section
    ``X = 0``.
lane-30
    The same with the second camera turned 30 degrees from the first about
    the flight direction (4 m from the ball, 30 degrees above the side view).
tee
    A golf ball launched at 70 m/s, 12 degrees up and 3 degrees left, from
    a tee 0.3 m before the viewing planes; camera ``beside`` 2.5 m to the
    side, camera ``above`` 2.5 m above, both at 120 kHz.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, replace
from pathlib import Path
from typing import NamedTuple

import numpy as np

from ..geometry.camera import LineScanCamera
from ..geometry.rig import Rig, RigCamera, WorldMotion, load_rig, save_rig
from ..model.render import Appearance, SensorNoise, render, write_image

__all__ = [
    "RIG_PRESETS",
    "RigPreset",
    "RigSimulation",
    "camera_about_lane",
    "get_rig_preset",
    "plot_sweep",
    "reference_crossing_motion",
    "rig_for_angle",
    "rig_scene",
    "simulate_rig",
    "write_rig_simulation",
]

_GRAVITY = (0.0, 0.0, -9.81)


class RigPreset(NamedTuple):
    """A simulated rig scene.

    Attributes
    ----------
    rig : Rig
    motion : WorldMotion
        The ball, world frame; ``t_ref_s`` is its crossing of the first camera's plane.
    n_lines : int
        Lines per image (the same for every camera).
    appearance : Appearance
    """

    rig: Rig
    motion: WorldMotion
    n_lines: int
    appearance: Appearance


def camera_about_lane(intrinsics: LineScanCamera, distance_m: float, angle_deg: float, plane_x_m: float = 0.0) -> LineScanCamera:
    """A camera ``distance_m`` from the lane's axis (world ``X``), looking at it, turned ``angle_deg`` about it.

    At 0 degrees it stands at ``-Y`` looking along ``+Y`` with its sensor
    along ``-Z`` (vertical); positive angles turn it over the top (90: at
    ``+Z`` looking down, its sensor along ``-Y``).  Its viewing plane is
    ``X = plane_x_m`` and its ``x`` axis is world ``+X`` (a ball flying
    along ``+X`` crosses in ``+x``).
    """
    a = math.radians(angle_deg)
    # side pose: rows x = X, y = -Z, z = +Y; turned by -a about X (over the top for a > 0)
    R0 = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    c, s = math.cos(-a), math.sin(-a)
    Rx = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    R = R0 @ Rx.T
    centre = Rx @ np.array([0.0, -distance_m, 0.0]) + np.array([plane_x_m, 0.0, 0.0])
    return intrinsics.with_pose(R, -R @ centre)


def _lane_cam() -> LineScanCamera:
    return LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=70000.0, exposure_s=12e-6, gravity_mps2=None)


def rig_for_angle(angle_deg: float, distance_m: float = 4.0, *, first: LineScanCamera | None = None, second: LineScanCamera | None = None) -> Rig:
    """The lane rig with the second camera turned ``angle_deg`` about the flight direction from the first (both ``distance_m`` away)."""
    cam = _lane_cam() if first is None else first
    cam2 = cam if second is None else second
    side = RigCamera("side", camera_about_lane(cam, distance_m, 0.0))
    other = RigCamera("second", camera_about_lane(cam2, distance_m, angle_deg))
    return _with_gravity(Rig((side, other), _GRAVITY))


def _with_gravity(rig: Rig) -> Rig:
    cams = tuple(replace(c, camera=replace(c.camera, gravity_mps2=rig.gravity_mps2)) for c in rig.cameras)
    return replace(rig, cameras=cams)


def _lane(angle_deg: float, name: str) -> RigPreset:
    cam = _lane_cam()
    rig = Rig((RigCamera("side", camera_about_lane(cam, 4.0, 0.0)), RigCamera(name, camera_about_lane(cam, 4.0, angle_deg))), _GRAVITY)
    n_lines = 150
    t_mid = 0.5 * (n_lines - 1) / cam.line_rate_hz
    v = (44.6, 3.2, -5.1)
    motion = WorldMotion(0.0335, t_mid, (0.0, 0.06, -0.05), v, _GRAVITY)
    app = Appearance(ball_level=0.65, ambient=0.3)
    return RigPreset(_with_gravity(rig), motion, n_lines, app)


def _tee() -> RigPreset:
    cam = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=120000.0)
    rig = Rig((RigCamera("beside", camera_about_lane(cam, 2.5, 0.0, 0.3)), RigCamera("above", camera_about_lane(cam, 2.5, 90.0, 0.3))), _GRAVITY)
    n_lines = 110
    t_mid = 0.5 * (n_lines - 1) / cam.line_rate_hz
    e, az = math.radians(12.0), math.radians(3.0)
    v = 70.0 * np.array([math.cos(e) * math.cos(az), math.cos(e) * math.sin(az), math.sin(e)])
    # the tee at the origin, the ball 0.3 m on at its crossing
    tau = 0.3 / v[0]
    pos = v * tau + 0.5 * np.asarray(_GRAVITY) * tau * tau
    motion = WorldMotion(0.02135, t_mid, tuple(pos), tuple(v + np.asarray(_GRAVITY) * tau), _GRAVITY)
    app = Appearance(ball_level=0.9, ambient=0.3)
    return RigPreset(_with_gravity(rig), motion, n_lines, app)


#: Every rig preset.
RIG_PRESETS: dict[str, RigPreset] = {"lane-90": _lane(90.0, "top"), "lane-30": _lane(30.0, "oblique"), "tee": _tee()}


def get_rig_preset(name: str) -> RigPreset:
    """The rig preset called ``name`` (ValueError listing the names otherwise)."""
    try:
        return RIG_PRESETS[name]
    except (KeyError, TypeError):
        raise ValueError(f"unknown rig preset {name!r}; choose one of: {', '.join(RIG_PRESETS)}") from None


@dataclass(frozen=True)
class RigSimulation:
    """One rendered rig scene.

    Attributes
    ----------
    rig : Rig
        The rig as simulated (every clock offset known: the truth).
    motion : WorldMotion
        The ball, world frame.
    images : tuple of ndarray
        One stored image per camera (the rig's order).
    camera_motions : tuple of BallMotion
        The ball as each camera saw it (camera frame and clock).
    """

    rig: Rig
    motion: WorldMotion
    images: tuple[np.ndarray, ...]
    camera_motions: tuple


def simulate_rig(
    rig: Rig,
    motion: WorldMotion,
    n_lines: int,
    appearance: Appearance = Appearance(),
    *,
    clock_offsets_s: dict[str, float] | None = None,
    noise: SensorNoise = SensorNoise(),
    seed: int = 0,
    background_level: float = 0.1,
    cameras: tuple[str, ...] | None = None,
) -> RigSimulation:
    """Render the same ball in every camera of a rig (Eq. (8) in the world frame, each camera's Eq. (1)).

    Parameters
    ----------
    rig : Rig
    motion : WorldMotion
        World frame and rig clock.
    n_lines : int
        Lines of every image (line ``i`` at camera time ``i / line_rate``).
    appearance : Appearance
    clock_offsets_s : dict, optional
        True offsets (s) by camera name, for cameras whose rig offset is
        unknown or to be overridden; the others use the rig's (0 for unknown).
    noise : SensorNoise
    seed : int
        Camera ``k``'s noise has seed ``seed + 1000 k``.
    background_level : float
    cameras : tuple of str, optional
        Render only these cameras' balls (the others get an empty image), to
        simulate a ball seen by one camera only.

    Raises
    ------
    ValueError
        If the ball does not cross a camera's plane in front of it within its image.
    """
    offsets = dict(clock_offsets_s or {})
    truth_cams, images, motions = [], [], []
    for k, rc in enumerate(rig.cameras):
        off = offsets.get(rc.name, rc.clock_offset_s if rc.clock_known else 0.0)
        truth_cams.append(replace(rc, clock_offset_s=float(off)))
        cm = motion.in_camera(rc, float(off))
        t_end = (n_lines - 1) / rc.camera.line_rate_hz
        if cm is None or not (0.0 <= cm.t_c_s <= t_end) or cm.position_m[2] <= motion.radius_m:
            where = "never" if cm is None else f"at camera time {cm.t_c_s:.6g} s, depth {cm.position_m[2]:.3g} m"
            raise ValueError(f"simulate --rig: the ball crosses camera {rc.name!r}'s viewing plane {where}: not in front of it within its {n_lines} lines (0..{t_end:.6g} s)")
        shown = [] if cameras is not None and rc.name not in cameras else [(cm, appearance)]
        images.append(render(rc.camera, shown, n_lines, background_level=background_level, noise=noise, seed=seed + 1000 * k).image)
        motions.append(cm)
    return RigSimulation(replace(rig, cameras=tuple(truth_cams)), motion, tuple(images), tuple(motions))


def write_rig_simulation(sim: RigSimulation, out: str | Path, *, unknown_clocks: tuple[str, ...] = (), seed: int | None = None) -> list[Path]:
    """Write ``OUT.rig.toml``, one ``OUT.NAME.png`` per camera and ``OUT.truth.json`` (world frame); the paths.

    ``unknown_clocks``: these cameras' offsets are written as ``"unknown"``
    (the truth file keeps their values under ``clock_offsets_s``).
    """
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    rig = sim.rig
    # an unknown clock is written with a 1 ms prior (the matching window) unless the rig states one
    cams = tuple(replace(c, clock_offset_s=None, clock_sigma_s=c.clock_sigma_s or 1e-3) if c.name in unknown_clocks else c for c in rig.cameras)
    rig_path = out.with_name(out.name + ".rig.toml")
    save_rig(replace(rig, cameras=cams), rig_path, comment="written by ballscan simulate --rig")
    paths = [rig_path]
    for rc, img in zip(rig.cameras, sim.images):
        p = out.with_name(f"{out.name}.{rc.name}.png")
        write_image(p, img)
        paths.append(p)
    truth = sim.motion.to_dict()
    truth["frame"] = "world"
    truth["clock_offsets_s"] = {c.name: c.clock_offset_s for c in rig.cameras}
    truth["cameras"] = {c.name: m.to_dict() for c, m in zip(rig.cameras, sim.camera_motions)}
    truth["seed"] = seed
    truth_path = out.with_name(out.name + ".truth.json")
    truth_path.write_text(json.dumps(truth, indent=2))
    paths.append(truth_path)
    return paths


def rig_scene(rig_arg: str) -> tuple[Rig, RigPreset | None]:
    """The rig of ``--rig``: a preset's name, or a rig file (then no motion)."""
    if rig_arg in RIG_PRESETS:
        p = RIG_PRESETS[rig_arg]
        return p.rig, p
    if not Path(rig_arg).exists():
        raise ValueError(f"--rig: {rig_arg!r} is neither a rig file nor a rig preset ({', '.join(RIG_PRESETS)})")
    return load_rig(rig_arg), None


def reference_crossing_motion(rig: Rig, radius_m: float, position_m, velocity_mps, t_c_s: float) -> WorldMotion:
    """A world motion from the centre ``position_m`` at rig time ``t_c_s`` (for ``simulate --rig`` from a rig file)."""
    return WorldMotion(radius_m, t_c_s, tuple(position_m), tuple(velocity_mps), tuple(rig.gravity_vector()))


def plot_sweep(rows, path: str | Path | None = None, ax=None):
    """Plot the joint bound on the direction against the second camera's angle (:func:`ballscan.solve.rig_precision.sweep_second_camera`'s rows).

    Draws on ``ax`` (a new figure without pyplot when None), writes ``path``
    when given, and returns the figure.
    """
    from matplotlib.figure import Figure

    if ax is None:
        fig = Figure(figsize=(6.0, 3.6), layout="constrained")
        ax = fig.add_subplot()
    else:
        fig = ax.figure
    a = [r[0] for r in rows]
    for key, label, style in (("direction_sigma_deg", "direction (largest)", "-o"), ("elevation_sigma_deg", "elevation", "--"), ("azimuth_sigma_deg", "azimuth", ":")):
        ax.plot(a, [getattr(b, key) for _, b in rows], style, label=label)
    ax.set_yscale("log")
    ax.set_xlabel("second camera turned about the ball's path [deg]")
    ax.set_ylabel("1-sigma bound [deg]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    if path is not None:
        fig.savefig(path, dpi=120)
    return fig
