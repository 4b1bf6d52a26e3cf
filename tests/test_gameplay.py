"""Gameplay events, each on a scene that causes it: landings from drops, crusher's crushed and
freed, flying_whale's grab and release, a knock-over and getting up, gravity_flip's flip."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from playground import (
    Controller,
    Crushed,
    Freed,
    Gameplay,
    GameplayEvent,
    GotUp,
    Grabbed,
    GravityChanged,
    Idle,
    Landed,
    LostBalance,
    Released,
    World,
)
from playground.level.loading import load
from playground.scene import Scene, build

LEVELS = Path(__file__).resolve().parent.parent / "levels"
G = 9.81  # m/s², the default field
TOL_SPEED_REL = 1e-12
"""Relative: a body released from rest falls at exactly n·g·dt after n steps (pymunk's explicit
velocity update), so the touchdown speed is g·t to rounding."""


def drop(height: float) -> list[GameplayEvent]:
    """The player released from rest ``height`` m above its ride height over a floor."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    player = Controller(world, "player", position=(0.0, 0.95 + height))
    events = Gameplay(world, [player])
    world.run(2.0)
    return events.poll()


def level(name: str, seconds: float) -> tuple[Scene, Gameplay]:
    scene = build(load(LEVELS / f"{name}.toml"))
    events = Gameplay(scene.world, scene.controllers.values())
    scene.run(seconds)
    return scene, events


def kinds(events: list[GameplayEvent], name: str) -> list[str]:
    return [type(e).__name__ for e in events if e.name == name]


def test_a_drop_lands_once_at_its_free_fall_speed_and_a_higher_one_hits_harder() -> None:
    impacts = []
    for height in (1.0, 2.0, 4.0):  # m
        events = drop(height)
        assert [type(e) for e in events] == [Landed]
        (landed,) = events
        assert isinstance(landed, Landed)
        assert landed.speed == pytest.approx(G * landed.time, rel=TOL_SPEED_REL)
        assert landed.impact > 70.0 * G  # N: more than its weight
        impacts.append(landed.impact)
    assert impacts == sorted(impacts) and len(set(impacts)) == 3


def test_a_player_built_standing_has_not_landed() -> None:
    assert drop(0.0) == []


def test_crusher_crushes_both_and_frees_only_the_strong_pusher() -> None:
    _scene, events = level("crusher", 3.0)
    queued = events.poll()
    assert kinds(queued, "player")[-1] == "Freed"  # it heaves its crate off
    assert kinds(queued, "weak")[-1] == "Crushed"  # its push budget is too small
    crushed = [e for e in queued if isinstance(e, Crushed)]
    assert all(e.load > 1500.0 for e in crushed)  # N: the crush threshold of both
    assert any(isinstance(e, Freed) and e.time > 1.0 for e in queued)


def test_flying_whale_grabs_the_whale_then_releases_it() -> None:
    scene, events = level("flying_whale", 2.0)
    (grabbed,) = events.poll()
    assert isinstance(grabbed, Grabbed)
    assert grabbed.held == "whale" and grabbed.time == pytest.approx(0.5)  # s: its grab input
    scene.controllers["player"].source = Idle()  # the grab let go
    scene.run(0.5)
    released = events.poll()
    assert [type(e) for e in released] == [Released]
    assert released[0].time == pytest.approx(2.0)


def test_a_knock_over_loses_balance_then_gets_up() -> None:
    world = World()
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    player = Controller(world, "player", position=(0.0, 0.95))
    events = Gameplay(world, [player])
    world.run(0.5)
    world.apply_impulse("player", (300.0, 0.0), point=(0.0, 1.8))  # N·s at the head
    world.run(6.0)
    assert [type(e) for e in events.poll()] == [LostBalance, GotUp]


def test_gravity_flip_reports_the_flip_once_with_the_new_gravity() -> None:
    _scene, events = level("gravity_flip", 1.5)
    (flipped,) = [e for e in events.poll() if isinstance(e, GravityChanged)]
    assert flipped.time == pytest.approx(1.0)  # s: the level's flip
    gx, gy = flipped.gravity
    assert gy > 0.0 and math.hypot(gx, gy) == pytest.approx(G)


def test_events_wait_for_the_game_and_are_delivered_once() -> None:
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    player = Controller(world, "player", position=(0.0, 2.95))
    events = Gameplay(world, [player])
    world.run(2.0)
    seen: list[GameplayEvent] = []
    assert events.deliver(seen.append) == 1 and isinstance(seen[0], Landed)
    assert events.deliver(seen.append) == 0 and events.poll() == []
    events.close()
    world.apply_impulse("player", (0.0, 300.0))  # up it goes, and lands again: unwatched
    world.run(2.0)
    assert events.poll() == []


def test_a_field_turning_with_time_is_not_a_gravity_change() -> None:
    """rotating_room's gravity turns every step by its own law: no field or rule was changed."""
    _scene, events = level("rotating_room", 2.0)
    assert not [e for e in events.poll() if isinstance(e, GravityChanged)]
