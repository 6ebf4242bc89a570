"""Score ``ballscan estimate --rig`` on the POV-Ray rig views: one camera against two on independent renders.

    python benchmarks/povray_set/score_rig.py [--scenes DIR] [--pairs 90,30] [--jobs 2] [--recipe RECIPE.toml]
                                              [--save ROWS.json] [--load ROWS.json]

The rig set (``generate.py --rig 0,90,30``, README "Rigs") holds, per seed,
views ``NAME_a000``, ``NAME_a030`` and ``NAME_a090`` of the same ball by
cameras turned about the lane's axis; each camera file carries its world ->
camera ``[pose]`` and the world frame is the camera frame of ``a000``, whose
truth is therefore the world truth.  The views share the clock and have no
gravity.

For every seed the scorer measures each view alone (``ballscan estimate
IMG --camera CAM --json``, compared with that view's truth in its own frame)
and, for each pair ``a000`` + ``aAAA`` of ``--pairs``, writes a rig file
(both clock offsets 0) and measures the pair (``ballscan estimate --rig
RIG A B --json``, compared with the world truth).  Estimated balls are
matched to the true ball by the nearest ``t_c_s``.  A line-scan camera does
not see the sign of ``V.x`` (every view shares the axis ``x``), so
velocities are compared with ``V.x >= 0``.

Per ball and method: the direction error (degrees between the estimated and
the true velocity); the relative speed error; the direction's Mahalanobis
distance (the velocity error across the estimated direction, against the
covariance projected there: two degrees of freedom, "covered" within the
68.27 % quantile 2.296); the speed's |error| / sigma ("covered" within 1).
An estimate flagged ``degenerate`` (some component undetermined: one
camera's ``V.z``) or ``not_converged`` counts as not measured.  Each pair's
table is printed over all balls and over the balls measured by the pair
and by each of its views alone.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
DEFAULT_SCENES = HERE / "rig"
#: chi-square quantile of 2 degrees of freedom at 68.27 % (the 1-sigma region of a 2-D direction).
CHI2_2_1SIGMA = 2.2957


def run_json(cmd: list[str], timeout: float = 600) -> tuple[dict | None, str]:
    """Run a ballscan command printing JSON; the parsed output or the reason it failed."""
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timeout"
    if p.returncode != 0:
        return None, f"exit {p.returncode}: {(p.stderr.strip().splitlines() or [''])[-1][:160]}"
    try:
        return json.loads(p.stdout), ""
    except json.JSONDecodeError as e:
        return None, f"unreadable JSON ({e})"


def seeds_in(scenes: Path) -> list[str]:
    """Scene names (``pvNNNN``) whose view ``a000`` is rendered."""
    names = set()
    for p in scenes.glob("*_a000.png"):
        m = re.fullmatch(r"(.+)_a000\.png", p.name)
        if m:
            names.add(m.group(1))
    return sorted(names)


def rig_toml(scenes: Path, name: str, angle: int) -> str:
    """The rig file of views ``a000`` (reference) and ``aANGLE`` of ``name`` (shared clock)."""
    out = []
    for a in (0, angle):
        cam = (scenes / f"{name}_a{a:03d}.camera.toml").resolve()
        out.append(f'[[camera]]\nname = "a{a:03d}"\nclock_offset_s = 0.0\nfile = "{cam}"\n')
    return "\n".join(out)


def _positive_x(v: np.ndarray) -> np.ndarray:
    return v if v[0] >= 0 else v * np.array([-1.0, 1.0, 1.0])


def compare(ball: dict, truth: dict, cov_v: np.ndarray | None) -> dict:
    """Errors of one estimated ball against the true one, in the frame both are given in."""
    v, vt = np.asarray(ball["velocity_mps"], float), np.asarray(truth["velocity_mps"], float)
    flip = v[0] < 0
    v, vt = _positive_x(v), _positive_x(vt)
    if cov_v is not None and flip:
        S = np.diag([-1.0, 1.0, 1.0])
        cov_v = S @ cov_v @ S
    c = float(v @ vt / (np.linalg.norm(v) * np.linalg.norm(vt)))
    row = {
        "dir_err_deg": math.degrees(math.acos(min(1.0, max(-1.0, c)))),
        "speed_rel_err": float(np.linalg.norm(v) / np.linalg.norm(vt) - 1.0),
        "t_c_err_s": float(ball["t_c_s"] - truth["t_c_s"]),
        "flags": list(ball.get("flags", [])),
    }
    sp_sigma = ball.get("speed_sigma_mps")
    if sp_sigma:
        row["speed_z"] = float((np.linalg.norm(v) - np.linalg.norm(vt)) / sp_sigma)
    if cov_v is not None and np.all(np.isfinite(cov_v)):
        u = v / np.linalg.norm(v)
        P = np.eye(3) - np.outer(u, u)
        d = P @ (v - vt)
        Cp = P @ cov_v @ P
        row["dir_m2"] = float(d @ np.linalg.pinv(Cp, rcond=1e-12, hermitian=True) @ d)
        row["v_sigma_max_mps"] = float(math.sqrt(max(np.linalg.eigvalsh(cov_v).max(), 0.0)))
    return row


def nearest(balls: list[dict], t_c: float) -> dict | None:
    """The estimated ball nearest in ``t_c_s`` to the true crossing (None when there is none)."""
    cands = [b for b in balls if b.get("t_c_s") is not None]
    return min(cands, key=lambda b: abs(b["t_c_s"] - t_c)) if cands else None


def score_view(ballscan: str, scenes: Path, view: str, recipe: Path | None = None) -> dict:
    """One view measured alone, in its own frame (with ``recipe``'s settings, ``estimate --recipe``)."""
    truth = json.loads((scenes / f"{view}.truth.json").read_text())
    cmd = [ballscan, "estimate", str(scenes / f"{view}.png"), "--camera", str(scenes / f"{view}.camera.toml"),
           "--radius", repr(truth["radius_m"]), "--json"] + (["--recipe", str(recipe)] if recipe else [])
    out, err = run_json(cmd)
    if out is None:
        return {"measured": False, "error": err}
    b = nearest(out["balls"], truth["t_c_s"])
    if b is None or b.get("velocity_mps") is None:
        return {"measured": False, "error": "", "flags": [] if b is None else b.get("flags", []), "n_found": len(out["balls"])}
    cov = b.get("covariance", {}).get("matrix")
    cov_v = None if cov is None else np.array([[math.nan if x is None else x for x in r[3:6]] for r in cov[3:6]], float)
    return {"measured": True, "n_found": len(out["balls"]), **compare(b, truth, cov_v)}


def score_pair(ballscan: str, scenes: Path, name: str, angle: int, work: Path, recipe: Path | None = None) -> dict:
    """Views ``a000`` + ``aANGLE`` as a rig, in the world frame (view ``a000``'s), with ``recipe``'s settings."""
    truth = json.loads((scenes / f"{name}_a000.truth.json").read_text())
    rig = work / f"{name}_a{angle:03d}.rig.toml"
    rig.write_text(rig_toml(scenes, name, angle))
    cmd = [ballscan, "estimate", "--rig", str(rig), str(scenes / f"{name}_a000.png"), str(scenes / f"{name}_a{angle:03d}.png"),
           "--radius", repr(truth["radius_m"]), "--json"] + (["--recipe", str(recipe)] if recipe else [])
    out, err = run_json(cmd)
    if out is None:
        return {"measured": False, "error": err}
    b = nearest(out["balls"], truth["t_c_s"])
    if b is None or b.get("velocity_mps") is None or None in b["velocity_mps"]:
        # a velocity component the joint fit leaves undetermined is null: no direction, no speed
        return {"measured": False, "error": "", "flags": [] if b is None else b.get("flags", []), "n_found": len(out["balls"])}
    cov = b["covariance"]["matrix"]
    cov_v = np.array([[math.nan if x is None else x for x in r[4:7]] for r in cov[4:7]], float)
    row = {"measured": True, "n_found": len(out["balls"]), "cameras": b["cameras"], **compare(b, truth, cov_v)}
    row["inconsistent_cameras"] = b.get("inconsistent_cameras", [])
    row["delta_chi2"] = {k: v.get("delta_chi2") for k, v in b.get("per_camera", {}).items()}
    return row


def score_seed(ballscan: str, scenes: Path, name: str, pairs: list[int], work: Path, recipe: Path | None = None) -> dict:
    truth = json.loads((scenes / f"{name}_a000.truth.json").read_text())
    views = [0] + pairs
    row = {"scene": name, "kind": truth["kind"], "conditions": truth["conditions"],
           "alone": {f"a{a:03d}": score_view(ballscan, scenes, f"{name}_a{a:03d}", recipe) for a in views},
           "pair": {f"a{a:03d}": score_pair(ballscan, scenes, name, a, work, recipe) for a in pairs}}
    return row


# ------------------------------------------------------------------ tables


def _fmt(x: float, digits: int = 2) -> str:
    return "-" if x is None or not math.isfinite(x) else f"{x:.{digits}f}"


#: Flags under which an estimate's velocity is not a measurement (some component undetermined, or no convergence).
UNMEASURED_FLAGS = ("degenerate", "not_converged")


def measured(r: dict) -> bool:
    """A velocity reported and not flagged undetermined or unconverged."""
    return bool(r.get("measured")) and not any(f in r.get("flags", []) for f in UNMEASURED_FLAGS)


def summary_row(label: str, rs: list[dict], n_total: int) -> str:
    """One table row: measured, direction error median / 90th pct / worst, speed error, coverage."""
    m = [r for r in rs if measured(r)]
    if not m:
        return f"| {label} | 0/{n_total} | - | - | - | - | - | - | - |"
    d = np.array([r["dir_err_deg"] for r in m])
    sp = np.abs([r["speed_rel_err"] for r in m]) * 100
    m2 = [r["dir_m2"] for r in m if "dir_m2" in r]
    sz = [abs(r["speed_z"]) for r in m if "speed_z" in r]
    cov_d = 100 * np.mean(np.array(m2) <= CHI2_2_1SIGMA) if m2 else math.nan
    cov_s = 100 * np.mean(np.array(sz) <= 1.0) if sz else math.nan
    return (f"| {label} | {len(m)}/{n_total} | {_fmt(np.median(d), 3)} | {_fmt(np.percentile(d, 90), 2)} | {_fmt(d.max(), 2)} | "
            f"{_fmt(np.median(sp), 2)} | {sp.max():.3g} | {_fmt(cov_d, 0)} | {_fmt(cov_s, 0)} |")


HEADER = (
    "| estimate | measured | direction median [deg] | 90th pct [deg] | worst [deg] | speed error median (abs) [%] | worst [%] | direction 1-sigma coverage [%] | speed 1-sigma coverage [%] |",
    "|---|---|---|---|---|---|---|---|---|",
)


def tables(rows: list[dict], pairs: list[int]) -> list[str]:
    """Per pair: the joint estimate against each of its cameras alone, on the same balls."""
    out = []
    for a in pairs:
        key = f"a{a:03d}"
        out += ["", f"### Views a000 + {key} ({len(rows)} balls)", "", *HEADER]
        joint = [r["pair"][key] for r in rows]
        out.append(summary_row(f"a000 + {key} jointly", joint, len(rows)))
        for v in ("a000", key):
            out.append(summary_row(f"{v} alone", [r["alone"][v] for r in rows], len(rows)))
        same = [r for r in rows if measured(r["pair"][key]) and all(measured(r["alone"][v]) for v in ("a000", key))]
        out += ["", f"Same balls: the {len(same)} measured by the pair and by each of its views alone", "",
                *HEADER]
        out.append(summary_row(f"a000 + {key} jointly", [r["pair"][key] for r in same], len(same)))
        for v in ("a000", key):
            out.append(summary_row(f"{v} alone", [r["alone"][v] for r in same], len(same)))
        both = [r for r in rows if measured(r["pair"][key]) and "dual" in _cams(r["pair"][key])]
        out.append("")
        def n_flag(f: str) -> int:
            return sum(f in r["pair"][key].get("flags", []) for r in rows)
        out.append(f"- measured by both cameras jointly: {len(both)} of {len(rows)}; flagged single_camera: {n_flag('single_camera')}, "
                   f"inconsistent_camera: {n_flag('inconsistent_camera')}, degenerate: {n_flag('degenerate')}, not_converged: {n_flag('not_converged')}; "
                   f"no ball found or none measured: {sum(not r['pair'][key].get('measured') for r in rows)}")
        ratios = []
        for r in both:
            s = [r["alone"][v].get("v_sigma_max_mps") for v in ("a000", key)]
            s = [x for x in s if x is not None and math.isfinite(x)]
            j = r["pair"][key].get("v_sigma_max_mps")
            if s and j:
                ratios.append(min(s) / j)
        if ratios:
            out.append(f"- largest principal sigma of V, better camera alone / joint (balls both measured alone and jointly): "
                       f"median {statistics.median(ratios):.0f}x, min {min(ratios):.1f}x over {len(ratios)}")
        worse = [(r["scene"], r["pair"][key]["dir_err_deg"]) for r in both if r["pair"][key]["dir_err_deg"] > 1.0]
        if worse:
            out.append("- joint direction errors above 1 degree: " + ", ".join(f"{s} {e:.2f}" for s, e in worse))
    return out


def _cams(r: dict) -> str:
    return "dual" if len(r.get("cameras", [])) >= 2 else "one"


def per_ball(rows: list[dict], pairs: list[int]) -> list[str]:
    """Every ball: its direction error by each method (degrees), and the joint's flags."""
    head = ["scene"] + [f"a{a:03d} alone" for a in [0] + pairs] + [f"a000+a{a:03d}" for a in pairs]
    out = ["", "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        cells = [r["scene"]]
        for a in [0] + pairs:
            x = r["alone"][f"a{a:03d}"]
            cells.append(_fmt(x["dir_err_deg"], 3) if x.get("measured") else "-")
        for a in pairs:
            x = r["pair"][f"a{a:03d}"]
            cell = _fmt(x["dir_err_deg"], 3) if x.get("measured") else "-"
            fl = [f for f in x.get("flags", []) if f in ("single_camera", "inconsistent_camera", "not_converged", "degenerate")]
            cells.append(cell + (f" ({', '.join(fl)})" if fl else ""))
        out.append("| " + " | ".join(cells) + " |")
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=Path, default=DEFAULT_SCENES)
    ap.add_argument("--pairs", default="90,30", help="angles of the second view, degrees (with view a000)")
    ap.add_argument("--only", help="comma-separated scene names (pvNNNN)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--save", type=Path)
    ap.add_argument("--load", type=Path)
    ap.add_argument("--per-ball", action="store_true", help="also print every ball's direction errors")
    ap.add_argument("--ballscan", default=shutil.which("ballscan") or "ballscan")
    ap.add_argument("--recipe", type=Path, help="a recipe file for every estimate (ballscan estimate --recipe): the estimator's settings to score")
    a = ap.parse_args(argv)
    if a.load and a.recipe:
        ap.error("--recipe sets how balls are measured; --load measures none")
    pairs = [int(x) for x in a.pairs.split(",")]
    if a.load:
        rows = json.loads(a.load.read_text())
    else:
        names = seeds_in(a.scenes)
        if a.only:
            names = [n for n in names if n in set(a.only.split(","))]
        if not names:
            print(f"score_rig: no rendered rig views under {a.scenes}", file=sys.stderr)
            return 1
        with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(a.jobs) as ex:
            rows = list(ex.map(lambda n: score_seed(a.ballscan, a.scenes, n, pairs, Path(tmp), a.recipe), names))
        if a.save:
            a.save.write_text(json.dumps(rows, indent=1) + "\n")
    print("\n".join(tables(rows, pairs)))
    if a.per_ball:
        print("\n".join(per_ball(rows, pairs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
