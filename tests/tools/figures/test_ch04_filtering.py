"""Laws of chapter 4's numbers (:mod:`tools.figures.ch04_filtering`):
the exercises' answers and the chapter's claims, checked against the code that computes them."""

from __future__ import annotations

import math

from tools.figures import ch04_filtering as ch4
from tools.figures.runs import DT, G

TOL_FIXED_POINT = 0.01
"""Relative: the 1€ filter's simulated ramp lag against the fixed point L = 1/(2π(min_cutoff +
β·s·(1 + L/Te))) (the issue's 1 %; the fixed point is the steady state, and after the ramp's one
second the derivative smoother at 1 Hz has settled to e^(−2π) ≈ 0.2 % of its start)."""


def test_exercise_4_median_of_3_removes_a_one_step_spike() -> None:
    """Chapter 4: a one-step spike passes the 1€ filter at most of its height, not the median."""
    assert ch4.ch4_spike_median() == 0.0
    assert ch4.ch4_spike_euro() > 0.5 * ch4.SPIKE


def test_exercise_4_without_the_spike_stage_the_bounce_check_fails() -> None:
    """Chapter 4's exercise: with spike_filter off, the bounce level's spike check fails."""
    from playground.level import find, load
    from playground.scene import build
    from playground.scene.checks import watch

    level = load(find("bounce"))
    perception = level.tracking.perception.model_copy(update={"spike_filter": False})
    tracking = level.tracking.model_copy(update={"perception": perception})
    scene = build(level.model_copy(update={"tracking": tracking}))
    checks = watch(scene)
    scene.run(level.settings.seconds)
    verdict = {r.name: r.passed for r in checks.results()}
    assert verdict["spikes stay out of the filtered support"] is False
    assert verdict["the highest ball never outruns its free fall"] is True


def test_euro_lag_is_the_fixed_point() -> None:
    """Chapter 4: the 1€ filter's lag on a ramp solves L = 1/(2π(min_cutoff + β·s·(1 + L/Te))),
    the derivative being taken against the previous filtered value (perception's filter and the
    tuned one)."""
    for measured, fixed in (
        (ch4.ch4_lag_euro(), ch4.ch4_lag_euro_fixed()),
        (ch4.ch4_tuned_lag(), ch4.ch4_tuned_lag_fixed()),
    ):
        assert abs(measured - fixed) < TOL_FIXED_POINT * fixed, (measured, fixed)
    beta_zero = ch4.euro_ramp_lag(2.0, 0.0, G, DT)
    assert math.isclose(beta_zero, 1.0 / (2.0 * math.pi * 2.0), rel_tol=1e-9)
