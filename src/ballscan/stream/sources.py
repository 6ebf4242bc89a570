"""Line sources for :mod:`ballscan.stream.engine`: raw files and pipes, image folders, rendered streams, Basler cameras.

Every source is an iterable of :class:`~ballscan.stream.engine.Chunk` (consecutive
lines, optional per-line timestamps). A chunk may be a view of a buffer the
source reuses: consume it before asking for the next one. A fault is raised
as a :class:`SourceError` with a one-line message *after* every complete line
before it has been yielded, so nothing measured before a fault is lost.

Raw lines
---------
A raw stream is ``W`` samples per line, no header, ``uint8`` or little-endian
``uint16`` (``--dtype``), from a file, a named pipe or standard input
(``-``). Reads go with ``readinto`` into one preallocated buffer. A stream
whose length is not a whole number of lines ends with a partial line: the
complete lines are delivered, then a :class:`TruncatedStream` error says so
(a wrong ``--width`` usually shows up this way). On a pipe, a ``timeout_s``
turns a silent source into a :class:`SourceStalled` error, counted from the
start too: a named pipe is opened without waiting for its writer. A ``stop``
request (an object with ``is_set()``, e.g. a ``threading.Event`` set by a
signal handler) ends a raw source after its complete lines, within
:data:`STOP_POLL_S` seconds even while it waits for data.
"""

from __future__ import annotations

import json
import math
import os
import re
import select
import stat
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, BinaryIO

import numpy as np

from ..geometry.camera import LineScanCamera, save_camera
from ..outputs import atomic_write_text, check_not_symlink
from ..geometry.motion import BallMotion
from .engine import Chunk, StreamError

__all__ = [
    "STOP_POLL_S",
    "SourceError",
    "TruncatedStream",
    "SourceStalled",
    "TimestampReader",
    "RawLineSource",
    "ImageFolderSource",
    "ArraySource",
    "PylonSource",
    "PylonFrames",
    "block_gap",
    "tick_frequency_hz",
    "PYLON_PIXEL_FORMATS",
    "PYLON_TIMESTAMPS",
    "SimulatedStream",
    "simulate_stream",
    "stream_balls",
]


#: Longest wait (s) for data before a raw source looks at its stop request again.
STOP_POLL_S = 0.1


class SourceError(StreamError):
    """A line source cannot deliver (more) lines."""


class TruncatedStream(SourceError):
    """The stream ends inside a line."""


class SourceStalled(SourceError):
    """No data arrived within the timeout."""


# --------------------------------------------------------------------------
# Timestamps
# --------------------------------------------------------------------------
class TimestampReader:
    """Per-line timestamps read incrementally (seconds; text, one per line, or ``.npy``).

    Memory stays small however long the file is: ``.npy`` files are memory
    mapped, text files are read line by line.

    Parameters
    ----------
    path : str or path-like
    """

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = os.fspath(path)
        p = Path(self.path)
        if not p.is_file():
            raise SourceError(f"{self.path}: no such timestamps file")
        self._pos = 0
        self._arr = None
        self._fh = None
        if p.suffix.lower() == ".npy":
            try:
                arr = np.load(p, mmap_mode="r", allow_pickle=False)
            except Exception as exc:  # noqa: BLE001 - any decoding problem is one message
                raise SourceError(f"{self.path}: cannot read .npy timestamps ({exc})") from None
            if arr.ndim != 1 or arr.dtype.kind not in "iuf":
                raise SourceError(f"{self.path}: timestamps must be a 1-D array of numbers, got {arr.dtype} {arr.shape}")
            self._arr = arr
        else:
            self._fh = open(p, encoding="utf-8")
            self._lineno = 0

    def take(self, n: int) -> np.ndarray:
        """The next ``n`` timestamps (float64).

        Raises
        ------
        SourceError
            If the file ends first or holds a value that is not a number.
        """
        if self._arr is not None:
            out = np.asarray(self._arr[self._pos : self._pos + n], dtype=np.float64)
        else:
            vals: list[float] = []
            while len(vals) < n:
                line = self._fh.readline()
                if not line:
                    break
                self._lineno += 1
                s = line.strip()
                if not s or s.startswith("#"):
                    continue
                try:
                    vals.append(float(s))
                except ValueError:
                    raise SourceError(f"{self.path}: line {self._lineno}: not a number: {s[:40]!r}") from None
            out = np.asarray(vals, dtype=np.float64)
        if out.size < n:
            raise SourceError(f"{self.path}: only {self._pos + out.size} timestamps, but the stream has more lines")
        self._pos += n
        return out

    def close(self) -> None:
        if self._fh is not None:
            self._fh.close()


