"""``python -m tools``: the repository's page and figure generators (see :mod:`tools.cli`)."""

import sys

from tools.cli import main

sys.exit(main())
