"""The raw reads and writes give the very doubles pymunk's properties give (bit for bit), so the
hot paths that use them cannot drift from the public API, even after a pymunk upgrade."""

from __future__ import annotations

import math
import struct

import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine import raw

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


UNTIMED = settings(deadline=None)
"""No per-example deadline: these check values, not speed, and on a shared 2-core machine an
example can take longer than hypothesis's default 200 ms without anything being wrong."""


@UNTIMED
@given(_FINITE, _FINITE, _FINITE, _FINITE, _FINITE, _FINITE)
def test_reads_equal_the_properties_bit_for_bit(
    vx: float, vy: float, w: float, angle: float, fx: float, fy: float
) -> None:
    body = _stepped_body(vx, vy, w, angle, fx, fy)
    h = raw.handle(body)
    assert _bits(raw.velocity(h)) == _bits(tuple(body.velocity))
    assert _bits(raw.position(h)) == _bits(tuple(body.position))
    assert _bits(raw.rotation(h)) == _bits(tuple(body.rotation_vector))
    assert _bits(raw.force(h)) == _bits(tuple(body.force))
    assert _bits((raw.angular_velocity(h),)) == _bits((body.angular_velocity,))
    assert _bits((raw.torque(h),)) == _bits((body.torque,))


def test_body_id_is_the_property() -> None:
    bodies = [pymunk.Body(1.0, 1.0) for _ in range(5)]
    assert [raw.body_id(b) for b in bodies] == [b.id for b in bodies]
    assert len({raw.body_id(b) for b in bodies}) == 5


@UNTIMED
@given(_FINITE, _FINITE, _FINITE)
def test_writes_equal_the_property_writes(fx: float, fy: float, t: float) -> None:
    direct, prop = pymunk.Body(1.0, 1.0), pymunk.Body(1.0, 1.0)
    raw.set_force(raw.handle(direct), fx, fy)
    raw.set_torque(raw.handle(direct), t)
    prop.force = (fx, fy)
    prop.torque = t
    assert _bits((*direct.force, direct.torque)) == _bits((*prop.force, prop.torque))


def _ball_on_a_floor() -> tuple[pymunk.Space, pymunk.Body]:
    """A ball resting on a floor in a space where bodies fall asleep after 0.1 s at rest."""
    space = pymunk.Space()
    space.sleep_time_threshold = 0.1
    space.gravity = (0.0, -10.0)
    floor = pymunk.Segment(space.static_body, (-5, 0), (5, 0), 0.1)
    body = pymunk.Body(1.0, math.inf)
    body.position = (0.0, 0.6)
    space.add(floor, body, pymunk.Circle(body, 0.5))
    return space, body


def test_a_write_wakes_a_sleeping_body_as_the_property_does() -> None:
    space, body = _ball_on_a_floor()
    for _ in range(600):
        space.step(1 / 60)
    assert body.is_sleeping
    raw.set_force(raw.handle(body), 0.0, 1.0)
    assert not body.is_sleeping


@UNTIMED
@given(_FINITE, _FINITE, _FINITE, _FINITE, st.floats(0.01, 1e3), st.floats(0.01, 1e3))
def test_mass_moment_and_centre_equal_the_properties_bit_for_bit(
    x: float, y: float, cx: float, angle: float, m: float, i: float
) -> None:
    body = pymunk.Body(m, i)
    body.center_of_gravity = (cx * 1e-3, -cx * 2e-3)
    body.position = (x, y)
    body.angle = angle
    h = raw.handle(body)
    assert _bits((raw.mass(h), raw.moment(h))) == _bits((body.mass, body.moment))
    assert _bits(raw.centre_of_gravity(h)) == _bits(
        tuple(body.local_to_world(body.center_of_gravity))
    )


def test_body_type_is_the_property() -> None:
    kinds = (pymunk.Body.DYNAMIC, pymunk.Body.KINEMATIC, pymunk.Body.STATIC)
    bodies = [pymunk.Body(1.0, 1.0, body_type=kind) for kind in kinds]
    assert [raw.body_type(raw.handle(b)) for b in bodies] == list(kinds)


@UNTIMED
@given(_FINITE, _FINITE)
def test_space_gravity_is_the_property(gx: float, gy: float) -> None:
    space = pymunk.Space()
    space.gravity = (gx, gy)
    assert _bits(raw.gravity(raw.space_handle(space))) == _bits(tuple(space.gravity))


def test_is_sleeping_is_the_property() -> None:
    space, body = _ball_on_a_floor()
    seen = set()
    for _ in range(600):
        space.step(1 / 60)
        assert bool(raw.is_sleeping(raw.handle(body))) == body.is_sleeping
        seen.add(body.is_sleeping)
    assert seen == {False, True}


Seen = tuple[tuple[float, ...], bool, tuple[int, int]]
"""(impulse and normal, first contact, the two bodies' ids) of one arbiter."""