# --------------------------------------------------------------------------
# Raw lines from a file, a pipe or standard input
# --------------------------------------------------------------------------
class RawLineSource:
    """Raw 8/16-bit lines from a file, a named pipe or standard input.

    Parameters
    ----------
    path : str, path-like or binary file object
        ``"-"`` for standard input.
    width : int
        Pixels per line.
    dtype : {"uint8", "uint16"}
        Sample type (``uint16`` little-endian).
    chunk_lines : int
        Most lines per chunk (the preallocated buffer's size).
    timeout_s : float or None
        On a pipe or terminal: raise :class:`SourceStalled` when no byte
        arrives for this long. Regular files never stall.
    timestamps : str, path-like or None
        Per-line timestamps file (text or ``.npy``), read along.
    name : str, optional
        Name in messages and results (default: the path).
    stop : object with ``is_set()``, optional
        When it is set, the source ends after the complete lines it has read
        (no error; a partial line is dropped).
    """

    def __init__(
        self,
        path: str | os.PathLike[str] | BinaryIO,
        width: int,
        dtype: str | np.dtype = "uint8",
        *,
        chunk_lines: int = 1024,
        timeout_s: float | None = None,
        timestamps: str | os.PathLike[str] | None = None,
        name: str | None = None,
        stop: Any = None,
    ) -> None:
        if isinstance(width, bool) or not isinstance(width, (int, np.integer)) or width < 2:
            raise ValueError(f"--width: must be an integer >= 2, got {width!r}")
        dt = np.dtype(dtype)
        if dt not in (np.dtype(np.uint8), np.dtype(np.uint16)):
            raise ValueError(f"--dtype: must be uint8 or uint16, got {dtype!r}")
        if isinstance(chunk_lines, bool) or not isinstance(chunk_lines, (int, np.integer)) or chunk_lines < 1:
            raise ValueError(f"chunk_lines: must be a positive integer, got {chunk_lines!r}")
        if timeout_s is not None and not (timeout_s > 0):
            raise ValueError(f"--timeout: must be positive, got {timeout_s!r}")
        self.path = path
        self.width = int(width)
        self.dtype = dt.newbyteorder("<") if dt.itemsize > 1 else dt
        self.chunk_lines = int(chunk_lines)
        self.timeout_s = timeout_s
        self.timestamps = timestamps
        if name is None:
            name = "<stdin>" if path == "-" else (os.fspath(path) if isinstance(path, (str, os.PathLike)) else getattr(path, "name", "<stream>"))
        self.name = str(name)
        self.lines_read = 0
        self.stop = stop
        self._wait_since: float | None = None

    def _open(self) -> tuple[Any, bool]:
        """A raw (unbuffered) binary reader and whether we opened it."""
        if self.path == "-":
            return sys.stdin.buffer.raw, False
        if isinstance(self.path, (str, os.PathLike)):
            p = os.fspath(self.path)
            if not os.path.exists(p):
                raise SourceError(f"{self.name}: no such file")
            if os.path.isdir(p):
                raise SourceError(f"{self.name}: is a directory (use an image folder source for chunk files)")
            if stat.S_ISFIFO(os.stat(p).st_mode):
                # not blocked until a writer opens it: the timeout counts from now
                return open(os.open(p, os.O_RDONLY | os.O_NONBLOCK), "rb", buffering=0), True
            return open(p, "rb", buffering=0), True
        return self.path, False

    def __iter__(self) -> Iterator[Chunk]:
        fh, owned = self._open()
        ts_reader = TimestampReader(self.timestamps) if self.timestamps is not None else None
        try:
            yield from self._chunks(fh, ts_reader)
        finally:
            if owned:
                fh.close()
            if ts_reader is not None:
                ts_reader.close()

    def _chunks(self, fh: Any, ts_reader: TimestampReader | None) -> Iterator[Chunk]:
        line_bytes = self.width * self.dtype.itemsize
        buf = np.empty((self.chunk_lines, self.width), dtype=self.dtype)
        mv = memoryview(buf).cast("B")
        total = mv.nbytes
        fd = None
        try:
            fd = fh.fileno()
            mode = os.fstat(fd).st_mode
            is_stream = stat.S_ISFIFO(mode) or stat.S_ISCHR(mode) or stat.S_ISSOCK(mode)
        except (OSError, AttributeError, ValueError):
            is_stream = False
        filled = 0
        eof = False
        stopped = False
        while not eof:
            while filled < total:
                if self.stop is not None and self.stop.is_set():
                    eof = stopped = True
                    break
                if is_stream and fd is not None:
                    ready = self._wait(fd, filled >= line_bytes)
                    if ready is None:
                        continue  # the stop request is looked at again
                    if not ready:
                        if filled >= line_bytes:
                            break  # deliver the complete lines we have: latency matters
                        continue
                try:
                    got = fh.readinto(mv[filled:])
                except BlockingIOError:
                    continue
                except OSError as exc:
                    raise SourceError(f"{self.name}: read failed after line {self.lines_read} ({exc.strerror or exc})") from None
                if got is None:
                    continue
                if got == 0:
                    eof = True
                    break
                filled += got
            n = filled // line_bytes
            if n:
                self.lines_read += n
                ts = ts_reader.take(n) if ts_reader is not None else None
                yield Chunk(buf[:n], ts)
                rest = filled - n * line_bytes
                if rest:
                    mv[:rest] = mv[n * line_bytes : filled]
                filled = rest
            if eof and filled and not stopped:
                raise TruncatedStream(
                    f"{self.name}: ends with a partial line of {filled} bytes (a line is {line_bytes} bytes: "
                    f"--width {self.width}, --dtype {self.dtype.name}); the {self.lines_read} complete lines before it were processed"
                )

    def _wait(self, fd: int, have_lines: bool) -> bool | None:
        """Wait until ``fd`` is readable; False means "nothing now" when lines are pending, None "look at the stop request".

        Without pending lines the wait is cut into slices of at most
        :data:`STOP_POLL_S` when there is a stop request; the timeout counts
        over the slices.
        """
        if have_lines:
            r, _, _ = select.select([fd], [], [], 0.0)
            return bool(r)
        now = time.monotonic()
        if self._wait_since is None:
            self._wait_since = now
        waited = now - self._wait_since
        left = None if self.timeout_s is None else self.timeout_s - waited
        if left is not None and left <= 0:
            raise SourceStalled(
                f"{self.name}: no data for {self.timeout_s:g} s after line {self.lines_read} (source stalled; --timeout)"
            )
        step = left if self.stop is None else (STOP_POLL_S if left is None else min(left, STOP_POLL_S))
        r, _, _ = select.select([fd], [], [], step)
        if not r:
            return None
        self._wait_since = None
        return True


# --------------------------------------------------------------------------
# A folder of image chunks
# --------------------------------------------------------------------------
def _natural_key(p: Path) -> list:
    return [int(t) if t.isdigit() else t.lower() for t in re.split(r"(\d+)", p.name)]


