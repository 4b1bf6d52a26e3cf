"""``playground._engine.motion``: many bodies' velocity, angular velocity, force and torque read
in one call give the very doubles ``body.velocity``, ``body.angular_velocity``, ``body.force``
and ``body.torque`` give, by the compiled helper and by its fallback alike, as they are now (a
change between two reads is read)."""

from __future__ import annotations

import os
from array import array
from typing import Any

import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine import motion, raw
from playground._engine.motion import Motions

values = st.floats(allow_nan=False, allow_infinity=False, width=64) | st.sampled_from([-0.0, 0.0])
states = st.tuples(values, values, values, values, values, values)


def _bits(rows: list[tuple[float, ...]]) -> list[str]:
    """The values' IEEE 754 bits: equal only if equal to the last bit (and -0.0 is not 0.0)."""
    return [x.hex() for row in rows for x in row]


@settings(deadline=None)
@given(st.lists(states, max_size=30))
def test_a_read_gives_each_bodys_motion_bit_for_bit(
    rows: list[tuple[float, float, float, float, float, float]],
) -> None:
    """Law: Motions and its cffi fallback give each body's velocity, angular velocity (and force
    and torque), in the list's order, to the bit."""
    bodies = []
    for vx, vy, w, fx, fy, t in rows:
        body = pymunk.Body(1.0, 1.0)
        body.velocity, body.angular_velocity = (vx, vy), w
        body.force, body.torque = (fx, fy), t
        bodies.append(body)
    want_v = _bits([(*b.velocity, b.angular_velocity) for b in bodies])
    want_all = _bits([(*b.velocity, b.angular_velocity, *b.force, b.torque) for b in bodies])
    handles = [raw.handle(b) for b in bodies]
    reads = Motions(bodies)
    assert _bits(list(reads.velocities())) == want_v
    assert _bits(list(motion.velocities_by_cffi(handles))) == want_v
    assert _bits(list(reads.velocities_and_forces())) == want_all
    assert _bits(list(motion.velocities_and_forces_by_cffi(handles))) == want_all


def test_a_read_sees_a_change_and_keeps_the_lists_it_gave() -> None:
    """A velocity set between two reads is read by the second; the first read's list stays as
    it was (a caller keeps it)."""
    a, b = pymunk.Body(2.0, 0.5), pymunk.Body(70.0, 1.25)
    reads = Motions([a, b])
    first = reads.velocities()
    b.velocity, b.angular_velocity = (3.0, -4.0), 0.5
    second = reads.velocities()
    assert first == [(0.0, 0.0, 0.0), (0.0, 0.0, 0.0)]
    assert second == [(0.0, 0.0, 0.0), (3.0, -4.0, 0.5)]
    assert Motions([]).velocities_and_forces() == []


@pytest.mark.skipif(motion.MOTION_BY != "compiled", reason="the compiled helper is not built")
def test_the_compiled_helper_refuses_what_it_cannot_read() -> None:
    """Wrong item types, a null body or a null getter raise, naming what is wrong, instead of
    reading memory that is not there."""
    from playground._engine import _motion

    read: Any = _motion.motion  # called with wrong arguments on purpose
    body = pymunk.Body(2.0, 0.5)
    body.velocity = (1.0, 2.0)
    getters = (motion._VELOCITY, motion._ANGULAR_VELOCITY, motion._FORCE, motion._TORQUE)
    one = array(motion._ADDRESS, [motion._address(raw.handle(body))])
    assert read(*getters, one, False) == [(1.0, 2.0, 0.0)]
    with pytest.raises(TypeError, match="bodies"):
        read(*getters, array("d", [1.0]), False)
    with pytest.raises(ValueError, match="null"):
        read(*getters, array(motion._ADDRESS, [0]), True)
    with pytest.raises(ValueError, match="get_force must not be null"):
        read(getters[0], getters[1], 0, getters[3], one, True)
    with pytest.raises(TypeError, match="6 arguments"):
        read(*getters, one)


@pytest.mark.skipif(os.environ.get("CI") != "true", reason="only CI (.ci/run) must build it")
def test_ci_runs_the_compiled_helper_not_the_fallback() -> None:
    """CI installs on a machine with a compiler and Python's headers: there Motions must read
    through the compiled helper, or CI would test only the fallback."""
    assert motion.MOTION_BY == "compiled"
