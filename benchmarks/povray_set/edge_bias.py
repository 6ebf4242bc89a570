"""Edge bias on the POV-Ray set: each measured edge against the truth's projected limb, line by line.

    python benchmarks/povray_set/edge_bias.py [--scenes DIR] [--split tune] [--clean] [--per-line] NAME [NAME ...]
    python benchmarks/povray_set/edge_bias.py [--split tune] [--clean] --limb-levels
    python benchmarks/povray_set/edge_bias.py [--split tune] [--clean] --beyond

For each scene (its first true ball) the default estimator runs in-process
(``estimate_image``); the edges its reported fit took
(``BallEstimate.fitted_edges``) are compared with the mean edges of the
averaged silhouette at the truth's motion (``model.averaged``: the limb the
set's own coverage matches to 0.001 px, see the convention audit in
``docs/benchmarks.md``).  Offsets are counted positive inwards (a left edge
to the right of the true limb, a right edge to its left), in pixels, on the
narrow-window edges where the model's edge spread is below 0.3 px and the
wide-window ones where it is 0.3-0.8 px (where the fit takes each).

Columns: the fit's path, the lines with both edges, each side's median
offset, the slope of each side's offset over the passage (pixels from the
first to the last measured line: a straight fit in time), the fit's V.z
error in transverse speeds, and the same fit's V.z error started from the
truth on the same edges.  ``--clean`` measures the scene's noise-free
render (``scenes/clean/``, same detection) instead; ``--per-line`` prints
every line's offsets.  Tuning half only unless ``--split all``.

``--limb-levels`` (no names: every uncut scene of the split) bins the
offsets of all those edges by the shading law's brightness half a pixel
inside the true limb, as a fraction of the ball's contrast (the law fitted
on the ball's interior at the truth's motion,
``measure.shading.ball_limb``): where a side lit at grazing incidence has
about the background's brightness, its window finds the terminator
inside the limb instead.

``--beyond`` (no names) bins the same edges by what lies outside them: the
mean normalised profile of the 4 pixels from the second pixel beyond the
edge outwards, over its noise sigma.  A band darker than the backdrop (for
a bright ball; brighter, for a dark one) is the ball's part of the other
polarity, a side in shadow or a dark panel: the edge is not the limb.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent


def truth_motion(tb: dict):
    from ballscan.geometry.motion import BallMotion

    return BallMotion(tb["radius_m"], tb["t_c_s"], tuple(tb["position_m"]), tuple(tb["velocity_mps"]))


def load(scenes: Path, name: str, clean: bool):
    """The scene's truth, camera and image (the noise-free render with ``clean``, at the noisy one's scale)."""
    from ballscan.geometry.camera import load_camera
    from ballscan.measure.images import as_line_image, load_image

    truth = json.loads((scenes / f"{name}.truth.json").read_text())
    cam = load_camera(scenes / f"{name}.camera.toml")
    img = load_image(scenes / f"{name}.png")
    if clean:
        from PIL import Image

        n = truth["noise"]
        raw = np.asarray(Image.open(scenes / "clean" / f"{name}.png"), float) / 65535.0
        dn = n["black_dn"] + raw * n["white_dn"]
        img = as_line_image(dn.astype(np.float32), bits=16)
    return truth, cam, img


def offsets(edges, cam, motion) -> dict:
    """Inward offsets of the narrow-window edges from the truth's mean edges, per line (NaN where unusable)."""
    from ballscan.model.averaged import averaged_model

    me = averaged_model(cam, motion.to_params()[None], motion.radius_m, edges.t_s, motion.acceleration_mps2)
    tl, tr, spread = me.left_px[0], me.right_px[0], me.spread_px[0]
    seen = me.presence[0] > 0
    # the narrow windows where the fit takes them, the wide ones beyond (FitSettings' spreads)
    narrow = seen & (spread < 0.3)
    wide = seen & (spread >= 0.3) & (spread <= 0.8) & (edges.left_wide_ok is not None)
    out = {"lines": edges.lines, "t": edges.t_s, "true_left": tl, "true_right": tr, "wide": wide}
    for side, sg, true in (("left", 1.0, tl), ("right", -1.0, tr)):
        e_n, ok_n = getattr(edges, f"{side}_px"), getattr(edges, f"{side}_ok")
        e_w, ok_w = getattr(edges, f"{side}_wide_px"), getattr(edges, f"{side}_wide_ok")
        d = np.where(ok_n & narrow, sg * (e_n - true), np.nan)
        if e_w is not None:
            d = np.where(ok_w & wide, sg * (e_w - true), d)
        out[side] = d
    return out


def trend(t: np.ndarray, d: np.ndarray) -> float:
    """Change of ``d`` from the first to the last finite line, by a straight fit in time (pixels)."""
    ok = np.isfinite(d)
    if ok.sum() < 5:
        return math.nan
    c = np.polyfit(t[ok], d[ok], 1)
    return float(c[0] * (t[ok].max() - t[ok].min()))


def refit_from_truth(cam, edges, motion):
    from ballscan.solve.fit import fit_motion

    return fit_motion(cam, edges, motion).motion


