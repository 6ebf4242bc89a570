"""The joint fit of a rig (solve.joint, pipeline.rig) and known constraints (solve.constraint), end to end on rendered images."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from ballscan.geometry.rig import WorldMotion, load_rig
from ballscan.lab.presets import get_preset
from ballscan.lab.rig import RIG_PRESETS, camera_about_lane, simulate_rig
from ballscan.model.render import Appearance, render
from ballscan.pipeline.estimate import estimate_image
from ballscan.pipeline.recipe import Recipe
from ballscan.pipeline.rig import combined_start, estimate_rig, gain_prior, match_window_s, measure_group, own_block, single_camera_rig
from ballscan.solve.constraint import Constraint, parse_constraint
from ballscan.solve.joint import JointCamera, JointLayout, JointProblem, fit_joint
from ballscan.solve.problem import BlockState, ResidualBlock
from ballscan.solve.settings import FitSettings
from ballscan.solve.synthetic import synthetic_edges

LANE = RIG_PRESETS["lane-90"]


def _errors_in_sigmas(ball, truth: WorldMotion) -> np.ndarray:
    """(estimate - truth) / sigma of (y, z, vx, vy, vz) at the estimate's crossing time, and of t_c."""
    m = ball.motion
    tr = truth.at(m.t_ref_s)
    est = np.array([*m.position_m[1:], *m.velocity_mps])
    tv = np.array([*tr.position_m[1:], *tr.velocity_mps])
    return (est - tv) / ball.sigmas[2:]


@pytest.fixture(scope="module")
def lane_render():
    return simulate_rig(LANE.rig, LANE.motion, LANE.n_lines, LANE.appearance, seed=11)


def test_two_cameras_within_three_sigma_of_the_truth(lane_render):
    rep = estimate_rig(lane_render.images, LANE.rig, LANE.motion.radius_m)
    assert len(rep.balls) == 1
    b = rep.balls[0]
    assert b.cameras == ("side", "top") and b.flags == ()
    z = _errors_in_sigmas(b, LANE.motion)
    assert np.all(np.abs(z) < 3.0), z
    # the crossing time: the truth's crossing of the reference plane
    assert abs(b.t_c_s - LANE.motion.t_ref_s) < 3 * b.sigmas[0]
    assert all(c.consistent for c in b.joint.cameras)
    # the depth axis pinned: the world velocity's largest principal sigma vs each camera alone
    joint = math.sqrt(np.linalg.eigvalsh(b.covariance[4:, 4:]).max())
    alone = [math.sqrt(np.linalg.eigvalsh(np.asarray(e.covariance)[3:, 3:]).max()) for e in b.estimates.values()]
    assert joint * 10 < min(alone)
    el, el_s, az, az_s = b.direction()
    V = np.asarray(LANE.motion.velocity_mps)
    assert abs(el - math.degrees(math.atan2(V[2], math.hypot(V[0], V[1])))) < 3 * el_s
    assert abs(az - math.degrees(math.atan2(V[1], V[0]))) < 3 * az_s
    d = b.to_dict()
    assert d["per_camera"]["top"]["consistent"] and d["inconsistent_cameras"] == []
    assert len(d["covariance"]["matrix"]) == 7 and d["own"]["side"]["velocity_mps"] is not None


def test_a_ball_both_cameras_see_enters_the_joint_fit_measured_on_the_refined_background(lane_render):
    refined = Recipe(refined_background=True)
    b = estimate_rig(lane_render.images, LANE.rig, LANE.motion.radius_m).balls[0]
    for rc, img in zip(LANE.rig.cameras, lane_render.images):
        own = estimate_image(img, rc.camera, LANE.motion.radius_m, recipe=refined).balls[0]
        np.testing.assert_array_equal(b.estimates[rc.name].velocity_mps, own.velocity_mps)
    # switched off, each camera's first measurement (the detector's level) enters instead
    off = estimate_rig(lane_render.images, LANE.rig, LANE.motion.radius_m, recipe=Recipe(rig_refined_background=False)).balls[0]
    for rc, img in zip(LANE.rig.cameras, lane_render.images):
        own = estimate_image(img, rc.camera, LANE.motion.radius_m).balls[0]
        np.testing.assert_array_equal(off.estimates[rc.name].velocity_mps, own.velocity_mps)
    assert not np.array_equal(off.motion.velocity_mps, b.motion.velocity_mps)
    assert np.all(np.abs(_errors_in_sigmas(b, LANE.motion)) < 3.0)


