"""Laws of the expectation rules: each rule of the table reports its own mistake at its key path,
and a state and a number are told apart."""

from __future__ import annotations

import pytest

from playground.level import LevelError, loads

LEVEL = """title = "x"
description = "y"
[settings]
seconds = 2.0
[[props]]
name = "crate"
position = [0, 1]
mass = 1
shapes = [{kind = "box", size = [1, 1]}]
[[actors]]
name = "player"
position = [3, 1]
[[expect]]
"""


def _problems(expect: str) -> list[str]:
    with pytest.raises(LevelError) as info:
        loads(LEVEL + expect)
    return [str(p) for p in info.value.problems]


@pytest.mark.parametrize(
    ("expect", "problem"),
    [
        (
            'body = "crate"\nquantity = "tilt"\nrelative_to = "crat"\nt = 1\nbelow = 1',
            "expect.0.relative_to: no body named 'crat' (did you mean 'crate'?)",
        ),
        (
            'body = "crate"\nquantity = "tilt"\nrelative_to = "player"\nt = 1\nbelow = 1',
            "expect.0.relative_to: only position, velocity, angle and angular_velocity",
        ),
        (
            'body = "crate"\nquantity = "angle"\nchange = true\nt = 1\nbelow = 1',
            "expect.0.change: change needs a window",
        ),
        ('body = "crate"\nquantity = "angle"\nbelow = 1', "expect.0.t: check = 'at' needs a time"),
        ('body = "crate"\nquantity = "angle"\nt = 3\nbelow = 1', "expect.0.t: t = 3.0 s is after"),
        (
            'body = "crate"\nquantity = "angle"\ncheck = "always"\nwindow = [0, 5]\nbelow = 1',
            "expect.0.window: ends after the run's end (2.0 s)",
        ),
        (
            'body = "crate"\nquantity = "state"\nt = 1\nequals = "grounded"',
            "expect.0.quantity: 'crate' is not an actor: it has no state",
        ),
        (
            'body = "player"\nquantity = "state"\ncheck = "mean"\nequals = "grounded"',
            "expect.0.check: a state has no mean",
        ),
        (
            'body = "player"\nquantity = "state"\ncheck = "impulse"\nequals = "grounded"',
            "expect.0.check: a state has no impulse",
        ),
        (
            'body = "player"\nquantity = "position"\ncomponent = "y"\ncheck = "impulse"\nbelow = 1',
            "expect.0.check: an impulse integrates a force, not position",
        ),
        (
            'body = "player"\nquantity = "hover"\ncheck = "impulse"\nwindow = [1, 1]\n'
            "equals = [0, 1]",
            "expect.0.window: an impulse needs a window of some length",
        ),
        ('body = "crate"\nquantity = "angle"\nt = 1', "expect.0: nothing to compare"),
        (
            'body = "crate"\nquantity = "angle"\nt = 1\nequals = 0\nbelow = 1',
            "expect.0: give equals (± tolerance) or above/below bounds, not both",
        ),
        (
            'body = "crate"\nquantity = "angle"\ncomponent = "x"\nt = 1\nbelow = 1',
            "expect.0.component: angle is a number; it has no component",
        ),
        (
            'body = "crate"\nquantity = "support"\ncomponent = "y"\nt = 1\nbelow = 1',
            "expect.0.body: 'crate' is not tracked; add it to tracking.bodies",
        ),
        (
            'body = "player"\nquantity = "angle"\nfiltered = true\nt = 1\nbelow = 1',
            "expect.0.filtered: only force readings are filtered, not angle",
        ),
        (
            'body = "player"\nquantity = "angle"\nt = 1\nbelow = 1\n'
            'minus = {body = "player", quantity = "velocity"}',
            "expect.0.minus.quantity: velocity and angle are not both vectors or both numbers",
        ),
        (
            'body = "player"\nquantity = "velocity"\nt = 1\nbelow = 1\nangle_to = [0, 0]',
            "expect.0.angle_to: a zero vector has no direction",
        ),
        (
            'body = "player"\nquantity = "velocity"\nt = 1\nbelow = 1\n'
            'angle_to = {body = "player", quantity = "tilt"}',
            "expect.0.angle_to.quantity: tilt is not a vector",
        ),
        (
            'body = "player"\nquantity = "velocity"\nt = 1\nbelow = 1',
            "expect.0.component: bounds need a component: x, y or norm",
        ),
        (
            'body = "player"\nquantity = "velocity"\nt = 1\nequals = 1',
            "expect.0.equals: velocity is a vector: give [x, y] or a component",
        ),
        (
            'body = "player"\nquantity = "angle"\nt = 1\nequals = [1, 0]',
            "expect.0.equals: expected a number for a component, angle or scalar",
        ),
        (
            'body = "player"\nquantity = "hover"\nt = 1\nequals = [0, 1]\nweights_of = "crat"',
            "expect.0.weights_of: no body named 'crat' (did you mean 'crate'?)",
        ),
        (
            'body = "player"\nquantity = "angle"\nt = 1\nbelow = 1\nweights_of = "player"',
            "expect.0.weights_of: only a force is counted in a body's mass or weight, not angle",
        ),
        (
            'body = "player"\nquantity = "hover"\nt = 1\nbelow = 1\nangle_to = [0, 1]\n'
            'per_mass_of = "player"',
            "expect.0.per_mass_of: only a force is counted in a body's mass or weight, not an "
            "angle",
        ),
        (
            'body = "player"\nquantity = "hover"\nt = 1\nequals = [0, 1]\nweights_of = "player"\n'
            'per_mass_of = "player"',
            "expect.0: give weights_of or per_mass_of, not both",
        ),
    ],
)
def test_each_rule_reports_its_mistake_at_its_key_path(expect: str, problem: str) -> None:
    """Law: a level with one mistake in an expectation gets that rule's problem, key path first."""
    problems = _problems(expect)
    assert any(p.startswith(problem) for p in problems), problems


def test_an_unknown_body_stops_the_rules() -> None:
    """Law: the rules say nothing more about an expectation on a body that does not exist."""
    assert _problems('body = "crat"\nquantity = "angle"') == [
        "expect.0.body: no body named 'crat' (did you mean 'crate'?)"
    ]


def test_every_problem_is_reported_in_the_order_of_the_table() -> None:
    """Law: several mistakes in one expectation are reported together, timing before value."""
    problems = _problems('body = "crate"\nquantity = "angle"\ncomponent = "x"\nequals = [1, 0]')
    assert [p.split(":")[0] for p in problems] == [
        "expect.0.t",
        "expect.0.component",
        "expect.0.equals",
    ]
