"""``python -m playground``: the ``playground`` command (see :mod:`playground.cli`)."""

import sys

from playground.cli import main

sys.exit(main())
