"""Seeded random line-scan scenes for the POV-Ray validation set: what is in them and where.

A scene is drawn from one integer seed (``draw_scene``): the ball kind and its
texture, the motion, the camera and its line rate, the light, the background,
the optics (lens distortion, defocus) and the sensor (bit depth, noise, column
gains, a defective column, lamp flicker), and the hard cases (a ball cut by a
sensor end or by the first or last line, two balls close in time).  Every
length here is in metres, every time in seconds, image positions in pixels, in
the camera frame of ``geometry.md`` (``x`` across the viewing plane, ``y``
along the sensor, ``z`` forward).

The split is fixed by the seed: even seeds are the tuning half, odd seeds the
report half (``split_of``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

__all__ = [
    "KINDS", "RADIUS_M", "Ball", "Camera", "Light", "Sensor", "Optics", "Scene",
    "draw_scene", "split_of", "visible_interval_s", "image_extent_px", "rig_views",
]

#: Ball kinds and their official radii (``plain`` draws its radius).
KINDS = ("tennis", "baseball", "golf", "pingpong", "football", "plain")
RADIUS_M = {"tennis": 0.0335, "baseball": 0.0366, "golf": 0.02135, "pingpong": 0.020, "football": 0.110}

#: Frame budget of one scene (lines traced x exposure sub-frames, plus one background frame).
MAX_FRAMES = 2000
#: Sub-frames are added until the image moves at most this far (pixels) between two of them.
SUBFRAME_STEP_PX = 0.25


@dataclass(frozen=True)
class Ball:
    """One ball: C(t) = position_m + velocity_mps (t - t_c_s); texture and pose for the renderer."""

    kind: str
    radius_m: float
    t_c_s: float
    position_m: tuple[float, float, float]
    velocity_mps: tuple[float, float, float]
    rgb: tuple[float, float, float]
    albedo_scale: float
    phong: float
    orientation_deg: tuple[float, float, float]
    spin_axis: tuple[float, float, float]
    spin_rps: float


@dataclass(frozen=True)
class Camera:
    """The line camera of geometry.md (``width`` pixels, ``n_lines`` lines in the image)."""

    width: int
    focal_px: float
    principal_px: float
    line_rate_hz: float
    exposure_s: float
    k1: float
    k2: float
    n_lines: int


@dataclass(frozen=True)
class Light:
    """Lamps (directions towards the lamp, unit), ambient share, flicker and the background profile."""

    main_dir: tuple[float, float, float]
    second_dir: tuple[float, float, float] | None
    second_intensity: float
    ambient: float
    flicker_hz: float
    flicker_depth: float
    flicker_phase_rad: float
    background_level: float
    background_ramp: float
    background_wave: float
    background_wave_periods: float
    background_wave_phase_rad: float
    background_distance_m: float


@dataclass(frozen=True)
class Sensor:
    """DN = black + Poisson(Y g_j full_well) white / full_well + N(0, read^2), rounded and clipped."""

    bits: int
    white_dn: float
    black_dn: float
    read_dn: float
    full_well_e: float
    prnu_sigma: float
    defect: str  # "none", "dead" or "hot"
    defect_column: int
    hot_dn: float


@dataclass(frozen=True)
class Optics:
    """Defocus of a real aperture (POV-Ray focal blur): aperture diameter and the distance in focus."""

    aperture_m: float
    focus_m: float
    blur_px: float  # blur-circle diameter at the first ball's crossing depth


@dataclass(frozen=True)
class Scene:
    """One scene of the set, all it takes to write the POV-Ray source, the camera file and the truth."""

    name: str
    seed: int
    balls: tuple[Ball, ...]
    camera: Camera
    light: Light
    sensor: Sensor
    optics: Optics
    subframes: int
    traced_lines: tuple[int, ...]
    conditions: tuple[str, ...]
    cut: str = "none"  # none, sensor_start, sensor_end, first_line, last_line
    pose_rotation: tuple[tuple[float, ...], ...] | None = None
    pose_translation_m: tuple[float, float, float] | None = None
    extra: dict = field(default_factory=dict, compare=False)

    @property
    def split(self) -> str:
        return split_of(self.seed)


def split_of(seed: int) -> str:
    """``"tune"`` for even seeds, ``"report"`` for odd seeds: the set's one fixed split."""
    return "tune" if seed % 2 == 0 else "report"


