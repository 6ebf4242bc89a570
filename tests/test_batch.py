"""Tests of ``ballscan batch`` (ballscan.stream.batch, ballscan.cli.stream.batch)."""

from __future__ import annotations

import csv
import sys
from pathlib import Path

import numpy as np
import pytest

from ballscan.stream.batch import COLUMNS, find_inputs, measure_input, run_batch
from ballscan.geometry.camera import LineScanCamera, save_camera
from ballscan.errors import BallscanError
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, SensorNoise, render, write_image
from ballscan.cli.stream import batch

RADIUS = 0.0335
CAM = LineScanCamera(width=512, focal_px=1100.0, principal_px=255.5, line_rate_hz=20000.0)


def _image(lines: list[float], n: int = 400, seed: int = 0) -> np.ndarray:
    balls = [(BallMotion(RADIUS, ln / CAM.line_rate_hz, (0.0, 0.1 * k - 0.05, 4.0), (35.0, 1.0, -2.0)), Appearance.flat(0.8)) for k, ln in enumerate(lines)]
    return render(CAM, balls, n, background_level=0.12, noise=SensorNoise(), seed=seed).image


@pytest.fixture(scope="module")
def recordings(tmp_path_factory) -> Path:
    """Three images (1, 2 and 0 balls), a raw stream with 2 balls, and an unreadable file."""
    d = tmp_path_factory.mktemp("rec")
    for name, lines in (("one", [200.0]), ("two", [120.0, 290.0]), ("none", [])):
        write_image(d / f"{name}.png", _image(lines, seed=len(name)))
        save_camera(CAM, d / f"{name}.camera.toml")
    raw = _image([700.0, 2000.0], n=3000, seed=9)
    (d / "stream.raw").write_bytes(raw.tobytes())
    save_camera(CAM, d / "stream.raw.camera.toml")
    (d / "bad.png").write_bytes(b"not a png at all")
    save_camera(CAM, d / "bad.camera.toml")
    return d


def _rows(path: Path) -> list[dict]:
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def test_find_inputs_and_cameras_beside(recordings):
    files = find_inputs([recordings])
    assert sorted(p.name for p in files) == ["bad.png", "none.png", "one.png", "stream.raw", "two.png"]
    res = measure_input(str(recordings / "two.png"), None, RADIUS)
    assert res.error is None and len(res.rows) == 2
    assert set(res.rows[0]) == set(COLUMNS)


def test_batch_parallel_restartable(recordings, tmp_path):
    out = tmp_path / "balls.csv"
    s = run_batch([recordings], out, RADIUS, jobs=2)
    assert (s.n_inputs, s.n_skipped, s.n_done, s.n_balls) == (5, 0, 4, 5)
    assert len(s.errors) == 1 and "bad.png" in s.errors[0][1] and "\n" not in s.errors[0][1]
    rows = _rows(out)
    by_src = {}
    for r in rows:
        by_src.setdefault(Path(r["source"]).name, []).append(r)
    assert {k: len(v) for k, v in by_src.items()} == {"one.png": 1, "two.png": 2, "stream.raw": 2}
    for r in rows:
        # truth 35.07 m/s; on this narrow sensor the fit's depth velocity is uncertain
        assert abs(float(r["speed_mps"]) - 35.07) <= 5 * float(r["speed_sigma_mps"]) + 0.5
        assert float(r["speed_sigma_mps"]) > 0 and r["first_line"] and r["last_line"]
    stream_first = sorted(int(r["first_line"]) for r in by_src["stream.raw"])
    assert 660 < stream_first[0] < 700 and 1960 < stream_first[1] < 2000  # stream line numbers
    # restart: everything measured (also the image without balls) is skipped; the failure is retried
    s2 = run_batch([recordings], out, RADIUS, jobs=2)
    assert (s2.n_skipped, s2.n_done, len(s2.errors)) == (4, 0, 1)
    assert len(_rows(out)) == len(rows)


def test_batch_one_camera_for_all_and_missing_camera(recordings, tmp_path):
    lone = tmp_path / "lone.png"
    lone.write_bytes((recordings / "one.png").read_bytes())
    s = run_batch([lone], tmp_path / "a.csv", RADIUS)
    assert s.n_done == 0 and "no camera file" in s.errors[0][1]
    cam = tmp_path / "cam.toml"
    save_camera(CAM, cam)
    s = run_batch([lone], tmp_path / "b.csv", RADIUS, camera=cam)
    assert s.n_done == 1 and s.n_balls == 1


def test_batch_command_function(recordings, tmp_path, capsys):
    from ballscan.cli.signals import ExitStatus

    assert batch([recordings / "one.png"], tmp_path / "c.csv", RADIUS, progress=True) == 1
    with pytest.raises(ExitStatus) as ei:
        batch([recordings / "bad.png"], tmp_path / "c.csv", RADIUS, progress=False)
    assert ei.value.code == 1
    err = capsys.readouterr().err
    assert "ballscan: error:" in err and "bad.png" in err
    assert "1 inputs measured (1 balls), 0 skipped" in err
    assert "0 inputs measured (0 balls), 0 skipped" in err


