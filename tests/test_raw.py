"""The raw reads and writes give the very doubles pymunk's properties give (bit for bit), so the
hot paths that use them cannot drift from the public API, even after a pymunk upgrade."""

from __future__ import annotations

import math
import struct

import pymunk
from hypothesis import given
from hypothesis import strategies as st

from playground import _raw

_FINITE = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False)


def _bits(values: tuple[float, ...]) -> bytes:
    """The values' IEEE 754 bytes: equal only if equal to the last bit (and of the same sign
    for zeros, which == does not tell)."""
    return struct.pack(f"{len(values)}d", *values)


def _stepped_body(
    vx: float, vy: float, w: float, angle: float, fx: float, fy: float
) -> pymunk.Body:
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    body = pymunk.Body(2.0, 0.5)
    body.position = (vx * 0.01, vy * 0.01)
    body.angle = angle
    body.velocity = (vx, vy)
    body.angular_velocity = w
    space.add(body, pymunk.Circle(body, 0.3))
    space.step(1 / 120)
    body.force = (fx, fy)
    body.torque = fx - fy
    return body


@given(_FINITE, _FINITE, _FINITE, _FINITE, _FINITE, _FINITE)
def test_reads_equal_the_properties_bit_for_bit(
    vx: float, vy: float, w: float, angle: float, fx: float, fy: float
) -> None:
    body = _stepped_body(vx, vy, w, angle, fx, fy)
    h = _raw.handle(body)
    assert _bits(_raw.velocity(h)) == _bits(tuple(body.velocity))
    assert _bits(_raw.position(h)) == _bits(tuple(body.position))
    assert _bits(_raw.rotation(h)) == _bits(tuple(body.rotation_vector))
    assert _bits(_raw.force(h)) == _bits(tuple(body.force))
    assert _bits((_raw.angular_velocity(h),)) == _bits((body.angular_velocity,))
    assert _bits((_raw.torque(h),)) == _bits((body.torque,))


def test_body_id_is_the_property() -> None:
    bodies = [pymunk.Body(1.0, 1.0) for _ in range(5)]
    assert [_raw.body_id(b) for b in bodies] == [b.id for b in bodies]
    assert len({_raw.body_id(b) for b in bodies}) == 5


@given(_FINITE, _FINITE, _FINITE)
def test_writes_equal_the_property_writes(fx: float, fy: float, t: float) -> None:
    raw, prop = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
    _raw.set_force(_raw.handle(raw), fx, fy)
    _raw.set_torque(_raw.handle(raw), t)
    prop.force = (fx, fy)
    prop.torque = t
    assert _bits((*raw.force, raw.torque)) == _bits((*prop.force, prop.torque))


def test_a_write_wakes_a_sleeping_body_as_the_property_does() -> None:
    space = pymunk.Space()
    space.sleep_time_threshold = 0.1
    space.gravity = (0.0, -10.0)
    floor = pymunk.Segment(space.static_body, (-5, 0), (5, 0), 0.1)
    body = pymunk.Body(1.0, math.inf)
    body.position = (0.0, 0.6)
    space.add(floor, body, pymunk.Circle(body, 0.5))
    for _ in range(600):
        space.step(1 / 60)
    assert body.is_sleeping
    _raw.set_force(_raw.handle(body), 0.0, 1.0)
    assert not body.is_sleeping


@given(_FINITE, _FINITE, _FINITE, _FINITE, st.floats(0.01, 1e3), st.floats(0.01, 1e3))
def test_mass_moment_and_centre_equal_the_properties_bit_for_bit(
    x: float, y: float, cx: float, angle: float, m: float, i: float
) -> None:
    body = pymunk.Body(m, i)
    body.center_of_gravity = (cx * 1e-3, -cx * 2e-3)
    body.position = (x, y)
    body.angle = angle
    h = _raw.handle(body)
    assert _bits((_raw.mass(h), _raw.moment(h))) == _bits((body.mass, body.moment))
    assert _bits(_raw.centre_of_gravity(h)) == _bits(
        tuple(body.local_to_world(body.center_of_gravity))
    )


def test_body_type_is_the_property() -> None:
    kinds = (pymunk.Body.DYNAMIC, pymunk.Body.KINEMATIC, pymunk.Body.STATIC)
    bodies = [pymunk.Body(1.0, 1.0, body_type=kind) for kind in kinds]
    assert [_raw.body_type(_raw.handle(b)) for b in bodies] == list(kinds)