def _loguniform(rng: np.random.Generator, lo: float, hi: float) -> float:
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def _unit(v) -> tuple[float, float, float]:
    a = np.asarray(v, float)
    a = a / np.linalg.norm(a)
    return (float(a[0]), float(a[1]), float(a[2]))


def visible_interval_s(ball: Ball, cam: Camera) -> tuple[float, float]:
    """Times (s) between which the ball touches the pixels' footprint |x| <= z / (2 f) (geometry.md)."""
    vx = abs(ball.velocity_mps[0])
    z = ball.position_m[2]
    half = (ball.radius_m + z / (2 * cam.focal_px)) / vx
    # the depth changes over the crossing: widen by the footprint's growth
    dz = abs(ball.velocity_mps[2]) * half
    half = (ball.radius_m + (z + dz) / (2 * cam.focal_px)) / vx
    return ball.t_c_s - half, ball.t_c_s + half


def _distort(n: np.ndarray, k1: float, k2: float) -> np.ndarray:
    return n * (1 + k1 * n**2 + k2 * n**4)


def image_extent_px(ball: Ball, cam: Camera, times_s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest sensor position u (pixels) of the ball's silhouette at each time.

    The ball's section by the viewing plane (widened to the pixel footprint) is a
    disc; its tangents from the projection centre give the normalised
    coordinates, then ``u = c + f n_d`` with the radial distortion of geometry.md.
    """
    t = np.asarray(times_s, float) - ball.t_c_s
    c = np.asarray(ball.position_m)[:, None] + np.asarray(ball.velocity_mps)[:, None] * t[None, :]
    x, y, z = c
    rho = np.sqrt(np.clip(ball.radius_m**2 - np.minimum(x**2, ball.radius_m**2), 0, None))
    rho = np.maximum(rho, 1e-9)
    d = np.hypot(y, z)
    a0 = np.arctan2(y, z)
    da = np.arcsin(np.clip(rho / d, 0, 1))
    lo = _distort(np.tan(a0 - da), cam.k1, cam.k2)
    hi = _distort(np.tan(a0 + da), cam.k1, cam.k2)
    return cam.principal_px + cam.focal_px * lo, cam.principal_px + cam.focal_px * hi


def _draw_kind(rng: np.random.Generator, dark: bool) -> dict:
    kind = KINDS[int(rng.integers(len(KINDS)))]
    radius = RADIUS_M.get(kind) or _loguniform(rng, 0.01, 0.12)
    rgb = {
        "tennis": (0.70, 0.85, 0.15), "baseball": (0.90, 0.88, 0.82), "golf": (0.93, 0.93, 0.93),
        "football": (0.92, 0.92, 0.92),
    }.get(kind)
    if kind == "pingpong":
        rgb = (0.95, 0.95, 0.95) if rng.random() < 0.5 else (1.0, 0.45, 0.05)
    if rgb is None:
        rgb = tuple(float(v) for v in rng.uniform(0.2, 1.0, 3))
    phong = {"pingpong": 0.3, "golf": 0.35, "baseball": 0.1}.get(kind, 0.0)
    if rng.random() < 0.35:
        phong = float(rng.uniform(0.2, 0.8))
    albedo = float(rng.uniform(0.08, 0.3)) if dark else float(rng.uniform(0.7, 1.0))
    return dict(kind=kind, radius_m=float(radius), rgb=rgb, albedo_scale=albedo, phong=phong)


def _draw_direction(rng: np.random.Generator, speed: float) -> tuple[float, float, float]:
    """Velocity (m/s) with the in-plane angle up to 60 deg and |V.z| up to half the speed."""
    psi_y = math.radians(rng.uniform(-10, 10) if rng.random() < 0.5 else rng.uniform(-60, 60))
    vz = rng.uniform(-0.1, 0.1) if rng.random() < 0.45 else rng.uniform(-0.5, 0.5)
    sign = 1.0 if rng.random() < 0.5 else -1.0
    c = math.sqrt(1 - vz * vz)
    return (sign * speed * c * math.cos(psi_y), speed * c * math.sin(psi_y), speed * vz)


def _draw_light(rng: np.random.Generator, dark: bool, z0: float) -> Light:
    if rng.random() < 0.75:  # the usual set-up: lamps on the camera's side
        main = _unit((rng.uniform(-0.6, 0.6), rng.uniform(-0.6, 0.6), rng.uniform(-1.0, -0.4)))
    else:
        main = _unit((rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1.0, 0.3)))
    second = None
    second_i = 0.0
    if rng.random() < 0.4:
        second = _unit((rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1.0, 0.5)))
        second_i = float(rng.uniform(0.2, 0.7))
    flicker = rng.random() < 0.3
    bg = float(rng.uniform(0.45, 0.85)) if dark else _loguniform(rng, 0.01, 0.3)
    return Light(
        main_dir=main, second_dir=second, second_intensity=second_i,
        ambient=float(rng.uniform(0.1, 0.6)),
        flicker_hz=float(rng.choice([100.0, 120.0])) if flicker else 0.0,
        flicker_depth=float(rng.uniform(0.05, 0.35)) if flicker else 0.0,
        flicker_phase_rad=float(rng.uniform(0, 2 * math.pi)),
        background_level=bg,
        background_ramp=float(rng.uniform(-0.4, 0.4)),
        background_wave=float(rng.uniform(0, 0.25)) if rng.random() < 0.6 else 0.0,
        background_wave_periods=float(rng.uniform(0.5, 4)),
        background_wave_phase_rad=float(rng.uniform(0, 2 * math.pi)),
        background_distance_m=float(z0 * rng.uniform(2.0, 6.0)),
    )


def _draw_sensor(rng: np.random.Generator, width: int) -> Sensor:
    bits = int(rng.choice([8, 8, 12, 16]))
    top = 2**bits - 1
    read = {8: _loguniform(rng, 0.5, 3.0), 12: _loguniform(rng, 2.0, 25.0), 16: _loguniform(rng, 10.0, 300.0)}[bits]
    u = rng.random()
    defect = "dead" if u < 0.1 else ("hot" if u < 0.2 else "none")
    return Sensor(
        bits=bits, white_dn=float(top * rng.uniform(0.75, 0.92)), black_dn=float(top * rng.uniform(0.01, 0.04)),
        read_dn=float(read), full_well_e=_loguniform(rng, 3000.0, 40000.0),
        prnu_sigma=_loguniform(rng, 0.002, 0.02), defect=defect,
        defect_column=int(rng.integers(0, width)), hot_dn=float(top * rng.uniform(0.5, 0.85)),
    )


def _draw_camera(rng: np.random.Generator, ball: dict, speed_x: float, z0: float) -> Camera:
    width = int(rng.integers(64, 201))
    n_vis = _loguniform(rng, 24, 300)
    f = ball["focal_px"]
    lr = n_vis * speed_x / (2 * ball["radius_m"] + z0 / f)
    lr = float(min(max(lr, 20.0), 300000.0))
    share = _loguniform(rng, 0.03, 1.0)
    offaxis = rng.random() < 0.4
    c = (width - 1) / 2 + (rng.uniform(-0.4, 0.4) * f if offaxis else rng.uniform(-0.1, 0.1) * width)
    k1 = float(rng.uniform(-0.3, 0.3)) if rng.random() < 0.4 else 0.0
    k2 = float(rng.uniform(-0.1, 0.1)) if k1 and rng.random() < 0.5 else 0.0
    return Camera(width=width, focal_px=float(f), principal_px=float(c), line_rate_hz=lr,
                  exposure_s=share / lr, k1=k1, k2=k2, n_lines=0)


def _place_y(ball: Ball, cam: Camera, rng: np.random.Generator, cut: str, lo_frac: float, hi_frac: float) -> Ball:
    """Choose y0 so the silhouette lies inside the sensor (or is cut by the chosen end)."""
    t0, t1 = visible_interval_s(ball, cam)
    times = np.linspace(t0, t1, 41)
    diam = 2 * cam.focal_px * ball.radius_m / ball.position_m[2]
    for _ in range(4):
        lo, hi = image_extent_px(ball, cam, times)
        u_lo, u_hi = float(lo.min()), float(hi.max())
        if cut == "sensor_start":
            shift = -rng.uniform(0.2, 0.6) * diam - u_lo
        elif cut == "sensor_end":
            shift = (cam.width - 1) + rng.uniform(0.2, 0.6) * diam - u_hi
        else:
            room_lo = lo_frac * (cam.width - 1) + 2 - u_lo
            room_hi = hi_frac * (cam.width - 1) - 2 - u_hi
            shift = rng.uniform(room_lo, room_hi) if room_hi > room_lo else 0.5 * (room_lo + room_hi)
        rng = np.random.default_rng(rng.integers(2**31))
        z = ball.position_m[2]
        n_now = ball.position_m[1] / z
        n_new = n_now + shift / (cam.focal_px * (1 + 3 * cam.k1 * n_now**2))
        ball = replace(ball, position_m=(0.0, n_new * z, z))
        cut = cut if cut in ("sensor_start", "sensor_end") else "done"
        if cut == "done":
            lo, hi = image_extent_px(ball, cam, times)
            if lo.min() >= lo_frac * (cam.width - 1) + 1 and hi.max() <= hi_frac * (cam.width - 1) - 1:
                break
    return ball


def _lines(balls: tuple[Ball, ...], cam: Camera, cut: str, cut_frac: float) -> tuple[Camera, tuple[Ball, ...], list[int]]:
    """Line timing: margins before and after the balls, or a cut by the first or last line."""
    lr = cam.line_rate_hz
    spans = [visible_interval_s(b, cam) for b in balls]
    t_in = min(s[0] for s in spans) - cam.exposure_s / 2
    t_out = max(s[1] for s in spans) + cam.exposure_s / 2
    n_vis = (t_out - t_in) * lr
    margin = max(6.0, 0.3 * n_vis)
    first = (t_in + cut_frac * (spans[0][1] - spans[0][0])) * lr if cut == "first_line" else t_in * lr - margin
    last = (spans[-1][1] - cut_frac * (spans[-1][1] - spans[-1][0])) * lr if cut == "last_line" else t_out * lr + margin
    offset = math.floor(first)
    shift = offset / lr
    balls = tuple(replace(b, t_c_s=b.t_c_s - shift) for b in balls)
    cam = replace(cam, n_lines=int(math.ceil(last)) - offset + 1)
    return cam, balls, _traced_lines(balls, cam)


def _traced_lines(balls: tuple[Ball, ...], cam: Camera) -> list[int]:
    """Lines whose exposure may meet a ball's footprint (one line of margin each side)."""
    lr = cam.line_rate_hz
    traced = set()
    for b in balls:
        a, z = visible_interval_s(b, cam)
        i0 = int(math.floor((a - cam.exposure_s / 2) * lr)) - 1
        i1 = int(math.ceil((z + cam.exposure_s / 2) * lr)) + 1
        traced.update(i for i in range(i0, i1 + 1) if 0 <= i < cam.n_lines)
    return sorted(traced)


def _subframes(balls: tuple[Ball, ...], cam: Camera, n_traced: int) -> int:
    """Exposure sub-frames: enough that the image moves <= SUBFRAME_STEP_PX between two, within the budget."""
    move = max(cam.focal_px * math.dist((0, 0, 0), b.velocity_mps) / b.position_m[2] * cam.exposure_s for b in balls)
    ns = min(16, max(1, math.ceil(move / SUBFRAME_STEP_PX)))
    return max(1, min(ns, (MAX_FRAMES - 1) // max(n_traced, 1)))


def _draw_ball(rng: np.random.Generator, base: dict, speed: float, z0: float, t_c: float) -> Ball:
    axis = _unit(rng.normal(size=3))
    spin = float(rng.uniform(0, 50)) * min(1.0, speed / 20) if rng.random() < 0.7 else 0.0
    return Ball(
        kind=base["kind"], radius_m=base["radius_m"], t_c_s=t_c, position_m=(0.0, 0.0, z0),
        velocity_mps=_draw_direction(rng, speed), rgb=base["rgb"], albedo_scale=base["albedo_scale"],
        phong=base["phong"], orientation_deg=tuple(float(a) for a in rng.uniform(0, 360, 3)),
        spin_axis=axis, spin_rps=spin,
    )


def _second_ball(rng: np.random.Generator, first: Ball, cam: Camera) -> Ball:
    """A second ball of the same kind crossing soon after the first, on the other half of the sensor."""
    t0, t1 = visible_interval_s(first, cam)
    dt = (t1 - t0) * rng.uniform(0.4, 1.6)
    speed = math.dist((0, 0, 0), first.velocity_mps) * rng.uniform(0.8, 1.2)
    v = _draw_direction(rng, speed)
    v = (math.copysign(v[0], first.velocity_mps[0]), 0.3 * v[1], 0.3 * v[2])
    z = first.position_m[2] * rng.uniform(0.85, 1.15)
    return replace(first, t_c_s=first.t_c_s + dt, position_m=(0.0, 0.0, z), velocity_mps=v,
                   orientation_deg=tuple(float(a) for a in rng.uniform(0, 360, 3)))


def _draw_optics(rng: np.random.Generator, z0: float, f: float) -> Optics:
    if rng.random() >= 0.3:
        return Optics(aperture_m=0.0, focus_m=z0, blur_px=0.0)
    blur = float(rng.uniform(0.7, 4.0))
    focus = z0 * (rng.uniform(0.6, 0.85) if rng.random() < 0.5 else rng.uniform(1.2, 1.6))
    aperture = blur * z0 * focus / (f * abs(z0 - focus))
    return Optics(aperture_m=float(aperture), focus_m=float(focus), blur_px=blur)


def draw_scene(seed: int, name: str | None = None) -> Scene:
    """Draw one scene from ``seed`` (deterministic: the same seed gives the same scene)."""
    rng = np.random.default_rng([20260523, seed])
    dark = rng.random() < 0.3
    base = _draw_kind(rng, dark)
    u = rng.random()
    cut = ("sensor_start", "sensor_end", "first_line", "last_line")[int(rng.integers(4))] if u < 0.2 else "none"
    two = cut == "none" and rng.random() < 0.1
    speed = _loguniform(rng, 0.05, 70.0)
    ball = _draw_ball(rng, base, speed, 1.0, 0.0)
    tan_y = abs(ball.velocity_mps[1] / ball.velocity_mps[0])
    width_guess = 64 + 136 * 0.5
    r_max = (width_guess - 8) / (2 * (1 + tan_y)) / (2 if two else 1)
    for _ in range(100):  # a focal length and a distance in the ranges that give the radius in pixels
        base["focal_px"] = _loguniform(rng, 800.0, 12000.0)
        r_px = min(_loguniform(rng, 3.0, 40.0), r_max)
        z0 = base["focal_px"] * base["radius_m"] / r_px
        if 0.25 <= z0 <= 15.0:
            break
    ball = replace(ball, position_m=(0.0, 0.0, z0))
    cam = _draw_camera(rng, base, abs(ball.velocity_mps[0]), z0)
    r_px = cam.focal_px * ball.radius_m / z0
    need = 2 * r_px * (1 + 1.2 * tan_y) * (2.2 if two else 1) + 12
    if cam.width < need:
        cam = replace(cam, width=int(min(200, math.ceil(need))))
        cam = replace(cam, principal_px=min(cam.principal_px, cam.width * 2.0) if cam.k1 else cam.principal_px)
    balls = [_place_y(ball, cam, rng, cut, 0.0, 0.45 if two else 1.0)]
    if two:
        b2 = _second_ball(rng, balls[0], cam)
        balls.append(_place_y(b2, cam, rng, "none", 0.55, 1.0))
    cut_frac = float(rng.uniform(0.1, 0.6))
    cam, balls, traced = _lines(tuple(balls), cam, cut, cut_frac)
    light = _draw_light(rng, dark, z0)
    sensor = _draw_sensor(rng, cam.width)
    optics = _draw_optics(rng, z0, cam.focal_px)
    ns = _subframes(balls, cam, len(traced))
    conditions = _conditions(balls, cam, light, sensor, optics, cut, dark)
    return Scene(name=name or f"pv{seed:04d}", seed=seed, balls=balls, camera=cam, light=light, sensor=sensor,
                 optics=optics, subframes=ns, traced_lines=tuple(traced), conditions=conditions, cut=cut)


def _conditions(balls, cam: Camera, light: Light, sensor: Sensor, optics: Optics, cut: str, dark: bool) -> tuple[str, ...]:
    """Condition tags the scorer groups by (a scene may carry several)."""
    tags = ["dark_ball" if dark else "bright_ball"]
    v = balls[0].velocity_mps
    if abs(v[2]) > 0.1 * math.dist((0, 0, 0), v):
        tags.append("depth_motion")
    if abs(math.degrees(math.atan2(v[1], abs(v[0])))) > 20:
        tags.append("oblique")
    if cut != "none":
        tags.append("cut_" + cut)
    if len(balls) > 1:
        tags.append("two_balls")
    if optics.blur_px > 0:
        tags.append("defocus")
    if cam.k1 or cam.k2:
        tags.append("distortion")
    if light.flicker_hz:
        tags.append("flicker")
    if sensor.defect != "none":
        tags.append(sensor.defect + "_column")
    if light.second_dir is not None:
        tags.append("second_lamp")
    if cam.exposure_s * cam.line_rate_hz > 0.5:
        tags.append("long_exposure")
    tags.append(f"{sensor.bits}bit")
    return tuple(tags)


def rig_views(scene: Scene, angles_deg: tuple[float, ...]) -> list[Scene]:
    """The same balls seen by cameras turned about the lane's axis (the line through the first ball's
    crossing point along the camera's x), one scene per angle, each with its world -> camera pose.

    The world frame is the first view's camera frame at angle 0; a camera turned by ``a`` keeps the
    viewing plane ``x = 0`` (the rotation is about x) and sees the crossing point at the same
    distance, so every view has the same line timing.
    """
    p = np.asarray(scene.balls[0].position_m)
    views = []
    for a in angles_deg:
        r = math.radians(a)
        rot = np.array([[1, 0, 0], [0, math.cos(r), -math.sin(r)], [0, math.sin(r), math.cos(r)]])
        trans = np.array([0.0, p[1], p[2]]) - rot @ p
        balls = tuple(
            replace(b, position_m=tuple(float(v) for v in rot @ np.asarray(b.position_m) + trans),
                    velocity_mps=tuple(float(v) for v in rot @ np.asarray(b.velocity_mps)))
            for b in scene.balls)
        light = replace(scene.light, main_dir=_unit(rot @ np.asarray(scene.light.main_dir)),
                        second_dir=None if scene.light.second_dir is None
                        else _unit(rot @ np.asarray(scene.light.second_dir)))
        views.append(replace(scene, name=f"{scene.name}_a{int(round(a)):03d}", balls=balls, light=light,
                             pose_rotation=tuple(tuple(float(v) for v in row) for row in rot),
                             pose_translation_m=tuple(float(v) for v in trans),
                             conditions=_conditions(balls, scene.camera, light, scene.sensor, scene.optics,
                                                    scene.cut, "dark_ball" in scene.conditions)))
    # one line timing for the rig: every view traces the lines any view needs
    traced = sorted(set().union(*(_traced_lines(v.balls, v.camera) for v in views)))
    ns = max(_subframes(v.balls, v.camera, len(traced)) for v in views)
    return [replace(v, traced_lines=tuple(traced), subframes=ns) for v in views]
