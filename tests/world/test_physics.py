"""Laws of the physics stage: the implementation that serves the tracked bodies is chosen by their
count and the scene, the state moves with a switch, and a runaway reading is reported with its
body."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pymunk.batch as batch
import pytest
from numpy.typing import NDArray

from playground.forces.batch import BatchBodies
from playground.forces.scalar import ScalarBodies
from playground.gravity import Radial
from playground.limits import RUNAWAY_FORCE
from playground.world.config import WorldConfig
from playground.world.world import World


def _pile(n: int, config: WorldConfig | None = None) -> World:
    world = World(config)
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    for i in range(n):
        world.add_box(f"b{i}", mass=1.0, size=(0.5, 0.5), position=(0.6 * i - 0.3 * n, 0.25))
    world.track(*world.names)
    return world


@pytest.mark.parametrize(
    ("n", "config", "scalar"),
    [
        (3, WorldConfig(), True),
        (3, WorldConfig(substeps=2), True),
        (3, WorldConfig(contact_split=True), True),
        (3, WorldConfig(contact_split=True, sleep_time=1.0), True),
        (30, WorldConfig(), False),
    ],
)
def test_the_implementation_follows_the_count_and_the_scene(
    n: int, config: WorldConfig, scalar: bool
) -> None:
    """Law: few tracked bodies are served in plain floats, contact split, sleeping and substeps
    included; more than ``scalar_max_bodies`` are served by the batch implementation."""
    world = _pile(n, config)
    world.step()
    assert (world.tracked_kind == "scalar") is scalar


def test_substeps_in_a_crowded_space_are_served_by_the_batch_implementation() -> None:
    """Law: with substeps every body's force is re-applied before each substep, so a space of
    more than ``scalar_max_bodies`` bodies is served by the batch implementation, even with few
    tracked."""
    world = _pile(3, WorldConfig(substeps=2))
    world.scalar_max_bodies = 4
    world.step()
    assert world.tracked_kind == "scalar"
    world.add_box("crowd", mass=1.0, size=(0.5, 0.5), position=(20.0, 0.25))
    world.add_box("crowd2", mass=1.0, size=(0.5, 0.5), position=(22.0, 0.25))
    world.step()
    assert world.tracked_kind == "batch"


class _Tilted:
    """A field of a kind the scalar implementation does not know: it has no plain-float form."""

    uniform = False

    def at(self, points: NDArray[np.float64], t: float) -> NDArray[np.float64]:
        return np.column_stack([0.1 * points[:, 1], np.full(len(points), -9.81)])


def test_a_field_that_varies_is_served_in_plain_floats_for_few_bodies() -> None:
    """Law: a field that varies in space, of a kind evaluated in plain floats, keeps the scalar
    implementation while the named dynamic bodies are few (tracked or not); with more, or with a
    field of another kind, its forces are batch rows."""
    world = _pile(3)
    world.gravity = Radial(radius=1.0, center=(0.0, -20.0))
    world.step()
    assert world.tracked_kind == "scalar"
    world.scalar_max_bodies = 3
    world.add_box("untracked", mass=1.0, size=(0.5, 0.5), position=(20.0, 0.25))
    world.step()
    assert world.tracked_kind == "batch"
    world.remove("untracked")
    world.step()
    assert world.tracked_kind == "scalar"
    world.gravity = _Tilted()
    world.step()
    assert world.tracked_kind == "batch"


def test_the_readings_move_with_a_switch() -> None:
    """Law: switching implementations mid-run hands the state over: a run that leaves the scalar
    implementation after one second reads what a run on the batch one throughout reads (within
    rounding)."""
    switched, batch_only = _pile(3), _pile(3)
    batch_only.scalar_max_bodies = 0
    for world in (switched, batch_only):
        world.run(1.0)
    switched.scalar_max_bodies = 0
    switched._replan()
    for world in (switched, batch_only):
        world.run(1.0)
    assert switched.tracked_kind == "batch"
    a, b = switched.forces("b1"), batch_only.forces("b1")
    assert a.support == pytest.approx(b.support, rel=1e-12)
    assert switched.perceived_gravity("b1") == pytest.approx(batch_only.perceived_gravity("b1"))


def test_a_runaway_reading_names_its_body() -> None:
    """Law: the physics stage reports the first tracked body whose engine force is not finite,
    with its id and the column (the world turns it into a RunawayError naming the body)."""
    world = _pile(2)
    world.run(0.1)
    tracked = world._physics.tracked.active
    assert isinstance(tracked, ScalarBodies) and tracked.runaway(RUNAWAY_FORCE) is None
    tracked.rows[1].ey = math.nan
    body_id, column, value = tracked.runaway(RUNAWAY_FORCE) or (0, -1, 0.0)
    assert body_id == world.body("b1").id and column == 1 and math.isnan(value)


def _untracked_pile(n: int, config: WorldConfig | None = None) -> World:
    world = World(config)
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0))
    for i in range(n):
        world.add_box(f"b{i}", mass=1.0, size=(0.5, 0.5), position=(0.6 * i - 0.3 * n, 0.25))
    return world


def _count_batch_calls(monkeypatch: pytest.MonkeyPatch) -> dict[str, int]:
    """Count the batch reads and writes from now on."""
    counts = {"read": 0, "write": 0}
    read, write = batch.get_space_bodies, batch.set_space_bodies

    def counted_read(*args: Any) -> Any:
        counts["read"] += 1
        return read(*args)

    def counted_write(*args: Any) -> Any:
        counts["write"] += 1
        return write(*args)

    monkeypatch.setattr(batch, "get_space_bodies", counted_read)
    monkeypatch.setattr(batch, "set_space_bodies", counted_write)
    return counts


def test_a_field_that_varies_costs_one_batch_read_and_one_write(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Law: a per-body field under the batch implementation is evaluated at the positions of its
    own read (positions, velocities and forces in one batch read) and written in one batch write,
    and the bodies fall as in the field."""
    world = _untracked_pile(30, WorldConfig(guard=False))
    world.gravity = Radial(center=(0.0, -1e5), radius=1e5, softening=0.0)
    world.step()
    counts = _count_batch_calls(monkeypatch)
    world.step()
    assert counts == {"read": 1, "write": 1}
    free = world.add_box("free", mass=2.0, size=(0.5, 0.5), position=(0.0, 20.0))
    world.step()
    world.step()
    assert free.velocity.y == pytest.approx(-2 * world.config.dt * 9.81, rel=1e-3)


