"""Laws of the contact/constraint split: never a phantom joint force.

With the split on, ``constraint = engine − Σ arbiter impulses / dt`` is what joints did. In a
scene without any joint it must be zero on every step, or the step's split must say it is unknown
(NaN, ``split_valid`` False) — never a wrong number. Chipmunk's arbiters report impulses they did
not apply on a contact made again from a cached arbiter and on a rescaled warm start (see
``ForceSolver``); these scenes make both happen.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import pymunk
import pytest

from playground import Elevator, World, WorldConfig

G = 9.81
"""|g|, m/s² (the world's default)."""

TOL_REL = 1e-9
"""Engine force and arbiter sum are two readings of the same impulses: they differ only by float
rounding in sums of a few terms."""

TOL_ABS = 1e-9
"""Newtons: near-zero components compare absolutely."""

CHIPMUNK_PERSISTENCE = 3
"""Chipmunk's default ``collision_persistence``: arbiters outlive their contact by 3 steps."""

Scene = Callable[[WorldConfig], World]


def sinking_platform(cfg: WorldConfig) -> World:
    """A 10 kg box on a platform that accelerates downward at 3 m/s² from t = 0.5 s: the box
    keeps losing and re-making its contact (one step in three on pymunk's defaults)."""
    world = World(cfg)
    plat = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    shape = pymunk.Poly.create_box(plat, (3.0, 0.2))
    shape.friction = 1.0
    world.add("platform", plat, shape)
    path = Elevator(start=(0.0, 0.0), axis=(0.0, -1.0), acceleration=3.0, start_time=0.5)
    world.add_mover("platform", path)
    world.add_box("box", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.6))
    world.track("box")
    return world


def woken_box(cfg: WorldConfig) -> World:
    """A 10 kg box falls asleep on the floor; at t = 2 s another 10 kg box is dropped onto it
    from 1.5 m above its top and bounces on it."""
    world = World(dataclasses.replace(cfg, sleep_time=0.1))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    world.add_box("box", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    world.track("box")

    def drop(w: World) -> None:
        w.add_box("dropped", mass=10.0, size=(1.0, 1.0), position=(0.0, 2.0))
        w.track("dropped")

    world.at(2.0, drop)
    return world


SCENES: dict[str, Scene] = {"sinking_platform": sinking_platform, "woken_box": woken_box}

CONFIGS = {
    "plain": WorldConfig(contact_split=True),
    "substeps3": WorldConfig(contact_split=True, substeps=3),
}

STEPS = 480
"""4 s at the default dt: the platform accelerates for 3.5 s; the dropped box lands at 2.4 s."""


def phantom(world: World, name: str) -> float:
    """|constraint| beyond round-off, N (0 when the split is right); NaN if unknown."""
    f = world.forces(name)
    return math.hypot(*f.constraint) - (TOL_REL * math.hypot(*f.engine) + TOL_ABS)


def tracked(world: World) -> list[str]:
    return [n for n in ("box", "dropped") if n in world.names]


@pytest.mark.parametrize("config", CONFIGS.values(), ids=CONFIGS.keys())
@pytest.mark.parametrize("scene", SCENES.values(), ids=SCENES.keys())
def test_no_phantom_joint_force(scene: Scene, config: WorldConfig) -> None:
    """Law: in a scene without joints the split is known and the constraint force is zero on
    every step a body is integrated (the world drops arbiters that lose their contact, so no
    contact is re-made from a stale one)."""
    world = scene(config)
    touched = 0
    for _ in range(STEPS):
        world.step()
        for name in tracked(world):
            f = world.forces(name)
            if not f.valid:
                continue  # asleep: not integrated, no reading
            assert f.split_valid, (name, world.time, f)
            assert phantom(world, name) <= 0.0, (name, world.time, f)
            touched += math.hypot(*f.contact) > 1.0
    assert touched > 30, "the bodies hardly touched anything: the law was not exercised"


@pytest.mark.parametrize("scene", SCENES.values(), ids=SCENES.keys())
def test_cached_arbiter_steps_are_unknown(scene: Scene) -> None:
    """Law: with Chipmunk's own arbiter persistence put back on the space, a step whose split
    could be wrong is marked unknown (NaN, split_valid False); every step with a split has the
    right one. Some steps are unknown (the detection is exercised)."""
    world = scene(WorldConfig(contact_split=True))
    world.space.collision_persistence = CHIPMUNK_PERSISTENCE
    known = unknown = 0
    for _ in range(STEPS):
        world.step()
        for name in tracked(world):
            f = world.forces(name)
            if not f.valid:
                continue
            if f.split_valid:
                known += 1
                assert phantom(world, name) <= 0.0, (name, world.time, f)
            else:
                unknown += 1
                for v in (f.contact, f.contact_normal, f.contact_friction, f.constraint):
                    assert all(math.isnan(x) for x in v), (name, world.time, f)
    assert unknown > 0, "no step was marked unknown: the stale arbiters were not detected"
    assert known > unknown, (known, unknown)  # targeted: not every step is given up


def test_rescaled_warm_start_is_unknown() -> None:
    """Law: when the step length changes, Chipmunk warm-starts a continuing contact with its old
    impulse times h/h_prev but reports the old impulse: that first substep's split is unknown;
    the steps after it are known and right."""
    world = World(WorldConfig(contact_split=True))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    world.add_box("box", mass=10.0, size=(1.0, 1.0), position=(0.0, 0.5))
    world.track("box")
    world.run(1.0)
    for change in ({"dt": 1.0 / 60.0}, {"substeps": 3}):
        world.config = dataclasses.replace(world.config, **change)  # type: ignore[arg-type]
        world.step()
        f = world.forces("box")
        assert f.valid and not f.split_valid, (change, f)
        assert math.isnan(f.constraint[1])
        for _ in range(10):
            world.step()
            assert world.forces("box").split_valid
            assert phantom(world, "box") <= 0.0, (change, world.forces("box"))
    weight = 10.0 * G
    assert abs(world.forces("box").contact[1] - weight) < 1e-3 * weight
