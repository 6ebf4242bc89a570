"""Faults of the machine and the user: signals, kill -9 and reruns, concurrent runs, wrong widths, silent pipes.

Each test runs the real command where the fault is the process's own (a
signal, ``kill -9``: ``python -m ballscan`` in a subprocess) and the library
or ``main([...])`` elsewhere. Every ball must come out exactly once, with no
malformed file, no traceback and no hang.
"""

from __future__ import annotations

import contextlib
import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import psutil
import pytest

from ballscan.cli import main
from ballscan.errors import BallscanError
from ballscan.geometry.camera import LineScanCamera, save_camera
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, SensorNoise, render, write_image
from ballscan.outputs import TEMP_MARK, OutputLock
from ballscan.stream.batch import COLUMNS, run_batch
from ballscan.stream.events import LOCK_NAME
from ballscan.stream.engine import process_stream
from ballscan.stream.sources import ArraySource, simulate_stream

RADIUS = 0.0335
CAM = LineScanCamera(width=512, focal_px=1100.0, principal_px=255.5, line_rate_hz=20000.0)
#: Seconds within which a stopped command must have ended (a hang guard, not a speed test).
HANG_S = 60.0


#: The commands started by the running test; ended at its teardown whatever its outcome.
_STARTED: list[subprocess.Popen] = []


@pytest.fixture(autouse=True)
def _end_started_commands():
    yield
    while _STARTED:
        p = _STARTED.pop()
        if p.poll() is None:
            # its workers hold its pipes: a worker left behind would block the read below
            try:
                children = psutil.Process(p.pid).children(recursive=True)
            except psutil.NoSuchProcess:
                children = []
            for c in children:
                with contextlib.suppress(psutil.NoSuchProcess):
                    c.kill()
            p.kill()
        try:
            p.communicate(timeout=HANG_S)
        except subprocess.TimeoutExpired:
            for pipe in (p.stdout, p.stderr, p.stdin):
                if pipe is not None:
                    pipe.close()
            pytest.fail(f"a started command's output stayed open {HANG_S:g} s after it was killed")


