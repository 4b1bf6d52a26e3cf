"""Laws of the expectation kinds: another body's reading (``minus``), the angle between two
vectors (``angle_to``) and a controller's own readings, on scenes whose answers are exact."""

from __future__ import annotations

import math

import pytest

from playground.forces.ledger import Category
from playground.level import LevelError, loads
from playground.scene import build
from playground.scene.checks import watch

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


# -- the check kinds, on a body gliding at constant velocity: x(t) = 2 m/s · t ---------------------

GLIDE = """
title = "Glide"
description = "A ball glides at 2 m/s with no gravity and nothing to touch."
[settings]
seconds = 1.0
[gravity]
kind = "uniform"
g = [0.0, 0.0]
[[props]]
name = "ball"
position = [0.0, 5.0]
velocity = [2.0, 0.0]
mass = 1.0
shapes = [{ kind = "circle", radius = 0.1 }]
[[props]]
name = "marker"
position = [1.0, 2.0]
mass = 1.0
shapes = [{ kind = "circle", radius = 0.1 }]
"""

TOL_GLIDE = 1e-9
"""m: x = 2 m/s · t summed over 120 steps of 1/120 s rounds at ~1e-15 m."""


def _glide(expect: str, seconds: float = 1.0) -> list[tuple[bool, str]]:
    """Run the glide with these checks for ``seconds`` (less than the level's: cut short)."""
    scene = build(loads(GLIDE + expect))
    checks = watch(scene)
    scene.run(seconds)
    return [(r.passed, r.detail) for r in checks.results()]


def test_at_reads_the_value_at_its_time_and_says_how_far_off() -> None:
    """x(0.5 s) = 1 m: ``equals = 1`` passes; ``equals = 1.25`` fails off by 0.25 m; a run cut
    short before the check's time fails saying it never reached it."""
    hit, miss, late = _glide(
        f"""
[[expect]]
body = "ball"
quantity = "position"
component = "x"
t = 0.5
equals = 1.0
tolerance = {TOL_GLIDE}

[[expect]]
body = "ball"
quantity = "position"
component = "x"
t = 0.5
equals = 1.25

[[expect]]
body = "ball"
quantity = "position"
component = "x"
t = 0.9
equals = 1.8
""",
        seconds=0.8,
    )
    assert hit[0], hit[1]
    assert not miss[0] and "off by 0.25 m" in miss[1], miss[1]
    assert not late[0] and "without reaching it" in late[1], late[1]


def test_always_names_the_first_break_and_eventually_the_first_success() -> None:
    """x < 1.01 m holds until 0.505 s: ``always`` fails first broken at the step after, 61/120 s,
    where x > 1.01 m first happens; x > 5 m never happens and the failure gives the closest
    step, the last."""
    always, eventually, never = _glide(
        """
[[expect]]
body = "ball"
quantity = "position"
component = "x"
check = "always"
below = 1.01

[[expect]]
body = "ball"
quantity = "position"
component = "x"
check = "eventually"
above = 1.01

[[expect]]
body = "ball"
quantity = "position"
component = "x"
check = "eventually"
above = 5.0
"""
    )
    assert not always[0] and "first broken at t = 0.5083 s" in always[1], always[1]
    assert eventually[0] and "first at t = 0.5083 s" in eventually[1], eventually[1]
    assert not never[0] and "closest at t = 1 s" in never[1], never[1]


PUSH = 3.0
"""N: the force pushing the 1 kg ball along x from 0.5 s (the impulse test)."""
TOL_IMPULSE = 1e-9
"""N·s: 60 step readings of 3 N summed, each the ball's Δv·m/dt recovered to ~1e-15 N."""


