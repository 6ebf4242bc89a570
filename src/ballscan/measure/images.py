"""Loading line-scan images and per-line timestamps (geometry.md, "Images").

A line-scan image is a 2-D array of shape ``(n_lines, W)``: row ``i`` is scan
line ``i``, column ``j`` is sensor pixel ``j``. Values are kept as stored (a
12-bit camera's data in a 16-bit file stays 0..4095); the saturation level is
the type's maximum unless the caller overrides it.

Accepted files
--------------
* PNG, 8- or 16-bit grey, 8-bit grey+alpha, 8-bit RGB(A) or palette. 16-bit
  colour PNGs are refused because the decoder (Pillow) would silently reduce
  them to 8 bits; save those as 16-bit grey PNG or as TIFF.
* TIFF (one page), ``uint8`` or ``uint16``, grey or RGB(A), contiguous or
  planar samples.
* Colour is converted to grey with the Rec. 601 luma weights
  0.299, 0.587, 0.114; alpha is dropped.
* Floating-point and signed-integer images are refused: the contract is 8-
  or 16-bit data whose saturation level is the type's maximum, and a float
  file has no such level (decision documented here, see geometry.md).

Every problem is reported as one :class:`~ballscan.errors.ImageFileError`
naming the file. The file's format is decided from its magic bytes, not its
extension. Before any pixel data is decoded, the dimensions claimed by the
PNG ``IHDR`` chunk or the TIFF directory are checked against ``max_pixels``
so that a crafted header ("decompression bomb") cannot make us allocate
memory; the limit counts pixels (lines x pixels per line) whatever the
format and samples per pixel, and a PNG's header is read and checked before
the rest of the file.  Every PNG chunk's CRC is verified, so a flipped byte
is reported rather than decoded into wrong pixels; a PNG's compressed data
must decompress to exactly the size its header declares (a truncated file is
refused, never padded), and a palette image must have one valid palette
(1 to 256 entries of 3 bytes, none in a grey image) that every pixel's
index lies in.  A decoder that runs out of memory below the limit is a
refusal naming the file, not a ``MemoryError``.
"""

from __future__ import annotations

import io
import os
import struct
import warnings
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import ImageFileError

__all__ = ["LineImage", "StoredImage", "as_line_image", "line_image", "load_image", "load_timestamps", "read_stored", "png_sample_bytes", "DEFAULT_MAX_PIXELS"]

#: Default refusal limit on ``n_lines * W`` (about 268 million pixels, 2 GiB
#: as float64): far above any real line-scan capture, far below what a forged
#: header can claim.
DEFAULT_MAX_PIXELS = 2**28

_PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
_TIFF_MAGICS = (b"II*\x00", b"MM\x00*", b"II+\x00", b"MM\x00+")
_LUMA = np.array([0.299, 0.587, 0.114])


@dataclass(frozen=True)
class LineImage:
    """A line-scan image as stored in its file.

    Attributes
    ----------
    data : numpy.ndarray
        float64, shape ``(n_lines, W)``; row = scan line, column = sensor
        pixel. Digital numbers (DN) as stored, e.g. 0..255 or 0..4095.
    saturation_dn : float
        Level (DN) at or above which a pixel is clipped: the dtype's maximum
        (255 or 65535) unless overridden when loading.
    bits : int
        Bits per sample of the file, 8 or 16.
    source : str
        Path of the file (used in messages).
    """

    data: np.ndarray
    saturation_dn: float
    bits: int
    source: str

    def __post_init__(self) -> None:
        if not (isinstance(self.data, np.ndarray) and self.data.ndim == 2):
            raise ValueError(f"LineImage.data: must be a 2-D (n_lines, W) numpy array, got {type(self.data).__name__} of shape {np.shape(self.data)}")
        if not (isinstance(self.saturation_dn, (int, float, np.integer, np.floating)) and not np.isnan(self.saturation_dn)):
            raise ValueError(f"LineImage.saturation_dn: must be a number, got {self.saturation_dn!r}")
        if not (isinstance(self.bits, (int, np.integer)) and not isinstance(self.bits, bool) and 1 <= self.bits <= 32):
            raise ValueError(f"LineImage.bits: must be an integer in [1, 32], got {self.bits!r}")

    @property
    def n_lines(self) -> int:
        """Number of scan lines (rows)."""
        return int(self.data.shape[0])

    @property
    def width(self) -> int:
        """Number of sensor pixels per line (columns)."""
        return int(self.data.shape[1])


