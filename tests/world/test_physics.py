"""Laws of the physics stage: the path that serves the tracked bodies is chosen by their count
and the scene, the state moves with a switch, and a runaway reading is reported with its body."""

from __future__ import annotations

import math

import pytest

from playground.gravity import Radial
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
        (3, WorldConfig(substeps=2), False),
        (3, WorldConfig(contact_split=True), False),
        (30, WorldConfig(), False),
    ],
)
def test_the_path_follows_the_count_and_the_scene(
    n: int, config: WorldConfig, scalar: bool
) -> None:
    """Law: few tracked bodies with one substep and no contact split are served in plain floats;
    more than ``scalar_max_bodies``, substeps or the contact split take the batch path."""
    world = _pile(n, config)
    world.step()
    assert world.on_scalar_path is scalar


def test_a_field_that_varies_takes_the_batch_path() -> None:
    """Law: a field that varies in space is applied as batch force rows: no scalar path."""
    world = _pile(3)
    world.gravity = Radial(radius=1.0, center=(0.0, -20.0))
    world.step()
    assert not world.on_scalar_path


def test_the_readings_move_with_a_switch() -> None:
    """Law: switching paths mid-run hands the state over: a run that leaves the scalar path after
    one second reads what a run on the batch path throughout reads (within rounding)."""
    switched, batch_only = _pile(3), _pile(3)
    batch_only.scalar_max_bodies = 0
    for world in (switched, batch_only):
        world.run(1.0)
    switched.scalar_max_bodies = 0
    switched._replan()
    for world in (switched, batch_only):
        world.run(1.0)
    assert not switched.on_scalar_path
    a, b = switched.forces("b1"), batch_only.forces("b1")
    assert a.support == pytest.approx(b.support, rel=1e-12)
    assert switched.perceived_gravity("b1") == pytest.approx(batch_only.perceived_gravity("b1"))


def test_a_runaway_reading_names_its_body() -> None:
    """Law: the physics stage reports the first tracked body whose engine force is not finite,
    with its id and the column (the world turns it into a RunawayError naming the body)."""
    world = _pile(2)
    world.run(0.1)
    physics = world._physics
    assert physics.runaway() is None
    physics.scalar_on = False
    physics.solver.engine[1, 1] = math.nan
    body_id, column, value, _ = physics.runaway() or (0, ("", "", ""), 0.0, 0.0)
    assert body_id == world.body("b1").id and column[0] == "engine force" and math.isnan(value)
