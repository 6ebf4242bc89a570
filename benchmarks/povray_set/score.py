"""Score ``ballscan estimate`` on the POV-Ray validation set: one table per ball kind and condition.

    python benchmarks/povray_set/score.py [--split report|tune|all] [--scenes DIR] [--jobs 2]
                                          [--save RESULTS.json] [--load RESULTS.json] [--against BASE.json]
                                          [--recipe RECIPE.toml]

Each rendered scene is measured with ``ballscan estimate --json`` by both
methods (``--method fit`` and ``--method paper``), and each true ball's
Cramér-Rao speed sigma is taken from ``ballscan precision`` with the scene's
noise (the pixel noise and the ball/background contrast measured on the
clean render, the column gains' PRNU); beside it the bound with each pixel's
own contrast, the limb's, read off the clean render (``limb_bound.py``: a
shaded ball's limb is not its centre, a cut ball shows only part of it, a
defocused one is blurred).  Estimated balls are matched to true
ones by the nearest ``t_c_s``, as ``shared/tools/score_scenes.py`` does.

Columns (fit/paper where two values): balls measured (a speed reported), the
median and worst relative speed error, the median relative error of the
transverse speed ``hypot(V.x, V.y)`` (``speed_transverse_mps``: what one
line camera sees directly, free of the weak depth axis), the median direction
error (degrees between the velocities with V.x >= 0), the share of errors
within 1 and 3 reported sigmas for the speed, for each direction angle
(``direction_deg`` against ``direction_sigma_deg``) and, for the fit, for the
depth velocity V.z and ``|V.x|`` (the speed along the lane, the line camera's best-measured component); the fit's median speed error over the Cramér-Rao sigma, of the flat ball and of the limb's contrast; the ratio of the fit's median speed error to the paper
method's on the balls both measured, and the number of the fit's speed errors
beyond 4 reported sigmas (the paper method reports no sigma).  Rows: all balls, the subset with |V.z| <= 0.1 |V|, at least
100 lines and not cut, each ball kind, each condition tag of the truth files.

``--against BASE.json`` (rows saved from another version of the estimator on
the same scenes) adds a paired comparison of the fit, ball by ball: the
medians of about a hundred heavy-tailed errors move more than the balls do,
so a change is judged by the signed-rank test of each ball's log error ratio.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
METHODS = ("fit", "paper")
#: a ball whose limb puts more than this share of its information on pixels of the other sign than its centre
LIMB_OTHER_SIGN = 0.1

from limb_bound import limb_bounds  # noqa: E402


def truth_balls(t: dict) -> list[dict]:
    return t["balls"] if "balls" in t else [t]


def run_json(cmd: list[str], timeout: float = 300) -> tuple[dict | None, str]:
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


def precision_args(cam: Path, ball: dict, prnu: float) -> list[str] | None:
    """``ballscan precision``'s arguments for one true ball's bound with its scene's noise, None where the truth has no contrast."""
    pi = ball.get("precision_inputs") or {}
    if not pi or pi["contrast_dn"] <= 0:
        return None
    v = ball["velocity_mps"]
    return ["precision", "--camera", str(cam), "--radius", repr(ball["radius_m"]),
            f"--velocity={abs(v[0])!r},{v[1]!r},{v[2]!r}", "--position=" + ",".join(repr(x) for x in ball["position_m"]),
            "--pixel-noise", repr(pi["pixel_sigma_dn"]), "--contrast", repr(pi["contrast_dn"]),
            "--prnu", repr(prnu), "--json"]


def cramer_rao(ballscan: str, cam: Path, ball: dict, prnu: float) -> float | None:
    """Cramér-Rao 1-sigma of the speed (m/s) of one true ball with its scene's noise."""
    args = precision_args(cam, ball, prnu)
    out, _ = run_json([ballscan, *args]) if args else (None, "")
    return out["bounds"][0].get("speed_sigma_mps") if out else None


