"""Render the POV-Ray validation scenes and assemble their line images (on demand, needs ``povray``).

    python benchmarks/povray_set/render.py [--scenes DIR] [--only GLOB] [--jobs 16] [--chunk 40]

Runs ``nice -n 19 povray`` over frame ranges of every scene whose image is
missing, ``--jobs`` processes at once (POV-Ray idles about 0.2 s per frame, so
many processes share two cores well), then assembles each scene: the
sub-frames of a line are averaged (the exposure), the 4 film rows (the pixel's
footprint across the line), the grey is the Rec. 601 luma of linear RGB, and
each pixel averages the film samples between its distorted edges (geometry.md's
lens model).  Lines no ball reaches get the background frame scaled by the
line's mean lamp flicker.  Sensor noise is then drawn from the scene's seed.
Frames are kept under ``DIR/frames`` only while a scene is incomplete.
"""

from __future__ import annotations

import argparse
import fnmatch
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from pov import undistort  # noqa: E402
from scene import draw_scene, rig_views  # noqa: E402

LUMA = np.array([0.299, 0.587, 0.114])


def read_ppm16(path: Path) -> np.ndarray:
    """A binary 16-bit PPM (POV-Ray's ``Output_File_Type=P``) as float RGB in [0, 1], shape (H, W, 3)."""
    raw = path.read_bytes()
    toks, i = [], 0
    while len(toks) < 4:
        while raw[i:i + 1].isspace():
            i += 1
        if raw[i:i + 1] == b"#":
            i = raw.index(b"\n", i) + 1
            continue
        j = i
        while not raw[j:j + 1].isspace():
            j += 1
        toks.append(raw[i:j])
        i = j
    w, h, top = int(toks[1]), int(toks[2]), int(toks[3])
    dtype = ">u2" if top > 255 else "u1"
    data = np.frombuffer(raw, dtype=dtype, offset=i + 1, count=w * h * 3)
    return data.reshape(h, w, 3).astype(float) / top


def scene_of(truth: dict):
    """Re-draw the scene a truth file was written from (its seed, and its rig view if it has a pose)."""
    sc = draw_scene(int(truth["seed"]))
    m = re.search(r"_a(\d{3})$", truth["scene"])
    if m:
        sc = rig_views(sc, (float(m.group(1)),))[0]
    return sc


def povray_jobs(name: str, src: Path, frames_dir: Path, n_frames: int, chunk: int) -> list[list[str]]:
    """Command lines rendering the missing frames of one scene, ``chunk`` frames each."""
    have = {int(m.group(1)) for p in frames_dir.glob(f"{name}_*.ppm") if (m := re.search(r"_(\d+)\.ppm$", p.name))}
    jobs = []
    for a in range(0, n_frames, chunk):
        b = min(n_frames, a + chunk) - 1
        if all(k in have for k in range(a, b + 1)):
            continue
        jobs.append(["nice", "-n", "19", "povray", str(src / f"{name}.ini"), f"+I{src / name}.pov",
                     f"+O{frames_dir / name}_", f"+SF{a}", f"+EF{b}", "+WT1", "-D", "-GA"])
    return jobs


def flicker_mean(light: dict, t_s: np.ndarray, tau_s: float, ns: int) -> np.ndarray:
    """Mean lamp power over each line's sub-frame times (1 without flicker)."""
    if not light["flicker_hz"]:
        return np.ones_like(t_s)
    k = (np.arange(ns) + 0.5) / ns - 0.5
    tt = t_s[:, None] + tau_s * k[None, :]
    w = 2 * math.pi * light["flicker_hz"]
    return (1 + light["flicker_depth"] * np.sin(w * tt + light["flicker_phase_rad"])).mean(axis=1)


def pixel_weights(cam: dict, film_n: tuple[float, float], n_samples: int) -> tuple[np.ndarray, np.ndarray]:
    """Film-sample coordinates (in samples) of each pixel's distorted edges u = j -+ 0.5."""
    u = np.arange(cam["width"] + 1) - 0.5
    nd = (u - cam["principal_px"]) / cam["focal_px"]
    n = np.array([undistort(float(v), cam["k1"], cam["k2"]) for v in nd])
    s = (n - film_n[0]) / (film_n[1] - film_n[0]) * n_samples
    return s[:-1], s[1:]


