"""Gameplay events, each on a scene that causes it: landings from drops, crusher's crushed and
freed, flying_whale's grab and release, a knock-over and getting up, gravity_flip's flip."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from playground import (
    Controller,
    ControllerConfig,
    Crushed,
    Freed,
    Gameplay,
    GameplayEvent,
    GotUp,
    Grabbed,
    GravityChanged,
    Idle,
    Intent,
    Landed,
    LostBalance,
    Released,
    World,
)
from playground.gameplay import MIN_LANDING_SPEED
from playground.level.loading import load
from playground.scene import Scene, build

LEVELS = Path(__file__).resolve().parent.parent / "levels"
G = 9.81  # m/s², the default field
REST = 1.0
"""m: the default capsule's centre at rest over a floor segment of radius 0.05 m (its ride height,
0.95 m, is held from the probe circle's hit on the segment's surface)."""
REACH = 0.55
"""m above rest where the probe first finds the floor: probe_length 1.4 m + probe_radius 0.1 m +
the segment's 0.05 m, less the rest height."""
TOL_MOMENTUM_REL = 1e-9
"""Relative: the support is recovered from the body's own velocity change, so the momentum the
support beyond the weight took out of a fall is mass × speed to rounding."""
TOL_SPEED = 1e-9
"""m/s: the reported speed is one of the body's velocities, read back to rounding."""


def drop(height: float, mass: float = 70.0) -> list[GameplayEvent]:
    """The player (``mass`` kg) released from rest ``height`` m above its rest over a floor."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    player = Controller(world, "player", position=(0.0, REST + height), config=config(mass))
    events = Gameplay(world, [player])
    world.run(2.0)
    return events.poll()


def config(mass: float, jump_speed: float = 4.0) -> ControllerConfig:
    return ControllerConfig(mass=mass, jump_speed=jump_speed)


def level(name: str, seconds: float) -> tuple[Scene, Gameplay]:
    scene = build(load(LEVELS / f"{name}.toml"))
    events = Gameplay(scene.world, scene.controllers.values())
    scene.run(seconds)
    return scene, events


def kinds(events: list[GameplayEvent], name: str) -> list[str]:
    return [type(e).__name__ for e in events if e.name == name]


def landed(events: list[GameplayEvent]) -> Landed:
    assert [type(e) for e in events] == [Landed], events
    (event,) = events
    assert isinstance(event, Landed)
    return event


@pytest.mark.parametrize("mass", [35.0, 70.0, 140.0])  # kg
def test_a_drop_lands_once_and_its_impulse_is_mass_times_speed(mass: float) -> None:
    """Law: from any height (short drops within the probe's reach too) one landing, its speed
    no more than free fall's from that height, exactly free fall's to the probe's reach above it,
    and the impulse that stopped it m·v; higher hits harder."""
    speeds = []
    for height in (0.05, 0.3, 1.0, 2.0, 4.0):  # m above rest
        event = landed(drop(height, mass))
        assert MIN_LANDING_SPEED <= event.speed <= math.sqrt(2.0 * G * height)
        if height > REACH:
            assert event.speed >= math.sqrt(2.0 * G * (height - REACH))
        assert event.impulse == pytest.approx(mass * event.speed, rel=TOL_MOMENTUM_REL)
        assert event.impact > mass * G  # N: it felt more than its weight while stopping
        speeds.append(event.speed)
    assert speeds == sorted(speeds) and len(set(speeds)) == len(speeds)


def test_the_same_drop_hits_in_proportion_to_the_mass() -> None:
    """Law: the hover scales with the mass, so every mass falls alike and the impulse and the
    peak force scale with m."""
    light, heavy = landed(drop(1.0, 35.0)), landed(drop(1.0, 140.0))
    assert heavy.speed == pytest.approx(light.speed, rel=TOL_MOMENTUM_REL)
    assert heavy.impulse == pytest.approx(4.0 * light.impulse, rel=TOL_MOMENTUM_REL)
    assert heavy.impact == pytest.approx(4.0 * light.impact, rel=TOL_MOMENTUM_REL)


def test_a_player_built_standing_has_not_landed() -> None:
    assert drop(0.0) == []


@pytest.mark.parametrize("jump_speed", [2.0, 4.0])  # m/s: apex v²/2g within, beyond the reach
def test_a_jump_lands_once_at_its_fastest_fall(jump_speed: float) -> None:
    """A jump whose apex stays within the probe's reach touches down at its apex, at rest: the
    landing is the fall after it, reported with the fastest speed the body had (read here
    step by step), never a landing at 0 m/s."""
    world = World()
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    player = Controller(world, "player", position=(0.0, REST), config=config(70.0, jump_speed))
    events = Gameplay(world, [player])
    world.run(0.5)
    player.intent = Intent(jump=True)
    world.step()
    player.intent = Intent()
    fastest = 0.0
    for _ in range(240):
        world.step()
        fastest = max(fastest, -player.body.velocity.y)
    event = landed(events.poll())
    assert event.time > 0.5 and event.speed == pytest.approx(fastest, abs=TOL_SPEED)
    assert MIN_LANDING_SPEED < event.speed <= jump_speed
    assert event.impulse == pytest.approx(70.0 * event.speed, rel=TOL_MOMENTUM_REL)


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
    player = Controller(world, "player", position=(0.0, REST))
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
