"""Convention audit of the POV-Ray validation set: its geometry against ballscan's own renderer.

    python benchmarks/povray_set/audit.py [--scenes DIR] [--jobs 6] NAME [NAME ...]

For each scene the scene's own POV-Ray source is traced once more with the
ball flat white and self-lit and without backdrop, lamps' shading, bump maps
or focal blur: the assembled image is then the ball's exact sub-pixel
coverage through the whole chain of this set (line and sub-frame times,
pixel footprint, film, principal point, lens distortion).  ballscan's renderer
draws the coverage of the truth file's balls on the scene's camera file.  Per
scan line the half-level crossings of both give the left and right edges;
the table prints the lines each image shows, the median and worst edge
offsets (POV-Ray minus ballscan, pixels) and the ratio of the summed
coverages.  Any convention mismatch between this generator and geometry.md
(time of line i, exposure centred or starting, pixel centre or edge, a
mirrored sensor axis, the principal point, the sign of the distortion, the
truth's time or frame) shows as an offset in pixels or in lines.  The same
half-level edges on the scene's clean (shaded, textured) render show the bias
its lighting and texture put on a threshold edge, and ``ballscan estimate``
on the coverage image (0.1 + 0.5 coverage, 16 bit) shows the estimator on
this set's geometry without shading or texture.

Needs ``povray`` (Debian package); about 10 s a scene.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import render  # noqa: E402


def coverage_source(pov: str) -> str:
    """The scene's POV-Ray source with every ball flat white and self-lit, no backdrop, no focal blur."""
    pov = re.sub(r"texture \{.*?\} \}\n  no_shadow",
                 "texture { pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n  no_shadow", pov, flags=re.S)
    pov = re.sub(r"plane \{ z,.*?finish \{ ambient 1 diffuse 0 \} \}", "", pov, flags=re.S)
    pov = re.sub(r"\n  aperture [^\n]*variance 0", "", pov)
    return pov.replace("ambient_light rgb FL", "ambient_light rgb 1")


def pov_coverage(scenes: Path, name: str, work: Path, jobs: int) -> np.ndarray:
    """Trace the coverage variant of one scene; its assembled image (0..1, lines x pixels)."""
    truth = json.loads((scenes / f"{name}.truth.json").read_text())
    sc = render.scene_of(truth)
    (work / f"{name}.pov").write_text(coverage_source((scenes / "src" / f"{name}.pov").read_text()))
    shutil.copy(scenes / "src" / f"{name}.ini", work / f"{name}.ini")
    frames = work / "frames"
    frames.mkdir(exist_ok=True)
    cmds = render.povray_jobs(name, work, frames, int(truth["render"]["frames"]), 40)
    with ThreadPoolExecutor(jobs) as pool:
        codes = list(pool.map(lambda c: subprocess.run(c, cwd=work, capture_output=True).returncode, cmds))
    if any(codes):
        raise RuntimeError(f"{name}: povray failed ({codes})")
    cam = {"width": sc.camera.width, "focal_px": sc.camera.focal_px, "principal_px": sc.camera.principal_px,
           "line_rate_hz": sc.camera.line_rate_hz, "exposure_s": sc.camera.exposure_s, "k1": sc.camera.k1,
           "k2": sc.camera.k2}
    truth["lighting"] = dict(truth["lighting"], flicker_hz=0.0)
    return render.clean_image(truth, cam, frames, sc.subframes, list(sc.traced_lines))


def ballscan_coverage(scenes: Path, name: str) -> np.ndarray:
    """ballscan's coverage image of the truth file's balls on the scene's camera file."""
    from ballscan.geometry.camera import load_camera
    from ballscan.geometry.motion import BallMotion
    from ballscan.model.render import render as bs_render

    truth = json.loads((scenes / f"{name}.truth.json").read_text())
    balls = truth["balls"] if "balls" in truth else [truth]
    motions = [BallMotion(b["radius_m"], b["t_c_s"], tuple(b["position_m"]), tuple(b["velocity_mps"])) for b in balls]
    cam = load_camera(scenes / f"{name}.camera.toml")
    return np.asarray(bs_render(cam, motions, int(truth["image_shape"][0]), noise="none").coverage, float)


