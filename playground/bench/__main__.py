"""``python -m playground.bench``: see :mod:`playground.bench.cli`."""

import sys

from playground.bench.cli import main

sys.exit(main())