def _through_properties(body: pymunk.Body) -> list[Seen]:
    seen: list[Seen] = []

    def read(arb: pymunk.Arbiter) -> None:
        a, b = arb.bodies
        seen.append(((*arb.total_impulse, *arb.normal), arb.is_first_contact, (a.id, b.id)))

    body.each_arbiter(read)
    return seen


def _through_raw(body: pymunk.Body) -> list[Seen]:
    seen: list[Seen] = []

    def read(_: raw.Handle, arb: raw.ArbiterHandle, data: object) -> None:
        first = raw.is_first_contact(arb) != 0
        seen.append((raw.arbiter_impulse(arb), first, raw.arbiter_body_ids(arb)))

    callback = raw.arbiter_callback(read)
    raw.each_arbiter(raw.handle(body), callback, raw.NULL)
    return seen


@UNTIMED
@given(st.lists(st.tuples(_FINITE, _FINITE), min_size=2, max_size=6))
def test_arbiter_reads_equal_the_properties_bit_for_bit(spins: list[tuple[float, float]]) -> None:
    """Law: through the C iterator a body's arbiters come in the same order, seen from the same
    side, with the same impulses, normals, first-contact flags and bodies as through
    ``Body.each_arbiter`` and the ``Arbiter`` properties, on every step of a settling stack (first
    contacts included)."""
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    floor = pymunk.Segment(space.static_body, (-5, 0), (5, 0), 0.1)
    space.add(floor)
    bodies = []
    for i, (vx, w) in enumerate(spins):
        body = pymunk.Body(1.0, 0.1)
        body.position = (0.1 * (i % 2), 0.45 + 0.7 * i)
        body.velocity = (vx * 1e-6, 0.0)
        body.angular_velocity = w * 1e-6
        space.add(body, pymunk.Poly.create_box(body, (0.6, 0.6)))
        bodies.append(body)
    arbiters = 0
    for _ in range(60):
        space.step(1 / 60)
        for body in [*bodies, space.static_body]:
            props, direct = _through_properties(body), _through_raw(body)
            assert [(_bits(i), f, ids) for i, f, ids in direct] == [
                (_bits(i), f, ids) for i, f, ids in props
            ]
            arbiters += len(direct)
    assert arbiters > 0


@UNTIMED
@given(_FINITE, _FINITE, _FINITE, _FINITE, _FINITE, _FINITE)
def test_vector_structs_equal_the_properties_bit_for_bit(
    vx: float, vy: float, w: float, angle: float, fx: float, fy: float
) -> None:
    body = _stepped_body(vx, vy, w, angle, fx, fy)
    v, f = raw.get_velocity(raw.handle(body)), raw.get_force(raw.handle(body))
    assert _bits((v.x, v.y, f.x, f.y)) == _bits((*body.velocity, *body.force))


@UNTIMED
@given(_FINITE, _FINITE, _FINITE, _FINITE)
def test_mover_reads_and_writes_equal_the_properties_bit_for_bit(
    vx: float, vy: float, w: float, angle: float
) -> None:
    direct = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    prop = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    direct.angle = prop.angle = angle
    h = raw.handle(direct)
    raw.set_velocity(h, vx, vy)
    raw.set_angular_velocity(h, w)
    prop.velocity = (vx, vy)
    prop.angular_velocity = w
    assert _bits((*direct.velocity, direct.angular_velocity, raw.angle(h))) == _bits(
        (*prop.velocity, prop.angular_velocity, prop.angle)
    )


@UNTIMED
@given(st.floats(1e-4, 1.0), st.integers(0, 10))
def test_space_step_and_persistence_are_the_properties(dt: float, persistence: int) -> None:
    space = pymunk.Space()
    space.collision_persistence = persistence
    space.step(dt)
    s = raw.space_handle(space)
    assert _bits((raw.current_time_step(s),)) == _bits((space.current_time_step,))
    assert raw.collision_persistence(s) == space.collision_persistence == persistence


def _keep(*_: object) -> None:
    """A callback that keeps nothing."""


def test_a_callback_is_made_where_cffi_allows() -> None:
    assert raw.c_callback("cpSpacePointQueryFunc", _keep) is not None
    assert raw.arbiter_callback(_keep) is not None


@pytest.mark.parametrize("refusal", [MemoryError, RuntimeError])
def test_where_cffi_refuses_callbacks_there_is_none(
    monkeypatch: pytest.MonkeyPatch, refusal: type[Exception]
) -> None:
    """Then the queries and the arbiter readers fall back to pymunk's own iteration."""

    def refuse(*_: object) -> None:
        raise refusal("write+execute memory refused")

    monkeypatch.setattr(raw, "_new_callback", refuse)
    assert raw.c_callback("cpSpacePointQueryFunc", _keep) is None
    assert raw.arbiter_callback(_keep) is None