def test_a_ball_whose_lines_another_ball_spans_too_keeps_its_first_measurement(lane_render, monkeypatch):
    # the second measurement (of a ball no joint fit takes) is matched to the first by the lines each
    # ball spans: where two balls span the same lines it cannot tell them apart and keeps the first
    import ballscan.pipeline.rig as prig

    first = tuple(estimate_image(img, rc.camera, LANE.motion.radius_m, recipe=Recipe(refined_background=True))
                  for img, rc in zip(lane_render.images, LANE.rig.cameras))
    again = [estimate_image(img, rc.camera, LANE.motion.radius_m) for img, rc in zip(lane_render.images, LANE.rig.cameras)]
    twin = replace(again[1], balls=again[1].balls * 2)
    by_camera = {id(LANE.rig.cameras[0].camera): again[0], id(LANE.rig.cameras[1].camera): twin}
    monkeypatch.setattr(prig, "estimate_image", lambda img, camera, *a, **kw: by_camera[id(camera)])
    cut_short = (first[0], replace(first[1], balls=(replace(first[1].balls[0], fitted_edges=None),)))
    for reports, groups in ((first, [{0: 0}, {1: 0}]), (cut_short, [{0: 0, 1: 0}])):
        # each ball alone, or a pair of which one camera's estimate cannot enter a joint fit
        assert not any(prig._joins(LANE.rig, g, reports) for g in groups)
        out = prig._alone_reports(lane_render.images, LANE.rig, LANE.motion.radius_m, Recipe(), reports, groups)
        assert out[0].balls[0] is again[0].balls[0] and out[1].balls[0] is reports[1].balls[0]
    # with every group in a joint fit nothing is measured again, nor where the first measurement was the recipe's own
    monkeypatch.setattr(prig, "estimate_image", lambda *a, **kw: pytest.fail("measured again"))
    assert prig._joins(LANE.rig, {0: 0, 1: 0}, first)
    assert prig._alone_reports(lane_render.images, LANE.rig, LANE.motion.radius_m, Recipe(), first, []) is first
    for recipe in (Recipe(refined_background=True), Recipe(rig_refined_background=False)):
        assert prig._alone_reports(lane_render.images, LANE.rig, LANE.motion.radius_m, recipe, first, [{0: 0}, {1: 0}]) is first
    # beside a plane one estimate is enough for a joint fit, unless that camera's clock is unknown
    # (the joint fit's start needs a camera with a known clock)
    assert prig._joins(LANE.rig, {0: 0}, first, constrained=True) and prig._joins(LANE.rig, {1: 0}, first, constrained=True)
    free_clock = LANE.rig.with_camera(1, replace(LANE.rig.cameras[1], clock_offset_s=None, clock_sigma_s=1e-3))
    assert prig._joins(free_clock, {0: 0}, first, constrained=True) and not prig._joins(free_clock, {1: 0}, first, constrained=True)
    assert not prig._joins(LANE.rig, {0: 0}, first)
    # two usable estimates from cameras whose clocks are both unknown (a third camera's, the rig's clock,
    # unusable) give no start either: measured again
    monkeypatch.setattr(prig, "_usable", lambda rig, k, ball: True)
    free_pair = SimpleNamespace(cameras=[SimpleNamespace(clock_known=False)] * 2)
    reports = [SimpleNamespace(balls=[None])] * 2
    assert not prig._joins(free_pair, {0: 0, 1: 0}, reports) and not prig._joins(free_pair, {0: 0}, reports, constrained=True)


def test_unknown_clock_offset_recovered():
    truth_offset = 2.5e-4
    sim = simulate_rig(LANE.rig, LANE.motion, LANE.n_lines, LANE.appearance, seed=12, clock_offsets_s={"top": truth_offset})
    rig = LANE.rig.with_camera(1, replace(LANE.rig.cameras[1], clock_offset_s=None, clock_sigma_s=1e-3))
    b = estimate_rig(sim.images, rig, LANE.motion.radius_m).balls[0]
    assert b.cameras == ("side", "top") and b.flags == ()
    top = b.joint.cameras[1]
    assert top.clock_offset_sigma_s > 0
    assert abs(top.clock_offset_s - truth_offset) < 3 * top.clock_offset_sigma_s
    assert "clock_offset_s:top" in b.joint.parameter_names
    assert np.all(np.abs(_errors_in_sigmas(b, LANE.motion)) < 3.0)


