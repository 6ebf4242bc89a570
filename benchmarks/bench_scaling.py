"""Cost that grows with the balls, not with the image (run on demand: ``python benchmarks/bench_scaling.py``).

Each figure beside the same measurement of another checkout (``--old
PATH``: its ``src`` is put first on the path of a subprocess; default the
commit before this work, checked out in a temporary worktree), in one run:

* ``memory``: peak resident memory of measuring a 140 288 x 2048 8-bit image
  (an uncompressed TIFF, memory-mapped, and a PNG) minus that of the same
  command on its first 1000 lines, against the image's own size; the old
  code's figure from a harness that calls ``load_image`` with a raised
  pixel limit and ``estimate_image``; and whether the balls equal the
  stream's (``process_stream`` over the same lines);
* ``noball``: seconds per megapixel of an image without a ball (a 41 984-line
  TIFF, decoding excluded: the PNG's decode is timed apart);
* ``balls``: the estimator's per-ball time (``run_time_s``, median) on an
  image of 20 balls against one of 1 ball, and the whole image's time per
  ball above an image of the same size without balls;
* ``batch``: ``ballscan batch`` over 200 images of 2048 x 300 with ``-j 1``
  and ``-j 2`` (median wall of :data:`BATCH_ROUNDS` interleaved rounds, the
  two checkouts in ABBA order), the speed-up of ``-j 2``, ``-j 1``'s wall
  against the old code's, the processes left behind after it exits, and the
  fixed cost: ``batch`` over one of the images (each checkout's program
  entry: its console script's function);
* ``latency``: the stream's latency (``bench_stream.run``) over >= 200 balls,
  alone and with a CPU-bound process pinned to the other core (``taskset``).

``python benchmarks/bench_scaling.py [PARTS ...] [--old PATH]``.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))
PARTS = ("memory", "noball", "balls", "batch", "latency")
OLD_COMMIT = "30fe372"
#: Interleaved rounds of the batch part (medians of the walls).
BATCH_ROUNDS = 3

#: ``python -c`` code that runs a checkout's ``ballscan`` program as its console script does
#: (``ballscan.cli.run`` where it has one, else ``sys.exit(main())``).
PROGRAM = "import sys, ballscan.cli as c; sys.argv[0] = 'ballscan'; c.run() if hasattr(c, 'run') else sys.exit(c.main(sys.argv[1:]))"

# A subprocess's view of either layout (the flat one before the redesign, or sub-packages).
HARNESS = r"""
import json, sys, time
def imp(new, old, name):
    try:
        return getattr(__import__(new, fromlist=[name]), name)
    except ImportError:
        return getattr(__import__(old, fromlist=[name]), name)
load_image = imp("ballscan.measure.images", "ballscan.images", "load_image")
load_camera = imp("ballscan.geometry.camera", "ballscan.camera", "load_camera")
estimate_image = imp("ballscan.pipeline.estimate", "ballscan.estimate", "estimate_image")
detect = imp("ballscan.measure.detection", "ballscan.detection", "detect")
"""


def _env(src: Path | None) -> dict:
    """The environment of a subprocess that imports ``src``'s package (none: the installed one)."""
    env = dict(os.environ)
    if src is None:
        return env
    shim = Path(tempfile.gettempdir()) / "ballscan_bench_shim"
    shim.mkdir(exist_ok=True)
    # the editable install's path entry would win over the old checkout's namespace package
    (shim / "sitecustomize.py").write_text(f"import sys; sys.path[:] = [p for p in sys.path if p.rstrip('/') != {str(ROOT / 'src')!r}]\n")
    env["PYTHONPATH"] = f"{shim}:{src}"
    return env


