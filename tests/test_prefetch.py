"""PNGs decoded ahead on another core (ballscan.stream.prefetch): the same samples as read_stored, no process left."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import psutil

from ballscan.model.render import write_image
from ballscan.stream.prefetch import decoded, decoding_ahead, stop_decoding

# Run in a fresh process: a fork needs one Python thread, which a test
# session (Dask, a live server) does not promise.
SCRIPT = r"""
import json, os, sys, time
import numpy as np
from ballscan.measure.images import read_stored
from ballscan.parallel import TaskExecutor
from ballscan.stream import prefetch

wait_for, paths = sys.argv[2], sys.argv[3:]
out = {}
with prefetch.decoding_ahead(paths, capacity_bytes=int(sys.argv[1])):
    # the decoder's turn (this process would load the estimator): until it has reached wait_for
    deadline = time.monotonic() + 60.0
    while prefetch.decoded(wait_for) is None and time.monotonic() < deadline:
        time.sleep(0.01)
    out["while_running"] = prefetch.decoded(paths[0]) is not None
    out["n"] = prefetch.stop_decoding()
    out["again"] = prefetch.stop_decoding()
    out["children"] = len(__import__("psutil").Process().children())
    same = {}
    for p in paths:
        d = prefetch.decoded(p)
        if d is not None:
            ref = read_stored(p)
            same[os.path.basename(p)] = bool(d.data.dtype == ref.data.dtype and np.array_equal(d.data, ref.data) and d.bits == ref.bits and d.source == p)
    out["same"] = same

    def seen(p):
        d = prefetch.decoded(p)
        return os.getpid(), None if d is None else int(d.data.sum())

    with TaskExecutor(2) as ex:
        ex._start_pool(2)  # forked workers, whatever the items' cost
        out["in_workers"] = {os.path.basename(r.item): r.value[1] for r in ex.map(seen, paths) if r.value[0] != os.getpid()}
out["after"] = prefetch.decoded(paths[0]) is None
print(json.dumps(out))
"""


def _images(tmp_path):
    rng = np.random.default_rng(3)
    paths = []
    for k in range(4):
        img = rng.integers(0, 256, (40 + k, 64), dtype=np.uint8)
        write_image(tmp_path / f"a{k}.png", img)
        paths.append(tmp_path / f"a{k}.png")
    write_image(tmp_path / "deep.png", rng.integers(0, 4096, (30, 64), dtype=np.uint16))
    (tmp_path / "bad.png").write_bytes(b"\x89PNG\r\n\x1a\n but no image")
    write_image(tmp_path / "c.tif", rng.integers(0, 256, (20, 64), dtype=np.uint8))
    return [str(p) for p in (paths[0], paths[1], tmp_path / "bad.png", tmp_path / "deep.png", tmp_path / "c.tif", paths[2], paths[3])]


def _run(paths, capacity, wait_for):
    res = subprocess.run([sys.executable, "-c", SCRIPT, str(capacity), wait_for, *paths], capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr
    return json.loads(res.stdout.splitlines()[-1])


def test_decoded_pngs_are_read_stored_bit_for_bit_here_and_in_forked_workers(tmp_path):
    paths = _images(tmp_path)
    out = _run(paths, 1 << 20, paths[-1])  # the last PNG decoded
    # every readable PNG (the damaged one and the TIFF are read where measured)
    assert out["same"] == {"a0.png": True, "a1.png": True, "deep.png": True, "a2.png": True, "a3.png": True}
    assert out["while_running"] and out["n"] == out["again"] == 5
    assert out["children"] == 0  # the decoder is gone once stopped
    expect = {p.rsplit("/", 1)[-1]: None for p in paths}
    for p in paths:
        if p.endswith(".png") and "bad" not in p:
            from ballscan.measure.images import read_stored

            expect[p.rsplit("/", 1)[-1]] = int(read_stored(p).data.sum())
    assert out["in_workers"] and all(expect[k] == v for k, v in out["in_workers"].items())
    assert out["after"]


def test_the_decoder_stops_before_an_image_that_does_not_fit(tmp_path):
    paths = _images(tmp_path)
    out = _run(paths, 2 * 41 * 64 + 64, paths[1])  # room for a0 (40 lines) and a1 (41 lines), 64-byte aligned, not deep.png
    assert sorted(out["same"]) == ["a0.png", "a1.png"]


def test_outside_a_block_or_without_pngs_nothing_is_decoded(tmp_path):
    before = {p.pid for p in psutil.Process().children()}
    assert decoded("x.png") is None and stop_decoding() == 0
    with decoding_ahead([str(tmp_path / "c.tif"), str(tmp_path / "s.raw")]):
        assert {p.pid for p in psutil.Process().children()} == before
        assert stop_decoding() == 0
