"""Laws of chapter 3's numbers (:mod:`tools.figures.ch03_perceived_gravity`):
the exercises' answers and the chapter's claims, checked against the code that computes them."""

from __future__ import annotations

from tools.figures import ch03_perceived_gravity as ch3

TOL_RING = 0.01
"""Relative: spinning_ring's player, perceived gravity against ω²·r at its centre (the 1€
filter's lag on a vector turning with the ring shortens it by under 0.3 %; the level's own check
allows 1 %)."""


def test_exercise_3_twice_the_spin_four_times_the_gravity() -> None:
    """Chapter 3: perceived gravity in the ring is ω²·r, so doubling ω quadruples it."""
    for rate in (1.5, 3.0):
        felt, exact = ch3.ring_reading(rate)
        assert abs(felt - exact) < TOL_RING * exact
    assert abs(ch3.ch3_ring_ratio() - 4.0) < 4.0 * 2 * TOL_RING
