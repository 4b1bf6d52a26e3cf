"""Laws of the body registry: unique names, lookups, sleep for a whole group only, joints, and a
world locked during its step (what a hook adds or removes joins or leaves when the step ends)."""

from __future__ import annotations

import pymunk
import pytest

from playground.world.config import WorldConfig
from playground.world.schedule import Stage
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
    world.add_constraint(pymunk.PinJoint(a, b))
    world.remove("a")
    assert not world.space.constraints and len(world.space.shapes) == 1
    assert b.space is world.space


def _floor_and_crate() -> World:
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    world.add_box("crate", mass=1.0, size=(1.0, 1.0), position=(0.0, 2.0))
    world.track("crate")
    return world


def test_a_hook_that_removes_a_body_mid_step_removes_it_when_the_step_ends() -> None:
    """Law: a body removed from a CONTROL hook is still there for the rest of the step (it is
    stepped, its readings are taken, an OBSERVE hook sees it) and gone when the step ends; a
    second removal in the same step is refused at once."""
    world = _floor_and_crate()
    seen: list[bool] = []

    def drop(w: World) -> None:
        if w.steps == 0:
            w.remove("crate")
            with pytest.raises(KeyError, match="already removed in this step"):
                w.remove("crate")

    world.on(Stage.CONTROL, drop)
    world.on(Stage.OBSERVE, lambda w: seen.append("crate" in w.names))
    crate = world.body("crate")
    world.step()
    assert seen == [True]
    assert crate.velocity.y < 0.0  # stepped in the step it was removed in
    assert world.names == [] and crate.space is None
    world.step()
    assert seen == [True, False]


def test_a_hook_that_adds_a_body_mid_step_adds_it_when_the_step_ends() -> None:
    """Law: a body added from a CONTROL hook joins when the step ends: the step does not move it,
    asking for it during the step says when it comes, and tracking it waits with it; an add in
    the EVENTS stage (before the world locks) acts at once."""
    world = _floor_and_crate()
    box = pymunk.Body(1.0, 1.0)
    box.position = (3.0, 4.0)

    def spawn(w: World) -> None:
        if w.steps == 0:
            assert w.locked
            w.add("box", box, pymunk.Circle(box, 0.25))
            w.track("box")
            with pytest.raises(KeyError, match="joins when the step ends"):
                w.body("box")

    world.on(Stage.CONTROL, spawn)
    world.step()
    assert not world.locked
    assert world.body("box") is box and box.velocity == (0.0, 0.0)
    world.step()
    assert box.velocity.y < 0.0
    assert world.forces("box").specific == pytest.approx((0.0, 0.0), abs=1e-9)
    seen: list[float] = []
    world.at(world.time, lambda w: w.add_box("early", mass=1.0, size=(0.5, 0.5), position=(-3, 4)))
    world.on(Stage.OBSERVE, lambda w: seen.append(w.body("early").velocity.y))
    world.step()
    assert seen[0] < 0.0  # stepped in the step whose EVENTS stage added it


def test_hooks_and_later_actions_from_a_hook_start_when_the_step_ends() -> None:
    """Law: a hook added from a hook runs from the next step on, and ``later`` runs its action
    when the step ends, after the changes asked for before it."""
    world = World()
    calls: list[str] = []

    def added(w: World) -> None:
        calls.append(f"added {w.steps}")

    def first(w: World) -> None:
        if w.steps == 0:
            w.on(Stage.CONTROL, added)
            w.later(lambda w2: calls.append(f"later {w2.steps}"))

    world.on(Stage.CONTROL, first)
    world.run(2 * world.config.dt)
    assert calls == ["later 1", "added 1"]


def test_joints_are_checked_added_and_removed_at_once() -> None:
    """Law: ``add_constraint`` takes a joint between bodies of this world (or the static body) at
    once, even from a hook; a joint to another world's body, or one added twice, is refused
    naming the end; ``remove`` takes a joint out, and refuses one that is not in."""
    world = _floor_and_crate()
    stranger = World().add_box("s", mass=1.0, size=(1.0, 1.0), position=(0.0, 0.0))
    with pytest.raises(ValueError, match=r"^constraint\.b: expected a body of this world"):
        world.add_constraint(pymunk.PinJoint(world.body("crate"), stranger))
    pin = world.add_constraint(pymunk.PinJoint(world.body("crate"), world.space.static_body))
    with pytest.raises(ValueError, match="already in this world"):
        world.add_constraint(pin)
    world.remove(pin)
    with pytest.raises(ValueError, match="is not in this world"):
        world.remove(pin)
    grabbed: list[int] = []

    def grab(w: World) -> None:
        if w.steps == 0:
            w.add_constraint(pymunk.PinJoint(w.body("crate"), w.space.static_body, (0, 0), (0, 2)))
            grabbed.append(len(w.space.constraints))

    world.on(Stage.CONTROL, grab)
    world.step()
    assert grabbed == [1]
    assert world.body("crate").position.y == pytest.approx(2.0, abs=1e-3)  # held this step


def test_a_joint_to_a_body_waiting_to_join_waits_with_it() -> None:
    """Law: a joint added from a hook to a body added in the same step joins with the body."""
    world = _floor_and_crate()
    box = pymunk.Body(1.0, 1.0)

    def spawn(w: World) -> None:
        if w.steps == 0:
            w.add("box", box, pymunk.Circle(box, 0.25))
            w.add_constraint(pymunk.PinJoint(box, w.body("crate")))
            assert not w.space.constraints

    world.on(Stage.CONTROL, spawn)
    world.step()
    assert len(world.space.constraints) == 1