@pytest.mark.parametrize("velocity, position, flags", [
    ((30.0, -2.0, 1.0), None, ()),
    ((150.5, 0.0, 0.0), None, ("implausible_speed",)),
    ((30.0, 0.0, 0.0), (0.0, 0.0, 250.0), ("implausible_range",)),
])
def test_a_joint_motion_beyond_any_ball_is_flagged_as_one_cameras_would_be(velocity, position, flags):
    import ballscan.pipeline.rig as prig

    m = LANE.motion
    if position is not None:
        # the centre 250 m along the world's z from the lane's: farther than 200 m from both cameras
        position = tuple(np.asarray(m.position_m) + np.asarray(position))
    motion = replace(m, velocity_mps=velocity, position_m=position or m.position_m)

    def ball(motion, undetermined=()):
        # the ball reads its undetermined components from its joint fit
        return prig.RigBall(("side", "top"), motion, np.eye(7), (), joint=SimpleNamespace(undetermined=undetermined))

    assert prig._implausible(LANE.rig, ball(motion)) == flags
    assert prig._implausible(LANE.rig, ball(None)) == ()
    # what the fit leaves undetermined is not judged, however large (and its square does not overflow)
    wild = replace(motion, velocity_mps=(7e153, 0.0, 0.0), position_m=(1.5e300, 0.0, 0.0))
    assert prig._implausible(LANE.rig, ball(wild, ("x_m", "vx_mps"))) == ()
    assert prig._implausible(LANE.rig, ball(wild)) == ("implausible_speed", "implausible_range")


def test_a_joint_ball_is_flagged_on_its_joint_motion(lane_render, monkeypatch):
    import ballscan.pipeline.rig as prig

    picks = {k: estimate_image(img, rc.camera, LANE.motion.radius_m).balls[0] for k, (img, rc) in enumerate(zip(lane_render.images, LANE.rig.cameras))}
    real = prig.fit_joint
    for undetermined, flags in (((), ("implausible_speed",)), (("vz_mps",), ())):
        def fast(*a, **kw):
            res = real(*a, **kw)
            return replace(res, motion=replace(res.motion, velocity_mps=(200.0, 0.0, 0.0)), undetermined=undetermined)

        monkeypatch.setattr(prig, "fit_joint", fast)
        b = prig.measure_group(LANE.rig, picks, LANE.motion.radius_m)
        assert b.cameras == ("side", "top") and tuple(f for f in b.flags if f.startswith("implausible")) == flags


def test_a_ball_seen_by_one_camera_only_is_measured_by_it_and_flagged():
    sim = simulate_rig(LANE.rig, LANE.motion, LANE.n_lines, LANE.appearance, seed=13, cameras=("side",))
    rep = estimate_rig(sim.images, LANE.rig, LANE.motion.radius_m)
    assert len(rep.balls) == 1
    b = rep.balls[0]
    assert b.cameras == ("side",) and "single_camera" in b.flags and b.joint is None
    own = estimate_image(sim.images[0], LANE.rig.cameras[0].camera, LANE.motion.radius_m).balls[0]
    np.testing.assert_allclose(b.motion.velocity_mps, LANE.rig.cameras[0].camera.vectors_to_world(own.velocity_mps), rtol=1e-12)
    assert np.all(np.abs(_errors_in_sigmas(b, LANE.motion)) < 3.0)
    # the camera's own plausibility flags stay with the ball
    import ballscan.pipeline.rig as prig

    flagged = replace(own, flags=own.flags + ("implausible_speed",))
    assert "implausible_speed" in prig.measure_group(LANE.rig, {0: flagged}, LANE.motion.radius_m).flags


