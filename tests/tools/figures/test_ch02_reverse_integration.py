"""Laws of chapter 2's numbers (:mod:`tools.figures.ch02_reverse_integration`):
the exercises' answers and the chapter's claims, checked against the code that computes them."""

from __future__ import annotations

import math

from tools.figures import ch02_reverse_integration as ch2
from tools.figures.runs import DT


def test_exercise_2_ghost_force_is_the_forgotten_damping() -> None:
    """Chapter 2: the naive estimate's first-step force is −m·(1 − d)·v₀/h."""
    d = ch2.SLIDE_DAMPING**DT
    expected = -10.0 * (1.0 - d) * 3.0 / DT
    assert math.isclose(ch2.ch2_ghost_force(), expected, rel_tol=1e-6)
