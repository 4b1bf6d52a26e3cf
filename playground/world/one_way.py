"""One-way shapes: solid only from their top, the +y side of their body's frame (a platform
bodies jump up through and land on).

:func:`make_one_way` marks a shape (its ``collision_type``, :data:`ONE_WAY`) and puts the rule
into its space: a contact with a one-way shape begins only if the other shape comes from above
(the contact normal, from the one-way shape toward the other, within 60° of its top's
direction, :data:`FROM_ABOVE`);
otherwise the pair passes through each other until they part. A controller's ground probe
passes a one-way shape too unless the probe starts above it (:func:`passes`), so a player
rising through a platform is not held by it, and stands on it once it is up.

>>> import pymunk
>>> space = pymunk.Space()
>>> space.gravity = (0.0, -9.81)
>>> platform = pymunk.Segment(space.static_body, (-2.0, 2.0), (2.0, 2.0), 0.1)
>>> make_one_way(space, platform)
>>> space.add(platform)
>>> ball = pymunk.Body(1.0, 1.0)
>>> ball.position, ball.velocity = (0.0, 1.0), (0.0, 8.0)      # m, m/s: thrown up through it
>>> space.add(ball, pymunk.Circle(ball, 0.3))
>>> for _ in range(360):
...     space.step(1.0 / 120.0)
>>> round(ball.position.y, 1), abs(ball.velocity.y) < 1e-6     # m: resting on its top
(2.4, True)
"""

from __future__ import annotations

import pymunk

__all__ = ["FROM_ABOVE", "ONE_WAY", "install", "make_one_way", "passes", "top"]

ONE_WAY = 0x0E1
"""The ``collision_type`` that marks a one-way shape."""
FROM_ABOVE = 0.5
"""A contact begins from above when its normal lies within 60° of the top's direction (its
cosine at least this): a body that meets the shape's side (a normal across the top, whose
cosine rounds either way of 0) passes through it."""


def top(shape: pymunk.Shape) -> tuple[float, float]:
    """The direction a one-way shape's top faces, in world coordinates now (unit): its body's
    local +y."""
    body = shape.body
    if body is None:
        return (0.0, 1.0)
    r = body.rotation_vector
    return (-r.y, r.x)


def _begin(arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
    """A contact with a one-way shape begins only from above it (it is ignored until the two
    part otherwise)."""
    a, b = arbiter.shapes
    one_way, sign = (a, 1.0) if a.collision_type == ONE_WAY else (b, -1.0)
    n = arbiter.normal  # from a toward b
    ux, uy = top(one_way)
    arbiter.process_collision = sign * (n.x * ux + n.y * uy) >= FROM_ABOVE


def install(space: pymunk.Space) -> None:
    """Put the one-way rule into ``space`` (again: the same rule)."""
    space.on_collision(ONE_WAY, None, begin=_begin)


def make_one_way(space: pymunk.Space, shape: pymunk.Shape) -> None:
    """Make ``shape`` one-way in ``space`` (before or after it is added)."""
    shape.collision_type = ONE_WAY
    install(space)


def passes(shape: pymunk.Shape, x: float, y: float, clearance: float) -> bool:
    """A probe from (x, y) (m) passes ``shape``: it is one-way and the point is not above it,
    clear of it by ``clearance`` (m, the probe's radius: a probe that starts touching it reads
    no surface)."""
    if shape.collision_type != ONE_WAY:
        return False
    q = shape.point_query((x, y))
    ux, uy = top(shape)
    return q.distance < clearance or q.gradient.x * ux + q.gradient.y * uy <= 0.0
