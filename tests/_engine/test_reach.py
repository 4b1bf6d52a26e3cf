"""The reach through Chipmunk's point query answers as pymunk's public query walked for the
nearest shape a controller may push, bit for bit: the same shape (of equally near ones, the
first), point and distance; sensors, static and kinematic bodies and the ground passed over."""

from __future__ import annotations

import math
import random
import struct

import pymunk
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from playground._engine import reach
from playground._engine.reach import Reach, nearest_by_pymunk

BODIES = 6
"""The bodies of a scene (the first one is the ground the query passes over)."""


def _bits(found: reach.Found | None) -> tuple[int, bytes] | None:
    """The find's shape (by identity) and its floats' IEEE 754 bytes."""
    if found is None:
        return None
    return id(found[0]), struct.pack("3d", *found[1:])


def _scene(seed: int) -> tuple[pymunk.Space, pymunk.ShapeFilter, list[pymunk.Body]]:
    """Bodies of every type around the origin, each with twin shapes (equally near) some of them
    sensors, static segments, and one shape of the querying group (which the filter leaves out)."""
    rng = random.Random(seed)
    space = pymunk.Space()
    static = space.static_body
    for _ in range(4):
        a = (rng.uniform(-2, 2), rng.uniform(-2, 2))
        b = (rng.uniform(-2, 2), rng.uniform(-2, 2))
        space.add(pymunk.Segment(static, a, b, rng.choice((0.0, 0.1))))
    bodies = []
    for i in range(BODIES):
        kind = (
            pymunk.Body.DYNAMIC
            if i < 3
            else rng.choice((pymunk.Body.KINEMATIC, pymunk.Body.DYNAMIC))
        )
        body = pymunk.Body(1.0, 1.0, body_type=kind)
        body.position = (rng.uniform(-2, 2), rng.uniform(-2, 2))
        body.angle = rng.uniform(-3, 3)
        if rng.random() < 0.5:
            shapes: list[pymunk.Shape] = [pymunk.Circle(body, 0.4), pymunk.Circle(body, 0.4)]
        else:
            shapes = [pymunk.Poly.create_box(body, (0.8, 0.3), 0.02) for _ in range(2)]
        shapes.append(pymunk.Segment(body, (-0.5, 0.2), (0.5, 0.2), 0.05))
        for shape in shapes:
            shape.sensor = rng.random() < 0.25
        space.add(body, *shapes)
        bodies.append(body)
    own = pymunk.Circle(bodies[1], 0.6)
    own.filter = pymunk.ShapeFilter(group=7)
    space.add(own)
    return space, pymunk.ShapeFilter(group=7), bodies


_COORD = st.floats(-2.5, 2.5, allow_nan=False)


@settings(max_examples=300, deadline=None)
@given(
    st.integers(0, 50),
    _COORD,
    _COORD,
    st.sampled_from((0.0, 0.3, 1.0, 3.0)),
    st.booleans(),
    st.sampled_from((math.inf, 0.5, 0.0)),
)
def test_the_reach_answers_as_pymunks_query(
    seed: int, x: float, y: float, reach: float, on_ground: bool, within: float
) -> None:
    space, shape_filter, bodies = _scene(seed)
    ground = bodies[0] if on_ground else None
    fast = Reach(space, shape_filter).nearest(x, y, reach, ground, within)
    ref = nearest_by_pymunk(space, (x, y), reach, shape_filter, ground, within)
    assert _bits(fast) == _bits(ref)


def test_of_equally_near_shapes_the_first_wins_and_the_rest_are_passed() -> None:
    space = pymunk.Space()
    ground, box, still, sensor_body = (pymunk.Body(1.0, 1.0) for _ in range(4))
    still.body_type = pymunk.Body.KINEMATIC
    ground.position, box.position, still.position, sensor_body.position = (
        (0.0, -0.5),
        (1.0, 0.0),
        (0.0, 0.5),
        (0.0, 0.6),
    )
    first, second = pymunk.Circle(box, 0.5), pymunk.Circle(box, 0.5)
    sensor = pymunk.Circle(sensor_body, 0.5)
    sensor.sensor = True
    space.add(ground, box, still, sensor_body, pymunk.Circle(ground, 0.4), first, second)
    space.add(
        pymunk.Circle(still, 0.4), sensor, pymunk.Segment(space.static_body, (0, 0), (0, 1), 0)
    )
    shape_filter = pymunk.ShapeFilter()
    found = Reach(space, shape_filter).nearest(0.0, 0.0, 1.0, ground)
    # Of the twins, the one Chipmunk's index visits first (not necessarily the first added).
    assert found is not None and found[0] in (first, second)
    assert _bits(found) == _bits(nearest_by_pymunk(space, (0.0, 0.0), 1.0, shape_filter, ground))
    # Only strictly nearer than ``within``: the same distance is not enough.
    assert Reach(space, shape_filter).nearest(0.0, 0.0, 1.0, ground, found[3]) is None


def test_without_cffi_callbacks_the_reach_asks_pymunk(monkeypatch: pytest.MonkeyPatch) -> None:
    space, shape_filter, bodies = _scene(3)
    arm = Reach(space, shape_filter)
    fast = arm.nearest(0.0, 0.0, 3.0, bodies[0])
    monkeypatch.setattr(reach, "_callback", None)
    assert fast is not None and _bits(arm.nearest(0.0, 0.0, 3.0, bodies[0])) == _bits(fast)