def test_a_uniform_balls_window_edges_enter_the_joint_fit_as_their_pixels():
    # a flat ball on the default sensor (column gains scatter): each camera's own fit takes window edges,
    # the joint fit those windows' pixels (the pixel model describes the ball)
    windows = Recipe()
    sim = simulate_rig(LANE.rig, LANE.motion, LANE.n_lines, Appearance(ball_level=0.65, shading=False), seed=14)
    b = estimate_rig(sim.images, LANE.rig, LANE.motion.radius_m, recipe=windows).balls[0]
    assert b.cameras == ("side", "top") and b.flags == ()
    for e in b.estimates.values():
        assert e.record.final_fit == "edges" and e.pixel_limb is not None
        edges, settings = own_block(e, windows)
        # the sensor's column gains (0.8 %) measured on the ball's interior: the pixels' gains take that prior
        gain = gain_prior(e, windows)
        assert 0.004 < gain < 0.012 and gain == e.record.column_gain_sigma
        assert settings == replace(windows.pixel_fit, pixel_gain_sigma=gain) and edges.profile_shade is not None
        # without the limb model the block keeps the edges
        assert own_block(replace(e, pixel_limb=None), windows)[1] == windows.edge_fit
        # gains counted as known: on a flat-fielded image, or a scatter within what the recipe takes for a flat sensor
        assert gain_prior(replace(e, record=replace(e.record, flat_fielded=True)), windows) == 0.0
        assert gain_prior(e, Recipe(matched_max_gain_sigma=gain)) == 0.0
        assert gain_prior(replace(e, record=replace(e.record, column_gain_sigma=math.nan)), windows) == 0.0
    assert all(c.consistent for c in b.joint.cameras)
    assert np.all(np.abs(_errors_in_sigmas(b, LANE.motion)) < 3.0)
    # the pixels hold more than the edges: the speed's and the direction's sigmas shrink
    picks = {k: replace(b.estimates[rc.name], pixel_limb=None) for k, rc in enumerate(LANE.rig.cameras)}
    edges_only = measure_group(LANE.rig, picks, LANE.motion.radius_m, windows)
    assert edges_only.flags == ()
    assert b.speed()[1] < 0.9 * edges_only.speed()[1]
    assert b.direction()[1] < 0.9 * edges_only.direction()[1] and b.direction()[3] < 0.9 * edges_only.direction()[3]


def test_a_uniform_balls_matched_edges_on_a_prnu_sensor_enter_the_joint_fit_with_the_gains_prior():
    # the same ball with matched_max_prnu: each camera matches its edges on the image as it is and fits the
    # ends' pixels with the column gains as nuisance parameters; the joint fit takes them alike
    matched = Recipe(matched_max_prnu=0.05)
    sim = simulate_rig(LANE.rig, LANE.motion, LANE.n_lines, Appearance(ball_level=0.65, shading=False), seed=14)
    b = estimate_rig(sim.images, LANE.rig, LANE.motion.radius_m, recipe=matched).balls[0]
    assert b.cameras == ("side", "top") and b.flags == ()
    for e in b.estimates.values():
        gain = gain_prior(e, matched)
        assert e.record.final_fit == "spread" and 0.004 < gain < 0.012
        assert own_block(e, matched)[1] == replace(matched.spread_fit, pixel_gain_sigma=gain)
    assert all(c.consistent for c in b.joint.cameras)
    assert np.all(np.abs(_errors_in_sigmas(b, LANE.motion)) < 3.0)


def test_a_wrong_pose_is_flagged(lane_render):
    # the top camera's viewing plane put 2 cm down the lane: its crossing disagrees with the side camera's
    wrong = camera_about_lane(LANE.rig.cameras[1].camera, 4.0, 90.0, 0.02)
    rig = LANE.rig.with_camera(1, replace(LANE.rig.cameras[1], camera=wrong))
    b = estimate_rig(lane_render.images, rig, LANE.motion.radius_m).balls[0]
    assert b.cameras == ("side", "top")
    assert "inconsistent_camera" in b.flags
    assert any(not c.consistent for c in b.joint.cameras)
    assert max(c.delta_chi2 for c in b.joint.cameras) > 100
    assert b.to_dict()["inconsistent_cameras"]


def _undetermined(e, keys: tuple[str, ...], guess_t_c_s: float | None = None):
    """``e`` as a camera's own fit that left ``keys`` undetermined (their values None, covariance rows NaN)."""
    cov = np.array(e.covariance, dtype=float)
    rows = {"t_c_s": [0], "position_m": [1, 2], "velocity_mps": [3, 4, 5], "vz": [5]}
    for k in keys:
        cov[rows[k], :] = cov[:, rows[k]] = np.nan
    values = {k: None for k in ("t_c_s", "position_m", "velocity_mps") if k in keys or (k == "velocity_mps" and "vz" in keys)}
    initial = e.initial if guess_t_c_s is None else replace(e.initial, t_c_s=guess_t_c_s)
    return replace(e, **values, speed_mps=None, covariance=cov, initial=initial, flags=e.flags + ("degenerate",))