def test_substeps_write_the_forces_again_only_when_a_body_has_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Law: with substeps the forces are written again before each later substep (pymunk clears
    them after each), but not when no body has a force: then there is nothing to write."""
    world = _untracked_pile(3, WorldConfig(substeps=3, guard=False))
    world.step()
    counts = _count_batch_calls(monkeypatch)
    world.step()
    assert counts == {"read": 1, "write": 0}
    world.apply_force("b0", (1.0, 0.0))
    world.step()
    assert counts == {"read": 2, "write": 2}


def test_a_runaway_under_the_batch_implementation_looks_at_forces_not_torques() -> None:
    """Law: in the batch implementation a quick pass over every reading (torques included) lets a
    sound step through, and a closer look decides otherwise: a torque beyond the force bound is no
    runaway, an engine force beyond it is, named by its body and column."""
    world = _pile(30)
    world.scalar_max_bodies = 0
    world.run(0.1)
    tracked = world._physics.tracked.active
    assert isinstance(tracked, BatchBodies) and tracked.runaway(RUNAWAY_FORCE) is None
    tracked.solver.engine_torque[4] = 1e300
    assert tracked.runaway(RUNAWAY_FORCE) is None
    tracked.solver.engine[7, 0] = -1e300
    body_id, column, value = tracked.runaway(RUNAWAY_FORCE) or (0, -1, 0.0)
    assert body_id == world.body("b7").id and column == 0
    assert value == -1e300


@pytest.mark.parametrize("push", ["ledger force", "ledger torque", "straight force"])
def test_a_field_alone_moves_bodies_as_the_full_batch_read_does(push: str) -> None:
    """Law: with nothing tracked, one substep and no sleeping, a field reads only positions and
    forces and writes only forces; the bodies move as with the full batch read and write of
    whole rows (one body tracked there), to the last bit, with forces and torques of the ledger
    or set straight on a body (the torques it does not write stay)."""
    worlds = [_untracked_pile(12), _untracked_pile(12)]
    worlds[1].scalar_max_bodies = 0
    worlds[1].track("b0")
    for world in worlds:
        world.gravity = Radial(center=(0.0, -40.0), radius=40.0, softening=0.0)
    for step in range(60):
        for world in worlds:
            if push == "ledger force":
                world.apply_force("b3", (5.0, 20.0), point=(world.body("b3").position.x, 0.4))
            elif push == "ledger torque":
                world.apply_torque("b5", 3.0)
            elif step % 7 == 0:
                world.body("b7").force = (0.0, 30.0)
                world.body("b7").torque = -2.0
            world.step()
    lean, full = worlds
    assert not lean.tracked_bodies and full.tracked_bodies
    for name in lean.names:
        a, b = lean.body(name), full.body(name)
        assert (a.position, a.angle, a.velocity, a.angular_velocity) == (
            b.position,
            b.angle,
            b.velocity,
            b.angular_velocity,
        ), name
    assert lean.body("b5").angle != 0.0 or push != "ledger torque"


@pytest.mark.parametrize("substeps", [1, 2, 4])
def test_substep_readers_run_after_each_substep_but_the_last(substeps: int) -> None:
    """World.on_substep: a reader sees the space after each substep of a step but the last
    (whose state is still there after the step), never with one substep; off_substep stops it,
    and stopping one that is not called is an error naming it."""
    world = _pile(1, WorldConfig(substeps=substeps))
    seen: list[float] = []

    def reader() -> None:
        seen.append(world.space.current_time_step)

    world.on_substep(reader)
    world.run(3 * world.config.dt)
    h = world.config.dt / substeps
    assert seen == [h] * (3 * (substeps - 1))
    world.off_substep(reader)
    world.step()
    assert len(seen) == 3 * (substeps - 1)
    with pytest.raises(ValueError, match="reader: reader is not called"):
        world.off_substep(reader)