class ImageFolderSource:
    """Chunks of lines stored as PNG/TIFF images in a folder, in natural name order.

    Parameters
    ----------
    folder : str or path-like
    width : int or None
        Expected pixels per line (default: the first image's).
    lines_as_columns : bool
        The images store time along their columns.
    timestamps : str, path-like or None
        Per-line timestamps file for the whole stream (text or ``.npy``).
    """

    SUFFIXES = (".png", ".tif", ".tiff")

    def __init__(self, folder: str | os.PathLike[str], width: int | None = None, *, lines_as_columns: bool = False, timestamps=None) -> None:
        self.folder = Path(folder)
        if not self.folder.is_dir():
            raise SourceError(f"{self.folder}: not a folder")
        self.files = sorted((p for p in self.folder.iterdir() if p.suffix.lower() in self.SUFFIXES and p.is_file()), key=_natural_key)
        if not self.files:
            raise SourceError(f"{self.folder}: no PNG or TIFF images")
        self.width = width
        self.lines_as_columns = lines_as_columns
        self.timestamps = timestamps
        self.name = str(self.folder)
        self.dtype: np.dtype | None = None
        self.lines_read = 0

    def __iter__(self) -> Iterator[Chunk]:
        from ..measure.images import load_image

        ts_reader = TimestampReader(self.timestamps) if self.timestamps is not None else None
        try:
            for p in self.files:
                img = load_image(p, lines_as_columns=self.lines_as_columns)
                dt = np.dtype(np.uint8 if img.bits == 8 else np.uint16)
                if self.width is None:
                    self.width = img.width
                if img.width != self.width:
                    raise SourceError(
                        f"{p}: {img.width} pixels per line, expected {self.width}; the {self.lines_read} lines before it were processed"
                    )
                if self.dtype is None:
                    self.dtype = dt
                elif dt != self.dtype:
                    raise SourceError(f"{p}: {img.bits}-bit image in a {8 * self.dtype.itemsize}-bit stream")
                self.lines_read += img.n_lines
                ts = ts_reader.take(img.n_lines) if ts_reader is not None else None
                yield Chunk(np.rint(img.data).astype(dt), ts)
        finally:
            if ts_reader is not None:
                ts_reader.close()


class ArraySource:
    """Lines of an in-memory array (or a memory-mapped raw file) in chunks of ``chunk_lines``.

    Parameters
    ----------
    data : numpy.ndarray
        ``(n_lines, W)`` uint8/uint16.
    chunk_lines : int
    timestamps_s : numpy.ndarray or None
    name : str
    """

    def __init__(self, data: np.ndarray, chunk_lines: int = 1024, timestamps_s: np.ndarray | None = None, name: str = "<array>") -> None:
        self.data = data
        self.chunk_lines = int(chunk_lines)
        self.timestamps_s = timestamps_s
        self.name = name

    def __iter__(self) -> Iterator[Chunk]:
        n = self.data.shape[0]
        for a in range(0, n, self.chunk_lines):
            b = min(a + self.chunk_lines, n)
            yield Chunk(np.asarray(self.data[a:b]), None if self.timestamps_s is None else np.asarray(self.timestamps_s[a:b], dtype=np.float64))


# --------------------------------------------------------------------------
# Basler cameras through pypylon (optional extra)
# --------------------------------------------------------------------------
#: Pixel formats a pylon source grabs, with the sample type of their chunks.
PYLON_PIXEL_FORMATS = {"Mono8": np.dtype(np.uint8), "Mono12": np.dtype(np.uint16), "Mono16": np.dtype(np.uint16)}
#: Where a pylon source's line times come from (see :class:`PylonFrames`).
PYLON_TIMESTAMPS = ("none", "grab", "chunk")
_BLOCK_ID_INVALID = 2**64 - 1  # pylon's "this block ID must not be used"
_GIGE_BLOCK_ID_MAX = 65535  # GigE block IDs (standard ID mode) run 1..65535 and wrap to 1


def _import_pylon():
    """``(genicam, pylon)`` from pypylon, or a one-line SourceError when it is missing."""
    import warnings

    try:
        with warnings.catch_warnings():
            # pypylon's SWIG modules emit DeprecationWarnings on import
            # ("builtin type SwigPyPacked has no __module__"); as errors
            # (pytest -W error) they abort the import half-way and crash.
            warnings.simplefilter("ignore", DeprecationWarning)
            from pypylon import genicam, pylon
    except ImportError:
        raise SourceError("pylon source: pypylon is not installed (pip install pypylon, the Basler pylon SDK for Python)") from None
    return genicam, pylon


def _pylon_message(exc: BaseException, limit: int = 160) -> str:
    """A pylon exception's text on one line, at most ``limit`` characters."""
    return " ".join(str(exc).split())[:limit]


def block_gap(previous: int | None, block_id: int) -> int:
    """Frames missing between two consecutive grab results, from their block IDs.

    GigE cameras number frames 1..65535 and wrap to 1 (64-bit in extended ID
    mode), USB3 cameras from 0 on (64-bit); ``2**64 - 1`` marks an invalid
    ID and a camera without block IDs sends 0 for every frame.

    Parameters
    ----------
    previous : int or None
        Block ID of the frame before (None: this is the first frame).
    block_id : int
        Block ID of this frame.

    Returns
    -------
    int
        Frames lost in between (0 when the IDs cannot tell).
    """
    if previous is None or _BLOCK_ID_INVALID in (previous, block_id):
        return 0
    if block_id > previous:
        return block_id - previous - 1
    if 1 <= block_id < previous <= _GIGE_BLOCK_ID_MAX:
        return _GIGE_BLOCK_ID_MAX - previous + block_id - 1
    return 0


def tick_frequency_hz(nodemap: Any, genicam: Any, name: str = "pylon") -> float:
    """Timestamp ticks per second of a camera (Hz).

    GigE cameras count ticks of ``GevTimestampTickFrequency``; USB3 cameras
    (no such feature) count nanoseconds.

    Parameters
    ----------
    nodemap : genicam.INodeMap
        The camera's node map.
    genicam : module
        pypylon's ``genicam`` (for ``IsReadable``).
    name : str
        Name of the source in messages.

    Returns
    -------
    float
        Ticks per second: the feature's value, else 1e9.

    Raises
    ------
    SourceError
        If the camera reports a frequency that is not positive.
    """
    node = nodemap.GetNode("GevTimestampTickFrequency")
    if node is None or not genicam.IsReadable(node):
        return 1e9
    f = float(node.GetValue())
    if not f > 0:
        raise SourceError(f"{name}: the camera reports GevTimestampTickFrequency = {f:g} Hz: its timestamps cannot be converted to seconds")
    return f