@pytest.mark.parametrize("keys, guess_t_c_s", [(("vz",), None), (("t_c_s", "position_m", "velocity_mps"), -6374.5)])
def test_a_camera_whose_own_fit_is_degenerate_still_enters_the_joint_fit(lane_render, monkeypatch, keys, guess_t_c_s):
    # one camera alone cannot fix its depth velocity (or, cut short, anything): the other camera pins it;
    # an absurd key-point crossing falls back to the middle of the ball's lines
    import ballscan.pipeline.rig as prig

    reports = [estimate_image(img, rc.camera, LANE.motion.radius_m) for img, rc in zip(lane_render.images, LANE.rig.cameras)]
    for k in (0, 1):  # the reference camera degenerate, then the other one
        broken = list(reports)
        broken[k] = replace(reports[k], balls=(_undetermined(reports[k].balls[0], keys, guess_t_c_s),))
        # every measurement of a camera's image (its second on the refined background too) gives its report
        by_camera = {id(rc.camera): r for rc, r in zip(LANE.rig.cameras, broken)}
        monkeypatch.setattr(prig, "estimate_image", lambda img, camera, *a, **kw: by_camera[id(camera)])
        rep = prig.estimate_rig(lane_render.images, LANE.rig, LANE.motion.radius_m)
        assert len(rep.balls) == 1
        b = rep.balls[0]
        assert b.cameras == ("side", "top") and "single_camera" not in b.flags, (k, b.flags)
        assert np.all(np.abs(_errors_in_sigmas(b, LANE.motion)) < 3.0)
        assert abs(b.t_c_s - LANE.motion.t_ref_s) < 3 * b.sigmas[0]
    e = _undetermined(reports[0].balls[0], keys, guess_t_c_s)
    x, C = prig.own_state(e, 1.0 / LANE.rig.cameras[0].camera.line_rate_hz)
    assert np.all(np.isfinite(x)) and np.all(np.isfinite(C)) and np.all(np.linalg.eigvalsh(C) >= 0)
    assert C[5, 5] >= 1e6 and C[5, :5] @ C[5, :5] == 0.0


@pytest.fixture(scope="module")
def rail_plane():
    """The paper's rail ball rendered, its plane and the one-camera rig: (preset, image, radius, plane, rig)."""
    p = get_preset("paper-rail")
    img = render(p.camera, [(p.motion, p.appearance)], p.n_lines, seed=4).image
    R = p.motion.radius_m
    # the rail's plane behind the ball, facing the camera: its centre at depth 1 m
    con = Constraint("plane", normal=(0.0, 0.0, -1.0), offset_m=-(1.0 + R), sigma_m=1e-3, sigma_deg=0.1)
    return p, img, R, con, single_camera_rig(p.camera)


def test_plane_constraint_on_a_rail_ball(rail_plane):
    p, img, R, con, rig = rail_plane
    b = estimate_rig([img], rig, R, constraint=con).balls[0]
    free = estimate_image(img, p.camera, R).balls[0]
    truth = WorldMotion(R, p.motion.t_c_s, p.motion.position_m, p.motion.velocity_mps)
    assert np.all(np.abs(_errors_in_sigmas(b, truth)) < 3.0)
    assert b.sigmas[6] * 3 < free.velocity_sigma_mps[2]  # V.z (depth) pinned by the plane
    # z0: the plane adds information on the depth.  The joint fit scales a camera's rows by the
    # correlation of its residuals under the fitted motion, and the plane's V.z leaves this shaded,
    # textured ball's edges a structured misfit (scale 2.67 against 1.0): compared per unit of each
    # fit's scale, against the same joint fit under a plane too loose to matter
    loose = replace(con, sigma_m=1e3, sigma_deg=89.0)
    unpinned = estimate_rig([img], rig, R, constraint=loose).balls[0]
    per_unit = [x.sigmas[3] / math.sqrt(x.joint.cameras[0].scale) for x in (b, unpinned)]
    assert per_unit[0] <= per_unit[1]
    assert b.joint.constraint is con and b.joint.constraint_residuals.shape == (2,)
    assert "constraint" in b.to_dict()


def test_one_camera_beside_a_constraint_is_measured_on_its_refined_background(rail_plane):
    # the plane fixes the depth motion as a second camera would: the camera's estimate that enters
    # the constrained fit is its refined background's, and with the switch off the detector's
    p, img, R, con, rig = rail_plane
    refined = estimate_image(img, p.camera, R, recipe=Recipe(refined_background=True)).balls[0]
    level = estimate_image(img, p.camera, R).balls[0]
    assert not np.array_equal(refined.velocity_mps, level.velocity_mps)
    for recipe, own in ((Recipe(), refined), (Recipe(rig_refined_background=False), level)):
        b = estimate_rig([img], rig, R, recipe=recipe, constraint=con).balls[0]
        assert b.joint is not None and b.cameras == ("camera",)
        np.testing.assert_array_equal(b.estimates["camera"].velocity_mps, own.velocity_mps)
    # without the constraint, or beside a point (which need not fix the depth motion), the ball is
    # one camera's estimate on the recipe's own level
    point = Constraint("point", point_m=tuple(np.asarray(p.motion.position_m)), sigma_m=0.01)
    for c in (None, point):
        b = estimate_rig([img], rig, R, constraint=c).balls[0]
        np.testing.assert_array_equal(b.estimates["camera"].velocity_mps, level.velocity_mps)