def half_level_edges(d: np.ndarray) -> dict[int, tuple[float, float]]:
    """Per line, the left and right crossings (pixels) of half the level two pixels inside the ball's run.

    ``d`` is the ball's signed difference from the background; lines whose run touches the sensor's
    ends are skipped.
    """
    a = np.abs(d)
    thr = 0.08 * np.percentile(a.max(axis=1), 95)
    out = {}
    for i, row in enumerate(a):
        run = np.flatnonzero(row > thr)
        if run.size < 3 or run[0] < 2 or run[-1] > row.size - 3:
            continue
        k = max(1, min(3, run.size // 3))

        def cross(j: int, step: int) -> float:
            level = 0.5 * row[j]
            while 0 < j < row.size - 1 and row[j] >= level:
                j -= step
            return j + step * (level - row[j]) / (row[j + step] - row[j] + 1e-300)

        out[i] = (cross(run[0] + k, 1), cross(run[-1] - k, -1))
    return out


def offsets(a: dict, b: dict) -> tuple[np.ndarray, np.ndarray]:
    """Left and right edge offsets ``a - b`` (pixels) on the lines both show."""
    common = sorted(set(a) & set(b))
    return (np.array([a[i][0] - b[i][0] for i in common]), np.array([a[i][1] - b[i][1] for i in common]))


def estimate_on(image: np.ndarray, scenes: Path, name: str, work: Path) -> str:
    """``ballscan estimate`` on a coverage image: speed error (%), transverse speed error (%), V.z est/true."""
    from ballscan.model.render import write_image

    path = work / f"{name}.cov16.png"
    write_image(path, np.rint((0.1 + 0.5 * np.clip(image, 0, 1)) * 65535).astype(np.uint16))
    truth = json.loads((scenes / f"{name}.truth.json").read_text())
    tb = (truth["balls"] if "balls" in truth else [truth])[0]
    p = subprocess.run([shutil.which("ballscan") or "ballscan", "estimate", str(path), "--camera",
                        str(scenes / f"{name}.camera.toml"), "--radius", repr(tb["radius_m"]), "--json"],
                       capture_output=True, text=True)
    try:
        est = json.loads(p.stdout)["balls"]
    except (json.JSONDecodeError, KeyError):
        return "estimate failed"
    if not est:
        return "no ball found"
    e = min(est, key=lambda e: abs((e.get("t_c_s") or 0) - tb["t_c_s"]))
    if e.get("speed_mps") is None:
        return "speed undetermined"
    v = tb["velocity_mps"]
    vt = math.hypot(v[0], v[1])
    return (f"{100 * (e['speed_mps'] - tb['speed_mps']) / tb['speed_mps']:+.3f} / "
            f"{100 * (e['speed_transverse_mps'] - vt) / vt:+.3f} / {e['velocity_mps'][2]:+.3g} ({v[2]:+.3g})")


def audit(scenes: Path, name: str, work: Path, jobs: int) -> str:
    """One table row."""
    pov = pov_coverage(scenes, name, work, jobs)
    bs = ballscan_coverage(scenes, name)
    ep, eb = half_level_edges(pov), half_level_edges(bs)
    lo, hi = offsets(ep, eb)
    truth = json.loads((scenes / f"{name}.truth.json").read_text())
    sc = render.scene_of(truth)
    from PIL import Image

    clean = np.asarray(Image.open(scenes / "clean" / f"{name}.png"), float) / 65535
    t = np.arange(clean.shape[0]) / sc.camera.line_rate_hz
    flick = render.flicker_mean(truth["lighting"], t, sc.camera.exposure_s, sc.subframes)
    shaded = clean - (clean[0] / flick[0])[None, :] * flick[:, None]
    s_lo, s_hi = offsets(half_level_edges(shaded), eb)
    span = lambda e: f"{min(e)}-{max(e)}" if e else "-"  # noqa: E731
    med = lambda x: f"{np.median(x):+.3f}" if x.size else "-"  # noqa: E731
    worst = lambda x: f"{np.abs(x).max():.2f}" if x.size else "-"  # noqa: E731
    return (f"| {name} | {span(ep)} | {span(eb)} | {med(lo)} / {med(hi)} | {worst(lo)} / {worst(hi)} | "
            f"{pov.sum() / bs.sum():.4f} | {med(s_lo)} / {med(s_hi)} | {estimate_on(pov, scenes, name, work)} |")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="+", help="scene names (NAME.truth.json in --scenes)")
    ap.add_argument("--scenes", type=Path, default=HERE / "scenes")
    ap.add_argument("--jobs", type=int, default=6, help="povray processes at once")
    a = ap.parse_args(argv)
    if shutil.which("povray") is None:
        print("audit.py: povray is not installed (Debian package povray)", file=sys.stderr)
        return 2
    print("| scene | lines (POV-Ray coverage) | lines (ballscan) | edge offset median L / R px | worst L / R px"
          " | coverage sum ratio | shaded half-level offset L / R px | estimate on coverage: speed % / transverse %"
          " / V.z (true) |")
    print("|" + "---|" * 8)
    with tempfile.TemporaryDirectory(prefix="povaudit") as tmp:
        for name in a.names:
            print(audit(a.scenes.resolve(), name, Path(tmp), a.jobs), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
