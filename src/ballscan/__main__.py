"""``python -m ballscan``: the ``ballscan`` command."""

import sys

from .cli import main

sys.exit(main())
