"""New noise on the POV-Ray set's clean renders: how far the estimate's scatter and its bias are from its reported sigma, scene by scene.

    python benchmarks/povray_set/renoise.py [--split tune] [--every K] [--reps N] [--jobs J] [--recipe R.toml] [--plane | --twin] [NAME ...]

Each scene's noise-free render (``scenes/clean/``, linear grey) gets ``N``
new draws of the scene's own sensor model (``render.add_noise``: shot and
read noise, PRNU column gains, the bit depth, its dead or hot column, with
other seeds than the committed image's) and ``ballscan estimate --json``
runs on each, in-process.  One coverage figure over ~110 balls mixes two
things a change must tell apart: the scatter that the noise causes, which
the reported sigma is meant to describe, and an offset that every draw of
the same scene shares (the model's error on that scene's limb, shading and
background, and any bias of the estimator in the noise).  Per scene and
quantity (``|V.x|``, the speed across the line of sight ``|(V.x, V.y)|``,
``V.z``, the speed and the direction angles ``psi_y`` and ``psi_z``; each
against its reported sigma, the median over the draws):

- ``std``: the standard deviation over the draws / sigma (1 for a sigma
  that describes the noise's scatter);
- ``bias``: (mean over the draws - truth) / sigma;
- ``clean``: the error on the noise-free render / sigma (the model's part
  of the bias: ``bias - clean`` is what the noise adds to it).

``--plane`` gives each estimate a known constraint, the plane the true path
rolls on with its normal nearest the line of sight (the case where the
constraint, not the image, fixes the depth motion), and the camera the true
crossing direction; the speed across the line of sight and the direction
angles are then not compared (the constrained fit's JSON gives elevation
and azimuth instead).

Without ``--plane`` the speed's scatter and bias are also compared with
the scene's Cramér-Rao sigma (the pixel bound with its sensor noise, as
``score.py`` takes it: ``std_cr``, ``bias_cr``) and with the bound of the
ball's own limb (``limb_bound.py``: ``std_cr_limb``, ``bias_cr_limb``; not
with ``--twin``), grouped by the noise-free fit's edge residual: how far
the fit is from an efficient estimator, and whether by noise or by the
model's error.

``--twin`` draws the same noise on ballscan's own render of each scene's
ball instead (its camera, motion and line count, a uniform disc at the
truth's ball and background levels): the fit's scatter against the bound
there is the estimator's efficiency on a ball its model describes exactly.

Scenes with one true ball that the default fit measures (velocity
determined) on at least 3 draws.  The last lines give the medians over the
scenes of ``std``, ``|bias|``, the share of draws within 1 sigma and the
RMS error.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import math
import sys
from pathlib import Path

import numpy as np
from PIL import Image

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from render import add_noise  # noqa: E402
from limb_bound import limb_speed_sigma  # noqa: E402

#: the quantities compared: |V.x|, |(V.x, V.y)|, V.z, the speed (m/s) and the direction angles (degrees)
QUANTITIES = ("vx", "across", "vz", "speed", "psi_y", "psi_z")


UNITS = {"vx": "m/s", "across": "m/s", "vz": "m/s", "speed": "m/s", "psi_y": "deg", "psi_z": "deg"}


def _values(ball: dict) -> dict[str, tuple[float, float] | None]:
    """Each quantity's (value, sigma) in one ``--json`` ball, None where the fit left it undetermined."""
    v, s = ball.get("velocity_mps"), ball.get("velocity_sigma_mps")
    out: dict[str, tuple[float, float] | None] = dict.fromkeys(QUANTITIES)
    if v is None or s is None or v[0] is None:
        return out
    out["vx"] = (abs(v[0]), s[0])
    out["vz"] = (v[2], s[2]) if v[2] is not None and s[2] is not None else None
    if ball.get("speed_mps") is not None and ball.get("speed_sigma_mps") is not None:
        out["speed"] = (ball["speed_mps"], ball["speed_sigma_mps"])
    if ball.get("speed_transverse_mps") is not None and ball.get("speed_transverse_sigma_mps") is not None:
        out["across"] = (ball["speed_transverse_mps"], ball["speed_transverse_sigma_mps"])
    d, ds = ball.get("direction_deg"), ball.get("direction_sigma_deg")
    for k, name in enumerate(("psi_y", "psi_z")):
        if d is not None and ds is not None and d[k] is not None and ds[k] is not None:
            out[name] = (d[k], ds[k])
    return out


