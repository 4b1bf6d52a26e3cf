"""Where the chapters' numbers and figures are declared (docs/chapters): a chapter module marks
each function that computes a quoted number with :func:`number` and its figure with
:func:`figure`, once, and the tables below fill themselves as the modules are imported."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TypeVar

Number = Callable[[], float]
"""A number a chapter quotes: computed on demand, in the unit the text states."""

Figure = Callable[[Path], Path]
"""A chapter figure: draws a PNG at the path given and returns it."""

NUMBERS: dict[str, Number] = {}
"""Every number the chapters quote, by the name their ``<!-- num:NAME -->`` markers use."""

FIGURES: dict[str, Figure] = {}
"""Every chapter figure, by file name (under docs/img/chapters)."""

N = TypeVar("N", bound=Number)
F = TypeVar("F", bound=Figure)
T = TypeVar("T")


def register(table: dict[str, T], name: str, entry: T) -> None:
    """Put ``entry`` in ``table`` under ``name``, which must be new.

    >>> table: dict[str, int] = {}
    >>> register(table, "one", 1)
    >>> table
    {'one': 1}
    >>> register(table, "one", 2)
    Traceback (most recent call last):
    ...
    ValueError: 'one' is declared twice
    """
    if name in table:
        raise ValueError(f"{name!r} is declared twice")
    table[name] = entry


def number(fn: N) -> N:
    """Declare ``fn`` a quoted number, under its own name in :data:`NUMBERS`."""
    entry: Number = fn  # widened to the table's type: a dict's values are invariant
    register(NUMBERS, fn.__name__, entry)
    return fn


def figure(name: str) -> Callable[[F], F]:
    """Declare the decorated function the figure ``name`` (a file name) in :data:`FIGURES`."""

    def declare(fn: F) -> F:
        entry: Figure = fn  # widened to the table's type, as above
        register(FIGURES, name, entry)
        return fn

    return declare
