"""The benchmarks' pile: columns of boxes resting on a floor, as a world and as a bare space.

Both hold the same bodies in the same order, set up the same way, so a world step and a bare
``space.step`` of the pile can be compared (see :mod:`playground.bench.blocks`).

>>> world = pile_world(10, WorldConfig())
>>> len(world.names), len(pile_space(10, WorldConfig()).bodies)
(10, 10)
"""

from __future__ import annotations

import pymunk

from playground.gravity import STANDARD_GRAVITY, GravityField
from playground.world.config import WorldConfig
from playground.world.world import World

__all__ = ["BOX", "COLUMN", "pile_names", "pile_space", "pile_world"]

BOX = 0.5
"""Edge of every box, m."""

COLUMN = 5
"""Boxes per column of the pile."""


def _positions(n: int) -> list[tuple[float, float]]:
    """Box centres: columns of :data:`COLUMN` boxes, 0.1 m apart, resting on y = 0."""
    return [((i // COLUMN) * (BOX + 0.1), BOX / 2 + (i % COLUMN) * BOX) for i in range(n)]


def floor_length(n: int) -> float:
    """Length of the floor under a pile of ``n`` boxes, m."""
    return (n // COLUMN + 1) * (BOX + 0.1) + 2.0


def pile_names(n: int) -> list[str]:
    """The boxes' names in a :func:`pile_world`."""
    return [f"box{i}" for i in range(n)]


def pile_space(n: int, config: WorldConfig) -> pymunk.Space:
    """The pile in a bare space, set up as :class:`World` sets up its space."""
    space = pymunk.Space()
    space.iterations = config.iterations
    space.collision_slop = config.collision_slop
    space.collision_persistence = 1
    space.gravity = (0.0, -STANDARD_GRAVITY)
    seg = pymunk.Segment(space.static_body, (-2.0, -0.05), (floor_length(n), -0.05), 0.05)
    seg.friction = 1.0
    space.add(seg)
    for x, y in _positions(n):
        body = pymunk.Body(1.0, pymunk.moment_for_box(1.0, (BOX, BOX)))
        body.position = (x, y)
        shape = pymunk.Poly.create_box(body, (BOX, BOX))
        shape.friction = 0.8
        shape.elasticity = 0.0
        space.add(body, shape)
    return space


def pile_world(n: int, config: WorldConfig, gravity: GravityField | None = None) -> World:
    """The pile in a :class:`World` (boxes named ``box0`` … in :func:`pile_names`)."""
    world = World(config, gravity=gravity)
    world.add_static_segment((-2.0, -0.05), (floor_length(n), -0.05), radius=0.05)
    for name, p in zip(pile_names(n), _positions(n), strict=True):
        world.add_box(name, mass=1.0, size=(BOX, BOX), position=p)
    return world
