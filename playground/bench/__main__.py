"""``python -m playground.bench``: see :mod:`playground.cli.bench`."""

import sys

from playground.cli.bench import main

sys.exit(main())
