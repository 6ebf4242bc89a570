"""Tests of the live view's library: ballscan.live.balls, .hub, .replay and .server (over HTTP, without a browser)."""

from __future__ import annotations

import base64
import csv
import io
import json
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from ballscan.errors import BallscanError
from ballscan.geometry.camera import LineScanCamera, crop_camera, save_camera
from ballscan.geometry.motion import BallMotion
from ballscan.live.balls import MAX_CROP_PX, TABLE_COLUMNS, BallFilter, ball_from_csv_row, ball_from_record, crop_view, table_csv
from ballscan.live.hub import LiveConfig, LiveHub
from ballscan.live.replay import load_run
from ballscan.model.render import Appearance, SensorNoise, render
from ballscan.model.silhouette import silhouette
from ballscan.pipeline.report import CSV_COLUMNS, UNITS
from ballscan.stream.engine import Chunk, StreamConfig, process_stream

RADIUS = 0.0335
CAM = LineScanCamera(width=512, focal_px=1100.0, principal_px=255.5, line_rate_hz=20000.0)
#: (crossing line, y0 m, speed along x m/s) of the test stream's balls
BALLS = ((900.0, 0.0, 35.0), (2000.0, 0.2, 28.0), (3200.0, -0.15, 41.0))


def stream_lines(n_lines: int = 4200, seed: int = 1) -> np.ndarray:
    """An 8-bit stream of CAM with the balls of BALLS."""
    motions = [(BallMotion(RADIUS, ln / CAM.line_rate_hz, (0.0, y0, 4.0), (vx, 1.0, -2.0)), Appearance.flat(0.8)) for ln, y0, vx in BALLS]
    return render(CAM, motions, n_lines, background_level=0.12, noise=SensorNoise(), seed=seed).image


@pytest.fixture(scope="module")
def lines():
    return stream_lines()


@pytest.fixture(scope="module")
def results(lines):
    chunks = [Chunk(lines[a : a + 512]) for a in range(0, lines.shape[0], 512)]
    return list(process_stream(chunks, CAM, RADIUS, StreamConfig(keep_crops=True), source="test"))


@pytest.fixture
def server_factory():
    httpx = pytest.importorskip("httpx")
    pytest.importorskip("starlette")
    pytest.importorskip("uvicorn")
    from ballscan.live.server import LiveServer

    started = []

    def make(store):
        s = LiveServer(store, "127.0.0.1", 0, title="test")
        s.start()
        client = httpx.Client(base_url=s.url.rstrip("/"), timeout=10)
        started.append((s, client))
        return s, client

    yield make
    for s, client in started:
        client.close()
        s.stop()


# ------------------------------------------------------------------- balls
def test_the_stream_has_its_balls(results):
    assert len(results) == len(BALLS)
    for r, (_, _, vx) in zip(results, BALLS):
        assert abs(r.estimate.speed_mps - np.hypot(vx, np.hypot(1.0, 2.0))) < 5 * r.estimate.speed_sigma_mps + 0.05