def test_constraint_residuals_vanish_on_the_truth():
    state = np.array([0.0, 0.1, 1.0, 10.0, 1.0, 2.0])
    g = np.array([0.0, 0.0, -9.81])
    plane = Constraint("plane", normal=(0.0, 0.0, 2.0), offset_m=1.0 - 0.03, sigma_m=1e-3)
    flat = state.copy()
    flat[5] = 0.0
    np.testing.assert_allclose(plane.residuals(flat, 0.03, g), 0.0, atol=1e-9)
    assert plane.residuals(state, 0.03, g)[1] > 10
    # a point on the parabola, 0.2 s on
    tau = 0.2
    Q = state[:3] + state[3:] * tau + 0.5 * g * tau * tau
    point = Constraint("point", point_m=tuple(Q), sigma_m=0.01)
    np.testing.assert_allclose(point.residuals(state, 0.03, g), 0.0, atol=1e-9)
    off = Constraint("point", point_m=tuple(Q + np.array([0.0, 0.05, 0.0])), sigma_m=0.01)
    assert np.linalg.norm(off.residuals(state, 0.03, g)) == pytest.approx(5.0, rel=0.05)
    assert off.jacobian(state, 0.03, g).shape == (3, 6)


@pytest.mark.parametrize(
    "spec, kind",
    [("plane:0,0,1,0", "plane"), ("plane:0,0,1,0.1,0.002,0.2", "plane"), ("point:1,2,3", "point"), ("point:1,2,3,0.05", "point")],
)
def test_parse_constraint(spec, kind):
    c = parse_constraint(spec)
    assert c.kind == kind


@pytest.mark.parametrize("spec", ["line:0,0,1", "plane:0,0,1", "plane:0,0,0,1", "point:a,b,c", "point:0,0,0,-1", "plane:0,0,1,0,0.001,95"])
def test_parse_constraint_refuses(spec):
    with pytest.raises(ValueError, match="constraint"):
        parse_constraint(spec)


def _synthetic_cameras(noise_px: float, seed: int):
    cams = []
    for k, rc in enumerate(LANE.rig.cameras):
        cm = LANE.motion.in_camera(rc)
        e = synthetic_edges(rc.camera, cm, LANE.n_lines, edge_sigma_px=max(noise_px, 0.1), seed=seed + k, add_noise=noise_px > 0)
        cams.append(JointCamera(rc.name, rc.camera, e, 0.0 if k == 0 else None, FitSettings(fit_edge_bias=False, edge_floor_px=0.0)))
    return cams


def test_joint_problem_jacobian_matches_differences():
    cams = _synthetic_cameras(0.0, 0)
    m = LANE.motion
    g = np.asarray(m.gravity_mps2)
    lay = JointLayout(cams, m.t_ref_s, g, (False, False))
    states = [BlockState(ResidualBlock(c.camera, c.edges), m.in_camera(LANE.rig.cameras[k], 0.0), c.settings) for k, c in enumerate(cams)]
    x = np.concatenate([m.state, [0.0]]) + np.array([0, 1e-4, -1e-4, 0.01, 0.02, -0.02, 1e-7])
    sels = [st.select(lay.camera_x(x, k)[0], False) for k, st in enumerate(states)]
    con = Constraint("point", point_m=(0.0, 0.06, -0.05), sigma_m=0.01)
    prob = JointProblem(lay, states, sels, m.radius_m, con)
    r0, J = prob.residuals_and_jacobian(x)
    h = np.array([1e-6, 1e-6, 1e-6, 1e-4, 1e-4, 1e-4, 1e-9])
    for i in range(x.size):
        xp, xm = x.copy(), x.copy()
        xp[i] += h[i]
        xm[i] -= h[i]
        num = (prob.residuals(xp) - prob.residuals(xm)) / (2 * h[i])
        assert np.allclose(J[:, i], num, rtol=2e-3, atol=2e-3 * np.abs(num).max() + 1e-9), i


