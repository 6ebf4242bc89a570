"""Hostile inputs, fuzzed: camera files, PNG/TIFF headers and chunks, command-line values.

Every case ends in a result or a one-line :class:`~ballscan.errors.BallscanError`
(or the command line's one-line error, exit status 2), within a time limit,
and no output holds a non-finite number.  Seeded (derandomized) hypothesis
runs: the same cases on every run.
"""

from __future__ import annotations

import io
import json
import math
import re
import signal
import struct
import zlib
from contextlib import contextmanager

import numpy as np
import pytest
import tifffile
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from ballscan.cli.app import main
from ballscan.errors import BallscanError, CameraFileError, ImageFileError
from ballscan.geometry.camera import LineScanCamera, load_camera
from ballscan.measure.images import line_image, read_stored

from .conftest import DATA

def fuzz(n: int) -> settings:
    """Seeded settings of ``n`` cases (the same cases every run)."""
    return settings(max_examples=n, derandomize=True, deadline=None, database=None, suppress_health_check=list(HealthCheck))
#: Seconds any one case may take: a case over it is a hang.
CASE_LIMIT_S = 60


@contextmanager
def time_limit(seconds: int = CASE_LIMIT_S):
    """Fail a case that runs longer than ``seconds`` (SIGALRM; the suite runs on POSIX)."""

    def hang(*_):
        raise AssertionError(f"no result within {seconds} s: a hang")

    old = signal.signal(signal.SIGALRM, hang)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def _one_line_error(exc: BaseException, name: str) -> None:
    msg = str(exc)
    assert isinstance(exc, BallscanError), f"{type(exc).__name__}: {msg}"
    assert msg and "\n" not in msg and name in msg, msg


# ------------------------------------------------------------------ camera files
VALID = {"width": 2048, "focal_px": 2500.0, "principal_px": 1023.5, "line_rate_hz": 70000.0}
KEYS = ["width", "focal_px", "principal_px", "line_rate_hz", "exposure_s", "k1", "k2", "crossing", "gravity_mps2", "pose", "extra"]
WILD_NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0.0, -0.0, 1e-300, 1e300, -1e300, 1e8, 1e-9, 2.0**63, 5e-324]),
    st.integers(min_value=-(2**70), max_value=2**70),
)


def _toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, str):
        return json.dumps(v)
    return "[" + ", ".join(_toml_value(x) for x in v) + "]"


TOML_VALUES = st.recursive(
    st.one_of(WILD_NUMBERS, st.booleans(), st.text(max_size=8)),
    lambda inner: st.lists(inner, max_size=4),
    max_leaves=10,
)


@st.composite
def camera_texts(draw) -> str:
    """A camera file: the valid one with some keys replaced by wild values, a deep nest, or bytes flipped and cut."""
    d = dict(VALID)
    for key in draw(st.lists(st.sampled_from(KEYS), max_size=4)):
        d[key] = draw(TOML_VALUES)
    text = "".join(f"{k} = {_toml_value(v)}\n" for k, v in d.items() if k != "pose")
    if "pose" in d or draw(st.booleans()):
        rot = draw(st.one_of(st.just([[1, 0, 0], [0, 1, 0], [0, 0, 1]]), st.lists(st.lists(WILD_NUMBERS, min_size=3, max_size=3), min_size=3, max_size=3)))
        text += f"[pose]\nrotation = {_toml_value(rot)}\ntranslation = {_toml_value(draw(st.lists(WILD_NUMBERS, min_size=3, max_size=3)))}\n"
    if draw(st.integers(0, 9)) == 0:
        depth = draw(st.integers(100, 6000))
        text += "nest = " + "[" * depth + "]" * depth + "\n"
    raw = bytearray(text.encode())
    for _ in range(draw(st.integers(0, 3))):
        pos = draw(st.integers(0, len(raw) - 1))
        raw[pos] = draw(st.integers(0, 255))
    if draw(st.booleans()):
        raw = raw[: draw(st.integers(0, len(raw)))]
    return bytes(raw)


