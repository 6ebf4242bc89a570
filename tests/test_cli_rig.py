"""The command line of rigs: rig check, simulate/estimate/precision --rig, --constraint, one-line errors."""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from ballscan.cli.app import main


def run(capsys, *args):
    code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_rig_check_prints_planes_and_their_crossing(capsys):
    code, out, err = run(capsys, "rig", "check", "lane-30")
    assert code == 0, err
    assert "side: viewing plane +1.0000 X" in out and "side x oblique: the same plane; optical axes 30.00 deg apart" in out


def test_simulate_then_estimate_rig_json(tmp_path, capsys):
    name = tmp_path / "lane"
    code, out, err = run(capsys, "simulate", "--rig", "lane-90", "--out", name, "--seed", "7", "--unknown-clock", "top", "--clock-offset", "top=0.0002")
    assert code == 0, err
    for suffix in (".rig.toml", ".side.png", ".top.png", ".truth.json"):
        assert (tmp_path / f"lane{suffix}").exists()
    truth = json.loads((tmp_path / "lane.truth.json").read_text())
    assert truth["frame"] == "world" and truth["clock_offsets_s"]["top"] == 0.0002
    code, out, err = run(capsys, "estimate", "--rig", f"{name}.rig.toml", f"{name}.side.png", f"{name}.top.png", "--radius", truth["radius_m"], "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert len(doc["balls"]) == 1
    b = doc["balls"][0]
    assert b["cameras"] == ["side", "top"] and b["flags"] == []
    for key in ("t_c_s", "position_m", "velocity_mps", "speed_mps", "velocity_sigma_mps", "elevation_deg", "elevation_sigma_deg",
                "azimuth_deg", "azimuth_sigma_deg", "covariance", "per_camera", "inconsistent_cameras", "own"):
        assert key in b
    top = b["per_camera"]["top"]
    assert abs(top["clock_offset_s"] - 2e-4) < 3 * top["clock_offset_sigma_s"]
    V = np.array(truth["velocity_mps"])
    assert abs(b["elevation_deg"] - math.degrees(math.atan2(V[2], math.hypot(V[0], V[1])))) < 4 * b["elevation_sigma_deg"]
    # the table
    code, out, err = run(capsys, "estimate", "--rig", f"{name}.rig.toml", f"{name}.side.png", f"{name}.top.png", "--radius", truth["radius_m"])
    assert code == 0 and "side+top" in out and "consistent, clock offset" in out


def test_precision_rig_bound_sweep_and_plot(tmp_path, capsys):
    args = ("precision", "--rig", "lane-90", "--radius", "0.0335", "--position", "0,0.06,-0.05", "--velocity", "44.6,3.2,-5.1")
    code, out, err = run(capsys, *args, "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["direction_sigma_deg"] < 0.1 and len(doc["velocity_sigma_mps"]) == 3
    png = tmp_path / "sweep.png"
    code, out, err = run(capsys, *args, "--sweep", "10:90:40", "--plot", png)
    assert code == 0, err
    rows = [line.split() for line in out.splitlines()[1:4]]
    assert [float(r[0]) for r in rows] == [10.0, 50.0, 90.0]
    assert float(rows[0][1]) > float(rows[2][1])
    assert png.stat().st_size > 1000


def test_constraint_with_one_camera(tmp_path, capsys):
    name = tmp_path / "rail"
    assert run(capsys, "simulate", "--preset", "paper-rail", "--out", name, "--seed", "2")[0] == 0
    con = "plane:0,0,-1,-1.0335,0.001,0.1"
    code, out, err = run(capsys, "estimate", f"{name}.png", "--camera", f"{name}.camera.toml", "--radius", "0.0335", "--constraint", con, "--json")
    assert code == 0, err
    b = json.loads(out)["balls"][0]
    assert b["constraint"]["kind"] == "plane" and len(b["constraint"]["residuals_sigma"]) == 2
    assert abs(b["velocity_mps"][2]) < 3 * b["velocity_sigma_mps"][2]
    code, out, err = run(capsys, "precision", "--camera", f"{name}.camera.toml", "--radius", "0.0335", "--position", "0,0,1", "--velocity", "0.1,0,0", "--constraint", con)
    assert code == 0 and "elevation" in out


@pytest.mark.parametrize(
    "args, words",
    [
        (("rig", "check", "nowhere.rig.toml"), "neither a rig file nor a rig preset"),
        (("estimate", "--rig", "lane-90.rig.toml", "a.png", "--radius", "0.03"), "file not found"),
        (("estimate", "a.png", "--camera", "c.toml", "--radius", "0.03", "--constraint", "line:1"), "--constraint"),
        (("estimate", "a.png", "b.png", "--camera", "c.toml", "--radius", "0.03"), "one image per command"),
        (("precision", "--radius", "0.03", "--position", "0,0,1", "--velocity", "1,0,0", "--sweep", "0:90:10"), "give --camera"),
        (("simulate", "--rig", "lane-90", "--out", "x", "--only", "nobody"), "no camera 'nobody'"),
    ],
)
def test_rig_errors_are_one_line(tmp_path, capsys, monkeypatch, args, words):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, *args)
    assert code == 2
    assert words in err and err.count("\n") == 1, err


def test_estimate_rig_needs_one_image_per_camera(tmp_path, capsys):
    name = tmp_path / "lane"
    assert run(capsys, "simulate", "--rig", "lane-90", "--out", name, "--noise", "none")[0] == 0
    code, out, err = run(capsys, "estimate", "--rig", f"{name}.rig.toml", f"{name}.side.png", "--radius", "0.0335")
    assert code == 2 and "1 images for 2 cameras" in err


def test_rig_watch_pairs_two_raw_streams(tmp_path, capsys):
    from dataclasses import replace

    from ballscan.lab.rig import RIG_PRESETS, simulate_rig
    from ballscan.geometry.rig import save_rig

    p = RIG_PRESETS["lane-90"]
    motion = replace(p.motion, t_ref_s=1500 / 70000.0)
    sim = simulate_rig(p.rig, motion, 2400, p.appearance, seed=4)
    paths = []
    for rc, img in zip(p.rig.cameras, sim.images):
        path = tmp_path / f"{rc.name}.raw"
        img.tofile(path)
        paths.append(path)
    save_rig(p.rig, tmp_path / "lane.rig.toml")
    code, out, err = run(capsys, "rig", "watch", tmp_path / "lane.rig.toml", *paths, "--radius", "0.0335", "--chunk-lines", "200")
    assert code == 0, err
    lines = out.splitlines()
    assert len(lines) == 1
    b = json.loads(lines[0])
    assert b["cameras"] == ["side", "top"] and b["flags"] == []
    tr = motion.at(b["t_c_s"])
    z = (np.array(b["velocity_mps"]) - tr.velocity_mps) / np.array(b["velocity_sigma_mps"])
    assert np.all(np.abs(z) < 4.0), z  # the pairing and the crops' cameras (calibration: bench_rig.py)
    assert set(b["own_t_c_s"]) == {"side", "top"}
    code, out, err = run(capsys, "rig", "watch", tmp_path / "lane.rig.toml", paths[0], "--radius", "0.0335")
    assert code == 2 and "1 sources for 2 cameras" in err
    # 'ballscan watch --rig' is the same command
    code, alias, err = run(capsys, "watch", "--rig", tmp_path / "lane.rig.toml", *paths, "--radius", "0.0335", "--chunk-lines", "200")
    assert code == 0, err
    assert [json.loads(x)["velocity_mps"] for x in alias.splitlines()] == [b["velocity_mps"]]
    code, out, err = run(capsys, "watch", "--rig", tmp_path / "lane.rig.toml", paths[0], "--radius", "0.0335")
    assert code == 2 and "1 sources for 2 cameras" in err


@pytest.mark.parametrize(
    "args, words",
    [
        (["--rig", "R.toml", "a.raw", "b.raw", "--radius", "0.03", "--camera", "c.toml"], ["--camera", "does not apply"]),
        (["--rig", "R.toml", "a.raw", "b.raw", "--radius", "0.03", "--format", "table"], ["--format", "does not apply"]),
        (["a.raw", "b.raw", "--camera", "c.toml", "--radius", "0.03"], ["one source without --rig"]),
        (["a.raw", "--radius", "0.03"], ["give --camera"]),
        (["a.raw", "--camera", "c.toml"], ["give --radius"]),
        (["a.raw", "--camera", "c.toml", "--radius", "0.03", "--pair-timeout", "1"], ["--pair-timeout", "needs --rig"]),
    ],
)
def test_watch_rig_alias_refuses_what_does_not_fit(tmp_path, capsys, monkeypatch, args, words):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, "watch", *args)
    assert code == 2 and out == ""
    assert all(w in err for w in words), err
    assert len(err.strip().splitlines()) == 1


