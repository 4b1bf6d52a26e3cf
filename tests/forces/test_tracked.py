"""Laws of the tracked set: reading the tracked bodies changes nothing, whichever implementation
serves them, and the table of every row holds what the readers give body by body."""

from __future__ import annotations

import numpy as np
import pytest

from playground import World, WorldConfig


def _pile(n: int, most: int) -> World:
    world = World(WorldConfig(contact_split=True))
    world.scalar_max_bodies = most
    world.add_static_segment((-20.0, 0.0), (20.0, 0.0))
    for i in range(n):
        world.add_box(f"b{i}", mass=1.0 + i, size=(0.5, 0.5), position=(0.3 * i, 0.3 + 0.6 * i))
    world.track(*world.names)
    return world


def _read_everything(world: World) -> None:
    world.readings()
    for name in world.names:
        world.forces(name)
        world.perceived_gravity(name)
        world.perceived_up(name)
        world.perceived_up_and_gravity(name)


@pytest.mark.parametrize(("most", "kind"), [(28, "scalar"), (0, "batch")])
def test_reading_changes_nothing(most: int, kind: str) -> None:
    """Law: a world whose readings are read every step runs bit for bit as one never read, also
    after it hands its state to the other implementation (a body tracked more, then planned
    again), readings and perceived gravity included."""
    read, unread = _pile(4, most), _pile(4, most)
    assert read.tracked_kind == unread.tracked_kind == "batch"  # nothing planned yet
    for step in range(240):
        if step == 120:
            for world in (read, unread):
                world.scalar_max_bodies = 28 - most  # the other implementation from here on
        read.step()
        unread.step()
        if step < 120:
            assert read.tracked_kind == kind
        _read_everything(read)
    assert read.tracked_kind != kind
    a, b = read.readings(), unread.readings()
    for field in ("valid", "engine", "support", "contact", "perceived_gravity", "perceived_up"):
        assert np.array_equal(getattr(a, field), getattr(b, field), equal_nan=True), field
    for name in read.names:
        assert read.body(name).position == unread.body(name).position, name


@pytest.mark.parametrize("most", [28, 0])
def test_the_table_holds_what_the_readers_give(most: int) -> None:
    """Law: ``readings()`` has one row per tracked body in ``tracked_bodies`` order, holding each
    body's reading and perceived gravity as the readers give them, to the last bit; it is a
    copy, so the next step does not change it."""
    world = _pile(3, most)
    world.run(0.5)
    table = world.readings()
    assert list(table.bodies) == world.tracked_bodies
    for row, body in enumerate(table.bodies):
        name = world.name_of(body)
        assert name is not None
        f = world.forces(name)
        assert tuple(float(v) for v in table.engine[row]) == f.engine
        assert tuple(float(v) for v in table.support[row]) == f.support
        assert float(table.engine_torque[row]) == f.engine_torque
        assert bool(table.split_valid[row]) == f.split_valid
        g = table.perceived_gravity[row]
        assert (float(g[0]), float(g[1])) == world.perceived_gravity(name)
    engine = table.engine.copy()
    world.body("b0").velocity = (5.0, 0.0)
    world.step()
    assert np.array_equal(table.engine, engine)
    assert not np.array_equal(world.readings().engine, engine)
