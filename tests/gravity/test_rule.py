"""Laws of gravity rules (:mod:`playground.gravity.rule`): the one formula gives the same bits
for one body in plain floats, for a rule's :meth:`~playground.gravity.GravityRule.apply` and for
rows of bodies (:func:`~playground.gravity.apply_rules`)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from playground.gravity import GravityRule, apply_rules
from playground.gravity.rule import ruled

RNG = np.random.default_rng(3)
N = 500
FIELD = RNG.normal(size=(N, 2)) * 10.0 ** RNG.uniform(-3.0, 3.0, (N, 1))
"""Field values over six decades of magnitude, m/s²."""
SCALE = RNG.choice([0.0, 0.5, 1.0, 2.0, -1.0], N)
DIRECTION = np.where(RNG.random((N, 1)) < 0.5, np.nan, RNG.normal(size=(N, 2)))
"""Half the bodies keep the field's direction (NaN rows)."""


def _direction(i: int) -> tuple[float, float] | None:
    d = DIRECTION[i]
    return None if math.isnan(d[0]) else (float(d[0]), float(d[1]))


def test_one_body_in_floats_gives_what_the_rows_give() -> None:
    """Law: scale and own direction, one body at a time, equal the vectorised rules bit for
    bit (the magnitude is the C library's hypot, as numpy's)."""
    want = apply_rules(FIELD, SCALE, DIRECTION)
    for i in range(N):
        got = ruled(float(FIELD[i, 0]), float(FIELD[i, 1]), float(SCALE[i]), _direction(i))
        assert got == (want[i, 0], want[i, 1]), i


def test_a_rule_applies_what_the_rows_give_for_it() -> None:
    """Law: :meth:`GravityRule.apply` gives, bit for bit, the row ``apply_rules`` gives a body
    with that rule (its direction made a unit vector once, by the rule)."""
    rules = [GravityRule(float(SCALE[i]), _direction(i)) for i in range(N)]
    direction = np.array([r.direction or (np.nan, np.nan) for r in rules])
    want = apply_rules(FIELD, SCALE, direction)
    for i, rule in enumerate(rules):
        assert rule.apply(float(FIELD[i, 0]), float(FIELD[i, 1])) == (want[i, 0], want[i, 1]), i


@pytest.mark.parametrize("scale", [0.0, 0.5, 2.0])
def test_scale_scales_and_a_direction_keeps_the_magnitude(scale: float) -> None:
    """The rule's meaning: ``scale · g``; with a direction, ``scale · |g|`` along it."""
    assert GravityRule(scale).apply(3.0, -4.0) == (3.0 * scale, -4.0 * scale)
    assert GravityRule(scale, (0.0, 1.0)).apply(3.0, -4.0) == (0.0, 5.0 * scale)
