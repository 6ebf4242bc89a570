"""Tests of ballscan.stream.events: a stream's event folder, whole files, one writer, damaged files found on restart."""

from __future__ import annotations

import json

import numpy as np
import pytest

from ballscan.errors import BallscanError
from ballscan.geometry.camera import LineScanCamera
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, SensorNoise, render
from ballscan.outputs import TEMP_MARK
from ballscan.stream.engine import StreamConfig, process_stream
from ballscan.stream.events import LOCK_NAME, EventFolder

CAM = LineScanCamera(width=512, focal_px=1100.0, principal_px=255.5, line_rate_hz=20000.0)


@pytest.fixture(scope="module")
def results():
    m = BallMotion(0.0335, 900 / CAM.line_rate_hz, (0.0, 0.0, 4.0), (35.0, 1.0, -2.0))
    data = render(CAM, [(m, Appearance.flat(0.8))], 2000, background_level=0.12, noise=SensorNoise(), seed=1).image
    return list(process_stream([data], CAM, 0.0335, StreamConfig(keep_crops=True)))


def test_files_whole_and_rewritten_when_damaged(results, tmp_path):
    with EventFolder(tmp_path) as ev:
        written = ev.save(results[0], CAM, 0)
    names = sorted(p.name for p in written)
    assert len(names) == 4 and all(TEMP_MARK not in n for n in names)
    js = next(p for p in written if p.suffix == ".json")
    crop = next(p for p in written if p.suffix == ".png" and "overlay" not in p.name)
    good = crop.read_bytes()
    crop.write_bytes(good[:60])  # an older writer's half crop
    js.write_text('{"speed_mps": 3')  # and half a JSON
    (tmp_path / f".x.png.{TEMP_MARK}.abc.png").write_bytes(b"tmp")
    with EventFolder(tmp_path) as ev:
        assert sorted(p.name for p in ev.removed) == sorted([crop.name, js.name, f".x.png.{TEMP_MARK}.abc.png"])
        ev.save(results[0], CAM, 0)
    assert crop.read_bytes() == good and json.loads(js.read_text())["first_line"] == results[0].estimate.first_line


def test_a_second_writer_is_refused(results, tmp_path):
    with EventFolder(tmp_path):
        with pytest.raises(BallscanError, match="another ballscan run"):
            EventFolder(tmp_path).open()
    assert (tmp_path / LOCK_NAME).is_file()


def test_event_files_that_are_symlinks_are_not_written_through(results, tmp_path):
    with EventFolder(tmp_path) as ev:
        js = next(p for p in ev.save(results[0], CAM, 0) if p.suffix == ".json")
    target = tmp_path.parent / f"{tmp_path.name}_elsewhere.json"
    target.write_text("keep")
    js.unlink()
    js.symlink_to(target)
    with EventFolder(tmp_path) as ev, pytest.raises(BallscanError, match="symbolic link"):
        ev.save(results[0], CAM, 0)
    assert target.read_text() == "keep"