def _truth(tb: dict) -> dict[str, float]:
    v = np.asarray(tb["velocity_mps"], dtype=float)
    d = tb["direction_deg"]
    return {"vx": abs(v[0]), "across": math.hypot(v[0], v[1]), "vz": v[2], "speed": float(np.linalg.norm(v)), "psi_y": d["psi_y"], "psi_z": d["psi_z"]}


def plane_through_path(truth: dict) -> str:
    """The ``--constraint`` of the plane the true path rolls on whose normal is nearest the line of sight's axis ``z``.

    The normal ``n`` is ``z`` less its component along the velocity (so the
    velocity lies in the plane and the plane pins the depth motion), and
    ``D = n . X(t_c) - R`` puts the ball's centre its radius above it.
    """
    v = np.asarray(truth["velocity_mps"], dtype=float)
    u = v / np.linalg.norm(v)
    n = np.array([0.0, 0.0, 1.0]) - u[2] * u
    n /= np.linalg.norm(n)
    d = float(n @ np.asarray(truth["position_m"], dtype=float)) - truth["radius_m"]
    return "plane:" + ",".join(repr(float(x)) for x in (*n, d))


def _camera_with_crossing(scenes: Path, name: str, truth: dict, tmp: Path) -> Path:
    """A copy of the scene's camera file stating the true crossing direction (a constraint's plane is not symmetric in ``V.x``)."""
    path = tmp / f"{name}.camera.toml"
    sign = "+x" if truth["velocity_mps"][0] > 0 else "-x"
    path.write_text((scenes / f"{name}.camera.toml").read_text() + f'crossing = "{sign}"\n')
    return path


def _estimate(image: Path, camera: Path, radius_m: float, t_c_s: float, extra: list[str]) -> dict | None:
    """The ``--json`` ball nearest in ``t_c`` to the truth's, None where none was found."""
    from ballscan.cli.app import main

    buf = io.StringIO()
    with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(io.StringIO()):
        code = main(["estimate", str(image), "--camera", str(camera), "--radius", repr(radius_m), "--json", *extra])
    balls = json.loads(buf.getvalue())["balls"] if code == 0 else []
    return min(balls, key=lambda b: abs((b.get("t_c_s") or 0.0) - t_c_s)) if balls else None


def cramer_rao_speed(scenes: Path, name: str, truth: dict) -> float | None:
    """The Cramér-Rao 1-sigma of the true ball's speed (m/s) with the scene's sensor noise (``ballscan precision``, in-process).

    The bound of any unbiased estimator on the pixels, for a uniform disc of
    the contrast and pixel noise of the truth's ``precision_inputs`` (as the
    set's scoring takes it); None where the truth has none.
    """
    from ballscan.cli.app import main
    from score import precision_args

    args = precision_args(scenes / f"{name}.camera.toml", truth, truth["noise"]["prnu_sigma"])
    if args is None:
        return None
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf), contextlib.redirect_stderr(io.StringIO()):
        code = main(args)
    return json.loads(buf.getvalue())["bounds"][0].get("speed_sigma_mps") if code == 0 else None


def twin_render(scenes: Path, name: str, truth: dict) -> np.ndarray:
    """ballscan's own noise-free render of the scene's ball (linear grey): its camera, motion and line count, a uniform disc at the truth's ball and background levels.

    What the scene would be if ballscan's model of it were exact: with the
    scene's sensor model on it, the fit's scatter against the bound is the
    estimator's efficiency alone (no shading, texture, flicker or defocus).
    A level beyond 1 (a flickering backdrop at its peak) is clipped; the
    bound keeps the truth's contrast.
    """
    from ballscan.geometry.camera import load_camera
    from ballscan.geometry.motion import BallMotion
    from ballscan.model.render import Appearance, render

    pi = truth["precision_inputs"]
    ball = BallMotion(truth["radius_m"], truth["t_c_s"], tuple(truth["position_m"]), tuple(truth["velocity_mps"]))
    camera = load_camera(scenes / f"{name}.camera.toml")
    # the background's level is the clean render's, flicker included, which may pass 1 (clipped by the sensor's full well)
    level = lambda x: min(max(float(x), 0.0), 1.0)  # noqa: E731
    out = render(camera, [(ball, Appearance(ball_level=level(pi["ball_level"]), shading=False))], truth["image_shape"][0],
                 background_level=level(pi["background_level"]), noise="none")
    return out.clean