def warp(fine: np.ndarray, s_lo: np.ndarray, s_hi: np.ndarray) -> np.ndarray:
    """Each pixel's mean of the piecewise-constant film samples between its edges (rows: lines)."""
    cum = np.concatenate([np.zeros((fine.shape[0], 1)), np.cumsum(fine, axis=1)], axis=1)
    grid = np.arange(fine.shape[1] + 1)
    lo = np.stack([np.interp(s_lo, grid, row) for row in cum])
    hi = np.stack([np.interp(s_hi, grid, row) for row in cum])
    return (hi - lo) / (s_hi - s_lo)[None, :]


def clean_image(truth: dict, cam: dict, frames_dir: Path, ns: int, traced: list[int]) -> np.ndarray:
    """The noise-free image (linear grey, 0..1) from the rendered frames."""
    name = truth["scene"]
    files = {int(m.group(1)): p for p in frames_dir.glob(f"{name}_*.ppm") if (m := re.search(r"_(\d+)\.ppm$", p.name))}

    def line(frames: range) -> np.ndarray:
        acc = sum(read_ppm16(files[k]) for k in frames) / len(frames)
        return (acc @ LUMA).mean(axis=0)  # film rows: the footprint across the line

    bg = line(range(len(traced) * ns, len(traced) * ns + 1))
    n_lines = truth["image_shape"][0]
    t = np.arange(n_lines) / cam["line_rate_hz"]
    fine = bg[None, :] * flicker_mean(truth["lighting"], t, cam["exposure_s"], ns)[:, None]
    for k, i in enumerate(traced):
        fine[i] = line(range(k * ns, (k + 1) * ns))
    s_lo, s_hi = pixel_weights(cam, tuple(truth["render"]["film_undistorted_n"]), fine.shape[1])
    return warp(fine, s_lo, s_hi)


def add_noise(y: np.ndarray, noise: dict, seed: int) -> np.ndarray:
    """The sensor model of the truth file's ``noise`` (seeded by the scene's seed)."""
    rng = np.random.default_rng([20260524, seed])
    gain = 1 + noise["prnu_sigma"] * rng.normal(size=y.shape[1])
    fw, top = noise["full_well_e"], 2 ** noise["bits"] - 1
    e = rng.poisson(np.clip(y * gain[None, :], 0, None) * fw)
    dn = noise["black_dn"] + e * noise["white_dn"] / fw + rng.normal(0, noise["read_dn"], y.shape)
    j = noise["defect_column"]
    if noise["defect"] == "dead":
        dn[:, j] = noise["black_dn"] + rng.normal(0, noise["read_dn"], y.shape[0])
    elif noise["defect"] == "hot":
        dn[:, j] = noise["hot_dn"] + rng.normal(0, noise["read_dn"], y.shape[0])
    out = np.clip(np.rint(dn), 0, top)
    return out.astype(np.uint8 if noise["bits"] == 8 else np.uint16)


def precision_inputs(y: np.ndarray, truth_ball: dict, cam: dict, noise: dict, flick: np.ndarray, bg: np.ndarray) -> dict:
    """What ``ballscan precision`` needs of one ball: contrast and pixel noise in DN, measured on the clean image."""
    lr, f, c = cam["line_rate_hz"], cam["focal_px"], cam["principal_px"]
    x, y0, z0 = truth_ball["position_m"]
    i_c = int(round(truth_ball["t_c_s"] * lr))
    r_px = f * truth_ball["radius_m"] / z0
    n = y0 / z0
    u_c = c + f * n * (1 + cam["k1"] * n * n + cam["k2"] * n**4)
    chord = int(max(1, 0.2 * 2 * truth_ball["radius_m"] / abs(truth_ball["velocity_mps"][0]) * lr))
    rows = np.arange(i_c - chord, i_c + chord + 1)
    rows = rows[(rows >= 0) & (rows < y.shape[0])]
    cols = np.arange(int(math.ceil(u_c - 0.5 * r_px)), int(math.floor(u_c + 0.5 * r_px)) + 1)
    cols = cols[(cols >= 0) & (cols < y.shape[1])]
    if rows.size == 0 or cols.size == 0:
        return {}
    ball = float(np.median(y[np.ix_(rows, cols)]))
    back = float(np.median(bg[cols]) * np.median(flick[rows]))
    scale = noise["white_dn"]
    level = 0.5 * (ball + back)
    sigma = math.sqrt(noise["read_dn"] ** 2 + level * scale * scale / noise["full_well_e"])
    return {"contrast_dn": abs(ball - back) * scale, "pixel_sigma_dn": sigma, "ball_level": ball, "background_level": back}