@fuzz(400)
@given(camera_texts())
def test_fuzzed_camera_files_load_or_give_one_line_errors(tmp_path_factory, raw):
    p = tmp_path_factory.mktemp("cam") / "fuzz.camera.toml"
    p.write_bytes(raw)
    with time_limit(10):
        try:
            cam = load_camera(p)
        except CameraFileError as exc:
            _one_line_error(exc, str(p))
            return
    assert isinstance(cam, LineScanCamera)
    for v in (cam.width, cam.focal_px, cam.principal_px, cam.line_rate_hz, cam.exposure, cam.k1, cam.k2):
        assert math.isfinite(v)
    assert 1e-3 <= cam.line_rate_hz <= 1e8 and 1 <= cam.focal_px <= 1e7


# ------------------------------------------------------------------ images
def _chunk(ctype: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + ctype + data + struct.pack(">I", zlib.crc32(ctype + data) & 0xFFFFFFFF)


def _png(width: int, height: int, depth: int, colour: int, rows: bytes, plte: bytes | None, interlace: int) -> bytes:
    out = b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, interlace))
    if plte is not None:
        out += _chunk(b"PLTE", plte)
    return out + _chunk(b"IDAT", zlib.compress(rows)) + _chunk(b"IEND", b"")


@st.composite
def png_files(draw) -> bytes:
    """A PNG: valid ones (every colour type and depth ballscan reads), the same with one byte flipped or the file cut, and wild headers, palettes and data lengths behind valid CRCs (the checks past the CRC are reached)."""
    kind = draw(st.integers(0, 9))
    if kind < 6:
        colour, depth = draw(st.sampled_from([(0, 8), (0, 16), (2, 8), (3, 8), (3, 4), (3, 2), (3, 1), (4, 8), (6, 8)]))
        width, height, interlace, offset = draw(st.integers(2, 40)), draw(st.integers(2, 40)), draw(st.sampled_from([0, 0, 1])), 0
    else:
        width = draw(st.one_of(st.integers(0, 40), st.sampled_from([2**31 - 1, 2**32 - 1, 70_000])))
        height = draw(st.one_of(st.integers(0, 40), st.sampled_from([2**31 - 1, 20_000, 2**32 - 1])))
        colour, depth = draw(st.sampled_from([0, 2, 3, 4, 6, 1, 5])), draw(st.sampled_from([8, 16, 1, 2, 4, 0, 3]))
        interlace, offset = draw(st.sampled_from([0, 1, 2])), draw(st.sampled_from([0, -1, 1, -5]))
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}.get(colour, 1)
    bits = channels * max(depth, 1)
    passes = ((0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)) if interlace == 1 else ((0, 0, 1, 1),)
    rows = b""
    for x0, y0, dx, dy in passes:
        w, h = -(-max(min(width, 64) - x0, 0) // dx), -(-max(min(height, 40) - y0, 0) // dy)
        if w and h:
            line = bytes([draw(st.integers(0, 4))]) + draw(st.binary(min_size=(w * bits + 7) // 8, max_size=(w * bits + 7) // 8))
            if colour == 3:
                line = line[:1] + bytes(0 if depth < 8 else b % 2 for b in line[1:])  # indices inside a palette of 2
            rows += line * h
    n_lines = max(min(height, 40), 1)
    rows = rows[: max(len(rows) + offset * (len(rows) // n_lines), 0)] + (rows[: len(rows) // n_lines] if offset > 0 else b"")
    good_plte = st.integers(2, 2 ** min(max(depth, 1), 8)).map(lambda n: bytes(range(n)) * 3) if colour == 3 else st.none()
    wild_plte = st.one_of(st.none(), st.binary(min_size=1, max_size=30).map(lambda b: b * 3), st.binary(min_size=3, max_size=800))
    plte = draw(good_plte if kind < 6 else st.one_of(good_plte, wild_plte))
    raw = bytearray(_png(width, height, depth, colour, rows, plte, interlace))
    if kind in (4, 8):
        for _ in range(draw(st.integers(1, 4))):
            raw[draw(st.integers(0, len(raw) - 1))] = draw(st.integers(0, 255))
    elif kind in (5, 9):
        raw = raw[: draw(st.integers(0, len(raw)))]
    return bytes(raw)


@st.composite
def tiff_files(draw) -> bytes:
    """A small TIFF (grey, RGB, compressed or not) with header and directory bytes overwritten or the file cut."""
    shape = draw(st.sampled_from([(12, 16), (3, 40), (12, 16, 3), (5, 5, 4)]))
    dtype = draw(st.sampled_from([np.uint8, np.uint16]))
    buf = io.BytesIO()
    kw = {"photometric": "rgb"} if len(shape) == 3 else {"photometric": "minisblack"}
    tifffile.imwrite(buf, np.arange(np.prod(shape), dtype=dtype).reshape(shape), compression=draw(st.sampled_from([None, "zlib"])), **kw)
    raw = bytearray(buf.getvalue())
    for _ in range(draw(st.integers(0, 6))):
        pos = draw(st.integers(0, min(len(raw), 400) - 1))
        raw[pos] = draw(st.one_of(st.integers(0, 255), st.sampled_from([0xFF, 0x7F, 0x00])))
    if draw(st.integers(0, 3)) == 0:
        raw = raw[: draw(st.integers(0, len(raw)))]
    return bytes(raw)


def _load(p):
    stored = read_stored(p, max_pixels=10_000_000)
    return line_image(stored)


@fuzz(500)
@given(st.one_of(png_files(), tiff_files()))
def test_fuzzed_images_load_or_give_one_line_errors(tmp_path_factory, raw):
    p = tmp_path_factory.mktemp("img") / "fuzz.img"
    p.write_bytes(raw)
    with time_limit(10):
        try:
            img = _load(p)
        except ImageFileError as exc:
            _one_line_error(exc, str(p))
            return
    assert img.data.ndim == 2 and min(img.data.shape) >= 2
    assert np.all(np.isfinite(img.data)) and img.data.min() >= 0 and img.data.max() <= 2**img.bits - 1
    if raw[:4] == b"\x89PNG":
        width, height = struct.unpack(">II", raw[16:24])
        assert img.data.shape == (height, width)  # never padded, never cut


# ------------------------------------------------------------------ the command line
NON_FINITE = re.compile(r"\b(nan|inf|infinity)\b", re.IGNORECASE)
NUMBER_TEXT = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.sampled_from(["0", "-1", "1e308", "-1e308", "1e-320", "37", "nan", "inf", "-inf", "1e6", "0.0335", "abc", ""]),
)


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    folder = tmp_path_factory.mktemp("scene")
    assert main(["simulate", "--preset", "table-tennis", "--out", str(folder / "s"), "--seed", "2"]) == 0
    return folder / "s"


def _run(capsys, args) -> tuple[int, str, str]:
    with time_limit():
        code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


def _without_compile_notice(err: str) -> list[str]:
    """``err``'s lines less the kernels' one-time compile notice (printed by whichever command runs first after an install)."""
    lines = err.strip().splitlines()
    first = next((i for i, line in enumerate(lines) if line.startswith("ballscan: compiling ")), None)
    if first is None:
        return lines
    last = next(i for i, line in enumerate(lines) if line.startswith("ballscan: kernels ready"))
    return lines[:first] + lines[last + 1 :]


def _check_output(code: int, out: str, err: str) -> None:
    """Exit 0, or 2 with one line of ours (or the parser's usage block); warnings one line each; no traceback, no non-finite number."""
    assert code in (0, 2), (code, err)
    assert "Traceback" not in err and "Traceback" not in out
    if out.startswith("{"):  # JSON: every number finite (words in its texts may say "inf")
        json.loads(out, parse_constant=lambda c: pytest.fail(f"non-finite {c} in the JSON"))
    else:
        assert not NON_FINITE.search(out), out
    errors = [line for line in _without_compile_notice(err) if not line.startswith("ballscan: warning: ")]
    if code == 2 and "Usage:" not in err:
        assert len(errors) == 1 and errors[0].startswith("ballscan: error: "), err
    if code == 0:
        assert errors == [], err


@fuzz(60)
@given(radius=st.one_of(NUMBER_TEXT, st.floats(1e-5, 1e4).map(repr)), saturation=st.one_of(st.none(), NUMBER_TEXT), max_pixels=st.one_of(st.none(), st.sampled_from(["1", "0", "-5", "100", "2147483648", "x"])), as_json=st.booleans())
def test_fuzzed_estimate_values(scene, capsys, radius, saturation, max_pixels, as_json):
    args = ["estimate", f"{scene}.png", "--camera", f"{scene}.camera.toml", "--radius", radius]
    args += ["--saturation", saturation] if saturation is not None else []
    args += ["--max-pixels", max_pixels] if max_pixels is not None else []
    args += ["--json"] if as_json else []
    code, out, err = _run(capsys, args)
    _check_output(code, out, err)
    if code == 0 and as_json:
        json.loads(out, parse_constant=lambda c: pytest.fail(f"non-finite {c} in the JSON"))


@fuzz(100)
@given(
    what=st.sampled_from(["--radius", "--position", "--velocity", "--t-c", "--lines", "--bits", "--ball-level", "--background", "--seed"]),
    value=NUMBER_TEXT,
    triple=st.tuples(NUMBER_TEXT, NUMBER_TEXT, NUMBER_TEXT),
    noise=st.sampled_from(["default", "none"]),
)
def test_fuzzed_simulate_values(tmp_path_factory, capsys, what, value, triple, noise):
    folder = tmp_path_factory.mktemp("sim")
    if what in ("--position", "--velocity"):
        value = ",".join(triple)
    if what == "--lines":
        value = str(min(abs(int(float(value))) if re.fullmatch(r"-?\d+(\.\d+)?(e\d+)?", value) and math.isfinite(float(value)) else 5, 10**9))
    code, out, err = _run(capsys, ["simulate", "--preset", "table-tennis", what, value, "--noise", noise, "--out", folder / "s"])
    _check_output(code, out, err)
    if code != 0:
        assert not (folder / "s.truth.json").exists()
        return
    truth = json.loads((folder / "s.truth.json").read_text(), parse_constant=lambda c: pytest.fail(f"non-finite {c} in the truth"))
    assert math.isfinite(truth["speed_mps"])


# ------------------------------------------------------------------ cameras at the ends of their ranges
SCENE = DATA / "scenes" / "pub_pingpong"


@pytest.mark.parametrize(
    "change",
    [
        {"line_rate_hz": 1e8},
        {"line_rate_hz": 1e-3},
        {"focal_px": 1e7},
        {"focal_px": 1.0},
        {"principal_px": -100 * 1024.0},
        {"principal_px": 101 * 1024.0},
        {"k1": 1e6},
        {"k2": 1e6},
        {"exposure_s": 1e-10},
    ],
    ids=lambda c: ",".join(f"{k}={v:g}" for k, v in c.items()),
)
def test_estimate_on_cameras_at_the_ends_of_their_ranges_is_bounded_and_finite(tmp_path, capsys, change):
    import tomllib

    import tomli_w

    d = tomllib.loads((SCENE.parent / f"{SCENE.name}.camera.toml").read_text())
    d.pop("exposure_s", None)
    d.update(change)
    cam = tmp_path / "edge.camera.toml"
    cam.write_text(tomli_w.dumps(d))
    code, out, err = _run(capsys, ["estimate", f"{SCENE}.png", "--camera", cam, "--radius", "0.02", "--json"])
    _check_output(code, out, err)
    if code == 0:
        json.loads(out, parse_constant=lambda c: pytest.fail(f"non-finite {c} in the JSON"))