def _check_pylon_timing(line_rate_hz: float, timestamps: str) -> None:
    if timestamps not in PYLON_TIMESTAMPS:
        raise ValueError(f"--pylon-timestamps: must be one of {', '.join(PYLON_TIMESTAMPS)}, got {timestamps!r}")
    if isinstance(line_rate_hz, bool) or not isinstance(line_rate_hz, (int, float, np.number)) or not line_rate_hz > 0:
        raise ValueError(f"pylon source: the line rate must be positive (Hz), got {line_rate_hz!r}")


class PylonFrames:
    """Grab results to chunks: the lines copied, their times (s), block-ID gaps as dropped lines.

    Line ``i`` of a frame gets the frame's time plus ``i / line_rate_hz``.
    The frame's time is, by ``timestamps``:

    - ``"none"``: its first line's index in the stream, counting the lines
      of lost frames, over ``line_rate_hz`` (the engine's ``line /
      line_rate`` where nothing is lost);
    - ``"grab"``: the grab result's ``GetTimeStamp()``, camera ticks;
    - ``"chunk"``: the frame's Timestamp chunk, camera ticks.

    Ticks become seconds since the first frame's exposure start (integer
    ticks subtracted first: no precision lost on a large clock). A gap of
    ``k`` block IDs means ``k * Height`` lines were lost: the times jump
    across it, so the engine flags a ball it crosses ``dropped_lines``;
    stream line numbers count the lines delivered, as with a timestamps file.

    Parameters
    ----------
    line_rate_hz : float
        Lines per second (Hz).
    timestamps : {"none", "grab", "chunk"}
    tick_frequency_hz : float
        Camera timestamp ticks per second (Hz); 1e9 for nanoseconds.
    name : str
        Name in messages.

    Attributes
    ----------
    frames, lines_read : int
        Frames and lines delivered.
    dropped_frames, dropped_lines : int
        Frames and lines lost (block-ID gaps).
    gaps : list of (int, int)
        ``(line, count)``: ``count`` lines lost after delivered line ``line``.
    t0_ticks : int or None
        Camera ticks of the first frame (camera timestamps only): the
        absolute camera time of ``t`` s is ``t0_ticks / tick_frequency_hz + t``.
    """

    def __init__(self, line_rate_hz: float, timestamps: str = "none", tick_frequency_hz: float = 1e9, name: str = "pylon") -> None:
        _check_pylon_timing(line_rate_hz, timestamps)
        if not tick_frequency_hz > 0:
            raise ValueError(f"{name}: tick frequency must be positive, got {tick_frequency_hz!r} Hz")
        self.line_rate_hz = float(line_rate_hz)
        self.timestamps = timestamps
        self.tick_frequency_hz = float(tick_frequency_hz)
        self.name = name
        self.frames = self.lines_read = self.dropped_frames = self.dropped_lines = 0
        self.gaps: list[tuple[int, int]] = []
        self.t0_ticks: int | None = None
        self._block: int | None = None
        self._last_t = -math.inf

    def chunk(self, result: Any) -> Chunk:
        """The chunk of one grab result (its pixels copied: release it afterwards).

        Parameters
        ----------
        result : pylon.GrabResult
            Needs ``GrabSucceeded``, ``GetErrorDescription``, ``GetArray``,
            ``GetBlockID``, and ``GetTimeStamp`` or ``ChunkTimestamp.Value``
            for camera timestamps.

        Raises
        ------
        SourceError
            A failed grab, a frame that is not grey, camera times that do not
            increase or a missing Timestamp chunk.
        """
        if not result.GrabSucceeded():
            raise SourceError(f"{self.name}: grab failed after line {self.lines_read}: {result.GetErrorDescription()}")
        lines = np.array(result.GetArray())
        if lines.ndim != 2:
            raise SourceError(f"{self.name}: frame {self.frames} is not a grey image (shape {lines.shape}; use a Mono pixel format)")
        self._count_gap(int(result.GetBlockID()), lines.shape[0])
        times = self._times(result, lines.shape[0])
        self._last_t = float(times[-1])
        self.frames += 1
        self.lines_read += lines.shape[0]
        return Chunk(lines, times)

    def _count_gap(self, block_id: int, height: int) -> None:
        missing = block_gap(self._block, block_id)
        self._block = block_id
        if missing:
            self.dropped_frames += missing
            self.dropped_lines += missing * height
            self.gaps.append((self.lines_read - 1, missing * height))

    def _times(self, result: Any, n: int) -> np.ndarray:
        """Times of the frame's ``n`` lines (s)."""
        if self.timestamps == "none":
            first = self.lines_read + self.dropped_lines  # as the engine's line / line_rate, to the bit
            return np.arange(first, first + n, dtype=np.float64) / self.line_rate_hz
        return self._frame_time(result) + np.arange(n) / self.line_rate_hz

    def _frame_time(self, result: Any) -> float:
        """Camera time of the frame's first line (s since the first frame's)."""
        ticks = self._ticks(result)
        if self.t0_ticks is None:
            self.t0_ticks = ticks
        t = (ticks - self.t0_ticks) / self.tick_frequency_hz
        if not t > self._last_t:
            raise SourceError(
                f"{self.name}: frame {self.frames} starts at {t:.9g} s, not after the previous frame's last line ({self._last_t:.9g} s): "
                f"the camera's {self.timestamps} timestamps do not advance, or its line rate exceeds {self.line_rate_hz:g} Hz (--pylon-timestamps none counts lines instead)"
            )
        return t

    def _ticks(self, result: Any) -> int:
        if self.timestamps == "grab":
            return int(result.GetTimeStamp())
        try:
            return int(result.ChunkTimestamp.Value)
        except AttributeError:
            raise SourceError(f"{self.name}: frame {self.frames} carries no Timestamp chunk (--pylon-timestamps chunk)") from None


