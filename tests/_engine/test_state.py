"""A body's state and the space's gravity, read in one call, are the very doubles pymunk's
properties give (bit for bit), so the controller's reads cannot drift from the public API."""

from __future__ import annotations

import math
import struct

import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine.state import (
    body_motion,
    body_state,
    centre_of_gravity,
    jointed,
    radius_of_gyration,
    space_gravity,
)

_FINITE = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False)
UNTIMED = settings(deadline=None)
"""No per-example deadline: these check values, not speed (a shared machine can be slow)."""


def _bits(values: tuple[float, ...]) -> bytes:
    """The values' IEEE 754 bytes: equal only if equal to the last bit (zeros' signs included)."""
    return struct.pack(f"{len(values)}d", *values)


def _stepped(
    kind: int, vx: float, vy: float, w: float, angle: float, gy: float
) -> tuple[pymunk.Space, pymunk.Body]:
    space = pymunk.Space()
    space.gravity = (0.5 * gy, gy)
    body = pymunk.Body(2.0, 0.5, body_type=kind)
    body.position = (vx * 0.01, vy * 0.01)
    body.angle = angle
    body.velocity = (vx, vy)
    body.angular_velocity = w
    shape = pymunk.Circle(body, 0.3, offset=(0.1, -0.2))
    shape.mass = 2.0
    space.add(body, shape)
    space.step(1 / 120)
    return space, body


@UNTIMED
@given(_FINITE, _FINITE, _FINITE, _FINITE, _FINITE)
def test_body_state_is_the_properties_bit_for_bit(
    vx: float, vy: float, w: float, angle: float, gy: float
) -> None:
    """Position, velocity, rotation, spin, mass and moment are pymunk's, to the last bit."""
    space, body = _stepped(pymunk.Body.DYNAMIC, vx, vy, w, angle, gy)
    s = body_state(body)
    assert _bits((s.x, s.y)) == _bits(tuple(body.position))
    assert _bits((s.vx, s.vy)) == _bits(tuple(body.velocity))
    assert _bits((s.cos, s.sin)) == _bits(tuple(body.rotation_vector))
    assert _bits((s.spin, s.mass, s.moment)) == _bits(
        (body.angular_velocity, body.mass, body.moment)
    )
    assert _bits(space_gravity(space)) == _bits(tuple(space.gravity))


@UNTIMED
@pytest.mark.parametrize("kind", [pymunk.Body.DYNAMIC, pymunk.Body.KINEMATIC])
@given(vx=_FINITE, vy=_FINITE, w=_FINITE, angle=_FINITE)
def test_body_motion_and_centre_are_the_properties_bit_for_bit(
    kind: int, vx: float, vy: float, w: float, angle: float
) -> None:
    """A ground's type, velocity, spin and centre of gravity (world frame) are pymunk's."""
    _, body = _stepped(kind, vx, vy, w, angle, -9.81)
    got_kind, mvx, mvy, spin = body_motion(body)
    assert got_kind == body.body_type == kind
    assert _bits((mvx, mvy, spin)) == _bits((*body.velocity, body.angular_velocity))
    expected = body.local_to_world(body.center_of_gravity)
    assert _bits(centre_of_gravity(body)) == _bits(tuple(expected))


@UNTIMED
@given(st.floats(min_value=1e-3, max_value=1e6), st.floats(min_value=1e-6, max_value=1e9))
def test_radius_of_gyration_is_the_properties_root_bit_for_bit(mass: float, moment: float) -> None:
    """√(I/m) of the body's own mass and moment, to the last bit."""
    body = pymunk.Body(mass, moment)
    assert _bits((radius_of_gyration(body),)) == _bits((math.sqrt(body.moment / body.mass),))


def test_a_body_is_jointed_while_a_constraint_holds_it() -> None:
    """A pivot to another body makes both jointed (pymunk's ``Body.constraints``)."""
    a, b = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
    assert not jointed(a) and not jointed(b)
    joint = pymunk.PivotJoint(a, b, (0.0, 0.0))
    assert jointed(a) and jointed(b) and a.constraints == {joint}
