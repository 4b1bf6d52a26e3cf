"""The contact load a controller reads is the step's mean over its substeps, as the force
solver's readings are: each contact's impulse summed over the substeps, over dt (pymunk keeps
only the last substep's impulse on an arbiter).

Two wrong readings pass at one substep and fail here: the last substep's impulse over the
substep (a landing's impulse falls mostly in one substep, so the step reads it ×substeps or
not at all) and the last substep's impulse over the whole step (a substeps-th of the load: no
crusher player is crushed).
"""

from __future__ import annotations

import pytest

from playground import Controller, ControllerConfig, State, World
from playground.level import find, load
from playground.level.variants import parse_sets
from playground.scene import Scene, build
from playground.world import WorldConfig

SUBSTEPS = [2, 4]
"""The substep counts the readings are asked at (one substep is every shipped level's)."""

TOL_IMPULSE_REL = 1e-9
"""Relative, Σ load·dt against the crate's momentum balance: both are the same impulses summed
in another order (rounding only)."""

SETTLED = 1.0
"""s: crusher's crate has fallen onto the player's head and come to rest there (it lands at
0.37 s and is heaved off at 2 s)."""


BOX_MASS = 100.0
"""kg: a load under the default player's crush threshold (981 N < 1500 N)."""
TOL_REST_REL = 1e-6
"""Relative, a resting box's load against its weight: the box still settles by micrometres
per second on the hover's spring after 2 s."""


def _crusher(substeps: int) -> Scene:
    return build(load(find("crusher"), parse_sets([f"settings.substeps={substeps}"])))


@pytest.mark.parametrize("substeps", SUBSTEPS)
def test_the_load_over_a_landing_is_the_crates_momentum_balance(substeps: int) -> None:
    """Newton's third law over crusher's crate falling onto the player's head and coming to
    rest: the only force on the crate but gravity is the player's head, so the player's load
    summed over the steps, Σ load·dt, is m·(v − v₀) + m·g·t of the crate, to rounding."""
    scene = _crusher(substeps)
    world, crate = scene.world, scene.world.body("crate")
    player = scene.controllers["player"]
    g = -world.space.gravity.y
    dt = world.config.dt
    v0 = crate.velocity.y
    world.step()
    # A step's reading covers the physics of the step before it.
    impulse, steps, v = 0.0, 0, crate.velocity.y
    while world.time < SETTLED:
        world.step()
        impulse += player.contact_load * dt
        steps += 1
        v = crate.velocity.y if world.time < SETTLED else v
    # The last reading covers the step before the last; v is the crate's after that step.
    expected = crate.mass * (v - v0) + crate.mass * g * steps * dt
    assert player.state is State.CRUSHED
    assert impulse == pytest.approx(expected, rel=TOL_IMPULSE_REL)


@pytest.mark.parametrize("substeps", SUBSTEPS)
def test_both_crusher_players_are_crushed_at_any_substeps(substeps: int) -> None:
    """Under a 250 kg crate (2452.5 N, over the 1500 N threshold) both players read its weight
    and are crushed until they push, as at one substep."""
    scene = _crusher(substeps)
    world = scene.world
    crushed = {"player": [], "weak": []}
    while world.time < 2.0:
        world.step()
        if world.time >= 0.5:
            for name, states in crushed.items():
                states.append(scene.controllers[name].state)
    for name, states in crushed.items():
        assert set(states) == {State.CRUSHED}, name


@pytest.mark.parametrize("substeps", [1, *SUBSTEPS])
def test_a_resting_load_reads_its_weight_at_any_substeps(substeps: int) -> None:
    """A 100 kg box resting on a player's head: the player's contact load is the box's weight,
    m·g, whatever the substeps."""
    world = World(WorldConfig(substeps=substeps))
    world.add_static_segment((-5.0, 0.0), (5.0, 0.0))
    config = ControllerConfig()
    player = Controller(world, "player", (0.0, config.ride_height))
    top = config.ride_height + config.half_length + config.radius
    world.add_box("box", mass=BOX_MASS, size=(0.6, 0.5), position=(0.0, top + 0.26))
    world.run(2.0)
    g = -world.space.gravity.y
    assert player.contact_load == pytest.approx(BOX_MASS * g, rel=TOL_REST_REL)
