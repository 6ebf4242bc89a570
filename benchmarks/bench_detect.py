"""Time of ``detect()`` per image against another checkout's, in one run (run on demand: ``python benchmarks/bench_detect.py``).

Images: the committed scenes and POV-Ray renders under ``tests/data``, a
2,048 x 7,000-line 8-bit image without a ball (noise 2 DN on 100 DN), and
the POV-Ray set's tuning half (``benchmarks/povray_set/scenes``, even
seeds; summarised). Each checkout runs in a subprocess of its own
(``--old PATH``: that checkout's ``src`` first on the path; default the
``main`` branch, exported to a temporary directory); the two alternate for
``--rounds`` rounds and each image's time is the least over the rounds of
the median of ``--reps`` calls (decoding excluded, one call to warm up).

``python benchmarks/bench_detect.py [--old SRC] [--rounds 3] [--reps 5] [--no-set]``
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

CHILD = r"""
import glob, json, sys, time
import numpy as np
from ballscan.measure.detection import detect
from ballscan.measure.images import LineImage, load_image
paths, reps = json.loads(sys.argv[1]), int(sys.argv[2])
rng = np.random.default_rng(1)
out = {}
for p in paths:
    if p == "noball":
        im = LineImage(data=(100 + rng.normal(0, 2, (7000, 2048))).round().astype(np.uint8), saturation_dn=255.0, bits=8, source="noball")
    else:
        im = load_image(p)
    detect(im)
    ts = []
    for _ in range(reps):
        t0 = time.perf_counter()
        d = detect(im)
        ts.append(time.perf_counter() - t0)
    out[p] = [float(np.median(ts)), len(d.regions), list(im.data.shape)]
print(json.dumps(out))
"""


def _env(src: Path | None) -> dict:
    """The environment of a subprocess that imports ``src``'s package (None: this checkout's)."""
    env = dict(os.environ)
    if src is None:
        env["PYTHONPATH"] = str(ROOT / "src")
        return env
    shim = Path(tempfile.gettempdir()) / "ballscan_bench_detect_shim"
    shim.mkdir(exist_ok=True)
    # the editable install's path entry would win over the other checkout's package
    (shim / "sitecustomize.py").write_text(f"import sys; sys.path[:] = [p for p in sys.path if p.rstrip('/') != {str(ROOT / 'src')!r}]\n")
    env["PYTHONPATH"] = f"{shim}:{src}"
    return env


def _times(src: Path | None, paths: list[str], reps: int) -> dict:
    res = subprocess.run([sys.executable, "-c", CHILD, json.dumps(paths), str(reps)], capture_output=True, text=True, env=_env(src))
    if res.returncode:
        raise RuntimeError(res.stderr.strip()[-600:])
    return json.loads(res.stdout)


def _export_main() -> Path:
    """The ``main`` branch's ``src``, exported to a temporary directory."""
    tmp = Path(tempfile.mkdtemp(prefix="ballscan_main_"))
    arch = subprocess.run(["git", "-C", str(ROOT), "archive", "main", "src"], capture_output=True, check=True).stdout
    subprocess.run(["tar", "-x", "-C", str(tmp)], input=arch, check=True)
    return tmp / "src"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--old", type=Path, help="another checkout's src directory (default: main, exported)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--no-set", action="store_true", help="leave out the POV-Ray set's tuning half")
    a = ap.parse_args()
    old = a.old or _export_main()
    named = sorted(str(p) for p in (ROOT / "tests" / "data").glob("*/*.png")) + ["noball"]
    pov = [] if a.no_set else sorted(str(p) for p in (ROOT / "benchmarks" / "povray_set" / "scenes").glob("pv*.png") if int(p.stem[2:]) % 2 == 0)
    paths = named + pov
    best: dict[str, dict] = {"old": {}, "new": {}}
    for _ in range(a.rounds):
        for key, src in (("old", old), ("new", None)):
            for p, (t, nreg, shape) in _times(src, paths, a.reps).items():
                prev = best[key].get(p)
                best[key][p] = (min(t, prev[0]) if prev else t, nreg, shape)
    print(f"old: {old}   rounds {a.rounds} x median of {a.reps} calls   load {os.getloadavg()[0]:.2f}\n")
    print("| image | lines x columns | old ms | new ms | new / old | regions old / new |")
    print("|---|---|---|---|---|---|")
    for p in named:
        (to, ro, shape), (tn, rn, _) = best["old"][p], best["new"][p]
        print(f"| {Path(p).name} | {shape[0]} x {shape[1]} | {1e3 * to:.2f} | {1e3 * tn:.2f} | {tn / to:.2f} | {ro} / {rn} |")
    if pov:
        ratios = [best["new"][p][0] / best["old"][p][0] for p in pov]
        q = statistics.quantiles(ratios, n=10)
        so, sn = sum(best["old"][p][0] for p in pov), sum(best["new"][p][0] for p in pov)
        print(
            f"\nPOV-Ray tuning half ({len(pov)} images): total {1e3 * so:.0f} ms old, {1e3 * sn:.0f} ms new ({sn / so:.2f}x); "
            f"per image new / old median {statistics.median(ratios):.2f}, 10 % {q[0]:.2f}, 90 % {q[-1]:.2f}, worst {max(ratios):.2f}"
        )


if __name__ == "__main__":
    main()