# --------------------------------------------------------------------------
# PNG
# --------------------------------------------------------------------------
#: Samples per pixel of each PNG colour type, and the bit depths the PNG specification allows it.
_PNG_CHANNELS = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}
_PNG_DEPTHS = {0: (1, 2, 4, 8, 16), 2: (8, 16), 3: (1, 2, 4, 8), 4: (8, 16), 6: (8, 16)}
#: Adam7's passes: first column, first line, column step, line step.
_ADAM7 = ((0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2))
#: Bytes a PNG may hold beyond its compressed pixels (metadata chunks, zlib's framing) before it is refused unread.
_PNG_SLACK_BYTES = 16 << 20
#: Largest decompressed image data kept to hand to Pillow (:func:`_stored_png`); above it the data is counted piece by piece.
_PNG_KEEP_BYTES = 64 << 20


@dataclass(frozen=True)
class _PngBody:
    """What the chunk walk found: the palette's entries, the bytes before the first IDAT, and the checked image data (None when too large to keep)."""

    palette: int
    head: bytes
    data: bytes | None


@dataclass(frozen=True)
class _PngHeader:
    """A PNG's IHDR: pixels per line, lines, bits per sample, colour type, interlace method."""

    width: int
    height: int
    depth: int
    colour: int
    interlace: int

    def filtered_bytes(self) -> int:
        """Bytes of the decompressed image data the header declares (each line's filter byte included)."""
        bits = _PNG_CHANNELS[self.colour] * self.depth
        passes = _ADAM7 if self.interlace else ((0, 0, 1, 1),)
        total = 0
        for x0, y0, dx, dy in passes:
            w = (self.width - x0 + dx - 1) // dx if self.width > x0 else 0
            h = (self.height - y0 + dy - 1) // dy if self.height > y0 else 0
            if w and h:
                total += h * (1 + (w * bits + 7) // 8)
        return total


def _png_header(head: bytes, src: str, max_pixels: int) -> _PngHeader:
    """The PNG's IHDR from the file's first 33 bytes, checked (size limit in pixels) before anything else is read."""
    if len(head) < 33:
        raise ImageFileError(src, "truncated PNG (no complete IHDR chunk)")
    length, ctype = struct.unpack(">I4s", head[8:16])
    if ctype != b"IHDR" or length != 13:
        raise ImageFileError(src, "corrupt PNG (first chunk is not a valid IHDR)")
    (crc,) = struct.unpack(">I", head[29:33])
    if zlib.crc32(head[12:29]) & 0xFFFFFFFF != crc:
        raise ImageFileError(src, "corrupt PNG (CRC mismatch in IHDR chunk at byte 8)")
    width, height, depth, colour, compression, filtering, interlace = struct.unpack(">IIBBBBB", head[16:29])
    # Refuse before anything is decoded, allocated or even read.
    if width == 0 or height == 0:
        raise ImageFileError(src, f"empty PNG image ({width} x {height} pixels)")
    if width * height > max_pixels:
        raise ImageFileError(
            src, f"PNG header claims {height} lines x {width} pixels = {width * height} pixels, more than the limit of {max_pixels}"
        )
    if colour not in _PNG_CHANNELS or depth not in _PNG_DEPTHS[colour]:
        raise ImageFileError(src, f"corrupt PNG (bit depth {depth} is not allowed for colour type {colour})")
    if compression != 0 or filtering != 0 or interlace not in (0, 1):
        raise ImageFileError(src, f"corrupt PNG (unknown compression {compression}, filter {filtering} or interlace {interlace} method)")
    if depth not in (8, 16) and colour != 3:
        raise ImageFileError(src, f"unsupported PNG bit depth {depth} (need 8 or 16)")
    if depth == 16 and colour != 0:
        raise ImageFileError(src, "16-bit colour or grey+alpha PNG is not supported (save as 16-bit grey PNG or TIFF)")
    return _PngHeader(width, height, depth, colour, interlace)


def _check_png(raw: bytes, src: str, header: _PngHeader) -> _PngBody:
    """Walk the PNG's chunks (CRCs, order, palette) and check that its data decompresses to exactly the declared size."""
    pos = len(_PNG_SIGNATURE) + 25
    n = len(raw)
    idat: list[bytes] = []
    palette = 0
    seen_iend = False
    first_idat = 0
    while pos < n:
        if pos + 8 > n:
            raise ImageFileError(src, "truncated PNG (incomplete chunk header)")
        length, ctype = struct.unpack(">I4s", raw[pos : pos + 8])
        if length > 2**31 - 1:
            raise ImageFileError(src, f"corrupt PNG (chunk length {length} out of range)")
        end = pos + 8 + length + 4
        if end > n:
            raise ImageFileError(src, f"truncated PNG (chunk {ctype!r} runs past the end of the file)")
        body = raw[pos + 4 : pos + 8 + length]
        (crc,) = struct.unpack(">I", raw[pos + 8 + length : end])
        if zlib.crc32(body) & 0xFFFFFFFF != crc:
            name = ctype.decode("latin-1", "replace")
            raise ImageFileError(src, f"corrupt PNG (CRC mismatch in {name} chunk at byte {pos})")
        if ctype == b"IHDR":
            raise ImageFileError(src, "corrupt PNG (a second IHDR chunk)")
        if ctype == b"PLTE":
            palette = _check_palette(length, header, bool(idat), palette, src)
        elif ctype == b"IDAT":
            first_idat = first_idat or pos
            idat.append(body[4:])
        elif ctype == b"IEND":
            seen_iend = True
            break
        pos = end
    if not idat:
        raise ImageFileError(src, "truncated PNG (no image data)")
    if not seen_iend:
        raise ImageFileError(src, "truncated PNG (no IEND chunk)")
    if header.colour == 3 and not palette:
        raise ImageFileError(src, "corrupt PNG (a palette image without a PLTE palette)")
    data = _check_png_data(idat, header, src, keep=header.filtered_bytes() <= _PNG_KEEP_BYTES)
    return _PngBody(palette, raw[:first_idat], data)


def _check_palette(length: int, header: _PngHeader, after_data: bool, seen: int, src: str) -> int:
    """The number of entries of a PLTE chunk of ``length`` bytes, checked against the PNG specification."""
    if header.colour in (0, 4):
        raise ImageFileError(src, "corrupt PNG (a PLTE palette in a grey image)")
    if seen or after_data:
        raise ImageFileError(src, "corrupt PNG (a second PLTE chunk, or one after the image data)")
    if length == 0 or length % 3 or length // 3 > 256:
        raise ImageFileError(src, f"corrupt PNG (a PLTE palette of {length} bytes: need 1 to 256 entries of 3 bytes)")
    entries = length // 3
    if header.colour == 3 and entries > 2**header.depth:
        raise ImageFileError(src, f"corrupt PNG (a palette of {entries} entries for {header.depth}-bit indices)")
    return entries


def _check_png_data(idat: list[bytes], header: _PngHeader, src: str, piece: int = 1 << 24, keep: bool = False) -> bytes | None:
    """The IDAT chunks' zlib stream decompresses to exactly the bytes the header declares (counted piece by piece, in bounded memory).

    With ``keep`` the decompressed data is returned (else None), for Pillow
    to decode without decompressing it again (:func:`_stored_png`).
    """
    expected = header.filtered_bytes()
    d = zlib.decompressobj()
    got = 0
    kept: list[bytes] = []
    try:
        for data in idat:
            while data and got <= expected:
                out = d.decompress(data, piece)
                got += len(out)
                if keep:
                    kept.append(out)
                data = d.unconsumed_tail
            if got > expected or d.eof:
                break
        while not d.eof and got <= expected:  # what the decompressor holds back
            out = d.decompress(b"", piece)
            if not out:
                got += len(d.flush())
                break
            got += len(out)
            if keep:
                kept.append(out)
    except zlib.error as exc:
        raise ImageFileError(src, f"corrupt PNG (image data: {_one_line(exc)})") from None
    if got > expected:
        raise ImageFileError(src, f"corrupt PNG (more image data than the header's {header.height} lines x {header.width} pixels)")
    if got < expected:
        what = "" if header.interlace else f", {got // max(expected // header.height, 1)} of {header.height} lines"
        raise ImageFileError(src, f"truncated PNG (image data holds {got} of the {expected} bytes its header declares{what})")
    if not d.eof:
        raise ImageFileError(src, "truncated PNG (the compressed image data does not end)")
    return b"".join(kept) if keep else None


def _stored_png(head: bytes, data: bytes) -> bytes:
    """A PNG of the chunks ``head`` (signature to the first IDAT) and the checked image ``data`` in stored (uncompressed) deflate blocks.

    The strict check of the data's length must decompress it (Pillow pads a
    short stream with zeros silently); handed over this way, Pillow's own
    decompression is a copy. Reading a 2048 x 300 8-bit PNG this way takes
    3.35 ms (median of 40 interleaved reads on a 2-core machine at load 6)
    against 7.68 ms for the check followed by Pillow's decode of the file,
    and 2.88 ms for Pillow's decode without the check.
    """
    stored = zlib.compress(data, 0)
    crc = zlib.crc32(stored, zlib.crc32(b"IDAT")) & 0xFFFFFFFF
    iend = struct.pack(">I", 0) + b"IEND" + struct.pack(">I", zlib.crc32(b"IEND") & 0xFFFFFFFF)
    # one join: each copy of a large buffer costs its page faults
    return b"".join((head, struct.pack(">I", len(stored)), b"IDAT", stored, struct.pack(">I", crc), iend))


def _read_png(path: Path, src: str, size: int, max_pixels: int) -> tuple[np.ndarray, int]:
    from PIL import Image, PngImagePlugin

    try:
        with open(path, "rb") as fh:
            head = fh.read(33)
            header = _png_header(head, src, max_pixels)
            limit = header.filtered_bytes() + header.filtered_bytes() // 64 + _PNG_SLACK_BYTES
            if size > limit:
                raise ImageFileError(src, f"{size} bytes is more than a PNG of {header.height} lines x {header.width} pixels can hold ({limit})")
            raw = head + fh.read()
    except OSError as exc:
        raise ImageFileError(src, f"cannot read ({_one_line(exc)})") from None
    body = _check_png(raw, src, header)
    palette = body.palette
    del raw
    try:
        with warnings.catch_warnings():
            # Our own max_pixels check has run; Pillow's global bomb limit is not ours.
            warnings.simplefilter("ignore", Image.DecompressionBombWarning)
            # The plugin class is used directly: Image.open would apply Pillow's
            # process-wide MAX_IMAGE_PIXELS instead of the caller's max_pixels.
            source = str(path) if body.data is None else io.BytesIO(_stored_png(body.head, body.data))
            del body
            with PngImagePlugin.PngImageFile(source) as im:
                im.load()
                if im.mode == "P":
                    top = int(np.asarray(im).max())
                    if top >= palette:
                        raise ImageFileError(src, f"corrupt PNG (pixel index {top} beyond its palette of {palette} entries)")
                    im = im.convert("RGBA" if "transparency" in im.info else "RGB")
                elif im.mode in ("1",):
                    im = im.convert("L")
                arr = np.array(im)
    except ImageFileError:
        raise
    except MemoryError:
        raise ImageFileError(src, f"not enough memory to decode {header.height} lines x {header.width} pixels") from None
    except Exception as exc:  # Pillow raises many types for damaged streams
        raise ImageFileError(src, f"cannot decode PNG ({_one_line(exc)})") from None
    if arr.shape[:2] != (header.height, header.width):
        raise ImageFileError(src, f"PNG decoded to shape {arr.shape}, its header says {header.height} x {header.width}")
    if header.depth == 16 and arr.dtype != np.uint16:
        # Pillow gives mode I;16 -> uint16, or "I" -> int32 holding 0..65535.
        if arr.dtype.kind in "iu" and arr.size and (arr.min() < 0 or arr.max() > 65535):
            raise ImageFileError(src, "16-bit PNG decoded out of range")
        arr = arr.astype(np.uint16)
    return arr, (16 if header.depth == 16 else 8)


def png_sample_bytes(path: str | Path) -> int:
    """Bytes of the samples :func:`read_stored` gives for a PNG, from its header alone; 0 where the header is unreadable.

    A palette expands to RGB or RGBA (counted as RGBA), 1- to 4-bit grey to
    8 bits; 16-bit samples take two bytes.
    """
    try:
        with open(path, "rb") as fh:
            header = _png_header(fh.read(33), str(path), DEFAULT_MAX_PIXELS)
    except (OSError, ImageFileError):
        return 0
    channels = 4 if header.colour == 3 else _PNG_CHANNELS[header.colour]
    return header.width * header.height * channels * (2 if header.depth == 16 else 1)


# --------------------------------------------------------------------------
# TIFF
# --------------------------------------------------------------------------
def _read_tiff(path: Path, size: int, src: str, max_pixels: int, memory_map: bool = False) -> tuple[np.ndarray, int]:
    import logging

    import tifffile

    tiff_log = logging.getLogger("tifffile")
    level = tiff_log.level
    count = 0
    tiff_log.setLevel(logging.CRITICAL)  # its notes on odd tags would break the one-line contract
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # tifffile logs/warns on odd tags; errors are ours
            with tifffile.TiffFile(str(path)) as tif:
                n_pages = len(tif.pages)
                if n_pages != 1:
                    raise ImageFileError(
                        src, f"TIFF has {n_pages} pages/images, need exactly one 2-D image"
                    )
                page = tif.pages[0]
                shape = tuple(int(s) for s in page.shape)
                axes = page.axes
                samples = shape[axes.index("S")] if "S" in axes and len(axes) == len(shape) else 1
                count = int(np.prod(shape, dtype=np.float64)) // max(samples, 1) if shape else 0
                if count == 0:
                    raise ImageFileError(src, f"empty TIFF image (shape {shape})")
                if count > max_pixels:  # pixels, whatever their samples
                    raise ImageFileError(
                        src,
                        f"TIFF header claims shape {shape} = {count} pixels, more than the limit of {max_pixels}",
                    )
                if samples > 4:
                    raise ImageFileError(src, f"TIFF of {samples} samples per pixel (need grey or RGB(A))")
                dtype = np.dtype(page.dtype) if page.dtype is not None else None
                if dtype is None or dtype not in (np.dtype(np.uint8), np.dtype(np.uint16)):
                    raise ImageFileError(
                        src, f"unsupported TIFF sample type {dtype} (need 8- or 16-bit unsigned)"
                    )
                # Truncation: every strip/tile must lie inside the file.
                offsets = page.dataoffsets
                counts = page.databytecounts
                if offsets and counts:
                    last = max(int(o) + int(c) for o, c in zip(offsets, counts))
                    if last > size:
                        raise ImageFileError(
                            src, f"truncated TIFF (image data ends at byte {last}, file has {size})"
                        )
                # an uncompressed grey image stored in one piece is mapped, not read
                mapped = memory_map and page.is_memmappable and len(shape) == 2
                arr = None if mapped else page.asarray()
            if mapped:
                arr = tifffile.memmap(str(path), page=0, mode="r")
    except ImageFileError:
        raise
    except MemoryError:
        raise ImageFileError(src, f"not enough memory to read its {count} pixels") from None
    except Exception as exc:
        raise ImageFileError(src, f"cannot read TIFF ({_one_line(exc)})") from None
    finally:
        tiff_log.setLevel(level)
    if not isinstance(arr, np.memmap):
        arr = np.asarray(arr)
    # Bring a samples axis (RGB / planar) to the end, refuse any other extra axis.
    if "S" in axes and arr.ndim == len(axes):
        arr = np.moveaxis(arr, axes.index("S"), -1)
        rest = [s for a, s in zip(axes, arr.shape) if a != "S"]
        if len(rest) != 2:
            raise ImageFileError(src, f"TIFF is not a 2-D image (axes {axes}, shape {shape})")
    return arr, (16 if arr.dtype == np.uint16 else 8)


# --------------------------------------------------------------------------
def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split()) or type(exc).__name__
    return text[:200]


