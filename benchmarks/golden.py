"""Golden outputs: what ``ballscan estimate --json`` and the stream engine print.

The golden record holds, for every reference scene in ``tests/data/scenes``,
the ``--json`` output of ``ballscan estimate`` with both methods, and the
estimates of the stream bench's engine run (``bench_stream.run``'s chunks,
a ball every 10 000 lines), every key except the run times (``run_time_s``
and ``time_*_s``).  Restructurings keep it; a change that moves it on
purpose says so and by how much.

Usage::

    python benchmarks/golden.py --write tests/data/golden.json   # record
    python benchmarks/golden.py --check tests/data/golden.json   # rtol 1e-9
    python benchmarks/golden.py --check tests/data/golden.json --exact

``tests/test_golden.py`` runs the check at :data:`RTOL` (numpy's
CPU-specific paths differ between machines; the paper method's Powell
search at :data:`PAPER_RTOL`, see :func:`check`); ``benchmarks/golden_compare.sh OLD NEW``
records two commits on one machine and compares them bit for bit.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
# with --src, the checkout whose package is measured (its src/ first on the path)
_BOOT = (
    "import os, sys, pathlib\n"
    "src = os.environ.get('GOLDEN_SRC')\n"
    "if src: sys.path[:] = [src] + [p for p in sys.path if not (pathlib.Path(p or '.') / 'ballscan').is_dir()]\n"
    "from ballscan.cli.app import main\n"
    "sys.exit(main(sys.argv[1:]))\n"
)
METHODS = ("fit", "paper")
STREAM_CHUNKS = 60


def _strip_times(v):
    """``v`` without its run-time keys (``run_time_s``, ``time_*_s``)."""
    if isinstance(v, dict):
        return {k: _strip_times(x) for k, x in v.items() if not (k == "run_time_s" or (k.startswith("time_") and k.endswith("_s")))}
    if isinstance(v, list):
        return [_strip_times(x) for x in v]
    return v


def _ballscan() -> list[str]:
    return [sys.executable, "-c", _BOOT]


def use_checkout(root: Path) -> None:
    """Measure the package of the checkout ``root`` (its ``src`` first on the path, here and in the CLI runs)."""
    global ROOT
    ROOT = root.resolve()
    src = str(ROOT / "src")
    os.environ["GOLDEN_SRC"] = src
    sys.path[:] = [src] + [p for p in sys.path if not (Path(p or ".") / "ballscan").is_dir()]


def estimate_scenes() -> dict:
    """``ballscan estimate --json`` on each scene with each method."""
    out = {}
    for png in sorted((ROOT / "tests" / "data" / "scenes").glob("*.png")):
        stem = png.name[: -len(".png")]
        truth = json.loads((png.parent / f"{stem}.truth.json").read_text())
        radius = (truth["balls"][0] if "balls" in truth else truth)["radius_m"]
        for method in METHODS:
            rel = png.relative_to(ROOT)  # the JSON names the image as given: relative, the same in every checkout
            cmd = [*_ballscan(), "estimate", str(rel), "--camera", str(rel.parent / f"{stem}.camera.toml"), "--radius", repr(radius), "--method", method, "--json"]
            res = subprocess.run(cmd, capture_output=True, text=True, check=True, cwd=ROOT)
            out[f"{stem}/{method}"] = _strip_times(json.loads(res.stdout))
    return out


def stream_estimates(n_chunks: int = STREAM_CHUNKS) -> list:
    """The stream engine's estimates on the stream bench's chunks (a ball every 10 000 lines)."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    import bench_stream as B

    from ballscan.stream.engine import StreamConfig, process_stream

    bgs = B.background_chunks(8)
    every = 10_000 // B.CHUNK
    balls = {k: B.ball_chunk(400.0 + 37 * (k % 7), seed=k)[0] for k in range(every // 2, n_chunks, every)}
    chunks = (balls[k] if k in balls else bgs[k % len(bgs)] for k in range(n_chunks))
    results = process_stream(chunks, B.CAMERA, 0.0335, StreamConfig(), source="bench")
    return [_strip_times(r.estimate.to_dict(B.CAMERA)) for r in results]


def collect() -> dict:
    return {"estimate": estimate_scenes(), "stream": stream_estimates()}


def compare(a, b, rtol: float, path: str = "") -> list[str]:
    """Where ``a`` and ``b`` differ beyond ``rtol`` (numbers) or at all (everything else)."""
    if isinstance(a, dict) and isinstance(b, dict):
        diffs = [f"{path}/{k}: only in one" for k in sorted(set(a) ^ set(b))]
        for k in sorted(set(a) & set(b)):
            diffs += compare(a[k], b[k], rtol, f"{path}/{k}")
        return diffs
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: length {len(a)} != {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in compare(x, y, rtol, f"{path}[{i}]")]
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool) and not isinstance(b, bool):
        if a == b or (math.isnan(a) and math.isnan(b)):
            return []
        if rtol > 0 and math.isclose(a, b, rel_tol=rtol, abs_tol=rtol * 1e-9):
            return []
        return [f"{path}: {a!r} != {b!r}"]
    return [] if a == b else [f"{path}: {a!r} != {b!r}"]


#: rtol of the fit's and the stream's outputs between machines and numpy
#: releases: numpy's SIMD paths (AVX2 against AVX-512) and older releases
#: (2.0-2.2) sum in other orders, which moves the covariances' small
#: off-diagonal terms and the speed correction by up to 1.5e-10 relative
#: (an AVX-512 EPYC against the record's machine).  A restructuring is held
#: bit for bit by ``golden_compare.sh`` on one machine instead.
RTOL = 1e-9

#: rtol of the paper method's outputs across library versions: scipy's Powell
#: (Brent line searches) stops within its own tolerance, and a scipy release
#: that changes its path moves the result by up to about 2e-5 relative
#: (far below the method's own error) and its evaluation count by a few.
PAPER_RTOL = 1e-4


def check(recorded: dict, now: dict, rtol: float = RTOL) -> list[str]:
    """Differences of ``now`` from ``recorded``: ``rtol`` everywhere except the paper method's outputs (:data:`PAPER_RTOL`, evaluation counts not compared)."""

    def paper_part(v):
        return {k: x for k, x in v.items() if k.endswith("/paper")}

    def without_evaluations(v):
        if isinstance(v, dict):
            return {k: without_evaluations(x) for k, x in v.items() if k != "evaluations"}
        if isinstance(v, list):
            return [without_evaluations(x) for x in v]
        return v

    rest = {k: v for k, v in recorded.items() if k != "estimate"}, {k: v for k, v in now.items() if k != "estimate"}
    old_est, new_est = recorded.get("estimate", {}), now.get("estimate", {})
    fit_old = {k: v for k, v in old_est.items() if not k.endswith("/paper")}
    fit_new = {k: v for k, v in new_est.items() if not k.endswith("/paper")}
    diffs = compare(rest[0], rest[1], rtol)
    diffs += compare(fit_old, fit_new, rtol, "/estimate")
    diffs += compare(without_evaluations(paper_part(old_est)), without_evaluations(paper_part(new_est)), max(rtol, PAPER_RTOL) if rtol > 0 else 0.0, "/estimate")
    return diffs


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    g = ap.add_mutually_exclusive_group(required=True)
    g.add_argument("--write", type=Path, help="record the golden outputs into this JSON file")
    g.add_argument("--check", type=Path, help="compare the outputs with this JSON file")
    ap.add_argument("--root", type=Path, help="measure this checkout's package (default: the installed one)")
    ap.add_argument("--exact", action="store_true", help="with --check: bit for bit instead of rtol 1e-9")
    args = ap.parse_args(argv)
    if args.root:
        use_checkout(args.root)
    now = collect()
    if args.write:
        args.write.write_text(json.dumps(now, indent=1, sort_keys=True) + "\n")
        print(f"{args.write}: {len(now['estimate'])} scene runs, {len(now['stream'])} stream estimates")
        return 0
    recorded = json.loads(args.check.read_text())
    diffs = compare(recorded, now, 0.0) if args.exact else check(recorded, now)
    for d in diffs[:50]:
        print(d)
    print(f"{len(diffs)} differences ({'bit for bit' if args.exact else f'rtol {RTOL:g}, the paper method {PAPER_RTOL:g}'})")
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main())
