"""The live view: a page in the browser over a running watch or a saved run.

:class:`~ballscan.live.hub.LiveHub` sits between the measurement loop and
the page (a bounded ring of balls, the stream's health; the loop never
waits for it); :func:`~ballscan.live.replay.load_run` reads a saved run;
:class:`~ballscan.live.server.LiveServer` serves the page over either
(the optional ``live`` extra: starlette and uvicorn). The page's script is
vendored in ``static/`` and draws everything itself: the server sends
numbers, each ball's crop as grey pixels and its fitted outline.
"""

from .balls import TABLE_COLUMNS, BallFilter, CropView, LiveBall, crop_view, table_csv
from .hub import Health, LiveConfig, LiveHub
from .replay import SavedRun, load_run
from .server import LiveServer, parse_address

__all__ = [
    "TABLE_COLUMNS", "BallFilter", "CropView", "LiveBall", "crop_view", "table_csv",
    "Health", "LiveConfig", "LiveHub", "SavedRun", "load_run", "LiveServer", "parse_address",
]  # fmt: skip
