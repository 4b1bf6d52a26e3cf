"""Laws of the matrix: every shipped level passes clean and fails under each break it declares
(the whole matrix, as `playground faults` runs it); a declared break that goes uncaught fails it."""

from __future__ import annotations

import hashlib

from playground import faults
from playground.level import load, loads, shipped


def test_the_matrix_is_green() -> None:
    """Every shipped level passes clean and fails under each break it declares; the level files
    are read, never written."""
    paths = shipped()
    before = {name: hashlib.sha256(p.read_bytes()).hexdigest() for name, p in paths.items()}
    rows = faults.matrix([(name, load(p)) for name, p in paths.items()])
    bad = [
        f"{o.level} / {o.fault or 'clean'}: {o.error or o.failed or 'no check failed'}"
        for row in rows
        for o in (row.clean, *row.breaks)
        if not o.ok
    ]
    assert not bad, "\n".join(bad)
    after = {name: hashlib.sha256(p.read_bytes()).hexdigest() for name, p in paths.items()}
    assert after == before


def test_a_declared_break_that_goes_uncaught_is_reported() -> None:
    """A level that declares a break its checks cannot see fails the matrix."""
    level = loads(
        'title = "x"\ndescription = "y"\ncatches = ["ring_spin_stopped"]\n'
        "[[geometry]]\nkind = 'segment'\na = [-5, 0]\nb = [5, 0]\n"
        "[[actors]]\nname = 'player'\nposition = [0, 0.95]\n"
        "[[expect]]\nbody = 'player'\nquantity = 'state'\nt = 1.0\nequals = 'grounded'\n"
    )
    (row,) = faults.matrix([("x", level)])
    assert row.clean.ok and not row.ok
    assert row.breaks[0].failed == () and row.breaks[0].declared