def test_fit_joint_on_synthetic_edges_is_unbiased_within_its_sigmas():
    m = LANE.motion
    cams = _synthetic_cameras(0.1, 5)
    start = WorldMotion(m.radius_m, m.t_ref_s, tuple(np.asarray(m.position_m) + [0, 0.003, -0.002]), tuple(np.asarray(m.velocity_mps) + [0.05, 0.5, -0.5]), m.gravity_mps2)
    res = fit_joint(cams, start, [2e-6])
    assert res.converged and res.consistent
    tr = m.at(res.motion.t_ref_s)
    z = (np.array([*res.motion.position_m[1:], *res.motion.velocity_mps]) - np.array([*tr.position_m[1:], *tr.velocity_mps])) / res.sigmas[2:]
    assert np.all(np.abs(z) < 3.0), z
    i = res.parameter_names.index("clock_offset_s:top")
    assert abs(res.cameras[1].clock_offset_s) < 3 * math.sqrt(res.parameter_covariance[i, i])


def test_matching_window_and_combined_start(lane_render):
    reports = [estimate_image(img, rc.camera, 0.0335) for img, rc in zip(lane_render.images, LANE.rig.cameras)]
    picks = {0: reports[0].balls[0], 1: reports[1].balls[0]}
    start, offsets = combined_start(LANE.rig, picks, 0.0335)
    assert offsets == []
    tr = LANE.motion.at(start.t_ref_s)
    assert np.linalg.norm(np.asarray(start.velocity_mps) - tr.velocity_mps) < 0.5
    state = np.array([*tr.position_m, *tr.velocity_mps])
    t_pred, half = match_window_s(LANE.rig, 1, state, np.zeros((6, 6)), tr.t_ref_s)
    assert t_pred == pytest.approx(picks[1].t_c_s, abs=1e-6) and half == pytest.approx(LANE.rig.match_window_s)


def test_images_must_match_the_cameras(lane_render):
    with pytest.raises(ValueError, match="one per camera"):
        estimate_rig(lane_render.images[:1], LANE.rig, 0.0335)


def test_parallel_planes_apart_with_gravity_and_an_unknown_clock():
    # the top camera's plane 0.3 m down the lane: 6.7 ms later, the ball 0.2 mm lower (gravity), its clock 6 ms behind
    top = camera_about_lane(LANE.rig.cameras[1].camera, 4.0, 90.0, 0.3)
    rig = LANE.rig.with_camera(1, replace(LANE.rig.cameras[1], camera=top))
    sim = simulate_rig(rig, LANE.motion, 220, LANE.appearance, seed=21, clock_offsets_s={"top": -6e-3})
    rig = rig.with_camera(1, replace(rig.cameras[1], clock_offset_s=None, clock_sigma_s=2e-3))
    b = estimate_rig(sim.images, rig, LANE.motion.radius_m).balls[0]
    assert b.cameras == ("side", "top") and b.flags == ()
    assert np.all(np.abs(_errors_in_sigmas(b, LANE.motion)) < 3.0)
    top_fit = b.joint.cameras[1]
    assert abs(top_fit.clock_offset_s + 6e-3) < 3 * top_fit.clock_offset_sigma_s


POVRAY_RIG = Path(__file__).parent / "data" / "povray_rig"


@pytest.fixture(scope="module")
def povray_pair(tmp_path_factory):
    """An independent render (POV-Ray, benchmarks/povray_set/score_rig.py): views a000 (the world frame)
    and a090 of one ball, a rig file referring to their camera files (shared clock, no gravity); the rig,
    the truth and the joint report."""
    name = "pv1013"
    rig_file = tmp_path_factory.mktemp("pair") / "pair.rig.toml"
    rig_file.write_text("".join(
        f'[[camera]]\nname = "{v}"\nclock_offset_s = 0.0\nfile = "{(POVRAY_RIG / f"{name}_{v}.camera.toml").as_posix()}"\n\n' for v in ("a000", "a090")))
    rig = load_rig(rig_file)
    truth = json.loads((POVRAY_RIG / f"{name}_a000.truth.json").read_text())
    images = [POVRAY_RIG / f"{name}_{v}.png" for v in ("a000", "a090")]
    return rig, truth, estimate_rig(images, rig, truth["radius_m"])