def _peak_mib(cmd: list[str], env: dict) -> tuple[float, float, str]:
    """Peak resident MiB and wall seconds of a command (GNU time), and its stdout."""
    t0 = time.perf_counter()
    res = subprocess.run(["/usr/bin/time", "-f", "%M", *cmd], capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    if res.returncode:
        raise RuntimeError(f"{' '.join(cmd[:4])}...: {res.stderr.strip()[-400:]}")
    return int(res.stderr.strip().splitlines()[-1]) / 1024.0, wall, res.stdout


def _python(code: str, env: dict) -> list[str]:
    return [sys.executable, "-c", HARNESS + code]


# ------------------------------------------------------------------ images
def _camera_file(folder: Path) -> Path:
    from bench_stream import CAMERA

    from ballscan.geometry.camera import save_camera

    path = folder / "cam.toml"
    save_camera(CAMERA, path)
    return path


def _long_image(n_chunks: int, ball_every: int | None) -> np.ndarray:
    """``n_chunks`` x 1024 lines of bench_stream's sensor, a ball every ``ball_every`` chunks."""
    from bench_stream import CHUNK, W, background_chunks, ball_chunk

    bgs = background_chunks(8)
    out = np.empty((n_chunks * CHUNK, W), dtype=np.uint8)
    for k in range(n_chunks):
        ball = ball_every and k % ball_every == ball_every // 2
        out[k * CHUNK : (k + 1) * CHUNK] = ball_chunk(400.0 + 37 * (k % 7), seed=k)[0] if ball else bgs[k % len(bgs)]
    return out


def _write(folder: Path, name: str, image: np.ndarray) -> tuple[Path, Path]:
    import tifffile
    from PIL import Image

    tif, png = folder / f"{name}.tif", folder / f"{name}.png"
    tifffile.imwrite(tif, image)
    Image.fromarray(image).save(png, compress_level=1)
    return tif, png


# ------------------------------------------------------------------ parts
def part_memory(folder: Path, old: Path) -> dict:
    from bench_stream import CAMERA

    from ballscan.stream.engine import StreamConfig, process_stream

    big = _long_image(137, ball_every=10)
    tif, png = _write(folder, "big", big)
    stif, spng = _write(folder, "small", big[:1000])
    cam = _camera_file(folder)
    size_mib = big.nbytes / 2**20
    stream = [(r.estimate.first_line, r.estimate.t_c_s) for r in process_stream((big[i : i + 1024] for i in range(0, big.shape[0], 1024)), CAMERA, 0.0335, StreamConfig())]
    del big
    new_cmd = lambda path: [sys.executable, "-m", "ballscan", "estimate", str(path), "--camera", str(cam), "--radius", "0.0335", "--json", "--max-pixels", str(2**30)]
    old_code = lambda path: f"r = estimate_image(load_image({str(path)!r}, max_pixels=2**30), load_camera({str(cam)!r}), 0.0335); print(len(r.balls))"
    out = {"image_mib": size_mib, "stream_balls": len(stream)}
    for kind, (b, s) in {"tiff": (tif, stif), "png": (png, spng)}.items():
        peak, wall, text = _peak_mib(new_cmd(b), _env(None))
        base, _, _ = _peak_mib(new_cmd(s), _env(None))
        balls = [(x["first_line"], x["t_c_s"]) for x in json.loads(text)["balls"]]
        out[f"new_{kind}"] = {"working_mib": peak - base, "ratio": (peak - base) / size_mib, "wall_s": wall, "balls": len(balls), "same_as_stream": balls == stream}
        peak, wall, text = _peak_mib(_python(old_code(b), _env(old)), _env(old))
        base, _, _ = _peak_mib(_python(old_code(s), _env(old)), _env(old))
        out[f"old_{kind}"] = {"working_mib": peak - base, "ratio": (peak - base) / size_mib, "wall_s": wall, "balls": int(text.split()[-1])}
    return out


def part_noball(folder: Path, old: Path) -> dict:
    image = _long_image(41, ball_every=None)
    tif, png = _write(folder, "noball", image)
    cam = _camera_file(folder)
    mpx = image.size / 1e6
    new = f"""
from ballscan.measure.images import read_stored
from ballscan.stream.recording import measure_recording
from ballscan.pipeline.warmup import ensure_warm
from ballscan.stream.engine import preload_estimator
preload_estimator()
cam = load_camera({str(cam)!r})
t = time.perf_counter(); s = read_stored({str(png)!r}); decode = time.perf_counter() - t
s = read_stored({str(tif)!r}); s.data[::4096].sum()
t = time.perf_counter(); r = measure_recording(s, cam, 0.0335); dt = time.perf_counter() - t
print(json.dumps({{"s": dt, "balls": len(r.balls), "png_decode_s": decode}}))
"""
    old_code = f"""
cam = load_camera({str(cam)!r})
t = time.perf_counter(); img = load_image({str(png)!r}, max_pixels=2**30); decode = time.perf_counter() - t
estimate_image(img, cam, 0.0335)  # warm
t = time.perf_counter(); r = estimate_image(img, cam, 0.0335); dt = time.perf_counter() - t
print(json.dumps({{"s": dt, "balls": len(r.balls), "png_decode_s": decode}}))
"""
    a = json.loads(subprocess.run(_python(new, _env(None)), capture_output=True, text=True, check=True).stdout.splitlines()[-1])
    b = json.loads(subprocess.run(_python(old_code, _env(old)), capture_output=True, text=True, check=True, env=_env(old)).stdout.splitlines()[-1])
    return {"mpx": mpx, "new_ms_per_mpx": a["s"] / mpx * 1e3, "old_ms_per_mpx": b["s"] / mpx * 1e3, "ratio_old_new": b["s"] / a["s"],
            "new_png_decode_ms_per_mpx": a["png_decode_s"] / mpx * 1e3, "balls": (a["balls"], b["balls"])}  # fmt: skip


def _balls_image(n_balls: int, n_lines: int) -> np.ndarray:
    from bench_stream import CAMERA, GAIN, NOISE

    from ballscan.geometry.motion import BallMotion
    from ballscan.model.render import Appearance, apply_sensor, render

    rng = np.random.default_rng(n_balls)
    motions = [
        (BallMotion(0.0335, (150.0 + k * (n_lines - 300) / max(n_balls - 1, 1)) / CAMERA.line_rate_hz, (0.0, rng.uniform(-0.3, 0.3), 4.0), (40.0, 2.0, -3.0)), Appearance.flat(0.8))
        for k in range(n_balls)
    ]  # fmt: skip
    r = render(CAMERA, motions, n_lines, background_level=0.12, noise=None) if n_balls else None
    clean = r.clean if r is not None else np.full((n_lines, CAMERA.width), 0.12)
    return apply_sensor(clean * GAIN[None, :], NOISE, 5)[0]


def part_balls(folder: Path, old: Path) -> dict:
    n_lines = 6400
    cam = _camera_file(folder)
    paths = {}
    for n in (0, 1, 20):
        paths[n] = _write(folder, f"balls{n}", _balls_image(n, n_lines))[0]
    code = f"""
cam = load_camera({str(cam)!r})
out = {{}}
estimate_image(load_image({str(paths[1])!r}), cam, 0.0335)  # warm
for n, p in {dict((k, str(v)) for k, v in paths.items())!r}.items():
    img = load_image(p)
    best = None
    for _ in range(3):
        t = time.perf_counter(); r = estimate_image(img, cam, 0.0335); dt = time.perf_counter() - t
        per = sorted(b.run_time_s for b in r.balls)
        if best is None or dt < best[0]:
            best = (dt, per[len(per) // 2] if per else 0.0, len(r.balls))
    out[n] = best
print(json.dumps(out))
"""
    res = {}
    for name, src in (("new", None), ("old", old)):
        d = json.loads(subprocess.run(_python(code, _env(src)), capture_output=True, text=True, check=True, env=_env(src)).stdout.splitlines()[-1])
        t0, t1, t20 = d["0"][0], d["1"][0], d["20"][0]
        res[name] = {
            "balls_found": (d["1"][2], d["20"][2]),
            "run_time_ms_1": d["1"][1] * 1e3, "run_time_ms_20": d["20"][1] * 1e3, "run_time_ratio": d["20"][1] / d["1"][1],
            "per_ball_ms_1": (t1 - t0) * 1e3, "per_ball_ms_20": (t20 - t0) / 20 * 1e3, "per_ball_ratio": ((t20 - t0) / 20) / (t1 - t0),
        }  # fmt: skip
    return res


def _leftovers(tag: str) -> list[str]:
    out = subprocess.run(["ps", "-eo", "pid,args"], capture_output=True, text=True).stdout.splitlines()
    return [line for line in out if tag in line and "ps -eo" not in line]


def part_batch(folder: Path, old: Path) -> dict:
    from PIL import Image

    data = folder / "batch"
    data.mkdir()
    base = _balls_image(1, 300)
    for k in range(200):
        # the same ball, new sensor noise per image
        img = np.clip(base.astype(np.int16) + np.random.default_rng(k).integers(-1, 2, base.shape), 0, 255).astype(np.uint8)
        Image.fromarray(img).save(data / f"img{k:03d}.png")
    cam = _camera_file(folder)
    one = folder / "one"
    one.mkdir()
    shutil.copy(data / "img000.png", one / "img000.png")
    walls: dict[str, list[float]] = {}
    res: dict = {}
    # interleaved rounds (-j 1, -j 2, one image; the checkouts in ABBA order):
    # a noisy machine's load changes alike for the runs compared; medians reported
    for rnd in range(BATCH_ROUNDS):
        for jobs, inputs in ((1, data), (2, data), (1, one)):
            for name, src in (("new", None), ("old", old))[:: 1 if rnd % 2 == 0 else -1]:
                key = f"{name}_j{jobs}" if inputs is data else f"{name}_one_image"
                out = folder / f"{key}_{rnd}.csv"
                cmd = [sys.executable, "-c", PROGRAM, "batch", str(inputs), "--camera", str(cam), "--radius", "0.0335", "--out", str(out), "-j", str(jobs), "--no-progress"]
                t0 = time.perf_counter()
                subprocess.run(cmd, capture_output=True, text=True, env=_env(src))
                walls.setdefault(key, []).append(time.perf_counter() - t0)
                time.sleep(0.5)
                rows = max(sum(1 for _ in open(out)) - 1, 0) if out.exists() else 0
                res[key] = {"rows": min(rows, res.get(key, {}).get("rows", rows)), "left_behind": max(len(_leftovers(str(folder))), res.get(key, {}).get("left_behind", 0))}
    for key, w in walls.items():
        res[key]["wall_s"] = float(np.median(w))
        res[key]["walls_s"] = [round(x, 2) for x in w]
    for name in ("new", "old"):
        # the same rows whatever the workers (in the order the inputs finished)
        res[f"{name}_j2"]["rows_equal_j1"] = sorted(open(folder / f"{name}_j1_0.csv")) == sorted(open(folder / f"{name}_j2_0.csv"))
    for name in ("new", "old"):
        res[f"{name}_speedup_j2"] = res[f"{name}_j1"]["wall_s"] / res[f"{name}_j2"]["wall_s"]
    res["j1_new_over_old"] = res["new_j1"]["wall_s"] / res["old_j1"]["wall_s"]
    res["targets"] = {"new_speedup_j2 >= 1.7": res["new_speedup_j2"] >= 1.7, "j1_new_over_old <= 1.0": res["j1_new_over_old"] <= 1.0,
                      "no process left": all(res[k]["left_behind"] == 0 for k in walls)}  # fmt: skip
    return res


def part_latency(folder: Path, old: Path) -> dict:
    code = """
import json, sys
sys.path.insert(0, %r)
import bench_stream as B
from ballscan.stream.engine import preload_estimator
preload_estimator()
B.run(40, 10_000)
r = B.run(2100, 10_000)
print(json.dumps({"balls": r["balls"], "median_ms": r["latency_ms"][0], "p99_ms": r["latency_p99_ms"], "max_ms": r["latency_ms"][1]}))
""" % str(ROOT / "benchmarks")
    res = {}
    for label, hog in (("alone", False), ("neighbour_busy", True)):
        proc = subprocess.Popen(["taskset", "-c", "1", sys.executable, "-c", "while True: pass"]) if hog else None
        try:
            out = subprocess.run(["taskset", "-c", "0", sys.executable, "-c", code], capture_output=True, text=True, check=True)
            res[label] = json.loads(out.stdout.splitlines()[-1])
        finally:
            if proc is not None:
                proc.kill()
                proc.wait()
    return res


def _warm(old: Path, tmp: Path) -> None:
    """Compile both checkouts' kernels before anything is measured (a compile's memory would count)."""
    folder = tmp / "warm"
    folder.mkdir()
    tif = _write(folder, "w", _balls_image(1, 1200))[0]
    cam = _camera_file(folder)
    for src in (None, old):
        code = f"estimate_image(load_image({str(tif)!r}), load_camera({str(cam)!r}), 0.0335)"
        subprocess.run(_python(code, _env(src)), check=True, capture_output=True, env=_env(src))


def _old_checkout(commit: str, tmp: Path) -> Path:
    dest = tmp / "old"
    subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(dest), commit], check=True, capture_output=True)
    return dest


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("parts", nargs="*", help=f"parts to run (default all: {', '.join(PARTS)})")
    ap.add_argument("--old", type=Path, help=f"the checkout to compare with (default: commit {OLD_COMMIT} in a temporary worktree)")
    args = ap.parse_args(argv)
    unknown = set(args.parts) - set(PARTS)
    if unknown:
        ap.error(f"unknown parts {sorted(unknown)}; choose from {', '.join(PARTS)}")
    tmp = Path(tempfile.mkdtemp(prefix="ballscan_scaling_"))
    worktree = args.old is None
    old = (_old_checkout(OLD_COMMIT, tmp) if worktree else args.old.resolve()) / "src"
    try:
        print(f"load average {os.getloadavg()}; old code: {old}", flush=True)
        _warm(old, tmp)
        for part in args.parts or PARTS:
            folder = tmp / part
            folder.mkdir()
            t0 = time.perf_counter()
            result = globals()[f"part_{part}"](folder, old)
            print(json.dumps({part: result, "seconds": round(time.perf_counter() - t0, 1)}, default=float), flush=True)
    finally:
        if worktree:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(tmp / "old")], capture_output=True)
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
