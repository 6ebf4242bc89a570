"""The ``ballscan`` command, a thin layer over the library."""

from .app import app, main, run

__all__ = ["app", "main", "run"]