def scene_row(scenes: Path, name: str, reps: int, extra: list[str], tmp: Path, plane: bool = False, twin: bool = False) -> dict | None:
    """One scene's figures (see the module's notes), None where it does not qualify.

    With ``plane`` every estimate has the true path's plane as a known
    constraint (:func:`plane_through_path`) and its camera the true crossing.
    With ``twin`` the draws (and the noise-free estimate) are made on
    :func:`twin_render` instead of the POV-Ray render.
    """
    if plane and twin:
        raise ValueError("plane and twin: a constraint's scene is the POV-Ray render's")
    truth = json.loads((scenes / f"{name}.truth.json").read_text())
    if "balls" in truth:
        return None
    camera = scenes / f"{name}.camera.toml"
    if plane:
        camera = _camera_with_crossing(scenes, name, truth, tmp)
        extra = [*extra, "--constraint", plane_through_path(truth)]
    clean_path = scenes / "clean" / f"{name}.png"
    if twin:
        if not truth.get("precision_inputs"):
            return None
        y = twin_render(scenes, name, truth)
        clean_path = tmp / f"{name}_twin.png"
        Image.fromarray(np.clip(np.rint(y * 65535), 0, 65535).astype(np.uint16)).save(clean_path)
    else:
        y = np.asarray(Image.open(clean_path)).astype(float) / 65535.0
    true = _truth(truth)
    draws: dict[str, list[tuple[float, float]]] = {q: [] for q in QUANTITIES}
    for k in range(reps):
        path = tmp / f"{name}_{k}.png"
        Image.fromarray(add_noise(y, truth["noise"], 10_000 + truth["seed"] * 100 + k)).save(path)
        ball = _estimate(path, camera, truth["radius_m"], truth["t_c_s"], extra)
        path.unlink()
        for q, vs in (_values(ball) if ball else {}).items():
            if vs is not None and math.isfinite(vs[0]) and math.isfinite(vs[1]) and vs[1] > 0:
                draws[q].append(vs)
    # the noise-free render itself (16-bit linear grey)
    clean_ball = _estimate(clean_path, camera, truth["radius_m"], truth["t_c_s"], extra) if len(draws["vx"]) >= 3 else None
    clean = _values(clean_ball) if clean_ball else dict.fromkeys(QUANTITIES)
    if plane:
        camera.unlink()
    if twin:
        clean_path.unlink()
    if len(draws["vx"]) < 3:
        return None
    row = {"scene": name, "conditions": truth["conditions"], "n": len(draws["vx"]),
           "residual_rms_px": clean_ball.get("residual_rms_px") if clean_ball else None,
           "cr_speed_sigma_mps": None if plane else cramer_rao_speed(scenes, name, truth),
           "cr_limb_speed_sigma_mps": None if plane or twin else limb_speed_sigma(scenes, name)[0]}
    for q in QUANTITIES:
        if len(draws[q]) < 3:
            continue
        val, sig = (np.array(a) for a in zip(*draws[q]))
        s = float(np.median(sig))
        c = clean.get(q)
        row[q] = {
            "std": float(np.std(val, ddof=1)) / s,
            "bias": float(np.mean(val) - true[q]) / s,
            "clean": (c[0] - true[q]) / s if c is not None else None,
            "rms": float(np.sqrt(np.mean((val - true[q]) ** 2))),
            "cover1": float(np.mean(np.abs(val - true[q]) <= sig)),
        }
    for key, cr in (("cr", row["cr_speed_sigma_mps"]), ("cr_limb", row["cr_limb_speed_sigma_mps"])):
        if "speed" in row and cr:
            val = np.array([v for v, _ in draws["speed"]])
            row["speed"][f"std_{key}"] = float(np.std(val, ddof=1)) / cr
            row["speed"][f"bias_{key}"] = float(np.mean(val) - true["speed"]) / cr
    return row


