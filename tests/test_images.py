"""Tests of ballscan.measure.images: loading line-scan images and timestamps."""

from __future__ import annotations

import struct
import zlib
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest
import tifffile

from ballscan.errors import ImageFileError
from ballscan.measure.images import LineImage, load_image, load_timestamps

SCENES = Path(__file__).parent / "data" / "scenes"


def _grey(dtype, shape=(7, 11), top=None):
    top = np.iinfo(dtype).max if top is None else top
    rng = np.random.default_rng(3)
    return rng.integers(0, top + 1, size=shape).astype(dtype)


# ---------------------------------------------------------------- round trips
@pytest.mark.parametrize("dtype", [np.uint8, np.uint16])
@pytest.mark.parametrize("ext", ["png", "tif"])
def test_grey_round_trip(tmp_path, dtype, ext):
    a = _grey(dtype)
    p = tmp_path / f"img.{ext}"
    if ext == "png":
        iio.imwrite(p, a)
    else:
        tifffile.imwrite(p, a)
    im = load_image(p)
    assert isinstance(im, LineImage)
    assert im.data.dtype == np.float64
    assert im.data.shape == a.shape
    np.testing.assert_array_equal(im.data, a)
    assert im.bits == (8 if dtype == np.uint8 else 16)
    assert im.saturation_dn == float(np.iinfo(dtype).max)
    assert im.source == str(p)


@pytest.mark.parametrize("ext", ["png", "tif"])
def test_twelve_bit_in_sixteen_kept_as_stored(tmp_path, ext):
    a = _grey(np.uint16, top=4095)
    a[0, 0] = 4095
    p = tmp_path / f"img12.{ext}"
    (iio.imwrite if ext == "png" else tifffile.imwrite)(p, a)
    im = load_image(p, saturation_dn=4095)
    np.testing.assert_array_equal(im.data, a)
    assert im.data.max() == 4095
    assert im.saturation_dn == 4095.0
    assert load_image(p).saturation_dn == 65535.0


@pytest.mark.parametrize("ext", ["png", "tif"])
@pytest.mark.parametrize("channels", [3, 4])
def test_rgb_to_rec601_luma(tmp_path, ext, channels):
    a = _grey(np.uint8, shape=(5, 6, channels))
    p = tmp_path / f"rgb.{ext}"
    if ext == "png":
        iio.imwrite(p, a)
    else:
        tifffile.imwrite(p, a, photometric="rgb")
    im = load_image(p)
    expect = 0.299 * a[..., 0] + 0.587 * a[..., 1] + 0.114 * a[..., 2]
    assert im.data.shape == (5, 6)
    np.testing.assert_allclose(im.data, expect, atol=1e-9)


def test_rgb16_tiff_luma(tmp_path):
    a = _grey(np.uint16, shape=(4, 5, 3))
    p = tmp_path / "rgb16.tif"
    tifffile.imwrite(p, a, photometric="rgb")
    im = load_image(p)
    assert im.bits == 16
    np.testing.assert_allclose(im.data, a.astype(float) @ [0.299, 0.587, 0.114], atol=1e-9)


@pytest.mark.parametrize("ext", ["png", "tif"])
def test_lines_as_columns_transposes(tmp_path, ext):
    a = _grey(np.uint8, shape=(4, 9))
    p = tmp_path / f"t.{ext}"
    (iio.imwrite if ext == "png" else tifffile.imwrite)(p, a)
    im = load_image(p, lines_as_columns=True)
    assert im.data.shape == (9, 4)
    np.testing.assert_array_equal(im.data, a.T)


def test_reference_scene_loads():
    im = load_image(SCENES / "pub_two_close.png")
    assert im.data.shape == (300, 2048)
    assert im.bits == 8
    clean = load_image(SCENES / "clean" / "pub_two_close.png")
    assert clean.bits == 16 and clean.data.max() > 255


def test_format_decided_by_content_not_extension(tmp_path):
    a = _grey(np.uint8)
    p = tmp_path / "really_a_tiff.png"
    tifffile.imwrite(p, a)
    np.testing.assert_array_equal(load_image(p).data, a)


# ---------------------------------------------------------------- bad files
def _png_bytes(a: np.ndarray) -> bytes:
    import io

    buf = io.BytesIO()
    iio.imwrite(buf, a, extension=".png")
    return buf.getvalue()


