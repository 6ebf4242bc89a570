"""The Basler camera source (ballscan.stream.sources.PylonSource, PylonFrames) and watch's pylon options.

Grab results and node maps are stubs where pylon's emulator cannot help (its
timestamps are zero, its block IDs consecutive, it has no Timestamp chunk);
the emulator (``PYLON_CAMEMU=1``) runs the plumbing end to end when pypylon
is installed.
"""

from __future__ import annotations

import importlib.util
from types import SimpleNamespace

import numpy as np
import pytest

from ballscan.cli.app import main
from ballscan.cli.stream import open_source
from ballscan.geometry.camera import LineScanCamera, save_camera
from ballscan.geometry.motion import BallMotion
from ballscan.model.render import Appearance, SensorNoise, render, write_image
from ballscan.stream.engine import process_stream
from ballscan.stream.sources import ArraySource, PylonFrames, SourceError, _import_pylon, block_gap, tick_frequency_hz

RADIUS = 0.0335
CAM = LineScanCamera(width=512, focal_px=1100.0, principal_px=255.5, line_rate_hz=20000.0)
EMULATED = "0815-0000"  # serial number of pylon's first emulated camera


def rendered(n_lines: int, ball_lines=(900.0, 2000.0)) -> np.ndarray:
    """An 8-bit stream of CAM with a ball centred on each of the given lines."""
    motions = [(BallMotion(RADIUS, ln / CAM.line_rate_hz, (0.0, 0.1 * k, 4.0), (35.0, 1.0, -2.0)), Appearance.flat(0.8)) for k, ln in enumerate(ball_lines)]
    return render(CAM, motions, n_lines, background_level=0.12, noise=SensorNoise(), seed=1).image


class Result:
    """A stub pylon grab result."""

    def __init__(self, lines, block_id=0, ticks=0, chunk_ticks=None, ok=True):
        self.lines, self.block_id, self.ticks, self.ok = lines, block_id, ticks, ok
        if chunk_ticks is not None:
            self.ChunkTimestamp = SimpleNamespace(Value=chunk_ticks)

    def GrabSucceeded(self):
        return self.ok

    def GetErrorDescription(self):
        return "The buffer was incompletely grabbed."

    def GetArray(self):
        return self.lines

    def GetBlockID(self):
        return self.block_id

    def GetTimeStamp(self):
        return self.ticks


class Node:
    """A stub GenICam node: its value and whether it can be read."""

    def __init__(self, value, readable=True):
        self.value, self.readable = value, readable

    def GetValue(self):
        return self.value


GENICAM = SimpleNamespace(IsReadable=lambda node: node.readable)


def nodemap(**nodes):
    return SimpleNamespace(GetNode=nodes.get)


# ---------------------------------------------------------------- block IDs
@pytest.mark.parametrize(
    ("previous", "block_id", "missing"),
    [
        (None, 7, 0),  # first frame
        (1, 2, 0),
        (1, 4, 2),
        (0, 1, 0),  # USB3 IDs start at 0
        (2**40, 2**40 + 6, 5),  # 64-bit IDs (USB3, GigE extended ID mode)
        (65535, 1, 0),  # GigE IDs wrap 65535 -> 1, no 0
        (65534, 2, 2),  # 65535 and 1 lost
        (0, 0, 0),  # a camera without block IDs
        (2**64 - 1, 5, 0),  # invalid ID
        (5, 2**64 - 1, 0),
    ],
)
def test_block_gap_counts_the_frames_lost_between_two_ids(previous, block_id, missing):
    assert block_gap(previous, block_id) == missing


# ---------------------------------------------------------- camera clock
def test_tick_frequency_is_the_gige_feature_else_nanoseconds():
    assert tick_frequency_hz(nodemap(GevTimestampTickFrequency=Node(125_000_000)), GENICAM) == 125e6
    assert tick_frequency_hz(nodemap(), GENICAM) == 1e9  # USB3: no such feature
    assert tick_frequency_hz(nodemap(GevTimestampTickFrequency=Node(0, readable=False)), GENICAM) == 1e9
    with pytest.raises(SourceError, match=r"^pylon: the camera reports GevTimestampTickFrequency = 0 Hz"):
        tick_frequency_hz(nodemap(GevTimestampTickFrequency=Node(0)), GENICAM)