def test_scheduler_needs_distributed(recordings, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(BallscanError, match=r"--scheduler needs Dask distributed: pip install \"dask\[distributed\]\""):
        run_batch([recordings / "one.png"], tmp_path / "d.csv", RADIUS, scheduler="tcp://127.0.0.1:1")


@pytest.mark.slow
def test_batch_on_dask_local_cluster(recordings, tmp_path):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster:
        s = run_batch([recordings], tmp_path / "e.csv", RADIUS, scheduler=cluster.scheduler_address)
    assert (s.n_done, s.n_balls, len(s.errors)) == (4, 5, 1)
    assert len(_rows(tmp_path / "e.csv")) == 5


def test_truncated_raw_stream_keeps_its_balls(recordings, tmp_path):
    raw = tmp_path / "cut.raw"
    raw.write_bytes((recordings / "stream.raw").read_bytes() + b"\x00" * 7)
    s = run_batch([raw], tmp_path / "f.csv", RADIUS, camera=recordings / "one.camera.toml")
    assert s.n_balls == 2 and len(s.errors) == 1 and "partial line of 7 bytes" in s.errors[0][1]
    assert len(_rows(tmp_path / "f.csv")) == 2
    assert run_batch([raw], tmp_path / "f.csv", RADIUS, camera=recordings / "one.camera.toml").n_skipped == 1


def test_batch_background_reaches_raw_streams(recordings, tmp_path):
    """--background: the stream's balls measured on the engine's columns (default, as watch) or the crop's own."""
    rows = {}
    for bg in ("engine", "crop"):
        out = tmp_path / f"{bg}.csv"
        s = run_batch([recordings / "stream.raw"], out, RADIUS, background=bg)
        assert s.n_balls == 2 and not s.errors
        with open(out) as fh:
            rows[bg] = list(csv.DictReader(fh))
    # the same balls, measured on different backgrounds
    assert [r["first_line"] for r in rows["engine"]] == [r["first_line"] for r in rows["crop"]]
    assert [r["t_c_s"] for r in rows["engine"]] != [r["t_c_s"] for r in rows["crop"]]
    with pytest.raises(ValueError, match="background"):
        run_batch([recordings / "stream.raw"], tmp_path / "x.csv", RADIUS, background="image")


def test_the_batch_warm_up_loads_the_estimators_kernels_not_the_stream_engines():
    import subprocess

    code = (
        "from ballscan.stream.batch import load_estimator; load_estimator(); "
        "from ballscan import compiled; from ballscan.pipeline.warmup import KERNEL_MODULES; "
        "est = [bool(k.signatures) for m in KERNEL_MODULES for k in compiled.KERNELS[m] if not k.py_func.__name__.startswith('_')]; "
        "line = [bool(k.signatures) for k in compiled.KERNELS['ballscan.stream._line_kernels']]; "
        "print(len(est), all(est), len(line), any(line))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert int(out[0]) >= 40 and out[1] == "True"
    assert int(out[2]) >= 1 and out[3] == "False"


def test_batch_recipe_file_reaches_every_input(recordings, tmp_path, capsys):
    """--recipe: the paper method from a recipe file, as --method paper gives it; --method over the file; a bad file is one line, status 2."""
    from ballscan.cli.app import main

    (tmp_path / "paper.toml").write_text('method = "paper"\n')
    rows = {}
    for name, extra in (("file", ["--recipe", tmp_path / "paper.toml"]), ("flag", ["--method", "paper"]),
                        ("over", ["--recipe", tmp_path / "paper.toml", "--method", "fit"])):
        out = tmp_path / f"{name}.csv"
        main(["batch", str(recordings / "two.png"), "--out", str(out), "--radius", str(RADIUS)] + [str(a) for a in extra])
        rows[name] = _rows(out)
    capsys.readouterr()
    assert [r["method"] for r in rows["file"]] == ["paper", "paper"]
    assert [(r["method"], r["t_c_s"]) for r in rows["file"]] == [(r["method"], r["t_c_s"]) for r in rows["flag"]]
    assert [r["method"] for r in rows["over"]] == ["fit", "fit"]
    (tmp_path / "bad.toml").write_text("pixels = 2\n")
    code = main(["batch", str(recordings / "two.png"), "--out", str(tmp_path / "bad.csv"), "--radius", str(RADIUS), "--recipe", str(tmp_path / "bad.toml")])
    err = capsys.readouterr().err
    assert code == 2 and err.strip() == f"ballscan: error: {tmp_path / 'bad.toml'}: pixels: expected True or False, got 2"
    with pytest.raises(ValueError, match="recipe"):
        run_batch([recordings / "two.png"], tmp_path / "x.csv", RADIUS, recipe="paper")


def test_a_rerun_with_another_recipe_is_refused_not_mixed(recordings, tmp_path):
    from ballscan.pipeline.recipe import Recipe

    out = tmp_path / "r.csv"
    assert run_batch([recordings / "one.png", recordings / "none.png"], out, RADIUS, recipe=Recipe(method="paper")).n_balls == 1
    rows = _rows(out)
    with pytest.raises(BallscanError, match=r'r.csv: measured with the recipe \{"method": "paper"\}, not \{\}'):
        run_batch([recordings], out, RADIUS)
    assert _rows(out) == rows  # nothing written
    # the same recipe resumes: the two inputs skipped, the others measured
    s = run_batch([recordings], out, RADIUS, recipe=Recipe(method="paper"))
    assert s.n_skipped == 2 and {r["method"] for r in _rows(out)} == {"paper"}
    # a CSV whose inputs had no ball is held to its recipe too
    empty = tmp_path / "e.csv"
    run_batch([recordings / "none.png"], empty, RADIUS)
    with pytest.raises(BallscanError, match="e.csv: measured with the recipe"):
        run_batch([recordings / "none.png"], empty, RADIUS, recipe=Recipe(shading=False))