def fitted_ball(scenes: Path, name: str, clean: bool, single: bool = False):
    """The scene's truth, camera, image, first true ball and the estimate nearest it in time with fitted edges (None: none, or with ``single`` not exactly one)."""
    from ballscan.pipeline.estimate import estimate_image

    truth, cam, img = load(scenes, name, clean)
    tb = (truth["balls"] if "balls" in truth else [truth])[0]
    found = [b for b in estimate_image(img, cam, tb["radius_m"]).balls if b.t_c_s is not None and b.fitted_edges is not None]
    b = min(found, key=lambda e: abs(e.t_c_s - tb["t_c_s"])) if found and (len(found) == 1 or not single) else None
    return truth, cam, img, tb, b


def scene_row(scenes: Path, name: str, clean: bool, per_line: bool) -> str:
    truth, cam, img, tb, b = fitted_ball(scenes, name, clean)
    if b is None:
        return f"| {name} | no fit | | | | | | |"
    m = truth_motion(tb)
    o = offsets(b.fitted_edges, cam, m)
    both = np.isfinite(o["left"]) & np.isfinite(o["right"])
    v = tb["velocity_mps"]
    vt = math.hypot(v[0], v[1])
    est_vz = b.velocity_mps[2] if b.velocity_mps is not None else None
    try:
        vz_t = refit_from_truth(cam, b.fitted_edges, m).velocity_mps[2]
    except (ValueError, ArithmeticError):
        vz_t = math.nan
    if per_line:
        for i in range(o["lines"].size):
            if np.isfinite(o["left"][i]) or np.isfinite(o["right"][i]):
                print(f"  {name} line {o['lines'][i]}: L {o['left'][i]:+.3f} R {o['right'][i]:+.3f}", file=sys.stderr)
    f = lambda x: f"{x:+.3f}" if x is not None and np.isfinite(x) else "-"  # noqa: E731
    med = lambda x: float(np.nanmedian(x)) if np.isfinite(x).any() else math.nan  # noqa: E731
    ez = (est_vz - v[2]) / vt if est_vz is not None else None
    return (f"| {name} | {truth['kind']} | {b.record.final_fit if b.record else '-'} / {b.fitted_edges.edges_method} | {int(both.sum())} | "
            f"{f(med(o['left']))} / {f(med(o['right']))} | {f(trend(o['t'], o['left']))} / {f(trend(o['t'], o['right']))} | "
            f"{f(ez)} | {f((vz_t - v[2]) / vt)} |")


#: Bins of the limb's brightness (fraction of the ball's contrast) for ``--limb-levels``.
LEVEL_BINS = (-math.inf, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6, math.inf)


def limb_level_rows(scenes: Path, name: str, clean: bool) -> list[tuple[float, float]]:
    """(limb brightness half a pixel inside, inward offset px) of each fitted narrow or wide edge of the scene's first ball."""
    from ballscan.geometry.camera import line_times
    from ballscan.measure.detection import detect
    from ballscan.measure.shading import ball_limb
    from ballscan.pipeline.recipe import Recipe
    from ballscan.pipeline.stages import shading_background

    _, cam, img, tb, b = fitted_ball(scenes, name, clean)
    if b is None:
        return []
    m = truth_motion(tb)
    recipe = Recipe()
    bg = shading_background(img, detect(img), recipe)
    t = line_times(cam, img.data.shape[0])
    limb = ball_limb(cam, m, img.data, b.fitted_edges, t, bg, level_samples=recipe.level_samples)
    if limb is None:
        return []
    o = offsets(b.fitted_edges, cam, m)
    out = []
    for side, sg in (("left", 1.0), ("right", -1.0)):
        ok = np.isfinite(o[side])
        lines = o["lines"][ok]
        level = limb.surface(lines, np.full(lines.size, sg), np.full((lines.size, 1), 0.5))[:, 0]
        out += list(zip(level.tolist(), o[side][ok].tolist()))
    return out


def _uncut_scenes(scenes: Path, split: str) -> list[str]:
    """The split's scenes whose balls no image border cuts."""
    out = []
    for p in sorted(scenes.glob("pv*.truth.json")):
        t = json.loads(p.read_text())
        if t["cut"] == "none" and (split != "tune" or t["split"] == "tune"):
            out.append(t["scene"])
    return out


def _binned(key: np.ndarray, d: np.ndarray, names: list[str], bins, label: str) -> list[str]:
    """Table rows of the offsets ``d`` binned by ``key``: edges, balls, median, mean and 90 % absolute offset, those beyond 0.5 px."""
    out = []
    for lo, hi in zip(bins[:-1], bins[1:]):
        sel = (key >= lo) & (key < hi)
        if sel.any():
            balls = {n for n, s in zip(names, sel) if s}
            a = np.abs(d[sel])
            out.append(f"| {label.format(lo, hi)} | {int(sel.sum())} | {len(balls)} | {np.median(d[sel]):+.3f} | "
                       f"{np.mean(a):.3f} | {np.percentile(a, 90):.3f} | {int((a > 0.5).sum())} |")
    return out


