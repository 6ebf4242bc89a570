"""The Cramér-Rao bound of each POV-Ray ball with its limb's own contrast, read off the scene's noise-free render.

    python benchmarks/povray_set/limb_bound.py ROWS.json [ROWS.json ...]   # add it to saved rows

``ballscan precision`` bounds a flat ball at one contrast, which
``render.py`` measures on the ball's centre.  A shaded ball's limb is
dimmer than its centre (a ball darker than the backdrop: darker still), a
textured ball's limb shows whatever the pattern puts there, and it is the
limb that the edges measure.  :func:`limb_bounds` bounds each true ball
with ``ballscan.solve.precision.image_crlb``: every pixel's contrast read off
the clean render (``scenes/clean/NAME.png``), the scene's sensor model
(read, shot and quantisation noise, the column gains' PRNU), the lens's blur
circle at the ball's depth (from the scene's aperture and focus distance)
and only the lines and pixels the image holds (a cut ball's visible part).
The pixels another ball covers are not read.  The backdrop of every line is
the column's level on the lines no ball reaches, times the line's mean lamp
flicker.  A dead or hot column's pixels count as any other's.  It also gives
the share of the limb's information on pixels of the other sign than the
ball's centre (``limb_other_sign``: a bright ball's side in shadow darker
than the backdrop, a football's black panels).

Run on saved rows, it adds ``cr_limb_speed_sigma`` and ``limb_other_sign``
to each ball's row and ``z_cr_limb`` (speed error over it) to each measured
fit.
"""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from render import flicker_mean  # noqa: E402

from ballscan.geometry.camera import line_times, load_camera  # noqa: E402
from ballscan.geometry.motion import BallMotion  # noqa: E402
from ballscan.measure.images import load_image  # noqa: E402
from ballscan.model.averaged import averaged_model  # noqa: E402
from ballscan.model.render import SensorNoise  # noqa: E402
from ballscan.solve.precision import limb_contrast, limb_crlb  # noqa: E402

__all__ = ["LimbBound", "limb_bounds", "limb_speed_sigma", "scene_background"]


def _balls(truth: dict) -> list[dict]:
    return truth["balls"] if "balls" in truth else [truth]


def _motion(ball: dict) -> BallMotion:
    return BallMotion(ball["radius_m"], ball["t_c_s"], tuple(ball["position_m"]), tuple(ball["velocity_mps"]))


def scene_background(truth: dict, clean: np.ndarray, seen: np.ndarray, exposure_s: float, line_rate_hz: float) -> np.ndarray:
    """The backdrop (linear grey) of every line and pixel: each column's level on the lines no ball reaches (``seen`` False), times each line's mean flicker."""
    t = np.arange(clean.shape[0]) / line_rate_hz
    flick = flicker_mean(truth["lighting"], t, exposure_s, int(truth["render"].get("subframes_per_line", 1)))
    free = ~seen
    if free.sum() < 3:
        raise ValueError("fewer than 3 lines without a ball: no backdrop to read")
    level = np.median(clean[free] / flick[free, None], axis=0)
    return flick[:, None] * level[None, :]


@dataclass(frozen=True)
class LimbBound:
    """One true ball's bound of its own limb.

    Attributes
    ----------
    speed_sigma_mps : float
        :func:`ballscan.solve.precision.image_crlb`'s speed sigma.
    other_sign_share : float
        Share of the limb's information on pixels of the other sign than
        the ball's centre (a bright ball's side darker than the backdrop, a
        football's black panels): :meth:`ballscan.solve.precision.LimbContrast.other_sign_share`.
    """

    speed_sigma_mps: float
    other_sign_share: float


def ball_blur_px(truth: dict, focal_px: float, z_m: float) -> float:
    """The blur circle's diameter (pixels) of a ball at depth ``z_m``: the scene's aperture and focus distance (``optics.blur_px`` is the first ball's)."""
    optics = truth.get("optics") or {}
    a, focus = float(optics.get("aperture_m") or 0.0), float(optics.get("focus_m") or 0.0)
    if a <= 0 or focus <= 0:
        return 0.0
    return focal_px * a * abs(z_m - focus) / (z_m * focus)


def limb_speed_sigma(scenes: Path, name: str) -> list[float | None]:
    """Each true ball's speed sigma (m/s) of :func:`limb_bounds` (None where it cannot be had)."""
    return [None if b is None else b.speed_sigma_mps for b in limb_bounds(scenes, name)]


