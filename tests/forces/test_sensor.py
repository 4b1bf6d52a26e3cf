"""Laws of the force sensor on a plain pymunk space: a crate reads its weight, the sensor reads
what a world reads of the same scene to the last bit, and the explicit hooks are the step."""

from __future__ import annotations

import dataclasses
import math

import pymunk
import pytest

from playground import World, WorldConfig
from playground.forces import ForceSensor

TOL_REST = 1e-6
"""Relative: a box at rest on the floor for a second reads its weight to rounding."""


def _space_like(world: World) -> pymunk.Space:
    """A plain space with the settings the world gives its own."""
    space = pymunk.Space()
    for name in (
        "gravity",
        "iterations",
        "damping",
        "collision_slop",
        "collision_persistence",
        "sleep_time_threshold",
    ):
        setattr(space, name, getattr(world.space, name))
    return space


def _crates(space: pymunk.Space, n: int) -> list[pymunk.Body]:
    """A floor and ``n`` crates of 10 kg side by side on it, dropped from 5 cm."""
    space.add(pymunk.Segment(space.static_body, (-60.0, 0.0), (60.0, 0.0), 0.05))
    crates = []
    for i in range(n):
        crate = pymunk.Body(10.0, pymunk.moment_for_box(10.0, (1.0, 1.0)))
        crate.position = (1.5 * i - 0.75 * n, 0.6)
        space.add(crate, pymunk.Poly.create_box(crate, (1.0, 1.0)))
        crates.append(crate)
    return crates


@pytest.mark.parametrize("n", [1, 40])
def test_a_crate_on_a_plain_space_reads_its_weight(n: int) -> None:
    """Law: 10 kg crates at rest on the floor of a plain space read 98.1 N of support and
    perceive g, one crate (served in plain floats) or forty (served with numpy)."""
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    crates = _crates(space, n)
    sensor = ForceSensor(space)
    for crate in crates:
        sensor.track(crate)
    for _ in range(120):
        sensor.step(1 / 60)
    assert sensor.bodies == crates
    for crate in crates:
        f = sensor.readings(crate)
        assert f.valid and f.support[1] == pytest.approx(98.1, rel=TOL_REST)
        g = sensor.perceived_gravity(crate)
        assert g == pytest.approx((0.0, -9.81), rel=TOL_REST, abs=1e-9)
        assert sensor.perceived_up(crate) == pytest.approx((0.0, 1.0))


@pytest.mark.parametrize("n", [3, 40])
def test_the_sensor_reads_what_a_world_reads(n: int) -> None:
    """Law: the same crates on a world's space, tracked by the world, and on a plain space with
    the world's settings, tracked by a sensor, read the same engine force, support and perceived
    gravity every step, to the last bit (one code behind both), with the contact split on, also
    across a change of the step's length."""
    world = World(WorldConfig(contact_split=True))
    space = _space_like(world)
    in_world, alone = _crates(world.space, n), _crates(space, n)
    world.track(*in_world)
    sensor = ForceSensor(space, contact_split=True)
    unknown = 0
    for crate in alone:
        sensor.track(crate)
    for k in range(90):
        if k == 60:  # a new step length: Chipmunk rescales its warm starts, the split is unknown
            world.config = dataclasses.replace(world.config, dt=world.config.dt / 2)
        world.step()
        sensor.step(world.config.dt)
        for a, b in zip(in_world, alone, strict=True):
            fa, fb = world.forces(a), sensor.readings(b)
            assert (fa.engine, fa.support) == (fb.engine, fb.support)
            assert fa.split_valid == fb.split_valid
            same = fa.contact == fb.contact
            assert same or (math.isnan(fa.contact[0]) and math.isnan(fb.contact[0]))
            assert world.perceived_gravity(a) == sensor.perceived_gravity(b)
        unknown += k == 60 and not world.forces(in_world[0]).split_valid
    assert unknown  # the rescaled step was seen


def test_the_explicit_hooks_are_the_step() -> None:
    """Law: before_step, the game's own space.step calls with after_substep after each, then
    finish, read what step(dt, substeps) reads, bit for bit; out of order they refuse."""
    spaces = [pymunk.Space(), pymunk.Space()]
    sensors = []
    for space in spaces:
        space.gravity = (0.0, -9.81)
        sensor = ForceSensor(space)
        sensor.track(_crates(space, 1)[0])
        sensors.append(sensor)
    dt = 1 / 60
    for _ in range(60):
        sensors[0].step(dt, substeps=3)
        sensors[1].before_step(3)
        for _ in range(3):
            spaces[1].step(dt / 3)
            sensors[1].after_substep()
        sensors[1].finish(dt)
    a, b = (s.table() for s in sensors)
    assert a.engine.tolist() == b.engine.tolist()
    assert a.perceived_gravity.tolist() == b.perceived_gravity.tolist()
    with pytest.raises(RuntimeError, match="before_step"):
        sensors[1].after_substep()
    sensors[1].before_step(2)
    spaces[1].step(dt / 2)
    sensors[1].after_substep()
    with pytest.raises(RuntimeError, match="1 after_substep calls"):
        sensors[1].finish(dt)


def test_a_body_of_another_space_is_refused() -> None:
    """Law: the sensor tracks bodies of its own space only, and reads only tracked ones."""
    sensor = ForceSensor(pymunk.Space())
    stranger = pymunk.Body(1.0, 1.0)
    with pytest.raises(ValueError, match="sensor's space"):
        sensor.track(stranger)
    with pytest.raises(KeyError, match="not tracked"):
        sensor.readings(stranger)


@pytest.mark.parametrize("n", [1, 40])
def test_a_crate_taken_out_with_space_remove_is_untracked(n: int) -> None:
    """Rule (ForceSensor.untrack): a tracked body the game takes out with ``space.remove`` is
    untracked by the next frame, whichever implementation serves the rest, and reading it says
    it left; the others read their weight on."""
    space = pymunk.Space()
    space.gravity = (0.0, -9.81)
    crates = _crates(space, n)
    sensor = ForceSensor(space)
    for crate in crates:
        sensor.track(crate)
    for _ in range(60):
        sensor.step(1 / 60)
    gone = crates[0]
    space.remove(gone, *gone.shapes)
    for _ in range(60):
        sensor.step(1 / 60)
    assert sensor.bodies == crates[1:]
    with pytest.raises(KeyError, match="not in the sensor's space"):
        sensor.readings(gone)
    for crate in crates[1:]:
        assert sensor.readings(crate).support[1] == pytest.approx(98.1, rel=TOL_REST)
