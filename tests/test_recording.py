"""Recordings longer than the stream engine's buffer: measured as a stream of their lines, in their stored type, memory-mapped where the file allows."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import tifffile
from PIL import Image

from ballscan.cli.app import main
from ballscan.geometry.camera import LineScanCamera, save_camera
from ballscan.geometry.motion import BallMotion
from ballscan.measure.images import read_stored
from ballscan.model.render import Appearance, SensorNoise, render
from ballscan.stream.engine import StreamConfig, process_stream
from ballscan.stream.recording import is_recording, measure_file, measure_recording, open_raw

RADIUS = 0.0335
CAM = LineScanCamera(width=256, focal_px=1100.0, principal_px=127.5, line_rate_hz=20000.0)
N_LINES = 12_000
CROSSINGS = ((1500.0, 0.0), (6100.0, 0.1), (11000.0, -0.1))


@pytest.fixture(scope="module")
def recording(tmp_path_factory):
    motions = [(BallMotion(RADIUS, ln / CAM.line_rate_hz, (0.0, y0, 4.0), (35.0, 1.0, -2.0)), Appearance.flat(0.8)) for ln, y0 in CROSSINGS]
    r = render(CAM, motions, N_LINES, background_level=0.12, noise=SensorNoise(), seed=3)
    folder = tmp_path_factory.mktemp("rec")
    tif, png, raw = folder / "rec.tif", folder / "rec.png", folder / "rec.raw"
    tifffile.imwrite(tif, r.image)  # uncompressed, one strip run: memory-mappable
    Image.fromarray(r.image).save(png)
    raw.write_bytes(np.ascontiguousarray(r.image).tobytes())
    cam = folder / "cam.toml"
    save_camera(CAM, cam)
    return r, tif, png, raw, cam


def _key(report):
    return [(b.first_line, b.last_line, b.t_c_s, b.velocity_mps, b.velocity_sigma_mps, b.flags) for b in report.balls]


def test_a_long_recording_gives_the_streams_balls_in_every_file_form(recording):
    r, tif, png, raw, _ = recording
    stream = [res.estimate for res in process_stream((r.image[i : i + 1000] for i in range(0, N_LINES, 1000)), CAM, RADIUS, StreamConfig())]
    assert len(stream) == len(CROSSINGS)
    want = [(b.first_line, b.last_line, b.t_c_s, b.velocity_mps, b.velocity_sigma_mps, b.flags) for b in stream]
    for path in (tif, png):
        assert _key(measure_file(path, CAM, RADIUS)) == want, path
    assert _key(measure_recording(open_raw(raw, CAM.width), CAM, RADIUS)) == want


def test_the_balls_are_measured_to_their_sigmas(recording):
    r, tif, *_ = recording
    rep = measure_file(tif, CAM, RADIUS)
    for est, truth in zip(rep.balls, r.balls):
        assert est.t_c_s == pytest.approx(truth.t_c_s, abs=2 / CAM.line_rate_hz)
        z = (np.array(est.velocity_mps) - truth.velocity_mps) / np.array(est.velocity_sigma_mps)
        assert np.all(np.abs(z) < 4), z


def test_an_uncompressed_tiff_is_memory_mapped_and_a_png_decoded_in_its_stored_type(recording):
    _, tif, png, *_ = recording
    mapped, decoded = read_stored(tif), read_stored(png)
    assert isinstance(mapped.data, np.memmap) and mapped.data.dtype == np.uint8
    assert not isinstance(decoded.data, np.memmap) and decoded.data.dtype == np.uint8
    assert is_recording(mapped) and not is_recording(read_stored(tif), StreamConfig(buffer_lines=N_LINES))


def test_estimate_measures_a_long_recording_as_a_stream(recording, tmp_path, capsys):
    _, tif, _, _, cam = recording
    assert main(["estimate", str(tif), "--camera", str(cam), "--radius", str(RADIUS), "--json", "--plot", str(tmp_path / "o.png")]) == 0
    d = json.loads(capsys.readouterr().out)
    assert [b["first_line"] for b in d["balls"]] == [b.first_line for b in measure_file(tif, CAM, RADIUS).balls]
    assert (tmp_path / "o.png").stat().st_size > 1000
    assert main(["estimate", str(tif), "--camera", str(cam), "--radius", str(RADIUS), "--max-pixels", "1000"]) == 2
    assert "more than the limit" in capsys.readouterr().err


def test_a_raw_file_of_a_partial_line_is_refused_naming_it(tmp_path):
    bad = tmp_path / "bad.raw"
    bad.write_bytes(b"\x00" * (CAM.width * 3 + 5))
    with pytest.raises(Exception, match="bad.raw: .* not a whole number of 256-pixel uint8 lines"):
        open_raw(bad, CAM.width)


def test_a_colour_recording_is_refused_by_the_engine(recording):
    from ballscan.errors import BallscanError
    from ballscan.measure.images import StoredImage

    with pytest.raises(BallscanError, match="8- or 16-bit grey"):
        measure_recording(StoredImage(np.zeros((10, CAM.width, 3), np.uint8), 8, "c.png"), CAM, RADIUS)


@pytest.mark.parametrize("saturation", [0.0, -5.0, float("nan"), float("inf")])
def test_a_bad_saturation_level_is_refused_naming_the_file_on_both_paths(recording, saturation):
    from ballscan.errors import BallscanError
    from ballscan.stream.recording import measure_stored

    _, tif, _, _, _ = recording
    long, short = read_stored(tif), read_stored(tif)
    short = type(short)(np.ascontiguousarray(short.data[:500]), short.bits, short.source)
    for stored in (long, short):
        with pytest.raises(BallscanError, match="rec.tif.*saturation level must be a positive number"):
            measure_stored(stored, CAM, RADIUS, saturation_dn=saturation)
