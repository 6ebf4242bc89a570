"""``ballscan simulate``: render a scene and write image, camera file and truth.

Writes ``NAME.png``, ``NAME.camera.toml`` and ``NAME.truth.json`` in the
formats of geometry.md.  The scene comes from a camera file plus motion
arguments, or from a named preset whose values the arguments override.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, replace
from pathlib import Path

from ..geometry.camera import load_camera, save_camera
from ..geometry.motion import BallMotion
from .presets import get_preset
from ..model.render import Appearance, SensorNoise, render, truth_dict, write_image

__all__ = ["SimulationRequest", "run_simulation", "parse_ball_spec"]


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


def run_simulation(req: SimulationRequest) -> list[Path]:
    """Render the requested scene and write its three files; returns their paths."""
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
    if req.t_c_s is not None:
        t_c = req.t_c_s
    elif motion is not None and req.n_lines is None:
        t_c = motion.t_c_s
    else:
        t_c = 0.5 * (n_lines - 1) / camera.line_rate_hz
    if not n_lines or n_lines < 2:
        raise ValueError(f"--lines: must be at least 2, got {n_lines}")
    motion = BallMotion(radius, t_c, position, velocity, tuple(camera.gravity_camera_mps2()))
    changes = {"shading": req.shading}
    if req.texture != "none" or req.preset is None:
        changes["texture"] = req.texture
    if req.ball_level is not None:
        changes["ball_level"] = req.ball_level
    app = replace(app, **changes)
    balls = [(motion, app)] + [(parse_ball_spec(s), app) for s in req.extra_balls]
    for k, (b, _) in enumerate(balls):
        # a ball that reaches the plane z = 0 is behind or beside the camera:
        # nothing of it would image, and an empty picture must not pass for a scene
        if not b.position_m[2] > b.radius_m:
            what = "--position" if k == 0 else f"--add-ball {k}"
            raise ValueError(f"{what}: the ball's centre must be in front of the camera by more than its radius (z = {b.position_m[2]!r} m)")
    if req.noise == "none":
        noise = SensorNoise.none(req.bits or 16)
    elif req.noise == "default":
        noise = SensorNoise() if req.bits is None else SensorNoise(bits=req.bits, white_dn=0.9 * (2**req.bits - 1))
    else:
        raise ValueError(f"--noise: expected 'default' or 'none', got {req.noise!r}")
    rendered = render(camera, balls, n_lines, background_level=req.background_level, noise=noise, seed=req.seed)
    out = Path(req.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    png = out.with_name(out.name + ".png")
    cam_path = out.with_name(out.name + ".camera.toml")
    truth_path = out.with_name(out.name + ".truth.json")
    write_image(png, rendered.image)
    save_camera(camera, cam_path, comment=f"written by ballscan simulate for {png.name}")
    truth = truth_dict([b for b, _ in balls])
    truth["image_shape"] = list(rendered.image.shape)
    truth["noise"] = {"bits": noise.bits, "read_dn": noise.read_dn, "seed": req.seed} if req.noise != "none" else None
    truth_path.write_text(json.dumps(truth, indent=2))
    return [png, cam_path, truth_path]