class PylonSource:
    """Lines grabbed from a Basler camera with pypylon (optional extra: ``pip install pypylon``).

    Each grabbed frame of a line-scan camera is ``Height`` lines of
    ``Width`` pixels; it becomes one chunk (``Mono8`` -> ``uint8``,
    ``Mono12``/``Mono16`` -> ``uint16``) with its lines' times from
    :class:`PylonFrames`. The camera is set up in this order: the feature
    file, ``Width``/``Height``, the emulator's image folder, ``PixelFormat``,
    the Timestamp chunk.

    Parameters
    ----------
    serial : str or None
        Serial number of the camera (default: the first found). With the
        environment variable ``PYLON_CAMEMU=1`` (set before pypylon is
        imported) pylon offers emulated cameras.
    line_rate_hz : float
        Lines per second (Hz): the line times within a frame, and the
        frames' times without camera timestamps.
    frames : int or None
        Stop after this many frames (default: run until interrupted).
    timeout_s : float
        Grab timeout (s); a camera that sends nothing for this long raises
        :class:`SourceStalled`.
    width, height : int or None
        Set the camera's ``Width`` (pixels per line) and ``Height`` (lines
        per frame) before grabbing.
    image_folder : str or None
        For an emulated camera: play back the images of this folder
        (``ImageFilename``, ``ImageFileMode = On``, ``TestImageSelector =
        Off``; pylon plays them in name order and loops).
    timestamps : {"none", "grab", "chunk"}
        Where the frames' times come from: the line count, the grab
        results' timestamps or the Timestamp chunk (``ChunkModeActive``,
        ``ChunkSelector = Timestamp``, ``ChunkEnable`` are set). Camera ticks
        are converted with the camera's ``GevTimestampTickFrequency`` (Hz;
        nanoseconds where it has none, as USB3 cameras).
    pixel_format : {"Mono8", "Mono12", "Mono16"} or None
        Set the camera's ``PixelFormat`` (default: leave it).
    pfs : str, path-like or None
        A pylon feature file (``.pfs``, saved by pylon Viewer) loaded into
        the camera first.

    Attributes
    ----------
    width : int or None
        Pixels per line (the camera's, once grabbing).
    max_dn : int or None
        Largest sample value of the camera's pixel format (255, 4095 or
        65535), once grabbing: the saturation level of Mono12 lines is
        4095, not their ``uint16`` type's maximum.
    """

    def __init__(
        self,
        serial: str | None = None,
        *,
        line_rate_hz: float,
        frames: int | None = None,
        timeout_s: float = 5.0,
        width: int | None = None,
        height: int | None = None,
        image_folder: str | os.PathLike[str] | None = None,
        timestamps: str = "none",
        pixel_format: str | None = None,
        pfs: str | os.PathLike[str] | None = None,
    ) -> None:
        _check_pylon_timing(line_rate_hz, timestamps)
        if pixel_format is not None and pixel_format not in PYLON_PIXEL_FORMATS:
            raise ValueError(f"--pixel-format: must be one of {', '.join(PYLON_PIXEL_FORMATS)}, got {pixel_format!r}")
        if pfs is not None and not Path(pfs).is_file():
            raise SourceError(f"{os.fspath(pfs)}: no such pylon feature file (--pfs)")
        _import_pylon()
        self.name = f"pylon:{serial or 'first'}"
        self.serial = serial
        self.line_rate_hz = float(line_rate_hz)
        self.frames = frames
        self.timeout_s = float(timeout_s)
        self.set_width = width
        self.set_height = height
        self.image_folder = None if image_folder is None else os.fspath(image_folder)
        self.timestamps = timestamps
        self.pixel_format = pixel_format
        self.max_dn: int | None = None
        self.pfs = None if pfs is None else os.fspath(pfs)
        self.width: int | None = width
        self._frames = PylonFrames(self.line_rate_hz, timestamps, name=self.name)

    @property
    def lines_read(self) -> int:
        """Lines delivered so far."""
        return self._frames.lines_read

    @property
    def dropped_lines(self) -> int:
        """Lines lost so far (block-ID gaps)."""
        return self._frames.dropped_lines

    @property
    def gaps(self) -> list[tuple[int, int]]:
        """``(line, count)`` of each block-ID gap: ``count`` lines lost after delivered line ``line``."""
        return list(self._frames.gaps)

    def __iter__(self) -> Iterator[Chunk]:
        genicam, pylon = _import_pylon()
        cam = self._open(genicam, pylon)
        try:
            self._frames = self._configure(cam, genicam, pylon)
            cam.StartGrabbing(pylon.GrabStrategy_OneByOne)
            for result in self._results(cam, genicam, pylon):
                try:
                    chunk = self._frames.chunk(result)
                finally:
                    result.Release()
                yield chunk
        except genicam.GenericException as exc:
            raise SourceError(f"{self.name}: pylon error after line {self.lines_read}: {_pylon_message(exc, 200)}") from None
        finally:
            if cam.IsGrabbing():
                cam.StopGrabbing()
            cam.Close()

    def _open(self, genicam: Any, pylon: Any) -> Any:
        """The camera of ``serial`` (or the first), opened."""
        factory = pylon.TlFactory.GetInstance()
        devices = list(factory.EnumerateDevices())
        dev = next((d for d in devices if self.serial is None or d.GetSerialNumber() == self.serial), None)
        if dev is None:
            found = ", ".join(d.GetSerialNumber() for d in devices) or "none; PYLON_CAMEMU=1 offers emulated ones"
            raise SourceError(f"{self.name}: no Basler camera{' with serial number ' + self.serial if self.serial else ''} (found: {found})")
        try:
            cam = pylon.InstantCamera(factory.CreateDevice(dev))
            cam.Open()
        except genicam.GenericException as exc:
            raise SourceError(f"{self.name}: cannot open the camera ({_pylon_message(exc)})") from None
        return cam

    def _configure(self, cam: Any, genicam: Any, pylon: Any) -> PylonFrames:
        """Set the camera up; the frame converter for its clock."""
        nodemap = cam.GetNodeMap()
        if self.pfs is not None:
            self._load_pfs(nodemap, genicam, pylon)
        if self.set_width is not None:
            self._set(nodemap, genicam, "Width", int(self.set_width))
        if self.set_height is not None:
            self._set(nodemap, genicam, "Height", int(self.set_height))
        if self.image_folder is not None:
            self._set(nodemap, genicam, "ImageFilename", self.image_folder)
            self._set(nodemap, genicam, "ImageFileMode", "On")
            self._set(nodemap, genicam, "TestImageSelector", "Off")
        if self.pixel_format is not None:
            self._set(nodemap, genicam, "PixelFormat", self.pixel_format, "--pixel-format")
        if self.timestamps == "chunk":
            for feature, value in (("ChunkModeActive", True), ("ChunkSelector", "Timestamp"), ("ChunkEnable", True)):
                self._set(nodemap, genicam, feature, value, "--pylon-timestamps chunk")
        self.max_dn = self._bits(nodemap)
        self.width = int(nodemap.GetNode("Width").GetValue())
        f = 1e9 if self.timestamps == "none" else tick_frequency_hz(nodemap, genicam, self.name)
        return PylonFrames(self.line_rate_hz, self.timestamps, f, self.name)

    def _load_pfs(self, nodemap: Any, genicam: Any, pylon: Any) -> None:
        try:
            pylon.FeaturePersistence.Load(self.pfs, nodemap, True)
        except genicam.GenericException as exc:
            raise SourceError(f"{self.pfs}: cannot load this pylon feature file into {self.name} ({_pylon_message(exc)})") from None

    def _bits(self, nodemap: Any) -> int:
        """Largest sample value of the camera's pixel format; SourceError unless Mono8/12/16."""
        fmt = str(nodemap.GetNode("PixelFormat").ToString())
        if fmt not in PYLON_PIXEL_FORMATS:
            raise SourceError(f"{self.name}: the camera's PixelFormat is {fmt}; ballscan grabs {', '.join(PYLON_PIXEL_FORMATS)} (--pixel-format)")
        return (1 << int(fmt[4:])) - 1

    def _set(self, nodemap: Any, genicam: Any, feature: str, value: Any, option: str = "") -> None:
        """Set a camera feature, or a one-line SourceError naming it, the value and the option that asked for it."""
        node = nodemap.GetNode(feature)
        why = f" ({option})" if option else ""
        if node is None or not genicam.IsWritable(node):
            raise SourceError(f"{self.name}: the camera has no writable {feature} to set to {value!r}{why}")
        try:
            node.SetValue(value)
        except genicam.GenericException as exc:
            raise SourceError(f"{self.name}: the camera refuses {feature} = {value!r}{why}: {_pylon_message(exc)}") from None

    def _results(self, cam: Any, genicam: Any, pylon: Any) -> Iterator[Any]:
        """Grab results until ``frames`` or the camera stops; SourceStalled after ``timeout_s`` without one."""
        n = 0
        while cam.IsGrabbing() and (self.frames is None or n < self.frames):
            try:
                result = cam.RetrieveResult(int(self.timeout_s * 1000), pylon.TimeoutHandling_ThrowException)
            except genicam.TimeoutException:
                raise SourceStalled(f"{self.name}: no frame for {self.timeout_s:g} s after line {self.lines_read} (camera stalled)") from None
            n += 1
            yield result


