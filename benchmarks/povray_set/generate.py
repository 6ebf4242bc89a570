"""Write the POV-Ray validation scenes: .pov + .ini (to render), camera .toml and truth .json.

    python benchmarks/povray_set/generate.py [--first 0] [--count 200] [--out DIR]
    python benchmarks/povray_set/generate.py --seeds 7,9 --rig 0,90,30 --out DIR   # two-camera rigs
    python benchmarks/povray_set/generate.py --uniform --first 0 --count 40        # uniform balls, pu####
    python benchmarks/povray_set/generate.py --cut --first 3000 --count 120 --out benchmarks/povray_set/cut

Each scene is drawn from its seed (``scene.draw_scene``; even seeds are the
tuning half, odd seeds the report half).  Writes ``DIR/src/NAME.pov``,
``DIR/src/NAME.ini``, ``DIR/NAME.camera.toml`` and ``DIR/NAME.truth.json``;
``render.py`` traces the frames and writes ``DIR/NAME.png`` (the noisy image)
and ``DIR/clean/NAME.png`` (noise-free linear grey x 65535), and completes the
truth with the measured contrast.  With ``--rig A,B,..`` each seed is seen by
cameras turned about the lane's axis by those angles (degrees), each view a
scene ``NAME_aAAA`` whose camera file has the world -> camera ``[pose]`` (the
world frame is the camera frame at angle 0).  With ``--cut`` the seeds from
``--first`` on are drawn until ``--count`` scenes whose first ball is cut
(by a sensor end or by the first or last line) and large and long enough to
be measured from its visible part (``--min-radius-px``, ``--min-lines``)
are found: the supplement of cut balls (``cut/``).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from dataclasses import asdict, replace
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from pov import film_range, frame_count, ini_source, pov_source, samples_along, SAMPLES_ACROSS  # noqa: E402
from scene import Scene, draw_scene, rig_views  # noqa: E402

DEFAULT_OUT = HERE / "scenes"


def ball_truth(ball) -> dict:
    """geometry.md's truth keys of one ball, plus its direction angles and texture."""
    v = ball.velocity_mps
    speed = math.dist((0, 0, 0), v)
    return {
        "radius_m": ball.radius_m, "t_c_s": ball.t_c_s, "position_m": list(ball.position_m),
        "velocity_mps": list(v), "speed_mps": speed,
        "direction_deg": {"psi_y": math.degrees(math.atan2(v[1], abs(v[0]))),
                          "psi_z": math.degrees(math.atan2(v[2], abs(v[0])))},
        "texture": {"kind": ball.kind, "rgb": list(ball.rgb), "albedo_scale": ball.albedo_scale, "phong": ball.phong,
                    "orientation_deg_xyz": list(ball.orientation_deg), "spin_axis": list(ball.spin_axis),
                    "spin_rps": ball.spin_rps},
    }


def scene_truth(scene: Scene) -> dict:
    """The truth file: one ball's keys at the top level, or ``balls`` for several; scene settings beside."""
    balls = [ball_truth(b) for b in sorted(scene.balls, key=lambda b: b.t_c_s)]
    out = dict(balls[0]) if len(balls) == 1 else {"balls": balls}
    lo, hi = film_range(scene)
    out.update({
        "scene": scene.name, "seed": scene.seed, "split": scene.split, "kind": scene.balls[0].kind,
        "conditions": list(scene.conditions), "cut": scene.cut,
        "image": f"{scene.name}.png", "camera": f"{scene.name}.camera.toml",
        "image_shape": [scene.camera.n_lines, scene.camera.width],
        "frame": "camera frame of geometry.md; metres, seconds",
        "lighting": {k: v for k, v in asdict(scene.light).items()},
        "optics": asdict(scene.optics),
        "lens": {"k1": scene.camera.k1, "k2": scene.camera.k2,
                 "applied": "POV-Ray traces a pin-hole film over the undistorted y/z range; each pixel averages "
                            "the film samples between its distorted edges"},
        "noise": {**asdict(scene.sensor),
                  "model": "DN = black_dn + Poisson(Y*g_j*full_well_e)*white_dn/full_well_e + N(0, read_dn^2), "
                           "rounded and clipped; Y = linear grey (Rec.601 luma of linear RGB); g_j = 1 + "
                           "prnu_sigma*N(0,1) per column; a dead column reads black_dn + N(0, read_dn^2), a hot "
                           "column hot_dn + N(0, read_dn^2)"},
        "render": {"renderer": "POV-Ray 3.7 (povray), one frame per (line, sub-frame)",
                   "samples_along_line_per_px": samples_along(scene), "samples_across_line_per_px": SAMPLES_ACROSS,
                   "subframes_per_line": scene.subframes, "subframe_times": "t_i + tau*((k+0.5)/NS - 0.5)",
                   "frames": frame_count(scene), "lines_traced": [scene.traced_lines[0], scene.traced_lines[-1]],
                   "film_undistorted_n": [lo, hi], "pov_source": f"src/{scene.name}.pov"},
    })
    if scene.pose_rotation is not None:
        out["pose"] = {"rotation": [list(r) for r in scene.pose_rotation], "translation": list(scene.pose_translation_m)}
    return out


