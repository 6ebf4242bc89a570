"""What the live page shows of one ball: its numbers, its crop and the fitted outline.

A :class:`LiveBall` is built from an estimate's record (geometry.md's keys,
as ``ballscan watch`` prints them, or a ``batch`` CSV row); a
:class:`CropView` holds the ball's crop as 8-bit grey pixels and the model's
silhouette at the fitted motion as a closed outline in the crop's pixels
(the outline ``--plot`` draws, :func:`ballscan.model.silhouette.silhouette`
of Eq. (8) at each line's time), for the browser to draw. A
:class:`BallFilter` selects balls by flag and speed range; the same
selection gives the page's table and its CSV download (:data:`TABLE_COLUMNS`).
"""

from __future__ import annotations

import base64
import csv
import io
import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..geometry.camera import LineScanCamera, crop_camera
from ..geometry.motion import BallMotion
from ..model.silhouette import silhouette
from ..pipeline.report import FLAG_TEXT

__all__ = ["CropView", "LiveBall", "BallFilter", "TABLE_COLUMNS", "crop_view", "ball_from_record", "ball_from_csv_row", "table_csv"]

#: Columns of the page's table and of its CSV download (SI units: m/s, s, degrees; empty where unknown).
TABLE_COLUMNS = (
    "ball", "source", "first_line", "last_line", "t_c_s", "speed_mps", "speed_sigma_mps",
    "speed_transverse_mps", "psi_y_deg", "psi_y_sigma_deg", "psi_z_deg", "psi_z_sigma_deg", "flags", "lag_s",
)  # fmt: skip

#: Largest crop side sent to the browser (pixels); longer crops are subsampled by a whole step.
MAX_CROP_PX = 384
#: Most points of a crop's outline.
MAX_OUTLINE_POINTS = 400


@dataclass(frozen=True)
class CropView:
    """A ball's crop as the browser draws it.

    Attributes
    ----------
    width, height : int
        Pixels of ``pixels_b64`` (after subsampling): sensor columns across, lines down.
    pixels_b64 : str
        ``width * height`` bytes, row by row (line by line), 8-bit grey
        stretched between the crop's 0.5th and 99.5th percentiles, base64.
    first_line, first_column : int
        Stream line and sensor column of the crop's first pixel.
    step_lines, step_columns : int
        Subsampling steps (a displayed pixel is every ``step``-th stored one).
    outline : tuple of (float, float)
        The fitted silhouette, closed: ``(column, line)`` in displayed
        pixels (0 at the first pixel's centre); empty when the motion or the
        camera is unknown.
    """

    width: int
    height: int
    pixels_b64: str
    first_line: int
    first_column: int
    step_lines: int
    step_columns: int
    outline: tuple[tuple[float, float], ...] = ()

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready form."""
        return {
            "width": self.width, "height": self.height, "pixels": self.pixels_b64,
            "first_line": self.first_line, "first_column": self.first_column,
            "step_lines": self.step_lines, "step_columns": self.step_columns,
            "outline": [[round(x, 2), round(y, 2)] for x, y in self.outline],
        }  # fmt: skip


def _outline(camera: LineScanCamera, motion: BallMotion, times_s: np.ndarray, first_column: int, last_column: int) -> np.ndarray:
    """The model's closed outline in crop pixels ``(column, line)``: down the left edge, up the right one (as the overlay plot)."""
    sil = silhouette(crop_camera(camera, first_column, last_column), motion, times_s, model="averaged")
    lines = np.flatnonzero(sil.present)
    if lines.size == 0:
        return np.zeros((0, 2))
    xs = np.concatenate([sil.left_px[lines], sil.right_px[lines][::-1], sil.left_px[lines[:1]]])
    ys = np.concatenate([lines, lines[::-1], lines[:1]]).astype(float)
    pts = np.column_stack([xs, ys])
    return pts[np.all(np.isfinite(pts), axis=1)]