def angle_deg(a: list[float], b: list[float]) -> float:
    a = [abs(a[0])] + list(a[1:])
    b = [abs(b[0])] + list(b[1:])
    na, nb = math.dist((0, 0, 0), a), math.dist((0, 0, 0), b)
    c = sum(x * y for x, y in zip(a, b)) / (na * nb + 1e-300)
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def compare(est: dict | None, tb: dict) -> dict:
    """Errors of one estimate against one true ball (``None`` fields where nothing was measured)."""
    row = {"measured": False}
    if not est or est.get("speed_mps") is None:
        row["flags"] = est.get("flags", []) if est else ["not_found"]
        if est and est.get("speed_transverse_mps") is not None:
            row.update(_transverse_only(est, tb))
        return row
    s_true = tb["speed_mps"]
    err = (est["speed_mps"] - s_true) / s_true
    row.update(measured=True, speed_err=err, flags=est.get("flags", []))
    v = tb["velocity_mps"]
    row["transverse_err"] = _transverse_err(est, tb)
    ev, es = est.get("velocity_mps"), est.get("velocity_sigma_mps")
    ok_vz = ev is not None and es is not None and ev[2] is not None and es[2]
    row["z_vz"] = abs(ev[2] - v[2]) / es[2] if ok_vz else None
    # |vx|: the crossing direction's sign aside, what the line rate and the ball's passage fix
    ok_vx = ev is not None and es is not None and ev[0] is not None and es[0]
    row["z_vx"] = abs(abs(ev[0]) - abs(v[0])) / es[0] if ok_vx else None
    # the speed error's first-order part from |vx| alone (relative): what the passage's duration fixes
    row["speed_err_vx"] = (abs(ev[0]) - abs(v[0])) * abs(v[0]) / s_true**2 if ev is not None and ev[0] is not None else None
    row["residual_rms_px"] = est.get("residual_rms_px")
    sig = est.get("speed_sigma_mps")
    row["z_speed"] = abs(est["speed_mps"] - s_true) / sig if sig else None
    try:
        row["dir_err_deg"] = angle_deg(est["velocity_mps"], tb["velocity_mps"])
    except (TypeError, KeyError, IndexError):
        row["dir_err_deg"] = None
    for name in ("psi_y", "psi_z"):
        row[f"z_{name}"] = _z_angle(est, tb, name)
    return row


def _true_transverse(est: dict, tb: dict) -> float:
    """The true ball's speed across the estimate's transverse axis: ``hypot(V.x, V . axis)``, ``axis`` (0, 1, 0) unless the estimate gives one."""
    v = tb["velocity_mps"]
    axis = est.get("transverse_axis") or (0.0, 1.0, 0.0)
    return math.hypot(v[0], sum(a * b for a, b in zip(v, axis)))


def _transverse_err(est: dict, tb: dict) -> float | None:
    """Relative error of the estimate's ``speed_transverse_mps`` (None where it has none)."""
    vt_true, vt = _true_transverse(est, tb), est.get("speed_transverse_mps")
    return (vt - vt_true) / vt_true if vt is not None and vt_true > 0 else None


def _z_angle(est: dict, tb: dict, name: str) -> float | None:
    """|error| / reported sigma of the direction angle ``name`` (``psi_y`` or ``psi_z``; None where not reported)."""
    k = ("psi_y", "psi_z").index(name)
    d, ds = est.get("direction_deg"), est.get("direction_sigma_deg")
    ok = d is not None and ds is not None and d[k] is not None and ds[k]
    return abs(d[k] - tb["direction_deg"][name]) / ds[k] if ok else None


def _transverse_only(est: dict, tb: dict) -> dict:
    """Errors of what an estimate whose velocity along the line of sight is undetermined still reports: the speed across it and ``psi_y``."""
    vt, vt_sig = est["speed_transverse_mps"], est.get("speed_transverse_sigma_mps")
    z_vt = abs(vt - _true_transverse(est, tb)) / vt_sig if vt_sig else None
    return {"transverse_only": True, "transverse_err": _transverse_err(est, tb), "z_vt": z_vt, "z_psi_y": _z_angle(est, tb, "psi_y")}