def test_impulse_integrates_a_force_over_its_window() -> None:
    """A 1 kg ball pushed with 3 N along x from 0.5 s: the impulse of its support over
    [0.75, 1] s is 3 N · 0.25 s = 0.75 N·s (each step after the window's start, its reading
    times dt: the step that ends at 0.75 s is not in it); over [0.25, 1] s, [1.5, 0] N·s, 1.5
    m/s per kilogram of the ball; its change since 0.5 s over [0.5, 1] s, 1.5 N·s; 1 N·s there
    is off by 0.5 N·s."""
    scene = build(
        loads(
            GLIDE
            + "[tracking]\nbodies = ['ball']\n"
            + f"""
[[expect]]
body = "ball"
quantity = "support"
component = "x"
check = "impulse"
window = [0.75, 1.0]
equals = 0.75
tolerance = {TOL_IMPULSE}

[[expect]]
body = "ball"
quantity = "support"
check = "impulse"
window = [0.25, 1.0]
equals = [1.5, 0.0]
per_mass_of = "ball"
tolerance = {TOL_IMPULSE}

[[expect]]
body = "ball"
quantity = "support"
component = "x"
change = true
check = "impulse"
window = [0.5, 1.0]
equals = 1.5
tolerance = {TOL_IMPULSE}

[[expect]]
body = "ball"
quantity = "support"
component = "x"
check = "impulse"
window = [0.25, 1.0]
equals = 1.0
tolerance = {TOL_IMPULSE}
"""
        )
    )
    checks = watch(scene)
    ball = scene.world.body("ball")
    while scene.world.time < 1.0 - 1e-9:
        if scene.world.time >= 0.5 - 1e-9:
            scene.world.apply_force(ball, (PUSH, 0.0), category=Category.SUPPORT)
        scene.world.step()
    scalar, vector, change, wrong = checks.results()
    assert scalar.passed and vector.passed and change.passed, (scalar, vector, change)
    assert "N·s" in scalar.detail and "N·s/kg of ball" in vector.detail, vector.detail
    assert not wrong.passed and "off by 0.5 N·s" in wrong.detail, wrong.detail


def test_mean_change_relative_to_and_norm() -> None:
    """Over [0.5, 1] s the mean of x is 1.5 m; the ball relative to the marker at 1 s is
    (2, 5) − (1, 2) = (1, 3), of norm √10."""
    results = _glide(
        f"""
[[expect]]
body = "ball"
quantity = "position"
component = "x"
check = "mean"
window = [0.5, 1.0]
equals = 1.5
tolerance = {TOL_GLIDE}

[[expect]]
body = "ball"
quantity = "position"
relative_to = "marker"
t = 1.0
equals = [1.0, 3.0]
tolerance = {TOL_GLIDE}

[[expect]]
body = "ball"
quantity = "position"
relative_to = "marker"
component = "norm"
t = 1.0
equals = {math.sqrt(10.0)}
tolerance = {TOL_GLIDE}
"""
    )
    assert all(ok for ok, _ in results), results


def test_change_is_measured_from_the_windows_first_step() -> None:
    """``change``: x went from 1 m at 0.5 s to 2 m at 1 s, so the change is 1 m, not 2 m."""
    (result,) = _glide(
        f"""
[[expect]]
body = "ball"
quantity = "position"
component = "x"
check = "always"
change = true
window = [0.5, 1.0]
below = {1.0 + TOL_GLIDE}
"""
    )
    assert result[0], result[1]


def test_a_window_past_the_end_of_the_run_fails() -> None:
    """``always`` over [0.5, 1] s on a run cut short at 0.8 s: it held while it ran, but the
    window did not close, so it does not pass."""
    (result,) = _glide(
        """
[[expect]]
body = "ball"
quantity = "velocity"
component = "x"
check = "always"
window = [0.5, 1.0]
above = 1.9
""",
        seconds=0.8,
    )
    assert not result[0] and "before the window closed" in result[1], result[1]


def test_repeated_check_names_are_made_unique() -> None:
    from playground.scene.checks import check_names

    level = loads(
        GLIDE
        + '[[expect]]\nname = "x"\nbody = "ball"\nquantity = "angle"\nt = 0.5\nequals = 0.0\n'
        + '[[expect]]\nname = "x"\nbody = "ball"\nquantity = "angle"\nt = 1.0\nequals = 0.0\n'
    )
    assert check_names(level) == ["x", "x #2"]