def crop_view(
    crop: np.ndarray,
    first_line: int,
    first_column: int,
    *,
    camera: LineScanCamera | None = None,
    motion: BallMotion | None = None,
    times_s: np.ndarray | None = None,
) -> CropView:
    """The crop's display pixels and, given the camera, the motion and the lines' times, its fitted outline.

    Parameters
    ----------
    crop : numpy.ndarray
        Stored values, ``(n_lines, n_columns)``, any numeric type.
    first_line, first_column : int
        Stream line and sensor column of ``crop[0, 0]``.
    camera : LineScanCamera, optional
        The full sensor's camera (the crop's is derived from it).
    motion : BallMotion, optional
        The fitted motion (camera frame, metres and m/s).
    times_s : numpy.ndarray, optional
        Centre time of each crop line, seconds.
    """
    img = np.asarray(crop, dtype=np.float64)
    if img.ndim != 2 or img.size == 0:
        raise ValueError(f"crop: expected a non-empty 2-D array, got shape {img.shape}")
    n, w = img.shape
    sl = max(1, math.ceil(n / MAX_CROP_PX))
    sc = max(1, math.ceil(w / MAX_CROP_PX))
    shown = img[::sl, ::sc]
    lo, hi = np.percentile(shown, [0.5, 99.5])
    scale = 255.0 / (hi - lo) if hi > lo else 0.0
    grey = np.clip((shown - lo) * scale, 0, 255).astype(np.uint8)
    pts: tuple[tuple[float, float], ...] = ()
    if camera is not None and motion is not None and times_s is not None and len(times_s) == n:
        xy = _outline(camera, motion, np.asarray(times_s, dtype=np.float64), int(first_column), int(first_column) + w)
        if len(xy) > MAX_OUTLINE_POINTS:
            xy = xy[np.linspace(0, len(xy) - 1, MAX_OUTLINE_POINTS).round().astype(int)]
        pts = tuple((float(x) / sc, float(y) / sl) for x, y in xy)
    return CropView(
        grey.shape[1], grey.shape[0], base64.b64encode(np.ascontiguousarray(grey).tobytes()).decode("ascii"),
        int(first_line), int(first_column), sl, sc, pts,
    )  # fmt: skip


def _num(v: Any) -> float | None:
    """A finite float or None (JSON null, an empty CSV cell, NaN)."""
    if v is None or v == "":
        return None
    f = float(v)
    return f if math.isfinite(f) else None


def _int(v: Any) -> int | None:
    return None if v is None or v == "" else int(v)


def _pair(v: Any) -> tuple[float | None, float | None]:
    if not v:
        return (None, None)
    return (_num(v[0]), _num(v[1]))


