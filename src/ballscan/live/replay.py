"""A saved run for the page: a ``--save-events`` folder, a ``batch`` CSV or JSON lines.

:func:`load_run` reads every ball of a saved run into a :class:`SavedRun`,
which the page lists and filters like a live run (``ballscan view``). Files
are only read. The crops of a ``--save-events`` folder are read when the
page asks for a ball (the folder may hold thousands); with the camera file
their fitted outline is drawn too (the motion is in each ball's JSON, the
lines' times in the event's ``.columns.npz``).
"""

from __future__ import annotations

import csv
import json
import re
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from ..errors import BallscanError
from ..geometry.camera import LineScanCamera
from ..geometry.motion import BallMotion
from ..measure.images import load_image
from ..pipeline.report import CSV_COLUMNS
from .balls import BallFilter, CropView, LiveBall, ball_from_csv_row, ball_from_record, crop_view
from .hub import Health

__all__ = ["SavedRun", "load_run"]

#: A saved ball's JSON in a --save-events folder: the event's stem, then the ball in it.
_EVENT_JSON = re.compile(r"^(event_\d+_lines_\d+-\d+)_ball(\d+)\.json$")


@dataclass
class SavedRun:
    """Every ball of a saved run (read-only), listed as the page lists a live run's.

    Attributes
    ----------
    name : str
        What was read (shown as the page's title).
    all_balls : list of LiveBall
        In the run's order.
    camera : LineScanCamera or None
        For the crops' outlines.
    crop_files : dict
        Ball index -> (crop PNG, columns NPZ or None, motion or None), for
        ``--save-events`` folders.
    """

    name: str
    all_balls: list[LiveBall]
    camera: LineScanCamera | None = None
    crop_files: dict[int, tuple[Path, Path | None, BallMotion | None]] = field(default_factory=dict)

    mode = "replay"

    def balls(self, selection: BallFilter | None = None) -> list[LiveBall]:
        """The balls that pass ``selection``, in the run's order (without crops)."""
        sel = selection or BallFilter()
        return [b for b in self.all_balls if sel.accepts(b)]

    def ball_detail(self, index: int) -> LiveBall | None:
        """One ball with its crop (read now) where the run saved one, else without; None for no such ball."""
        if not 0 <= index < len(self.all_balls):
            return None
        ball = self.all_balls[index]
        files = self.crop_files.get(index)
        if files is None:
            return ball
        return replace(ball, crop=self._crop(*files))

    def _crop(self, png: Path, npz: Path | None, motion: BallMotion | None) -> CropView | None:
        if not png.exists():
            return None
        pixels = load_image(png).data
        first_line, first_col, times = 0, 0, None
        if npz is not None and npz.exists():
            with np.load(npz) as z:
                first_line, first_col = int(z["crop_lines"][0]), int(z["crop_cols"][0])
                times = np.asarray(z["times_s"], dtype=np.float64)
        else:
            m = re.search(r"_lines_(\d+)-", png.name)
            first_line = int(m.group(1)) if m else 0
        return crop_view(pixels, first_line, first_col, camera=self.camera, motion=motion, times_s=times)

    def health(self) -> Health:
        """A saved run's "health": its size; the banner says it is a replay."""
        return Health("replay", f"replay of {self.name}: {len(self.all_balls)} balls", 0, 0.0, 0.0, None, None, 0, len(self.all_balls), 0, (), 0)


def _motion(record: dict) -> BallMotion | None:
    try:
        return BallMotion.from_dict(record) if record.get("position_m") and record.get("velocity_mps") and record.get("t_c_s") is not None else None
    except (KeyError, TypeError, ValueError):
        return None


def _load_events(folder: Path, camera: LineScanCamera | None) -> SavedRun:
    found = []
    for p in folder.iterdir():
        m = _EVENT_JSON.match(p.name)
        if m:
            found.append((m.group(1), int(m.group(2)), p))
    if not found:
        raise BallscanError(f"{folder}: no saved balls (event_*_ball*.json, as 'ballscan watch --save-events' writes)")
    found.sort(key=lambda t: (int(t[0].split("_")[1]), t[1]))
    balls, crops = [], {}
    for k, (stem, _, path) in enumerate(found):
        record = _read_json(path)
        balls.append(ball_from_record(record, k))
        png = folder / f"{stem}.png"
        if png.exists():
            npz = folder / f"{stem}.columns.npz"
            crops[k] = (png, npz if npz.exists() else None, _motion(record))
    return SavedRun(str(folder), balls, camera, crops)


def _read_json(path: Path) -> dict:
    try:
        record = json.loads(path.read_text())
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise BallscanError(f"{path}: not a ball's JSON ({exc})") from None
    if not isinstance(record, dict):
        raise BallscanError(f"{path}: not a ball's JSON (a {type(record).__name__}, expected an object)")
    return record


def _load_csv(path: Path) -> SavedRun:
    with open(path, newline="") as fh:
        reader = csv.DictReader(fh)
        missing = [c for c in ("source", "speed_mps", "flags") if c not in (reader.fieldnames or ())]
        if missing:
            raise BallscanError(f"{path}: not a batch CSV (no column {', '.join(missing)}; expected {', '.join(CSV_COLUMNS[:4])}, ...)")
        balls = []
        for k, row in enumerate(reader):
            try:
                balls.append(ball_from_csv_row(row, k))
            except ValueError as exc:
                raise BallscanError(f"{path}: row {k + 2}: {exc}") from None
    return SavedRun(str(path), balls)


def _load_json_lines(path: Path) -> SavedRun:
    balls = []
    with open(path) as fh:
        for n, text in enumerate(fh, start=1):
            if not text.strip():
                continue
            try:
                record = json.loads(text)
            except json.JSONDecodeError as exc:
                raise BallscanError(f"{path}: line {n}: not JSON ({exc.msg})") from None
            # a watch line is one ball; an 'estimate --json' object holds a list of them
            records = record.get("balls") if isinstance(record, dict) and isinstance(record.get("balls"), list) else [record]
            for r in records:
                if not isinstance(r, dict):
                    raise BallscanError(f"{path}: line {n}: expected a ball's JSON object")
                try:
                    balls.append(ball_from_record(r, len(balls), source=str(record.get("image", ""))))
                except (TypeError, ValueError) as exc:
                    raise BallscanError(f"{path}: line {n}: {exc}") from None
    return SavedRun(str(path), balls)


def load_run(path: str | Path, camera: LineScanCamera | None = None) -> SavedRun:
    """Every ball of a saved run.

    Parameters
    ----------
    path : str or Path
        A ``--save-events`` folder, a ``batch`` CSV (``.csv``) or JSON lines
        (``ballscan watch``'s output; also ``estimate --json`` objects).
    camera : LineScanCamera, optional
        The run's camera: a folder's crops then show their fitted outline.

    Raises
    ------
    BallscanError
        A missing or unreadable file, or one that holds no run, named.
    """
    p = Path(path)
    if not p.exists():
        raise BallscanError(f"{p}: no such file or folder")
    if p.is_dir():
        return _load_events(p, camera)
    try:
        if p.suffix.lower() == ".csv":
            return _load_csv(p)
        return _load_json_lines(p)
    except (OSError, UnicodeDecodeError) as exc:
        raise BallscanError(f"{p}: cannot be read ({exc})") from None