def _to_grey(arr: np.ndarray, src: str) -> np.ndarray:
    """Grey float64 2-D array from a decoded grey / grey+alpha / RGB(A) array."""
    if arr.ndim == 2:
        return arr.astype(np.float64)
    if arr.ndim == 3 and arr.shape[2] in (1, 2, 3, 4):
        c = arr.shape[2]
        if c <= 2:  # grey or grey+alpha: drop alpha
            return arr[:, :, 0].astype(np.float64)
        # Rec. 601 luma of the stored values; alpha (4th sample) dropped.
        return arr[:, :, :3].astype(np.float64) @ _LUMA
    raise ImageFileError(src, f"not a 2-D image (decoded array shape {arr.shape})")


@dataclass(frozen=True, eq=False)
class StoredImage:
    """An image file's samples as stored: grey ``uint8``/``uint16`` (a memory map for an uncompressed TIFF), or colour.

    Attributes
    ----------
    data : numpy.ndarray
        ``(n_lines, W)`` grey samples of the file's type, or ``(n_lines, W,
        channels)`` colour samples.
    bits : int
        8 or 16.
    source : str
        Path of the file (used in messages).
    """

    data: np.ndarray
    bits: int
    source: str

    @property
    def is_grey(self) -> bool:
        """True for one sample per pixel (what a stream engine measures as stored)."""
        return self.data.ndim == 2

    @property
    def n_lines(self) -> int:
        return int(self.data.shape[0])