@dataclass(frozen=True)
class LiveBall:
    """One ball as the page lists it (SI units; None where undetermined).

    Attributes
    ----------
    index : int
        Running number of the ball in its run (0-based), the page's key.
    source : str
    first_line, last_line : int or None
        Stream lines of the ball.
    t_c_s : float or None
        Time the centre crossed the viewing plane, seconds.
    speed_mps, speed_sigma_mps : float or None
    speed_transverse_mps : float or None
        ``|(vx, vy)|``, or the speed across the line of sight where only
        that is determined (geometry.md), m/s.
    direction_deg, direction_sigma_deg : tuple of float or None
        ``(psi_y, psi_z)`` and their 1-sigma, degrees (geometry.md).
    flags : tuple of str
        geometry.md's flag words.
    lag_s : float or None
        Seconds from the reading of the ball's last line to the ball's
        publication (live runs).
    latency_s : float or None
        The engine's latency (from the arrival of the chunk that completed
        the event to the result), seconds.
    crop : CropView or None
    """

    index: int
    source: str
    first_line: int | None
    last_line: int | None
    t_c_s: float | None
    speed_mps: float | None
    speed_sigma_mps: float | None
    speed_transverse_mps: float | None
    direction_deg: tuple[float | None, float | None]
    direction_sigma_deg: tuple[float | None, float | None]
    flags: tuple[str, ...] = ()
    lag_s: float | None = None
    latency_s: float | None = None
    crop: CropView | None = None

    def summary(self) -> dict[str, Any]:
        """JSON-ready form without the crop (the table's row, the charts' point)."""
        return {
            "index": self.index, "source": self.source, "first_line": self.first_line, "last_line": self.last_line,
            "t_c_s": self.t_c_s, "speed_mps": self.speed_mps, "speed_sigma_mps": self.speed_sigma_mps,
            "speed_transverse_mps": self.speed_transverse_mps,
            "direction_deg": list(self.direction_deg), "direction_sigma_deg": list(self.direction_sigma_deg),
            "flags": list(self.flags), "flag_text": [FLAG_TEXT.get(f, f) for f in self.flags],
            "lag_s": self.lag_s, "latency_s": self.latency_s, "has_crop": self.crop is not None,
        }  # fmt: skip

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready form with the crop (a ball's detail)."""
        d = self.summary()
        d["crop"] = None if self.crop is None else self.crop.to_dict()
        return d

    def table_row(self) -> dict[str, Any]:
        """One row of :data:`TABLE_COLUMNS`."""
        def cell(v: Any) -> Any:
            return "" if v is None else v

        return {
            "ball": self.index, "source": self.source, "first_line": cell(self.first_line), "last_line": cell(self.last_line),
            "t_c_s": cell(self.t_c_s), "speed_mps": cell(self.speed_mps), "speed_sigma_mps": cell(self.speed_sigma_mps),
            "speed_transverse_mps": cell(self.speed_transverse_mps),
            "psi_y_deg": cell(self.direction_deg[0]), "psi_y_sigma_deg": cell(self.direction_sigma_deg[0]),
            "psi_z_deg": cell(self.direction_deg[1]), "psi_z_sigma_deg": cell(self.direction_sigma_deg[1]),
            "flags": " ".join(self.flags), "lag_s": cell(self.lag_s),
        }  # fmt: skip


def ball_from_record(
    record: Mapping[str, Any], index: int, *, source: str = "", lag_s: float | None = None, crop: CropView | None = None
) -> LiveBall:
    """A :class:`LiveBall` from an estimate's JSON record (``ballscan watch``'s line, geometry.md's keys).

    Raises
    ------
    ValueError
        When a key holds a value of the wrong kind.
    """
    return LiveBall(
        index=int(index),
        source=str(record.get("source", source)),
        first_line=_int(record.get("first_line")),
        last_line=_int(record.get("last_line")),
        t_c_s=_num(record.get("t_c_s")),
        speed_mps=_num(record.get("speed_mps")),
        speed_sigma_mps=_num(record.get("speed_sigma_mps")),
        speed_transverse_mps=_num(record.get("speed_transverse_mps")),
        direction_deg=_pair(record.get("direction_deg")),
        direction_sigma_deg=_pair(record.get("direction_sigma_deg")),
        flags=tuple(str(f) for f in record.get("flags") or ()),
        lag_s=lag_s,
        latency_s=_num(record.get("latency_s")),
        crop=crop,
    )


def ball_from_csv_row(row: Mapping[str, str], index: int) -> LiveBall:
    """A :class:`LiveBall` from a row of ``batch``'s CSV (:data:`ballscan.pipeline.report.CSV_COLUMNS`)."""
    return LiveBall(
        index=int(index),
        source=row.get("source", ""),
        first_line=_int(row.get("first_line")),
        last_line=_int(row.get("last_line")),
        t_c_s=_num(row.get("t_c_s")),
        speed_mps=_num(row.get("speed_mps")),
        speed_sigma_mps=_num(row.get("speed_sigma_mps")),
        speed_transverse_mps=_num(row.get("speed_transverse_mps")),
        direction_deg=(_num(row.get("psi_y_deg")), _num(row.get("psi_z_deg"))),
        direction_sigma_deg=(_num(row.get("psi_y_sigma_deg")), _num(row.get("psi_z_sigma_deg"))),
        flags=tuple((row.get("flags") or "").split()),
    )


@dataclass(frozen=True)
class BallFilter:
    """Which balls the page lists: by flag and by speed range.

    Parameters
    ----------
    flag : str
        ``""`` (any ball), ``"none"`` (balls without flags), ``"any"``
        (flagged balls), or one of geometry.md's flag words (balls with it).
    min_speed_mps, max_speed_mps : float or None
        Inclusive speed range, m/s; a ball of undetermined speed is outside
        any range.
    """

    flag: str = ""
    min_speed_mps: float | None = None
    max_speed_mps: float | None = None

    def __post_init__(self) -> None:
        if self.flag not in ("", "none", "any") and self.flag not in FLAG_TEXT:
            raise ValueError(f"flag: expected '', 'none', 'any' or one of {', '.join(FLAG_TEXT)}, got {self.flag!r}")
        for name in ("min_speed_mps", "max_speed_mps"):
            v = getattr(self, name)
            if v is not None and not math.isfinite(v):
                raise ValueError(f"{name}: must be finite, got {v!r}")

    @classmethod
    def from_query(cls, query: Mapping[str, str]) -> BallFilter:
        """From a page's query (``flag``, ``min_mps``, ``max_mps``; empty means no limit)."""
        def num(key: str) -> float | None:
            text = (query.get(key) or "").strip()
            if not text:
                return None
            try:
                return float(text)
            except ValueError:
                raise ValueError(f"{key}: expected a number, got {text!r}") from None

        return cls(query.get("flag", "") or "", num("min_mps"), num("max_mps"))

    def accepts(self, ball: LiveBall) -> bool:
        """True when ``ball`` passes."""
        if self.flag == "none" and ball.flags:
            return False
        if self.flag == "any" and not ball.flags:
            return False
        if self.flag not in ("", "none", "any") and self.flag not in ball.flags:
            return False
        if self.min_speed_mps is None and self.max_speed_mps is None:
            return True
        s = ball.speed_mps
        if s is None:
            return False
        return (self.min_speed_mps is None or s >= self.min_speed_mps) and (self.max_speed_mps is None or s <= self.max_speed_mps)


def table_csv(balls: Iterable[LiveBall]) -> str:
    """The balls as CSV text, :data:`TABLE_COLUMNS` (floats written with ``repr``: they read back exactly)."""
    out = io.StringIO()
    wr = csv.DictWriter(out, fieldnames=TABLE_COLUMNS, lineterminator="\n")
    wr.writeheader()
    for b in balls:
        wr.writerow(b.table_row())
    return out.getvalue()
