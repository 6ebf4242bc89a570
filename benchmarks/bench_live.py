"""Benchmark of the live page's cost to a watch (run on demand: ``python benchmarks/bench_live.py``).

``ballscan watch`` reads a rendered stream (2048-pixel 8-bit lines, a ball
every 10 000 lines) from a named pipe that this script fills as fast as the
watch reads it, in two ways, interleaved in one run (A B B A ...):

* ``plain``: ``watch`` as it is;
* ``serve``: ``watch --serve 127.0.0.1:0`` with three event-stream clients
  (httpx, each on a thread of this process) connected before the first line.

For each run: lines per second (the lines over the time the pipe took them:
a pipe holds 64 KiB, so the writer finishes when the watch has read all but
that), the engine's latency of each ball (``latency_s`` of its JSON line:
from the arrival of the chunk that completed the ball's event to its result),
and with ``--serve`` the push delay (from the ball's JSON line reaching this
script to its event reaching each client) and the lag the page shows (from
the ball's last line read to its publication); and the CPU seconds of the
watch process over the stream (from the pipe's opening until the watch,
its pipe still open but silent, has measured everything it read: the
server's thread included), and over its whole life (the web server's
imports are part of ``--serve``'s cost). On a shared machine the CPU
seconds are the steadier figure; the rates move with the other jobs.
Last, in this process (no start-up), the same stream through
``process_stream`` with and without the live view's hooks, server and
three clients: the measuring thread's CPU seconds (what the live view may
not slow) and the whole process's. Target: ``serve`` within 10 %
of ``plain`` in rate and latency.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np
import psutil

RADIUS = 0.0335


def make_stream(folder: Path, n_lines: int) -> Path:
    """A rendered stream with a ball every 10 000 lines (``ballscan simulate --stream``'s renderer)."""
    from ballscan.lab.presets import get_preset
    from ballscan.stream.sources import simulate_stream

    raw = folder / "bench_live.raw"
    simulate_stream(raw, get_preset("tennis-serve").camera, n_lines, max(n_lines // 10_000, 1), seed=3)
    return raw


class Client:
    """One event-stream viewer: the time each ball's event arrives."""

    def __init__(self, url: str) -> None:
        import httpx

        self.arrived: dict[int, float] = {}
        self.lags: dict[int, float] = {}
        self.connected = threading.Event()
        self._client = httpx.Client(timeout=None)
        self._thread = threading.Thread(target=self._read, args=(url,), daemon=True)
        self._thread.start()

    def _read(self, url: str) -> None:
        kind = None
        try:
            with self._client.stream("GET", url + "events") as resp:
                for text in resp.iter_lines():
                    if text.startswith("event: "):
                        kind = text[7:]
                    elif text.startswith("data: "):
                        now = time.monotonic()
                        self.connected.set()
                        if kind == "ball":
                            ball = json.loads(text[6:])
                            self.arrived[ball["index"]] = now
                            self.lags[ball["index"]] = ball["lag_s"]
        except Exception:  # the watch stopped: the stream is over
            pass

    def close(self) -> None:
        self._client.close()


def run_once(raw: Path, camera: Path, serve: bool, clients: int) -> dict:
    """One watch over the stream; its rate, the balls' latencies and, when serving, the push delays."""
    fifo = Path(tempfile.mkdtemp()) / "lines.fifo"
    os.mkfifo(fifo)
    cmd = [sys.executable, "-m", "ballscan", "watch", str(fifo), "--camera", str(camera), "--radius", str(RADIUS), "--no-progress"]
    if serve:
        cmd += ["--serve", "127.0.0.1:0"]
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    printed: list[tuple[float, dict]] = []
    errors: list[str] = []

    def read_out():
        for text in proc.stdout:
            printed.append((time.monotonic(), json.loads(text)))

    def read_err():
        for text in proc.stderr:
            errors.append(text)

    readers = [threading.Thread(target=f, daemon=True) for f in (read_out, read_err)]
    for t in readers:
        t.start()
    viewers: list[Client] = []
    if serve:
        while not any("live view at" in e for e in errors):
            if proc.poll() is not None:
                raise RuntimeError("".join(errors))
            time.sleep(0.01)
        url = re.search(r"live view at (\S+)", "".join(errors)).group(1)
        viewers = [Client(url) for _ in range(clients)]
        for v in viewers:
            v.connected.wait(10)
    data = raw.read_bytes()
    piece = 1 << 20
    watcher = psutil.Process(proc.pid)
    out = open(fifo, "wb", buffering=0)  # opens when the watch starts reading
    cpu0 = sum(watcher.cpu_times()[:2])
    t0 = time.monotonic()
    for a in range(0, len(data), piece):
        out.write(data[a : a + piece])
    t1 = time.monotonic()
    # the pipe stays open: the watch measures what it read, then waits (its CPU time settles)
    cpu1, t_settle = sum(watcher.cpu_times()[:2]), time.monotonic() + 10
    while time.monotonic() < t_settle:
        time.sleep(0.3)
        now = sum(watcher.cpu_times()[:2])
        if now - cpu1 < 0.01:
            break
        cpu1 = now
    out.close()
    if serve:
        while not any("stream ended" in e for e in errors) and proc.poll() is None:
            time.sleep(0.01)
        t_wait = time.monotonic() + 5
        while time.monotonic() < t_wait and any(len(v.arrived) < len(printed) for v in viewers):
            time.sleep(0.01)
        proc.send_signal(signal.SIGINT)
    proc.wait(60)
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    for t in readers:
        t.join(5)
    for v in viewers:
        v.close()
    fifo.unlink()
    n_lines = len(data) // 2048
    push = [v.arrived[k] - t for v in viewers for k, (t, _) in enumerate(printed) if k in v.arrived]
    return {
        "rate": n_lines / (t1 - t0),
        "cpu": (ru1.ru_utime + ru1.ru_stime) - (ru0.ru_utime + ru0.ru_stime),
        "stream_cpu": cpu1 - cpu0,
        "latency": [r["latency_s"] for _, r in printed],
        "balls": len(printed),
        "push": push,
        "received": [len(v.arrived) for v in viewers],
        "lag": [v.lags[k] for v in viewers[:1] for k in v.lags],
    }


def thread_split(raw: Path, camera_path: Path, serve: bool, clients: int) -> tuple[float, float]:
    """In this process: the measuring thread's CPU seconds over the stream, and the whole process's (server and clients included)."""
    from ballscan.geometry.camera import load_camera
    from ballscan.live.server import LiveWatch
    from ballscan.stream.engine import StreamConfig, process_stream
    from ballscan.stream.sources import RawLineSource

    camera = load_camera(camera_path)
    src = RawLineSource(raw, camera.width, chunk_lines=32)  # a pipe read as fast as it is written gives 64 KiB reads
    live, viewers = None, []
    if serve:
        live = LiveWatch(camera, "127.0.0.1:0")
        live.start()
        viewers = [Client(live.server.url) for _ in range(clients)]
        for v in viewers:
            v.connected.wait(10)
    chunks = live.hub.chunks(src) if live is not None else src
    p0, t0 = time.process_time(), time.thread_time()
    for res in process_stream(chunks, camera, RADIUS, StreamConfig(keep_crops=serve), source=raw.name):
        json.dumps(res.to_dict(camera), allow_nan=False)  # as watch prints it
        if live is not None:
            live.hub.ball(res)
    t1 = time.thread_time()
    time.sleep(0.3)  # the server sends the last balls
    p1 = time.process_time()
    if live is not None:
        live.server.stop()
        for v in viewers:
            v.close()
    return t1 - t0, p1 - p0


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lines", type=int, default=100_000, help="lines of the stream (default 100 000: 10 balls)")
    ap.add_argument("--repeats", type=int, default=4, help="runs of each way (default 4)")
    ap.add_argument("--clients", type=int, default=3, help="event-stream clients with --serve (default 3)")
    ap.add_argument("--stream", type=Path, default=None, help="a raw stream made before (with its .camera.toml beside it)")
    args = ap.parse_args(argv)
    from ballscan.stream.engine import preload_estimator

    preload_estimator()  # the compiled kernels on disk before the first watch
    with tempfile.TemporaryDirectory() as tmp:
        raw = args.stream or make_stream(Path(tmp), args.lines)
        camera = raw.with_name(raw.name + ".camera.toml")
        results: dict[str, list[dict]] = {"plain": [], "serve": []}
        for k in range(args.repeats):
            order = ("plain", "serve") if k % 2 == 0 else ("serve", "plain")
            for way in order:
                r = run_once(raw, camera, way == "serve", args.clients)
                results[way].append(r)
                print(f"run {k} {way:5s}: {r['rate']:>10,.0f} lines/s, {r['stream_cpu']:.3f} CPU s, {r['balls']} balls, latency median {1e3 * np.median(r['latency']):.1f} ms"
                      + (f", received {r['received']}" if way == "serve" else ""), flush=True)  # fmt: skip
        split = {"plain": [], "serve": []}
        for k in range(args.repeats):
            for way in (("plain", "serve") if k % 2 == 0 else ("serve", "plain")):
                split[way].append(thread_split(raw, camera, way == "serve", args.clients))
    rate = {w: float(np.median([r["rate"] for r in rs])) for w, rs in results.items()}
    lat = {w: np.concatenate([r["latency"] for r in rs]) for w, rs in results.items()}
    push = np.concatenate([r["push"] for r in results["serve"]])
    lag = np.concatenate([r["lag"] for r in results["serve"]])
    print(f"\nload average {os.getloadavg()[0]:.1f} (2 cores); {args.repeats} runs of each, interleaved; {args.clients} clients with --serve")
    print(f"{'quantity':44s} {'plain':>12s} {'--serve':>12s} {'serve/plain':>12s}")
    print(f"{'lines/s (median of runs)':44s} {rate['plain']:>12,.0f} {rate['serve']:>12,.0f} {rate['serve'] / rate['plain']:>12.3f}")
    cpu = {w: float(np.median([r["cpu"] for r in rs])) for w, rs in results.items()}
    scpu = {w: float(np.median([r["stream_cpu"] for r in rs])) for w, rs in results.items()}
    print(f"{'CPU s of the watch over the stream':44s} {scpu['plain']:>12.3f} {scpu['serve']:>12.3f} {scpu['serve'] / scpu['plain']:>12.3f}")
    print(f"{'CPU s of the watch process (start-up included)':44s} {cpu['plain']:>12.2f} {cpu['serve']:>12.2f} {cpu['serve'] / cpu['plain']:>12.3f}")
    th = {w: float(np.median([a for a, _ in v])) for w, v in split.items()}
    pr = {w: float(np.median([b for _, b in v])) for w, v in split.items()}
    print(f"{'in one process: the measuring thread, CPU s':44s} {th['plain']:>12.3f} {th['serve']:>12.3f} {th['serve'] / th['plain']:>12.3f}")
    print(f"{'  the process (server, clients), CPU s':44s} {pr['plain']:>12.3f} {pr['serve']:>12.3f} {pr['serve'] / pr['plain']:>12.3f}")
    for name, q in (("median", 50), ("95th percentile", 95)):
        a, b = np.percentile(lat["plain"], q) * 1e3, np.percentile(lat["serve"], q) * 1e3
        print(f"{'latency ' + name + ' (ms)':44s} {a:>12.2f} {b:>12.2f} {b / a:>12.3f}")
    print(f"{'push delay to the clients, median / max (ms)':44s} {'':>12s} {np.median(push) * 1e3:>5.1f} / {push.max() * 1e3:.1f}")
    print(f"{'lag shown (last line read to page), median (ms)':44s} {'':>12s} {np.median(lag) * 1e3:>12.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