def test_two_povray_views_pin_the_direction(povray_pair):
    name = "pv1013"
    rig, truth, rep = povray_pair
    assert len(rep.balls) == 1
    b = rep.balls[0]
    assert b.cameras == ("a000", "a090") and "single_camera" not in b.flags and "inconsistent_camera" not in b.flags, b.flags
    # a line-scan camera does not see the sign of V.x (both views share the axis x)
    V, Vt = np.asarray(b.motion.velocity_mps), np.asarray(truth["velocity_mps"]) * np.array([-1.0, 1.0, 1.0])
    assert V[0] > 0 and Vt[0] > 0
    el, el_s, az, az_s = b.direction()
    assert abs(el - math.degrees(math.atan2(Vt[2], math.hypot(Vt[0], Vt[1])))) < 3 * el_s
    assert abs(az - math.degrees(math.atan2(Vt[1], Vt[0]))) < 3 * az_s
    sp, sp_s = b.speed()
    assert abs(sp - np.linalg.norm(Vt)) < 3 * sp_s
    # the crossing time within a tenth of a line period (its 3-sigma check: the next test)
    line_period_s = 1.0 / rig.cameras[0].camera.line_rate_hz
    assert abs(b.t_c_s - truth["t_c_s"]) < 0.1 * line_period_s
    joint_err = _angle_deg(V, Vt)
    assert joint_err < 0.5
    # each view alone, on the same pixels (its frame): its depth axis unpinned
    alone = []
    for v in ("a000", "a090"):
        own = b.estimates[v]
        vt = np.asarray(json.loads((POVRAY_RIG / f"{name}_{v}.truth.json").read_text())["velocity_mps"])
        if own.velocity_mps is not None:
            alone.append(_angle_deg(np.asarray(own.velocity_mps), vt * np.array([np.sign(vt[0]), 1.0, 1.0])))
    assert alone and min(alone) > 10 * joint_err, (alone, joint_err)


@pytest.mark.xfail(strict=True, reason="the textured, shaded limb's model error moves the joint crossing time by 14 us, "
                   "3.2 of its joint sigmas: the t_c sigma is not calibrated on this ball")
def test_two_povray_views_crossing_time_within_3_sigma(povray_pair):
    _, truth, rep = povray_pair
    b = rep.balls[0]
    assert abs(b.t_c_s - truth["t_c_s"]) < 3 * b.sigmas[0]


def _angle_deg(a: np.ndarray, b: np.ndarray) -> float:
    return math.degrees(math.acos(min(1.0, float(a @ b / (np.linalg.norm(a) * np.linalg.norm(b))))))


def test_the_joint_covariance_holds_each_cameras_limb_error():
    """Analytic against brute force, as for one camera: the joint velocity's added covariance is the sum of the
    outer products of the joint fit's moves when each side of each camera is displaced by one sigma of the
    trend and of the curvature in turn, here with one camera's residuals 1.5 times their stated sigma (unequal
    covariance scales)."""
    from dataclasses import replace

    m = LANE.motion
    start = WorldMotion(m.radius_m, m.t_ref_s, m.position_m, m.velocity_mps, m.gravity_mps2)
    cams = _synthetic_cameras(0.1, 5)
    rng = np.random.default_rng(11)
    e0 = cams[0].edges
    loud = replace(e0, left_px=e0.left_px + rng.normal(0, 0.15, e0.t_s.size), right_px=e0.right_px + rng.normal(0, 0.15, e0.t_s.size))
    cams = [replace(cams[0], edges=loud), cams[1]]

    def fit(cams, trend_px):
        return fit_joint([replace(c, settings=replace(c.settings, limb_trend_sigma_px=trend_px, limb_residual_gain=0.0)) for c in cams], start, [2e-6])

    on, off = fit(cams, 0.05), fit(cams, 0.0)
    assert on.cameras[0].scale > 1.8 * on.cameras[1].scale
    brute = np.zeros((3, 3))
    for k, c in enumerate(cams):
        for side in ("left", "right"):
            x = getattr(c.edges, f"{side}_px")
            ok = np.isfinite(x)
            t = c.edges.t_s
            tau = 2.0 * (t - t[ok].min()) / (t[ok].max() - t[ok].min()) - 1.0
            for shape in (tau, 1.5 * tau**2 - 0.5):
                moved = list(cams)
                moved[k] = replace(c, edges=replace(c.edges, **{f"{side}_px": x + 0.05 * shape}))
                d = np.asarray(fit(moved, 0.05).motion.velocity_mps) - np.asarray(on.motion.velocity_mps)
                brute += np.outer(d, d)
    added = on.covariance[4:, 4:] - off.covariance[4:, 4:]
    sig, total = np.sqrt(np.diag(brute)), np.sqrt(np.diag(on.covariance)[4:])
    # VY and VZ, which the limbs' trends and curvatures move by 0.05 m/s each: within 1 %; VX, which the
    # curvature moves through the passage's duration (0.04 m/s here), within 10 % (its second-order part)
    assert np.allclose(np.sqrt(np.diag(added))[1:], sig[1:], rtol=0.01), (np.sqrt(np.diag(added)), sig)
    assert np.allclose(np.sqrt(added[0, 0]), sig[0], rtol=0.1), (np.sqrt(np.diag(added)), sig)
