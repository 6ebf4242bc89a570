"""The stream's width check: false alarms, detections and cost (run on demand: ``python benchmarks/bench_width.py``).

* For ``--seeds`` simulated 2048-px streams (``simulate_stream``: 8-bit
  sensor noise with its 0.8 % column gains; ``--lines`` lines, 3 balls), the
  width check's verdict through :class:`ballscan.stream.engine.StreamEngine`
  when read with the right width (a refusal is a false alarm) and when the
  stream's lines are 2047 and 2049 px (a refusal before the first ball is a
  detection), with the line of the verdict.
* The same on streams without column gains and without any noise
  (``prnu_sigma=0``; no pattern: the verdict must stay "unknown", no
  refusal).
* The shared reference scenes (PNG images, a few hundred lines): their
  lines through :class:`ballscan.stream.width.WidthCheck` at their own width
  (a refusal is a false alarm).
* The engine's rate on a ball-free 2048-px stream with the check on and off,
  in the same run (alternating, the best of 3).
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

from ballscan.errors import BallscanError
from ballscan.geometry.camera import LineScanCamera
from ballscan.model.render import SensorNoise
from ballscan.stream.engine import StreamConfig, StreamEngine
from ballscan.stream.sources import simulate_stream
from ballscan.stream.width import WidthCheck

CAM = LineScanCamera(width=2048, focal_px=4000.0, principal_px=1023.5, line_rate_hz=70000.0, exposure_s=1.2e-5)


def _run(data: np.ndarray, width: int) -> tuple[str, int, int]:
    """(verdict, line of the verdict or refusal, balls measured) of an engine reading ``data`` as ``width``-px lines."""
    n = data.size // width
    lines = data[: n * width].reshape(n, width)
    cam = replace(CAM, width=width, principal_px=(width - 1) / 2)
    eng = StreamEngine(cam, 0.0335, StreamConfig(), source="bench")
    balls = 0
    try:
        for a in range(0, n, 1024):
            balls += len(eng.push(lines[a : a + 1024]))
        balls += len(eng.finish())
    except BallscanError:
        return "refused", eng.lines_received, balls
    v = eng._width_check.verdict
    return v.state, v.lines, balls


def streams(seeds: int, n_lines: int, folder: Path) -> list[dict]:
    rows = []
    for seed in range(seeds):
        for w_true in (2048, 2047, 2049):
            cam = replace(CAM, width=w_true, principal_px=(w_true - 1) / 2)
            sim = simulate_stream(folder / f"s{seed}_{w_true}.raw", cam, n_lines, 3, seed)
            data = np.fromfile(sim.raw, dtype=np.uint8)
            first_ball = min(b["first_line"] for b in sim.balls)
            state, line, balls = _run(data, 2048)
            rows.append({"seed": seed, "stream_px": w_true, "verdict": state, "at_line": line, "balls": balls, "first_ball_line": first_ball})
            print("  " + json.dumps(rows[-1]), flush=True)
            sim.raw.unlink()
    return rows


def flat_streams(seeds: int, n_lines: int, folder: Path) -> list[dict]:
    rows = []
    for seed in range(seeds):
        for name, noise in (("no column gains", SensorNoise(prnu_sigma=0.0)), ("no noise", SensorNoise(prnu_sigma=0.0, read_dn=0.0, full_well_e=None))):
            sim = simulate_stream(folder / f"f{seed}.raw", CAM, n_lines, 3, seed, noise=noise)
            state, line, balls = _run(np.fromfile(sim.raw, dtype=np.uint8), 2048)
            rows.append({"seed": seed, "kind": name, "verdict": state, "at_line": line, "balls": balls})
            print("  " + json.dumps(rows[-1]), flush=True)
            sim.raw.unlink()
    return rows


def scenes(folder: Path) -> list[dict]:
    from ballscan.measure.images import load_image

    rows = []
    for png in sorted(folder.glob("*.png")):
        img = load_image(png)
        x = np.asarray(img.data)
        x = np.clip(np.rint(x), 0, 65535).astype(np.uint16 if x.max() > 255 else np.uint8)
        wc = WidthCheck(x.shape[1], min_lines=64)
        v = wc.add(x, 0, np.ones(x.shape[0], bool))
        rows.append({"scene": png.name, "lines": x.shape[0], "verdict": v.state, "z": round(v.z, 1)})
    return rows


def cost(n_lines: int) -> dict:
    rng = np.random.default_rng(0)
    pattern = 30 + 0.3 * rng.standard_normal(2048)
    data = np.clip(np.rint(pattern + 2.0 * rng.standard_normal((n_lines, 2048))), 0, 255).astype(np.uint8)
    best = {True: np.inf, False: np.inf}
    for _ in range(3):
        for on in (False, True):
            eng = StreamEngine(CAM, 0.0335, StreamConfig(width_check=on))
            t = time.process_time()
            for a in range(0, n_lines, 1024):
                eng.push(data[a : a + 1024])
            eng.finish()
            best[on] = min(best[on], time.process_time() - t)
    return {"lines": n_lines, "off_lines_per_cpu_s": n_lines / best[False], "on_lines_per_cpu_s": n_lines / best[True], "ratio_on_off": best[True] / best[False]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=20)
    ap.add_argument("--lines", type=int, default=8000)
    ap.add_argument("--scenes", type=Path, default=Path("/work/shared/scenes"))
    args = ap.parse_args()
    import os

    print(f"load average {os.getloadavg()}")
    with tempfile.TemporaryDirectory() as tmp:
        out = {"streams": streams(args.seeds, args.lines, Path(tmp)), "flat": flat_streams(min(args.seeds, 5), args.lines, Path(tmp))}
    if args.scenes.is_dir():
        out["scenes"] = scenes(args.scenes)
    out["cost"] = cost(262144)
    for k, rows in out.items():
        print(k)
        for r in rows if isinstance(rows, list) else [rows]:
            print("  " + json.dumps(r))
    s = out["streams"]
    for w in (2048, 2047, 2049):
        sel = [r for r in s if r["stream_px"] == w]
        print(f"{w}-px streams read as 2048: " + ", ".join(f"{v} {sum(r['verdict'] == v for r in sel)}" for v in ("confirmed", "unknown", "refused", "sheared")) + f"; balls measured on refused ones {sum(r['balls'] for r in sel if r['verdict'] == 'refused')}")


if __name__ == "__main__":
    main()