def read_stored(
    path: str | os.PathLike[str],
    *,
    lines_as_columns: bool = False,
    max_pixels: int = DEFAULT_MAX_PIXELS,
    memory_map: bool = True,
) -> StoredImage:
    """Read a PNG or TIFF file's samples in their stored type, checked as :func:`load_image` checks them.

    An uncompressed grey TIFF is memory-mapped (``memory_map``): its pixels
    are read from the file as they are used, so an image far larger than
    the memory can be measured line by line.  ``lines_as_columns`` copies
    the transposed samples.  Raises :class:`ImageFileError` as
    :func:`load_image` does.
    """
    src = os.fspath(path)
    p = Path(src)
    if not p.exists():
        raise ImageFileError(src, "no such file")
    if p.is_dir():
        raise ImageFileError(src, "is a directory, not an image file")
    try:
        size = p.stat().st_size
        with open(p, "rb") as fh:
            head = fh.read(8)
    except OSError as exc:
        raise ImageFileError(src, f"cannot read ({_one_line(exc)})") from None
    if size == 0:
        raise ImageFileError(src, "empty file (0 bytes)")
    if head[:4] == _PNG_SIGNATURE[:4]:
        if head != _PNG_SIGNATURE:
            raise ImageFileError(src, "truncated or corrupt PNG signature")
        arr, bits = _read_png(p, src, size, max_pixels)
    elif head[:4] in _TIFF_MAGICS:
        arr, bits = _read_tiff(p, size, src, max_pixels, memory_map)
    else:
        raise ImageFileError(src, "unknown image format (need PNG or TIFF)")
    try:
        return _as_stored(arr, bits, src, lines_as_columns)
    except MemoryError:
        raise ImageFileError(src, f"not enough memory for its {arr.size} samples") from None


