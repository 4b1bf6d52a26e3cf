"""Laws of the contact split of the scalar implementation: each body's arbiter sums equal the
batch implementation's bit for bit, and a step whose split may be wrong is unknown on both."""

from __future__ import annotations

import dataclasses
import math
import random

import pymunk
import pytest

from playground import World, WorldConfig
from playground._engine import raw

STEPS = 180
"""1.5 s at 120 Hz: the balls roll, the box lands on the plank and the pile settles."""


def _plank_on_balls(scalar_max: int, seed: int, persistence: int) -> World:
    """A plank on six balls of random sizes on the floor, a box dropped on it: the plank has up
    to seven arbiters at once, a ball up to four (floor, plank, its neighbours)."""
    rng = random.Random(seed)
    world = World(WorldConfig(contact_split=True))
    world.space.collision_persistence = persistence
    world.scalar_max_bodies = scalar_max
    world.add_static_segment((-10.0, 0.0), (10.0, 0.0), radius=0.0)
    for i in range(6):
        r = 0.3 + 0.02 * rng.random()
        m = rng.uniform(0.5, 3.0)
        ball = pymunk.Body(m, pymunk.moment_for_circle(m, 0.0, r))
        ball.position = (0.6 * i - 1.5, r)
        shape = pymunk.Circle(ball, r)
        shape.friction = 0.9
        world.add(f"ball{i}", ball, shape)
    world.add_box(
        "plank", mass=4.0, size=(3.6, 0.1), position=(0.0, 0.72), angle=0.02 * rng.random()
    )
    world.add_box("box", mass=2.0, size=(0.4, 0.4), position=(rng.uniform(-1.0, 1.0), 1.5))
    world.track(*world.names)
    return world


def _same(a: tuple[float, float], b: tuple[float, float]) -> bool:
    return all(x == y or (math.isnan(x) and math.isnan(y)) for x, y in zip(a, b, strict=True))


@pytest.mark.parametrize(
    ("seed", "persistence", "callbacks"),
    [(seed, persistence, True) for seed in range(3) for persistence in (1, 3)]
    + [(0, 1, False), (0, 3, False)],
)
def test_a_body_with_many_arbiters_reads_the_same_split(
    seed: int, persistence: int, callbacks: bool, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Law: on a body with several arbiters at once, the scalar implementation's contact, contact
    normal, constraint and split_valid equal the batch implementation's bit for bit, every step,
    with arbiters dropped at once or kept three steps, and where cffi callbacks are refused (the
    arbiters are then iterated by pymunk); the scene does give known splits, unknown ones (first
    contacts from cached arbiters) with persistence 3, and bodies with three or more arbiters."""
    if not callbacks:
        monkeypatch.setattr(raw, "arbiter_callback", lambda visit: None)
    scalar, vector = (_plank_on_balls(m, seed, persistence) for m in (10**6, 0))
    known = unknown = crowded = 0
    for _ in range(STEPS):
        scalar.step()
        vector.step()
        assert scalar.tracked_kind == "scalar" and vector.tracked_kind == "batch"
        for name in scalar.names:
            a, b = scalar.forces(name), vector.forces(name)
            assert a.split_valid == b.split_valid, name
            for field in ("contact", "contact_normal", "contact_friction", "constraint"):
                assert _same(getattr(a, field), getattr(b, field)), (scalar.steps, name, field)
            known += a.split_valid
            unknown += a.valid and not a.split_valid
            arbiters: list[pymunk.Arbiter] = []
            scalar.body(name).each_arbiter(arbiters.append)
            crowded += len(arbiters) >= 3
    assert known > STEPS
    assert (unknown > 0) == (persistence > 1)
    assert crowded > STEPS


def test_a_rescaled_warm_start_is_unknown_on_both_paths() -> None:
    """Law: the step after dt changes, a body with a continuing contact has no split on either
    path (Chipmunk rescaled its warm start), and has one again the step after."""
    worlds = [_plank_on_balls(m, 0, 1) for m in (10**6, 0)]
    for world in worlds:
        world.run(1.0)
        world.config = WorldConfig(dt=1.0 / 240.0, contact_split=True)
        world.step()
    assert [w.forces("plank").split_valid for w in worlds] == [False, False]
    for world in worlds:
        world.step()
    assert [w.forces("plank").split_valid for w in worlds] == [True, True]


def _split_turned_off(world: World, scalar_max: int) -> tuple[bool, tuple[float, float]]:
    """Run with the split on, then one step with it off and ``scalar_max`` as the world's
    scalar_max_bodies: the box's split_valid and contact."""
    world.run(0.25)
    assert world.forces("box").split_valid
    world.scalar_max_bodies = scalar_max
    world.config = dataclasses.replace(world.config, contact_split=False)
    world.step()
    f = world.forces("box")
    return f.split_valid, f.contact


def test_turning_the_split_off_clears_its_readings_on_both_paths() -> None:
    """Law: the step after the contact split is turned off, a body has no split reading (not
    valid, contact NaN) on the scalar implementation as on the vectorised one."""
    results = []
    for most in (10**6, 0):
        world = _plank_on_balls(most, 0, 1)
        results.append(_split_turned_off(world, most))
        assert (world.tracked_kind == "scalar") == (most > 0)
    for valid, contact in results:
        assert not valid and all(math.isnan(c) for c in contact)


def test_split_readings_handed_to_the_scalar_path_with_the_split_off_are_cleared() -> None:
    """Law: when the world moves to the scalar implementation at the moment the split is turned
    off, the split readings the batch implementation held are cleared on the first scalar step."""
    world = _plank_on_balls(0, 0, 1)
    valid, contact = _split_turned_off(world, 10**6)
    assert world.tracked_kind == "scalar"
    assert not valid and all(math.isnan(c) for c in contact)