def test_crop_view_pixels_and_outline(results):
    r = results[0]
    m = r.estimate.motion()
    view = crop_view(r.crop, r.crop_lines[0], r.crop_cols[0], camera=CAM, motion=m, times_s=r.crop_times_s)
    grey = np.frombuffer(base64.b64decode(view.pixels_b64), dtype=np.uint8).reshape(view.height, view.width)
    assert (view.height, view.width) == r.crop.shape and view.step_lines == view.step_columns == 1
    # a monotone stretch of the stored values: the brightest and darkest pixels stay so
    assert grey.flat[np.argmax(r.crop)] == 255 and grey.flat[np.argmin(r.crop)] == 0
    # the outline is the model's silhouette of the crop's columns (as --plot draws it)
    sil = silhouette(crop_camera(CAM, *r.crop_cols), m, r.crop_times_s, model="averaged")
    present = np.flatnonzero(sil.present)
    pts = np.array(view.outline)
    assert pts[0, 1] == present[0] and pts[0, 0] == pytest.approx(sil.left_px[present[0]], abs=0.01)
    assert pts[0] == pytest.approx(pts[-1])
    assert pts[:, 1].max() == present[-1]
    right = dict(zip(present.tolist(), sil.right_px[present]))
    for x, y in pts[len(present) : 2 * len(present)]:
        assert x == pytest.approx(right[int(y)], abs=0.01)
    # the outline lies on the ball: its pixels are bright inside it
    mid = int(present[len(present) // 2])
    inside = r.crop[mid, int(np.ceil(sil.left_px[mid])) + 1 : int(sil.right_px[mid]) - 1]
    assert inside.mean() > r.crop[mid, :5].mean() + 50


def test_crop_view_subsamples_a_long_crop():
    crop = np.arange(2000 * 50, dtype=np.uint16).reshape(2000, 50)
    view = crop_view(crop, 100, 7)
    assert view.step_lines == int(np.ceil(2000 / MAX_CROP_PX)) and view.height <= MAX_CROP_PX and view.width == 50
    assert view.outline == () and (view.first_line, view.first_column) == (100, 7)
    with pytest.raises(ValueError, match="crop"):
        crop_view(np.zeros((0, 3)), 0, 0)


def test_ball_from_record_and_csv_agree(results):
    r = results[1]
    rec = r.to_dict(CAM)
    b = ball_from_record(rec, 4, lag_s=0.01)
    assert (b.index, b.source, b.first_line, b.speed_mps, b.flags) == (4, "test", r.estimate.first_line, r.estimate.speed_mps, r.estimate.flags)
    assert b.direction_deg == pytest.approx(rec["direction_deg"]) and b.lag_s == 0.01
    from ballscan.pipeline.report import csv_row

    row = {k: str(v) for k, v in csv_row("test", 0, r.estimate, CAM).items()}
    c = ball_from_csv_row(row, 4)
    for key in ("speed_mps", "speed_sigma_mps", "speed_transverse_mps", "t_c_s"):
        assert getattr(c, key) == pytest.approx(getattr(b, key), rel=1e-12)
    assert c.direction_deg == pytest.approx(b.direction_deg) and c.direction_sigma_deg == pytest.approx(b.direction_sigma_deg)
    undetermined = ball_from_record({"speed_mps": None, "flags": ["degenerate"], "direction_deg": None}, 0)
    assert undetermined.speed_mps is None and undetermined.direction_deg == (None, None)


def test_filter_by_flag_and_speed():
    balls = [
        ball_from_record({"speed_mps": 30.0, "flags": []}, 0),
        ball_from_record({"speed_mps": 40.0, "flags": ["saturated"]}, 1),
        ball_from_record({"speed_mps": None, "flags": ["degenerate"]}, 2),
        ball_from_record({"speed_mps": 50.0, "flags": ["overlap", "saturated"]}, 3),
    ]

    def pick(**kw):
        return [b.index for b in balls if BallFilter(**kw).accepts(b)]

    assert pick() == [0, 1, 2, 3]
    assert pick(flag="none") == [0] and pick(flag="any") == [1, 2, 3] and pick(flag="saturated") == [1, 3]
    assert pick(min_speed_mps=35.0) == [1, 3] and pick(max_speed_mps=40.0) == [0, 1] and pick(min_speed_mps=40.0, max_speed_mps=40.0) == [1]
    assert pick(flag="saturated", max_speed_mps=45.0) == [1]
    assert BallFilter.from_query({"flag": "overlap", "min_mps": "12.5", "max_mps": ""}) == BallFilter("overlap", 12.5, None)
    with pytest.raises(ValueError, match="flag"):
        BallFilter("bogus")
    with pytest.raises(ValueError, match="min_mps"):
        BallFilter.from_query({"min_mps": "fast"})


def test_table_csv_reads_back():
    balls = [ball_from_record({"speed_mps": 30.123456789, "speed_sigma_mps": 0.1, "flags": ["overlap"], "first_line": 5}, 0)]
    rows = list(csv.DictReader(io.StringIO(table_csv(balls))))
    assert tuple(rows[0]) == TABLE_COLUMNS
    assert float(rows[0]["speed_mps"]) == 30.123456789 and rows[0]["flags"] == "overlap" and rows[0]["psi_y_deg"] == ""


# --------------------------------------------------------------------- hub
def test_hub_collects_balls_lags_and_health(lines, results):
    hub = LiveHub(CAM)
    t_chunks = []
    chunks = [Chunk(lines[a : a + 512]) for a in range(0, lines.shape[0], 512)]
    for ch in hub.chunks(chunks):
        t_chunks.append(ch)
    for r in results:
        hub.ball(r)
    assert hub.balls() == [] and hub.health().balls == len(results)  # not drained yet: nothing made on this thread
    assert hub.drain() == len(results)
    got = hub.balls()
    assert [b.index for b in got] == [0, 1, 2]
    assert [b.speed_mps for b in got] == [r.estimate.speed_mps for r in results]
    assert all(b.crop is not None and b.crop.outline for b in got) and all(b.lag_s is not None and b.lag_s >= 0 for b in got)
    h = hub.health()
    assert (h.state, h.lines, h.balls, h.skipped, h.width) == ("running", lines.shape[0], 3, 0, CAM.width)
    # the strip is the background: the median level of the sampled lines, everywhere near the render's level
    assert len(h.strip_dn) == 256 and abs(np.median(h.strip_dn) - np.median(lines)) < 2
    new, skipped = hub.balls_after(0)
    assert [b.index for b in new] == [1, 2] and skipped == 0
    hub.end("the source ended")
    assert hub.health().state == "ended" and hub.health().message == "the source ended"


def test_hub_is_bounded_and_never_waits(results):
    cfg = LiveConfig(capacity=5, crop_capacity=2, pending=8)
    hub = LiveHub(CAM, cfg)
    for _ in range(20):  # nobody drains: the oldest waiting balls are dropped, the loop goes on
        hub.ball(results[0])
    assert hub.health().skipped == 12 and hub.drain() == 8
    got = hub.balls()
    assert [b.index for b in got] == [3, 4, 5, 6, 7]  # the ring keeps the newest five
    assert [b.crop is not None for b in got] == [False, False, False, True, True]
    new, skipped = hub.balls_after(0)  # a viewer that saw ball 0 last missed 1 and 2
    assert [b.index for b in new] == [3, 4, 5, 6, 7] and skipped == 2
    assert hub.ball_detail(1) is None and hub.ball_detail(7).crop is not None


def test_hub_says_when_the_source_stalls():
    hub = LiveHub(CAM, LiveConfig(stall_after_s=0.05))
    assert hub.health().state == "waiting"
    hub.chunk(np.zeros((10, CAM.width), np.uint8))
    assert hub.health().state == "running"
    threading.Event().wait(0.1)
    h = hub.health()
    assert h.state == "stalled" and "no lines for" in h.message


def test_live_config_checks():
    with pytest.raises(ValueError, match="capacity"):
        LiveConfig(capacity=0)
    with pytest.raises(ValueError, match="stall_after_s"):
        LiveConfig(stall_after_s=-1.0)


# ------------------------------------------------------------------ replay
def test_replay_of_json_lines_and_csv(tmp_path, results):
    jl = tmp_path / "run.jsonl"
    jl.write_text("".join(json.dumps(r.to_dict(CAM)) + "\n" for r in results) + "\n")
    run = load_run(jl)
    assert [b.speed_mps for b in run.balls()] == [r.estimate.speed_mps for r in results]
    from ballscan.pipeline.report import csv_row

    path = tmp_path / "run.csv"
    with open(path, "w", newline="") as fh:
        wr = csv.DictWriter(fh, fieldnames=CSV_COLUMNS)
        wr.writeheader()
        for k, r in enumerate(results):
            wr.writerow(csv_row("run.raw", k, r.estimate, CAM))
    run = load_run(path)
    assert [b.speed_mps for b in run.balls()] == pytest.approx([r.estimate.speed_mps for r in results], rel=1e-12)
    assert run.ball_detail(1).crop is None and run.ball_detail(3) is None


def test_replay_errors_name_the_file(tmp_path):
    with pytest.raises(BallscanError, match="no such file"):
        load_run(tmp_path / "missing.jsonl")
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"speed_mps": 3}\nnot json\n')
    with pytest.raises(BallscanError, match=r"bad.jsonl: line 2: not JSON"):
        load_run(bad)
    other = tmp_path / "other.csv"
    other.write_text("a,b\n1,2\n")
    with pytest.raises(BallscanError, match="other.csv: not a batch CSV"):
        load_run(other)
    with pytest.raises(BallscanError, match="no saved balls"):
        load_run(tmp_path)


@pytest.fixture(scope="module")
def saved_events(tmp_path_factory, lines):
    """A watch run over the test stream with --save-events: the folder, its JSON lines and the camera file."""
    from ballscan.cli import main

    d = tmp_path_factory.mktemp("watch")
    raw = d / "s.raw"
    raw.write_bytes(np.ascontiguousarray(lines).tobytes())
    cam = d / "cam.toml"
    save_camera(CAM, cam)
    out = d / "out.jsonl"
    import contextlib

    with open(out, "w") as fh, contextlib.redirect_stdout(fh):
        assert main(["watch", str(raw), "--camera", str(cam), "--radius", str(RADIUS), "--save-events", str(d / "events"), "--no-progress"]) == 0
    return d / "events", out, cam


def test_replay_of_a_saved_events_folder(saved_events):
    folder, out, cam = saved_events
    printed = [json.loads(t) for t in out.read_text().splitlines()]
    from ballscan.geometry.camera import load_camera

    run = load_run(folder, load_camera(cam))
    assert [b.speed_mps for b in run.balls()] == [p["speed_mps"] for p in printed]
    b = run.ball_detail(2)
    assert b.crop is not None and b.crop.outline
    assert b.crop.first_line < b.first_line and b.crop.first_line + b.crop.height * b.crop.step_lines > b.last_line
    # without the camera: the crop, no outline
    assert load_run(folder).ball_detail(0).crop.outline == ()


# ------------------------------------------------------------------ server
def test_server_routes_are_read_only(server_factory, results):
    hub = LiveHub(CAM)
    for r in results:
        hub.ball(r)
    hub.drain()
    server, client = server_factory(hub)
    info = client.get("/api/info").json()
    assert info["mode"] == "live" and info["units"] == UNITS
    assert [b["speed_mps"] for b in client.get("/api/balls").json()["balls"]] == [r.estimate.speed_mps for r in results]
    one = client.get("/api/ball/1").json()
    assert one["crop"]["width"] == results[1].crop.shape[1] and len(one["crop"]["outline"]) > 10
    assert client.get("/api/ball/99").status_code == 404
    fast = min(r.estimate.speed_mps for r in results) + 0.5
    text = client.get("/api/balls.csv", params={"min_mps": fast}).text
    rows = list(csv.DictReader(io.StringIO(text)))
    assert [float(r["speed_mps"]) for r in rows] == [r.estimate.speed_mps for r in results if r.estimate.speed_mps >= fast]
    assert client.get("/api/balls", params={"flag": "bogus"}).status_code == 400
    assert "ballscan" in client.get("/").text and client.get("/static/live.js").status_code == 200
    for path in ("/api/balls", "/api/ball/1", "/events", "/"):
        assert client.post(path).status_code == 405
        assert client.delete(path).status_code == 405
    assert client.get("/static/../hub.py").status_code == 404


def _read_events(client, path: str, want: int, kinds=("ball",)) -> list[tuple[str, dict]]:
    got = []
    with client.stream("GET", path) as resp:
        assert resp.status_code == 200, resp.read()
        kind = None
        for text in resp.iter_lines():
            if text.startswith("event: "):
                kind = text[7:]
            elif text.startswith("data: ") and kind in kinds:
                got.append((kind, json.loads(text[6:])))
                if len(got) >= want:
                    break
    return got


def _viewers(server, count: int, want: int, path: str = "/events?after=-1", kinds=("ball",)) -> tuple[list[threading.Thread], dict]:
    """``count`` viewers, each on a thread with a connection of its own, reading ``want`` events of ``kinds`` from ``path``.

    Returns the started threads and a dict filled with each viewer's events,
    or the exception that ended it (for the test to report, not lost on its thread).
    """
    import httpx

    got: dict[int, list | Exception] = {}

    def viewer(k):
        try:
            with httpx.Client(base_url=server.url.rstrip("/"), timeout=30) as client:
                got[k] = _read_events(client, path, want, kinds)
        except Exception as exc:
            got[k] = exc

    threads = [threading.Thread(target=viewer, args=(k,), daemon=True) for k in range(count)]
    for t in threads:
        t.start()
    return threads, got


def _joined(threads, got: dict, timeout_s: float = 60.0) -> dict:
    t_end = time.monotonic() + timeout_s
    for t in threads:
        t.join(max(t_end - time.monotonic(), 0.0))
    assert not any(t.is_alive() for t in threads), f"viewers still reading after {timeout_s} s: {sorted(got)} done"
    errors = {k: v for k, v in got.items() if isinstance(v, Exception)}
    assert not errors, f"viewers ended by an error: {errors!r}"
    return got


def test_event_stream_pushes_each_new_ball_to_every_viewer(server_factory, results):
    hub = LiveHub(CAM)
    server, client = server_factory(hub)
    threads, got = _viewers(server, 3, len(results))
    for r in results:
        hub.ball(r)
    _joined(threads, got)
    for k in range(3):
        assert [d["speed_mps"] for _, d in got[k]] == [r.estimate.speed_mps for r in results]
        assert all(d["crop"] is not None for _, d in got[k])
    health = _read_events(client, "/events?after=2", 1, kinds=("health",))
    assert health[0][1]["balls"] == len(results) and health[0][1]["state"] == "waiting"


def test_a_viewer_closing_its_page_ends_no_other_stream(server_factory, results):
    """Viewers that open the stream and close it at once, over and over, while three others wait for each ball."""
    hub = LiveHub(CAM, LiveConfig(capacity=50, crop_capacity=2))
    server, client = server_factory(hub)
    n_balls = 12
    threads, got = _viewers(server, 3, n_balls)
    opened = ("ball", "health", "skipped")  # the brief viewers close at their first event
    brief, brief_got = _viewers(server, 8, 1, kinds=opened)
    t_brief = []

    def come_and_go():
        for _ in range(6):
            ts, g = _viewers(server, 4, 1, kinds=opened)
            t_brief.append((ts, g))
            for t in ts:
                t.join(30)

    churn = threading.Thread(target=come_and_go, daemon=True)
    churn.start()
    for k in range(n_balls):  # one at a time: the three wait on the stream between balls while others close theirs
        hub.ball(results[k % len(results)])
        time.sleep(0.03)
    churn.join(60)
    assert not churn.is_alive()
    _joined(threads, got)
    _joined(brief, brief_got)
    for ts, g in t_brief:
        _joined(ts, g)
    for k in range(3):
        assert [d["index"] for _, d in got[k]] == list(range(n_balls))
    assert client.get("/api/health").json()["balls"] == n_balls


def test_a_stuck_or_closed_viewer_holds_nobody_up(server_factory, results):
    import socket

    hub = LiveHub(CAM, LiveConfig(capacity=50, pending=200))
    server, client = server_factory(hub)
    host, port = server.host, server.port
    stuck = socket.create_connection((host, port))  # asks for the events and never reads them
    stuck.sendall(b"GET /events HTTP/1.1\r\nHost: x\r\n\r\n")
    closed = socket.create_connection((host, port))  # a browser closed at once
    closed.sendall(b"GET /events HTTP/1.1\r\nHost: x\r\n\r\n")
    closed.close()
    try:
        # 150 balls with their crops: far more than the stuck socket's buffers hold
        for k in range(150):
            hub.ball(results[k % len(results)])
        got = _read_events(client, "/events?after=139", 10)
        assert [d["index"] for _, d in got] == list(range(140, 150))
        assert hub.health().skipped == 0 and len(hub.balls()) == 50
    finally:
        stuck.close()


def test_view_serves_a_saved_run(server_factory, saved_events):
    folder, out, cam = saved_events
    from ballscan.geometry.camera import load_camera

    server, client = server_factory(load_run(folder, load_camera(cam)))
    assert client.get("/api/info").json()["mode"] == "replay"
    listed = client.get("/api/balls").json()["balls"]
    assert len(listed) == len(out.read_text().splitlines()) == len(BALLS)
    detail = client.get(f"/api/ball/{listed[-1]['index']}").json()
    assert detail["crop"]["outline"]


def test_an_address_in_use_is_a_one_line_error(server_factory):
    import socket

    from ballscan.live.server import LiveServer

    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        with pytest.raises(BallscanError, match=f"--serve 127.0.0.1:{port}: cannot listen there"):
            LiveServer(LiveHub(CAM), "127.0.0.1", port).start()


def test_parse_address():
    from ballscan.live.server import parse_address

    assert parse_address("8000") == ("127.0.0.1", 8000)
    assert parse_address("0.0.0.0:81") == ("0.0.0.0", 81)
    assert parse_address("[::1]:0") == ("::1", 0)
    for bad in ("http", "1:2:x", "70000", ":80"):
        with pytest.raises(ValueError, match="--serve"):
            parse_address(bad)


def test_cli_errors(tmp_path, capsys):
    from ballscan.cli import main

    cam = tmp_path / "cam.toml"
    save_camera(CAM, cam)
    assert main(["view", str(tmp_path / "none.csv")]) == 2
    assert "none.csv: no such file" in capsys.readouterr().err
    assert main(["watch", "x.raw", "--camera", str(cam), "--radius", "0.03", "--serve", "host:port"]) != 0
    assert "--serve" in capsys.readouterr().err