def test_gige_ticks_become_seconds_since_the_first_frame():
    frames = PylonFrames(20000.0, "grab", tick_frequency_hz=125e6, name="pylon:gige")
    t0 = 3 * 10**15  # a camera up for 9 months: too many ticks for float64 ns
    lines = np.zeros((512, 64), np.uint8)
    a = frames.chunk(Result(lines, 1, t0))
    b = frames.chunk(Result(lines, 2, t0 + 3_200_000))  # 512 lines at 20 kHz = 25.6 ms = 3.2e6 ticks
    np.testing.assert_allclose(a.timestamps_s, np.arange(512) / 20000.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(b.timestamps_s, 0.0256 + np.arange(512) / 20000.0, rtol=0, atol=1e-12)
    assert frames.t0_ticks == t0 and frames.dropped_lines == 0


def test_usb_nanosecond_ticks_and_chunk_timestamps():
    frames = PylonFrames(1000.0, "chunk", name="pylon:usb")  # 1e9 ticks/s
    lines = np.zeros((4, 8), np.uint16)
    frames.chunk(Result(lines, 0, ticks=0, chunk_ticks=5_000_000_000))
    b = frames.chunk(Result(lines, 1, ticks=0, chunk_ticks=5_004_000_000))  # grab timestamps ignored
    np.testing.assert_allclose(b.timestamps_s, [0.004, 0.005, 0.006, 0.007], rtol=0, atol=1e-12)
    assert b.lines.dtype == np.uint16
    with pytest.raises(SourceError, match=r"^pylon:usb: frame 2 carries no Timestamp chunk \(--pylon-timestamps chunk\)$"):
        frames.chunk(Result(lines, 2, ticks=123))


def test_a_camera_clock_that_does_not_advance_is_a_one_line_error():
    frames = PylonFrames(20000.0, "grab", name="pylon:emu")
    frames.chunk(Result(np.zeros((8, 4), np.uint8), 0, 0))
    with pytest.raises(SourceError) as info:
        frames.chunk(Result(np.zeros((8, 4), np.uint8), 1, 0))  # the emulator's zero timestamps
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith("pylon:emu: frame 1 starts at 0 s") and "--pylon-timestamps none" in msg


def test_failed_grabs_and_colour_frames_are_one_line_errors():
    frames = PylonFrames(20000.0)
    with pytest.raises(SourceError, match=r"^pylon: grab failed after line 0: The buffer was incompletely grabbed\.$"):
        frames.chunk(Result(np.zeros((8, 4), np.uint8), ok=False))
    with pytest.raises(SourceError, match="frame 0 is not a grey image"):
        frames.chunk(Result(np.zeros((8, 4, 3), np.uint8)))


# ---------------------------------------------------------- dropped frames
def test_a_block_id_gap_is_a_jump_in_the_line_times():
    frames = PylonFrames(100.0, "none")
    lines = np.zeros((8, 4), np.uint8)
    times = [frames.chunk(Result(lines, b)).timestamps_s for b in (0, 1, 4, 5)]  # frames 2 and 3 lost
    np.testing.assert_array_equal(times[1], np.arange(8, 16) / 100.0)  # the engine's line / line_rate
    np.testing.assert_array_equal(times[2], np.arange(32, 40) / 100.0)
    np.testing.assert_array_equal(times[3], np.arange(40, 48) / 100.0)
    assert (frames.lines_read, frames.dropped_frames, frames.dropped_lines, frames.gaps) == (32, 2, 16, [(15, 16)])


def test_a_lost_frame_flags_the_ball_it_crosses_and_keeps_its_timing():
    """A frame lost inside the first ball: that ball is flagged dropped_lines and
    measured as from per-line timestamps with the same gap; the second ball is not flagged."""
    height, lost = 16, 900 // 16  # the frame holding line 900, the first ball's centre
    data = rendered(3072)
    keep = np.ones(data.shape[0], bool)
    keep[lost * height : (lost + 1) * height] = False
    frames = PylonFrames(CAM.line_rate_hz, "none", name="pylon:stub")
    chunks = (frames.chunk(Result(data[b * height : (b + 1) * height], b)) for b in range(data.shape[0] // height) if b != lost)
    res = list(process_stream(chunks, CAM, RADIUS, source="pylon:stub"))
    times = np.flatnonzero(keep) / CAM.line_rate_hz
    ref = list(process_stream(ArraySource(data[keep], 512, times), CAM, RADIUS))
    assert frames.gaps == [(lost * height - 1, height)]
    assert len(res) == 2
    assert ["dropped_lines" in r.estimate.flags for r in res] == [True, False]
    assert [r.estimate.t_c_s for r in res] == [r.estimate.t_c_s for r in ref]
    assert [r.estimate.first_line for r in res] == [r.estimate.first_line for r in ref]  # lines delivered
    assert abs(res[0].estimate.t_c_s - 900 / CAM.line_rate_hz) < 1 / CAM.line_rate_hz


# ------------------------------------------------------------ bad settings
@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--pixel-format", "Mono10"], "--pixel-format: must be one of Mono8, Mono12, Mono16, got 'Mono10'"),
        (["--pylon-timestamps", "camera"], "--pylon-timestamps: must be one of none, grab, chunk, got 'camera'"),
        (["--pfs", "missing.pfs"], "missing.pfs: no such pylon feature file (--pfs)"),
    ],
)
def test_bad_pylon_options_are_one_line_errors_before_a_camera_opens(tmp_path, capsys, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    save_camera(CAM, tmp_path / "cam.toml")
    code = main(["watch", "pylon:123", "--camera", "cam.toml", "--radius", "0.0335", *args])
    err = capsys.readouterr().err
    assert code == 2 and err == f"ballscan: error: {message}\n"


def test_pylon_options_are_refused_for_other_sources(tmp_path):
    with pytest.raises(ValueError, match=r"^--pfs and --pylon-timestamps: only for a camera source \(pylon or pylon:SERIAL\), not 'run.raw'$"):
        open_source("run.raw", CAM, pfs=tmp_path / "cam.pfs", pylon_timestamps="grab")


# --------------------------------------------------------------- emulator
PFS_HEADER = "# {05D8C294-F295-4dfb-9D01-096BD04049F4}\n# GenApi persistence file (version 3.5.0)\n"


@pytest.fixture(scope="module")
def emulator():
    """pylon with its emulated cameras (skipped, with the reason, without pypylon or emulation)."""
    if importlib.util.find_spec("pypylon") is None:
        pytest.skip("pypylon not installed (pip install pypylon): pylon emulator tests skipped")
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("PYLON_CAMEMU", "1")  # read when pylon starts: before pypylon is first imported
        _, pylon = _import_pylon()  # pypylon's import warnings silenced (pytest -W error)
        serials = [d.GetSerialNumber() for d in pylon.TlFactory.GetInstance().EnumerateDevices()]
        if EMULATED not in serials:
            pytest.skip(f"no emulated pylon camera {EMULATED} (PYLON_CAMEMU=1 was set after pylon started?); cameras: {serials}")
        yield EMULATED


def feature_file(path, folder, height: int = 512) -> str:
    """A pylon feature file that makes the emulator play the images of ``folder``, ``height`` lines a frame."""
    features = {"Width": 512, "Height": height, "TestImageSelector": "Off", "ImageFilename": folder, "ImageFileMode": "On"}
    path.write_text(PFS_HEADER + "".join(f"{k}\t{v}\n" for k, v in features.items()))
    return path


def test_emulated_camera_plays_rendered_frames_set_by_a_feature_file(tmp_path, emulator):
    data = rendered(3072)
    folder = tmp_path / "frames"
    folder.mkdir()
    for k in range(6):
        write_image(folder / f"f{k:03d}.png", data[512 * k : 512 * (k + 1)])
    src = open_source(f"pylon:{emulator}", CAM, pfs=feature_file(tmp_path / "emu.pfs", folder))
    src.frames = 6
    res = list(process_stream(src, CAM, RADIUS, source=src.name))
    ref = list(process_stream(ArraySource(data, 512, np.arange(3072) / CAM.line_rate_hz), CAM, RADIUS))
    assert (src.width, src.lines_read, src.dropped_lines, src.max_dn) == (512, 3072, 0, 255)
    assert len(res) == 2
    assert [r.estimate.t_c_s for r in res] == [r.estimate.t_c_s for r in ref]


def test_emulated_camera_in_mono12_gives_uint16_lines(tmp_path, emulator):
    (tmp_path / "frames").mkdir()
    write_image(tmp_path / "frames" / "f.png", rendered(64, ball_lines=(32.0,)))
    src = open_source(f"pylon:{emulator}", CAM, pfs=feature_file(tmp_path / "emu.pfs", tmp_path / "frames", 64), pixel_format="Mono12")
    src.frames = 2
    chunks = [(c.lines.dtype, c.lines.shape, int(c.lines.max())) for c in src]
    assert src.max_dn == 4095
    assert all(dt == np.uint16 and shape == (64, 512) and 255 < top <= 4095 for dt, shape, top in chunks)


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"pylon_timestamps": "chunk"}, "pylon:0815-0000: the camera has no writable ChunkSelector to set to 'Timestamp' (--pylon-timestamps chunk)"),
        ({"pylon_timestamps": "grab"}, "pylon:0815-0000: frame 1 starts at 0 s, not after the previous frame's last line"),
    ],
)
def test_emulated_camera_without_a_clock_refuses_camera_timestamps(tmp_path, emulator, options, message):
    (tmp_path / "frames").mkdir()
    write_image(tmp_path / "frames" / "f.png", rendered(64, ball_lines=()))
    src = open_source(f"pylon:{emulator}", CAM, pfs=feature_file(tmp_path / "emu.pfs", tmp_path / "frames", 64), **options)
    src.frames = 3
    with pytest.raises(SourceError) as info:
        list(src)
    assert str(info.value).startswith(message) and "\n" not in str(info.value)


def test_an_unknown_serial_number_lists_the_cameras_found(emulator):
    with pytest.raises(SourceError, match=rf"^pylon:nope: no Basler camera with serial number nope \(found: .*{emulator}.*\)$"):
        next(iter(open_source("pylon:nope", CAM)))


def test_a_bad_feature_file_is_a_one_line_error_naming_it(tmp_path, emulator):
    bad = tmp_path / "bad.pfs"
    bad.write_text("Width\t512\n")  # no GenApi header
    src = open_source(f"pylon:{emulator}", CAM, pfs=bad)
    with pytest.raises(SourceError) as info:
        next(iter(src))
    msg = str(info.value)
    assert msg.startswith(f"{bad}: cannot load this pylon feature file into pylon:{emulator} (") and "\n" not in msg