def _ballscan(*args: str, **kw) -> subprocess.Popen:
    p = subprocess.Popen([sys.executable, "-m", "ballscan", *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, **kw)
    _STARTED.append(p)
    return p



def _balls(text: str) -> list[tuple[int, int, tuple[str, ...]]]:
    """(first_line, last_line, flags) of each JSON line of watch."""
    out = []
    for line in text.splitlines():
        d = json.loads(line)
        out.append((d["first_line"], d["last_line"], tuple(d["flags"])))
    return out


@pytest.fixture(scope="module")
def stream(tmp_path_factory):
    """A 512-px raw stream of 8000 lines with 4 balls, its camera file and truth."""
    d = tmp_path_factory.mktemp("stream")
    return simulate_stream(d / "s.raw", CAM, 8000, 4, seed=5)


@pytest.fixture(scope="module")
def images(tmp_path_factory):
    """Eight images of one or two balls, with their cameras beside them."""
    d = tmp_path_factory.mktemp("img")
    for k in range(8):
        lines = [200.0] if k % 2 else [120.0, 290.0]
        balls = [(BallMotion(RADIUS, ln / CAM.line_rate_hz, (0.0, 0.1 * j - 0.05, 4.0), (35.0, 1.0, -2.0)), Appearance.flat(0.8)) for j, ln in enumerate(lines)]
        write_image(d / f"img{k}.png", render(CAM, balls, 400, background_level=0.12, noise=SensorNoise(), seed=k).image)
        save_camera(CAM, d / f"img{k}.camera.toml")
    return d


def _rows(path: Path) -> list[dict]:
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    for r in rows:
        assert None not in r and all(v is not None for v in r.values()), "malformed row"
    return rows


def _per_source(rows: list[dict]) -> dict[str, int]:
    out: dict[str, int] = {}
    for r in rows:
        out[Path(r["source"]).name] = out.get(Path(r["source"]).name, 0) + 1
    return out


# ---------------------------------------------------------------- watch: signals
@pytest.mark.parametrize("sig", ["SIGTERM", "SIGINT"])
def test_a_stop_signal_mid_stream_loses_no_passed_ball(stream, sig):
    b = stream.balls
    cut = (b[2]["first_line"] + b[2]["last_line"]) // 2  # ball 2 in view when the lines stop
    lines = np.fromfile(stream.raw, dtype=np.uint8)[: cut * CAM.width]
    # the complete run of those lines
    want = [(r.estimate.first_line, r.estimate.last_line, tuple(r.estimate.flags)) for r in process_stream(ArraySource(lines.reshape(cut, CAM.width)), CAM, RADIUS)]
    assert len(want) == 3 and "cut_last_line" in want[-1][2]
    p = _ballscan("watch", "-", "--camera", str(stream.camera_path), "--radius", str(RADIUS), stdin=subprocess.PIPE)
    p.stdin.write(lines.tobytes())  # returns once the watch has read all but a pipe's buffer
    p.stdin.flush()
    time.sleep(0.5)
    p.send_signal(getattr(signal, sig))  # the writer keeps the pipe open: only the signal ends it
    out, err = p.communicate(timeout=HANG_S)
    got = _balls(out.decode())
    assert p.returncode == 128 + getattr(signal, sig), err.decode()
    assert got[:2] == want[:2]  # every ball that had passed, as the complete run
    assert len(got) == 3 and "cut_last_line" in got[2][2]  # the one in view measured, flagged
    assert f"stopped by {sig} after {cut} lines, 3 balls" in err.decode() and "Traceback" not in err.decode()


def test_watch_timeout_counts_before_the_first_byte_of_a_silent_fifo(tmp_path):
    fifo = tmp_path / "lines.fifo"
    os.mkfifo(fifo)
    cam = tmp_path / "cam.toml"
    save_camera(CAM, cam)
    p = _ballscan("watch", str(fifo), "--camera", str(cam), "--radius", str(RADIUS), "--timeout", "1")
    out, err = p.communicate(timeout=HANG_S)  # no writer ever: it used to block in open() for good
    assert p.returncode == 2 and out == b""
    assert f"{fifo}: no data for 1 s after line 0 (source stalled; --timeout)" in err.decode()


def test_a_stream_one_pixel_too_wide_is_refused_before_its_first_ball(stream, tmp_path, capsys):
    wide = replace_width(CAM, 513)
    sim = simulate_stream(tmp_path / "w.raw", wide, 3000, 2, seed=2)
    cam = tmp_path / "cam512.toml"
    save_camera(CAM, cam)
    assert main(["watch", str(sim.raw), "--camera", str(cam), "--radius", str(RADIUS), "--no-progress"]) == 2
    cap = capsys.readouterr()
    assert cap.out == ""
    assert "not 512 px wide: the background's column pattern repeats every 513 samples" in cap.err


def replace_width(cam: LineScanCamera, width: int) -> LineScanCamera:
    from dataclasses import replace

    return replace(cam, width=width, principal_px=(width - 1) / 2)


# ---------------------------------------------------------------- watch --save-events
def _event_files(folder: Path) -> dict[str, object]:
    """Each event file by name: a crop's bytes, a JSON's ball (lines and speed; times vary), an overlay's decoded size."""
    from PIL import Image

    out: dict[str, object] = {}
    for p in sorted(folder.iterdir()):
        if p.name == LOCK_NAME:
            continue
        if p.suffix == ".json":
            d = json.loads(p.read_text())
            out[p.name] = (d["first_line"], d["last_line"], d["speed_mps"])
        elif p.name.endswith(".overlay.png"):
            with Image.open(p) as im:
                im.load()
                out[p.name] = im.size
        else:
            out[p.name] = p.read_bytes()
    return out


def test_kill_9_during_save_events_then_a_rerun_writes_every_ball_once(stream, tmp_path, capsys):
    args = ["watch", str(stream.raw), "--camera", str(stream.camera_path), "--radius", str(RADIUS), "--no-progress"]
    ref = tmp_path / "ref"
    assert main([*args, "--save-events", str(ref)]) == 0
    capsys.readouterr()
    ev = tmp_path / "ev"
    p = _ballscan(*args, "--save-events", str(ev))
    t0 = time.monotonic()
    while not list(ev.glob("*_ball0.json")) and p.poll() is None and time.monotonic() - t0 < HANG_S:
        time.sleep(0.01)
    p.kill()
    p.communicate(timeout=HANG_S)
    # whatever the kill left: whole files only (a temporary name at most)
    for f in ev.iterdir():
        if f.name.startswith(".") and TEMP_MARK in f.name:
            continue
        if f.suffix == ".json":
            json.loads(f.read_text())
    # a damaged crop from an older writer is rewritten, not skipped
    crops = sorted(ev.glob("event_*[0-9].png"))
    if crops:
        crops[0].write_bytes(crops[0].read_bytes()[:100])
    assert main([*args, "--save-events", str(ev)]) == 0
    assert _event_files(ev) == _event_files(ref)
    assert len(list(ev.glob("*_ball*.json"))) == len(stream.balls)


def test_two_watches_on_one_event_folder_the_second_refused(stream, tmp_path, capsys):
    ev = tmp_path / "ev"
    with OutputLock(ev / LOCK_NAME, "x"):
        assert main(["watch", str(stream.raw), "--camera", str(stream.camera_path), "--radius", str(RADIUS), "--save-events", str(ev)]) == 2
    assert "another ballscan run" in capsys.readouterr().err


# ---------------------------------------------------------------- batch
def _cmdline(proc: psutil.Process) -> str:
    """A child's command line; empty for one that has just ended (a batch's decoder, joined at once)."""
    try:
        return " ".join(proc.cmdline())
    except (psutil.ZombieProcess, psutil.NoSuchProcess):
        return ""


def _workers(parent: psutil.Process) -> list[psutil.Process]:
    """The batch's live workers: its children but the resource tracker and those just ended."""
    return [c for c in parent.children(recursive=True) if (line := _cmdline(c)) and "resource_tracker" not in line]


def test_kill_9_during_batch_ends_its_workers_and_a_rerun_gives_every_ball_once(images, tmp_path):
    want = {f"img{k}.png": 1 if k % 2 else 2 for k in range(8)}
    out = tmp_path / "out.csv"
    p = _ballscan("batch", str(images), "--radius", str(RADIUS), "--out", str(out), "-j", "2", "--no-progress")
    parent = psutil.Process(p.pid)
    t0 = time.monotonic()
    workers: list[psutil.Process] = []
    while time.monotonic() - t0 < HANG_S and p.poll() is None:
        workers = _workers(parent)
        if len(workers) >= 2 and out.is_file() and out.read_bytes().count(b"\n") >= 2:
            break
        time.sleep(0.02)
    p.kill()
    p.communicate(timeout=HANG_S)
    # the workers notice their parent's death (a fraction of a second), not after their queue
    _, alive = psutil.wait_procs(workers, timeout=10.0)
    assert alive == []
    s = run_batch([images], out, RADIUS)
    rows = _rows(out)
    assert _per_source(rows) == want and len(rows) == 12
    assert s.errors == ()


def test_a_partial_last_row_is_dropped_and_its_input_measured_again(images, tmp_path):
    out = tmp_path / "out.csv"
    run_batch([images], out, RADIUS)
    data = out.read_bytes()
    last_src = _rows(out)[-1]["source"]
    out.write_bytes(data[: len(data) - 40])  # a write cut by a crash
    s = run_batch([images], out, RADIUS)
    assert s.repairs and "dropped a partial last row" in s.repairs[0] and Path(last_src).name in s.repairs[0]
    rows = _rows(out)
    assert len(rows) == 12 and len(_per_source(rows)) == 8 and s.n_done >= 1


def test_a_deleted_csv_means_every_input_again(images, tmp_path):
    out = tmp_path / "out.csv"
    first = run_batch([images], out, RADIUS)
    out.unlink()  # OUT.csv.done stays behind
    again = run_batch([images], out, RADIUS)
    assert (again.n_skipped, again.n_done, again.n_balls) == (0, 8, first.n_balls)
    assert len(_rows(out)) == 12


def test_a_second_batch_on_one_csv_is_refused(images, tmp_path, capsys):
    out = tmp_path / "out.csv"
    with OutputLock(tmp_path / "out.csv.lock", str(out)):
        with pytest.raises(BallscanError, match="another ballscan run"):
            run_batch([images / "img0.png"], out, RADIUS)
        assert main(["batch", str(images / "img0.png"), "--radius", str(RADIUS), "--out", str(out), "--no-progress"]) == 2
    assert "out.csv: another ballscan run (pid" in capsys.readouterr().err
    assert not out.exists() or _rows(out) == []


def test_batch_exit_status_is_1_with_a_failing_input(images, tmp_path, capsys):
    bad = tmp_path / "bad.png"
    bad.write_bytes(b"not a png")
    save_camera(CAM, tmp_path / "bad.camera.toml")
    assert main(["batch", str(bad), str(images / "img1.png"), "--radius", str(RADIUS), "--out", str(tmp_path / "o.csv"), "--no-progress"]) == 1
    err = capsys.readouterr().err
    assert "bad.png" in err and "1 failed" in err
    assert len(_rows(tmp_path / "o.csv")) == 1


def test_batch_refuses_a_symlinked_csv_unless_forced(images, tmp_path, capsys):
    target = tmp_path / "target.csv"
    target.write_text(",".join(COLUMNS) + "\r\n")
    link = tmp_path / "link.csv"
    link.symlink_to(target)
    assert main(["batch", str(images / "img1.png"), "--radius", str(RADIUS), "--out", str(link), "--no-progress"]) == 2
    assert "is a symbolic link" in capsys.readouterr().err and _rows(target) == []
    assert main(["batch", str(images / "img1.png"), "--radius", str(RADIUS), "--out", str(link), "--no-progress", "--force"]) == 0
    assert link.is_symlink() and len(_rows(target)) == 1


def test_sigterm_stops_batch_with_its_status_and_the_rows_written_stay(images, tmp_path):
    out = tmp_path / "out.csv"
    p = _ballscan("batch", str(images), "--radius", str(RADIUS), "--out", str(out), "-j", "2", "--no-progress")
    t0 = time.monotonic()
    while time.monotonic() - t0 < HANG_S and p.poll() is None and not (out.is_file() and out.read_bytes().count(b"\n") >= 2):
        time.sleep(0.02)
    workers = _workers(psutil.Process(p.pid)) if p.poll() is None else []
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=HANG_S)
    assert p.returncode == 128 + signal.SIGTERM, err.decode()
    assert "stopped by SIGTERM" in err.decode() and "Traceback" not in err.decode()
    assert psutil.wait_procs(workers, timeout=10.0)[1] == []
    run_batch([images], out, RADIUS)
    assert len(_rows(out)) == 12