def limb_bounds(scenes: Path, name: str) -> list[LimbBound | None]:
    """Each true ball's :class:`LimbBound` on the scene's clean render (None where it cannot be had)."""
    truth = json.loads((scenes / f"{name}.truth.json").read_text())
    clean_path = scenes / truth["render"]["clean_image"]
    if not clean_path.exists():
        return [None] * len(_balls(truth))
    clean = load_image(clean_path).data / 65535.0
    cam = load_camera(scenes / f"{name}.camera.toml")
    nz = truth["noise"]
    noise = SensorNoise(bits=nz["bits"], white_dn=nz["white_dn"], black_dn=nz["black_dn"], read_dn=nz["read_dn"],
                        full_well_e=nz["full_well_e"], prnu_sigma=nz["prnu_sigma"])
    t = line_times(cam, clean.shape[0])
    motions = [_motion(b) for b in _balls(truth)]
    models = [averaged_model(cam, m.to_params()[None], m.radius_m, t, m.acceleration_mps2) for m in motions]
    seen = np.zeros(clean.shape[0], dtype=bool)
    cover = []
    cols = np.arange(cam.width)
    for me in models:
        p = me.presence[0] > 0
        seen |= np.convolve(p, np.ones(9), mode="same") > 0  # the ball's lines and 4 on either side
        lo, hi = np.nan_to_num(me.left_px[0], nan=np.inf), np.nan_to_num(me.right_px[0], nan=-np.inf)
        cover.append(p[:, None] & (cols[None, :] >= np.floor(lo)[:, None] - 1) & (cols[None, :] <= np.ceil(hi)[:, None] + 1))
    try:
        bg = scene_background(truth, clean, seen, cam.exposure_s, cam.line_rate_hz)
    except ValueError:
        return [None] * len(motions)
    out = []
    for k, (m, ball) in enumerate(zip(motions, _balls(truth))):
        others = np.zeros(clean.shape, dtype=bool)
        for j, c in enumerate(cover):
            if j != k:
                others |= c
        blur = ball_blur_px(truth, cam.focal_px, m.position_m[2])
        cam_k = replace(cam, defocus_px=blur) if blur > 0 else cam
        try:
            lc = limb_contrast(cam_k, m, clean, bg, t, readable=~others)
            centre = ball["precision_inputs"]["ball_level"] - ball["precision_inputs"]["background_level"] if ball.get("precision_inputs") else 1.0
            out.append(LimbBound(float(limb_crlb(cam_k, m, noise, lc).speed_sigma_mps), lc.other_sign_share(centre)))
        except ValueError:
            out.append(None)
    return out


def add_to_rows(rows: list[dict], scenes: Path) -> list[dict]:
    """``cr_limb_speed_sigma`` and ``limb_other_sign`` for each row's ball, ``z_cr_limb`` for each measured fit.

    A scene's rows are its true balls in the truth's order (as ``score.py``
    writes them).

    Raises
    ------
    ValueError
        If a scene's rows are not one per true ball.
    """
    by_scene: dict[str, list[dict]] = {}
    for r in rows:
        by_scene.setdefault(r["scene"], []).append(r)
    for name, rs in by_scene.items():
        truth = json.loads((scenes / f"{name}.truth.json").read_text())
        balls = _balls(truth)
        if len(rs) != len(balls):
            raise ValueError(f"{name}: {len(rs)} rows for {len(balls)} true balls")
        for r, b, tb in zip(rs, limb_bounds(scenes, name), balls):
            r["cr_limb_speed_sigma"] = None if b is None else b.speed_sigma_mps
            r["limb_other_sign"] = None if b is None else b.other_sign_share
            r["fit"].pop("z_cr_limb", None)
            if b is not None and r["fit"].get("measured"):
                r["fit"]["z_cr_limb"] = abs(r["fit"]["speed_err"]) * tb["speed_mps"] / b.speed_sigma_mps
    return rows


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rows", type=Path, nargs="+", help="saved rows of score.py (rewritten in place)")
    ap.add_argument("--scenes", type=Path, default=HERE / "scenes")
    a = ap.parse_args(argv)
    for path in a.rows:
        rows = add_to_rows(json.loads(path.read_text()), a.scenes)
        path.write_text(json.dumps(rows, indent=1) + "\n")
        z = [r["fit"]["z_cr_limb"] for r in rows if r["fit"].get("z_cr_limb") is not None]
        print(f"{path}: {len(z)} measured balls, err / limb CR σ median {float(np.median(z)):.2f}" if z else f"{path}: no measured ball")
    return 0


if __name__ == "__main__":
    sys.exit(main())