def _as_stored(arr: np.ndarray, bits: int, src: str, lines_as_columns: bool) -> StoredImage:
    """The decoded samples as a :class:`StoredImage`: grey or colour, rows = scan lines, at least 2 x 2."""
    if arr.ndim == 3 and arr.shape[2] == 1:
        arr = arr[:, :, 0]
    if arr.ndim == 3 and arr.shape[2] == 2:  # grey + alpha: drop alpha
        arr = np.ascontiguousarray(arr[:, :, 0])
    if arr.ndim not in (2, 3) or (arr.ndim == 3 and arr.shape[2] not in (3, 4)):
        raise ImageFileError(src, f"not a 2-D image (decoded array shape {arr.shape})")
    if lines_as_columns:
        arr = np.ascontiguousarray(np.swapaxes(arr, 0, 1))
    n_lines, width = arr.shape[:2]
    if n_lines < 2 or width < 2:
        raise ImageFileError(src, f"image of {n_lines} lines x {width} pixels: need at least 2 lines and 2 pixels")
    return StoredImage(arr, bits, src)


def load_image(
    path: str | os.PathLike[str],
    *,
    lines_as_columns: bool = False,
    saturation_dn: float | None = None,
    max_pixels: int = DEFAULT_MAX_PIXELS,
) -> LineImage:
    """Load a line-scan image from a PNG or TIFF file.

    Parameters
    ----------
    path : str or path-like
        PNG or TIFF file (format decided by its magic bytes).
    lines_as_columns : bool, optional
        The file stores time along its columns: transpose it so that rows are
        scan lines.
    saturation_dn : float, optional
        Level (DN) at or above which a pixel is clipped. Default: the file's
        type maximum (255 or 65535). Must be > 0.
    max_pixels : int, optional
        Refuse images whose header claims more pixels than this, before
        decoding (default :data:`DEFAULT_MAX_PIXELS` = 2**28).

    Returns
    -------
    LineImage
        ``data`` is float64 of shape ``(n_lines, W)`` with the stored values.

    Raises
    ------
    ImageFileError
        One-line message naming the file: missing, empty, unknown format,
        truncated, corrupt, not 2-D, unsupported type, too large, or fewer than
        2 lines or 2 columns.
    """
    return line_image(read_stored(path, lines_as_columns=lines_as_columns, max_pixels=max_pixels, memory_map=False), saturation_dn)