def assemble(out: Path, name: str, keep_frames: bool) -> str:
    """Assemble one rendered scene: clean and noisy images, and the truth's precision inputs."""
    from ballscan.model.render import write_image

    truth_path = out / f"{name}.truth.json"
    truth = json.loads(truth_path.read_text())
    sc = scene_of(truth)
    cam = {"width": sc.camera.width, "focal_px": sc.camera.focal_px, "principal_px": sc.camera.principal_px,
           "line_rate_hz": sc.camera.line_rate_hz, "exposure_s": sc.camera.exposure_s, "k1": sc.camera.k1, "k2": sc.camera.k2}
    frames_dir = out / "frames"
    y = clean_image(truth, cam, frames_dir, sc.subframes, list(sc.traced_lines))
    (out / "clean").mkdir(exist_ok=True)
    write_image(out / "clean" / f"{name}.png", np.clip(np.rint(y * 65535), 0, 65535).astype(np.uint16))
    write_image(out / f"{name}.png", add_noise(y, truth["noise"], int(truth["seed"])))
    t = np.arange(y.shape[0]) / cam["line_rate_hz"]
    flick = flicker_mean(truth["lighting"], t, cam["exposure_s"], sc.subframes)
    untraced = [i for i in range(y.shape[0]) if i not in set(sc.traced_lines)]
    bg = y[untraced[0]] / flick[untraced[0]] if untraced else np.median(y, axis=0)
    balls = truth["balls"] if "balls" in truth else [truth]
    for b in balls:
        b["precision_inputs"] = precision_inputs(y, b, cam, truth["noise"], flick, bg)
    truth["render"]["clean_image"] = f"clean/{name}.png"
    truth_path.write_text(json.dumps(truth, indent=1) + "\n")
    if not keep_frames:
        for p in frames_dir.glob(f"{name}_*.ppm"):
            p.unlink()
    return name


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=Path, default=HERE / "scenes")
    ap.add_argument("--only", default="*", help="glob on scene names")
    ap.add_argument("--jobs", type=int, default=16)
    ap.add_argument("--chunk", type=int, default=40, help="frames per povray process")
    ap.add_argument("--keep-frames", action="store_true")
    ap.add_argument("--force", action="store_true", help="re-assemble scenes whose image exists")
    a = ap.parse_args(argv)
    if shutil.which("povray") is None:
        print("render.py: povray is not installed (Debian package povray)", file=sys.stderr)
        return 2
    out = a.scenes.resolve()
    names = sorted(p.name[: -len(".truth.json")] for p in out.glob("*.truth.json"))
    names = [n for n in names if fnmatch.fnmatch(n, a.only) and (a.force or not (out / f"{n}.png").exists())]
    frames_dir = out / "frames"
    frames_dir.mkdir(exist_ok=True)
    t0 = time.time()
    todo = {}
    for n in names:
        truth = json.loads((out / f"{n}.truth.json").read_text())
        todo[n] = povray_jobs(n, out / "src", frames_dir, int(truth["render"]["frames"]), a.chunk)
    print(f"{len(names)} scenes to render, {sum(len(j) for j in todo.values())} povray runs", flush=True)

    def run(cmd: list[str]) -> int:
        return subprocess.run(cmd, cwd=out / "src", stdout=subprocess.DEVNULL, stderr=subprocess.PIPE).returncode

    done = 0
    with ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = {n: [pool.submit(run, c) for c in cmds] for n, cmds in todo.items()}
        for n, fs in futures.items():
            codes = [f.result() for f in fs]
            if any(codes):
                print(f"{n}: povray failed ({codes})", flush=True)
                continue
            assemble(out, n, a.keep_frames)
            done += 1
            print(f"{n} done ({done}/{len(names)}, {time.time() - t0:.0f} s)", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
