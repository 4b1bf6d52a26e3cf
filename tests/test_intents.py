"""Laws of intents: what a wish may hold, which key of a script is in force, how a patrol walks."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground.intents import Idle, Intent, IntentSource, Patrol, Script


@pytest.mark.parametrize("field", ["move", "climb"])
@pytest.mark.parametrize("bad", [1.0001, -1.5, math.nan, math.inf])
def test_axes_are_within_minus_one_and_one(field: str, bad: float) -> None:
    """move and climb are fractions of what the controller may do: outside [-1, 1] or not
    finite is refused, naming the axis; the ends themselves are allowed."""
    with pytest.raises(ValueError, match=rf"^{field}: "):
        Intent(**{field: bad})
    assert getattr(Intent(**{field: -1.0}), field) == -1.0


UNTIMED = settings(deadline=None)
"""No per-example deadline: these check values, not speed, and on a shared 2-core machine an
example can take longer than hypothesis's default 200 ms without anything being wrong."""


@UNTIMED
@given(
    x=st.floats(-1e308, 1e308, allow_subnormal=False),
    y=st.floats(-1e308, 1e308, allow_subnormal=False),
)
def test_a_gravity_wish_is_a_direction(x: float, y: float) -> None:
    """A gravity wish keeps only the direction: a unit vector pointing the same way."""
    if x == 0.0 and y == 0.0:
        with pytest.raises(ValueError, match=r"^gravity: "):
            Intent(gravity=(x, y))
        return
    gx, gy = Intent(gravity=(x, y)).gravity or (math.nan, math.nan)
    assert math.hypot(gx, gy) == pytest.approx(1.0, abs=1e-15)
    # Same direction: the cross product vanishes and the dot product is positive.
    scale = max(abs(x), abs(y))
    assert abs(gx * y / scale - gy * x / scale) <= 1e-12
    assert gx * x / scale + gy * y / scale > 0.0


@pytest.mark.parametrize("bad", [(math.nan, 1.0), (1.0, 2.0, 3.0)])
def test_malformed_gravity_wishes_are_refused(bad: tuple[float, ...]) -> None:
    with pytest.raises(ValueError, match=r"^gravity"):
        Intent(gravity=bad)  # type: ignore[arg-type]


def test_nullify_names_a_body() -> None:
    assert Intent(nullify="crate").nullify == "crate"
    with pytest.raises(ValueError, match=r"^nullify: expected a body name"):
        Intent(nullify=3)  # type: ignore[arg-type]


def test_the_last_key_at_or_before_t_is_in_force() -> None:
    """Before the first key: idle. At a key's time: that key. Between keys: the earlier one.
    Two keys at the same time: the later one in the timeline wins."""
    jump, walk, stop = Intent(jump=True), Intent(move=1.0), Intent(move=-0.5)
    script = Script(((1.0, walk), (2.0, jump), (2.0, stop)))
    assert script.intent(0.999) == Intent()
    assert script.intent(1.0) is walk
    assert script.intent(1.999) is walk
    assert script.intent(2.0) is stop
    assert script.intent(1e9) is stop
    assert Script(()).intent(5.0) == Intent()


@pytest.mark.parametrize(
    ("timeline", "message"),
    [
        (((1.0, Intent()), (0.5, Intent())), r"^timeline\[1\]: expected times sorted ascending"),
        (((math.nan, Intent()),), r"^timeline\[0\] time: expected a finite number"),
        (((0.0, Intent()), (1.0, "jump")), r"^timeline\[1\]: expected an Intent"),
    ],
)
def test_a_malformed_script_names_the_key(timeline: tuple, message: str) -> None:  # type: ignore[type-arg]
    with pytest.raises(ValueError, match=message):
        Script(timeline)


@UNTIMED
@given(t=st.floats(0.0, 1e4), speed=st.floats(0.0, 1.0), period=st.floats(0.1, 100.0))
def test_a_patrol_walks_there_for_half_a_period_then_back(
    t: float, speed: float, period: float
) -> None:
    """The move is +speed in the first half of each period and −speed in the second."""
    phase = (t % period) / period
    expected = speed if phase < 0.5 else -speed
    assert Patrol(speed=speed, period=period).intent(t).move == expected


def test_a_patrol_turns_at_half_period() -> None:
    p = Patrol(speed=0.8, period=2.0)
    assert [p.intent(t).move for t in (0.0, 0.99, 1.0, 1.99, 2.0, 3.0)] == [
        0.8,
        0.8,
        -0.8,
        -0.8,
        0.8,
        -0.8,
    ]


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"speed": 1.5}, r"^speed: expected a number in \[0, 1\]"),
        ({"speed": -0.1}, r"^speed: "),
        ({"period": 0.0}, r"^period: expected a number > 0"),
        ({"period": math.inf}, r"^period: "),
    ],
)
def test_a_malformed_patrol_names_the_field(kwargs: dict[str, float], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        Patrol(**kwargs)


def test_every_source_is_an_intent_source() -> None:
    """Idle, Script and Patrol all satisfy the protocol a controller takes; Idle wants nothing."""
    sources = (Idle(), Script(((0.0, Intent(push=True)),)), Patrol())
    assert all(isinstance(s, IntentSource) for s in sources)
    assert all(Idle().intent(t) == Intent() for t in (0.0, 1.0, 1e9))
    assert not isinstance(object(), IntentSource)