def _table(rows: list[dict]) -> None:
    print(f"{'scene':<8} {'n':>2}  " + "  ".join(f"{q + ' std / bias / clean':>27}" for q in QUANTITIES) + "  conditions")
    for r in rows:
        cells = []
        for q in QUANTITIES:
            f = r.get(q)
            cells.append(f"{'-':>27}" if f is None else f"{f['std']:8.2f} {f['bias']:+8.2f} " + (f"{f['clean']:+8.2f}" if f["clean"] is not None else f"{'-':>8}"))
        print(f"{r['scene']:<8} {r['n']:>2}  " + "  ".join(cells) + "  " + ",".join(r["conditions"]))
    print()
    for q in QUANTITIES:
        fs = [r[q] for r in rows if q in r]
        if not fs:
            continue
        med = lambda key, f=abs: float(np.median([f(x[key]) for x in fs]))  # noqa: E731
        cl = [abs(x["clean"]) for x in fs if x["clean"] is not None]
        print(
            f"{q:<7} {len(fs):3d} scenes: std / sigma median {med('std', float):.2f}, |bias| / sigma median {med('bias'):.2f}"
            f" (noise-free {np.median(cl) if cl else math.nan:.2f}), within 1 sigma {100 * med('cover1', float):.0f} % (median scene),"
            f" RMS error median {med('rms', float):.4g} {UNITS[q]}"
        )
    _bound_table(rows)


#: the groups of :func:`_bound_table`: the noise-free render's edge residual RMS (px)
RESIDUAL_GROUPS = ((0.0, 0.05), (0.05, 0.1), (0.1, math.inf))


def _bound_table(rows: list[dict]) -> None:
    """The speed's scatter and bias over the draws against its Cramér-Rao sigma, by the noise-free fit's edge residual."""
    fs = [r for r in rows if "std_cr" in r.get("speed", {})]
    if not fs:
        return
    print()
    print("speed against its Cramér-Rao sigma (medians over the scenes; an efficient, unbiased fit has scatter / CR 1, bias / CR 0):")
    groups = [("all", fs)] + [
        (f"residual {lo:g}-{hi:g} px", [r for r in fs if r["residual_rms_px"] is not None and lo <= r["residual_rms_px"] < hi])
        for lo, hi in RESIDUAL_GROUPS
    ]
    groups.append(("no noise-free fit", [r for r in fs if r["residual_rms_px"] is None]))
    for label, g in groups:
        if g:
            limb = [r["speed"] for r in g if "std_cr_limb" in r["speed"]]
            print(f"  {label:<22} {len(g):3d} scenes: scatter / CR {np.median([r['speed']['std_cr'] for r in g]):6.2f},"
                  f" |bias| / CR {np.median([abs(r['speed']['bias_cr']) for r in g]):6.2f}"
                  + (f"; over the limb's bound ({len(limb)}): {np.median([f['std_cr_limb'] for f in limb]):6.2f},"
                     f" {np.median([abs(f['bias_cr_limb']) for f in limb]):6.2f}" if limb else ""))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="*", help="scenes (default: every K-th single-ball scene of the split)")
    ap.add_argument("--scenes", type=Path, default=HERE / "scenes")
    ap.add_argument("--split", default="tune", choices=("tune", "report", "all"))
    ap.add_argument("--only", default="pv*", help="glob on scene names (default the main set, pv*; pu* the uniform balls)")
    ap.add_argument("--every", type=int, default=4, help="every K-th scene of the split (default 4)")
    ap.add_argument("--reps", type=int, default=8, help="noise draws per scene (default 8)")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--recipe", type=Path, help="a recipe file for every estimate")
    ap.add_argument("--plane", action="store_true", help="give every estimate the true path's plane as a known constraint (--constraint), and the true crossing")
    ap.add_argument("--twin", action="store_true", help="draw the noise on ballscan's own render of each scene's ball (uniform, at its levels) instead of the POV-Ray render")
    ap.add_argument("--save", type=Path, help="write the rows as JSON")
    a = ap.parse_args()
    if a.reps < 3 or a.every < 1:
        raise SystemExit("error: --reps must be at least 3 and --every at least 1")
    if a.plane and a.twin:
        raise SystemExit("error: --plane and --twin do not go together")
    names = a.names
    if not names:
        picks = []
        for p in sorted(a.scenes.glob(f"{a.only}.truth.json")):
            t = json.loads(p.read_text())
            if (a.split == "all" or t["split"] == a.split) and "balls" not in t:
                picks.append(t["scene"])
        names = picks[:: a.every]
    extra = ["--recipe", str(a.recipe)] if a.recipe else []
    import tempfile

    from joblib import Parallel, delayed

    with tempfile.TemporaryDirectory() as tmp:
        rows = Parallel(n_jobs=a.jobs)(delayed(scene_row)(a.scenes, n, a.reps, extra, Path(tmp), a.plane, a.twin) for n in names)
    rows = [r for r in rows if r is not None]
    _table(rows)
    if a.save:
        a.save.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
