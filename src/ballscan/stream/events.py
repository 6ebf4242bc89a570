"""A folder of a stream's events (``watch --save-events``): whole files, one writer, checked on restart.

Each ball writes its event's crop (PNG) and the engine's background of the
crop's columns with the lines' times (``.columns.npz``, once per event),
its overlay (PNG) and its JSON. Names are the event's index and stream lines
(``event_00003_lines_5120-5290_ball0.json``), so watching the same stream
again writes the same files: every ball once. Every file is written to a
temporary name and renamed (:mod:`ballscan.outputs`): a crash leaves whole
files only. :meth:`EventFolder.open` takes the folder's lock
(``.ballscan.lock``: a second watch writing the same folder is refused),
removes the temporary files a crash left, and removes the damaged files an
older writer left (a PNG that does not decode, a JSON that does not parse,
an NPZ that does not load), so that their events are written again.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..outputs import OutputLock, atomic_path, atomic_write_text, check_not_symlink, remove_stale_temporaries

if TYPE_CHECKING:
    from ..geometry.camera import LineScanCamera
    from .engine import StreamResult

__all__ = ["EventFolder", "LOCK_NAME"]

#: The lock file inside an event folder.
LOCK_NAME = ".ballscan.lock"


def _damaged(path: Path) -> bool:
    """True when an event file does not read back whole."""
    try:
        if path.suffix == ".json":
            json.loads(path.read_text())
        elif path.suffix == ".npz":
            with np.load(path) as z:
                for k in z.files:
                    z[k]
        elif path.suffix == ".png":
            from PIL import Image

            with Image.open(path) as im:
                im.load()
        return False
    except Exception:  # any decoder's failure means the file is not whole
        return True


class EventFolder:
    """Where a stream's events go; use as a context manager (holds the folder's lock).

    Parameters
    ----------
    folder : path
    force : bool
        Write through event files that are symbolic links (refused otherwise).
    """

    def __init__(self, folder: str | os.PathLike[str], *, force: bool = False) -> None:
        self.folder = Path(folder)
        self.force = force
        self._lock = OutputLock(self.folder / LOCK_NAME, f"{self.folder} (--save-events)")
        self.removed: list[Path] = []

    def open(self) -> "EventFolder":
        """Take the lock, then remove temporary files and damaged event files (listed in ``removed``)."""
        self.folder.mkdir(parents=True, exist_ok=True)
        self._lock.acquire()
        self.removed = remove_stale_temporaries(self.folder)
        for p in sorted(self.folder.glob("event_*")):
            if p.is_file() and not p.is_symlink() and _damaged(p):
                p.unlink()
                self.removed.append(p)
        return self

    def close(self) -> None:
        self._lock.release()

    def __enter__(self) -> "EventFolder":
        return self.open()

    def __exit__(self, *exc: object) -> None:
        self.close()

    def save(self, result: StreamResult, camera: LineScanCamera, ball_in_event: int) -> list[Path]:
        """Write a ball's files (and its event's crop and columns with the event's first ball, or when missing).

        Parameters
        ----------
        result : StreamResult
            Made with ``keep_crops=True`` for the crop and overlay.
        camera : LineScanCamera
            The full camera (the crop's is derived from it).
        ball_in_event : int
            Index of the ball within its event (names the overlay and JSON).

        Returns
        -------
        list of Path
            Files written.
        """
        from ..geometry.camera import crop_camera
        from ..model.render import write_image
        from ..pipeline.plot import save_overlay
        from ..pipeline.results import EstimateReport

        stem = f"event_{result.event_index:05d}_lines_{result.crop_lines[0]}-{result.crop_lines[1]}"
        written = []
        if result.crop is not None:
            png = self.folder / f"{stem}.png"
            if ball_in_event == 0 or not png.is_file():
                with atomic_path(png, force=self.force) as tmp:
                    write_image(tmp, result.crop)
                written.append(png)
            cols = self.folder / f"{stem}.columns.npz"
            if result.crop_columns is not None and (ball_in_event == 0 or not cols.is_file()):
                # the engine's background the estimate used: with it the saved
                # crop gives the same estimate again (estimate_crop(..., columns=))
                with atomic_path(cols, force=self.force) as tmp, open(tmp, "wb") as fh:
                    np.savez(
                        fh,
                        background_dn=result.crop_columns.background_dn,
                        noise_dn=result.crop_columns.noise_dn,
                        times_s=result.crop_times_s,
                        crop_lines=np.asarray(result.crop_lines),
                        crop_cols=np.asarray(result.crop_cols),
                    )
                written.append(cols)
            cam = crop_camera(camera, *result.crop_cols)
            overlay = self.folder / f"{stem}_ball{ball_in_event}.overlay.png"
            est = result.estimate
            with atomic_path(overlay, force=self.force) as tmp:
                save_overlay(
                    tmp, result.crop.astype(float), cam, EstimateReport(png.name, (est,)), result.crop_times_s,
                    first_column=int(result.crop_cols[0]), first_line=int(result.crop_lines[0]),
                )  # fmt: skip
            written.append(overlay)
        js = self.folder / f"{stem}_ball{ball_in_event}.json"
        check_not_symlink(js, self.force)
        atomic_write_text(js, json.dumps(result.to_dict(camera), indent=2, allow_nan=False), force=self.force)
        written.append(js)
        return written
