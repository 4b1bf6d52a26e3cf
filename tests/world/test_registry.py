"""Laws of the body registry: unique names, lookups by name and by point, and sleep for a whole
group only."""

from __future__ import annotations

import pymunk
import pytest

from playground.world.config import WorldConfig
from playground.world.world import World


def test_names_are_unique_and_lookups_name_the_known_bodies() -> None:
    """Law: a second body of the same name is refused; an unknown name's KeyError lists the known
    ones; ``name_of`` inverts ``body`` and an unnamed body has no name."""
    world = World()
    world.add_box("a", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
    with pytest.raises(ValueError, match="a: a body with this name already exists"):
        world.add_box("a", mass=1.0, size=(1.0, 1.0), position=(3.0, 0.5))
    with pytest.raises(KeyError, match=r"known: a\)"):
        world.body("b")
    assert world.name_of(world.body("a")) == "a"
    assert world.name_of(world.space.static_body) is None


def test_sleep_puts_the_touching_group_to_sleep_and_needs_sleeping_on() -> None:
    """Law: ``sleep`` puts a body and every dynamic body touching it to sleep (a stack sleeps as
    one), leaves a body that touches nothing awake, and is refused with sleeping off."""
    world = World(WorldConfig(sleep_time=1.0))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    world.add_box("low", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
    world.add_box("high", mass=1.0, size=(1.0, 1.0), position=(0.0, 1.5))
    world.add_box("apart", mass=1.0, size=(1.0, 1.0), position=(3.0, 0.5))
    world.run(0.2)
    world.sleep("low")
    assert world.body("low").is_sleeping and world.body("high").is_sleeping
    assert not world.body("apart").is_sleeping
    with pytest.raises(ValueError, match="sleeping is off"):
        World().sleep("x")


def test_remove_takes_shapes_and_joints_along() -> None:
    """Law: removing a body removes its shapes and its constraints from the space."""
    world = World()
    a = world.add_box("a", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.5))
    b = world.add_box("b", mass=1.0, size=(1.0, 1.0), position=(2.0, 0.5))
    world.space.add(pymunk.PinJoint(a, b))
    world.remove("a")
    assert not world.space.constraints and len(world.space.shapes) == 1
    assert b.space is world.space
