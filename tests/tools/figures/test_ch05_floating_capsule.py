"""Laws of chapter 5's numbers (:mod:`tools.figures.ch05_floating_capsule`):
the exercises' answers and the chapter's claims, checked against the code that computes them."""

from __future__ import annotations

import math

from tools.figures import ch05_floating_capsule as ch5

TOL_LIMIT = 0.01
"""On 2πf·dt: the bisection's resolution (1e-3) plus the slow growth right at the limit."""

TOL_GROWTH = 0.01
"""Relative, on a growth per step: the peak-to-peak measurement samples peaks at whole steps, a
fraction of a step off the true crest (measured 0.08 % apart at 5 Hz, 1/120 s)."""


def test_exercise_5_stability_limit_is_two_zeta_plus_two_root() -> None:
    """Chapter 5: with the spring read where pymunk's integrator uses it and the damper on the
    velocity after the step, the hover is stable while 2πf·dt < 2ζ + 2√(ζ² + 1), and an undamped
    one neither gains nor loses energy."""
    assert abs(ch5.ch5_limit_zeta1() - (2.0 + 2.0 * math.sqrt(2.0))) < TOL_LIMIT
    assert abs(ch5.ch5_limit_zeta05() - (1.0 + math.sqrt(5.0))) < TOL_LIMIT
    assert abs(ch5.ch5_undamped_per_second() - 1.0) < TOL_LIMIT


def test_exercise_5_a_shove_below_the_threshold_is_recovered() -> None:
    """Chapter 5's exercise: a 140 N·s shove (below the measured threshold) does not knock the
    player over; one at the threshold does."""
    assert ch5.shove(140.0)[0] is False
    assert ch5.shove(ch5.ch5_knockover())[0] is True


def test_naive_spring_is_explicit_euler() -> None:
    """Chapter 5: the naive spring −kx − cv is explicit Euler: stable only while 2πf·dt < 2ζ, and
    undamped it grows by √(1 + (2πf·dt)²) every step."""
    assert abs(ch5.ch5_explicit_limit_zeta1() - 2.0) < TOL_LIMIT
    growth = ch5.ch5_explicit_undamped_per_step()
    theory = ch5.ch5_explicit_undamped_theory()
    assert abs(growth - theory) < TOL_GROWTH * theory
    assert theory > 1.0