# --------------------------------------------------------------------------
# Rendered streams (demos and tests)
# --------------------------------------------------------------------------
@dataclass(frozen=True)
class SimulatedStream:
    """Files written by :func:`simulate_stream`.

    Attributes
    ----------
    raw : Path
        Raw lines (``n_lines x W`` samples).
    camera_path : Path
        ``NAME.camera.toml``.
    truth_path : Path
        ``NAME.truth.jsonl``: one geometry.md truth object per ball, with
        ``first_line`` and ``last_line`` (stream lines where its silhouette is).
    timestamps_path : Path or None
        ``NAME.timestamps.npy`` when lines were dropped.
    balls : tuple of dict
        The truth objects.
    n_lines, width : int
    dtype : str
    """

    raw: Path
    camera_path: Path
    truth_path: Path
    timestamps_path: Path | None
    balls: tuple[dict, ...]
    n_lines: int
    width: int
    dtype: str = "uint8"
    meta: dict = field(default_factory=dict, compare=False)


def _visible_lines(camera: LineScanCamera, m: BallMotion) -> float:
    """Lines a ball spans (geometry.md: line_rate * ((2R + z0/f)/|Vx| + tau))."""
    return camera.line_rate_hz * ((2 * m.radius_m + m.position_m[2] / camera.focal_px) / abs(m.velocity_mps[0]) + camera.exposure)