def score_scene(ballscan: str, scenes: Path, name: str, recipe: Path | None = None) -> list[dict]:
    """Rows (one per true ball) of one scene, both methods (each with ``recipe``'s other settings, ``estimate --recipe``) and the bound."""
    truth = json.loads((scenes / f"{name}.truth.json").read_text())
    cam = scenes / f"{name}.camera.toml"
    balls = truth_balls(truth)
    lr = float(_camera_value(cam, "line_rate_hz"))
    f = float(_camera_value(cam, "focal_px"))
    ests = {}
    for m in METHODS:
        cmd = [ballscan, "estimate", str(scenes / f"{name}.png"), "--camera", str(cam),
               "--radius", repr(balls[0]["radius_m"]), "--method", m, "--json"] + (["--recipe", str(recipe)] if recipe else [])
        out, why = run_json(cmd)
        ests[m] = (out or {}).get("balls", []), why, len((out or {}).get("balls", []))
    rows = []
    for tb, lb in zip(balls, limb_bounds(scenes, name)):
        cr_limb = None if lb is None else lb.speed_sigma_mps
        v = tb["velocity_mps"]
        lines = lr * (2 * tb["radius_m"] + tb["position_m"][2] / f) / abs(v[0])
        row = {"scene": name, "kind": truth["kind"], "conditions": truth["conditions"], "cut": truth["cut"],
               "split": truth["split"], "lines": lines, "vz_share": abs(v[2]) / tb["speed_mps"],
               "n_true": len(balls), "cr_speed_sigma": cramer_rao(ballscan, cam, tb, truth["noise"]["prnu_sigma"]),
               "cr_limb_speed_sigma": cr_limb, "limb_other_sign": None if lb is None else lb.other_sign_share}
        for m in METHODS:
            found, why, n_found = ests[m]
            est = min(found, key=lambda e: abs((e.get("t_c_s") or 0) - tb["t_c_s"])) if found else None
            r = compare(est, tb)
            r["error"], r["n_found"] = why, n_found
            row[m] = r
        if row["fit"].get("measured") and row["cr_speed_sigma"]:
            row["fit"]["z_cr"] = abs(row["fit"]["speed_err"]) * tb["speed_mps"] / row["cr_speed_sigma"]
            if row["fit"].get("speed_err_vx") is not None:
                row["fit"]["z_cr_vx"] = abs(row["fit"]["speed_err_vx"]) * tb["speed_mps"] / row["cr_speed_sigma"]
        if row["fit"].get("measured") and cr_limb:
            row["fit"]["z_cr_limb"] = abs(row["fit"]["speed_err"]) * tb["speed_mps"] / cr_limb
        rows.append(row)
    return rows


def _camera_value(path: Path, key: str) -> str:
    for line in path.read_text().splitlines():
        if line.split("=")[0].strip() == key:
            return line.split("=", 1)[1].split("#")[0].strip()
    raise KeyError(f"{path}: no {key}")


def _med(xs: list[float]) -> float | None:
    return statistics.median(xs) if xs else None


def _fmt(v: float | None, spec: str) -> str:
    return "-" if v is None else format(v, spec)


def summarise(rows: list[dict]) -> list[str]:
    """The table's cells for one group of balls."""
    cells = [str(len(rows))]
    per = {}
    for m in METHODS:
        ok = [r[m] for r in rows if r[m].get("measured")]
        errs = [abs(r["speed_err"]) * 100 for r in ok]
        terrs = [abs(r["transverse_err"]) * 100 for r in ok if r.get("transverse_err") is not None]
        dirs = [r["dir_err_deg"] for r in ok if r.get("dir_err_deg") is not None]

        def cover(key: str, k: float) -> float | None:
            zs = [r[key] for r in ok if r.get(key) is not None]
            return 100 * sum(z <= k for z in zs) / len(zs) if zs else None

        per[m] = dict(n=len(ok), med=_med(errs), worst=max(errs) if errs else None, dir=_med(dirs), tmed=_med(terrs),
                      **{f"c{k}_{key}": cover(f"z_{key}", k) for k in (1, 3) for key in ("speed", "psi_y", "psi_z", "vz", "vx")})
    pair = lambda key, spec: f"{_fmt(per['fit'][key], spec)} / {_fmt(per['paper'][key], spec)}"  # noqa: E731
    cells += [f"{per['fit']['n']} / {per['paper']['n']}", pair("med", ".3f"), pair("worst", ".2f"),
              pair("tmed", ".3f"), pair("dir", ".2f")]
    for key in ("speed", "psi_y", "psi_z"):
        cells += [pair(f"c1_{key}", ".0f"), pair(f"c3_{key}", ".0f")]
    for key in ("vz", "vx"):
        cells.append(f"{_fmt(per['fit'][f'c1_{key}'], '.0f')} / {_fmt(per['fit'][f'c3_{key}'], '.0f')}")
    both = [r for r in rows if r["fit"].get("measured") and r["paper"].get("measured")]
    med_fit = _med([abs(r["fit"]["speed_err"]) for r in both])
    med_paper = _med([abs(r["paper"]["speed_err"]) for r in both])
    cells.append(_fmt(med_fit / med_paper if both and med_paper else None, ".2f"))
    beyond = [r["fit"]["z_speed"] > 4 for r in rows if r["fit"].get("z_speed") is not None]
    cells.append(f"{sum(beyond)}" if beyond else "-")
    for key in ("z_cr", "z_cr_limb"):
        cells.append(_fmt(_med([r["fit"][key] for r in rows if r["fit"].get(key) is not None]), ".2f"))
    return cells


