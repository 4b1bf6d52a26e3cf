"""Faults: named breaks of one feature each, and the matrix of which level checks catch them.

A *break* is a small, reversible change to one feature of the playground — the hover's reaction
cut, the drive reading the world instead of the ground, the inner ear turned by 30° — applied as a
context manager that patches one method or one config value of a class and restores it on exit.
It never touches a file. A level declares the breaks its checks must catch (``catches = [...]``);
:func:`matrix` runs each level clean and under each declared break and reports which checks
caught it. A check that passes while its feature is broken checks nothing.

Each concept has its module: :mod:`~playground.faults.catalog` (the breaks by name),
:mod:`~playground.faults.patching` (how a break patches), :mod:`~playground.faults.breaks` (the
breaks themselves, registered when the package is imported) and :mod:`~playground.faults.matrix`
(running levels under them).

Patches are process-wide (class attributes): run one broken scene at a time, in one thread.

>>> from playground.movers import Spin
>>> with apply("ring_spin_stopped"):
...     Spin(rate=1.5).pose(2.0)
((0.0, 0.0), 0.0)
>>> Spin(rate=1.5).pose(2.0)
((0.0, 0.0), 3.0)
"""

from playground.faults import breaks
from playground.faults.catalog import BREAKS, Break, BreakError, apply, names
from playground.faults.matrix import Outcome, Row, matrix, run

__all__ = [
    "BREAKS",
    "Break",
    "BreakError",
    "Outcome",
    "Row",
    "apply",
    "breaks",
    "matrix",
    "names",
    "run",
]
