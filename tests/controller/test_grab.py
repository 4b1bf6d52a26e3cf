"""Laws of grab, hang and climb: the grip holds m·(g + a) within its budget, lets go beyond it
or on release, climbing slides the hold along the held body, and the grip reading is the step's
mean at any number of substeps."""

from __future__ import annotations

import math

import pymunk
import pytest

from playground import (
    Controller,
    ControllerConfig,
    Elevator,
    Intent,
    Script,
    State,
    World,
)
from playground.level import find, load
from playground.level.variants import parse_sets
from playground.scene import build

G = 9.81
"""|g| of the world's default field, m/s²."""

M = ControllerConfig().mass
"""The default player's mass, kg."""

TOL_GRIP_REL = 0.01
"""Issue 3: grip = m·(g + a) within 1 % while hanging from a body accelerating up at a."""


def flyer(world: World, accel: float, bottom: float, start_time: float = 1.0) -> pymunk.Body:
    """A massive (kinematic) flying slab whose underside is at ``bottom`` (m), rising at ``accel``
    (m/s²) from ``start_time``."""
    body = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
    world.add("flyer", body, pymunk.Poly.create_box(body, (4.0, 0.5)))
    world.add_mover(
        "flyer", Elevator(start=(0.0, bottom + 0.25), acceleration=accel, start_time=start_time)
    )
    return body


def test_hanging_grip_is_m_g_plus_a_and_letting_go_works() -> None:
    """Newton: hanging from a body accelerating up at a, the grip carries m·(g + a); releasing the
    grab lets go (free fall, no engine force)."""
    a = 2.0
    world = World()
    flyer(world, a, bottom=3.05)
    script = Script(((0.0, Intent(grab=True)), (3.0, Intent())))
    player = Controller(world, "player", (0.0, 2.0), source=script)
    world.run(0.1)
    assert player.state is State.HANGING
    world.run(2.8)
    expected = M * (G + a)
    assert abs(player.grip - expected) < TOL_GRIP_REL * expected
    engine = world.forces("player").engine
    assert abs(engine[1] - expected) < TOL_GRIP_REL * expected
    world.run(0.2)
    assert player.state is State.AIRBORNE
    assert player.joint is None
    assert abs(world.forces("player").engine[1]) < TOL_GRIP_REL * expected


def test_exceeding_the_grip_budget_drops_the_player() -> None:
    """A grip budget between m·g and m·(g + a) holds the player until the flyer accelerates."""
    a = 3.0
    cfg = ControllerConfig(grip_force=M * (G + 0.5 * a))
    world = World()
    flyer(world, a, bottom=3.05)
    player = Controller(world, "player", (0.0, 2.0), cfg, Script(((0.0, Intent(grab=True)),)))
    world.run(0.9)
    assert player.state is State.HANGING
    world.run(1.0)
    assert player.state is not State.HANGING
    assert player.joint is None


def test_climbing_moves_the_grip_along_the_held_body() -> None:
    """Climb slides the held anchor along the held body's surface at climb_speed."""
    world = World()
    flyer(world, 0.0, bottom=3.05)
    script = Script(((0.0, Intent(grab=True)), (0.5, Intent(grab=True, climb=1.0))))
    player = Controller(world, "player", (0.0, 2.0), source=script)
    world.run(0.5)
    assert player.joint is not None
    x0 = player.joint.anchor_b.x
    world.run(1.0)
    assert player.joint is not None
    moved = abs(player.joint.anchor_b.x - x0)
    assert abs(moved - player.config.climb_speed * 1.0) < 0.02 * player.config.climb_speed


GRIP_MEAN_REL = 5e-3
"""Issue 22: at 2–4 substeps the grip reading is within 0.5 % of m·(g + a) on flying_whale (each
step's reading is within 9e-6 measured: the last of the climb's start still ringing at 3 s)."""
WHALE_ACCEL = 1.0
"""m/s²: flying_whale's climb from 2 s."""
MASS_FACTORS = (0.5, 1.0, 2.0)
"""The player's mass as a multiple of flying_whale's 70 kg (the robustness matrix's)."""


@pytest.mark.parametrize("mass_factor", MASS_FACTORS)
@pytest.mark.parametrize("substeps", [1, 2, 3, 4])
def test_the_grip_reading_is_the_steps_mean_over_its_substeps(
    substeps: int, mass_factor: float
) -> None:
    """Hanging from the climbing whale at ``substeps`` substeps, every step's grip reading is
    the step's mean joint force, m·(g + a), as the force solver's engine reading is — not the
    last substep's (at 2 substeps for 70 kg the substeps carry 828.5 and 684.9 N: a reading of
    the last one alone is 9.5 % low)."""
    mass = mass_factor * M
    sets = parse_sets([f"settings.substeps={substeps}", f"actors.player.controller.mass={mass}"])
    scene = build(load(find("flying_whale"), sets))
    player = scene.controllers["player"]
    scene.run(3.0)
    expected = mass * (G + WHALE_ACCEL)
    while scene.world.time < 4.0:
        scene.world.step()
        assert player.grip == pytest.approx(expected, rel=GRIP_MEAN_REL), scene.world.time
    engine = scene.world.forces("player").engine
    assert player.grip == pytest.approx(math.hypot(*engine), rel=GRIP_MEAN_REL)
