"""CountingSpace counts every removal, one asked for from a collision callback inside
``space.step`` too (made at the end of that step), and is a pymunk space otherwise."""

from __future__ import annotations

import pymunk

from playground import World
from playground._engine.space import CountingSpace


def test_a_removal_from_inside_the_step_is_counted_and_made_by_its_end() -> None:
    space = CountingSpace()
    space.gravity = (0.0, -9.81)  # m/s²
    space.add(pymunk.Segment(space.static_body, (-5.0, 0.0), (5.0, 0.0), 0.05))
    ball = pymunk.Body(1.0, 1.0)  # kg, kg·m²
    ball.position = (0.0, 0.5)  # m
    space.add(ball, pymunk.Circle(ball, 0.25))

    def begin(arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        space.remove(ball, *ball.shapes)

    space.on_collision(begin=begin)
    steps = 0
    while space.removals == 0 and steps < 120:
        space.step(1.0 / 120.0)  # s
        steps += 1
    assert space.removals == 1 and ball.space is None and not space.bodies


def test_a_copy_is_a_counting_space_with_the_count() -> None:
    space = CountingSpace()
    body = pymunk.Body(1.0, 1.0)
    space.add(body)
    space.remove(body)
    copy = space.copy()
    assert isinstance(copy, CountingSpace) and copy.removals == 1


def test_a_named_body_removed_by_a_collision_callback_leaves_the_world() -> None:
    """The world learns of a removal made inside its physics stage at the next step."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    ball = world.add_box("ball", mass=1.0, size=(0.5, 0.5), position=(0.0, 1.0))
    world.track("ball")

    def begin(arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        if ball.space is space:
            space.remove(ball, *ball.shapes)

    world.space.on_collision(begin=begin)
    world.run(1.0)
    assert world.names == [] and world.tracked_bodies == []