def _strict(text: str):
    """JSON that holds no NaN or Infinity (which JSON does not have)."""
    def refuse(name):
        raise ValueError(f"not JSON: {name}")
    return json.loads(text, parse_constant=refuse)


def test_a_joint_fit_with_an_undetermined_component_reports_it_undetermined(tmp_path, capsys):
    # a 0.053 m/s ball seen by two POV-Ray views 90 degrees apart whose joint fit leaves x and V.x
    # undetermined (the solver stops near 1e159 m/s along that flat direction): null, not a number
    rig_dir = Path(__file__).resolve().parents[1] / "benchmarks" / "povray_set" / "rig"
    rig = tmp_path / "pair.rig.toml"
    rig.write_text("".join(f'[[camera]]\nname = "{v}"\nclock_offset_s = 0.0\nfile = "{rig_dir / f"pv1069_{v}.camera.toml"}"\n\n' for v in ("a000", "a090")))
    radius = json.loads((rig_dir / "pv1069_a000.truth.json").read_text())["radius_m"]
    images = [rig_dir / f"pv1069_{v}.png" for v in ("a000", "a090")]
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # no overflow on the way either
        code, out, err = run(capsys, "estimate", "--rig", rig, *images, "--radius", radius, "--json")
        assert code == 0, err
        table = run(capsys, "estimate", "--rig", rig, *images, "--radius", radius)
    (b,) = _strict(out)["balls"]
    assert "degenerate" in b["flags"] and "vx_mps" in b["undetermined"]
    assert b["velocity_mps"][0] is None and b["speed_mps"] is None and b["elevation_deg"] is None and b["azimuth_deg"] is None
    # the crossing of the reference plane (world x) moves with x and V.x: undetermined as well
    assert b["t_c_s"] is None and b["t_c_sigma_s"] is None and all(c["t_c_s"] is None for c in b["per_camera"].values())
    assert all(v is not None and abs(v) < 1.0 for v in b["velocity_mps"][1:])
    code, out, err = table
    assert code == 0 and "inf" not in out, err
    assert out.splitlines()[1].split()[2] == "undetermined" and "(x_m, vx_mps)" in out