def table(rows: list[dict]) -> list[str]:
    """The Markdown table: all balls, the clean subset, each kind, each condition."""
    groups = [("all balls", rows),
              ("|V.z| <= 0.1|V|, >= 100 lines, not cut",
               [r for r in rows if r["vz_share"] <= 0.1 and r["lines"] >= 100 and r["cut"] == "none"])]
    for k in sorted({r["kind"] for r in rows}):
        groups.append((f"kind {k}", [r for r in rows if r["kind"] == k]))
    for c in sorted({c for r in rows for c in r["conditions"]}):
        groups.append((c, [r for r in rows if c in r["conditions"]]))
    # how well the fit's model matched the ball: its edges' residual RMS (a measured ball's only; rows scored before it was kept have none)
    for name, lo, hi in (("fit residual < 0.05 px", 0.0, 0.05), ("fit residual 0.05-0.1 px", 0.05, 0.1), ("fit residual >= 0.1 px", 0.1, math.inf)):
        groups.append((name, [r for r in rows if r["fit"].get("residual_rms_px") is not None and lo <= r["fit"]["residual_rms_px"] < hi]))
    # the limb's information on pixels of the other sign than the centre (limb_bound.py): more than a tenth of it, or less
    with_sign = [r for r in rows if r.get("limb_other_sign") is not None]
    groups.append(("limb of both signs (> 10 % other)", [r for r in with_sign if r["limb_other_sign"] > LIMB_OTHER_SIGN]))
    groups.append(("limb of one sign", [r for r in with_sign if r["limb_other_sign"] <= LIMB_OTHER_SIGN]))
    head = ["group", "balls", "measured", "speed err median %", "worst %", "transverse speed err median %",
            "direction err median deg", "speed 1σ %", "speed 3σ %", "psi_y 1σ %", "psi_y 3σ %", "psi_z 1σ %", "psi_z 3σ %",
            "V.z 1σ / 3σ % (fit)", "|V.x| 1σ / 3σ % (fit)", "fit / paper median (same balls)", "fit > 4σ", "err / CR σ median (fit)",
            "err / limb CR σ median (fit)"]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for name, g in groups:
        if g:
            out.append("| " + " | ".join([name] + summarise(g)) + " |")
    return out


def vx_part_lines(rows: list[dict]) -> list[str]:
    """The fit's err / CR against that of its ``|V.x|`` part alone: what is left is along the line of sight."""
    both = [r["fit"] for r in rows if r["fit"].get("z_cr") is not None and r["fit"].get("z_cr_vx") is not None]
    if not both:
        return []
    return ["", f"err / CR σ median (fit, {len(both)} balls): {_fmt(_med([f['z_cr'] for f in both]), '.2f')}; "
            f"of the speed error's first-order part from |V.x| alone: {_fmt(_med([f['z_cr_vx'] for f in both]), '.2f')}"]


def transverse_lines(rows: list[dict]) -> list[str]:
    """The fit's balls with the speed undetermined (one camera's line of sight) but the speed across it and ``psi_y`` reported."""
    t = [r["fit"] for r in rows if r["fit"].get("transverse_only")]
    if not t:
        return []
    errs = [abs(r["transverse_err"]) * 100 for r in t if r.get("transverse_err") is not None]

    def cover(key: str, k: float) -> str:
        zs = [r[key] for r in t if r.get(key) is not None]
        return f"{100 * sum(z <= k for z in zs) / len(zs):.0f}" if zs else "-"

    return ["", f"fit, speed undetermined but the speed across the line of sight reported: {len(t)} balls; its error median "
            f"{_fmt(_med(errs), '.2f')} %, worst {_fmt(max(errs) if errs else None, '.2f')} %; within 1 / 3 sigma: "
            f"that speed {cover('z_vt', 1)} / {cover('z_vt', 3)} %, psi_y {cover('z_psi_y', 1)} / {cover('z_psi_y', 3)} %"]


def _ball_keys(rows: list[dict]) -> list[tuple]:
    """Each row's true ball: its scene, its line count and depth share (the truth's, the same in every run) and its place among equals."""
    seen: dict[tuple, int] = {}
    keys = []
    for r in rows:
        ball = (r["scene"], round(r["lines"], 6), round(r["vz_share"], 9))
        keys.append(ball + (seen.get(ball, 0),))
        seen[ball] = keys[-1][-1] + 1
    return keys


