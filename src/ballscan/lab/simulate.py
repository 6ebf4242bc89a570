"""``ballscan simulate``: render a scene and write image, camera file and truth.

Writes ``NAME.png``, ``NAME.camera.toml`` and ``NAME.truth.json`` in the
formats of geometry.md.  The scene comes from a camera file plus motion
arguments, or from a named preset whose values the arguments override.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ..geometry.camera import LineScanCamera, load_camera, save_camera
from ..geometry.motion import BallMotion
from ..model.render import Appearance, SensorNoise, render, truth_dict, write_image
from ..outputs import atomic_write_text, check_not_symlink
from .presets import get_preset

__all__ = ["MAX_IMAGE_PIXELS", "SimulationRequest", "run_simulation", "parse_ball_spec"]


@dataclass(frozen=True)
class SimulationRequest:
    """What ``ballscan simulate`` was asked for (units in the names; None = not given)."""

    out: Path
    camera_path: Path | None = None
    preset: str | None = None
    radius_m: float | None = None
    position_m: tuple[float, float, float] | None = None
    velocity_mps: tuple[float, float, float] | None = None
    t_c_s: float | None = None
    n_lines: int | None = None
    noise: str = "default"
    seed: int = 0
    bits: int | None = None
    texture: str = "none"
    ball_level: float | None = None
    background_level: float = 0.1
    shading: bool = True
    extra_balls: tuple[str, ...] = ()
    force: bool = False


def parse_ball_spec(spec: str) -> BallMotion:
    """Parse ``'R;X,Y,Z;VX,VY,VZ;T_C'`` (metres, m/s, seconds) into a motion."""
    parts = spec.split(";")
    if len(parts) != 4:
        raise ValueError(f"--add-ball: expected 'R;X,Y,Z;VX,VY,VZ;T_C', got {spec!r}")
    try:
        r = float(parts[0])
        pos = tuple(float(v) for v in parts[1].split(","))
        vel = tuple(float(v) for v in parts[2].split(","))
        tc = float(parts[3])
    except ValueError:
        raise ValueError(f"--add-ball: not numbers in {spec!r}") from None
    return BallMotion(r, tc, pos, vel)


#: The largest image ``simulate`` renders in memory, in pixels (lines x width): its float
#: planes take about 40 bytes a pixel.  Longer scenes are rendered as a stream
#: (``--stream``), block by block.
MAX_IMAGE_PIXELS = 2**25
#: Far beyond any ball (a rifle bullet flies at 1 km/s) and any scene: numbers past these
#: would overflow the renderer's arithmetic, not describe a scene.
MAX_SPEED_MPS = 1e5
MAX_DISTANCE_M = 1e5
MAX_TIME_S = 1e6


def run_simulation(req: SimulationRequest) -> list[Path]:
    """Render the requested scene and write its three files; returns their paths.

    Raises
    ------
    ValueError
        A missing or invalid argument, an image over :data:`MAX_IMAGE_PIXELS`,
        or a scene in which some ball never reaches the image (off the
        sensor, before or after the image's lines, too small, too fast or
        without contrast to change a single pixel by one DN), naming the
        argument.
    ballscan.outputs.OutputFileError
        An output is a symbolic link (without ``force``) or cannot be written.
    """
    camera, balls, n_lines, noise = _scene(req)
    out = Path(req.out)
    png = out.with_name(out.name + ".png")
    cam_path = out.with_name(out.name + ".camera.toml")
    truth_path = out.with_name(out.name + ".truth.json")
    for p in (png, cam_path, truth_path):
        check_not_symlink(p, req.force)
    rendered = render(camera, balls, n_lines, background_level=req.background_level, noise=noise, seed=req.seed)
    if len(balls) == 1:
        _check_reaches_image(camera, balls[0][0], rendered, noise, "--position")
    truth = truth_dict([b for b, _ in balls])
    truth["image_shape"] = list(rendered.image.shape)
    truth["noise"] = {"bits": noise.bits, "read_dn": noise.read_dn, "seed": req.seed} if req.noise != "none" else None
    try:
        truth_text = json.dumps(truth, indent=2, allow_nan=False)
    except ValueError:
        raise ValueError("simulate: the scene's truth holds a number that is not finite (an overflowing speed?)") from None
    out.parent.mkdir(parents=True, exist_ok=True)
    write_image(png, rendered.image, force=req.force)
    save_camera(camera, cam_path, comment=f"written by ballscan simulate for {png.name}", force=req.force)
    atomic_write_text(truth_path, truth_text, force=req.force)
    return [png, cam_path, truth_path]


def _scene(req: SimulationRequest) -> tuple[LineScanCamera, list, int, SensorNoise]:
    """The camera, the balls with their appearance, the number of lines and the sensor of a request, each checked."""
    if req.preset is None and req.camera_path is None:
        raise ValueError("simulate: give --camera CAMERA.toml or --preset NAME")
    if req.preset is not None:
        p = get_preset(req.preset)
        camera, motion, n_lines, app = p.camera, p.motion, p.n_lines, p.appearance
        if req.camera_path is not None:
            camera = load_camera(req.camera_path)
    else:
        camera = load_camera(req.camera_path)
        missing = [n for n, v in (("--radius", req.radius_m), ("--position", req.position_m), ("--velocity", req.velocity_mps), ("--t-c", req.t_c_s), ("--lines", req.n_lines)) if v is None]
        if missing:
            raise ValueError("simulate: without --preset these are required: " + ", ".join(missing))
        motion, n_lines, app = None, None, Appearance()
    radius = req.radius_m if req.radius_m is not None else motion.radius_m
    position = req.position_m if req.position_m is not None else motion.position_m
    velocity = req.velocity_mps if req.velocity_mps is not None else motion.velocity_mps
    n_lines = req.n_lines if req.n_lines is not None else n_lines
    if not n_lines or n_lines < 2:
        raise ValueError(f"--lines: must be at least 2, got {n_lines}")
    if n_lines * camera.width > MAX_IMAGE_PIXELS:
        raise ValueError(
            f"--lines: {n_lines} lines of {camera.width} pixels is more than {MAX_IMAGE_PIXELS} pixels in memory; "
            "render a longer recording with --stream FILE"
        )
    if req.t_c_s is not None:
        t_c = req.t_c_s
    elif motion is not None and req.n_lines is None:
        t_c = motion.t_c_s
    else:
        t_c = 0.5 * (n_lines - 1) / camera.line_rate_hz
    motion = BallMotion(radius, t_c, position, velocity, tuple(camera.gravity_camera_mps2()))
    changes = {"shading": req.shading}
    if req.texture != "none" or req.preset is None:
        changes["texture"] = req.texture
    if req.ball_level is not None:
        changes["ball_level"] = req.ball_level
    app = replace(app, **changes)
    balls = [(motion, app)] + [(parse_ball_spec(s), app) for s in req.extra_balls]
    for k, (b, _) in enumerate(balls):
        _check_motion(b, k)
    if req.bits is not None and (isinstance(req.bits, bool) or req.bits not in (8, 12, 16)):
        raise ValueError(f"--bits: expected 8, 12 or 16, got {req.bits!r}")
    if req.noise == "none":
        noise = SensorNoise.none(req.bits or 16)
    elif req.noise == "default":
        noise = SensorNoise() if req.bits is None else SensorNoise(bits=req.bits, white_dn=0.9 * (2**req.bits - 1))
    else:
        raise ValueError(f"--noise: expected 'default' or 'none', got {req.noise!r}")
    if len(balls) > 1:
        for k, (b, a) in enumerate(balls):
            alone = render(camera, [(b, a)], n_lines, background_level=req.background_level, noise=None)
            _check_reaches_image(camera, b, alone, noise, "--position" if k == 0 else f"--add-ball {k}")
    return camera, balls, n_lines, noise


def _check_motion(b: BallMotion, k: int) -> None:
    """A ball the renderer can draw: in front of the camera, crossing the viewing plane, its numbers within reason.

    ``k`` is the ball's place on the command line: 0 for the ball of ``--position``,
    ``--velocity``, ``--radius`` and ``--t-c``, k for the k-th ``--add-ball``; an error
    names the option that holds the wrong number.
    """

    def option(name: str) -> str:
        return name if k == 0 else f"--add-ball {k}"

    if not b.radius_m <= MAX_DISTANCE_M:
        raise ValueError(f"{option('--radius')}: a ball {MAX_DISTANCE_M:g} m or more wide is beyond any scene")
    # a ball that reaches the plane z = 0 is behind or beside the camera:
    # nothing of it would image, and an empty picture must not pass for a scene
    if not b.position_m[2] > b.radius_m:
        raise ValueError(f"{option('--position')}: the ball's centre must be in front of the camera by more than its radius (z = {b.position_m[2]!r} m)")
    if b.velocity_mps[0] == 0.0:
        raise ValueError(f"{option('--velocity')}: VX must be non-zero: a ball that does not move across the viewing plane never crosses it")
    speed = math.hypot(*b.velocity_mps)
    if not speed <= MAX_SPEED_MPS:
        raise ValueError(f"{option('--velocity')}: a speed of {speed:.7g} m/s is beyond any scene (at most {MAX_SPEED_MPS:g} m/s)")
    if not max(abs(v) for v in b.position_m) <= MAX_DISTANCE_M:
        raise ValueError(f"{option('--position')}: a ball {MAX_DISTANCE_M:g} m or more away is beyond any scene")
    if not abs(b.t_c_s) <= MAX_TIME_S:
        raise ValueError(f"{option('--t-c')}: t_c = {b.t_c_s:g} s is beyond any recording ({MAX_TIME_S:g} s)")


def _check_reaches_image(camera: LineScanCamera, b: BallMotion, rendered, noise: SensorNoise, what: str) -> None:
    """Refuse a ball that changes no pixel of ``rendered`` by one DN, saying why (its time, its place, its size or its contrast)."""
    change = np.abs(rendered.clean - rendered.background_level) * noise.white_dn
    change_dn = float(np.max(change))
    # seen against its columns' background: some column shows the ball (a change of a DN or
    # more) on one line and the background (under half a DN, lost in rounding) on another
    if np.any((change >= 1.0).any(axis=0) & (change < 0.5).any(axis=0)):
        return
    t = rendered.t_lines_s
    u = camera.principal_px + camera.focal_px * b.position_m[1] / b.position_m[2]
    half_px = camera.focal_px * b.radius_m / b.position_m[2]
    if not float(np.max(rendered.coverage)) > 0.0:
        if not t[0] - 1.0 / camera.line_rate_hz <= b.t_c_s <= t[-1] + 1.0 / camera.line_rate_hz and not _seen_at_ends(camera, b, t):
            why = f"it crosses the viewing plane at t_c = {b.t_c_s:g} s, outside the image's lines ({t[0]:g} to {t[-1]:g} s)"
        elif not -half_px - 0.5 <= u <= camera.width - 0.5 + half_px:
            why = f"its centre images at pixel {u:.4g}, off the sensor's pixels 0 to {camera.width - 1}"
        else:
            why = "it is too small, too far or too fast to cover any pixel during a line's exposure"
    elif change_dn >= 1.0:
        why = "it covers every line of its columns, a stripe with no background to see it against (more lines, or a faster crossing)"
    else:
        why = f"it changes no pixel by one DN (at most {change_dn:.2g} DN): too small, too faint or without contrast against the background"
    raise ValueError(f"{what}: the ball never reaches the image: {why}")


def _seen_at_ends(camera: LineScanCamera, b: BallMotion, t: np.ndarray) -> bool:
    """Whether the ball's sphere meets the viewing plane at the first or last line (its crossing outside the lines, its body across them)."""
    for ti in (t[0], t[-1]):
        if abs(b.centre(np.array([ti]))[0, 0]) < b.radius_m:
            return True
    return False
