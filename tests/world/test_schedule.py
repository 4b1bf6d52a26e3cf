"""Laws of the schedule: hooks run in their stage in the order they were added, off is safe
from inside a step, and timed events run once, in order, in the first step at or after their
time."""

from __future__ import annotations

import pytest

from playground.world.schedule import Stage
from playground.world.world import World


def test_off_stops_a_hook_even_from_inside_the_step() -> None:
    """World.off is the opposite of World.on. A hook that takes another one off during a step
    does not disturb the stage that is running: both ran this step, only the first runs after."""
    world = World()
    calls: list[str] = []

    def second(w: World) -> None:
        calls.append("second")

    def first(w: World) -> None:
        calls.append("first")
        if w.steps == 1:
            w.off(Stage.OBSERVE, second)

    world.on(Stage.OBSERVE, first)
    world.on(Stage.OBSERVE, second)
    world.run(3 * world.config.dt)
    assert calls == ["first", "second", "first", "first"]
    with pytest.raises(ValueError, match="second is not registered in OBSERVE"):
        world.off(Stage.OBSERVE, second)


def test_events_run_once_in_time_then_schedule_order() -> None:
    """Law: an event runs in the EVENTS stage of the first step starting at or after its time;
    two at the same time run in the order they were scheduled; each runs once."""
    world = World()
    dt = world.config.dt
    ran: list[tuple[str, int]] = []
    world.at(2 * dt, lambda w: ran.append(("late", w.steps)))
    world.at(dt, lambda w: ran.append(("first", w.steps)))
    world.at(dt, lambda w: ran.append(("second", w.steps)))
    world.run(5 * dt)
    assert ran == [("first", 1), ("second", 1), ("late", 2)]


def test_hooks_run_only_in_the_four_hook_stages() -> None:
    """Law: the other stages (GRAVITY, MOVERS, PHYSICS, FORCES, FILTER) are the world's own:
    ``on`` refuses them, naming the stage."""
    world = World()
    with pytest.raises(ValueError, match=r"not Stage\.PHYSICS"):
        world.on(Stage.PHYSICS, lambda w: None)
