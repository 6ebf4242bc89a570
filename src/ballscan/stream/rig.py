"""Line streams of a rig's cameras, measured as they arrive and paired ball by ball: ``ballscan rig watch``.

Each camera's stream runs its own :func:`ballscan.stream.engine.process_stream`
in a thread; its results come to one queue.  A ball of the reference camera
waits for each other camera's ball in its window
(:func:`ballscan.pipeline.rig.predicted_crossing`): it is measured jointly
(:func:`ballscan.pipeline.rig.measure_group`) as soon as every camera has
given its match, or has passed the window (a later ball, or its stream's
end), or ``pair_timeout_s`` of wall time has gone by; a ball no reference
ball claims is measured alone, flagged ``single_camera``.
"""

from __future__ import annotations

import math
import queue
import threading
import time
from dataclasses import dataclass, field
from typing import Iterable, Iterator

from ..errors import BallscanError
from ..geometry.camera import crop_camera
from ..geometry.rig import Rig
from ..pipeline.recipe import Recipe
from ..pipeline.results import BallEstimate
from ..pipeline.rig import RigBall, measure_group, predicted_crossing
from ..solve.constraint import Constraint
from .engine import StreamConfig, process_stream

__all__ = ["pair_streams"]

_END = object()


@dataclass
class _Pending:
    """A ball waiting for its partners: camera index, estimate, arrival (wall s) and, for a reference ball, the windows."""

    k: int
    estimate: BallEstimate
    crop_cols: tuple[int, int]
    arrived_s: float
    windows: dict = field(default_factory=dict)  # camera -> (predicted t, half-width)
    claimed: bool = False


def _reader(k: int, chunks, rig: Rig, radius_m: float, config: StreamConfig, name: str, out: queue.Queue) -> None:
    try:
        for res in process_stream(chunks, rig.cameras[k].camera, radius_m, config, source=name):
            out.put((k, (res.estimate, res.crop_cols)))
    except BallscanError as exc:
        out.put((k, exc))
    finally:
        out.put((k, _END))


def _crop(rig: Rig, p: _Pending):
    """The camera of the columns the ball's edges were measured on (pixel 0 of the crop is its first column)."""
    c0, c1 = p.crop_cols
    return crop_camera(rig.cameras[p.k].camera, c0, c1)


def _t(e: BallEstimate) -> float:
    return math.nan if e.t_c_s is None else float(e.t_c_s)


def pair_streams(
    sources: Iterable,
    rig: Rig,
    radius_m: float,
    config: StreamConfig | None = None,
    *,
    names: tuple[str, ...] | None = None,
    constraint: Constraint | None = None,
    pair_timeout_s: float = 2.0,
) -> Iterator[RigBall]:
    """Measure a rig's streams (one iterable of chunks per camera, the rig's order) and yield one :class:`RigBall` per ball.

    Parameters
    ----------
    sources : sequence of iterables
        Each camera's chunks (as for :func:`ballscan.stream.engine.process_stream`).
    rig : Rig
    radius_m : float
    config : StreamConfig, optional
        Every stream's engine settings (its ``recipe`` also the joint fit's).
    names : tuple of str, optional
        The streams' names (default the cameras').
    constraint : Constraint, optional
    pair_timeout_s : float
        Wall seconds a ball waits for its partners before it is measured with what came.

    Raises
    ------
    BallscanError
        A stream's fault, after every ball paired before it.
    """
    sources = list(sources)
    if len(sources) != len(rig.cameras):
        raise ValueError(f"watch --rig: {len(sources)} sources for {len(rig.cameras)} cameras ({', '.join(rig.names)})")
    cfg = StreamConfig() if config is None else config
    recipe: Recipe = cfg.recipe
    names = names or rig.names
    q: queue.Queue = queue.Queue()
    threads = [threading.Thread(target=_reader, args=(k, s, rig, radius_m, cfg, names[k], q), daemon=True) for k, s in enumerate(sources)]
    for th in threads:
        th.start()
    ref = rig.reference
    pending: list[_Pending] = []
    latest = [-math.inf] * len(sources)
    done = [False] * len(sources)
    fault: BallscanError | None = None
    while not all(done) or pending:
        try:
            k, item = q.get(timeout=0.05)
        except queue.Empty:
            k, item = None, None
        if item is _END:
            done[k] = True
        elif isinstance(item, BallscanError):
            fault = fault or item
        elif item is not None:
            p = _Pending(k, item[0], item[1], time.monotonic())
            if k == ref:
                p.windows = {j: predicted_crossing(rig, p.estimate, j) for j in range(len(sources)) if j != ref}
            pending.append(p)
            latest[k] = max(latest[k], _t(p.estimate))
        yield from _ready(rig, pending, latest, done, radius_m, recipe, constraint, pair_timeout_s)
    for th in threads:
        th.join(timeout=1.0)
    if fault is not None:
        raise fault


def _ready(rig: Rig, pending: list, latest: list, done: list, radius_m: float, recipe: Recipe, constraint, timeout_s: float) -> Iterator[RigBall]:
    """The pending balls whose partners are in (or can no longer come), measured; removed from ``pending``."""
    now = time.monotonic()
    ref = rig.reference
    for p in sorted((p for p in pending if p.k == ref), key=lambda p: _t(p.estimate)):
        picks, crops, waiting = {ref: p.estimate}, {ref: _crop(rig, p)}, False
        for j, (t_pred, half) in p.windows.items():
            cands = [o for o in pending if o.k == j and not o.claimed and math.isfinite(t_pred) and abs(_t(o.estimate) - t_pred) <= half]
            if cands:
                best = min(cands, key=lambda o: abs(_t(o.estimate) - t_pred))
                picks[j], crops[j] = best.estimate, _crop(rig, best)
            elif not (done[j] or not math.isfinite(t_pred) or latest[j] > t_pred + half or now - p.arrived_s > timeout_s):
                waiting = True
        if waiting:
            continue
        for o in pending:
            if o.k != ref and any(o.estimate is e for e in picks.values()):
                o.claimed = True
        pending.remove(p)
        pending[:] = [o for o in pending if not o.claimed]
        yield measure_group(rig, picks, radius_m, recipe, constraint, crops)
    # the others' balls no reference ball can still claim
    for o in list(pending):
        if o.k == ref:
            continue
        t = _t(o.estimate)
        if done[ref] or latest[ref] > t + 10 * rig.match_window_s + 5 * rig.cameras[o.k].clock_sigma_s or now - o.arrived_s > 2 * timeout_s:
            if not any(p.k == ref for p in pending):
                pending.remove(o)
                yield measure_group(rig, {o.k: o.estimate}, radius_m, recipe, constraint, {o.k: _crop(rig, o)})