def stream_balls(
    camera: LineScanCamera,
    n_lines: int,
    n_balls: int,
    seed: int,
    *,
    radius_m: float = 0.0335,
    speed_mps: tuple[float, float] = (25.0, 45.0),
    depth_m: tuple[float, float] = (3.0, 5.0),
    close_pairs: int = 0,
    pair_gap_lines: float = 6.0,
    side_by_side: int = 0,
    start_lines: int = 600,
    t_lines_s: np.ndarray | None = None,
) -> list[BallMotion]:
    """Random, non-overlapping ball motions for a stream (camera frame).

    Balls are spread over ``[start_lines, n_lines - 100)`` in slots, one ball
    per slot at a random place in it; the first ``close_pairs`` slots hold two
    balls, the second starting ``pair_gap_lines`` clean lines after the first
    ends; the next ``side_by_side`` slots hold two balls crossing at nearly
    the same time (within 3 lines) in opposite halves of the sensor. Every
    ball is wholly on the sensor with a margin.

    Parameters
    ----------
    camera : LineScanCamera
    n_lines, n_balls, seed : int
    radius_m : float
    speed_mps, depth_m : (float, float)
        Ranges of ``|V|`` (m/s) and of ``z0`` (m).
    close_pairs : int
    pair_gap_lines : float
    side_by_side : int
    start_lines : int
        No ball before this line (room for the engine's first model).
    t_lines_s : numpy.ndarray or None
        Line times (with dropped lines); default ``line / line_rate``.
    """
    rng = np.random.default_rng(seed)
    t = np.arange(n_lines) / camera.line_rate_hz if t_lines_s is None else np.asarray(t_lines_s)
    n_slots = n_balls - close_pairs - side_by_side
    if n_slots < 1 or n_slots < close_pairs + side_by_side:
        raise ValueError(f"n_balls: {n_balls} balls cannot hold {close_pairs} close pairs and {side_by_side} side-by-side pairs")
    slot = (n_lines - 100 - start_lines) / n_slots
    out: list[BallMotion] = []
    W = camera.width
    for k in range(n_slots):
        pair = k < close_pairs
        twin = close_pairs <= k < close_pairs + side_by_side
        for _ in range(200):
            z0 = rng.uniform(*depth_m)
            speed = rng.uniform(*speed_mps)
            vy = rng.uniform(-0.1, 0.1) * speed
            vz = rng.uniform(-0.1, 0.1) * speed
            vx = math.sqrt(max(speed**2 - vy**2 - vz**2, 1.0))
            rad_px = camera.focal_px * radius_m / z0
            half_span = rad_px + abs(vy) / vx * camera.focal_px * radius_m / z0 * 1.2 + 8
            lo_u, hi_u = half_span + 4, W - 1 - half_span - 4
            if lo_u >= hi_u:
                continue
            if twin:
                hi_u = min(hi_u, W / 2 - half_span - 8)  # left half; the twin goes right
                if lo_u >= hi_u:
                    continue
            u = rng.uniform(lo_u, hi_u)
            y0 = (u - camera.principal_px) / camera.focal_px * z0
            m0 = BallMotion(radius_m, 0.0, (0.0, y0, z0), (vx, vy, vz))
            span = _visible_lines(camera, m0)
            need = span * (2.0 if pair else 1.0) + (pair_gap_lines if pair else 0.0) + 8
            if need < slot:
                break
        else:
            raise ValueError("simulate_stream: balls do not fit; use more lines or fewer balls")
        a = start_lines + k * slot + 4 + span / 2
        b = start_lines + (k + 1) * slot - 4 - need + span / 2
        centre = rng.uniform(a, max(a, b))
        out.append(BallMotion(radius_m, float(np.interp(centre, np.arange(n_lines), t)), (0.0, y0, z0), (vx, vy, vz)))
        if pair:
            # A second ball right after the first, elsewhere on the sensor.
            z1 = rng.uniform(*depth_m)
            u1 = rng.uniform(lo_u, hi_u)
            m1 = BallMotion(radius_m, 0.0, (0.0, (u1 - camera.principal_px) / camera.focal_px * z1, z1), (vx, -vy, vz))
            c1 = centre + span / 2 + pair_gap_lines + _visible_lines(camera, m1) / 2 + 1
            out.append(BallMotion(radius_m, float(np.interp(c1, np.arange(n_lines), t)), m1.position_m, m1.velocity_mps))
        if twin:
            # Same moment, right half of the sensor, same depth and speed.
            u1 = rng.uniform(W / 2 + half_span + 8, W - 1 - half_span - 8)
            c1 = centre + rng.uniform(-3.0, 3.0)
            y1 = (u1 - camera.principal_px) / camera.focal_px * z0
            out.append(BallMotion(radius_m, float(np.interp(c1, np.arange(n_lines), t)), (0.0, y1, z0), (vx, -vy, vz)))
    out.sort(key=lambda m: m.t_c_s)
    return out


#: The longest stream ``simulate_stream`` renders: its line times take 8 bytes a line in memory.
MAX_SIMULATED_LINES = 2**26


def _check_stream_size(n_lines: int, n_balls: int, radius_m: float) -> None:
    """Refuse a simulated stream's length, ball count or radius (m) that no scene can have (ValueError naming the value)."""
    if isinstance(n_lines, bool) or not isinstance(n_lines, (int, np.integer)) or not 1000 <= n_lines <= MAX_SIMULATED_LINES:
        raise ValueError(f"n_lines: must be an integer from 1000 to {MAX_SIMULATED_LINES}, got {n_lines!r}")
    if isinstance(n_balls, bool) or not isinstance(n_balls, (int, np.integer)) or not 1 <= n_balls <= n_lines // 100:
        raise ValueError(f"n_balls: must be an integer from 1 to {n_lines // 100} (a ball per 100 lines) for {n_lines} lines, got {n_balls!r}")
    if not (isinstance(radius_m, (int, float)) and math.isfinite(radius_m) and 0 < radius_m <= 1.0):
        raise ValueError(f"radius: must be a number of metres in (0, 1], got {radius_m!r}")


def _ball_spans(camera: LineScanCamera, balls: list, t_lines_s: np.ndarray) -> tuple[list[dict], list[tuple[int, int]]]:
    """Each ball's truth (with its first and last line on which the silhouette is present) and its span of lines to render.

    Parameters
    ----------
    camera : LineScanCamera
    balls : list of BallMotion
    t_lines_s : ndarray
        Each written line's time, seconds.
    """
    from ..model.silhouette import silhouette

    n_lines = t_lines_s.size
    truths, spans = [], []
    for m in balls:
        half = _visible_lines(camera, m)
        c = float(np.searchsorted(t_lines_s, m.t_c_s))
        lo = max(int(c - half) - 4, 0)
        hi = min(int(c + half) + 5, n_lines)
        present = np.flatnonzero(silhouette(camera, m, t_lines_s[lo:hi]).present)
        first, last = (lo + int(present[0]), lo + int(present[-1])) if present.size else (lo, lo)
        spans.append((lo, hi))
        truths.append({**m.to_dict(), "first_line": first, "last_line": last})
    return truths, spans


