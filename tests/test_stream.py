"""Tests of the stream engine, the line sources and ``watch`` (ballscan.stream.engine, .sources, .stream_cli)."""

from __future__ import annotations

import json
from dataclasses import replace
import os
import threading
import time
import tracemalloc
from pathlib import Path

import numpy as np
import pytest
import typer

from ballscan.geometry.camera import LineScanCamera, save_camera
from ballscan.pipeline.estimate import estimate_image
from ballscan.pipeline.recipe import Recipe
from ballscan.measure.images import LineImage
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, SensorNoise, apply_sensor, render, write_image
from ballscan.stream.sources import (
    ArraySource,
    ImageFolderSource,
    RawLineSource,
    SourceError,
    SourceStalled,
    TruncatedStream,
    load_truth_lines,
    simulate_stream,
    stream_balls,
)
from ballscan.geometry.camera import crop_camera
from ballscan.stream.engine import Chunk, StreamConfig, StreamEngine, StreamError, estimate_crop, process_stream
from ballscan.cli.stream import watch

RADIUS = 0.0335
CAM = LineScanCamera(width=512, focal_px=1100.0, principal_px=255.5, line_rate_hz=20000.0)
N_LINES = 64_000
N_BALLS = 32
SEED = 7
CHUNKS = (7, 64, 1024)


# ---------------------------------------------------------------- helpers
def small_stream(n_lines: int = 3000, balls=((900.0, 0.0), (2000.0, 0.2)), seed: int = 1, level: float = 0.12) -> np.ndarray:
    """A short 8-bit stream of CAM with balls crossing at the given (line, y0) pairs."""
    motions = [(BallMotion(RADIUS, ln / CAM.line_rate_hz, (0.0, y0, 4.0), (35.0, 1.0, -2.0)), Appearance.flat(0.8)) for ln, y0 in balls]
    return render(CAM, motions, n_lines, background_level=level, noise=SensorNoise(), seed=seed).image


def write_raw(path: Path, data: np.ndarray, extra: bytes = b"") -> Path:
    path.write_bytes(np.ascontiguousarray(data).tobytes() + extra)
    return path


def match(results, truths, line_rate):
    """Pair each truth with the results whose t_c is within one line and first line within 3."""
    pairs = []
    for tr in truths:
        hits = [
            r
            for r in results
            if r.estimate.t_c_s is not None
            and abs(r.estimate.t_c_s - tr["t_c_s"]) * line_rate < 1.0
            and abs(r.estimate.first_line - tr["first_line"]) <= 3
        ]
        pairs.append((tr, hits))
    return pairs


# ---------------------------------------------------------------- the long stream
@pytest.fixture(scope="module")
def long_stream(tmp_path_factory):
    """64 000 lines x 512 px, 32 balls (two close pairs), a 30 % illumination ramp, 4 lines dropped inside a ball."""
    plan = stream_balls(CAM, N_LINES, N_BALLS, SEED, close_pairs=2)
    ball_lines = [int(round(m.t_c_s * CAM.line_rate_hz)) for m in plan]
    # Ball positions in lines do not depend on the timestamps: drop lines inside ball 15.
    dropped = (ball_lines[15] + 3, 4)
    out = tmp_path_factory.mktemp("stream") / "s.raw"
    sim = simulate_stream(out, CAM, N_LINES, N_BALLS, SEED, close_pairs=2, ramp=0.3, dropped=dropped)
    return sim, dropped


@pytest.fixture(scope="module")
def runs(long_stream):
    sim, _ = long_stream
    out = {}
    for ch in CHUNKS:
        src = RawLineSource(sim.raw, CAM.width, chunk_lines=ch, timestamps=sim.timestamps_path)
        out[ch] = list(process_stream(src, CAM, RADIUS, source="s.raw"))
    # the crop's own background (StreamConfig.background="crop")
    src = RawLineSource(sim.raw, CAM.width, chunk_lines=64, timestamps=sim.timestamps_path)
    out["crop"] = list(process_stream(src, CAM, RADIUS, StreamConfig(background="crop"), source="s.raw"))
    return out


@pytest.mark.slow
def test_simulated_stream_files(long_stream):
    sim, dropped = long_stream
    assert sim.raw.stat().st_size == N_LINES * CAM.width
    truths = load_truth_lines(sim.truth_path)
    assert len(truths) == N_BALLS
    for tr in truths:
        assert {"radius_m", "t_c_s", "position_m", "velocity_mps", "speed_mps", "first_line", "last_line"} <= set(tr)
    t = np.load(sim.timestamps_path)
    steps = np.diff(t) * CAM.line_rate_hz
    assert np.flatnonzero(steps > 1.5).tolist() == [dropped[0]]
    assert steps[dropped[0]] == pytest.approx(1 + dropped[1])


