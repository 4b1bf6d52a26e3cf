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


def test_same_time_events_keep_their_order_after_earlier_ones_ran() -> None:
    """Law: events at the same time run in the order they were scheduled, also when they were
    scheduled after earlier events had already run (the order is a counter that never goes
    back, not the number of pending events, which shrinks as events run)."""
    world = World()
    dt = world.config.dt
    ran: list[str] = []
    world.at(dt, lambda w: ran.append("a"))
    world.at(dt, lambda w: ran.append("b"))
    world.at(4 * dt, lambda w: ran.append("c"))
    world.run(3 * dt)
    world.at(4 * dt, lambda w: ran.append("d"))
    world.at(4 * dt, lambda w: ran.append("e"))
    world.run(3 * dt)
    assert ran == ["a", "b", "c", "d", "e"]


def test_events_scheduled_out_of_order_run_in_time_order() -> None:
    """Law: whatever the order of scheduling, events run by time, then by scheduling order
    (a heap keyed by both; 1 000 events at 40 distinct times in random order)."""
    import random

    world = World()
    dt = world.config.dt
    rng = random.Random(23)
    plan = [rng.randrange(40) * dt for _ in range(1000)]
    ran: list[tuple[float, int]] = []
    for order, t in enumerate(plan):
        world.at(t, lambda w, t=t, order=order: ran.append((t, order)))
    world.run(41 * dt)
    assert ran == sorted(ran)
    assert len(ran) == len(plan)