def camera_toml(scene: Scene) -> str:
    """The camera file of geometry.md (with the crossing sign unstated, as a user would have it)."""
    cam = scene.camera
    text = (f"# validation scene {scene.name} (seed {scene.seed})\n"
            f"width = {cam.width}\nfocal_px = {cam.focal_px!r}\nprincipal_px = {cam.principal_px!r}\n"
            f"line_rate_hz = {cam.line_rate_hz!r}\nexposure_s = {cam.exposure_s!r}\n"
            f"k1 = {cam.k1!r}\nk2 = {cam.k2!r}\n")
    if scene.pose_rotation is not None:
        rows = ", ".join("[" + ", ".join(repr(v) for v in r) + "]" for r in scene.pose_rotation)
        text += f"\n[pose]\nrotation = [{rows}]\ntranslation = [{', '.join(repr(v) for v in scene.pose_translation_m)}]\n"
    return text


def write_scene(scene: Scene, out: Path) -> None:
    """Write the scene's source, camera file and truth under ``out``."""
    (out / "src").mkdir(parents=True, exist_ok=True)
    src = out / "src" / f"{scene.name}.pov"
    text = pov_source(scene)
    if (out / f"{scene.name}.png").exists() and src.exists() and src.read_text() == text:
        return  # rendered from this very source: keep its image and completed truth
    (out / f"{scene.name}.png").unlink(missing_ok=True)
    src.write_text(text)
    (out / "src" / f"{scene.name}.ini").write_text(ini_source(scene))
    (out / f"{scene.name}.camera.toml").write_text(camera_toml(scene))
    (out / f"{scene.name}.truth.json").write_text(json.dumps(scene_truth(scene), indent=1) + "\n")


def uniform_scene(scene: Scene) -> Scene:
    """The scene with plain balls lit by ambient light alone (no shading, highlight or second lamp), named ``pu####``.

    The ball the paper's model describes (a uniform disc) in the set's
    independent rendering and sensor model: its motion, camera, optics,
    flicker and sensor are the seed's.
    """
    balls = tuple(replace(b, kind="plain", phong=0.0) for b in scene.balls)
    light = replace(scene.light, ambient=1.0, second_dir=None, second_intensity=0.0)
    tags = tuple(t for t in scene.conditions if t != "second_lamp") + ("uniform",)
    return replace(scene, name=f"pu{scene.seed:04d}", balls=balls, light=light, conditions=tags)


def scenes_for(seeds: list[int], rig: tuple[float, ...] | None, uniform: bool = False) -> list[Scene]:
    """The scenes of ``seeds`` (every view of each when ``rig`` gives camera angles; with ``uniform`` their :func:`uniform_scene`)."""
    out = []
    for s in seeds:
        sc = draw_scene(s)
        if uniform:
            sc = uniform_scene(sc)
        out.extend(rig_views(sc, rig) if rig else [sc])
    return out


def crossing(scene: Scene) -> tuple[float, float]:
    """The first ball's radius (px) and the lines its whole passage would span (``line_rate 2 R / |V.x|``)."""
    b, cam = scene.balls[0], scene.camera
    return cam.focal_px * b.radius_m / b.position_m[2], cam.line_rate_hz * 2.0 * b.radius_m / abs(b.velocity_mps[0])


def cut_seeds(first: int, count: int, min_radius_px: float, min_lines: float, limit: int = 100_000) -> list[int]:
    """The first ``count`` seeds from ``first`` on whose scene's first ball is cut, at least ``min_radius_px`` in radius and ``min_lines`` long."""
    found = []
    for s in range(first, first + limit):
        sc = draw_scene(s)
        if sc.cut == "none":
            continue
        r_px, lines = crossing(sc)
        if r_px >= min_radius_px and lines >= min_lines:
            found.append(s)
            if len(found) == count:
                return found
    raise SystemExit(f"generate: only {len(found)} cut scenes in seeds {first}-{first + limit - 1}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--first", type=int, default=0)
    ap.add_argument("--count", type=int, default=200)
    ap.add_argument("--seeds", help="comma-separated seeds (instead of --first/--count)")
    ap.add_argument("--rig", help="comma-separated camera angles about the lane's axis, degrees")
    ap.add_argument("--uniform", action="store_true", help="plain balls in ambient light alone (uniform discs), named pu####")
    ap.add_argument("--cut", action="store_true", help="only scenes with a cut ball of --min-radius-px and --min-lines, scanning seeds from --first")
    ap.add_argument("--min-radius-px", type=float, default=8.0)
    ap.add_argument("--min-lines", type=float, default=80.0)
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT)
    a = ap.parse_args(argv)
    if a.cut:
        seeds = cut_seeds(a.first, a.count, a.min_radius_px, a.min_lines)
    else:
        seeds = [int(s) for s in a.seeds.split(",")] if a.seeds else list(range(a.first, a.first + a.count))
    rig = tuple(float(x) for x in a.rig.split(",")) if a.rig else None
    scenes = scenes_for(seeds, rig, a.uniform)
    for sc in scenes:
        write_scene(sc, a.out)
    frames = sum(frame_count(sc) for sc in scenes)
    print(f"{len(scenes)} scenes written to {a.out}: {frames} frames to render")
    return 0


if __name__ == "__main__":
    sys.exit(main())
