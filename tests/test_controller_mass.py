"""Law: the controller follows its body's mass.

``World.set_mass`` on a player changes the body the controller drives; the hover (stiffness,
damping, weight feed-forward), the drive and the jump use the mass now, not the mass in the
config it was built with: it rides at the same height, closes the same velocity gap at the same
rate and jumps at the same speed.
"""

from __future__ import annotations

import pytest

from playground import World
from playground.controller import Controller
from playground.intents import Intent

G = 9.81
"""|g|, m/s² (the world's default)."""

TOL_HEIGHT = 1e-9
"""m: at rest the spring term is exactly 0 and the weight feed-forward holds the body: the ride
height is kept to float rounding (measured 1e-16 m)."""

TOL_REL = 1e-9
"""Relative: one step of a force computed from the same mass that integrates it; float rounding."""

MASSES = [50.0, 70.0, 90.0]
"""kg: lighter than, equal to and heavier than the 70 kg the controller is built with."""


def settled(mass: float) -> tuple[World, Controller]:
    """A default (70 kg) player on flat ground, its mass set to ``mass`` after 1 s, then 2 s."""
    world = World()
    world.add_static_segment((-50.0, 0.0), (50.0, 0.0), radius=0.0)
    player = Controller(world, "player", position=(0.0, 0.95))
    world.run(1.0)
    world.set_mass("player", mass)
    world.run(2.0)
    return world, player


@pytest.mark.parametrize("mass", MASSES)
def test_rides_at_ride_height_after_a_mass_change(mass: float) -> None:
    """Law: after set_mass the player settles at its ride height carrying its new weight."""
    world, player = settled(mass)
    assert player.body.mass == mass
    assert player.probe is not None
    assert abs(player.probe.distance - player.config.ride_height) <= TOL_HEIGHT
    support = world.forces("player").support[1]
    assert abs(support - mass * G) <= TOL_REL * mass * G


@pytest.mark.parametrize("mass", MASSES)
def test_drive_closes_the_gap_at_its_rate_after_a_mass_change(mass: float) -> None:
    """Law: within its budget the drive changes the velocity by (goal − v)·dt/drive_time in one
    step, whatever the body's mass."""
    world, player = settled(mass)
    player.intent = Intent(move=0.01)  # a 4 cm/s goal: far inside the force budgets
    v0 = player.body.velocity.x
    world.step()
    expected = 0.01 * player.config.max_speed * world.config.dt / player.config.drive_time
    assert abs((player.body.velocity.x - v0) - expected) <= TOL_REL * expected


@pytest.mark.parametrize("mass", MASSES)
def test_jumps_at_jump_speed_after_a_mass_change(mass: float) -> None:
    """Law: the take-off impulse is the mass now × the speed missing: it leaves at jump_speed."""
    world, player = settled(mass)
    player.intent = Intent(jump=True)
    world.step()
    speed = player.config.jump_speed
    assert abs(player.body.velocity.y - speed) <= TOL_REL * speed
