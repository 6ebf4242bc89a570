"""The live page in a real headless browser (Debian's chromium and chromium-driver, through selenium).

``ballscan watch FIFO --serve 0`` runs as a process on a named pipe that
the test writes a rendered stream into; the page must list each ball within
a second of its JSON line, switch units, and say when the source stalls and
when it ends. ``ballscan view`` over the run's saved events lists every
ball. Skipped only when the browser, its driver or selenium is missing.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from ballscan.geometry.camera import save_camera

from .test_live import BALLS, CAM, RADIUS, stream_lines

CHROMIUM = Path("/usr/bin/chromium")
CHROMEDRIVER = Path("/usr/bin/chromedriver")
if not (CHROMIUM.exists() and CHROMEDRIVER.exists()):
    pytest.skip("needs Debian's chromium and chromium-driver (apt-get install chromium chromium-driver)", allow_module_level=True)
webdriver = pytest.importorskip("selenium.webdriver")
pytest.importorskip("starlette")
pytest.importorskip("uvicorn")

#: Seconds a ball may take from its JSON line to the page.
WITHIN_S = 1.0


@pytest.fixture(scope="module")
def browser():
    from selenium.webdriver.chrome.service import Service

    opts = webdriver.ChromeOptions()
    opts.binary_location = str(CHROMIUM)
    profile = tempfile.TemporaryDirectory()
    for arg in (
        "--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--disable-gpu", "--disable-background-networking",
        "--disable-component-update", "--no-first-run", f"--user-data-dir={profile.name}", "--window-size=1400,1100",
    ):  # fmt: skip
        opts.add_argument(arg)
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("SE_OFFLINE", "true")  # selenium fetches nothing
        driver = webdriver.Chrome(service=Service(str(CHROMEDRIVER)), options=opts)
    try:
        yield driver
    finally:
        driver.quit()
        profile.cleanup()


def _until(check, timeout_s: float, what: str, step_s: float = 0.02):
    t_end = time.monotonic() + timeout_s
    while True:
        got = check()
        if got:
            return got
        if time.monotonic() > t_end:
            raise AssertionError(f"timed out after {timeout_s} s waiting for {what}")
        time.sleep(step_s)


class Watch:
    """``ballscan watch`` on a named pipe, with the page served, its JSON lines timed as they are printed."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.lines = stream_lines()
        self.camera = folder / "cam.toml"
        save_camera(CAM, self.camera)
        self.fifo = folder / "lines.fifo"
        os.mkfifo(self.fifo)
        self.events = folder / "events"
        cmd = [
            sys.executable, "-m", "ballscan", "watch", str(self.fifo), "--camera", str(self.camera), "--radius", str(RADIUS),
            "--serve", "0", "--save-events", str(self.events), "--no-progress",
        ]  # fmt: skip
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.printed: list[tuple[float, dict]] = []
        self.stderr: list[str] = []
        self._readers = [threading.Thread(target=f, daemon=True) for f in (self._read_stdout, self._read_stderr)]
        for t in self._readers:
            t.start()
        found = _until(lambda: next((m for t in self.stderr if (m := re.search(r"live view at (\S+)", t))), None), 60, "the live view's address")
        self.url = found.group(1)
        self.writer = None
        self._writing: threading.Event | None = None

    def _read_stdout(self) -> None:
        for text in self.proc.stdout:
            self.printed.append((time.monotonic(), json.loads(text)))

    def _read_stderr(self) -> None:
        for text in self.proc.stderr:
            self.stderr.append(text)

    def write_stream(self) -> None:
        """Write every line into the pipe on a thread of its own, keeping the pipe open (the source is then silent, not ended)."""
        if self._writing is not None:
            return
        done = threading.Event()

        def write():
            self.writer = open(self.fifo, "wb", buffering=0)  # opens once the watch reads (its estimator loaded)
            for a in range(0, self.lines.shape[0], 512):
                self.writer.write(np.ascontiguousarray(self.lines[a : a + 512]).tobytes())
            done.set()

        self._writing = done
        threading.Thread(target=write, daemon=True).start()

    def wait_written(self) -> None:
        self.write_stream()
        assert self._writing.wait(60), "the watch did not read its source: " + "".join(self.stderr)

    def stop(self) -> int:
        if self.proc.poll() is None:
            self.proc.send_signal(2)  # Ctrl-C ends the page's lingering after the stream
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        for t in self._readers:
            t.join(5)
        self.proc.stdout.close()
        self.proc.stderr.close()
        return self.proc.returncode


@pytest.fixture(scope="module")
def watch(tmp_path_factory):
    from ballscan.stream.engine import preload_estimator

    preload_estimator()  # compiled kernels on disk before the watch's own start
    w = Watch(tmp_path_factory.mktemp("live"))
    try:
        yield w
    finally:
        if w.writer is not None and not w.writer.closed:
            w.writer.close()
        w.stop()


def _open(browser, url: str) -> None:
    browser.get(url)
    _until(lambda: browser.execute_script("return document.body.dataset.ready === '1'"), 10, "the page's script")


def _rows(browser) -> list[int]:
    return browser.execute_script("return Array.from(document.querySelectorAll('#balls-table tbody tr')).map((r) => Number(r.dataset.index))")


def _text(browser, element_id: str) -> str:
    return browser.execute_script(f"return document.getElementById('{element_id}').textContent")


