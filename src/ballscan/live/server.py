"""The live page's web server: starlette routes served by uvicorn on a thread of their own.

Every route is a GET (nothing on disk changes): the page and its vendored
script (``static/``), ``/api/info``, ``/api/balls`` (the listed balls,
filtered by flag and speed range, ``.csv`` for the download),
``/api/ball/{index}`` (one ball with its crop and outline), ``/api/health``
and ``/events``, a server-sent event stream of each new ball and, every half
second, the stream's health. The store is a :class:`~ballscan.live.hub.LiveHub`
(a live run) or a :class:`~ballscan.live.replay.SavedRun` (a saved one).

The server runs its own event loop on a daemon thread: the measurement loop
only hands balls to the hub, and a slow or closed browser holds nothing but
its own connection (it reads the hub's ring from its own cursor).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import socket
import threading
import time
from pathlib import Path
from typing import Any

from ..errors import BallscanError
from ..pipeline.report import FLAG_TEXT, UNITS
from .balls import BallFilter, table_csv

__all__ = ["STATIC", "parse_address", "build_app", "LiveServer", "LiveWatch"]

#: The page and its script, shipped with the package.
STATIC = Path(__file__).resolve().parent / "static"
#: Seconds between health messages on the event stream.
HEALTH_EVERY_S = 0.5


def _import_web():
    try:
        import starlette  # noqa: F401
        import uvicorn  # noqa: F401
    except ImportError:
        raise BallscanError("the live view needs the 'live' extra: pip install 'ballscan[live]' (starlette and uvicorn)") from None


def parse_address(text: str) -> tuple[str, int]:
    """``[HOST:]PORT`` -> ``(host, port)``; the host defaults to 127.0.0.1 (this machine only).

    ``[::1]:8000`` names an IPv6 host; port 0 picks a free port.

    Raises
    ------
    ValueError
        A port that is not an integer in 0..65535, or an empty host.
    """
    host, sep, port = str(text).strip().rpartition(":")
    if not sep:
        host = "127.0.0.1"
    host = host.strip("[]")
    if sep and not host:
        raise ValueError(f"--serve: expected [HOST:]PORT, got {text!r} (an empty host)")
    try:
        p = int(port)
    except ValueError:
        raise ValueError(f"--serve: expected [HOST:]PORT with an integer port, got {text!r}") from None
    if not 0 <= p <= 65535:
        raise ValueError(f"--serve: port must be in 0..65535, got {p}")
    return host, p


def _sse(event: str, data: Any) -> str:
    return f"event: {event}\ndata: {json.dumps(data, allow_nan=False, separators=(',', ':'))}\n\n"


class _Pump:
    """On the server's loop: turns the hub's new balls into ring entries and wakes the event streams.

    The streams wait on a future shared by all of them and replaced at each
    round, never on a shared lock: a viewer that closes its page cancels
    its stream at any await, and the cancellation must leave the other
    streams untouched (an ``asyncio.Condition`` waited on with a timeout
    can have its lock released by a cancelled waiter and then fail in
    another viewer's stream, ending it).
    """

    def __init__(self, store: Any) -> None:
        self.store = store
        self.wake = asyncio.Event()
        self._changed: asyncio.Future | None = None  # done at the pump's next round (made on the loop, on first use)
        self.closing = False
        self._encoded: dict[int, str] = {}  # a ball's event, encoded once for every viewer
        self._health: tuple[float, str] = (-1.0, "")

    def ball_event(self, ball: Any) -> str:
        """The ball's server-sent event (encoded once; the last few kept)."""
        text = self._encoded.get(ball.index)
        if text is None:
            text = self._encoded[ball.index] = _sse("ball", ball.to_dict())
            for k in sorted(self._encoded)[:-64]:
                del self._encoded[k]
        return text

    def health_event(self) -> str:
        """The health's server-sent event (made at most every half second, for every viewer)."""
        t, text = self._health
        now = time.monotonic()
        if now - t >= HEALTH_EVERY_S * 0.9:
            text = _sse("health", self.store.health().to_dict())
            self._health = (now, text)
        return text

    async def run(self) -> None:
        loop = asyncio.get_running_loop()
        if hasattr(self.store, "set_wake"):
            self.store.set_wake(lambda: loop.call_soon_threadsafe(self.wake.set))
        while not self.closing:
            with contextlib.suppress(asyncio.TimeoutError):
                await asyncio.wait_for(self.wake.wait(), HEALTH_EVERY_S)
            self.wake.clear()
            made = self.store.drain() if hasattr(self.store, "drain") else 0
            if made:
                self._health = (-1.0, "")  # the ball count changed: a fresh health for the next viewer
            self.notify()
            if made:
                await asyncio.sleep(0)

    def changed(self) -> asyncio.Future:
        """A future done at the pump's next round (on the server's loop); a waiter must not cancel it (``asyncio.wait`` does not)."""
        if self._changed is None or self._changed.done():
            self._changed = asyncio.get_running_loop().create_future()
        return self._changed

    def notify(self) -> None:
        """Wake every stream waiting on :meth:`changed`."""
        fut, self._changed = self._changed, None
        if fut is not None and not fut.done():
            fut.set_result(None)


async def _event_stream(store: Any, pump: _Pump, cursor: int):
    """One viewer's server-sent events: each ball newer than ``cursor`` (from the ring, at the viewer's pace) and the health every half second."""
    last_health = 0.0
    while not pump.closing:
        if hasattr(store, "balls_after"):
            new, skipped = store.balls_after(cursor)
            if skipped:
                yield _sse("skipped", {"balls": skipped})
            for b in new:
                cursor = b.index
                yield pump.ball_event(b)
        now = time.monotonic()
        if now - last_health >= HEALTH_EVERY_S:
            last_health = now
            yield pump.health_event()
        await asyncio.wait((pump.changed(),), timeout=HEALTH_EVERY_S)


def build_app(store: Any, *, title: str = "ballscan"):
    """The starlette application over ``store`` (a live hub or a saved run)."""
    _import_web()
    from starlette.applications import Starlette
    from starlette.responses import FileResponse, JSONResponse, PlainTextResponse, Response, StreamingResponse
    from starlette.routing import Mount, Route
    from starlette.staticfiles import StaticFiles

    pump = _Pump(store)
    nocache = {"Cache-Control": "no-store"}

    def selection(request) -> BallFilter:
        return BallFilter.from_query(request.query_params)

    async def index(request):
        return FileResponse(STATIC / "index.html", headers=nocache)

    async def info(request):
        return JSONResponse(
            {"mode": store.mode, "title": title, "units": {k: v for k, v in UNITS.items()}, "flags": FLAG_TEXT, "health_every_s": HEALTH_EVERY_S},
            headers=nocache,
        )

    async def balls(request):
        try:
            chosen = store.balls(selection(request))
        except ValueError as exc:
            return PlainTextResponse(str(exc), status_code=400)
        return JSONResponse({"balls": [b.summary() for b in chosen]}, headers=nocache)

    async def balls_csv(request):
        try:
            chosen = store.balls(selection(request))
        except ValueError as exc:
            return PlainTextResponse(str(exc), status_code=400)
        head = {"Content-Disposition": 'attachment; filename="balls.csv"', **nocache}
        return Response(table_csv(chosen), media_type="text/csv", headers=head)

    async def ball(request):
        b = store.ball_detail(int(request.path_params["index"]))
        if b is None:
            return PlainTextResponse("no such ball (it may have left the ring of recent balls)", status_code=404)
        return JSONResponse(b.to_dict(), headers=nocache)

    async def health(request):
        return JSONResponse(store.health().to_dict(), headers=nocache)

    async def events(request):
        try:
            cursor = int(request.query_params.get("after", "-1"))
        except ValueError:
            return PlainTextResponse("after: expected a ball index", status_code=400)

        head = {"X-Accel-Buffering": "no", **nocache}
        return StreamingResponse(_event_stream(store, pump, cursor), media_type="text/event-stream", headers=head)

    @contextlib.asynccontextmanager
    async def lifespan(app):
        task = asyncio.create_task(pump.run())
        try:
            yield
        finally:
            pump.closing = True
            task.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await task

    routes = [
        Route("/", index),
        Route("/api/info", info),
        Route("/api/balls", balls),
        Route("/api/balls.csv", balls_csv),
        Route("/api/ball/{index:int}", ball),
        Route("/api/health", health),
        Route("/events", events),
        Mount("/static", app=StaticFiles(directory=STATIC), name="static"),
    ]
    app = Starlette(routes=routes, lifespan=lifespan)
    app.state.pump = pump
    return app


class LiveServer:
    """Serve the page over ``store`` on a daemon thread.

    Parameters
    ----------
    store : LiveHub or SavedRun
    host : str
        Address to listen on (127.0.0.1: this machine only).
    port : int
        0 picks a free port (:attr:`url` says which).
    title : str
        The page's title.
    """

    def __init__(self, store: Any, host: str = "127.0.0.1", port: int = 8000, *, title: str = "ballscan") -> None:
        _import_web()
        self.store = store
        self.host = host
        self.port = int(port)
        self.title = title
        self._server = None
        self._app = None
        self._thread: threading.Thread | None = None

    @property
    def url(self) -> str:
        """The page's address."""
        host = f"[{self.host}]" if ":" in self.host else self.host
        return f"http://{host}:{self.port}/"

    def start(self, timeout_s: float = 10.0) -> str:
        """Listen and serve; return the page's address once the server answers.

        Raises
        ------
        BallscanError
            The address cannot be listened on (in use, not this machine's).
        """
        import uvicorn

        family = socket.AF_INET6 if ":" in self.host else socket.AF_INET
        sock = socket.socket(family, socket.SOCK_STREAM)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            sock.bind((self.host, self.port))
        except OSError as exc:
            sock.close()
            raise BallscanError(f"--serve {self.host}:{self.port}: cannot listen there ({exc.strerror or exc})") from None
        self.port = int(sock.getsockname()[1])
        self._app = build_app(self.store, title=self.title)
        config = uvicorn.Config(
            self._app, log_level="warning", access_log=False, lifespan="on",
            timeout_graceful_shutdown=1,
        )  # fmt: skip
        self._server = uvicorn.Server(config)
        self._thread = threading.Thread(target=self._server.run, kwargs={"sockets": [sock]}, name="ballscan-live", daemon=True)
        self._thread.start()
        t_end = time.monotonic() + timeout_s
        while not self._server.started:
            if not self._thread.is_alive() or time.monotonic() > t_end:
                raise BallscanError(f"--serve {self.host}:{self.port}: the server did not start")
            time.sleep(0.01)
        return self.url

    @property
    def serving(self) -> bool:
        """True while the server's thread runs."""
        return self._thread is not None and self._thread.is_alive() and self._server is not None

    def stop(self, timeout_s: float = 3.0) -> None:
        """Stop serving (open event streams are closed)."""
        if self._server is None:
            return
        self._app.state.pump.closing = True  # the event streams end at their next wake-up
        self._server.should_exit = True
        if self._thread is not None:
            self._thread.join(timeout_s)
        self._server = None


class LiveWatch:
    """A live view of a running watch: the hub the measurement loop feeds and the server over it.

    Parameters
    ----------
    camera : LineScanCamera
        The stream's camera.
    address : str
        ``[HOST:]PORT`` (:func:`parse_address`).
    dropped_lines : callable, optional
        The source's lost lines so far.
    title : str
        The page's title.
    config : LiveConfig, optional
    """

    def __init__(self, camera: Any, address: str, *, dropped_lines: Any = None, title: str = "ballscan watch", config: Any = None) -> None:
        from .hub import LiveHub

        host, port = parse_address(address)
        self.hub = LiveHub(camera, config, dropped_lines=dropped_lines)
        self.server = LiveServer(self.hub, host, port, title=title)

    def start(self) -> str:
        """Serve; return the page's address."""
        return self.server.start()

    def end(self, error: BaseException | None = None) -> None:
        """The stream ended (with ``error``, its fault): the page's banner says so."""
        lines = self.hub.health().lines
        if error is None or isinstance(error, KeyboardInterrupt):
            why = "interrupted" if error is not None else "the source ended"
            self.hub.end(f"{why} after {lines:,d} lines")
        else:
            self.hub.end(f"stopped after {lines:,d} lines: {error}", failed=True)

    def linger(self, stop: Any = None) -> None:
        """Keep serving the ended run until Ctrl-C (or ``stop.is_set()``, for a caller that turns signals into a flag), then stop."""
        try:
            while self.server.serving and not (stop is not None and stop.is_set()):
                time.sleep(0.2)
        except KeyboardInterrupt:
            pass
        finally:
            self.server.stop()