_OFFSET_COLUMNS = "| edges | balls | median offset px | mean abs offset px | 90 % abs offset px | more than 0.5 px off |"


def _collected(scenes: Path, split: str, clean: bool, rows_of) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """``rows_of(scenes, name, clean)``'s (key, offset) pairs over the split's uncut scenes: keys, offsets and each pair's scene."""
    rows = [(k, d, name) for name in _uncut_scenes(scenes, split) for k, d in rows_of(scenes, name, clean)]
    return np.array([r[0] for r in rows]), np.array([r[1] for r in rows]), [r[2] for r in rows]


def limb_level_table(scenes: Path, split: str, clean: bool) -> list[str]:
    """The inward offsets of every uncut ball's fitted edges, binned by the limb's brightness (``--limb-levels``)."""
    lv, d, names = _collected(scenes, split, clean, limb_level_rows)
    out = [f"{len(set(names))} balls, {int(np.isfinite(lv).sum())} edges ({int((~np.isfinite(lv)).sum())} more where the law does not see the ball)",
           "| limb brightness / contrast " + _OFFSET_COLUMNS, "|---|---|---|---|---|---|---|"]
    return out + _binned(lv, d, names, LEVEL_BINS, "{:.2f} - {:.2f}")


#: the band outside an edge for ``--beyond``: pixels from the edge's second outer neighbour on, and their count
BEYOND_GAP_PX, BEYOND_PX = 2, 4
#: bins of the band's mean over its noise sigma
BEYOND_BINS = (-np.inf, -8.0, -4.0, -2.0, 2.0, 4.0, 8.0, np.inf)


def beyond_rows(scenes: Path, name: str, clean: bool) -> list[tuple[float, float]]:
    """(band mean / its sigma, inward offset px) of each fitted narrow or wide edge of a scene with one ball found."""
    _, cam, _, tb, b = fitted_ball(scenes, name, clean, single=True)
    if b is None or b.fitted_edges.profile is None:
        return []
    e = b.fitted_edges
    o = offsets(e, cam, truth_motion(tb))
    p, c0 = e.profile, e.profile_col0
    sp = np.broadcast_to(e.profile_sigma, p.shape)
    out = []
    for side, sg in (("left", 1.0), ("right", -1.0)):
        px = getattr(e, f"{side}_px")
        for i in np.flatnonzero(np.isfinite(o[side])):
            first = int(math.floor(px[i] - c0 - BEYOND_GAP_PX)) if sg > 0 else int(math.ceil(px[i] - c0 + BEYOND_GAP_PX))
            cols = first - sg * np.arange(BEYOND_PX)
            if cols.min() < 0 or cols.max() >= p.shape[1] or not np.all(np.isfinite(p[i, cols.astype(int)])):
                continue
            band, sig = p[i, cols.astype(int)], sp[i, cols.astype(int)]
            out.append((float(band.mean() / (np.sqrt(np.sum(sig**2)) / BEYOND_PX)), float(o[side][i])))
    return out


def beyond_table(scenes: Path, split: str, clean: bool) -> list[str]:
    """The inward offsets of every uncut single ball's fitted edges, binned by the band outside them (``--beyond``)."""
    z, d, names = _collected(scenes, split, clean, beyond_rows)
    out = [f"{len(set(names))} balls, {d.size} edges; {int((np.abs(d) > 0.5).sum())} lie more than 0.5 px off the limb",
           "| band mean / sigma " + _OFFSET_COLUMNS, "|---|---|---|---|---|---|---|"]
    return out + _binned(z, d, names, BEYOND_BINS, "{:g} - {:g}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="*")
    ap.add_argument("--scenes", type=Path, default=HERE / "scenes")
    ap.add_argument("--split", choices=("tune", "all"), default="tune")
    ap.add_argument("--clean", action="store_true")
    ap.add_argument("--per-line", action="store_true")
    ap.add_argument("--limb-levels", action="store_true", help="every uncut ball's edge offsets binned by the limb's brightness")
    ap.add_argument("--beyond", action="store_true", help="every uncut single ball's edge offsets binned by the band outside the edge")
    a = ap.parse_args(argv)
    if a.limb_levels:
        print("\n".join(limb_level_table(a.scenes, a.split, a.clean)))
        return 0
    if a.beyond:
        print("\n".join(beyond_table(a.scenes, a.split, a.clean)))
        return 0
    if not a.names:
        ap.error("name at least one scene, --limb-levels or --beyond")
    print("| scene | kind | fit path / edges | lines with both edges | median offset L / R px (inwards) | "
          "trend over the passage L / R px | fit V.z error / V_t | V.z error / V_t, fit from the truth |")
    print("|" + "---|" * 8)
    for name in a.names:
        t = json.loads((a.scenes / f"{name}.truth.json").read_text())
        if a.split == "tune" and t["split"] != "tune":
            print(f"| {name} | report half: skipped | | | | | | |")
            continue
        print(scene_row(a.scenes, name, a.clean, a.per_line), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
