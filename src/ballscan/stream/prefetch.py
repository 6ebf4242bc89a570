"""PNG inputs decoded on another core while this process loads the estimator and measures the first ones.

A ``batch`` command's first half second goes to importing the estimator and
loading its compiled kernels, then to the first inputs, measured there
before workers are worth starting: one core's work; with local workers
allowed (``-j 2`` or more) the other core is idle meanwhile.
:func:`decoding_ahead` forks a decoder (:func:`ballscan.parallel.start_forked`)
that reads the PNG inputs in their order
(:func:`ballscan.measure.images.read_stored`, a quarter of a small image's
measuring time) into memory shared with this process and every process
later forked from it; :func:`decoded` hands an input's samples over instead
of reading the file again, and :func:`stop_decoding`, called before the
workers start, ends the decoder (the workers then use what it finished).
The samples are those ``read_stored`` gives (the same call), so the results
do not change; an input the decoder could not read or did not reach is read
where it is measured, which also reports its faults.

The decoded images stay in the shared memory until the block ends, at most
:data:`CAPACITY_BYTES`.  The decoder never outlives the block, nor this
process (the forked workers' parent watch).
"""

from __future__ import annotations

import contextlib
import mmap
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

import numpy as np

__all__ = ["CAPACITY_BYTES", "decoded", "decoding_ahead", "stop_decoding"]

#: Bytes of decoded samples held at most (the decoder stops before an image that would not fit).
CAPACITY_BYTES = 256 << 20

# the shared block: the images one after the other, each at a multiple of _ALIGN
_ALIGN = 64


@dataclass(frozen=True)
class _Slot:
    """Where one decoded image lies in the shared block."""

    offset: int
    shape: tuple[int, ...]
    dtype: str
    bits: int


class _Ahead:
    """The decoder of one :func:`decoding_ahead` block and what it finished."""

    def __init__(self, paths: Sequence[str], capacity_bytes: int) -> None:
        import multiprocessing

        from ..parallel import start_forked

        self.block = mmap.mmap(-1, capacity_bytes)  # anonymous and shared with forked children
        self.slots: dict[str, _Slot] = {}
        self._recv, send = multiprocessing.get_context("fork").Pipe(duplex=False)
        self._proc = start_forked(_decode_all, list(paths), self.block, send, name="ballscan-decoder")
        send.close()  # the decoder's end: the pipe reads its end when the decoder is gone

    def _take_notes(self) -> None:
        """The notes the decoder has sent so far (each one small write to the pipe, whole or not at all)."""
        with contextlib.suppress(EOFError, OSError):
            while self._recv.poll():
                path, slot = self._recv.recv()
                self.slots[path] = slot

    def stop(self) -> int:
        """End the decoder (at once) and take note of the images it finished; the count."""
        if self._proc is None:
            return len(self.slots)
        self._proc.kill()
        self._proc.join()
        self._proc = None
        self._take_notes()
        self._recv.close()
        return len(self.slots)

    def get(self, path: str):
        from ..measure.images import StoredImage

        if self._proc is not None:
            self._take_notes()
        slot = self.slots.get(path)
        if slot is None:
            return None
        n = int(np.prod(slot.shape))
        data = np.frombuffer(self.block, dtype=slot.dtype, count=n, offset=slot.offset).reshape(slot.shape).copy()
        return StoredImage(data, slot.bits, path)

    def close(self) -> None:
        self.stop()
        self.slots.clear()
        with contextlib.suppress(BufferError):  # a view still held: freed with the last reference
            self.block.close()


def _decode_all(paths: list[str], block: mmap.mmap, send) -> None:
    """The decoder: each PNG of ``paths`` into ``block`` after the previous, a note of it on ``send``; until killed or full."""
    from ..errors import BallscanError
    from ..measure.images import png_sample_bytes, read_stored

    offset = 0
    for path in paths:
        if offset + png_sample_bytes(path) > len(block):
            return  # not decoded at all: it would not fit
        try:
            stored = read_stored(path)
        except (BallscanError, ValueError, OSError):
            continue  # read again where it is measured, which reports it
        data = np.ascontiguousarray(stored.data)
        if offset + data.nbytes > len(block):
            return
        np.frombuffer(block, dtype=data.dtype, count=data.size, offset=offset)[:] = data.ravel()
        send.send((path, _Slot(offset, tuple(data.shape), data.dtype.str, stored.bits)))
        offset += -(-data.nbytes // _ALIGN) * _ALIGN


_current: _Ahead | None = None


@contextlib.contextmanager
def decoding_ahead(paths: Sequence[str], capacity_bytes: int = CAPACITY_BYTES) -> Iterator[None]:
    """Decode the PNGs among ``paths`` (in their order) on another core for the length of the block.

    Only where processes can be forked from this one
    (:func:`ballscan.parallel.can_fork`); elsewhere, or with no PNG, nothing
    happens.  Blocks do not nest.
    """
    from ..parallel import can_fork

    global _current
    pngs = [p for p in paths if p.lower().endswith(".png")]
    if _current is not None or not pngs or not can_fork():
        yield
        return
    _current = _Ahead(pngs, capacity_bytes)
    try:
        yield
    finally:
        ahead, _current = _current, None
        ahead.close()


def stop_decoding() -> int:
    """End the decoder of the current :func:`decoding_ahead` block (if any); the images it finished."""
    return 0 if _current is None else _current.stop()


def decoded(path: str):
    """The :class:`~ballscan.measure.images.StoredImage` of ``path`` as decoded ahead (a copy), or None.

    In this process while the decoder runs, or after :func:`stop_decoding`
    in this process and those forked from it since.
    """
    return None if _current is None else _current.get(path)