def line_image(stored: StoredImage, saturation_dn: float | None = None) -> LineImage:
    """The :class:`LineImage` (float64 grey, read-only) of a file's stored samples; ``saturation_dn`` as for :func:`load_image`."""
    if saturation_dn is not None and not (np.isfinite(saturation_dn) and saturation_dn > 0):
        raise ImageFileError(stored.source, f"saturation level must be a positive number, got {saturation_dn}")
    try:
        grey = _to_grey(np.asarray(stored.data), stored.source)
    except MemoryError:
        raise ImageFileError(stored.source, f"not enough memory for its {stored.data.size} samples as float64") from None
    sat = float(saturation_dn) if saturation_dn is not None else float(2**stored.bits - 1)
    grey.setflags(write=False)
    return LineImage(data=grey, saturation_dn=sat, bits=stored.bits, source=stored.source)


def as_line_image(
    image: "LineImage | np.ndarray | str | os.PathLike[str]",
    *,
    bits: int | None = None,
    saturation_dn: float | None = None,
    source: str = "<array>",
) -> LineImage:
    """A :class:`LineImage` from what a caller holds: a ``LineImage``, a file path, or an array.

    Parameters
    ----------
    image : LineImage, str, path-like or array (n_lines, W)
        A path is loaded with :func:`load_image`.  An array holds digital
        numbers as the camera gives them (row = scan line, column = sensor
        pixel), integer or float, finite and non-negative.
    bits : int, optional
        Bits per sample of an array (1-16).  Default: 8 for ``uint8``, 16 for
        ``uint16``; a float or wider integer array needs it (its saturation
        level is ``2**bits - 1``).
    saturation_dn : float, optional
        Level (DN) at or above which a pixel is clipped (default
        ``2**bits - 1``).
    source : str
        Name of an array in messages and in the result's ``image`` key.

    Raises
    ------
    ImageFileError
        For a path, as :func:`load_image`; for an array, one line naming
        ``source``: not 2-D, fewer than 2 lines or pixels, not finite,
        negative, or above ``2**bits - 1``.
    ValueError
        ``bits`` missing for a float array or out of range, or ``bits`` /
        ``saturation_dn`` given with a ``LineImage``.
    """
    if isinstance(image, LineImage):
        if bits is not None or saturation_dn is not None:
            raise ValueError("bits, saturation_dn: a LineImage carries its own; give them with an array")
        return image
    if isinstance(image, (str, os.PathLike)):
        if bits is not None:
            raise ValueError("bits: a file's bit depth is its own; give bits with an array")
        return load_image(image, saturation_dn=saturation_dn)
    arr = np.asarray(image)
    if bits is None:
        if arr.dtype not in (np.uint8, np.uint16):
            raise ValueError(f"bits: give the bit depth of a {arr.dtype} array (e.g. bits=12)")
        bits = 8 * arr.dtype.itemsize
    if isinstance(bits, bool) or not isinstance(bits, (int, np.integer)) or not 1 <= bits <= 16:
        raise ValueError(f"bits: must be an integer from 1 to 16, got {bits!r}")
    if arr.dtype.kind not in "uif":
        raise ImageFileError(source, f"array of {arr.dtype}: need integer or float digital numbers")
    if arr.ndim != 2 or min(arr.shape) < 2:
        raise ImageFileError(source, f"array of shape {arr.shape}: need (n_lines, W) with at least 2 lines and 2 pixels")
    data = np.array(arr, dtype=np.float64)
    top = float(2**bits - 1)
    if not np.all(np.isfinite(data)):
        raise ImageFileError(source, "array holds NaN or infinite values")
    lo, hi = float(data.min()), float(data.max())
    if lo < 0 or hi > top:
        raise ImageFileError(source, f"values {lo:g}..{hi:g} outside 0..{top:g} of {bits} bits")
    if saturation_dn is not None and not (np.isfinite(saturation_dn) and saturation_dn > 0):
        raise ImageFileError(source, f"saturation level must be a positive number, got {saturation_dn}")
    data.setflags(write=False)
    return LineImage(data=data, saturation_dn=top if saturation_dn is None else float(saturation_dn), bits=int(bits), source=source)