def paired_lines(rows: list[dict], base: list[dict]) -> list[str]:
    """The fit's errors in ``rows`` against ``base``'s on the same true balls: counts, median and geometric-mean ratios, Wilcoxon p.

    For the speed (balls measured in both) and the speed across the line of
    sight (balls with it in both): how many errors grew or shrank by more
    than 10 %, the median and the geometric mean of ``|err| / |err_base|``,
    and the two-sided signed-rank test's p of their logarithms over the
    balls whose error changed by more than 1e-9 (``-`` with fewer than 6).

    Raises
    ------
    ValueError
        No ball of ``rows`` is in ``base`` (rows of another split or set).
    """
    from scipy.stats import wilcoxon

    old = dict(zip(_ball_keys(base), base))
    keys = _ball_keys(rows)
    pairs = [(old[k]["fit"], r["fit"]) for k, r in zip(keys, rows) if k in old]
    if not pairs:
        raise ValueError("--against: no ball of these rows is in the base rows (another split or scene set?)")
    only_new = sum(n.get("measured") and not b.get("measured") for b, n in pairs)
    only_old = sum(b.get("measured") and not n.get("measured") for b, n in pairs)
    out = ["", f"against the base rows: {len(pairs)} balls in both ({len(rows) - len(pairs)} only here, {len(base) - len(pairs)} only in the base); "
           f"speed measured only now {only_new}, only in the base {only_old}",
           "| error | balls | larger / smaller by > 10 % | median ratio | geometric-mean ratio | Wilcoxon p |", "|---|---|---|---|---|---|"]
    for key, label, ok in (("speed_err", "speed", lambda f: f.get("measured")),
                           ("transverse_err", "speed across the line of sight", lambda f: True)):
        logs = [math.log(abs(n[key]) / abs(b[key])) for b, n in pairs
                if ok(b) and ok(n) and b.get(key) and n.get(key)]
        if not logs:
            continue
        changed = [x for x in logs if abs(x) > 1e-9]
        p = f"{wilcoxon(changed).pvalue:.3f}" if len(changed) >= 6 else "-"
        up, down = sum(x > math.log(1.1) for x in logs), sum(x < -math.log(1.1) for x in logs)
        out.append(f"| {label} | {len(logs)} | {up} / {down} | {math.exp(statistics.median(logs)):.3f} | "
                   f"{math.exp(statistics.fmean(logs)):.3f} | {p} |")
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=Path, default=HERE / "scenes")
    ap.add_argument("--split", choices=("report", "tune", "all"), default="report")
    ap.add_argument("--only", default="pv*", help="glob on scene names (default the main set, pv*; pu* the uniform balls)")
    ap.add_argument("--ballscan", default=shutil.which("ballscan") or "ballscan")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--save", type=Path, help="write the per-ball rows (JSON) here")
    ap.add_argument("--load", type=Path, help="tabulate saved rows instead of measuring")
    ap.add_argument("--recipe", type=Path, help="a recipe file for every estimate (ballscan estimate --recipe): the estimator's settings to score")
    ap.add_argument("--against", type=Path, help="saved rows of another version: compare the fit's errors ball by ball")
    a = ap.parse_args(argv)
    if a.load and a.recipe:
        ap.error("--recipe sets how balls are measured; --load measures none")
    if a.load:
        rows = json.loads(a.load.read_text())
    else:
        names = []
        for p in sorted(a.scenes.glob(f"{a.only}.truth.json")):
            t = json.loads(p.read_text())
            if (a.split == "all" or t["split"] == a.split) and (a.scenes / t["image"]).exists():
                names.append(t["scene"])
        def one(name: str) -> list[dict]:
            rows = score_scene(a.ballscan, a.scenes, name, a.recipe)
            print(f"{name} scored", file=sys.stderr, flush=True)
            return rows

        with ThreadPoolExecutor(max_workers=a.jobs) as pool:
            rows = [r for rs in pool.map(one, names) for r in rs]
        if a.save:
            a.save.write_text(json.dumps(rows, indent=1) + "\n")
    print(f"{len({r['scene'] for r in rows})} scenes, {len(rows)} balls ({a.split} half)")
    print("\n".join(table(rows)))
    print("\n".join(vx_part_lines(rows) + transverse_lines(rows)))
    failed = [f"{r['scene']} {m}: {r[m]['error'] or 'not measured'} flags {','.join(r[m].get('flags', []))}"
              for r in rows for m in METHODS if not r[m].get("measured")]
    if failed:
        print(f"\nnot measured ({len(failed)}):")
        print("\n".join("  " + f for f in failed))
    if a.against:
        try:
            print("\n".join(paired_lines(rows, json.loads(a.against.read_text()))))
        except ValueError as exc:
            print(f"score.py: {a.against}: {exc}", file=sys.stderr)
            return 2
    return 0


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    sys.exit(main())