def test_the_page_loads(browser, watch):
    _open(browser, watch.url)
    assert browser.title.startswith("ballscan watch") and "lines.fifo" in browser.title
    assert browser.execute_script("return document.querySelectorAll('canvas').length") == 4
    assert _text(browser, "unit") and browser.find_element("id", "unit").get_attribute("value") == "m/s"


def test_balls_appear_within_a_second_of_their_json_lines(browser, watch):
    _open(browser, watch.url)
    assert watch._writing is None, "the stream is written once, after the page is open"
    seen: dict[int, float] = {}
    watch.write_stream()

    def all_seen():
        now = time.monotonic()
        for k in _rows(browser):
            seen.setdefault(k, now)
        return len(seen) >= len(BALLS) and len(watch.printed) >= len(BALLS)

    _until(all_seen, 30, "every ball on the page")
    assert len(watch.printed) == len(BALLS)
    for k, (t_printed, record) in enumerate(watch.printed):
        assert seen[k] - t_printed < WITHIN_S, f"ball {k} took {seen[k] - t_printed:.2f} s from its JSON line to the page"
    last = watch.printed[-1][1]
    assert _text(browser, "speed") == f"{last['speed_mps']:.2f}"
    assert _text(browser, "speed-sigma") == f"± {last['speed_sigma_mps']:.2f}"
    assert _text(browser, "last-index") == f"#{len(BALLS) - 1}"
    # the table's rows, newest first, with each ball's speed
    cells = browser.execute_script("return Array.from(document.querySelectorAll('#balls-table tbody tr')).map((r) => r.cells[2].textContent)")
    assert cells == [f"{r['speed_mps']:.2f} ± {r['speed_sigma_mps']:.2f}" for _, r in reversed(watch.printed)]
    # the crop is drawn: the outline's blue pixels are on the canvas
    blue = browser.execute_script(
        "const d = document.getElementById('crop').getContext('2d').getImageData(0, 0, 320, 320).data; let n = 0;"
        "for (let i = 0; i < d.length; i += 4) if (d[i + 2] > 180 && d[i] < 140) n++; return n;"
    )
    assert blue > 50


def test_the_unit_switch(browser, watch):
    from selenium.webdriver.support.ui import Select

    watch.write_stream()
    _open(browser, watch.url)
    _until(lambda: len(_rows(browser)) == len(BALLS), 30, "the balls")
    last = watch.printed[-1][1]
    for unit, factor in (("km/h", 3.6), ("mph", 3600 / 1609.344), ("m/s", 1.0)):
        Select(browser.find_element("id", "unit")).select_by_value(unit)
        assert _text(browser, "speed") == f"{last['speed_mps'] * factor:.2f}"
        assert _text(browser, "speed-sigma") == f"± {last['speed_sigma_mps'] * factor:.2f}"
        assert browser.execute_script("return document.querySelector('#balls-table thead .unit-label').textContent") == unit


def test_banners_when_the_source_stalls_and_ends(browser, watch):
    watch.wait_written()
    _open(browser, watch.url)
    # the pipe stays open and silent: stalled (after a second without lines)
    _until(lambda: "stalled" in _text(browser, "banner"), 10, "the stall banner")
    assert browser.find_element("id", "banner").is_displayed()
    assert browser.execute_script("return document.getElementById('banner').classList.contains('stalled')")
    watch.writer.close()  # the source ends
    _until(lambda: "ended" in _text(browser, "banner"), 10, "the end banner")
    assert f"after {watch.lines.shape[0]:,d} lines" in _text(browser, "banner")
    assert watch.stop() == 0


def test_view_lists_every_ball_of_a_saved_run(browser, watch):
    watch.wait_written()
    if not watch.writer.closed:
        watch.writer.close()
    _until(lambda: watch.proc.poll() is not None or any("stream ended" in t for t in watch.stderr), 30, "the watch's end")
    watch.stop()
    printed = [r for _, r in watch.printed]
    cmd = [sys.executable, "-m", "ballscan", "view", str(watch.events), "--camera", str(watch.camera), "--serve", "0"]
    with subprocess.Popen(cmd, stderr=subprocess.PIPE, text=True) as proc:
        _view(browser, proc, printed)


def _view(browser, proc, printed) -> None:
    from selenium.webdriver.support.ui import Select

    try:
        line = proc.stderr.readline()
        url = re.search(r"at (\S+) \(Ctrl-C", line).group(1)
        _open(browser, url)
        _until(lambda: len(_rows(browser)) == len(printed), 10, "every saved ball")
        speeds = browser.execute_script("return Array.from(document.querySelectorAll('#balls-table tbody tr')).map((r) => r.cells[2].textContent)")
        assert speeds == [f"{r['speed_mps']:.2f} ± {r['speed_sigma_mps']:.2f}" for r in printed]
        assert "replay" in _text(browser, "banner")
        # the speed filter (in the viewer's unit) and the download link follow it
        Select(browser.find_element("id", "unit")).select_by_value("km/h")
        cut = sorted(r["speed_mps"] for r in printed)[1] * 3.6
        box = browser.find_element("id", "f-min")
        box.send_keys(f"{cut - 1e-6:.6f}\n")
        want = [k for k, r in enumerate(printed) if r["speed_mps"] * 3.6 >= cut - 1e-6]
        _until(lambda: _rows(browser) == want, 10, "the filtered table")
        assert "min_mps=" in browser.find_element("id", "download").get_attribute("href")
    finally:
        proc.send_signal(2)
        proc.wait(10)
