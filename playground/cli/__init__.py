"""The ``playground`` command: list, check and run levels headless, export the level schema.

Each subcommand lives in the module of its concept, as a function ``cmd_<name>(args) -> exit
code`` and an ``add(subparsers)`` that declares its arguments: :mod:`~playground.cli.levelfiles`
(``list``, ``check``, ``schema``), :mod:`~playground.cli.running` (``run``),
:mod:`~playground.cli.breaks` (``faults``), :mod:`~playground.cli.pictures` (``play``,
``gifs``); ``bench`` is :mod:`playground.cli.bench`. :mod:`~playground.cli.parser`
assembles them and dispatches; :mod:`~playground.cli.exits` maps every error to a one-line message
on stderr and an exit code, in one place: 0 ok; 1 a check failed (or a level did not validate, for
``check``); 2 bad input or environment; 3 an internal error (the traceback written to a file); 130
interrupted (Ctrl-C).

>>> main(["check", "incline"])
ok      incline: Incline
0
"""

from playground.cli.exits import (
    EXIT_FAILED,
    EXIT_INTERNAL,
    EXIT_INTERRUPTED,
    EXIT_OK,
    EXIT_USAGE,
)
from playground.cli.levelfiles import schema_text
from playground.cli.parser import main, parser
from playground.cli.running import PROGRESS_MIN_STEPS

__all__ = [
    "EXIT_FAILED",
    "EXIT_INTERNAL",
    "EXIT_INTERRUPTED",
    "EXIT_OK",
    "EXIT_USAGE",
    "PROGRESS_MIN_STEPS",
    "main",
    "parser",
    "schema_text",
]
