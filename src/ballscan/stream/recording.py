"""Recorded images of any length, measured as a stream: chunk by chunk, in their stored type, in bounded memory.

A whole-image estimate (:func:`ballscan.pipeline.estimate.estimate_image`)
holds the image as float64 and models its background over every pixel: its
memory and time grow with the image.  A recording longer than the stream
engine's ring buffer is instead fed to the same
:class:`~ballscan.stream.engine.StreamEngine` that measures a camera's
lines: its samples stay in the file's ``uint8``/``uint16`` (an uncompressed
TIFF or a raw file is memory-mapped and read as the engine goes), only the
engine's ring and the balls' crops are held, the lines without a ball cost
the engine's per-line test, and each ball costs its crop alone.  The balls
are those the stream of the same lines gives (the engine's results do not
depend on how the lines are cut into chunks).
"""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

import numpy as np

from ..errors import BallscanError
from ..geometry.camera import LineScanCamera
from ..measure.images import DEFAULT_MAX_PIXELS, StoredImage, line_image, read_stored
from ..pipeline.estimate import estimate_image
from ..pipeline.plausibility import check_radius
from ..pipeline.recipe import Recipe
from ..pipeline.results import EstimateReport
from .engine import Chunk, StreamConfig, process_stream

__all__ = ["is_recording", "measure_file", "measure_recording", "measure_stored", "open_raw"]


def open_raw(path: str | os.PathLike[str], width: int, dtype: str = "uint8") -> StoredImage:
    """A raw file of ``width``-sample lines (``uint8`` or little-endian ``uint16``), memory-mapped.

    Raises
    ------
    BallscanError
        The file is empty or not a whole number of lines (naming the file).
    """
    src = os.fspath(path)
    dt = np.dtype(dtype).newbyteorder("<")
    if dt.kind != "u" or dt.itemsize not in (1, 2):
        raise ValueError(f"dtype: expected uint8 or uint16, got {dtype!r}")
    size = Path(src).stat().st_size
    line_bytes = width * dt.itemsize
    if size == 0 or size % line_bytes:
        raise BallscanError(f"{src}: {size} bytes is not a whole number of {width}-pixel {dt.name} lines ({line_bytes} bytes each)")
    lines = np.memmap(src, dtype=dt, mode="r", shape=(size // line_bytes, width))
    return StoredImage(lines, 8 * dt.itemsize, src)


def measure_recording(
    stored: StoredImage,
    camera: LineScanCamera,
    radius_m: float,
    config: StreamConfig = StreamConfig(),
    *,
    chunk_lines: int = 4096,
    timestamps_s: np.ndarray | None = None,
) -> EstimateReport:
    """Every ball of a grey recording, measured by the stream engine over its lines.

    Parameters
    ----------
    stored : StoredImage
        Grey ``uint8``/``uint16`` samples (:func:`ballscan.measure.images.read_stored`, :func:`open_raw`).
    camera : LineScanCamera
        Its width must be the recording's.
    radius_m : float
        Ball radius, metres.
    config : StreamConfig
        The engine's settings (its ``recipe`` is the estimator's).
    chunk_lines : int
        Lines handed to the engine at a time (the results do not depend on it).
    timestamps_s : ndarray, optional
        Per-line times (seconds) replacing ``i / line_rate``.

    Returns
    -------
    EstimateReport
        The balls in the order the engine measured them, with stream (here:
        image) line numbers.
    """
    if not stored.is_grey or stored.data.dtype not in (np.uint8, np.uint16):
        raise BallscanError(f"{stored.source}: a recording is measured as stored: it must be 8- or 16-bit grey")
    n, width = stored.data.shape
    if width != camera.width:
        raise BallscanError(f"{stored.source}: has {width} pixels per line but the camera file says width = {camera.width}")
    if timestamps_s is not None and np.shape(timestamps_s) != (n,):
        raise BallscanError(f"{stored.source}: {np.shape(timestamps_s)[0]} timestamps for {n} lines")
    chunks = (
        Chunk(stored.data[i : i + chunk_lines], None if timestamps_s is None else np.asarray(timestamps_s[i : i + chunk_lines], dtype=float))
        for i in range(0, n, chunk_lines)
    )
    results = process_stream(chunks, camera, radius_m, config, source=stored.source)
    return EstimateReport(image=stored.source, balls=tuple(r.estimate for r in results), recipe=config.recipe)


def measure_stored(
    stored: StoredImage,
    camera: LineScanCamera,
    radius_m: float,
    recipe: Recipe = Recipe(),
    *,
    timestamps_s: np.ndarray | None = None,
    saturation_dn: float | None = None,
    stream: StreamConfig | None = None,
) -> EstimateReport:
    """Every ball of an image file's samples: as one image up to the stream engine's buffer, as a stream beyond.

    An image of at most ``stream.buffer_lines`` lines (or a colour one) is
    measured whole by :func:`ballscan.pipeline.estimate.estimate_image`; a
    longer grey one by :func:`measure_recording`, in the file's stored type
    and bounded memory.  ``stream`` defaults to ``StreamConfig(recipe=recipe)``.
    """
    cfg = StreamConfig(recipe=recipe) if stream is None else stream
    radius_m = check_radius(radius_m)
    if saturation_dn is not None and not (np.isfinite(saturation_dn) and saturation_dn > 0):
        raise BallscanError(f"{stored.source}: saturation level must be a positive number, got {saturation_dn}")
    try:
        if is_recording(stored, cfg):
            if saturation_dn is not None and cfg.saturation_dn is None:
                cfg = replace(cfg, saturation_dn=float(saturation_dn))
            return measure_recording(stored, camera, radius_m, cfg, timestamps_s=timestamps_s)
        return estimate_image(line_image(stored, saturation_dn), camera, radius_m, recipe=recipe, timestamps_s=timestamps_s)
    except MemoryError:
        raise BallscanError(f"{stored.source}: not enough memory to measure its {stored.n_lines} lines x {stored.data.shape[1]} pixels") from None


def is_recording(stored: StoredImage, config: StreamConfig = StreamConfig()) -> bool:
    """Whether :func:`measure_stored` measures ``stored`` as a stream (grey and longer than the engine's buffer)."""
    return stored.is_grey and stored.n_lines > config.buffer_lines


def measure_file(
    path: str | os.PathLike[str],
    camera: LineScanCamera,
    radius_m: float,
    recipe: Recipe = Recipe(),
    *,
    timestamps_s: np.ndarray | None = None,
    lines_as_columns: bool = False,
    saturation_dn: float | None = None,
    max_pixels: int = DEFAULT_MAX_PIXELS,
) -> EstimateReport:
    """:func:`measure_stored` of a PNG or TIFF file (:func:`ballscan.measure.images.read_stored`)."""
    stored = read_stored(path, lines_as_columns=lines_as_columns, max_pixels=max_pixels)
    return measure_stored(stored, camera, radius_m, recipe, timestamps_s=timestamps_s, saturation_dn=saturation_dn)