@pytest.mark.slow
def test_every_ball_found_once_none_invented(long_stream, runs):
    sim, _ = long_stream
    truths = load_truth_lines(sim.truth_path)
    res = runs[64]
    pairs = match(res, truths, CAM.line_rate_hz)
    missing = [tr["first_line"] for tr, hits in pairs if len(hits) != 1]
    assert missing == []
    assert len(res) == len(truths)
    # the stream really exercises chunk boundaries and close pairs
    straddling = [tr for tr in truths if tr["first_line"] // 64 != tr["last_line"] // 64]
    assert len(straddling) >= N_BALLS // 2
    events = [r.event_index for r in res]
    assert len(events) - len(set(events)) == 2  # each close pair shares one crop


@pytest.mark.slow
def test_same_results_for_any_chunk_size(runs):
    ref = runs[64]
    for ch in CHUNKS:
        got = runs[ch]
        assert [(r.estimate.first_line, r.estimate.last_line) for r in got] == [(r.estimate.first_line, r.estimate.last_line) for r in ref]
        for a, b in zip(got, ref):
            assert a.estimate.t_c_s == b.estimate.t_c_s
            assert a.estimate.position_m == b.estimate.position_m
            assert a.estimate.velocity_mps == b.estimate.velocity_mps
            assert a.crop_lines == b.crop_lines and a.crop_cols == b.crop_cols


@pytest.mark.slow
def test_accuracy_as_single_image_fit(long_stream, runs):
    """Each ball is measured as the precise fit measures the same lines as one image."""
    sim, _ = long_stream
    data = np.memmap(sim.raw, dtype=np.uint8, mode="r", shape=(N_LINES, CAM.width))
    ts = np.load(sim.timestamps_path)
    truths = load_truth_lines(sim.truth_path)
    ratios = []  # the crop's own background against the whole width
    err = {"engine": [], "crop": [], "single": []}  # errors against the truth
    for bg, res in (("engine", runs[64]), ("crop", runs["crop"])):
        for r in res:
            e = r.estimate
            l0, l1 = r.crop_lines
            c0, c1 = r.crop_cols
            # 1. the very same numbers as estimate_image on the event's crop (with the engine's columns)
            assert (r.crop_columns is None) == (bg == "crop")
            same = estimate_crop(np.asarray(data[l0:l1, c0:c1]), ts[l0:l1], crop_camera(CAM, c0, c1), RADIUS, Recipe(), 255.0, 8, "crop", columns=r.crop_columns)
            k = int(np.argmin([abs(b.t_c_s - e.t_c_s) for b in same]))
            assert same[k].t_c_s == e.t_c_s and same[k].position_m == e.position_m and same[k].velocity_mps == e.velocity_mps
            v = np.r_[e.t_c_s, e.position_m[1:], e.velocity_mps]
            s = np.r_[e.t_c_sigma_s, e.position_sigma_m[1:], e.velocity_sigma_mps]
            # 2. the truth within the fit's uncertainty
            tr = min(truths, key=lambda t: abs(t["t_c_s"] - e.t_c_s))
            u = np.r_[tr["t_c_s"], tr["position_m"][1:], tr["velocity_mps"]]
            assert np.all(np.abs(v - u) <= 5 * s)
            err[bg].append(v - u)
            # 3. the whole sensor width over the same lines
            ref = estimate_image(LineImage(np.asarray(data[l0:l1], dtype=float), 255.0, 8, "lines"), CAM, RADIUS, timestamps_s=ts[l0:l1]).balls
            rb = ref[int(np.argmin([abs(b.t_c_s - e.t_c_s) for b in ref]))]
            w = np.r_[rb.t_c_s, rb.position_m[1:], rb.velocity_mps]
            if bg == "engine":
                err["single"].append(w - u)
                continue
            # on the crop's own background, equal to it within a fraction of
            # the fit's 1-sigma (the crop's narrower columns change detect()'s
            # per-line gain and noise a little); where one fit keeps the lines
            # of the ball's partial exposure levelled and the other does not
            # (FitSettings.area_partial_check), the larger of the two sigmas
            # says how far apart two valid estimates may be
            s_ref = np.r_[rb.t_c_sigma_s, rb.position_sigma_m[1:], rb.velocity_sigma_mps]
            differ = e.extra["partial_levelled"] != rb.extra["partial_levelled"]
            ratios.append(np.abs(v - w) / (np.maximum(s, s_ref) if differ else s))
    ratios = np.array(ratios)  # (ball, [t_c, y0, z0, vx, vy, vz])
    # the crop's own background and shading fit differ a little from the
    # whole width's.  On very short balls (about 30 lines) two end edges more
    # or less move V.x by a few sigmas, and a ball whose partial lines one
    # fit levels and the other does not moves t_c by a few of the smaller
    # sigma: at most two balls beyond 1.5, none beyond 3
    assert np.all(ratios <= 3.0)
    assert np.sum(np.any(ratios > 1.5, axis=1)) <= 2
    # the levelled partial lines (areas over the shading law's brightness)
    # narrow V.x's sigma and follow the crop's own background and gain
    assert np.all(np.median(ratios, axis=0) <= np.array([0.3, 0.3, 0.3, 0.6, 0.3, 0.3]))
    # 4. on the engine's background (the default), as accurate as the whole
    #    width: the RMS error against the truth, stream over whole width,
    #    within the ratio's own scatter on 32 balls (about 0.2)
    rmse_ratio = np.sqrt(np.mean(np.square(err["engine"]), axis=0) / np.mean(np.square(err["single"]), axis=0))
    assert np.all(rmse_ratio <= 1.4)


@pytest.mark.slow
def test_dropped_lines_flagged_only_there(long_stream, runs):
    _, (line, _count) = long_stream
    flagged = [r for r in runs[64] if "dropped_lines" in r.estimate.flags]
    assert len(flagged) == 1
    assert flagged[0].estimate.first_line <= line <= flagged[0].estimate.last_line


@pytest.mark.slow
def test_ramp_followed_by_background(long_stream):
    sim, _ = long_stream
    eng = StreamEngine(CAM, RADIUS, source="s.raw")
    data = np.memmap(sim.raw, dtype=np.uint8, mode="r", shape=(N_LINES, CAM.width))
    ts = np.load(sim.timestamps_path)
    eng.push(np.asarray(data[:2048]), ts[:2048])
    early = float(np.median(eng.background_dn))
    for a in range(2048, N_LINES, 4096):
        eng.push(np.asarray(data[a : a + 4096]), ts[a : a + 4096])
    late = float(np.median(eng.background_dn))
    # 30 % brighter at the end (black level 6 DN is not scaled)
    assert (late - 6.0) / (early - 6.0) == pytest.approx(1.3, rel=0.03)
    eng.finish()


# ---------------------------------------------------------------- memory
def _background_pool(n: int, lines: int = 256) -> list[np.ndarray]:
    rng = np.random.default_rng(3)
    return [apply_sensor(np.full((lines, CAM.width), 0.12), SensorNoise(), rng)[0] for _ in range(n)]


def test_memory_does_not_grow_with_stream_length():
    pool = _background_pool(4)
    peaks = []
    for n_chunks in (100, 200):
        eng = StreamEngine(CAM, RADIUS, StreamConfig(buffer_lines=4096))
        ring = eng._ring.nbytes
        tracemalloc.start()
        for k in range(n_chunks):
            eng.push(pool[k % len(pool)])
        eng.finish()
        peaks.append(tracemalloc.get_traced_memory()[1])
        tracemalloc.stop()
        assert eng._ring.nbytes == ring
        assert eng.lines_received == n_chunks * 256
    assert peaks[1] <= 1.03 * peaks[0]


def test_event_longer_than_buffer_is_reported_cut_and_stream_recovers():
    pool = _background_pool(2)
    cfg = StreamConfig(buffer_lines=1024, block_lines=128, margin_lines=12)
    eng = StreamEngine(CAM, RADIUS, cfg)
    out = []
    for k in range(8):
        out += eng.push(pool[k % 2])
    # a step in illumination: looks like a never-ending "ball"
    for k in range(12):
        out += eng.push(np.clip(pool[k % 2].astype(int) + 40, 0, 255).astype(np.uint8))
    out += eng.finish()
    assert len(out) == 1
    e = out[0].estimate
    assert e.t_c_s is None and "cut_first_line" in e.flags and "cut_last_line" in e.flags
    assert "buffer" in e.extra["reason"]
    assert float(np.median(eng.background_dn)) > float(np.median(pool[0])) + 30


# ---------------------------------------------------------------- engine contract
def test_no_false_balls_in_pure_noise():
    pool = _background_pool(4, lines=1024)
    eng = StreamEngine(CAM, RADIUS)
    out = []
    for k in range(40):
        out += eng.push(pool[k % 4])
    out += eng.finish()
    assert out == []
    assert eng.stats().lines == 40 * 1024


def test_ball_at_stream_end_is_measured_and_flagged_cut():
    data = small_stream(3000, balls=((900.0, 0.0), (2990.0, 0.1)))
    res = list(process_stream(ArraySource(data, 100), CAM, RADIUS))
    assert len(res) == 2
    assert "cut_last_line" in res[1].estimate.flags
    assert "cut_last_line" not in res[0].estimate.flags


def test_non_monotonic_timestamps_keep_earlier_results():
    data = small_stream(3000, balls=((900.0, 0.0),))
    t = np.arange(3000) / CAM.line_rate_hz
    t[2500] = t[2499]
    eng = StreamEngine(CAM, RADIUS, source="cam")
    out = eng.push(data[:2000], t[:2000])
    with pytest.raises(StreamError, match=r"cam: timestamp of line 2500 .*strictly increasing; the 2500 lines before it were processed") as ei:
        eng.push(data[2000:], t[2000:])
    assert len(out) + len(ei.value.results) == 1
    assert eng.lines_received == 2500


def test_fault_inside_one_push_keeps_the_results_before_it():
    data = small_stream(3000, balls=((900.0, 0.0),))
    t = np.arange(3000) / CAM.line_rate_hz
    t[2500] = t[2499]
    eng = StreamEngine(CAM, RADIUS, source="cam")
    with pytest.raises(StreamError, match="cam: timestamp of line 2500") as ei:
        eng.push(data, t)
    assert [r.estimate.first_line is not None for r in ei.value.results] == [True]
    got = []
    with pytest.raises(StreamError, match="timestamp of line 2500"):
        for r in process_stream([Chunk(data, t)], CAM, RADIUS):
            got.append(r)
    assert [r.estimate.t_c_s for r in got] == [r.estimate.t_c_s for r in ei.value.results]


def test_result_comes_out_before_the_rest_of_the_chunk_is_tested():
    data = small_stream(3000)  # balls at lines 900 and 2000, one chunk
    eng = StreamEngine(CAM, RADIUS)
    read_at_result = []
    got = []
    for r in eng._push_iter(data):  # what process_stream yields from
        read_at_result.append(eng.lines_received)
        got.append(r)
    # the first ball's event ends near line 940: out once the piece [768, 1024) is tested, before line 2000 is read
    assert read_at_result == [1024, 2048]
    for tl in (7, 512):
        ref = StreamEngine(CAM, RADIUS, StreamConfig(test_lines=tl)).push(data)
        assert [(r.estimate.t_c_s, r.estimate.position_m, r.estimate.velocity_mps) for r in ref] == [
            (r.estimate.t_c_s, r.estimate.position_m, r.estimate.velocity_mps) for r in got
        ]
    with pytest.raises(ValueError, match="test_lines: must be an integer >= 1"):
        StreamConfig(test_lines=0)


def test_engine_rejects_wrong_width_and_dtype():
    eng = StreamEngine(CAM, RADIUS, source="cam")
    with pytest.raises(StreamError, match="lines of 500 pixels after line 0, but the camera has width = 512"):
        eng.push(np.zeros((10, 500), np.uint8))
    with pytest.raises(StreamError, match="uint16"):
        eng.push(np.zeros((10, 512), np.uint16))


def test_executor_gives_the_same_results_in_order():
    from concurrent.futures import ThreadPoolExecutor

    data = small_stream(3000)
    sync = list(process_stream(ArraySource(data, 256), CAM, RADIUS))
    with ThreadPoolExecutor(1) as ex:
        eng = StreamEngine(CAM, RADIUS, executor=ex)
        got = []
        for a in range(0, 3000, 256):
            got += eng.push(data[a : a + 256])
        got += eng.finish()
    assert [r.estimate.t_c_s for r in got] == [r.estimate.t_c_s for r in sync]
    assert len(got) == 2


# ---------------------------------------------------------------- sources and faults
def test_truncated_raw_stream_keeps_results(tmp_path, capsys):
    data = small_stream(3000)
    raw = write_raw(tmp_path / "t.raw", data, extra=b"\x10" * 100)
    cam_path = tmp_path / "cam.toml"
    save_camera(CAM, cam_path)
    with pytest.raises(TruncatedStream, match=r"t.raw: ends with a partial line of 100 bytes .*the 3000 complete lines before it were processed"):
        watch(str(raw), cam_path, RADIUS, progress=False)
    lines = [json.loads(s) for s in capsys.readouterr().out.splitlines()]
    assert len(lines) == 2
    for d in lines:
        assert d["source"] == str(raw)
        assert {"t_c_s", "position_m", "velocity_mps", "speed_mps", "flags", "first_line", "last_line"} <= set(d)


def test_wrong_raw_width_is_refused_or_a_truncated_line(tmp_path):
    raw = write_raw(tmp_path / "w.raw", small_stream(3000))
    cam511 = LineScanCamera(width=511, focal_px=1100.0, principal_px=255.0, line_rate_hz=20000.0)
    # the background's column pattern shows the 512-px lines before the first ball
    got = []
    with pytest.raises(StreamError, match="not 511 px wide: the background's column pattern repeats every 512 samples"):
        for r in process_stream(RawLineSource(raw, 511), cam511, RADIUS):
            got.append(r)
    assert got == []
    # without that check, the end of the file shows it
    with pytest.raises(TruncatedStream, match="--width 511"):
        list(process_stream(RawLineSource(raw, 511), cam511, RADIUS, StreamConfig(width_check=False)))
    cam_path = tmp_path / "cam.toml"
    save_camera(CAM, cam_path)
    with pytest.raises(Exception, match="--width 511 differs from the camera's width = 512"):
        watch(str(raw), cam_path, RADIUS, width=511, progress=False)


def test_image_folder_source_and_wrong_width(tmp_path):
    data = small_stream(3000)
    folder = tmp_path / "chunks"
    folder.mkdir()
    for k, a in enumerate(range(0, 3000, 500)):
        write_image(folder / f"chunk_{k}.png", data[a : a + 500])
    res = list(process_stream(ImageFolderSource(folder), CAM, RADIUS))
    ref = list(process_stream(ArraySource(data, 500), CAM, RADIUS))
    assert [r.estimate.t_c_s for r in res] == [r.estimate.t_c_s for r in ref]
    assert len(res) == 2
    write_image(folder / "chunk_10.png", np.full((100, 500), 30, np.uint8))
    got = []
    with pytest.raises(SourceError, match=r"chunk_10.png: 500 pixels per line, expected 512; the 3000 lines before it were processed"):
        for r in process_stream(ImageFolderSource(folder), CAM, RADIUS):
            got.append(r)
    assert len(got) == 2


def test_raw_timestamps_file_non_monotonic(tmp_path):
    data = small_stream(3000, balls=((900.0, 0.0),))
    raw = write_raw(tmp_path / "s.raw", data)
    t = np.arange(3000) / CAM.line_rate_hz
    t[2000] = 0.0
    np.save(tmp_path / "s.npy", t)
    got = []
    with pytest.raises(StreamError, match="timestamp of line 2000"):
        for r in process_stream(RawLineSource(raw, 512, chunk_lines=512, timestamps=tmp_path / "s.npy"), CAM, RADIUS):
            got.append(r)
    assert len(got) == 1


def _writer(fd: int, payload: bytes, pause_s: float, close: bool) -> threading.Thread:
    def run():
        os.write(fd, payload)
        time.sleep(pause_s)
        if close:
            os.close(fd)

    th = threading.Thread(target=run, daemon=True)
    th.start()
    return th


def test_stalled_pipe_times_out_and_keeps_results():
    data = small_stream(3000, balls=((900.0, 0.0),))
    r, w = os.pipe()
    # the writer holds the pipe open for 4 s: the 0.3 s timeout must end the
    # read long before (the margin covers a cold import of the estimator on a
    # loaded machine; this checks the timeout, not speed)
    th = _writer(w, data[:2000].tobytes(), 4.0, close=True)
    got = []
    t0 = time.perf_counter()
    with os.fdopen(r, "rb", buffering=0) as fh:
        with pytest.raises(SourceStalled, match=r"no data for 0.3 s after line 2000 \(source stalled; --timeout\)"):
            for res in process_stream(RawLineSource(fh, 512, timeout_s=0.3, name="pipe"), CAM, RADIUS):
                got.append(res)
    assert time.perf_counter() - t0 < 3.5
    assert len(got) == 1
    th.join()


def test_pipe_closed_mid_line_and_at_line_end():
    data = small_stream(3000, balls=((900.0, 0.0), (2990.0, 0.1)))
    for extra, expect_error in ((b"\x01\x02\x03", True), (b"", False)):
        r, w = os.pipe()
        th = _writer(w, data.tobytes() + extra, 0.0, close=True)
        got = []
        with os.fdopen(r, "rb", buffering=0) as fh:
            src = RawLineSource(fh, 512, timeout_s=5.0, name="pipe")
            if expect_error:
                with pytest.raises(TruncatedStream, match="pipe: ends with a partial line of 3 bytes"):
                    for res in process_stream(src, CAM, RADIUS):
                        got.append(res)
            else:
                got = list(process_stream(src, CAM, RADIUS))
        th.join()
        # nothing lost: the ball cut by the end of the stream is measured too
        assert len(got) == 2
        assert "cut_last_line" in got[1].estimate.flags


def test_watch_saves_events_and_runs_as_typer_command(tmp_path, capsys):
    import typer
    from typer.testing import CliRunner

    raw = write_raw(tmp_path / "s.raw", small_stream(3000))
    cam_path = tmp_path / "cam.toml"
    save_camera(CAM, cam_path)
    n = watch(str(raw), cam_path, RADIUS, save_events=tmp_path / "ev", progress=False)
    assert n == 2
    printed = capsys.readouterr().out
    pngs = sorted(p.name for p in (tmp_path / "ev").glob("*.png"))
    assert sum(p.endswith(".overlay.png") for p in pngs) == 2 and len(pngs) == 4
    # a saved event reproduces its estimate: the crop, its lines' times and the engine's columns
    from ballscan.measure.detection import ColumnModel
    from ballscan.measure.images import load_image

    npz = sorted((tmp_path / "ev").glob("*.columns.npz"))
    assert len(npz) == 2
    z = np.load(npz[0])
    crop = load_image(str(npz[0]).replace(".columns.npz", ".png")).data
    cam = replace(crop_camera(CAM, *z["crop_cols"].tolist()), exposure_s=1.0 / CAM.line_rate_hz)
    again = estimate_crop(crop, z["times_s"], cam, RADIUS, Recipe(), 255.0, 8, "crop", columns=ColumnModel(z["background_dn"], z["noise_dn"]))
    first = json.loads(printed.splitlines()[0])
    assert list(again[0].velocity_mps) == first["velocity_mps"] and again[0].t_c_s == first["t_c_s"]
    app = typer.Typer()
    app.command()(watch)
    app.command("other")(lambda: None)
    res = CliRunner().invoke(app, ["watch", str(raw), "--camera", str(cam_path), "--radius", str(RADIUS), "--chunk-lines", "100", "--no-status"])
    assert res.exit_code == 0, res.output
    rows = [json.loads(s) for s in res.stdout.splitlines() if s.startswith("{")]
    assert [d["first_line"] for d in rows] == [json.loads(s)["first_line"] for s in printed.splitlines()]
    assert "--out" not in CliRunner().invoke(app, ["watch", "--help"]).stdout
    # estimates in a worker process: the same lines out
    capsys.readouterr()
    assert watch(str(raw), cam_path, RADIUS, progress=False, jobs=1) == 2
    pooled = [json.loads(s)["t_c_s"] for s in capsys.readouterr().out.splitlines()]
    assert pooled == [json.loads(s)["t_c_s"] for s in printed.splitlines()]


def test_chunk_dataclass_is_frozen():
    c = Chunk(np.zeros((2, 4), np.uint8))
    with pytest.raises(AttributeError):
        c.lines = None  # type: ignore[misc]


def test_a_failing_estimate_is_a_value_not_a_crash(monkeypatch):
    import ballscan.pipeline.estimate as est_mod

    def boom(*args, **kwargs):
        raise ValueError("synthetic failure")

    monkeypatch.setattr(est_mod, "estimate_image", boom)
    res = list(process_stream(ArraySource(small_stream(3000), 256), CAM, RADIUS))
    assert len(res) == 2
    for r in res:
        assert r.estimate.t_c_s is None and "degenerate" in r.estimate.flags
        assert "synthetic failure" in r.estimate.extra["reason"]
        assert r.estimate.first_line is not None and r.estimate.last_line > r.estimate.first_line


def test_watch_reads_stdin_and_shows_status(tmp_path):
    import subprocess
    import sys

    raw = write_raw(tmp_path / "s.raw", small_stream(3000))
    cam_path = tmp_path / "cam.toml"
    save_camera(CAM, cam_path)
    code = (
        "import typer; from ballscan.cli.stream import watch; app = typer.Typer(); app.command()(watch); "
        "app.command('other')(lambda: None); app()"
    )
    with open(raw, "rb") as fh:
        proc = subprocess.run(
            [sys.executable, "-c", code, "watch", "-", "--camera", str(cam_path), "--radius", str(RADIUS), "--status", "--timeout", "10"],
            stdin=fh,
            capture_output=True,
            text=True,
            timeout=120,
        )
    assert proc.returncode == 0, proc.stderr
    rows = [json.loads(s) for s in proc.stdout.splitlines()]
    assert len(rows) == 2 and all(r["source"] == "<stdin>" for r in rows)
    assert "3,000 lines" in proc.stderr and "k lines/s" in proc.stderr and "2 balls" in proc.stderr


def test_per_line_offset_follows_lamp_flicker():
    """30 % flicker over 200 lines: the per-line offset keeps the band on the background."""
    balls = [(BallMotion(RADIUS, ln / CAM.line_rate_hz, (0.0, y0, 4.0), (35.0, 1.0, -2.0)), Appearance.flat(0.8)) for ln, y0 in ((1500, 0.0), (3500, 0.2), (5200, -0.2))]
    clean = render(CAM, balls, 6000, background_level=0.12, noise=None).clean
    flicker = 1 + 0.3 * np.sin(2 * np.pi * np.arange(6000) / 200)
    img, _ = apply_sensor(clean * flicker[:, None], SensorNoise(), 3)
    stats = {}
    for on in (True, False):
        eng = StreamEngine(CAM, RADIUS, StreamConfig(line_offset=on))
        res = []
        for a in range(0, 6000, 256):
            res += eng.push(img[a : a + 256])
        res += eng.finish()
        assert [round(r.estimate.t_c_s * CAM.line_rate_hz) for r in res] == [1500, 3500, 5200]
        stats[on] = eng.stats()
    assert stats[True].events == 3 and stats[True].rejected == 0
    # without it, flicker peaks leave the band: spurious events (rejected or empty crops)
    assert stats[False].events + stats[False].rejected > 3


def test_watch_ctrl_c_ends_the_stream_and_measures_the_ball_in_view(tmp_path, monkeypatch, capsys):
    import ballscan.cli.stream as sc

    data = small_stream(3000, balls=((900.0, 0.0), (2990.0, 0.1)))

    class Interrupted:
        name = "cam"
        width = CAM.width

        def __iter__(self):
            yield Chunk(data[:1500])
            yield Chunk(data[1500:])
            raise KeyboardInterrupt

    monkeypatch.setattr(sc, "open_source", lambda *a, **k: Interrupted())
    cam_path = tmp_path / "cam.toml"
    save_camera(CAM, cam_path)
    assert watch("whatever", cam_path, RADIUS, progress=False) == 2
    cap = capsys.readouterr()
    assert "interrupted after 3000 lines, 2 balls" in cap.err
    assert "cut_last_line" in json.loads(cap.out.splitlines()[-1])["flags"]


def test_balls_side_by_side_in_time_and_16_bit_raw(tmp_path):
    """Two balls crossing together (opposite halves of the sensor), 12-bit data in uint16 lines."""
    noise = SensorNoise(bits=12, white_dn=0.9 * 4095, black_dn=24.0, read_dn=6.0)
    sim = simulate_stream(tmp_path / "s16.raw", CAM, 8000, 6, seed=5, side_by_side=2, noise=noise)
    assert sim.dtype == "uint16" and sim.raw.stat().st_size == 8000 * 512 * 2
    res = list(process_stream(RawLineSource(sim.raw, 512, "uint16", chunk_lines=300), CAM, RADIUS))
    pairs = match(res, load_truth_lines(sim.truth_path), CAM.line_rate_hz)
    assert [len(h) for _, h in pairs] == [1] * 6 and len(res) == 6
    events = [r.event_index for r in res]
    assert len(events) - len(set(events)) == 2  # each side-by-side pair in one crop


def test_ball_longer_than_buffer_is_cut_and_later_balls_are_found():
    slow = (BallMotion(RADIUS, 3000 / CAM.line_rate_hz, (0.0, 0.0, 4.0), (1.0, 0.05, 0.0)), Appearance.flat(0.8))
    fast = [(BallMotion(RADIUS, ln / CAM.line_rate_hz, (0.0, y0, 4.0), (35.0, 1.0, -2.0)), Appearance.flat(0.8)) for ln, y0 in ((5000, 0.1), (5600, -0.1))]
    img = render(CAM, [slow, *fast], 6000, background_level=0.12, noise=SensorNoise(), seed=2).image
    res = list(process_stream(ArraySource(img, 100), CAM, RADIUS, StreamConfig(buffer_lines=1024, block_lines=128)))
    assert len(res) == 3
    assert res[0].estimate.t_c_s is None and "buffer" in res[0].estimate.extra["reason"]
    assert [round(r.estimate.t_c_s * CAM.line_rate_hz) for r in res[1:]] == [5000, 5600]


def test_stream_background_switch_reaches_the_estimator():
    """StreamConfig.background: the engine's columns (default) or the crop's own, as estimate_crop sees them."""
    data = small_stream(3000, balls=((1400.0, 0.05),))
    got = {}
    for bg in ("engine", "crop"):
        eng = StreamEngine(CAM, RADIUS, StreamConfig(background=bg, keep_crops=True))
        res = eng.push(data) + eng.finish()
        assert len(res) == 1
        r = res[0]
        assert (r.crop_columns is None) == (bg == "crop")
        (c0, c1) = r.crop_cols
        cam = replace(crop_camera(CAM, c0, c1), exposure_s=1.0 / CAM.line_rate_hz)
        ref = estimate_crop(r.crop, r.crop_times_s, cam, RADIUS, Recipe(), 255.0, 8, "crop", columns=r.crop_columns)
        assert ref[0].velocity_mps == r.estimate.velocity_mps
        got[bg] = r
    # the engine's level of the crop's columns: learned on the 1 400 lines before the ball
    cols = got["engine"].crop_columns
    c0, c1 = got["engine"].crop_cols
    assert cols.background_dn.shape == (c1 - c0,)
    assert np.abs(cols.background_dn - data[:1300, c0:c1].mean(axis=0)).max() < 0.5
    assert got["engine"].estimate.velocity_mps != got["crop"].estimate.velocity_mps
    with pytest.raises(ValueError, match="background"):
        StreamConfig(background="image")


def test_stream_shading_switch_reaches_the_estimator():
    """StreamConfig.recipe.shading is what estimate_image gets (the same numbers as on the crop)."""
    m = BallMotion(RADIUS, 300 / CAM.line_rate_hz, (0.0, 0.05, 3.0), (30.0, 1.0, 0.0))
    data = render(CAM, [(m, Appearance(texture="none", shading=True))], 600, background_level=0.1, noise=SensorNoise(), seed=5).image
    for shading in (True, False):
        eng = StreamEngine(CAM, RADIUS, StreamConfig(recipe=Recipe(shading=shading), keep_crops=True))
        res = eng.push(data) + eng.finish()
        assert len(res) == 1
        r = res[0]
        (c0, c1) = r.crop_cols
        cam = replace(crop_camera(CAM, c0, c1), exposure_s=1.0 / CAM.line_rate_hz)  # as the engine does without timestamps
        ref = estimate_crop(r.crop, r.crop_times_s, cam, RADIUS, Recipe(shading=shading), 255.0, 8, "crop", columns=r.crop_columns)
        assert ref[0].velocity_mps == r.estimate.velocity_mps
        assert (r.estimate.extra["shading"] is not None) == shading


def test_stream_matched_switch_reaches_the_estimator():
    # a flat ball on an ideal 8-bit sensor: the engine's estimates use the
    # matched edges unless the recipe's matched (watch --no-matched) is off
    cam = LineScanCamera(width=240, focal_px=3000.0, principal_px=119.5, line_rate_hz=50000.0)
    m = BallMotion(0.0335, 300 / cam.line_rate_hz, (0.0, 0.001, 3.0), (30.0, 0.0, 0.0))
    ideal = SensorNoise(bits=8, white_dn=230.0, black_dn=6.0, read_dn=1.0, full_well_e=None, prnu_sigma=0.0)
    data = render(cam, (m, Appearance.flat(0.8)), 600, background_level=0.1, noise=ideal, seed=1).image
    seen = {}
    for matched in (True, False):
        eng = StreamEngine(cam, 0.0335, StreamConfig(recipe=Recipe(matched=matched)))
        res = eng.push(data) + eng.finish()
        assert len(res) == 1
        seen[matched] = res[0].estimate
    assert seen[True].extra["edges"] == "matched" and seen[False].extra["edges"] == "window"
    assert seen[True].velocity_mps != seen[False].velocity_mps


@pytest.mark.parametrize(
    "field, bad",
    [
        ("k_sigma", float("nan")),
        ("ema_alpha", "0.5"),
        ("margin_px", 1.5),
        ("noise_floor_dn", 0.0),
        ("saturation_dn", -1.0),
        ("keep_crops", 1),
        ("line_offset", "yes"),
        ("recipe", "fit"),
        ("background", "image"),
    ],
)
def test_stream_config_refuses_a_bad_value_naming_its_field(field, bad):
    with pytest.raises(ValueError, match=rf"^{field}: "):
        StreamConfig(**{field: bad})
    assert StreamConfig(recipe=Recipe(method="paper")).recipe.method == "paper"


def test_watch_table_prints_one_readable_line_per_ball_and_keeps_the_status_apart(tmp_path, capsys):
    data = small_stream(3000)
    raw = write_raw(tmp_path / "t.raw", data)
    cam_path = tmp_path / "cam.toml"
    save_camera(CAM, cam_path)
    assert watch(str(raw), cam_path, RADIUS, progress=False) == 2
    as_json = [json.loads(s) for s in capsys.readouterr().out.splitlines()]
    assert watch(str(raw), cam_path, RADIUS, output_format="table", units="km/h", progress=True) == 2
    out = capsys.readouterr()
    rows = out.out.splitlines()
    assert len(rows) == 2
    for row, d in zip(rows, as_json):
        assert row.startswith(f"ball {d['event']} | lines {d['first_line']}-{d['last_line']} | {d['speed_mps'] * 3.6:.2f} ± ")
        assert "km/h" in row and "across axis" in row
    assert "lines/s" not in out.out and "lines/s" in out.err  # the status line only on stderr
    assert "\r\x1b[K" in out.err  # wiped before each result


def test_watch_refuses_bad_format_and_units(tmp_path):
    cam_path = tmp_path / "cam.toml"
    save_camera(CAM, cam_path)
    with pytest.raises(typer.BadParameter, match="json"):
        watch("whatever", cam_path, RADIUS, output_format="xml")
    with pytest.raises(typer.BadParameter, match="km/h"):
        watch("whatever", cam_path, RADIUS, units="knots")
