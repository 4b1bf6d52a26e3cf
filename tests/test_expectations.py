"""Laws of the expectation kinds: another body's reading (``minus``), the angle between two
vectors (``angle_to``) and a controller's own readings, on scenes whose answers are exact."""

from __future__ import annotations

import math

import pytest

from playground.expectations import watch
from playground.level import LevelError, loads
from playground.scene import build

TOL_ANGLE = 1e-9
"""rad: the idle player's support is m·g straight up to round-off (its hover carries it all)."""

REST = """
title = "Rest"
description = "An idle player."
[settings]
seconds = 2.0
[[geometry]]
kind = "segment"
a = [-5.0, 0.0]
b = [5.0, 0.0]
[[actors]]
name = "player"
position = [0.0, 0.95]
"""


def _results(expect: str) -> list[tuple[bool, str]]:
    scene = build(loads(REST + expect))
    checks = watch(scene)
    scene.run(scene.level.settings.seconds)
    return [(r.passed, r.detail) for r in checks.results()]


def test_angle_to_a_fixed_direction_is_the_angle_between_them() -> None:
    """Standing still, the support points straight up: 0 rad from [0, 1], π/4 from [1, 1]."""
    (up, diagonal) = _results(
        f"""
[[expect]]
body = "player"
quantity = "support"
angle_to = [0.0, 1.0]
check = "always"
window = [1.0, 2.0]
below = {TOL_ANGLE}

[[expect]]
body = "player"
quantity = "support"
angle_to = [1.0, 1.0]
check = "at"
t = 2.0
equals = {math.pi / 4}
tolerance = {TOL_ANGLE}
"""
    )
    assert up[0], up[1]
    assert diagonal[0], diagonal[1]


def test_angle_to_another_reading_and_a_flipped_one() -> None:
    """The hover pushes the way the support points (0 rad) and against the gravity the player
    perceives (scale −1 flips it: again 0 rad)."""
    results = _results(
        f"""
[[expect]]
body = "player"
quantity = "hover"
angle_to = {{ body = "player", quantity = "support" }}
check = "always"
window = [1.0, 2.0]
below = {TOL_ANGLE}

[[expect]]
body = "player"
quantity = "hover"
angle_to = {{ body = "player", quantity = "perceived_gravity", scale = -1.0 }}
check = "at"
t = 2.0
below = 1e-6
"""
    )
    assert all(ok for ok, _ in results), results


def test_minus_another_reading_and_a_failure_says_by_how_much() -> None:
    """support − hover = 0 for an idle player (nothing else holds it); support − 2·hover is
    −hover, and the failure names the check, the expected and the got values."""
    (zero, off) = _results(
        """
[[expect]]
body = "player"
quantity = "support"
minus = { body = "player", quantity = "hover" }
check = "always"
window = [1.0, 2.0]
equals = [0.0, 0.0]
tolerance = 1e-6

[[expect]]
body = "player"
quantity = "support"
minus = { body = "player", quantity = "hover", scale = 2.0 }
component = "y"
check = "at"
t = 2.0
equals = 0.0
tolerance = 1.0
"""
    )
    assert zero[0], zero[1]
    assert not off[0]
    assert "player.support-2·player.hover.y at 2 s" in off[1] and "-686.7" in off[1]


@pytest.mark.parametrize(
    ("expect", "where", "message"),
    [
        (
            'body = "floor"\nquantity = "hover"\nt = 1.0\nequals = [0, 0]',
            "expect.0.quantity",
            "'floor' is not an actor",
        ),
        (
            'body = "player"\nquantity = "angle"\nangle_to = [0, 1]\nt = 1.0\nbelow = 1',
            "expect.0.angle_to",
            "has no direction",
        ),
        (
            'body = "player"\nquantity = "support"\nangle_to = [0, 1]\ncomponent = "x"\n'
            "t = 1.0\nbelow = 1",
            "expect.0.component",
            "no component",
        ),
        (
            'body = "player"\nquantity = "support"\nangle_to = [0, 0]\nt = 1.0\nbelow = 1',
            "expect.0.angle_to",
            "zero vector",
        ),
        (
            'body = "player"\nquantity = "support"\nminus = { body = "player", quantity = '
            '"angle" }\nt = 1.0\nequals = [0, 0]',
            "expect.0.minus.quantity",
            "not both vectors",
        ),
        (
            'body = "player"\nquantity = "support"\nminus = { body = "floor", quantity = '
            '"engine" }\nt = 1.0\nequals = [0, 0]',
            "expect.0.minus.body",
            "not tracked",
        ),
        (
            'body = "player"\nquantity = "support"\nangle_to = { body = "plyer", quantity = '
            '"hover" }\nt = 1.0\nbelow = 1',
            "expect.0.angle_to.body",
            "did you mean 'player'",
        ),
    ],
)
def test_malformed_new_kinds_name_the_key(expect: str, where: str, message: str) -> None:
    text = (
        REST + '[[props]]\nname = "floor"\nposition = [0, -1]\nmass = 1\n'
        'shapes = [{ kind = "box", size = [1, 1] }]\n[[expect]]\n' + expect + "\n"
    )
    with pytest.raises(LevelError) as info:
        loads(text, "bad.toml")
    assert any(p.path == where and message in p.message for p in info.value.problems), str(
        info.value
    )
