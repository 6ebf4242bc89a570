"""Edges pulled inside the silhouette by texture at the limb: the outer envelope finds them, and only them."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscan.geometry.camera import LineScanCamera, line_times
from ballscan.geometry.motion import BallMotion
from ballscan.measure.detection import detect
from ballscan.measure.edges import measure_edges, without_edges
from ballscan.measure.images import LineImage
from ballscan.model.render import Appearance, SensorNoise, render
from ballscan.pipeline.background import full_background
from ballscan.solve.envelope import EnvelopeSettings, inward_edges, largest_jump_px, trim_inward
from ballscan.solve.fit import fit_motion
from ballscan.solve.synthetic import synthetic_edges

CAMERA = LineScanCamera(width=512, focal_px=2000.0, principal_px=255.5, line_rate_hz=20000.0, exposure_s=2e-5)


def _motion(vz: float = 0.0, vy: float = 0.3) -> BallMotion:
    # a 20-px ball crossing in about 120 lines
    return BallMotion(0.02, 0.003, (0.0, 0.0, 2.0), (6.5, vy, vz))


def _panel(edges, first: int, last: int, depth_px: float, side: str = "left"):
    """The edges of lines ``first:last`` moved inwards by up to ``depth_px``: a dark panel on the limb.

    Its depth across the lines is a half ellipse, as a round panel's border
    crossing the limb draws it: the edge jumps where the border meets it.
    """
    bump = np.zeros(edges.t_s.size)
    k = np.arange(last - first) + 0.5
    half = 0.5 * k.size
    bump[first:last] = depth_px * np.sqrt(1.0 - ((k - half) / half) ** 2)
    if side == "left":
        return replace(edges, left_px=edges.left_px + bump), bump > 0
    return replace(edges, right_px=edges.right_px - bump), bump > 0


def test_a_clean_ball_loses_no_edge():
    edges = synthetic_edges(CAMERA, _motion(vz=0.8), 160, edge_sigma_px=0.05, seed=1)
    found = inward_edges(CAMERA, edges, _motion(vz=0.8))
    assert found.count == 0
    assert 0.03 < found.sigma_px < 0.08  # the edges' own noise


@pytest.mark.parametrize("side", ["left", "right"])
def test_a_panel_at_the_limb_is_found_though_it_pulled_the_fit(side):
    truth = _motion(vz=0.5)
    clean = synthetic_edges(CAMERA, truth, 160, edge_sigma_px=0.05, seed=2)
    inner = np.flatnonzero(clean.left_ok)
    first = inner[0] + inner.size // 4
    edges, bumped = _panel(clean, first, first + 40, 10.0, side)  # a football's panel
    pulled = fit_motion(CAMERA, edges, truth)
    assert abs(pulled.motion.velocity_mps[2] - truth.velocity_mps[2]) > 5.0  # the panel moves V.z by 25 sigma
    # the passes about fits of the edges kept: the panel's deep edges, nothing beyond its border's lines
    found = trim_inward(CAMERA, edges, truth)  # from the key-point guess in the pipeline
    flagged = found.left if side == "left" else found.right
    other = found.right if side == "left" else found.left
    depth = np.abs(edges.left_px - clean.left_px) + np.abs(edges.right_px - clean.right_px)
    near = np.convolve(bumped.astype(float), np.ones(2 * EnvelopeSettings().dilate_lines + 1), mode="same") > 0
    assert np.all(flagged[bumped & (depth > 0.5)]) and not np.any(flagged & ~near) and not other.any()
    usable = edges.left_ok if side == "left" else edges.right_ok
    assert np.all(flagged[near & usable])  # the border's ramp too
    kept = replace(edges, left_ok=edges.left_ok & ~found.left, right_ok=edges.right_ok & ~found.right)
    refit = fit_motion(CAMERA, kept, truth)  # the pipeline starts the later fits from the key-point guess
    assert abs(refit.motion.velocity_mps[2] - truth.velocity_mps[2]) < 3.0 * np.sqrt(refit.covariance[5, 5])


def test_a_stitch_at_the_limb_is_left_to_the_fit():
    # 1 px over 20 lines: the edges stay within 0.2 px RMS of a fit of them all
    truth = _motion(vz=0.5)
    clean = synthetic_edges(CAMERA, truth, 160, edge_sigma_px=0.05, seed=2)
    inner = np.flatnonzero(clean.left_ok)
    edges, _ = _panel(clean, inner[0] + 30, inner[0] + 50, 1.0)
    assert trim_inward(CAMERA, edges, truth).count == 0
    assert trim_inward(CAMERA, edges, truth, settings=EnvelopeSettings(min_jump_px=0.1, min_rms_px=0.1)).count > 0


@settings(max_examples=15, deadline=None)
@given(vz=st.floats(-2.0, 2.0), vy=st.floats(-2.0, 2.0), seed=st.integers(0, 2**16))
def test_no_clean_edge_is_flagged_whatever_the_motion(vz, vy, seed):
    m = _motion(vz=vz, vy=vy)
    edges = synthetic_edges(CAMERA, m, 200, edge_sigma_px=0.05, seed=seed)
    assert inward_edges(CAMERA, edges, m).count == 0


def test_jumps_of_a_clean_limb_and_of_a_panel():
    clean = synthetic_edges(CAMERA, _motion(vz=0.8), 160, edge_sigma_px=0.05, seed=1)
    assert largest_jump_px(clean) < 0.5  # noise and the limb's curvature
    inner = np.flatnonzero(clean.left_ok)
    edges, _ = _panel(clean, inner[0] + 30, inner[0] + 70, 10.0, "right")
    assert largest_jump_px(edges) > 2.0


def test_found_edges_grow_by_their_border_lines_even_on_few_lines():
    from ballscan.solve.envelope import InwardEdges, _dilated

    edges = synthetic_edges(CAMERA, _motion(), 160, edge_sigma_px=0.05, seed=1)
    n = edges.t_s.size
    found = np.zeros(n, dtype=bool)
    i = int(np.flatnonzero(edges.left_ok)[20])
    found[i] = True
    grown = _dilated(InwardEdges(found, np.zeros(n, dtype=bool), 0.1), edges, 2)
    assert np.flatnonzero(grown.left).tolist() == [i - 2, i - 1, i, i + 1, i + 2] and not grown.right.any()
    few = replace(edges, t_s=edges.t_s[:5], left_ok=np.ones(5, dtype=bool), right_ok=np.ones(5, dtype=bool))
    one = np.array([False, False, True, False, False])
    assert _dilated(InwardEdges(one, np.zeros(5, dtype=bool), 0.1), few, 6).left.all()  # a kernel longer than the lines


def test_a_short_ball_is_not_checked():
    fast = BallMotion(0.02, 0.0005, (0.0, 0.0, 2.0), (60.0, 0.0, 0.0))
    edges = synthetic_edges(CAMERA, fast, 40, edge_sigma_px=0.05, seed=3)
    found = inward_edges(CAMERA, edges, fast, EnvelopeSettings(min_lines=12))
    assert found.count == 0 and np.isnan(found.sigma_px)


@pytest.mark.parametrize("kw, name", [({"k_sigma": 0}, "k_sigma"), ({"floor_px": float("nan")}, "floor_px"), ({"max_rounds": 0}, "max_rounds"), ({"min_lines": 2.5}, "min_lines")])
def test_settings_validated_by_name(kw, name):
    with pytest.raises(ValueError, match=name):
        EnvelopeSettings(**kw)


def test_without_edges_leaves_the_lines_out_of_the_edges_and_the_areas():
    m = _motion()
    img = render(CAMERA, (m, Appearance()), 160, noise=SensorNoise(), seed=4).image
    det = detect(LineImage(img, 1e9, 16, "render"))
    edges = measure_edges(img, det.regions[0], full_background(det), det.noise_dn, line_times(CAMERA, img.shape[0]))
    both = np.flatnonzero(edges.left_ok & edges.right_ok)
    drop_l = np.zeros(edges.t_s.size, dtype=bool)
    drop_r = np.zeros(edges.t_s.size, dtype=bool)
    drop_l[both[10:20]] = True
    drop_r[both[30:35]] = True
    out = without_edges(edges, drop_l, drop_r)
    assert not out.left_ok[drop_l].any() and not out.right_ok[drop_r].any()
    assert not (out.left_wide_ok[drop_l].any() or out.right_wide_ok[drop_r].any())
    assert not out.end_line[drop_l | drop_r].any()  # a texture-shortened line's area is not the ball's
    # nor does the fit take it as a line beside the ball, where both its edges are out
    from ballscan.model.averaged import ModelEdges, averaged_model
    from ballscan.solve.problem import select_lines_of
    from ballscan.solve.settings import FitSettings

    both = without_edges(edges, drop_l, drop_l | drop_r)
    me = averaged_model(CAMERA, m.to_params()[None, :], m.radius_m, both.t_s)
    me = ModelEdges(me.left_px[0], me.right_px[0], me.presence[0], me.area_px[0], me.spread_px[0], me.valid[0])
    use_area = select_lines_of(both, me, FitSettings())[2]
    assert both.area_excluded[drop_l | drop_r].all() and not use_area[drop_l | drop_r].any()
    assert use_area[~(drop_l | drop_r)].any()  # the lines beside the ball still count
    untouched = ~(drop_l | drop_r)
    np.testing.assert_array_equal(out.left_ok[untouched], edges.left_ok[untouched])
    np.testing.assert_array_equal(out.left_px[untouched], edges.left_px[untouched])
    with pytest.raises(ValueError, match="one flag per measured line"):
        without_edges(edges, drop_l[:-1], drop_r)


def test_the_recipe_switch_on_a_panelled_football():
    # pv0192 (POV-Ray set): with the envelope off, the panels' edges are fitted and the speed is
    # 805 % off; on, they are left out and flagged (the default; tests/test_povray_set.py scores it)
    import json
    from pathlib import Path

    from ballscan.geometry.camera import load_camera
    from ballscan.measure.images import load_image
    from ballscan.pipeline.estimate import estimate_image
    from ballscan.pipeline.recipe import Recipe

    scenes = Path(__file__).resolve().parents[1] / "benchmarks" / "povray_set" / "scenes"
    truth = json.loads((scenes / "pv0192.truth.json").read_text())
    img, cam = load_image(scenes / "pv0192.png"), load_camera(scenes / "pv0192.camera.toml")
    speeds = {}
    for on in (False, True):
        (ball,) = [b for b in estimate_image(img, cam, truth["radius_m"], recipe=Recipe(limb_envelope=on)).balls if b.speed_mps is not None]
        assert ("texture_at_limb" in ball.flags) == on and (ball.extra["inward_edges"] > 0) == on
        speeds[on] = ball.speed_mps
    assert speeds[False] > 5 * truth["speed_mps"] and abs(speeds[True] / truth["speed_mps"] - 1) < 0.05
