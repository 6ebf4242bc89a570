"""``python -m ballscan``: the ``ballscan`` command."""

from .cli import run

run()