def load_timestamps(path: str | os.PathLike[str], n_lines: int) -> np.ndarray:
    """Load per-line timestamps (seconds) for an image of ``n_lines`` lines.

    Parameters
    ----------
    path : str or path-like
        ``.npy`` file holding a 1-D array, or a text file with one number per
        line (blank lines and lines starting with ``#`` are ignored).
    n_lines : int
        Number of scan lines of the image; the file must hold exactly this
        many values.

    Returns
    -------
    numpy.ndarray
        float64, shape ``(n_lines,)``, finite and strictly increasing (s).

    Raises
    ------
    ImageFileError
        One-line message naming the file.
    """
    src = os.fspath(path)
    p = Path(src)
    if not p.is_file():
        raise ImageFileError(src, "no such timestamps file")
    if p.suffix.lower() == ".npy":
        try:
            arr = np.load(p, allow_pickle=False, mmap_mode="r")  # its shape is checked before its values are read
        except Exception as exc:
            raise ImageFileError(src, f"cannot read .npy timestamps ({_one_line(exc)})") from None
        if arr.size != n_lines:
            raise ImageFileError(src, f"{arr.size} timestamps for an image of {n_lines} lines")
        arr = np.asarray(arr)
        if arr.ndim == 2 and 1 in arr.shape:
            arr = arr.reshape(-1)
        if arr.ndim != 1:
            raise ImageFileError(src, f"timestamps must be a 1-D array, got shape {arr.shape}")
        if arr.dtype.kind not in "iuf":
            raise ImageFileError(src, f"timestamps must be numbers, got dtype {arr.dtype}")
        t = arr.astype(np.float64)
    else:
        limit = 64 * n_lines + (1 << 20)  # a number a line, with room for comments
        if p.stat().st_size > limit:
            raise ImageFileError(src, f"{p.stat().st_size} bytes is more than {n_lines} timestamps can take ({limit})")
        try:
            text = p.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise ImageFileError(src, f"cannot read timestamps ({_one_line(exc)})") from None
        values = []
        for k, line in enumerate(text.splitlines(), start=1):
            s = line.strip()
            if not s or s.startswith("#"):
                continue
            try:
                values.append(float(s))
            except ValueError:
                raise ImageFileError(src, f"line {k}: not a number: {s[:40]!r}") from None
        t = np.asarray(values, dtype=np.float64)
    if t.size == 0:
        raise ImageFileError(src, "no timestamps in file")
    if t.size != n_lines:
        raise ImageFileError(src, f"{t.size} timestamps for an image of {n_lines} lines")
    bad = np.flatnonzero(~np.isfinite(t))
    if bad.size:
        raise ImageFileError(src, f"timestamp {bad[0]} is not finite ({t[bad[0]]})")
    steps = np.diff(t)
    bad = np.flatnonzero(steps <= 0)
    if bad.size:
        i = int(bad[0])
        raise ImageFileError(
            src, f"timestamps must be strictly increasing: line {i + 1} ({float(t[i + 1])!r} s) <= line {i} ({float(t[i])!r} s)"
        )
    return t
