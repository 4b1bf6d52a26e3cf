"""``python -m playground.cli``: the ``playground`` command."""

import sys

from playground.cli.parser import main

sys.exit(main())