def _chunk(ctype: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + ctype + data + struct.pack(">I", zlib.crc32(ctype + data) & 0xFFFFFFFF)


def _assert_error(p: Path, **kw) -> ImageFileError:
    with pytest.raises(ImageFileError) as ei:
        load_image(p, **kw)
    msg = str(ei.value)
    assert p.name in msg
    assert "\n" not in msg
    return ei.value


def test_missing_file(tmp_path):
    e = _assert_error(tmp_path / "nope.png")
    assert "no such file" in str(e)


def test_empty_file(tmp_path):
    p = tmp_path / "empty.png"
    p.write_bytes(b"")
    assert "empty" in str(_assert_error(p))


def test_unknown_format(tmp_path):
    p = tmp_path / "notes.png"
    p.write_text("hello, not an image\n")
    assert "unknown image format" in str(_assert_error(p))


def test_truncated_png(tmp_path):
    raw = _png_bytes(_grey(np.uint8, shape=(40, 50)))
    p = tmp_path / "trunc.png"
    p.write_bytes(raw[: len(raw) // 2])
    assert "truncated" in str(_assert_error(p))


def test_png_without_iend_is_truncated(tmp_path):
    raw = _png_bytes(_grey(np.uint8, shape=(8, 8)))
    p = tmp_path / "noend.png"
    p.write_bytes(raw[:-12])  # drop the IEND chunk exactly
    assert "truncated" in str(_assert_error(p))


def test_png_flipped_byte_is_reported_not_decoded(tmp_path):
    raw = bytearray(_png_bytes(_grey(np.uint8, shape=(40, 50))))
    idat = raw.index(b"IDAT")
    raw[idat + 4 + 10] ^= 0x01  # one bit inside the compressed pixel data
    p = tmp_path / "crc.png"
    p.write_bytes(bytes(raw))
    e = _assert_error(p)
    assert "CRC" in str(e) and "IDAT" in str(e)


def test_png_header_decompression_bomb_refused(tmp_path):
    # IHDR claims 100000 x 100000 8-bit grey; the data is a tiny valid zlib stream.
    ihdr = struct.pack(">IIBBBBB", 100_000, 100_000, 8, 0, 0, 0, 0)
    raw = (
        b"\x89PNG\r\n\x1a\n"
        + _chunk(b"IHDR", ihdr)
        + _chunk(b"IDAT", zlib.compress(b"\x00" * 1000))
        + _chunk(b"IEND", b"")
    )
    p = tmp_path / "bomb.png"
    p.write_bytes(raw)
    e = _assert_error(p)
    assert "100000" in str(e) and "limit" in str(e)


def test_max_pixels_parameter(tmp_path):
    p = tmp_path / "small.png"
    iio.imwrite(p, _grey(np.uint8, shape=(10, 10)))
    _assert_error(p, max_pixels=99)
    assert load_image(p, max_pixels=100).data.shape == (10, 10)


def test_tiff_bomb_refused(tmp_path):
    p = tmp_path / "big.tif"
    a = _grey(np.uint8, shape=(20, 30))
    tifffile.imwrite(p, a)
    e = _assert_error(p, max_pixels=100)
    assert "limit" in str(e)


def test_three_d_tiff(tmp_path):
    p = tmp_path / "vol.tif"
    tifffile.imwrite(p, _grey(np.uint8, shape=(3, 10, 12)), photometric="minisblack")
    _assert_error(p)


def test_one_d_tiff(tmp_path):
    p = tmp_path / "line.tif"
    tifffile.imwrite(p, np.arange(10, dtype=np.uint8))
    _assert_error(p)


def test_one_line_png(tmp_path):
    p = tmp_path / "oneline.png"
    iio.imwrite(p, _grey(np.uint8, shape=(1, 30)))
    assert "at least 2 lines" in str(_assert_error(p))


def test_truncated_tiff(tmp_path):
    p = tmp_path / "trunc.tif"
    tifffile.imwrite(p, _grey(np.uint16, shape=(100, 100)))
    raw = p.read_bytes()
    p.write_bytes(raw[: len(raw) // 2])
    _assert_error(p)


def test_float_tiff_refused(tmp_path):
    p = tmp_path / "float.tif"
    tifffile.imwrite(p, np.ones((5, 5), dtype=np.float32))
    assert "unsupported" in str(_assert_error(p))


def test_bad_saturation(tmp_path):
    p = tmp_path / "ok.png"
    iio.imwrite(p, _grey(np.uint8))
    _assert_error(p, saturation_dn=-1.0)


# ---------------------------------------------------------------- timestamps
def test_timestamps_text_and_npy(tmp_path):
    t = np.arange(5) * 1e-4 + 0.5
    txt = tmp_path / "t.txt"
    txt.write_text("# seconds\n" + "\n".join(repr(float(v)) for v in t) + "\n")
    np.testing.assert_array_equal(load_timestamps(txt, 5), t)
    npy = tmp_path / "t.npy"
    np.save(npy, t)
    np.testing.assert_array_equal(load_timestamps(npy, 5), t)


@pytest.mark.parametrize(
    "content, n, word",
    [
        ("0.1\n0.2\n0.3\n", 4, "3 timestamps"),
        ("0.1\n0.1\n0.3\n", 3, "strictly increasing"),
        ("0.3\n0.2\n0.4\n", 3, "strictly increasing"),
        ("0.1\nnan\n0.3\n", 3, "not finite"),
        ("0.1\nabc\n0.3\n", 3, "not a number"),
        ("", 3, "no timestamps"),
    ],
)
def test_timestamps_errors(tmp_path, content, n, word):
    p = tmp_path / "stamps.txt"
    p.write_text(content)
    with pytest.raises(ImageFileError) as ei:
        load_timestamps(p, n)
    assert "stamps.txt" in str(ei.value) and word in str(ei.value)


def test_timestamps_npy_errors(tmp_path):
    p = tmp_path / "stamps.npy"
    np.save(p, np.zeros((3, 3)))
    with pytest.raises(ImageFileError, match="stamps.npy"):
        load_timestamps(p, 3)
    with pytest.raises(ImageFileError, match="missing.txt"):
        load_timestamps(tmp_path / "missing.txt", 3)


# ---------------------------------------------------------------- strict decoding (declared size, palettes, limits)
def _raw_png(width, height, depth, colour, rows: bytes, *, plte: bytes | None = None, extra: tuple = (), interlace: int = 0) -> bytes:
    out = b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, colour, 0, 0, interlace))
    if plte is not None:
        out += _chunk(b"PLTE", plte)
    for ctype, body in extra:
        out += _chunk(ctype, body)
    return out + _chunk(b"IDAT", zlib.compress(rows)) + _chunk(b"IEND", b"")


def _rows(width, height, value=7) -> bytes:
    return (b"\x00" + bytes([value]) * width) * height


def test_png_with_less_data_than_its_header_declares_is_refused_not_padded(tmp_path):
    p = tmp_path / "short.png"
    p.write_bytes(_raw_png(64, 20_000, 8, 0, _rows(64, 220)))  # 20,000 lines declared, 220 in the data
    e = _assert_error(p)
    assert "truncated" in str(e) and "220 of 20000 lines" in str(e)


def test_png_with_more_data_than_declared_is_refused(tmp_path):
    p = tmp_path / "long.png"
    p.write_bytes(_raw_png(64, 10, 8, 0, _rows(64, 11)))
    assert "more image data" in str(_assert_error(p))


def test_png_whose_data_stream_is_cut_is_refused(tmp_path):
    rows = zlib.compress(bytes(range(256)) * 100)[:-30]
    raw = b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", struct.pack(">IIBBBBB", 255, 100, 8, 0, 0, 0, 0)) + _chunk(b"IDAT", rows) + _chunk(b"IEND", b"")
    p = tmp_path / "cut.png"
    p.write_bytes(raw)
    assert "truncated" in str(_assert_error(p))


def test_interlaced_png_of_the_declared_size_loads(tmp_path):
    a = _grey(np.uint8, shape=(13, 21))
    rows = b""
    for x0, y0, dx, dy in ((0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)):
        sub = a[y0::dy, x0::dx]
        if sub.size:
            rows += b"".join(b"\x00" + line.tobytes() for line in sub)
    p = tmp_path / "adam7.png"
    p.write_bytes(_raw_png(21, 13, 8, 0, rows, interlace=1))
    np.testing.assert_array_equal(load_image(p).data, a)
    p.write_bytes(_raw_png(21, 13, 8, 0, rows[:-22], interlace=1))  # its last line missing
    assert "truncated" in str(_assert_error(p))


def _palette_rows(width, height, index) -> bytes:
    return (b"\x00" + bytes([index]) * width) * height


@pytest.mark.parametrize(
    "plte,index,word",
    [
        (None, 0, "without a PLTE"),  # missing palette
        (bytes(7), 0, "7 bytes"),  # not whole entries
        (bytes(12), 9, "index 9 beyond its palette of 4"),  # 4 entries, pixels use index 9
        (bytes(3 * 257), 0, "771 bytes"),
    ],
)
def test_invalid_palette_png_refused(tmp_path, plte, index, word):
    p = tmp_path / "pal.png"
    p.write_bytes(_raw_png(16, 8, 8, 3, _palette_rows(16, 8, index), plte=plte))
    assert word in str(_assert_error(p))


def test_valid_small_palette_png_loads(tmp_path):
    plte = bytes([0, 0, 0, 100, 100, 100, 200, 200, 200, 255, 255, 255])
    p = tmp_path / "pal4.png"
    p.write_bytes(_raw_png(16, 8, 8, 3, _palette_rows(16, 8, 2), plte=plte))
    np.testing.assert_allclose(load_image(p).data, 200.0)


def test_palette_in_a_grey_png_refused(tmp_path):
    p = tmp_path / "greypal.png"
    p.write_bytes(_raw_png(16, 8, 8, 0, _rows(16, 8), plte=bytes(12)))
    assert "grey image" in str(_assert_error(p))


def test_png_over_the_limit_refused_from_its_header_before_the_rest_is_read(tmp_path, monkeypatch):
    p = tmp_path / "huge.png"
    p.write_bytes(_raw_png(16_384, 16_385, 8, 0, b""))
    import ballscan.measure.images as images

    def no_walk(*_):
        raise AssertionError("the chunks were read")

    monkeypatch.setattr(images, "_check_png", no_walk)
    e = _assert_error(p, max_pixels=16_384 * 16_384)
    assert "limit" in str(e)


def test_png_much_larger_than_its_pixels_refused_unread(tmp_path):
    p = tmp_path / "padded.png"
    p.write_bytes(_raw_png(8, 8, 8, 0, _rows(8, 8), extra=((b"tEXt", b"k\x00" + bytes(17 << 20)),)))
    assert "more than a PNG of 8 lines x 8 pixels can hold" in str(_assert_error(p))


def test_image_at_the_pixel_limit_loads(tmp_path):
    p = tmp_path / "at.png"
    iio.imwrite(p, _grey(np.uint8, shape=(10, 10)))
    assert load_image(p, max_pixels=100).data.shape == (10, 10)
    t = tmp_path / "at_rgb.tif"
    tifffile.imwrite(t, _grey(np.uint8, shape=(10, 10, 3)), photometric="rgb")
    assert load_image(t, max_pixels=100).data.shape == (10, 10)


def test_tiff_limit_counts_pixels_not_samples(tmp_path):
    # 3 x 40 = 120 pixels: over a limit of 100 pixels, though 120 samples are under 4 x 100
    p = tmp_path / "grey.tif"
    tifffile.imwrite(p, _grey(np.uint8, shape=(3, 40)))
    assert "120 pixels" in str(_assert_error(p, max_pixels=100))
    rgb = tmp_path / "rgb.tif"
    tifffile.imwrite(rgb, _grey(np.uint8, shape=(3, 40, 3)), photometric="rgb")
    assert "120 pixels" in str(_assert_error(rgb, max_pixels=100))


@pytest.mark.parametrize("ext", ["png", "tif"])
def test_running_out_of_memory_is_a_refusal_naming_the_file(tmp_path, monkeypatch, ext):
    p = tmp_path / f"img.{ext}"
    iio.imwrite(p, _grey(np.uint8, shape=(30, 20)))
    real_array = np.array

    def no_memory(obj, *a, **kw):
        if hasattr(obj, "getim") or hasattr(obj, "keyframe"):  # a decoded Pillow image, or a TIFF page
            raise MemoryError
        return real_array(obj, *a, **kw)

    import tifffile as tf

    monkeypatch.setattr(np, "array", no_memory)
    monkeypatch.setattr(tf.TiffPage, "asarray", lambda *a, **k: (_ for _ in ()).throw(MemoryError()))
    assert "not enough memory" in str(_assert_error(p))


def test_timestamps_files_far_too_large_are_refused_unread(tmp_path):
    p = tmp_path / "t.txt"
    p.write_text("0.0\n" * 400_000)
    with pytest.raises(ImageFileError, match="more than 10 timestamps can take"):
        load_timestamps(p, 10)
    n = tmp_path / "t.npy"
    np.save(n, np.arange(1000.0))
    with pytest.raises(ImageFileError, match="1000 timestamps for an image of 10 lines"):
        load_timestamps(n, 10)


def test_png_sample_bytes_is_what_read_stored_gives(tmp_path):
    from PIL import Image

    from ballscan.measure.images import png_sample_bytes, read_stored

    rng = np.random.default_rng(5)
    grey8 = rng.integers(0, 256, (30, 40), dtype=np.uint8)
    cases = {
        "g8.png": Image.fromarray(grey8),
        "g16.png": Image.fromarray(rng.integers(0, 65536, (30, 40), dtype=np.uint16)),
        "rgb.png": Image.fromarray(rng.integers(0, 256, (30, 40, 3), dtype=np.uint8)),
        "pal.png": Image.fromarray(grey8).convert("P"),
    }
    for name, im in cases.items():
        im.save(tmp_path / name)
        got, stored = png_sample_bytes(tmp_path / name), read_stored(tmp_path / name).data.nbytes
        # a palette is counted as RGBA (its transparency is not in the header)
        assert got == (stored * 4 // 3 if name == "pal.png" else stored), (name, got, stored)
    (tmp_path / "bad.png").write_bytes(b"\x89PNG\r\n\x1a\n but no image")
    assert png_sample_bytes(tmp_path / "bad.png") == png_sample_bytes(tmp_path / "missing.png") == 0