def simulate_stream(
    out_raw: str | os.PathLike[str],
    camera: LineScanCamera,
    n_lines: int,
    n_balls: int,
    seed: int = 0,
    *,
    radius_m: float = 0.0335,
    close_pairs: int = 0,
    side_by_side: int = 0,
    ramp: float = 0.0,
    dropped: tuple[int, int] | None = None,
    noise: Any = None,
    background_level: float = 0.12,
    ball_level: float = 0.8,
    block_lines: int = 4096,
    speed_mps: tuple[float, float] = (25.0, 45.0),
    depth_m: tuple[float, float] = (3.0, 5.0),
    force: bool = False,
) -> SimulatedStream:
    """Render a long line stream with balls to a raw file, with its truth beside it.

    Writes ``OUT`` (raw lines), ``OUT.camera.toml``, ``OUT.truth.jsonl`` (one
    truth object per ball plus ``first_line`` / ``last_line``) and, with
    dropped lines, ``OUT.timestamps.npy``. Lines are rendered in blocks of
    ``block_lines``: memory does not grow with ``n_lines``.

    Parameters
    ----------
    out_raw : str or path-like
    camera : LineScanCamera
    n_lines : int
        Lines written (after dropping).
    n_balls : int
    seed : int
        Seeds the balls and the sensor noise.
    radius_m : float
    close_pairs : int
        Pairs of balls close in time (a few clean lines apart).
    side_by_side : int
        Pairs of balls crossing at the same time in opposite halves of the
        sensor (they overlap in time, not on the sensor).
    ramp : float
        Slow illumination ramp: the scene's brightness goes linearly from 1
        to ``1 + ramp`` over the stream.
    dropped : (int, int) or None
        ``(line, count)``: ``count`` line periods are missing after written
        line ``line`` (the timestamps jump).
    noise : SensorNoise or None
        Sensor model (default :class:`~ballscan.model.render.SensorNoise` 8-bit).
    background_level, ball_level : float
        Linear grey levels (0..1).
    block_lines : int
    speed_mps, depth_m : (float, float)
        Ranges of the balls' speed (m/s) and depth (m).
    force : bool
        Write through outputs that are symbolic links (refused otherwise).

    Raises
    ------
    ValueError
        ``n_lines`` outside 1000 .. :data:`MAX_SIMULATED_LINES`, ``n_balls``
        outside 1 .. one per 100 lines, a radius that is not a number in
        (0, 1] m, or balls that do not fit.

    Returns
    -------
    SimulatedStream
    """
    from dataclasses import replace as _replace

    from ..model.render import Appearance, SensorNoise, apply_sensor, render

    _check_stream_size(n_lines, n_balls, radius_m)
    noise = SensorNoise() if noise is None else noise
    out = Path(out_raw)
    for p in (out, out.with_name(out.name + ".camera.toml"), out.with_name(out.name + ".truth.jsonl"), out.with_name(out.name + ".timestamps.npy")):
        check_not_symlink(p, force)
    out.parent.mkdir(parents=True, exist_ok=True)
    idx = np.arange(n_lines, dtype=np.float64)
    if dropped is not None:
        line, count = int(dropped[0]), int(dropped[1])
        if not (0 < line < n_lines - 1 and count >= 1):
            raise ValueError(f"dropped: expected (line, count) inside the stream, got {dropped!r}")
        idx[line + 1 :] += count
    t = idx / camera.line_rate_hz
    balls = stream_balls(camera, n_lines, n_balls, seed, radius_m=radius_m, close_pairs=close_pairs, side_by_side=side_by_side, t_lines_s=t, speed_mps=speed_mps, depth_m=depth_m)
    rng = np.random.default_rng([seed, 1])
    # Fixed-pattern column gain drawn once for the whole stream.
    gain = 1.0 + noise.prnu_sigma * rng.standard_normal(camera.width) if noise.prnu_sigma > 0 else np.ones(camera.width)
    noise_blocks = _replace(noise, prnu_sigma=0.0)
    app = Appearance.flat(ball_level)
    truths, spans = _ball_spans(camera, balls, t)
    dtype = noise.dtype
    part = out.with_name(f".{out.name}.part")  # renamed over OUT when whole
    with open(part, "wb") as fh:
        for a in range(0, n_lines, block_lines):
            b = min(a + block_lines, n_lines)
            inside = [(m, app) for m, (lo, hi) in zip(balls, spans) if lo < b and hi > a]
            # Separate renders for disjoint groups keep the supersampling local.
            rendered = render(camera, inside, b - a, background_level=background_level, noise=None, t_lines_s=t[a:b])
            clean = rendered.clean
            if ramp:
                clean = clean * (1.0 + ramp * (np.arange(a, b) / n_lines))[:, None]
            img, _ = apply_sensor(clean * gain[None, :], noise_blocks, rng)
            fh.write(np.ascontiguousarray(img.astype(np.dtype(dtype).newbyteorder("<"))).tobytes())
    os.replace(part, check_not_symlink(out, force))
    save_camera(camera, out.with_name(out.name + ".camera.toml"), comment=f"written by ballscan simulate --stream for {out.name}", force=force)
    truth_path = out.with_name(out.name + ".truth.jsonl")
    atomic_write_text(truth_path, "".join(json.dumps(d, allow_nan=False) + "\n" for d in truths), force=force)
    ts_path = None
    if dropped is not None:
        ts_path = out.with_name(out.name + ".timestamps.npy")
        np.save(ts_path, t)
    meta = {"ramp": ramp, "dropped": dropped, "close_pairs": close_pairs, "side_by_side": side_by_side, "seed": seed, "noise": noise.to_dict()}
    return SimulatedStream(out, out.with_name(out.name + ".camera.toml"), truth_path, ts_path, tuple(truths), int(n_lines), int(camera.width), np.dtype(dtype).name, meta)


def load_truth_lines(path: str | os.PathLike[str]) -> list[dict]:
    """Read a ``.truth.jsonl`` file written by :func:`simulate_stream`."""
    return [json.loads(s) for s in Path(path).read_text().splitlines() if s.strip()]


__all__.append("load_truth_lines")

