"""Laws of one-way shapes: a contact begins only from above (a body thrown up through a platform
lands on it, one that meets its side passes through), the top turns with the shape's body, and a
probe passes a one-way shape unless it starts above it, clear by its radius."""

from __future__ import annotations

import math

import pymunk

from playground.world import one_way

DT = 1.0 / 120.0
"""s."""
R = 0.3
"""m: the ball's radius."""
TOL_REST = 1e-6
"""m/s: at rest on the platform."""


def space_with(platform_angle: float = 0.0) -> tuple[pymunk.Space, pymunk.Body]:
    """A space with gravity along −y turned by ``platform_angle`` and a one-way box 4 m wide
    whose top faces away from gravity, its centre 2 m from the origin along that top."""
    space = pymunk.Space()
    ux, uy = -math.sin(platform_angle), math.cos(platform_angle)
    space.gravity = (-9.81 * ux, -9.81 * uy)
    platform = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    platform.position = (2.0 * ux, 2.0 * uy)
    platform.angle = platform_angle
    box = pymunk.Poly.create_box(platform, (4.0, 0.2))
    one_way.make_one_way(space, box)
    space.add(platform, box)
    return space, platform


def ball(
    space: pymunk.Space, position: tuple[float, float], velocity: tuple[float, float]
) -> pymunk.Body:
    """A 1 kg ball of radius R at ``position`` (m) moving at ``velocity`` (m/s)."""
    body = pymunk.Body(1.0, pymunk.moment_for_circle(1.0, 0.0, R))
    body.position, body.velocity = position, velocity
    space.add(body, pymunk.Circle(body, R))
    return body


def test_thrown_up_through_it_a_ball_lands_on_it_and_rests() -> None:
    """From below it passes (no contact on the way up); falling back it lands on the top."""
    space, _ = space_with()
    b = ball(space, (0.0, 1.0), (0.0, 8.0))
    top = 2.1
    highest = 0.0
    for _ in range(480):
        space.step(DT)
        highest = max(highest, b.position.y)
    assert highest > top + R
    assert abs(b.velocity.y) < TOL_REST
    assert top < b.position.y < top + R


def test_a_turned_platform_is_one_way_along_its_own_top() -> None:
    """Turned by 90° with gravity, the platform's top is its body's +y: the same throw lands on
    it along the turned axis."""
    angle = math.pi / 2.0
    space, _ = space_with(angle)
    b = ball(space, (-1.0, 0.0), (-8.0, 0.0))
    for _ in range(480):
        space.step(DT)
    assert abs(b.velocity.x) < TOL_REST and -2.1 - R < b.position.x < -2.1


def test_meeting_its_side_a_ball_passes_through() -> None:
    """A contact whose normal lies across the top (its side) does not begin."""
    space, _ = space_with()
    space.gravity = (0.0, 0.0)
    b = ball(space, (-3.0, 2.0), (4.0, 0.0))
    for _ in range(240):
        space.step(DT)
    assert b.position.x > 2.0 + R and b.velocity.x == 4.0


def test_a_probe_passes_a_one_way_shape_unless_it_starts_above_it() -> None:
    """From above, clear by the radius: seen; touching it, inside it or below it: passed; a shape
    that is not one-way: never passed."""
    space, platform = space_with()
    (box,) = platform.shapes
    assert not one_way.passes(box, 0.0, 3.0, 0.1)
    assert one_way.passes(box, 0.0, 2.15, 0.1)
    assert one_way.passes(box, 0.0, 2.0, 0.1)
    assert one_way.passes(box, 0.0, 1.0, 0.1)
    solid = pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.0)
    assert not one_way.passes(solid, 0.0, -1.0, 0.1)
